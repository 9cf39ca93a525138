//! Problems 13.7.1–3: the sign checks of the cross-control cancellations (13.6.2), (13.6.4) —
//! the "two diagrams" of each problem become the two signs of the deflection, with the
//! rudder-roll geometry of (13.6.5)–(13.6.6) built from physical vectors — and the derivation
//! of (13.3.27).

use proptest::prelude::*;
use vectrix::flight::*;
use vectrix::num_dual::Dual64;
use vectrix::prelude::*;
use vectrix::statics::{AppliedForce, Point};

use crate::common::{GEOMETRY, U0, Var, aircraft, coefficients, partials, qs};
use crate::support::EPS;

/// Roll and yaw moments of the aircraft at the steady point of §13.2 for aileron and rudder.
fn roll_yaw(ac: &Aircraft, da: f64, dr: f64) -> (f64, f64) {
    let x = AircraftState { velocity: [U0, 0.0, 0.0], ..Default::default() };
    let u = Controls { elevator: 0.0, aileron: da, rudder: dr, thrust: 0.0 };
    let fm = ac.forces(&x, &u, 0.0, 0.0);
    (fm.roll, fm.yaw)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// P13.7.2: (13.6.4) δa = −(C_lδr/C_lδa)δr cancels rudder roll (13.6.3). The rudder's lift
    /// L⃗_δr = λĵ_AC (λ > 0 for left rudder, δr > 0) acts at c′ = μ_x î_AC + μ_z k̂_AC (μ_x < 0), so
    /// its roll moment is (r⃗_{c′/c} × L⃗_δr)·î_AC = −λμ_z (13.6.5–6): adverse (C_lδr > 0) at low
    /// angle of attack (the fin above c, μ_z < 0), proverse (C_lδr < 0) at high angle of attack
    /// (μ_z > 0). For rudder right and rudder left, at both angles of attack, the aileron of
    /// (13.6.4) cancels the roll in the nonlinear model, with δa opposite to δr when the effect is
    /// adverse and along it when proverse.
    #[test]
    fn problem_13_7_2_aileron_cancels_rudder_roll(
        mu_x in -30.0..-5.0f64, mu_z_mag in 0.5..8.0f64, kappa in 0.5..5.0f64, cl_da in 0.01..0.3f64, mag in 0.001..0.3f64,
    ) {
        let ac_frame = Frame::new();
        let pds_b = qs() * GEOMETRY.span;
        for mu_z in [-mu_z_mag, mu_z_mag] {
            // C_lδr from the geometry: roll moment per unit δr of λ = κ δr
            let c_prime = Point::at(ac_frame.vector([mu_x, 0.0, mu_z]));
            let roll_per_dr = AppliedForce::new(ac_frame.j() * kappa, c_prime).moment_about(&Point::origin()).dot(&ac_frame.i());
            prop_assert!((roll_per_dr + kappa * mu_z).abs() <= 8.0 * EPS * kappa * mu_z_mag);
            let cl_dr = roll_per_dr / pds_b;
            // adverse at low α (μ_z < 0), proverse at high α
            prop_assert!(cl_dr.signum() == -mu_z.signum());
            let ac = aircraft(Coefficients { croll_dr: cl_dr, croll_da: cl_da, ..coefficients() });
            for dr in [mag, -mag] {
                let da = -(cl_dr / cl_da) * dr;
                let want_sign = if mu_z < 0.0 { -dr.signum() } else { dr.signum() };
                prop_assert!(da.signum() == want_sign);
                let (roll, _) = roll_yaw(&ac, da, dr);
                let (roll_rudder, _) = roll_yaw(&ac, 0.0, dr);
                prop_assert!(roll.abs() <= 8.0 * EPS * roll_rudder.abs(), "residual roll {roll}");
            }
        }
    }
}

/// The moment about the centre of mass c (the origin) of forces at points of F_AC.
fn moment_of(ac: &Frame, forces: &[([f64; 3], [f64; 3])]) -> Vector {
    forces.iter().fold(Vector::zero(), |m, (f, at)| {
        m + AppliedForce::new(ac.vector(*f), Point::at(ac.vector(*at))).moment_about(&Point::origin())
    })
}

/// P13.7.1: with (13.6.2), δr = −(C_nδa/C_nδr)δa, draw two diagrams (right aileron up, δa > 0;
/// left aileron up, δa < 0) and check the signs of every term.
///
/// The diagrams are forces at points of F_AC (î forward, ĵ out the right wing, k̂ down) whose
/// moments about c vectrix's statics sums. The wing whose aileron goes down gains lift ΔL (along
/// −k̂) and, with it, induced drag ΔD (along −î); the other wing loses both (Fig. 13.6.10). Left
/// rudder (δr > 0, §13.6.2) puts a side force λĵ on the fin behind c (μ_x < 0). From the two
/// diagrams of each control: roll per δa > 0 (C_lδa > 0), yaw per δa < 0 (adverse: the nose
/// swings against the roll, C_nδa < 0), yaw per δr < 0 (C_nδr < 0) — Table 13.2's signs, and the
/// signs of the business jet's printed L_δa, N_δa, N_δr (Table 14.2, vectrix's catalog).
///
/// Then (13.6.2) on the business jet (vectrix's nonlinear model at its 400 kt trim, δr from the
/// printed N_δa/N_δr, which is C_nδa/C_nδr): right aileron up rolls right and yaws the nose left;
/// δr < 0 (trailing edge right) yaws it right; left aileron up mirrors both; in each diagram the
/// two yaw moments cancel, to the rounding of the model's sums.
#[test]
fn problem_13_7_1_rudder_cancels_adverse_aileron_yaw() {
    let ac_frame = Frame::new();
    let (y_a, x_a, d_lift, d_drag) = (14.0, -1.0, 1.0, 0.08);
    let (mu_x, mu_z, lambda) = (-18.0, -2.0, 1.0);
    let mut yaw_per_da_seen = Vec::new();
    for sign in [1.0, -1.0] {
        // δa = sign: the down aileron is on the left wing (y < 0) when δa > 0
        let down = -sign * y_a;
        let aileron = moment_of(
            &ac_frame,
            &[([-d_drag, 0.0, -d_lift], [x_a, down, 0.0]), ([d_drag, 0.0, d_lift], [x_a, -down, 0.0])],
        );
        let (roll_per_da, yaw_per_da) =
            (aileron.dot(&ac_frame.i()) / sign, aileron.dot(&ac_frame.k()) / sign);
        assert!(roll_per_da > 0.0, "C_lδa > 0: δa = {sign} rolls toward the raised aileron");
        assert!(yaw_per_da < 0.0, "C_nδa < 0: adverse yaw for δa = {sign}");
        // rudder δr = sign: side force sign·λĵ at the fin
        let rudder = moment_of(&ac_frame, &[([0.0, sign * lambda, 0.0], [mu_x, 0.0, mu_z])]);
        let yaw_per_dr = rudder.dot(&ac_frame.k()) / sign;
        assert!(yaw_per_dr < 0.0, "C_nδr < 0 for δr = {sign}");
        assert_eq!(yaw_per_dr, mu_x * lambda);
        yaw_per_da_seen.push(yaw_per_da);
    }
    // both diagrams of each control give one derivative: C_nδa does not change sign (§13.6.1)
    assert_eq!(yaw_per_da_seen[0], yaw_per_da_seen[1]);
    // the book's data carry these signs
    let lat = business_jet_lateral();
    assert!(lat.l_da > 0.0 && lat.n_da < 0.0 && lat.n_dr < 0.0);
    let jet = business_jet();
    let c = jet.coefficients;
    assert!(c.croll_da > 0.0 && c.cn_da < 0.0 && c.cn_dr < 0.0);
    // N = p_dSbC_n/J_zz: the printed ratio is the coefficient ratio of vectrix's model
    assert!((lat.n_da / lat.n_dr - c.cn_da / c.cn_dr).abs() <= 8.0 * EPS * (c.cn_da / c.cn_dr));
    let moments = |da: f64, dr: f64| {
        let x = AircraftState { velocity: [BUSINESS_JET_U0, 0.0, 0.0], ..Default::default() };
        let u = Controls { elevator: 0.0, aileron: da, rudder: dr, thrust: 0.0 };
        let fm = jet.forces(&x, &u, 0.0, 0.0);
        (fm.roll, fm.yaw)
    };
    for da in [0.05, -0.05] {
        // (13.6.2) with the printed derivatives
        let dr = -(lat.n_da / lat.n_dr) * da;
        let (roll, yaw_aileron) = moments(da, 0.0);
        let (_, yaw_rudder) = moments(0.0, dr);
        let (_, yaw) = moments(da, dr);
        assert!(roll.signum() == da.signum(), "δa = {da} rolls toward the raised aileron");
        assert!(yaw_aileron.signum() == -da.signum(), "δa = {da}: the aileron yaw is adverse");
        assert!(dr.signum() == -da.signum(), "δa = {da}: trailing edge toward the raised aileron");
        assert!(yaw_rudder.signum() == da.signum(), "δa = {da}: the rudder yaws into the roll");
        // one product and a sum of two terms of size |N|
        assert!(yaw.abs() <= 8.0 * EPS * yaw_aileron.abs(), "residual yaw {yaw} for δa = {da}");
    }
}

/// P13.7.3: derive (13.3.27), C_xu0 = −C_Du0. With F_AC chosen so that α₀ = β₀ = 0 (§13 intro),
/// a speed perturbation u along V̂₀ = î_AC leaves α = atan2(W, U) and β unchanged to first order,
/// so differentiating (13.2.11) C_x = −cαcβC_D + cαsβC_E + sαC_L gives C_xu0 = −C_Du0 (and
/// likewise C_zu0 = −C_Lu0 from (13.3.45)). Checked on the nonlinear model: C_x = F_Ax/(p_dS)
/// and C_D = D/(p_dS) differentiated by a dual number. In a body frame with α₀ ≠ 0 the same
/// perturbation turns the velocity (∂α/∂u = −W₀/(U₀² + W₀²)) and the relation fails — the
/// reason for the book's choice of frame.
#[test]
fn problem_13_7_3_speed_damping_derivative() {
    let c = coefficients();
    let ac = aircraft(c);
    let pu = partials(&ac, Var::U);
    let pds = qs();
    // C = F/(p_d S): d C/d(u/U₀) = U₀ (F′ p_d − F p_d′)/(p_d² S), p_d′ = 2 p_d0/U₀
    let dc = |f0: f64, f1: f64| U0 * (f1 - f0 * 2.0 / U0) / pds;
    let cx_u = dc(pu.force0[0], pu.force[0]);
    let cz_u = dc(pu.force0[2], pu.force[2]);
    let cd_u = dc(pu.del0[0], pu.del[0]);
    let cl_u = dc(pu.del0[2], pu.del[2]);
    assert!((cx_u + cd_u).abs() <= 64.0 * EPS * 10.0, "C_xu = {cx_u}, C_Du = {cd_u}");
    assert!((cz_u + cl_u).abs() <= 64.0 * EPS * 10.0, "C_zu = {cz_u}, C_Lu = {cl_u}");
    assert!((cd_u - (c.cd_u + 2.0 * c.k_induced * c.cl0 * c.cl_u)).abs() <= 64.0 * EPS);
    // α₀ = 0.2 in the body frame: u along î_AC changes α, and C_xu ≠ −C_Du
    let alpha0: f64 = 0.2;
    let (u0, w0) = (U0 * alpha0.cos(), U0 * alpha0.sin());
    let z = Dual64::from(0.0);
    let x = AircraftState {
        position: [z; 3],
        velocity: [Dual64::new(u0, 1.0), z, Dual64::from(w0)],
        attitude: Euler321::new(z, z, z),
        omega: [z; 3],
    };
    let fm = ac.forces(&x, &Controls::from_array([z; 4]), z, z);
    let a = x.aero_angles();
    assert!((a.alpha.eps + w0 / (u0 * u0 + w0 * w0)).abs() <= 16.0 * EPS / U0);
    let fx =
        (o_w_ac(a.alpha, a.beta).transpose() * nalgebra::Vector3::new(-fm.drag, -fm.side_drag, -fm.lift))[0];
    let pd = ac.dynamic_pressure(a.airspeed) * GEOMETRY.area;
    let (cx, cd) = (fx / pd, fm.drag / pd);
    assert!(
        (cx.eps + cd.eps).abs() * U0 > 0.1,
        "with α₀ ≠ 0 the lift term enters: {} vs {}",
        cx.eps,
        -cd.eps
    );
}
