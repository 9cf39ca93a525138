//! Aircraft as bodies: the `aero` effect puts an aircraft's aerodynamic forces and moments on a
//! free body, so an aircraft runs through the one scene pipeline (budgets, dense output,
//! invariants, outputs, units, trim, exact linearization) and combines with anything else a
//! scene declares.
//!
//! The aerodynamic model is `vectrix-flight`'s coefficient model (§13.3–13.5), evaluated at
//! the body's centre-of-mass velocity relative to still air and its angular velocity, both in
//! link components (the aircraft axes: x forward, y right wing, z down). Lift and the pitching
//! moment depend on α̇, and the side force, rolling and yawing moments on β̇ (13.3.2–8); α̇ and
//! β̇ depend on the body's own acceleration (the time derivatives of (10.6.18), (10.6.27)), so
//! the equations of motion are implicit in v̇ (notes ch9-14 §3). Forward dynamics is linear in
//! the applied wrenches, so v̇ is affine in every aircraft's (α̇, β̇): the right-hand side
//! evaluates ABA once at α̇ = β̇ = 0 and once per unit rate, and solves the small linear system
//! r = r(v̇₀ + Σ D_k r_k) exactly, in any scalar (f64 or dual numbers). No iteration.
//!
//! Book: §10.6 (α, β), §11.1–11.5 (forces, equations of motion), §13.3–13.5 (coefficients),
//! Tables 14.1–14.2 (the business jet).

use nalgebra::Vector3;
use vectrix_dynamics::Model;
use vectrix_dynamics::multibody::JointWrench;
use vectrix_flight::{Aircraft, AircraftState, Controls, aero_angle_rates, business_jet_in, o_w_ac};
use vectrix_tensor::Scalar;
use vectrix_units::UnitSystem;

use super::Scene;
use super::kin::{Kin, lift, lift33};
use super::parts::{Body, Effect};

/// The aircraft of the catalogue, by the name a scene gives in `aircraft = "…"` (an `aero`
/// effect) and `model = "…"` (an `aircraft` mass).
pub const AIRCRAFT: &[&str] = &["business_jet"];

/// A catalogue aircraft in SI (the book's data converted exactly, §15.19).
///
/// Book: Tables 14.1–14.2 (`business_jet`).
pub(crate) fn catalogue(name: &str) -> Option<Aircraft> {
    match name {
        "business_jet" => Some(business_jet_in(UnitSystem::Si)),
        _ => None,
    }
}

/// The error text for an aircraft name not in the catalogue.
pub(crate) fn unknown_aircraft(name: &str) -> String {
    format!("unknown aircraft `{name}`; valid: {}", AIRCRAFT.join(", "))
}

/// The names of [`vectrix_flight::Coefficients`]' fields, as a scene's `coefficients` table
/// writes them.
pub(crate) const COEFFICIENTS: [&str; 34] = [
    "u_ref",
    "cl0",
    "cl_u",
    "cl_alpha",
    "cl_q",
    "cl_alpha_dot",
    "cl_de",
    "cd_par",
    "k_induced",
    "cd_u",
    "cm0",
    "cm_u",
    "cm_alpha",
    "cm_q",
    "cm_alpha_dot",
    "cm_de",
    "ce_beta",
    "ce_beta_dot",
    "ce_p",
    "ce_r",
    "ce_da",
    "ce_dr",
    "croll_beta",
    "croll_beta_dot",
    "croll_p",
    "croll_r",
    "croll_da",
    "croll_dr",
    "cn_beta",
    "cn_beta_dot",
    "cn_p",
    "cn_r",
    "cn_da",
    "cn_dr",
];

/// Sets coefficient `name` of `c` (§13.3–13.5); `false` for a name not in [`COEFFICIENTS`].
pub(crate) fn set_coefficient(c: &mut vectrix_flight::Coefficients, name: &str, v: f64) -> bool {
    macro_rules! fields {
        ($($f:ident)*) => {
            match name {
                $(stringify!($f) => c.$f = v,)*
                _ => return false,
            }
        };
    }
    fields!(u_ref cl0 cl_u cl_alpha cl_q cl_alpha_dot cl_de cd_par k_induced cd_u cm0 cm_u cm_alpha cm_q
        cm_alpha_dot cm_de ce_beta ce_beta_dot ce_p ce_r ce_da ce_dr croll_beta croll_beta_dot croll_p
        croll_r croll_da croll_dr cn_beta cn_beta_dot cn_p cn_r cn_da cn_dr);
    true
}

/// The error text for a coefficient name not in [`COEFFICIENTS`], with the nearest name.
pub(crate) fn unknown_coefficient(name: &str) -> String {
    let near = COEFFICIENTS.iter().min_by_key(|c| super::error::distance(name, c)).copied().unwrap_or("cl0");
    format!("unknown coefficient `{name}` (did you mean `{near}`?); valid: {}", COEFFICIENTS.join(", "))
}

/// Whether the aircraft's coefficients make its forces depend on α̇ or β̇.
pub(crate) fn has_rate_terms(ac: &Aircraft) -> bool {
    let c = &ac.coefficients;
    [c.cl_alpha_dot, c.cm_alpha_dot, c.ce_beta_dot, c.croll_beta_dot, c.cn_beta_dot].iter().any(|x| *x != 0.0)
}

/// An aircraft state with only the body velocity and angular velocity set (all the
/// coefficient model reads).
fn air_state<T: Scalar>(vel: &Vector3<T>, omega: &Vector3<T>) -> AircraftState<T> {
    let z = T::zero();
    AircraftState::from_array([z, z, z, vel[0], vel[1], vel[2], z, z, z, omega[0], omega[1], omega[2]])
}

/// The velocity of body i's centre of mass relative to still air and its angular velocity,
/// link components: v_c = 𝓞 v_o + ω × c.
pub(crate) fn air_velocity<T: Scalar>(kin: &Kin<T>, b: &Body, i: usize) -> (Vector3<T>, Vector3<T>) {
    let e = kin.poses[i].0;
    let w = e * kin.omega[i];
    (e * kin.vel[i] + w.cross(&lift(&b.com)), w)
}

/// The aerodynamic wrench on body `b` (link components, about the link origin) for the
/// controls [δe, δa, δr] and the rates (α̇, β̇): F_A = 𝓞_{W/AC}ᵀ [−D, −E, −L] (11.1.5),
/// (11.1.21), with the moments (L_AC, M_AC, N_AC) about the centre of mass (13.3–13.5).
///
/// # Errors
/// At zero airspeed (α and β are undefined there) or a non-finite airspeed.
pub(crate) fn wrench<T: Scalar>(
    ac: &Aircraft,
    b: &Body,
    vel: &Vector3<T>,
    omega: &Vector3<T>,
    controls: [T; 3],
    rates: (T, T),
) -> Result<JointWrench<T>, String> {
    let speed = vel.norm().re();
    if !(speed.is_finite() && speed > 0.0) {
        return Err(format!(
            "the aero effect on body `{}` meets airspeed V = {speed} m/s; valid: V > 0 (α and β are undefined \
             at rest)",
            b.name
        ));
    }
    let x = air_state(vel, omega);
    let u = Controls { elevator: controls[0], aileron: controls[1], rudder: controls[2], thrust: T::zero() };
    let fm = ac.forces(&x, &u, rates.0, rates.1);
    let a = x.aero_angles();
    let force = o_w_ac(a.alpha, a.beta).transpose() * Vector3::new(-fm.drag, -fm.side_drag, -fm.lift);
    let moment = Vector3::new(fm.roll, fm.pitch, fm.yaw) + lift::<T>(&b.com).cross(&force);
    Ok(JointWrench { force, moment })
}

/// (α̇, β̇) of body i (a free body on the ground) for its joint accelerations `acc` =
/// (a_o in the joint frame, ω̇ in the link frame): the body-axis derivative of v_c is
/// 𝓞 a_o − ω × 𝓞 v_o + ω̇ × c.
///
/// Book: (10.6.18), (10.6.27) differentiated; transport theorem.
fn body_rates<T: Scalar>(kin: &Kin<T>, b: &Body, i: usize, acc: &[T]) -> (T, T) {
    let e = kin.poses[i].0;
    let w = e * kin.omega[i];
    let v_o = e * kin.vel[i];
    let c = lift::<T>(&b.com);
    let a_o = lift33::<T>(&b.orient).tr_mul(&Vector3::new(acc[0], acc[1], acc[2]));
    let w_dot = Vector3::new(acc[3], acc[4], acc[5]);
    let vel = v_o + w.cross(&c);
    let vel_dot = e * a_o - w.cross(&v_o) + w_dot.cross(&c);
    let z = Vector3::zeros();
    aero_angle_rates(&air_state(&vel, &w), &air_state(&vel_dot, &z))
}

/// Work space of the α̇/β̇ solve, allocated once per run.
#[derive(Debug, Clone, Default)]
pub(crate) struct AeroScratch<T: Scalar = f64> {
    wrenches: Vec<JointWrench<T>>,
    vd: Vec<T>,
    /// D_k = ∂v̇/∂r_k, k over (α̇, β̇) of every aircraft, nv each.
    d: Vec<T>,
    /// I − K (m × m, row-major) and the right-hand side r(v̇₀).
    a: Vec<T>,
    r: Vec<T>,
}

impl<T: Scalar> AeroScratch<T> {
    pub fn new(bodies: usize, nv: usize, aircraft: usize) -> Self {
        let m = 2 * aircraft;
        Self {
            wrenches: vec![JointWrench::default(); bodies],
            vd: vec![T::zero(); nv],
            d: vec![T::zero(); m * nv],
            a: vec![T::zero(); m * m],
            r: vec![T::zero(); m],
        }
    }
}

impl Scene {
    /// The aero effects whose forces depend on α̇ or β̇: (effect index, body).
    pub(crate) fn rate_aircraft(&self) -> impl Iterator<Item = (usize, &Aircraft)> + '_ {
        self.built.effects.iter().filter_map(|e| match e {
            Effect::Aero { body, aircraft, .. } if has_rate_terms(aircraft) => Some((*body, &**aircraft)),
            _ => None,
        })
    }

    /// Completes v̇ for the α̇ and β̇ terms: `vd` holds ABA's accelerations with the loads at
    /// α̇ = β̇ = 0 (`wrenches`, `tau`); the rates are solved exactly (see the module doc) and
    /// `vd` becomes the accelerations with them.
    ///
    /// # Errors
    /// A singular rate system (|Z_α̇| or |Y_β̇| equal to the airspeed: the equations of motion
    /// cannot be solved for v̇), or the dynamics' own errors.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn aero_rates<T: Scalar>(
        &self,
        model: &Model<T>,
        q: &[T],
        v: &[T],
        tau: &[T],
        kin: &Kin<T>,
        wrenches: &[JointWrench<T>],
        vd: &mut [T],
        aba: &mut vectrix_dynamics::multibody::AbaScratch<T>,
        s: &mut AeroScratch<T>,
    ) -> Result<(), String> {
        let b = &self.built;
        let nv = model.nv();
        let (zero, one) = (T::zero(), T::one());
        let mut count = 0;
        for (i, ac) in self.rate_aircraft() {
            let body = &b.bodies[i];
            let (vel, om) = air_velocity(kin, body, i);
            let w0 = wrench(ac, body, &vel, &om, [zero; 3], (zero, zero))?;
            for (c, rates) in [(one, zero), (zero, one)].into_iter().enumerate() {
                let w1 = wrench(ac, body, &vel, &om, [zero; 3], rates)?;
                s.wrenches.copy_from_slice(wrenches);
                s.wrenches[i].force += w1.force - w0.force;
                s.wrenches[i].moment += w1.moment - w0.moment;
                model.aba_into(q, v, tau, Some(&s.wrenches), &mut s.vd, aba).map_err(|e| e.to_string())?;
                let k = 2 * count + c;
                for (d, (a, b)) in s.d[k * nv..(k + 1) * nv].iter_mut().zip(s.vd.iter().zip(vd.iter())) {
                    *d = *a - *b;
                }
            }
            count += 1;
        }
        if count == 0 {
            return Ok(());
        }
        // r = r(v̇₀) + K r, K[·][k] = r(v̇₀ + D_k) − r(v̇₀) (r is affine in v̇)
        let m = 2 * count;
        for (n, (i, _)) in self.rate_aircraft().enumerate() {
            let body = &b.bodies[i];
            let at = |extra: Option<usize>| {
                let acc: [T; 6] = std::array::from_fn(|j| {
                    let x = body.vi + j;
                    vd[x] + extra.map_or(zero, |k| s.d[k * nv + x])
                });
                body_rates(kin, body, i, &acc)
            };
            let r0 = at(None);
            (s.r[2 * n], s.r[2 * n + 1]) = r0;
            for k in 0..m {
                let rk = at(Some(k));
                let diag = if k == 2 * n { one } else { zero };
                s.a[2 * n * m + k] = diag - (rk.0 - r0.0);
                let diag = if k == 2 * n + 1 { one } else { zero };
                s.a[(2 * n + 1) * m + k] = diag - (rk.1 - r0.1);
            }
        }
        solve_in_place(&mut s.a, &mut s.r, m).ok_or_else(|| {
            "the α̇/β̇ terms of an aero effect make the equations of motion singular (|Z_α̇| or |Y_β̇| equals the \
             airspeed); valid: an aircraft whose rate derivatives are small beside its airspeed"
                .to_string()
        })?;
        for (k, rk) in s.r.iter().enumerate() {
            for (x, d) in vd.iter_mut().zip(&s.d[k * nv..(k + 1) * nv]) {
                *x += *d * *rk;
            }
        }
        Ok(())
    }
}

/// Solves A x = b in place (A m × m row-major; x into b) by Gaussian elimination with partial
/// pivoting on the real parts; `None` for a singular A.
fn solve_in_place<T: Scalar>(a: &mut [T], b: &mut [T], m: usize) -> Option<()> {
    let scale = a.iter().fold(0.0_f64, |s, x| s.max(x.re().abs()));
    for col in 0..m {
        let piv =
            (col..m).max_by(|&x, &y| a[x * m + col].re().abs().total_cmp(&a[y * m + col].re().abs()))?;
        // (a NaN pivot is singular too)
        if a[piv * m + col].re().abs().partial_cmp(&(1e-12 * scale)) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        if piv != col {
            for k in 0..m {
                a.swap(col * m + k, piv * m + k);
            }
            b.swap(col, piv);
        }
        for row in col + 1..m {
            let f = a[row * m + col] / a[col * m + col];
            for k in col..m {
                let x = a[col * m + k];
                a[row * m + k] -= f * x;
            }
            let x = b[col];
            b[row] -= f * x;
        }
    }
    for col in (0..m).rev() {
        let mut x = b[col];
        for k in col + 1..m {
            x -= a[col * m + k] * b[k];
        }
        b[col] = x / a[col * m + col];
    }
    Some(())
}
