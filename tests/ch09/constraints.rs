//! §9.11 Lagrangian dynamics with constraints: holonomic φ(q, t) = 0 with multipliers,
//! checked against closed forms and against the same systems in independent coordinates.
//!
//! Book (§9.11, a stub in the text): "Use Lagrange multipliers to address constraints on
//! generalized coordinates." Convention tested throughout: M q̈ = f − Φ_qᵀλ, so for a rod
//! written as φ = |r⃗| − l, λ is the rod's tension.

use crate::support::NanAmax;
use std::f64::consts::PI;

use vectrix::dynamics::constraints::{
    ConstrainedIntegrator, Constraints, DEPENDENT_ROW_REL_TOL, LagrangeForm, constrained_accelerations,
    map_constrained_accelerations, solve_kkt,
};
use vectrix::dynamics::lagrange::accelerations;
use vectrix::nalgebra::{DMatrix, DVector};
use vectrix::ode::Adaptive;
use vectrix::prelude::*;

use super::mechanisms::{
    BeadOnHoop, BeadOnTurningWire, CartesianDoublePendulum, FourBar, HoopAngle, JointDoublePendulum,
    ParticlePendulum, assert_abs,
};

const EPS: f64 = f64::EPSILON;

/// A particle pendulum at angle θ from the downward vertical with rate θ̇: (q, q̇).
fn pendulum_state(l: f64, th: f64, thd: f64) -> ([f64; 2], [f64; 2]) {
    ([l * th.sin(), -l * th.cos()], [l * th.cos() * thd, l * th.sin() * thd])
}

/// §9.11: the pendulum as a particle on a rod, φ = |r⃗| − l. Claim (closed form, Newton's
/// law along the rod): the multiplier is the tension T = m(g cos θ + l θ̇²), and the motion is
/// θ̈ = −(g/l) sin θ.
#[test]
fn section_9_11_pendulum_as_constrained_particle_tension() {
    let p = ParticlePendulum { m: 1.3, l: 0.8, g: 9.81 };
    for &(th, thd) in &[(0.0, 0.0), (0.4, -1.2), (2.5, 3.0), (PI, 0.7), (-1.0, 0.0)] {
        let (q, qd) = pendulum_state(p.l, th, thd);
        let s = constrained_accelerations(&p, &q, &qd, 0.0).unwrap();
        let tension = p.m * (p.g * th.cos() + p.l * thd * thd);
        // a few roundings of terms of size m(g + lθ̇²)
        let scale = p.m * (p.g + p.l * thd * thd);
        assert_abs(s.lambda[0], tension, 16.0 * EPS * scale);
        // ẍ = l(cos θ θ̈ − sin θ θ̇²), ÿ = l(sin θ θ̈ + cos θ θ̇²) with θ̈ = −(g/l) sin θ
        let thdd = -p.g / p.l * th.sin();
        let want =
            [p.l * (th.cos() * thdd - th.sin() * thd * thd), p.l * (th.sin() * thdd + th.cos() * thd * thd)];
        for (got, want) in s.qdd.iter().zip(want) {
            assert_abs(*got, want, 16.0 * EPS * (p.g + p.l * thd * thd));
        }
        // the acceleration constraint Φ_q q̈ = γ holds
        let t = &s.terms;
        assert_abs((&t.jacobian * &s.qdd)[0], t.gamma[0], 16.0 * EPS * scale / p.m);
    }
}

/// Ex 9.10.2 as a constraint: "bead on a wire rotating at constant ω: ẍ = ω²x, reaction
/// 2mωẋ ĵ_B." Written in the plane with the rheonomic constraint −x sin ωt + y cos ωt = 0,
/// the radial motion agrees with the unconstrained route (T = ½m(ρ̇² + ω²ρ²),
/// [`accelerations`]) and with ρ̈ = ω²ρ, and the multiplier is −2mωρ̇ (the wire pushes with
/// +2mωρ̇ ĵ_B, ĵ_B = ∇φ).
#[test]
fn section_9_11_bead_on_turning_wire_matches_example_9_10_2() {
    struct Unconstrained(f64);
    impl Lagrangian for Unconstrained {
        fn dof(&self) -> usize {
            1
        }
        fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
            T::lit(0.5) * (qd[0] * qd[0] + T::lit(self.0 * self.0) * q[0] * q[0])
        }
    }
    let bead = BeadOnTurningWire { m: 1.0, w: 1.7 };
    for &(t, rho, rhod) in &[(0.0, 0.8, 0.2), (0.9, 1.5, -0.6), (3.1, -0.4, 2.0)] {
        let (c, s) = ((bead.w * t).cos(), (bead.w * t).sin());
        let q = [rho * c, rho * s];
        // q̇ = ρ̇ ê_r + ρω ê_θ, ê_r = (c, s), ê_θ = (−s, c)
        let qd = [rhod * c - rho * bead.w * s, rhod * s + rho * bead.w * c];
        let sol = constrained_accelerations(&bead, &q, &qd, t).unwrap();
        let (a_r, a_th) = (sol.qdd[0] * c + sol.qdd[1] * s, -sol.qdd[0] * s + sol.qdd[1] * c);
        // polar kinematics with θ̇ = ω, θ̈ = 0: a_r = ρ̈ − ρω², a_θ = 2ωρ̇
        let rho_dd = a_r + rho * bead.w * bead.w;
        let scale = bead.w * bead.w * rho.abs() + bead.w * rhod.abs();
        assert_abs(rho_dd, bead.w * bead.w * rho, 16.0 * EPS * scale);
        let unconstrained = accelerations(&Unconstrained(bead.w), &[rho], &[rhod], t).unwrap()[0];
        assert_abs(rho_dd, unconstrained, 16.0 * EPS * scale);
        assert_abs(a_th, 2.0 * bead.w * rhod, 16.0 * EPS * scale);
        assert_abs(sol.lambda[0], -2.0 * bead.m * bead.w * rhod, 16.0 * EPS * scale);
    }
}

/// A bead on a hoop turning about its vertical diameter at Ω, in Cartesian coordinates with
/// two constraints (one rheonomic). Closed form: θ̈ = sin θ (Ω² cos θ − g/R) with θ from the
/// downward vertical; the same from the Lagrangian in θ alone; and the hoop pushes the bead
/// sideways with the Coriolis force 2mΩRθ̇ cos θ ê_φ, so λ₂ = −2mΩRθ̇ cos θ.
#[test]
fn section_9_11_bead_on_rotating_hoop() {
    let bead = BeadOnHoop { m: 0.7, r: 0.5, w: 5.0, g: 9.81 };
    for &(t, th, thd) in &[(0.0, 0.3f64, 0.0), (0.37, 1.1, -2.0), (1.9, 2.8, 4.0), (0.1, -0.6, 1.5)] {
        let (cp, sp, ct, st) = ((bead.w * t).cos(), (bead.w * t).sin(), th.cos(), th.sin());
        let (e_r, e_th, e_ph) = ([st * cp, st * sp, -ct], [ct * cp, ct * sp, st], [-sp, cp, 0.0]);
        let q: Vec<f64> = e_r.iter().map(|e| bead.r * e).collect();
        let qd: Vec<f64> = (0..3).map(|k| bead.r * (thd * e_th[k] + bead.w * st * e_ph[k])).collect();
        let sol = constrained_accelerations(&bead, &q, &qd, t).unwrap();
        let dot = |e: &[f64; 3]| (0..3).map(|k| sol.qdd[k] * e[k]).sum::<f64>();
        let thdd = dot(&e_th) / bead.r + bead.w * bead.w * st * ct;
        let scale = bead.w * bead.w + thd * thd + bead.g / bead.r;
        assert_abs(thdd, st * (bead.w * bead.w * ct - bead.g / bead.r), 64.0 * EPS * scale);
        let route = accelerations(&HoopAngle(&bead), &[th], &[thd], t).unwrap()[0];
        assert_abs(thdd, route, 64.0 * EPS * scale);
        let coriolis = 2.0 * bead.m * bead.w * bead.r * thd * ct;
        assert_abs(sol.lambda[1], -coriolis, 64.0 * EPS * bead.m * bead.r * scale);
    }
}

/// Cartesian (q̈, λ) of the double pendulum from its joint-coordinate motion: Newton's law on
/// each particle gives the rod tensions T₂ = m₂(g⃗ − a⃗₂)·ê₂, T₁ = (m₁(g⃗ − a⃗₁) + T₂ê₂)·ê₁.
fn double_pendulum_from_joints(
    p: &CartesianDoublePendulum,
    th: [f64; 2],
    w: [f64; 2],
) -> ([f64; 4], [f64; 4], [f64; 4], [f64; 2]) {
    let alpha = accelerations(&JointDoublePendulum(p), &th, &w, 0.0).unwrap();
    let ((s1, c1), (s2, c2)) = (th[0].sin_cos(), th[1].sin_cos());
    let (l1, l2) = (p.l1, p.l2);
    let q = [l1 * s1, -l1 * c1, l1 * s1 + l2 * s2, -l1 * c1 - l2 * c2];
    let qd =
        [l1 * c1 * w[0], l1 * s1 * w[0], l1 * c1 * w[0] + l2 * c2 * w[1], l1 * s1 * w[0] + l2 * s2 * w[1]];
    // a⃗₁ and a⃗_{2/1} of circular motion: l(θ̈ ê_θ − θ̇² ê_r)
    let a1 = [l1 * (c1 * alpha[0] - s1 * w[0] * w[0]), l1 * (s1 * alpha[0] + c1 * w[0] * w[0])];
    let a21 = [l2 * (c2 * alpha[1] - s2 * w[1] * w[1]), l2 * (s2 * alpha[1] + c2 * w[1] * w[1])];
    let qdd = [a1[0], a1[1], a1[0] + a21[0], a1[1] + a21[1]];
    // ê₁, ê₂: unit vectors along the rods, pivot → m₁ and m₁ → m₂
    let (e1, e2) = ([s1, -c1], [s2, -c2]);
    let along = |v: [f64; 2], e: [f64; 2]| v[0] * e[0] + v[1] * e[1];
    let t2 = p.m2 * along([-qdd[2], -p.g - qdd[3]], e2);
    let t1 = along([-p.m1 * qdd[0] + t2 * e2[0], p.m1 * (-p.g - qdd[1]) + t2 * e2[1]], e1);
    (q, qd, qdd, [t1, t2])
}

/// §9.11: a double pendulum written as two particles with two rod constraints agrees with
/// the joint-coordinate Lagrangian to 1e-12 in the accelerations, and its multipliers are the
/// rod tensions given by Newton's law.
#[test]
fn section_9_11_double_pendulum_cartesian_vs_joint_coordinates() {
    let p = CartesianDoublePendulum { m1: 1.2, m2: 0.7, l1: 1.0, l2: 0.6, g: 9.81 };
    for &(th, thd) in &[
        ([0.3, -0.5], [0.0, 0.0]),
        ([2.0, 0.1], [1.5, -3.0]),
        ([-2.9, 2.9], [-4.0, 6.0]),
        ([PI, 0.0], [0.2, 0.0]),
    ] {
        let (q, qd, qdd, tension) = double_pendulum_from_joints(&p, th, thd);
        let s = constrained_accelerations(&p, &q, &qd, 0.0).unwrap();
        for (got, want) in s.qdd.iter().zip(qdd) {
            assert_abs(*got, want, 1e-12);
        }
        for (got, want) in s.lambda.iter().zip(tension) {
            assert_abs(*got, want, 1e-12 * (1.0 + want.abs()));
        }
    }
}

/// The same double pendulum by Newton–Euler: a two-link chain of point masses on pins
/// (vectrix's articulated-body algorithm, §7.11, joint angles relative) gives the Cartesian
/// accelerations of the constrained particles.
#[test]
fn section_9_11_double_pendulum_cartesian_vs_newton_euler_chain() {
    use vectrix::dynamics::multibody::{Joint, Link, Model};
    use vectrix::nalgebra::{Matrix3, Vector3};
    let p = CartesianDoublePendulum { m1: 1.2, m2: 0.7, l1: 1.0, l2: 0.6, g: 9.81 };
    let pin = Joint::Pin { axis: Vector3::z() };
    let links = [
        Link::new(None, pin, Vector3::zeros(), p.m1, Vector3::new(0.0, -p.l1, 0.0), Matrix3::zeros()),
        Link::new(
            Some(0),
            pin,
            Vector3::new(0.0, -p.l1, 0.0),
            p.m2,
            Vector3::new(0.0, -p.l2, 0.0),
            Matrix3::zeros(),
        ),
    ];
    let mut chain = Model::new(&links).unwrap();
    chain.gravity = Vector3::new(0.0, -p.g, 0.0);
    for &(th, w) in &[([0.3, -0.5], [0.0, 0.0]), ([2.0, 0.1], [1.5, -3.0]), ([-2.9, 2.9], [-4.0, 6.0])] {
        let (q, qd, _, _) = double_pendulum_from_joints(&p, th, w);
        let rel = [th[0], th[1] - th[0]];
        let alpha = chain.aba(&rel, &[w[0], w[1] - w[0]], &[0.0, 0.0], None).unwrap();
        let (a1, a2) = (alpha[0], alpha[0] + alpha[1]);
        let ((s1, c1), (s2, c2)) = (th[0].sin_cos(), th[1].sin_cos());
        let ax1 = [p.l1 * (c1 * a1 - s1 * w[0] * w[0]), p.l1 * (s1 * a1 + c1 * w[0] * w[0])];
        let want = [
            ax1[0],
            ax1[1],
            ax1[0] + p.l2 * (c2 * a2 - s2 * w[1] * w[1]),
            ax1[1] + p.l2 * (s2 * a2 + c2 * w[1] * w[1]),
        ];
        let s = constrained_accelerations(&p, &q, &qd, 0.0).unwrap();
        for (got, want) in s.qdd.iter().zip(want) {
            assert_abs(*got, want, 1e-12);
        }
    }
}

/// Bad input: initial conditions off the constraint manifold are an error naming the
/// violation, unless projection of the initial state is asked for.
#[test]
fn section_9_11_inconsistent_initial_conditions() {
    let p = ParticlePendulum { m: 1.0, l: 1.0, g: 9.81 };
    let integrator = ConstrainedIntegrator::new(Adaptive::dopri5().rtol(1e-10).atol(1e-10));
    // 1 mm too long, and moving along the rod
    let (q0, qd0) = ([0.0, -1.001], [0.5, 0.1]);
    let err = integrator.integrate(&LagrangeForm(&p), &q0, &qd0, 0.0, 1.0).unwrap_err();
    match err {
        DynamicsError::InconsistentInitialConditions { position, velocity, tol } => {
            assert_abs(position, 1e-3, 1e-15);
            assert_abs(velocity, 0.1, 1e-15);
            assert_eq!(tol, 1e-10);
        }
        e => panic!("{e}"),
    }
    let projected = ConstrainedIntegrator { project_initial: true, ..integrator };
    let run = projected.integrate(&LagrangeForm(&p), &q0, &qd0, 0.0, 1.0).unwrap();
    assert!(run.projections >= 1);
    // projected onto |r| = 1 (from straight below, along the rod) with q̇ ⊥ r
    assert_abs(run.q(0)[1], -1.0, 1e-12);
    assert_abs(run.qd(0)[1], 0.0, 1e-12);
    assert!(run.max_constraint_violation.position <= 1e-12);
}

/// Bad input: a constraint stated twice (|r| − l and |r|² − l², the same circle) is
/// redundant; the error names row 1 as dependent on row 0.
#[test]
fn section_9_11_redundant_constraint_names_the_row() {
    struct Twice(ParticlePendulum);
    impl Lagrangian for Twice {
        fn dof(&self) -> usize {
            2
        }
        fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], t: T) -> T {
            self.0.kinetic(q, qd, t)
        }
    }
    impl Constraints for Twice {
        fn constraint_count(&self) -> usize {
            2
        }
        fn constraints<T: Scalar>(&self, q: &[T], t: T, out: &mut [T]) {
            self.0.constraints(q, t, &mut out[..1]);
            out[1] = q[0] * q[0] + q[1] * q[1] - T::lit(self.0.l * self.0.l);
        }
    }
    let sys = Twice(ParticlePendulum { m: 1.0, l: 1.0, g: 9.81 });
    let (q, qd) = pendulum_state(1.0, 0.7, 0.3);
    match constrained_accelerations(&sys, &q, &qd, 0.0).unwrap_err() {
        DynamicsError::DependentConstraint { row, depends_on, residual, tol } => {
            assert_eq!((row, depends_on), (1, vec![0]));
            assert!(residual <= tol && tol == DEPENDENT_ROW_REL_TOL);
        }
        e => panic!("{e}"),
    }
}

/// Bad input: a singular constraint. φ = (|r| − l)² has the right zero set but no gradient on
/// it; and the parallelogram four-bar folded flat (all links on the ground line) has a
/// loop-closure row with zero gradient. Both name row 0.
#[test]
fn section_9_11_singular_constraint_names_the_row() {
    struct Squared(ParticlePendulum);
    impl Lagrangian for Squared {
        fn dof(&self) -> usize {
            2
        }
        fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], t: T) -> T {
            self.0.kinetic(q, qd, t)
        }
    }
    impl Constraints for Squared {
        fn constraint_count(&self) -> usize {
            1
        }
        fn constraints<T: Scalar>(&self, q: &[T], t: T, out: &mut [T]) {
            self.0.constraints(q, t, out);
            out[0] = out[0] * out[0];
        }
    }
    let sys = Squared(ParticlePendulum { m: 1.0, l: 1.0, g: 9.81 });
    let err = constrained_accelerations(&sys, &[0.0, -1.0], &[0.3, 0.0], 0.0).unwrap_err();
    assert!(matches!(err, DynamicsError::SingularConstraint { row: 0, .. }), "{err}");

    let flat = FourBar { a: 1.0, b: 2.0, c: 1.0, d: 2.0, rho: 1.0, g: 9.81 };
    let err = map_constrained_accelerations(&flat, &[0.0, 0.0, 0.0], &[0.0; 3], 0.0).unwrap_err();
    assert!(matches!(err, DynamicsError::SingularConstraint { row: 0, .. }), "{err}");
}

/// Bad input: more constraints than coordinates, non-finite states, wrong lengths, and the
/// plain-matrix core's checks.
#[test]
fn section_9_11_bad_input_is_typed() {
    struct Three;
    impl Lagrangian for Three {
        fn dof(&self) -> usize {
            2
        }
        fn kinetic<T: Scalar>(&self, _q: &[T], qd: &[T], _t: T) -> T {
            qd[0] * qd[0] + qd[1] * qd[1]
        }
    }
    impl Constraints for Three {
        fn constraint_count(&self) -> usize {
            3
        }
    }
    let err = constrained_accelerations(&Three, &[0.0; 2], &[0.0; 2], 0.0).unwrap_err();
    assert_eq!(err, DynamicsError::TooManyConstraints { count: 3, dof: 2 });
    let p = ParticlePendulum { m: 1.0, l: 1.0, g: 9.81 };
    let err = constrained_accelerations(&p, &[f64::NAN, -1.0], &[0.0; 2], 0.0).unwrap_err();
    assert!(matches!(err, DynamicsError::NonFinite { .. }), "{err}");
    let err = constrained_accelerations(&p, &[0.0, -1.0, 0.0], &[0.0; 2], 0.0).unwrap_err();
    assert!(matches!(err, DynamicsError::DimensionMismatch { .. }), "{err}");
    // the core on plain matrices
    let m = DMatrix::identity(2, 2);
    let g = DMatrix::from_row_slice(1, 2, &[1.0, 0.0]);
    let (f, gamma) = (DVector::from_vec(vec![1.0, 2.0]), DVector::from_vec(vec![0.5]));
    let s = solve_kkt(&m, &g, &f, &gamma, DEPENDENT_ROW_REL_TOL).unwrap();
    // x₁ = γ = 0.5, λ = f₁ − x₁ = 0.5, x₂ = f₂
    assert_eq!((s.x[0], s.x[1], s.lambda[0]), (0.5, 2.0, 0.5));
    let not_spd = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 0.0, -1.0]);
    let err = solve_kkt(&not_spd, &g, &f, &gamma, DEPENDENT_ROW_REL_TOL).unwrap_err();
    assert!(matches!(err, DynamicsError::SingularMassMatrix { .. }), "{err}");
    let three = DMatrix::from_row_slice(3, 2, &[1.0, 0.0, 0.0, 1.0, 1.0, 1.0]);
    let err = solve_kkt(&m, &three, &f, &DVector::zeros(3), DEPENDENT_ROW_REL_TOL).unwrap_err();
    assert_eq!(
        err,
        DynamicsError::DependentConstraint {
            row: 2,
            depends_on: vec![0, 1],
            residual: 0.0,
            tol: DEPENDENT_ROW_REL_TOL
        }
    );
    let err = solve_kkt(&m, &g, &f, &gamma, 0.0).unwrap_err();
    assert!(matches!(err, DynamicsError::OutOfRange { .. }), "{err}");
    let err = solve_kkt(&m, &g, &f, &DVector::zeros(2), DEPENDENT_ROW_REL_TOL).unwrap_err();
    assert!(matches!(err, DynamicsError::DimensionMismatch { .. }), "{err}");
}

mod prop {
    use proptest::prelude::*;

    use super::*;

    /// Angles biased toward the hard set (hanging, inverted, ±π) and rates.
    fn angle() -> impl Strategy<Value = f64> {
        prop_oneof![Just(0.0), Just(PI), Just(-PI), Just(PI - 1e-8), Just(1e-8), -PI..PI]
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// On every state of the manifold, the Cartesian double pendulum agrees with the
        /// joint-coordinate route, its accelerations satisfy Φ_q q̈ = γ, and the constraint
        /// force does no work on admissible velocities (q̇ᵀΦ_qᵀλ = 0, scleronomic φ).
        #[test]
        fn double_pendulum_agrees_on_random_states(
            th1 in angle(), th2 in angle(), w1 in -6.0..6.0f64, w2 in -6.0..6.0f64,
            m1 in 0.1..3.0f64, m2 in 0.1..3.0f64,
        ) {
            let p = CartesianDoublePendulum { m1, m2, l1: 1.0, l2: 0.6, g: 9.81 };
            let (q, qd, qdd, tension) = double_pendulum_from_joints(&p, [th1, th2], [w1, w2]);
            let s = constrained_accelerations(&p, &q, &qd, 0.0).unwrap();
            // accelerations up to ~ (1 + m1/m2)(g + lω²) ≈ 10³ in the worst draws
            let scale = (1.0 + m1 / m2 + m2 / m1) * (p.g + w1 * w1 + w2 * w2);
            for (got, want) in s.qdd.iter().zip(qdd) {
                prop_assert!((got - want).abs() <= 1e-13 * scale, "{} vs {}", got, want);
            }
            for (got, want) in s.lambda.iter().zip(tension) {
                prop_assert!((got - want).abs() <= 1e-13 * scale * (m1 + m2));
            }
            let residual = &s.terms.jacobian * &s.qdd - &s.terms.gamma;
            prop_assert!(residual.nan_amax() <= 1e-13 * scale);
            let power = DVector::from_column_slice(&qd).dot(&(s.terms.jacobian.transpose() * &s.lambda));
            prop_assert!(power.abs() <= 1e-13 * scale * (m1 + m2) * (w1.abs() + w2.abs() + 1.0));
        }
    }
}
