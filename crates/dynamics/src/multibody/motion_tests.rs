//! The velocity maps of `motion.rs` against closed forms (a double pendulum, a pin on a turning
//! pin with a slider, a ball turning at a constant rate), and on a tree with every joint type
//! against the time derivatives of the body-frame route ([`Model::twists`], [`Model::integrate`])
//! taken by dual numbers along the motion.

use nalgebra::{Matrix3, Vector3};
use num_dual::Dual64;

use super::*;
use crate::multibody::{Joint, Link};

/// Largest |a − b| over the components, NaN-propagating (a NaN anywhere gives NaN, which fails
/// every `<=` check).
fn gap(a: &Vector3<f64>, b: &Vector3<f64>) -> f64 {
    (a - b).iter().fold(0.0, |m: f64, x| if x.is_nan() || m.is_nan() { f64::NAN } else { m.max(x.abs()) })
}

fn link(parent: Option<usize>, joint: Joint, offset: [f64; 3]) -> Link {
    Link::new(
        parent,
        joint,
        Vector3::from(offset),
        1.0,
        Vector3::new(0.1, 0.0, 0.0),
        Matrix3::identity() * 0.1,
    )
}

fn twists_and_bias(m: &Model, q: &[f64], v: &[f64]) -> (Vec<LinkTwist>, Vec<LinkAcceleration>) {
    let (mut world, mut poses, mut s) = (PosesScratch::default(), Vec::new(), MotionScratch::default());
    m.poses_into(q, &mut world, &mut poses);
    let (mut tw, mut acc) = (Vec::new(), Vec::new());
    m.twists_into(&world, v, &mut s, &mut tw);
    m.bias_accelerations_into(&world, v, &mut s, &mut acc);
    (tw, acc)
}

/// Planar double pendulum, pins about ẑ, link 2 hinged at (l₁, 0, 0) of link 1: ω₁ = θ̇₁ẑ,
/// ω₂ = (θ̇₁ + θ̇₂)ẑ, r₂ = l₁(cos θ₁, sin θ₁, 0), v₂ = θ̇₁ ẑ × r₂; at v̇ = 0 both α vanish
/// (parallel axes) and the hinge accelerates centripetally, a₂ = −θ̇₁² r₂.
#[test]
fn double_pendulum_closed_form() {
    let l1 = 0.7;
    let m = Model::new(&[
        link(None, Joint::Pin { axis: Vector3::z() }, [0.0; 3]),
        link(Some(0), Joint::Pin { axis: Vector3::z() }, [l1, 0.0, 0.0]),
    ])
    .unwrap();
    let (th1, a, b) = (0.4_f64, 1.3, -0.6);
    let (tw, acc) = twists_and_bias(&m, &[th1, 1.1], &[a, b]);
    let r2 = Vector3::new(th1.cos(), th1.sin(), 0.0) * l1;
    let tol = 4.0 * f64::EPSILON;
    assert!(gap(&tw[0].omega, &Vector3::new(0.0, 0.0, a)) <= tol);
    assert!(gap(&tw[0].velocity, &Vector3::zeros()) <= tol);
    assert!(gap(&tw[1].omega, &Vector3::new(0.0, 0.0, a + b)) <= tol);
    assert!(gap(&tw[1].velocity, &(Vector3::z() * a).cross(&r2)) <= tol);
    assert!(
        gap(&acc[0].alpha, &Vector3::zeros()) <= tol && gap(&acc[0].acceleration, &Vector3::zeros()) <= tol
    );
    assert!(gap(&acc[1].alpha, &Vector3::zeros()) <= tol);
    assert!(gap(&acc[1].acceleration, &(-r2 * (a * a))) <= tol, "{:?}", acc[1]);
}

/// A pin about ẑ (rate a, angle θ), a pin about the first link's x̂ at (l, 0, 0) (rate b, at
/// angle 0), and a slider along the second link's ŷ (at s, rate ṡ). With x̂₁ = (c, s_θ, 0) and
/// ŷ₁ = (−s_θ, c, 0) the ground axes of link 1 (the second link is not yet turned, so its axes
/// are link 1's): ω₂ = aẑ + b x̂₁, α₂ = aẑ × b x̂₁; the hinge r₂ = l x̂₁ has a₂ = −a² r₂; the
/// slider's origin ρ = s ŷ₁ from the hinge moves with v_rel = ṡ ŷ₁ and accelerates by
/// a₃ = a₂ + α₂ × ρ + ω₂ × (ω₂ × ρ) + 2 ω₂ × v_rel (§5, Coriolis).
#[test]
fn pin_on_a_turning_pin_with_a_slider_closed_form() {
    let l = 0.5;
    let m = Model::new(&[
        link(None, Joint::Pin { axis: Vector3::z() }, [0.0; 3]),
        link(Some(0), Joint::Pin { axis: Vector3::x() }, [l, 0.0, 0.0]),
        link(Some(1), Joint::Sleeve { axis: Vector3::y() }, [0.0; 3]),
    ])
    .unwrap();
    let (th, a, b, s, sd) = (0.3_f64, 0.9, -1.7, 0.25, 0.8);
    let (tw, acc) = twists_and_bias(&m, &[th, 0.0, s], &[a, b, sd]);
    let (x1, y1) = (Vector3::new(th.cos(), th.sin(), 0.0), Vector3::new(-th.sin(), th.cos(), 0.0));
    let w2 = Vector3::z() * a + x1 * b;
    let al2 = (Vector3::z() * a).cross(&(x1 * b));
    let a2 = -x1 * (l * a * a);
    let (rho, vrel) = (y1 * s, y1 * sd);
    let a3 = a2 + al2.cross(&rho) + w2.cross(&w2.cross(&rho)) + w2.cross(&vrel) * 2.0;
    let v3 = (Vector3::z() * a).cross(&(x1 * l)) + w2.cross(&rho) + vrel;
    let tol = 8.0 * f64::EPSILON;
    assert!(gap(&tw[1].omega, &w2) <= tol && gap(&tw[2].omega, &w2) <= tol);
    assert!(gap(&tw[2].velocity, &v3) <= tol, "{:?} vs {v3:?}", tw[2].velocity);
    assert!(gap(&acc[1].alpha, &al2) <= tol && gap(&acc[2].alpha, &al2) <= tol);
    assert!(gap(&acc[1].acceleration, &a2) <= tol);
    assert!(gap(&acc[2].acceleration, &a3) <= tol, "{:?} vs {a3:?}", acc[2].acceleration);
}

/// A ball turning at a constant rate ω about ẑ from the identity: q(t) = (cos(ωt/2), 0, 0,
/// sin(ωt/2)), so q̇ = (−ω/2 sin(ωt/2), 0, 0, ω/2 cos(ωt/2)) (§2.15); a free joint's q̇ starts
/// with its translation rates; pins pass v through.
#[test]
fn qdot_of_a_ball_turning_about_z_closed_form() {
    let m = Model::new(&[
        link(None, Joint::Free, [0.0; 3]),
        link(Some(0), Joint::Ball, [0.0, 0.0, 1.0]),
        link(Some(1), Joint::Pin { axis: Vector3::y() }, [0.3, 0.0, 0.0]),
    ])
    .unwrap();
    let (w, t) = (1.9_f64, 0.7);
    let (s, c) = (w * t / 2.0).sin_cos();
    let q = [1.0, 2.0, 3.0, 1.0, 0.0, 0.0, 0.0, c, 0.0, 0.0, s, 0.4];
    let v = [0.5, -0.25, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0, w, -1.5];
    let mut qd = [f64::NAN; 12];
    m.qdot_into(&q, &v, &mut qd);
    let want = [0.5, -0.25, 2.0, 0.0, 0.0, 0.0, 0.0, -w / 2.0 * s, 0.0, 0.0, w / 2.0 * c, -1.5];
    for (k, (g, x)) in qd.iter().zip(&want).enumerate() {
        assert!((g - x).abs() <= 2.0 * f64::EPSILON, "q̇[{k}] = {g}, expected {x}");
    }
}

/// Ball quaternions are divided by their norm; the other coordinates are left as they are.
#[test]
fn normalize_quaternions_touches_only_balls() {
    let m = Model::new(&[
        link(None, Joint::Pin { axis: Vector3::z() }, [0.0; 3]),
        link(Some(0), Joint::Free, [0.0; 3]),
    ])
    .unwrap();
    let mut q = [3.0, 7.0, 8.0, 9.0, 0.0, 1.2, 0.0, 1.6];
    m.normalize_quaternions(&mut q);
    assert_eq!(&q[..4], &[3.0, 7.0, 8.0, 9.0]);
    assert!((q[5] - 0.6).abs() <= f64::EPSILON && (q[7] - 0.8).abs() <= f64::EPSILON && q[4] == 0.0);
}

/// A tree with every joint type, rotated joint frames and an oblique pin.
fn tree() -> Model {
    let mut links = vec![
        link(None, Joint::Free, [0.1, 0.0, 0.2]),
        link(Some(0), Joint::Pin { axis: Vector3::new(1.0, 2.0, 0.5) }, [0.5, 0.0, 0.0]),
        link(Some(1), Joint::Sleeve { axis: Vector3::x() }, [0.0, 0.4, 0.0]),
        link(Some(0), Joint::Collar { axis: Vector3::z() }, [0.0, -0.5, 0.1]),
        link(Some(3), Joint::Slot { axis: Vector3::z(), direction: Vector3::y() }, [0.3, 0.0, 0.0]),
        link(Some(4), Joint::Ball, [0.0, 0.0, 0.6]),
        link(Some(5), Joint::Weld, [0.2, 0.2, 0.0]),
        link(Some(6), Joint::Free, [0.0, 0.3, 0.1]),
    ];
    for (k, l) in links.iter_mut().enumerate() {
        let k = k as f64;
        l.orientation = nalgebra::Rotation3::from_scaled_axis(Vector3::new(0.2 * k, -0.1, 0.3)).into_inner();
    }
    Model::new(&links).unwrap()
}

/// Twists agree with the body-frame route [`Model::twists`], and the bias accelerations and
/// q̇ with the time derivatives, taken exactly by dual numbers, of that route's twists and of
/// the retraction q ⊕ v t ([`Model::integrate`]) along the motion with v̇ = 0.
#[test]
fn every_joint_against_derivatives_of_the_body_frame_route() {
    let m = tree();
    let mut q = m.neutral();
    for (k, x) in q.iter_mut().enumerate() {
        *x += 0.1 * (k as f64 + 1.0).sin();
    }
    m.normalize_quaternions(&mut q);
    let v: Vec<f64> = (0..m.nv()).map(|k| 0.7 * (1.3 * k as f64 + 0.5).cos()).collect();
    let (tw, acc) = twists_and_bias(&m, &q, &v);
    let reference = m.twists(&q, &v).unwrap();
    let d = m.cast::<Dual64>();
    let q0: Vec<Dual64> = q.iter().map(|&x| Dual64::from(x)).collect();
    let step: Vec<Dual64> = v.iter().map(|&x| Dual64::new(0.0, x)).collect();
    let qe = d.integrate(&q0, &step, Dual64::from(1.0)).unwrap();
    let ve: Vec<Dual64> = v.iter().map(|&x| Dual64::from(x)).collect();
    let moving = d.twists(&qe, &ve).unwrap();
    // scale of the numbers compared: |v| ≤ 0.7, lever arms ≤ 2 m: 1e-14 is a few hundred ulps
    let tol = 1e-14;
    for (k, ((t, r), (a, dm))) in tw.iter().zip(&reference).zip(acc.iter().zip(&moving)).enumerate() {
        assert!(gap(&t.omega, &r.omega) <= tol && gap(&t.velocity, &r.velocity) <= tol, "link {k}");
        assert!(gap(&a.alpha, &dm.omega.map(|x| x.eps)) <= tol, "α of link {k}: {:?}", a.alpha);
        assert!(
            gap(&a.acceleration, &dm.velocity.map(|x| x.eps)) <= tol,
            "a of link {k}: {:?}",
            a.acceleration
        );
    }
    let checked = m.bias_accelerations(&q, &v).unwrap();
    assert_eq!(checked, acc);
    let mut qd = vec![f64::NAN; m.nq()];
    m.qdot_into(&q, &v, &mut qd);
    for (k, (g, x)) in qd.iter().zip(&qe).enumerate() {
        assert!((g - x.eps).abs() <= tol, "q̇[{k}] = {g}, d/dt(q ⊕ v t) = {}", x.eps);
    }
}

/// The checked call refuses what the hot path does not check.
#[test]
fn bias_accelerations_refuses_bad_input() {
    let m = tree();
    let q = m.neutral();
    assert!(matches!(
        m.bias_accelerations(&q[1..], &vec![0.0; m.nv()]),
        Err(DynamicsError::DimensionMismatch { .. })
    ));
    let mut v = vec![0.0; m.nv()];
    v[2] = f64::NAN;
    assert!(matches!(m.bias_accelerations(&q, &v), Err(DynamicsError::NonFinite { .. })));
}

/// A lone free body (the free-leaf path: sliders and ball in one step) whose joint frame is
/// turned by 𝓞_{J/G}: at the identity quaternion ω = 𝓞ᵀ ω_link and v = 𝓞ᵀ (ẋ, ẏ, ż) (joint-frame
/// rates), and at v̇ = 0 nothing accelerates (a body on its own has no bias, §5).
#[test]
fn free_leaf_closed_form() {
    let mut l = link(None, Joint::Free, [0.3, -0.1, 0.2]);
    let turn = nalgebra::Rotation3::from_scaled_axis(Vector3::new(0.4, -0.7, 0.2)).into_inner();
    l.orientation = turn;
    let m = Model::new(&[l]).unwrap();
    assert_eq!(m.free_leaves, vec![0], "the free-leaf path is the one under test");
    let q = [1.0, 2.0, -1.0, 1.0, 0.0, 0.0, 0.0];
    let v = [0.5, -1.5, 0.25, 2.0, -0.5, 1.0];
    let (tw, acc) = twists_and_bias(&m, &q, &v);
    let tol = 4.0 * f64::EPSILON;
    assert!(gap(&tw[0].omega, &(turn.transpose() * Vector3::new(2.0, -0.5, 1.0))) <= tol, "{:?}", tw[0]);
    assert!(gap(&tw[0].velocity, &(turn.transpose() * Vector3::new(0.5, -1.5, 0.25))) <= tol, "{:?}", tw[0]);
    assert!(
        gap(&acc[0].alpha, &Vector3::zeros()) == 0.0 && gap(&acc[0].acceleration, &Vector3::zeros()) == 0.0
    );
    // q̇: the joint-frame rates, and ½ (1, 0⃗) ⊗ (0, ω) = (0, ω/2) at the identity (§2.15)
    let mut qd = [f64::NAN; 7];
    m.qdot_into(&q, &v, &mut qd);
    assert_eq!(qd, [0.5, -1.5, 0.25, 0.0, 1.0, -0.25, 0.5]);
}
