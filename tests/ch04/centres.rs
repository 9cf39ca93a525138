//! §4.15–4.18: screw axis, IVCR, IACR, Chasles-based velocity, rolling.

use vectrix::kinematics::*;
use vectrix::nalgebra::Vector3;
use vectrix::num_dual::{Dual2_64, DualNum};
use vectrix::prelude::*;
use vectrix::tensor::Scalar;

use crate::paths::*;
use crate::support::EPS;

const TOL: f64 = 256.0 * EPS;
/// Relative tolerance for the IVCR/IACR consistency tests.
const REL: f64 = 1e-12;

fn a() -> Frame {
    Frame::new()
}

/// v⃗_p = v⃗_q + ω⃗ × r⃗_{p/q} (4.4.9).
fn v_at(w: &Vector, v_q: &Vector, r: &Vector) -> Vector {
    *v_q + w.cross(r)
}

// (4.15.2): ω⃗·v⃗_q is the same for every point q of the body; the screw axis points move along
// ω⃗ with velocity (pitch)ω⃗ (§4.17).
#[test]
fn eq_4_15_2_invariant_and_screw_axis() {
    let a = a();
    let (w, v_q) = (a.vector([0.3, -1.2, 0.8]), a.vector([1.0, 0.4, -0.5]));
    for r in [[1.0, 2.0, 3.0], [-0.5, 0.0, 4.0]] {
        let v_p = v_at(&w, &v_q, &a.vector(r));
        assert!((w.dot(&v_p) - w.dot(&v_q)).abs() < TOL * 10.0);
    }
    let InstantaneousMotion::Screw(s) = screw_axis(&w, &v_q).unwrap() else {
        panic!("ω ≠ 0 gives a screw")
    };
    for lambda in [0.0, 1.7, -3.0] {
        let p = s.axis.point + s.axis.direction * lambda;
        let v_p = v_at(&w, &v_q, &p);
        assert!(dist(&v_p, &(w * s.pitch)) < TOL * 10.0, "axis points move along ω");
    }
    assert_eq!(screw_axis(&Vector::<f64>::zero(), &Vector::zero()).unwrap(), InstantaneousMotion::Rest);
    assert_eq!(
        screw_axis(&Vector::zero(), &v_q).unwrap(),
        InstantaneousMotion::Translation { velocity: v_q }
    );
}

// Fact 4.15.3, (4.15.6): an IVCR exists iff ω⃗·v⃗_q = 0; it is the line solving
// (|ω|²I − ωω′)r⃗_{p/q} = ω⃗ × v⃗_q, and its points are at rest.
#[test]
fn fact_4_15_3_ivcr() {
    let a = a();
    let w = a.vector([0.0, 0.0, 2.0]);
    let v_q = a.vector([1.0, -3.0, 0.0]);
    let line = ivcr(&w, &v_q, REL).unwrap().expect("ω ⊥ v_q");
    assert!(dist(&(ivcr_coefficient(&w) * line.point), &w.cross(&v_q)) < TOL * 10.0);
    for lambda in [0.0, 5.0] {
        let p = line.point + line.direction * lambda;
        assert!(v_at(&w, &v_q, &p).norm() < TOL * 10.0);
    }
    // nonzero pitch or ω = 0: no IVCR
    assert_eq!(ivcr(&w, &a.vector([1.0, 0.0, 0.1]), REL).unwrap(), None);
    assert_eq!(ivcr(&Vector::zero(), &v_q, REL).unwrap(), None);
    assert!(matches!(
        ivcr(&a.vector([f64::NAN, 0.0, 0.0]), &v_q, REL),
        Err(KinematicsError::NonFinite { .. })
    ));
}

// §4.16: with ω⃗ × α⃗ ≠ 0⃗ the IACR is a unique point (det(α^× + ω^×ω^×) = −|ω×α|², notes).
#[test]
fn eq_4_16_1_iacr_unique_point() {
    let a = a();
    let (w, al, a_q) = (a.vector([0.2, 1.0, -0.3]), a.vector([1.5, -0.2, 0.7]), a.vector([0.3, 2.0, -1.0]));
    let m = al.cross_dyad() + w.cross_dyad() * w.cross_dyad();
    assert!((m.determinant() + w.cross(&al).norm_squared()).abs() < TOL * 10.0);
    let Iacr::Point(p) = iacr(&w, &al, &a_q, REL).unwrap() else { panic!("unique point") };
    assert!(body_point_acceleration(&w, &al, &a_q, &p).norm() < TOL * 100.0);
}

// Facts 4.16.2–4.16.4: the singular cases give a line (or nothing when the consistency test
// fails). (4.16.2)'s printed matrix is garbled; the corrected (|α|²I − αα′)r = α×a_q is used.
#[test]
fn facts_4_16_2_to_4_16_4_iacr_lines() {
    let a = a();
    let k = a.vector([0.0, 0.0, 1.0]);
    let a_q = a.vector([1.0, -2.0, 0.0]);
    let cases = [
        ("F4.16.2 ω = 0", Vector::zero(), k * 3.0),
        ("F4.16.3 α = 0", k * 1.5, Vector::zero()),
        ("F4.16.4 α ∥ ω", k * 1.5, k * -0.7),
    ];
    for (name, w, al) in cases {
        let Iacr::Line(line) = iacr(&w, &al, &a_q, REL).unwrap() else { panic!("{name}: a line") };
        for lambda in [0.0, 2.5] {
            let p = line.point + line.direction * lambda;
            assert!(body_point_acceleration(&w, &al, &a_q, &p).norm() < TOL * 10.0, "{name}");
        }
        // a_q with a component along the axis: no point
        assert_eq!(iacr(&w, &al, &(a_q + k), REL).unwrap(), Iacr::None, "{name}");
    }
    assert_eq!(iacr(&Vector::zero(), &Vector::zero(), &a_q, REL).unwrap(), Iacr::Undefined);
}

/// Rodrigues's formula (2.11.1) on resolved components.
fn rodrigues<T: Scalar>(n: Vector3<T>, th: T, x: Vector3<T>) -> Vector3<T> {
    x * th.cos() + n * (n.dot(&x) * (T::one() - th.cos())) + n.cross(&x) * th.sin()
}

fn unit_n<T: Scalar>(t: T) -> Vector3<T> {
    let v = vec_path(t, &C1);
    v / v.norm()
}

// (4.17.1–7): for r⃗_{y′/z} = R⃗_n̂(θ)r⃗_{y/z} + αn̂, v⃗_{y′/z/A} = ω⃗×r⃗_{y′/z} + αn̂×ω⃗ + α̇n̂ + αn̂^{A•},
// with ω⃗ from (4.7.18): ω⃗ = θ̇n̂ + (1 − cos θ)n̂×ṅ + sin θ ṅ.
#[test]
fn eq_4_17_7_chasles_velocity() {
    let fa = a();
    let t0 = 0.6;
    let r_y = Vector3::new(0.3, -0.8, 1.1);
    let th = |t: Dual2_64| angle(t, [0.4, 1.3, -0.2]);
    let sl = |t: Dual2_64| angle(t, [0.1, -0.5, 0.3]);
    let pos = |t: Dual2_64| rodrigues(unit_n(t), th(t), r_y.map(Dual2_64::from)) + unit_n(t) * sl(t);
    let [r, rd, _] = vec_jet(pos, t0);
    let [n, nd, _] = vec_jet(unit_n, t0);
    let d = |f: &dyn Fn(Dual2_64) -> Dual2_64| f(Dual2_64::new(t0, 1.0, 0.0));
    let (tt, s) = (d(&th), d(&sl));
    let v = |x: Vector3<f64>| fa.vector(arr(x));
    let (n, nd) = (v(n), v(nd));
    let w = n * tt.v1 + n.cross(&nd) * (1.0 - tt.re.cos()) + nd * tt.re.sin();
    let got = chasles_velocity(&w, &v(r), s.re, s.v1, &n, &nd);
    assert!(dist(&got, &v(rd)) < TOL * 10.0);
}

// Fact 4.18.1: colocated contact points have the same relative velocity in every frame
// (r⃗_{x₁/x₂} = 0⃗ kills the transport term): a slip velocity re-taken with respect to a turning
// and translating frame by vectrix's transport theorem is unchanged, and Def 4.18.2 calls it
// slipping.
#[test]
fn fact_4_18_1_slip_velocity_is_the_same_in_every_frame() {
    let fa = LabeledFrame::new("A", Frame::new());
    let f = &fa.frame;
    let slip = slip_velocity(&f.vector([0.3, 0.0, -0.1]), &Vector::zero());
    assert!(!rolls_without_slip(&slip, &Vector::zero(), 1e-12));
    let jet = VectorJet::new(fa.label, Vector::zero(), slip, Vector::zero()).unwrap();
    let b = LabeledFrame::new("B", Frame::from_orientation_rel(f, &o3(0.7), 1e-12).unwrap());
    let m = FrameMotion::new(b, fa, f.vector([0.1, 0.2, 3.0]), f.vector([-1.0, 0.5, 0.2])).unwrap();
    assert!(dist(&jet.transported(&m).unwrap().rate(), &slip) < TOL);
}

// Ex 4.18.4: a wheel of radius R rolls without slipping in a straight line on a flat surface
// (F_A fixed in the surface, î_A along the path, ĵ_A up; x, q fixed in the plane, p fixed on
// the rim). When p is in contact with q, v⃗_{p/x/A} = v⃗_{q/x/A} = 0⃗.
//
// Computed, not assumed: the wheel frame F_B turns by −φ(t) about k̂_A (clockwise, rolling
// toward +î_A) along a path φ(t) with nonzero φ̇ and φ̈; rolling in a straight line puts the
// centre c at r⃗_{c/x} = (x₀ + Rφ)î_A + Rĵ_A (the unrolled arc). v⃗_{p/x/A} = v⃗_{c/x/A} +
// r⃗_{p/c}^{A•}, with v⃗_{c/x/A} the exact (dual-number) derivative of the centre's path and
// r⃗_{p/c}^{A•} from vectrix's transport of the body-fixed r⃗_{p/c} = −Rĵ_B (ω⃗_{B/A} from
// Poisson's equation on 𝓞_{B/A}(t)). Oracle at every t: the derivatives of the cycloid
// r⃗_{p/x}|_A = (x₀ + Rφ − R sin φ, R − R cos φ, 0); at the contact instant (φ = 2π) the
// velocity is 0⃗ and the acceleration Rφ̇²ĵ_A (the cusp).
#[test]
fn example_4_18_4_rolling_wheel_contact_point_is_at_rest() {
    let fa = LabeledFrame::new("A", Frame::new());
    let f = fa.frame;
    let (radius, x0) = (0.4, -1.3);
    // φ(t) = 2π at t = t_c, with φ̇ = 2.5 and φ̈ = 0.8 there (plus a sine so φ‴ ≠ 0)
    let t_c = 0.9;
    let phi = |t: Dual2_64| {
        let d = t - t_c;
        Dual2_64::from(2.0 * std::f64::consts::PI) + d * 2.5 + d * d * 0.4 + (d * 1.7).sin() * 0.1 - d * 0.17
    };
    let wheel = |t: f64| {
        let m = motion_from_path("B", &fa, |t| o3(-phi(t)), t);
        let centre =
            vec_jet(|t| Vector3::new(phi(t) * radius + x0, Dual2_64::from(radius), Dual2_64::from(0.0)), t);
        let p_c = VectorJet::fixed_in(m.body().label, m.body().frame.vector([0.0, -radius, 0.0]));
        let p_c = p_c.transported(&m).unwrap();
        let [_, v_c, a_c] = centre.map(|x| f.vector(arr(x)));
        (p_c.rate() + v_c, p_c.second_rate() + a_c)
    };
    let cycloid = |t: Dual2_64| {
        let ph = phi(t);
        Vector3::new(
            ph * radius + x0 - ph.sin() * radius,
            Dual2_64::from(radius) - ph.cos() * radius,
            Dual2_64::from(0.0),
        )
    };
    let p = |t: f64| Dual2_64::new(t, 1.0, 0.0);
    for t in [0.0, 0.35, t_c, 1.6] {
        let (v_p, a_p) = wheel(t);
        let [_, v, a] = vec_jet(cycloid, t);
        let (wd, wdd) = (phi(p(t)).v1, phi(p(t)).v2);
        // speeds ≈ Rφ̇ ≈ 1, accelerations ≈ Rφ̇² ≈ 2.5: rounding of a few rotations and products
        assert!(dist(&v_p, &f.vector(arr(v))) < TOL * radius * wd.abs(), "v at t = {t}");
        assert!(dist(&a_p, &f.vector(arr(a))) < TOL * radius * (wd * wd + wdd.abs()), "a at t = {t}");
    }
    // the contact instant: p touches q, v⃗_{p/x/A} = v⃗_{q/x/A} = 0⃗, a⃗_{p/x/A} = Rφ̇²ĵ_A
    let (v_p, a_p) = wheel(t_c);
    let wd = phi(p(t_c)).v1;
    let v_q = Vector::zero(); // q is fixed in the plane
    assert!(v_p.norm() < TOL * radius * wd);
    assert!(rolls_without_slip(&v_p, &v_q, TOL * radius * wd));
    assert!(dist(&a_p, &(f.j() * (radius * wd * wd))) < TOL * radius * wd * wd * 4.0);
    // away from contact p moves: |v⃗_{p/x/A}| = 2Rφ̇ sin(φ/2), and it is not the surface's velocity
    let (v_p, _) = wheel(0.35);
    let (ph, wd) = (phi(p(0.35)).re, phi(p(0.35)).v1);
    assert!((v_p.norm() - 2.0 * radius * wd * (ph / 2.0).sin().abs()).abs() < TOL * radius * wd);
    assert!(!rolls_without_slip(&v_p, &v_q, 1e-3));
}
