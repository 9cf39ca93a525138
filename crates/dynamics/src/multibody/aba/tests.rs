//! Tests of ABA's closed forms (free and ball leaves, the floating base's 6×6 solve) against
//! the three passes, the mass matrix and RNEA, and of the ground passes against the local ones.

use nalgebra::{Matrix3, Rotation3, Vector3};

use super::super::joint::{Joint, Link};
use super::super::model::Model;
use super::super::wrench::JointWrench;

/// A body on `joint` at the root with its centre off the joint point and a tilted, offset
/// joint frame, gravity g, alone and, for the generic three passes, with a massless welded
/// child (which stops it being a closed-form leaf).
fn alone_and_with_child(joint: Joint) -> (Model, Model) {
    let body = free_body(joint);
    let tip =
        Link::new(Some(0), Joint::Weld, Vector3::new(1.0, 0.0, 0.0), 0.0, Vector3::zeros(), Matrix3::zeros());
    let mut alone = Model::new(std::slice::from_ref(&body)).expect("valid");
    let mut with_child = Model::new(&[body, tip]).expect("valid");
    let g = Vector3::new(0.3, -0.2, -9.81);
    (alone.gravity, with_child.gravity) = (g, g);
    (alone, with_child)
}

/// The body of `alone_and_with_child` on `joint` at the root.
fn free_body(joint: Joint) -> Link {
    let j_c = Matrix3::new(2.0, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 1.1);
    let mut body =
        Link::new(None, joint, Vector3::new(0.5, -1.0, 2.0), 3.0, Vector3::new(0.2, -0.4, 0.7), j_c);
    body.orientation = *Rotation3::from_euler_angles(0.3, -0.7, 1.1).matrix();
    body
}

/// An external wrench on the body (and none on the welded child).
fn wrenches() -> Vec<JointWrench> {
    let wrench = JointWrench { force: Vector3::new(-0.6, 1.4, 2.2), moment: Vector3::new(0.9, 0.1, -0.5) };
    vec![wrench, JointWrench::default()]
}

/// A free body (see `alone_and_with_child`) at a state with joint forces and an external
/// wrench.
fn models() -> (Model, Model, Vec<f64>, Vec<f64>, Vec<f64>, Vec<JointWrench>) {
    let (alone, with_child) = alone_and_with_child(Joint::Free);
    let qn = nalgebra::UnitQuaternion::from_euler_angles(0.9, 0.4, -2.0);
    let q = vec![0.3, -1.2, 0.8, qn.w, qn.i, qn.j, qn.k];
    let v = vec![0.5, -0.3, 1.7, 2.0, -1.1, 3.3];
    let tau = vec![1.0, -2.0, 0.5, 0.7, -0.4, 0.25];
    (alone, with_child, q, v, tau, wrenches())
}

/// ABA of the leaf alone (closed form) against the three passes on the same body with its
/// welded child, to 1e-13·(`scale` + |v̇|) per coordinate, and RNEA at the returned v̇ gives
/// back τ to 1e-12.
fn closed_form_matches(
    alone: &Model,
    with_child: &Model,
    q: &[f64],
    v: &[f64],
    tau: &[f64],
    wrenches: &[JointWrench],
    scale: f64,
) {
    let fast = alone.aba(q, v, tau, Some(&wrenches[..1])).expect("definite");
    let passes = with_child.aba(q, v, tau, Some(wrenches)).expect("definite");
    for (a, b) in fast.iter().zip(&passes) {
        assert!((a - b).abs() <= 1e-13 * (scale + b.abs()), "{fast:?} vs {passes:?}");
    }
    let id = alone.rnea(q, v, &fast, Some(&wrenches[..1])).expect("valid");
    for (a, b) in id.tau.iter().zip(tau) {
        assert!((a - b).abs() <= 1e-12, "RNEA {:?} vs τ {tau:?}", id.tau);
    }
}

/// The closed form of a free leaf body agrees with the three passes of ABA on the same
/// body (made generic by a massless welded child), and with the inverse dynamics: RNEA at
/// the returned v̇ gives back the applied joint forces.
#[test]
fn free_leaf_closed_form_matches_the_passes_and_rnea() {
    let (alone, with_child, q, v, tau, wrenches) = models();
    assert_eq!(alone.free_leaves, vec![0]);
    assert!(with_child.free_leaves.is_empty());
    closed_form_matches(&alone, &with_child, &q, &v, &tau, &wrenches, 1.0);
}

/// The closed form of a ball leaf (a body turning about a fixed point of a tilted, offset
/// joint frame, its centre off that point, under gravity, a joint torque and an external
/// wrench) agrees with the three passes on the same body made generic by a massless welded
/// child, and RNEA at the returned v̇ gives back the joint torque.
#[test]
fn ball_leaf_closed_form_matches_the_passes_and_rnea() {
    let (alone, with_child) = alone_and_with_child(Joint::Ball);
    assert_eq!(alone.ball_leaves, vec![0]);
    assert!(with_child.ball_leaves.is_empty());
    let qn = nalgebra::UnitQuaternion::from_euler_angles(0.9, 0.4, -2.0);
    let q = vec![qn.w, qn.i, qn.j, qn.k];
    let (v, tau) = (vec![2.0, -1.1, 3.3], vec![0.7, -0.4, 0.25]);
    let wrenches = wrenches();
    // a few roundings of terms near 10 (the gyroscopic and gravity moments)
    closed_form_matches(&alone, &with_child, &q, &v, &tau, &wrenches, 10.0);
}

/// A floating base (a free joint at the root, tilted and offset) with a pin leg, a ball
/// leg and a welded tip, and the same tree with the free joint written as three sleeves
/// along ẑ, ŷ, x̂ and a ball (the same motion: translations commute), which ABA eliminates
/// segment by segment.
fn floating_base(j_base: Matrix3<f64>) -> (Model, Model) {
    let base_orientation = *Rotation3::from_euler_angles(0.3, -0.7, 1.1).matrix();
    let mut base = Link::new(
        None,
        Joint::Free,
        Vector3::new(0.5, -1.0, 2.0),
        3.0,
        Vector3::new(0.1, -0.2, 0.05),
        j_base,
    );
    base.orientation = base_orientation;
    let j = Matrix3::new(0.2, 0.01, 0.0, 0.01, 0.15, 0.02, 0.0, 0.02, 0.1);
    let pin_leg = Link::new(
        Some(0),
        Joint::Pin { axis: Vector3::new(0.3, 1.0, -0.2) },
        Vector3::new(0.4, 0.2, -0.1),
        1.2,
        Vector3::new(0.0, 0.0, -0.3),
        j,
    );
    let ball_leg =
        Link::new(Some(0), Joint::Ball, Vector3::new(-0.4, 0.2, -0.1), 0.8, Vector3::new(0.1, 0.0, -0.4), j);
    let tip = Link::new(Some(1), Joint::Weld, Vector3::new(0.0, 0.0, -0.6), 0.3, Vector3::zeros(), j * 0.1);
    let links = [base, pin_leg, ball_leg, tip];
    (Model::new(&links).expect("valid"), segment_form(&links))
}

/// The tree of `links` (links[0] on a free joint at the root) with that joint written as
/// three massless sleeves along ẑ, ŷ, x̂ and a ball carrying the body: the same motion
/// (translations commute), coordinates (z, y, x, ball, …), which ABA eliminates segment by
/// segment.
fn segment_form(links: &[Link]) -> Model {
    let base = &links[0];
    let sleeve = |parent, axis: Vector3<f64>, offset| {
        Link::new(parent, Joint::Sleeve { axis }, offset, 0.0, Vector3::zeros(), Matrix3::zeros())
    };
    let mut z = sleeve(None, Vector3::z(), base.offset);
    z.orientation = base.orientation;
    let mut out = vec![
        z,
        sleeve(Some(0), Vector3::y(), Vector3::zeros()),
        sleeve(Some(1), Vector3::x(), Vector3::zeros()),
    ];
    let mut body = base.clone();
    (body.parent, body.joint, body.offset, body.orientation) =
        (Some(2), Joint::Ball, Vector3::zeros(), Matrix3::identity());
    out.push(body);
    out.extend(links[1..].iter().map(|l| {
        let mut l = l.clone();
        l.parent = l.parent.map(|p| p + 3);
        l
    }));
    Model::new(&out).expect("valid")
}

/// (z, y, x, rest…) from (x, y, z, rest…).
fn perm(x: &[f64]) -> Vec<f64> {
    [&[x[2], x[1], x[0]], &x[3..]].concat()
}

/// A state of `floating_base`'s tree: q (base pose, pin angle, ball quaternion), v, a third
/// vector (τ or v̇) and an external wrench on every link.
fn floating_state() -> (Vec<f64>, Vec<f64>, Vec<f64>, Vec<JointWrench>) {
    let qb = nalgebra::UnitQuaternion::from_euler_angles(0.9, 0.4, -2.0);
    let ql = nalgebra::UnitQuaternion::from_euler_angles(-0.3, 0.8, 0.2);
    let q = vec![0.3, -1.2, 0.8, qb.w, qb.i, qb.j, qb.k, 0.7, ql.w, ql.i, ql.j, ql.k];
    let v = vec![0.5, -0.3, 1.7, 2.0, -1.1, 3.3, -0.8, 0.4, 1.9, -0.6];
    let third = vec![1.0, -2.0, 0.5, 0.7, -0.4, 0.25, 0.3, -0.2, 0.1, 0.6];
    let fe = |k: f64| JointWrench {
        force: Vector3::new(-0.6, 1.4, 2.2) * k,
        moment: Vector3::new(0.9, 0.1, -0.5) * k,
    };
    (q, v, third, vec![fe(1.0), fe(-0.5), fe(0.3), fe(0.7)])
}

/// v̇ of the floating base's 6×6 solve: against the same tree eliminated segment by segment
/// (a consistency check), against the mass matrix and bias forces (CRBA, RNEA, Cholesky:
/// another algorithm), and RNEA at the returned v̇ gives back τ, with gravity, joint forces
/// and external wrenches on every link.
#[test]
fn floating_base_solve_matches_the_segments_and_the_mass_matrix() {
    let (mut fast, mut slow) = floating_base(Matrix3::new(2.0, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 1.1));
    let g = Vector3::new(0.3, -0.2, -9.81);
    (fast.gravity, slow.gravity) = (g, g);
    assert_eq!((fast.free_roots.clone(), slow.free_roots.clone()), (vec![0], vec![]));
    let (q, v, tau, wrenches) = floating_state();
    // (the ground passes; the local passes' 6×6 solve below)
    let ground = fast.aba(&q, &v, &tau, Some(&wrenches)).expect("definite");
    let mut s = fast.aba_scratch();
    let mut got = vec![0.0; 10];
    fast.aba_local_into(&q, &v, &tau, Some(&wrenches), &mut got, &mut s).expect("definite");
    assert!(s.root_fast[0], "the 6×6 solve was taken");
    // the slow tree's coordinates: sleeves z, y, x then the ball (its joint frame is the
    // free joint's frame, so the same numbers)
    // (no wrench on the three massless sleeves)
    let slow_wrenches = [&[JointWrench::default(); 3][..], &wrenches].concat();
    let slow_vd = slow.aba(&perm(&q), &perm(&v), &perm(&tau), Some(&slow_wrenches)).expect("definite");
    let crba = fast.forward_dynamics_crba(&q, &v, &tau, Some(&wrenches)).expect("definite");
    let scale = got.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    for (((a, b), c), d) in got.iter().zip(&perm(&slow_vd)).zip(&crba).zip(&ground) {
        assert!((a - b).abs() <= 1e-13 * scale, "segments: {got:?} vs {slow_vd:?}");
        assert!((a - c).abs() <= 1e-12 * scale, "CRBA: {got:?} vs {crba:?}");
        assert!((a - d).abs() <= 1e-13 * scale, "ground passes: {got:?} vs {ground:?}");
    }
    let id = fast.rnea(&q, &v, &got, Some(&wrenches)).expect("valid");
    for (a, b) in id.tau.iter().zip(&tau) {
        assert!((a - b).abs() <= 1e-12 * scale, "RNEA {:?} vs τ {tau:?}", id.tau);
    }
}

/// A base whose rotational inertia is at the rounding level (J_c = 1e-16·1: definite on
/// its own) carrying a ball leg hinged at the base's centre (which adds no rotational
/// inertia about it): the 6×6 solve finds its angular pivot below ABA's floor and is
/// refused, and the four segments are eliminated one by one, keeping the base's spin
/// inert; the result is the same tree's segment by segment, to rounding.
#[test]
fn floating_base_at_the_rounding_level_falls_back_to_the_segments() {
    let j0 = Matrix3::identity() * 1e-16;
    let base = Link::new(None, Joint::Free, Vector3::new(0.5, -1.0, 2.0), 3.0, Vector3::zeros(), j0);
    let j = Matrix3::new(0.2, 0.01, 0.0, 0.01, 0.15, 0.02, 0.0, 0.02, 0.1);
    let leg = Link::new(Some(0), Joint::Ball, Vector3::zeros(), 0.8, Vector3::new(0.1, 0.0, -0.4), j);
    let links = [base, leg];
    let (mut fast, mut slow) = (Model::new(&links).expect("valid"), segment_form(&links));
    let g = Vector3::new(0.0, 0.0, -9.81);
    (fast.gravity, slow.gravity) = (g, g);
    assert_eq!(fast.free_roots, vec![0]);
    let ql = nalgebra::UnitQuaternion::from_euler_angles(-0.3, 0.8, 0.2);
    let q = vec![0.3, -1.2, 0.8, 1.0, 0.0, 0.0, 0.0, ql.w, ql.i, ql.j, ql.k];
    let v = vec![0.5, -0.3, 1.7, 0.0, 0.0, 0.0, -0.8, 0.4, 1.9];
    // (no torque at the leg's ball: it would turn the base, which cannot take it)
    let tau = vec![1.0, -2.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
    let mut s = fast.aba_scratch();
    let mut got = vec![0.0; 9];
    fast.aba_into(&q, &v, &tau, None, &mut got, &mut s).expect("the spin is inert");
    assert!(!s.root_fast[0], "the 6×6 solve was refused");
    let slow_vd = slow.aba(&perm(&q), &perm(&v), &perm(&tau), None).expect("the spin is inert");
    // (the sleeves' order changes the roundings: a few ulps of |v̇| ≈ 10)
    for (a, b) in perm(&got).iter().zip(&slow_vd) {
        assert!((a - b).abs() <= 1e-14 * 10.0, "{got:?} vs {slow_vd:?}");
    }
    assert_eq!(&got[3..6], &[0.0, 0.0, 0.0], "the base's spin is inert");
}

/// A particle on a rod about a ball joint (J_c = 0, so J_o has rank 2) is not a closed-form
/// body: ABA's rank-revealing path keeps the spin about the rod inert. Hanging straight
/// down at rest, nothing moves.
#[test]
fn ball_particle_keeps_the_rank_revealing_path() {
    let p =
        Link::new(None, Joint::Ball, Vector3::zeros(), 2.0, Vector3::new(0.0, 0.0, -1.0), Matrix3::zeros());
    let mut m = Model::new(&[p]).expect("valid");
    m.gravity = Vector3::new(0.0, 0.0, -9.81);
    assert!(m.ball_leaves.is_empty());
    let vd = m.aba(&[1.0, 0.0, 0.0, 0.0], &[0.0; 3], &[0.0; 3], None).expect("inert");
    assert_eq!(vd, vec![0.0, 0.0, 0.0]);
    // the ground passes hand the singular pivot to the local ones, writing nothing
    let mut s = m.aba_scratch();
    s.trig.fill(&[1.0, 0.0, 0.0, 0.0]);
    let mut out = vec![7.0; 3];
    assert!(!m.aba_ground(&[1.0, 0.0, 0.0, 0.0], &[0.0; 3], &[0.0; 3], None, &mut out, &mut s));
    assert_eq!(out, vec![7.0; 3]);
}

/// A particle on a free joint (J_c = 0) is not a closed-form body: ABA's rank-revealing
/// path keeps the rotation inert (ω̇ = 0) and the translation free fall.
#[test]
fn free_particle_keeps_the_rank_revealing_path() {
    let p = Link::new(None, Joint::Free, Vector3::zeros(), 2.0, Vector3::zeros(), Matrix3::zeros());
    let mut m = Model::new(&[p]).expect("valid");
    m.gravity = Vector3::new(0.0, 0.0, -9.81);
    assert!(m.free_leaves.is_empty());
    let vd = m.aba(&[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0], &[0.0; 6], &[0.0; 6], None).expect("inert");
    assert_eq!(vd, vec![0.0, 0.0, -9.81, 0.0, 0.0, 0.0]);
}

/// The ground passes resolve everything about the base's origin, so a floating tree far from
/// the ground origin loses nothing: the floating base of `floating_base` moved by 10⁶ m
/// (the free joint's position coordinates) accelerates as it does at the origin (gravity is
/// uniform), to rounding of |v̇|; the ground passes were taken at both places and agree with
/// the local passes.
#[test]
fn ground_passes_are_translation_invariant_and_match_the_local_passes() {
    let (mut model, _) = floating_base(Matrix3::new(2.0, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 1.1));
    model.gravity = Vector3::new(0.3, -0.2, -9.81);
    let qb = nalgebra::UnitQuaternion::from_euler_angles(0.9, 0.4, -2.0);
    let ql = nalgebra::UnitQuaternion::from_euler_angles(-0.3, 0.8, 0.2);
    let near = vec![0.3, -1.2, 0.8, qb.w, qb.i, qb.j, qb.k, 0.7, ql.w, ql.i, ql.j, ql.k];
    let mut far = near.clone();
    far[0] += 1e6;
    far[2] -= 3e5;
    let v = vec![0.5, -0.3, 1.7, 2.0, -1.1, 3.3, -0.8, 0.4, 1.9, -0.6];
    let tau = vec![1.0, -2.0, 0.5, 0.7, -0.4, 0.25, 0.3, -0.2, 0.1, 0.6];
    let mut s = model.aba_scratch();
    let run = |q: &[f64], s: &mut super::AbaScratch<f64>| {
        let (mut ground, mut local) = (vec![0.0; 10], vec![0.0; 10]);
        s.trig.fill(q);
        assert!(model.aba_ground(q, &v, &tau, None, &mut ground, s), "the ground passes were taken");
        model.aba_local_into(q, &v, &tau, None, &mut local, s).expect("definite");
        (ground, local)
    };
    let (g_near, l_near) = run(&near, &mut s);
    let (g_far, l_far) = run(&far, &mut s);
    let scale = l_near.iter().fold(1.0f64, |m, x| m.max(x.abs()));
    for k in 0..10 {
        assert!((g_near[k] - l_near[k]).abs() <= 1e-13 * scale, "{g_near:?} vs {l_near:?}");
        assert!((g_far[k] - l_near[k]).abs() <= 1e-13 * scale, "far: {g_far:?} vs {l_near:?}");
        assert!((l_far[k] - l_near[k]).abs() <= 1e-13 * scale, "local far: {l_far:?} vs {l_near:?}");
    }
}

/// RNEA's one-step free joint at the root (`Model::rnea_free_outward`, the ball's force handed
/// to the three sliders at once) against the same tree with the joint written as three
/// sleeves and a ball, taken segment by segment (a consistency check of the shortcut): the
/// floating base with legs, and the free body alone, both behind a tilted, offset joint
/// frame, with gravity off every axis and external wrenches. τ and the links' joint wrenches
/// agree to 1e-13 relative.
#[test]
fn free_joint_rnea_matches_the_segments() {
    let (base, base_segments) = floating_base(Matrix3::new(2.0, 0.3, -0.1, 0.3, 1.5, 0.2, -0.1, 0.2, 1.1));
    let (q, v, vd, legs) = floating_state();
    let one = legs[0];
    let (alone, _) = alone_and_with_child(Joint::Free);
    let mut alone_segments = segment_form(&[free_body(Joint::Free)]);
    let (mut base, mut base_segments) = (base, base_segments);
    (alone_segments.gravity, base.gravity, base_segments.gravity) =
        (alone.gravity, alone.gravity, alone.gravity);
    assert_eq!((base.free_roots.clone(), alone.free_leaves.clone()), (vec![0], vec![0]), "the shortcut runs");
    let cases = [
        (&base, &base_segments, q.clone(), v.clone(), vd.clone(), legs),
        (&alone, &alone_segments, q[..7].to_vec(), v[..6].to_vec(), vd[..6].to_vec(), vec![one]),
    ];
    for (fast, slow, q, v, vd, fext) in cases {
        let got = fast.rnea(&q, &v, &vd, Some(&fext)).expect("valid");
        let slow_fext = [&[JointWrench::default(); 3][..], &fext].concat();
        let want = slow.rnea(&perm(&q), &perm(&v), &perm(&vd), Some(&slow_fext)).expect("valid");
        let scale = want.tau.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        for (a, b) in perm(&got.tau).iter().zip(&want.tau) {
            assert!((a - b).abs() <= 1e-13 * scale, "τ {:?} vs the segments' {:?}", got.tau, want.tau);
        }
        for (a, b) in got.wrenches.iter().zip(&want.wrenches[3..]) {
            let d = (a.force - b.force).norm() + (a.moment - b.moment).norm();
            assert!(d <= 1e-13 * scale, "wrench {a:?} vs the segments' {b:?}");
        }
    }
}
