//! Property tests for chapter 7: RNEA ∘ ABA = identity on random trees and states, ABA = CRBA,
//! the analytical derivatives of ABA against dual numbers on random trees, the spherical
//! pendulum at the hard attitudes, momenta of rigid particle sets, and collisions.

use proptest::prelude::*;
use vectrix::dynamics::multibody::{Joint, Link, Model};
use vectrix::dynamics::restitution_1d;
use vectrix::nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};
use vectrix::num_dual::Dual64;
use vectrix::prelude::*;
use vectrix::statics::{MassProperties, Point};

use crate::multibody::{pendulum_motion, spherical_pendulum};
use crate::support::{EPS, NanAmax, nan_max, triple};

fn joint() -> impl Strategy<Value = Joint> {
    let axis = || triple().prop_filter("nonzero", |a| Vector3::from(*a).norm() > 0.1).prop_map(Vector3::from);
    prop_oneof![
        4 => axis().prop_map(|axis| Joint::Pin { axis }),
        1 => axis().prop_map(|axis| Joint::Sleeve { axis }),
        1 => axis().prop_map(|axis| Joint::Collar { axis }),
        1 => axis().prop_map(|a| {
            // a direction ⊥ a: a × (any vector not parallel to a)
            let d = a.cross(&if a.x.abs() < 0.9 * a.norm() { Vector3::x() } else { Vector3::y() });
            Joint::Slot { axis: a, direction: d }
        }),
        1 => Just(Joint::Ball),
        1 => Just(Joint::Weld),
    ]
}

fn link(parent_choice: f64, index: usize) -> impl Strategy<Value = Link> {
    (joint(), triple(), 0.2..3.0f64, triple(), [0.1..1.0f64, 0.1..1.0f64, 0.1..1.0f64], triple(), triple())
        .prop_map(move |(joint, offset, mass, com, l, rot, orient)| {
            // principal moments satisfying the triangle inequality: λ = a + b style sums
            let lam = Vector3::new(l[1] + l[2], l[0] + l[2], l[0] + l[1]);
            let r = Rotation3::from_scaled_axis(Vector3::from(rot) * 0.3).into_inner();
            let parent = if index == 0 {
                None
            } else {
                Some(((parent_choice * index as f64) as usize).min(index - 1))
            };
            let mut link = Link::new(
                parent,
                joint,
                Vector3::from(offset) * 0.1,
                mass,
                Vector3::from(com) * 0.05,
                r * Matrix3::from_diagonal(&lam) * r.transpose(),
            );
            link.orientation = Rotation3::from_scaled_axis(Vector3::from(orient) * 0.3).into_inner();
            link
        })
}

fn tree() -> impl Strategy<Value = Model> {
    (1usize..9, prop::collection::vec(0.0..1.0f64, 9)).prop_flat_map(|(n, choices)| {
        (0..n).map(|i| link(choices[i], i)).collect::<Vec<_>>().prop_map(|links| {
            let mut m = Model::new(&links).expect("valid random tree");
            m.gravity = Vector3::new(0.0, 0.0, -9.81);
            m
        })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// §7.11: inverse dynamics undoes forward dynamics, RNEA(q, v, ABA(q, v, τ)) = τ, and the
    /// O(n) ABA agrees with CRBA + Cholesky.
    #[test]
    fn rnea_after_aba_is_identity(model in tree(), seed in prop::collection::vec(-1.0..1.0f64, 64)) {
        let mut q = model.neutral();
        for (k, x) in q.iter_mut().enumerate() {
            *x += 2.0 * seed[k % 64];
        }
        let v: Vec<f64> = (0..model.nv()).map(|k| 3.0 * seed[(k + 17) % 64]).collect();
        let tau: Vec<f64> = (0..model.nv()).map(|k| 5.0 * seed[(k + 33) % 64]).collect();
        let a = model.aba(&q, &v, &tau, None).unwrap();
        let back = model.rnea(&q, &v, &a, None).unwrap().tau;
        let scale = 1.0 + tau.iter().chain(&a).fold(0.0f64, |m, x| nan_max(m, x.abs()));
        for (x, y) in back.iter().zip(&tau) {
            // ill-conditioned random trees: relative 1e-8 of the largest term
            prop_assert!((x - y).abs() <= 1e-8 * scale, "{back:?} vs {tau:?}");
        }
        let a2 = model.forward_dynamics_crba(&q, &v, &tau, None).unwrap();
        let sa = 1.0 + a.iter().fold(0.0f64, |m, x| nan_max(m, x.abs()));
        for (x, y) in a.iter().zip(&a2) {
            prop_assert!((x - y).abs() <= 1e-7 * sa, "{a:?} vs {a2:?}");
        }
    }

    /// The analytical ∂v̇/∂q and ∂v̇/∂v of ABA (module `derivatives`) equal forward-mode dual
    /// numbers through the generic ABA (one `Dual64` pass per tangent direction, q ⊕ ε eₖ),
    /// on random trees of every joint type and random states.
    #[test]
    fn aba_derivatives_equal_dual_numbers(model in tree(), seed in prop::collection::vec(-1.0..1.0f64, 64)) {
        let mut q = model.neutral();
        for (k, x) in q.iter_mut().enumerate() {
            *x += seed[k % 64];
        }
        let n = model.nv();
        // an all-weld tree has no coordinates and nothing to differentiate
        prop_assume!(n > 0);
        let v: Vec<f64> = (0..n).map(|k| 2.0 * seed[(k + 17) % 64]).collect();
        let tau: Vec<f64> = (0..n).map(|k| 3.0 * seed[(k + 33) % 64]).collect();
        let d = model.aba_derivatives(&q, &v, &tau, None).unwrap();
        let dual = model.cast::<Dual64>();
        let lift = |x: &[f64]| x.iter().map(|&x| Dual64::from(x)).collect::<Vec<_>>();
        let h = model.crba(&q).unwrap();
        let eig = h.symmetric_eigen().eigenvalues;
        let cond = eig.max() / eig.min();
        // Each entry is a sum of terms of the size of gravity and the accelerations (links of
        // O(1) length) that can cancel (a single hinge: ∂v̇/∂q = 0.0167 from terms near 10), so the
        // rounding scale is the largest of those, not the entry.
        let a0 = model.aba(&q, &v, &tau, None).unwrap();
        let scale = nan_max(
            a0.iter().fold(9.81f64, |m, x| nan_max(m, x.abs())),
            nan_max(d.dvdot_dq.nan_amax(), d.dvdot_dv.nan_amax()),
        );
        for k in 0..n {
            let mut e = lift(&vec![0.0; n]);
            e[k].eps = 1.0;
            let qk = dual.integrate(&lift(&q), &e, Dual64::from(1.0)).unwrap();
            let aq = dual.aba(&qk, &lift(&v), &lift(&tau), None).unwrap();
            let mut vk = lift(&v);
            vk[k].eps = 1.0;
            let av = dual.aba(&lift(&q), &vk, &lift(&tau), None).unwrap();
            for r in 0..n {
                // both are exact to rounding: ε κ(M) of the largest entry, 1024 for the
                // random trees' depth and the dual route's longer expressions
                prop_assert!((aq[r].eps - d.dvdot_dq[(r, k)]).abs() <= 1024.0 * EPS * cond * scale, "dq {} vs {} cond {cond} scale {scale}", aq[r].eps, d.dvdot_dq[(r, k)]);
                prop_assert!((av[r].eps - d.dvdot_dv[(r, k)]).abs() <= 1024.0 * EPS * cond * scale, "dv {} vs {} cond {cond} scale {scale}", av[r].eps, d.dvdot_dv[(r, k)]);
            }
        }
    }

    /// The spherical pendulum at the hard attitudes (hanging straight down θ = 0, tiny θ,
    /// horizontal, nearly and exactly inverted θ = π): ABA with its singular joint inertia
    /// gives the closed form p̈ = g − (g·p̂)p̂ − (|ṗ|²/L²) p and no spin acceleration.
    #[test]
    fn spherical_pendulum_at_hard_attitudes(
        theta in prop_oneof![Just(0.0), Just(1e-300), Just(1e-8), Just(std::f64::consts::FRAC_PI_2),
                             Just(std::f64::consts::PI - 1e-8), Just(std::f64::consts::PI), 0.0..std::f64::consts::PI],
        azimuth in -3.0..3.0f64, spin in -3.0..3.0f64, w in triple(),
    ) {
        let (l, g) = (0.6, 9.81);
        let model = spherical_pendulum(0.7, l, g);
        // attitude: tilt θ about the horizontal axis at the azimuth, then any spin about the rod
        let axis = Vector3::new(-azimuth.sin(), azimuth.cos(), 0.0);
        let uq = UnitQuaternion::from_scaled_axis(axis * theta) * UnitQuaternion::from_scaled_axis(Vector3::z() * spin);
        let q = [uq.w, uq.i, uq.j, uq.k];
        let w = Vector3::from(w) * 0.3;
        let [p, pd, pdd, wd] = pendulum_motion(&model, &q, &w, l);
        let gv = Vector3::new(0.0, 0.0, -g);
        let want = gv - p * (gv.dot(&p) / (l * l)) - p * (pd.norm_squared() / (l * l));
        let tol = 64.0 * EPS * (g + l * w.norm_squared());
        prop_assert!((pdd - want).norm() <= tol, "{pdd} vs {want}");
        prop_assert!(wd.z.abs() <= tol / l);
    }

    /// (7.6.10), (8.1.19): a rigid set of particles moving with (v_c, ω) has momentum m v_c,
    /// angular momentum about any moving point z equal to Σ r_{y/z} × m v_{y/z}, and kinetic
    /// energy Σ ½ m|v|².
    #[test]
    fn rigid_particle_set_momenta(
        pts in prop::collection::vec(([0.1..2.0f64], triple()), 2..6),
        v_c in triple(), omega in triple(), z in triple(), v_z in triple(),
    ) {
        let a = Frame::new();
        let parts: Vec<(f64, Point)> = pts.iter().map(|(m, r)| (m[0], Point::at(a.vector(*r)))).collect();
        let props = MassProperties::from_particles(&parts).unwrap();
        let body = RigidBody::new(props, a.vector(v_c), a.vector(omega));
        let (z, v_z) = (Point::at(a.vector(z)), a.vector(v_z));
        let (mut h, mut p, mut t) = (Vector::zero(), Vector::zero(), 0.0);
        for (m, y) in &parts {
            let v = body.velocity_of(y);
            p += v * *m;
            h += y.position_rel(&z).cross(&((v - v_z) * *m));
            t += 0.5 * m * v.norm_squared();
        }
        let scale = 1.0 + 100.0 * (1.0 + body.v_c.norm() + body.omega.norm()).powi(2);
        prop_assert!((body.momentum() - p).norm() <= 1e-12 * scale);
        prop_assert!((body.angular_momentum_about(&z, &v_z) - h).norm() <= 1e-12 * scale * 10.0);
        prop_assert!((body.kinetic_energy() - t).abs() <= 1e-12 * scale);
    }

    /// Fact 7.13.1: momentum is conserved and the kinetic energy lost is ½(1−e²)μ(u1−u2)² ≥ 0.
    #[test]
    fn collisions_conserve_momentum(m1 in 0.1..10.0f64, m2 in 0.1..10.0f64, u1 in -5.0..5.0f64, du in 0.01..5.0f64, e in 0.0..=1.0f64) {
        let u2 = u1 - du;
        let (a, b) = restitution_1d(m1, m2, u1, u2, e).unwrap();
        let scale = (m1 + m2) * (u1.abs() + u2.abs() + 1.0);
        prop_assert!((m1 * a + m2 * b - m1 * u1 - m2 * u2).abs() <= 1e-14 * scale);
        let lost = 0.5 * m1 * (u1 * u1 - a * a) + 0.5 * m2 * (u2 * u2 - b * b);
        let want = vectrix::dynamics::collision_energy_loss(m1, m2, u1, u2, e).unwrap();
        prop_assert!((lost - want).abs() <= 1e-12 * scale * scale);
        prop_assert!(b - a >= -1e-12 * scale);
    }
}
