//! §9.14 Gibbs–Appell–Kane dynamics: Kane's equations F_r + F*_r = 0 with generalized
//! speeds chosen by the user, partial velocities from dual numbers, and the reduced form
//! for nonholonomic systems.
//!
//! Book (§9.14, a stub in the text): "Include Gibbs-Appel-Kane dynamics." The reference is
//! sympy.physics.mechanics.KanesMethod on its own rolling-disc example
//! (scripts/ch09_kane_rolling_disk.py → tests/data/ch09_kane_rolling_disk.json).

use crate::support::NanAmax;
use vectrix::dynamics::constraints::kane::{
    BodyMotion, KaneLoads, KaneSystem, kane_accelerations, kane_state_derivative, partial_velocities,
};
use vectrix::dynamics::constraints::map_constrained_accelerations;
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::ode::Adaptive;
use vectrix::prelude::*;

use super::mechanisms::{assert_abs, frame_from};
use super::nonholonomic::{disk_motion, newton_euler};
use super::rolling::{KaneDisk, RollingDisk};

const EPS: f64 = f64::EPSILON;

/// The same disk with the speeds u = (ψ̇, θ̇, φ̇, ẋ, ẏ) permuted by `order` (u_k = q̇[order[k]]),
/// the last two dependent through the horizontal no-slip rows: the reduced form eliminates
/// them.
struct KaneDiskDependent {
    disk: RollingDisk,
    order: [usize; 5],
}

impl KaneDiskDependent {
    fn qd<T: Scalar>(&self, u: &[T]) -> [T; 5] {
        let mut qd = [T::zero(); 5];
        for (k, &i) in self.order.iter().enumerate() {
            qd[i] = u[k];
        }
        qd
    }
}

impl KaneSystem for KaneDiskDependent {
    fn coordinates(&self) -> usize {
        5
    }
    fn speeds(&self) -> usize {
        5
    }
    fn masses(&self) -> MapMasses {
        KinematicMap::masses(&self.disk)
    }
    fn kinematic_equations<T: Scalar>(&self, _q: &[T], u: &[T], _t: T, qd: &mut [T]) {
        qd.copy_from_slice(&self.qd(u));
    }
    fn body_motions<T: Scalar>(&self, q: &[T], u: &[T], _t: T) -> Vec<BodyMotion<T>> {
        let (a, qd) = (Frame::<T>::identity(), self.qd(u));
        let (_, o_ba) = self.disk.frames(q);
        vec![BodyMotion {
            v_c: a.vector(self.disk.centre_velocity(q, &qd).into()),
            omega: a.vector(self.disk.omega(q, &qd).into()),
            frame: frame_from(&o_ba),
        }]
    }
    fn loads(&self, _q: &[f64], _u: &[f64], _t: f64) -> KaneLoads {
        let a = Frame::new();
        KaneLoads {
            particles: vec![],
            bodies: vec![(a.vector([0.0, 0.0, -self.disk.m * self.disk.g]), Vector::zero())],
        }
    }
    fn speed_constraint_count(&self) -> usize {
        2
    }
    fn speed_constraints<T: Scalar>(&self, q: &[T], u: &[T], _t: T, out: &mut [T]) {
        let v = self.disk.contact_velocity(q, &self.qd(u));
        out.copy_from_slice(&[v.x, v.y]);
    }
}

fn disk() -> RollingDisk {
    RollingDisk { m: 1.7, r: 0.35, g: 9.81, incline: 0.0, all_rows: false }
}

/// u̇ of [`KaneDisk`] from the rates: u̇₁ = θ̈, u̇₂ = ψ̈ sin θ + ψ̇θ̇ cos θ + φ̈,
/// u̇₃ = ψ̈ cos θ − ψ̇θ̇ sin θ.
fn omega_l_rate(q: &[f64], qd: &[f64], qdd: &[f64]) -> [f64; 3] {
    let (s, c) = q[3].sin_cos();
    [qdd[3], qdd[2] * s + qd[2] * qd[3] * c + qdd[4], qdd[2] * c - qd[2] * qd[3] * s]
}

/// The sympy KanesMethod reference: for each (θ, u) the rates u̇ = MM⁻¹ forcing of the
/// rolling disc with u = ω|_L (mass 1.7, radius 0.35, g = 9.81; yaw and spin do not enter).
#[test]
fn section_9_14_rolling_disk_matches_sympy_kanes_method() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/ch09_kane_rolling_disk.json"
    ))
    .unwrap();
    let data: serde_json::Value = serde_json::from_str(&text).unwrap();
    let p = &data["params"];
    let d = RollingDisk {
        m: p["m"].as_f64().unwrap(),
        r: p["r"].as_f64().unwrap(),
        g: p["g"].as_f64().unwrap(),
        incline: 0.0,
        all_rows: false,
    };
    let sys = KaneDisk(d);
    let cases = data["cases"].as_array().unwrap();
    assert_eq!(cases.len(), 8);
    for case in cases {
        let lean = case["lean"].as_f64().unwrap();
        let u: Vec<f64> = case["u"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
        // printed with 17 significant digits: parse exactly
        let want: Vec<f64> =
            case["udot"].as_array().unwrap().iter().map(|x| x.as_str().unwrap().parse().unwrap()).collect();
        let q = [0.3, -1.0, 0.4, lean, 1.3];
        let s = kane_accelerations(&sys, &q, &u, 0.0).unwrap();
        // terms of size g/r + |u|², divided by cos θ ≥ cos 1.3 (measured ≤ 0.7 ε·scale)
        let scale = (sys.0.g / sys.0.r + u.iter().map(|x| x * x).sum::<f64>()) / lean.cos();
        for (got, want) in s.ud.iter().zip(want) {
            assert_abs(*got, want, 8.0 * EPS * scale);
        }
    }
}

/// Kane's equations with u = ω|_L, Kane's equations with u = q̇ reduced by the two no-slip
/// rows, and Lagrange's equations with multipliers give the same motion of the rolling disk,
/// and Newton–Euler with the contact force F⃗ = m a⃗_c − m g⃗ gives the same α⃗.
#[test]
fn section_9_14_kane_agrees_with_lagrange_multipliers_and_newton_euler() {
    let d = disk();
    let kane = KaneDisk(disk());
    let dependent = KaneDiskDependent { disk: disk(), order: [2, 3, 4, 0, 1] };
    for &(lean, rates) in
        &[(0.25, [1.5, 0.8, 9.0]), (-0.9, [-2.0, 0.3, 4.0]), (0.0, [0.0, 0.0, 5.0]), (1.2, [3.0, -1.0, -2.0])]
    {
        let q = [0.3, -1.0, 0.4, lean, 1.3];
        let qd = d.rolling_rates(&q, rates);
        let lagrange = map_constrained_accelerations(&d, &q, &qd, 0.0).unwrap();
        let scale = (d.g / d.r + rates.iter().map(|x| x * x).sum::<f64>()) / f64::cos(lean);
        // u = ω|_L
        let (s, c) = f64::sin_cos(lean);
        let u = [rates[1], rates[0] * s + rates[2], rates[0] * c];
        let k = kane_accelerations(&kane, &q, &u, 0.0).unwrap();
        for (got, want) in k.qd.iter().zip(qd) {
            assert_abs(*got, want, 16.0 * EPS * scale * d.r);
        }
        let want = omega_l_rate(&q, &qd, lagrange.qdd.as_slice());
        for (got, want) in k.ud.iter().zip(want) {
            assert_abs(*got, want, 64.0 * EPS * scale);
        }
        // u = (ψ̇, θ̇, φ̇; ẋ, ẏ), the last two eliminated
        let kd = kane_accelerations(&dependent, &q, &rates, 0.0).unwrap();
        for (i, &j) in dependent.order.iter().enumerate() {
            assert_abs(kd.u[i], qd[j], 16.0 * EPS * scale * d.r);
            assert_abs(kd.ud[i], lagrange.qdd[j], 64.0 * EPS * scale);
        }
        // Newton–Euler with the contact force that the motion needs
        let (a_c, alpha, _) = disk_motion(&d, &q, &qd, lagrange.qdd.as_slice());
        let (_, alpha_ne) = newton_euler(&d, &q, &qd, &a_c);
        assert!((alpha - alpha_ne).norm() <= 1e-12 * scale, "{alpha} vs {alpha_ne}");
    }
}

/// The steady turn of §9.12 from Kane's equations: A Ω² sin θ cos θ − (C + mr²) Ω ω₂ cos θ
/// = m g r sin θ makes u̇ = 0 in the lean frame (the speeds are constant in L).
#[test]
fn section_9_14_rolling_disk_steady_turn() {
    let sys = KaneDisk(disk());
    let (m, r, g) = (sys.0.m, sys.0.r, sys.0.g);
    let (a_j, c_j) = (0.25 * m * r * r, 0.5 * m * r * r);
    for &(lean, omega) in &[(0.3, 2.0), (-0.5, 4.0), (0.1, -7.0)] {
        let (s, c) = f64::sin_cos(lean);
        let w2 = (a_j * omega * omega * s * c - m * g * r * s) / ((c_j + m * r * r) * omega * c);
        let u = [0.0, w2, omega * c];
        let sol = kane_accelerations(&sys, &[0.0, 0.0, 0.0, lean, 0.0], &u, 0.0).unwrap();
        for k in 0..3 {
            assert_abs(sol.ud[k], 0.0, 64.0 * EPS * (g / r + omega * omega + w2 * w2));
        }
    }
}

/// Partial velocities by dual numbers, against their closed forms for u = ω|_L: the partial
/// angular velocities are the axes of L, ω⃗_r = (î_L, ĵ_L, k̂_L)_r, and the partial velocities
/// of the centre are v⃗_r = ω⃗_r × r k̂_L.
#[test]
fn section_9_14_partial_velocities_of_the_rolling_disk() {
    let sys = KaneDisk(disk());
    let q = [0.3, -1.0, 0.4, 0.7, 1.3];
    let pv = partial_velocities(&sys, &q, &[0.5, 2.0, -1.0], 0.0).unwrap();
    let (o_la, _) = sys.0.frames(&q);
    let k_l: Vector3<f64> = o_la.row(2).transpose();
    for r in 0..3 {
        let axis: Vector3<f64> = o_la.row(r).transpose();
        let (v_r, w_r) = pv.bodies[r][0];
        assert!((w_r - axis).nan_amax() <= 4.0 * EPS, "{w_r} vs {axis}");
        assert!((v_r - axis.cross(&k_l) * sys.0.r).nan_amax() <= 4.0 * EPS);
    }
}

/// Kane's equations as an ODE, y = (q, u_i): the Chaplygin sleigh with speeds (v, ω) along
/// the blade and about the vertical (the knife edge built in) follows the closed form of
/// §9.12, v = v∞ tanh(kt + atanh(v₀/v∞)).
#[test]
fn section_9_14_chaplygin_sleigh_by_kane() {
    struct KaneSleigh {
        m: f64,
        i: f64,
        a: f64,
    }
    impl KaneSystem for KaneSleigh {
        fn coordinates(&self) -> usize {
            3
        }
        fn speeds(&self) -> usize {
            2
        }
        fn masses(&self) -> MapMasses {
            // a flat plate about its centre: only J_zz = I enters planar motion
            MapMasses {
                particles: vec![],
                bodies: vec![(self.m, Matrix3::from_diagonal(&Vector3::new(0.5, 0.5, 1.0)) * self.i)],
            }
        }
        fn kinematic_equations<T: Scalar>(&self, q: &[T], u: &[T], _t: T, qd: &mut [T]) {
            qd.copy_from_slice(&[u[0] * q[2].cos(), u[0] * q[2].sin(), u[1]]);
        }
        fn body_motions<T: Scalar>(&self, q: &[T], u: &[T], _t: T) -> Vec<BodyMotion<T>> {
            let a = Frame::<T>::identity();
            let (s, c, al) = (q[2].sin(), q[2].cos(), T::lit(self.a));
            // v⃗_G = v ê + a ω ê⊥ with ê = (cos ψ, sin ψ), ê⊥ = (−sin ψ, cos ψ)
            let v_c = a.vector([u[0] * c - al * u[1] * s, u[0] * s + al * u[1] * c, T::zero()]);
            let frame = frame_from(&super::mechanisms::o3(q[2]));
            vec![BodyMotion { v_c, omega: a.vector([T::zero(), T::zero(), u[1]]), frame }]
        }
    }
    let s = KaneSleigh { m: 2.0, i: 0.3, a: 0.4 };
    let (v0, w0) = (-0.5, 2.0);
    let ip = s.i + s.m * s.a * s.a;
    let v_inf = ((s.m * v0 * v0 + ip * w0 * w0) / s.m).sqrt();
    let (k, u0) = (s.a * s.m * v_inf / ip, (v0 / v_inf).atanh());
    let f = |t: f64, y: &Vec<f64>| kane_state_derivative(&s, t, y).unwrap_or_else(|_| vec![f64::NAN; 5]);
    let sol =
        Adaptive::dop853().rtol(1e-12).atol(1e-12).solve(f, 0.0, &vec![0.0, 0.0, 0.0, v0, w0], 40.0).unwrap();
    for (t, y) in sol.t.iter().zip(&sol.y) {
        let u = k * t + u0;
        assert_abs(y[3], v_inf * u.tanh(), 1e-9);
        assert_abs(y[4], (s.m / ip).sqrt() * v_inf / u.cosh(), 1e-9);
    }
}

/// Bad input: dependent speeds that the speed constraints cannot determine (ψ̇ and θ̇ do not
/// enter the no-slip rows), and more speed constraints than speeds.
#[test]
fn section_9_14_bad_speed_choices_are_typed() {
    let wrong = KaneDiskDependent { disk: disk(), order: [0, 1, 4, 2, 3] };
    let q = [0.0, 0.0, 0.4, 0.2, 0.0];
    let err = kane_accelerations(&wrong, &q, &[0.0, 0.0, 1.0], 0.0).unwrap_err();
    assert!(matches!(err, DynamicsError::SpeedsNotDetermined { row: 0, dependent: 2, .. }), "{err}");
    let right = KaneDiskDependent { disk: disk(), order: [2, 3, 4, 0, 1] };
    let err = kane_accelerations(&right, &q, &[0.0, 1.0], 0.0).unwrap_err();
    assert!(matches!(err, DynamicsError::DimensionMismatch { .. }), "{err}");
    let err = kane_accelerations(&KaneDisk(disk()), &q, &[0.0, f64::INFINITY, 1.0], 0.0).unwrap_err();
    assert!(matches!(err, DynamicsError::NonFinite { .. }), "{err}");
}

mod prop {
    use proptest::prelude::*;

    use super::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// On random rolling states (lean up to ±1.4 rad, upright included), Kane's equations
        /// with u = ω|_L and Lagrange's equations with multipliers give the same rates, and
        /// the multipliers are minus the horizontal contact force m a⃗_c − m g⃗.
        #[test]
        fn kane_and_lagrange_agree_on_random_rolling_states(
            lean in prop_oneof![Just(0.0), Just(1e-8), -1.4..1.4f64],
            rates in [-6.0..6.0f64, -6.0..6.0f64, -20.0..20.0f64],
            heading in -3.2..3.2f64,
        ) {
            let d = disk();
            let q = [0.0, 0.0, heading, lean, 0.0];
            let qd = d.rolling_rates(&q, rates);
            let lagrange = map_constrained_accelerations(&d, &q, &qd, 0.0).unwrap();
            let (s, c) = f64::sin_cos(lean);
            let u = [rates[1], rates[0] * s + rates[2], rates[0] * c];
            let k = kane_accelerations(&KaneDisk(disk()), &q, &u, 0.0).unwrap();
            let want = omega_l_rate(&q, &qd, lagrange.qdd.as_slice());
            let scale = (d.g / d.r + rates.iter().map(|x| x * x).sum::<f64>()) / c;
            for (got, want) in k.ud.iter().zip(want) {
                prop_assert!((got - want).abs() <= 64.0 * EPS * scale, "{} vs {}", got, want);
            }
            let (a_c, _, _) = disk_motion(&d, &q, &qd, lagrange.qdd.as_slice());
            let (f, _) = newton_euler(&d, &q, &qd, &a_c);
            prop_assert!((lagrange.lambda[0] + f.x).abs() <= 64.0 * EPS * d.m * d.r * scale);
            prop_assert!((lagrange.lambda[1] + f.y).abs() <= 64.0 * EPS * d.m * d.r * scale);
        }
    }
}
