//! The planar passes against the spatial passes and RNEA, through dual numbers, and their
//! refusals (spatial trees, an inert pin).

use nalgebra::{Matrix3, Rotation3, Vector3};
use num_dual::Dual64;

use crate::multibody::joint::{Joint, Link};
use crate::multibody::model::Model;
use crate::multibody::wrench::JointWrench;

fn inertia(a: f64, b: f64, c: f64, p: f64) -> Matrix3<f64> {
    Matrix3::new(a, p, -0.5 * p, p, b, 0.3 * p, -0.5 * p, 0.3 * p, c)
}

/// Uniform numbers in [−1, 1) from a 64-bit LCG (Knuth's MMIX constants) seeded with `seed`.
fn uniform(mut seed: u64) -> impl FnMut() -> f64 {
    move || {
        seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
}

/// A chain of n pins (every third about −â), offsets and centres off the plane, products of
/// inertia, gravity off the plane: drawn from `rnd`.
fn random_chain(n: usize, rnd: &mut impl FnMut() -> f64) -> Model {
    let links: Vec<Link> = (0..n)
        .map(|i: usize| {
            let axis = if i % 3 == 1 { -Vector3::y() } else { Vector3::y() };
            let off = Vector3::new(rnd(), 0.3 * rnd(), rnd());
            let com = Vector3::new(rnd(), 0.2 * rnd(), rnd());
            let j = inertia(0.3 + 0.05 * rnd(), 0.25 + 0.05 * rnd(), 0.28 + 0.05 * rnd(), 0.02 * rnd());
            Link::new(i.checked_sub(1), Joint::Pin { axis }, off, 1.0 + 0.5 * rnd(), com, j)
        })
        .collect();
    let mut m = Model::new(&links).expect("valid");
    m.gravity = Vector3::new(0.3, -1.0, -9.81);
    m
}

/// A planar tree about `axis`: a branch, pins about +â and −â, a slider ⊥ â, a weld,
/// offsets and centres off the plane, products of inertia coupling â to the plane.
fn tree(axis: Vector3<f64>, across: Vector3<f64>) -> Vec<Link> {
    let off = |x: f64, y: f64, z: f64| Vector3::new(x, y, z);
    vec![
        Link::new(
            None,
            Joint::Pin { axis },
            off(0.1, -0.2, 0.3),
            1.5,
            off(0.4, 0.1, -0.2),
            inertia(0.3, 0.2, 0.25, 0.02),
        ),
        Link::new(
            Some(0),
            Joint::Pin { axis: -axis },
            off(0.6, 0.2, -0.1),
            0.8,
            off(0.3, -0.3, 0.1),
            inertia(0.1, 0.15, 0.12, -0.01),
        ),
        Link::new(
            Some(1),
            Joint::Sleeve { axis: across },
            off(0.2, 0.0, 0.4),
            0.5,
            off(0.05, 0.1, 0.2),
            inertia(0.05, 0.04, 0.06, 0.005),
        ),
        Link::new(
            Some(0),
            Joint::Pin { axis },
            off(-0.3, 0.5, 0.2),
            1.1,
            off(-0.2, 0.2, 0.3),
            inertia(0.2, 0.3, 0.22, 0.03),
        ),
        Link::new(
            Some(3),
            Joint::Weld,
            off(0.0, 0.1, -0.5),
            0.7,
            off(0.1, 0.0, -0.1),
            inertia(0.04, 0.05, 0.03, 0.0),
        ),
        Link::new(
            Some(4),
            Joint::Pin { axis },
            off(0.25, -0.1, 0.15),
            0.6,
            off(0.2, 0.05, 0.0),
            inertia(0.06, 0.05, 0.07, 0.01),
        ),
    ]
}

fn state() -> (Vec<f64>, Vec<f64>, Vec<f64>, Vec<JointWrench>) {
    let q = vec![0.7, -1.9, 0.35, 2.6, -0.4];
    let v = vec![1.3, -2.2, 0.8, 0.5, 3.1];
    let tau = vec![0.4, -1.1, 2.0, 0.3, -0.6];
    let w = (0..6)
        .map(|k| {
            let k = k as f64;
            JointWrench {
                force: Vector3::new(0.3 - 0.1 * k, 0.2 * k, -0.5 + 0.05 * k),
                moment: Vector3::new(0.1 * k, -0.2, 0.3 - 0.07 * k),
            }
        })
        .collect();
    (q, v, tau, w)
}

fn close(a: &[f64], b: &[f64], tol: f64) {
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= tol * (1.0 + y.abs()), "{a:?}\nvs\n{b:?}");
    }
}

/// The planar passes give the spatial passes' v̇ on the same tree (to rounding) for pins
/// about ±ŷ, a slider along x̂, a weld, a branch, out-of-plane offsets, gravity and
/// external wrenches with out-of-plane parts; and RNEA at that v̇ gives back τ.
#[test]
fn planar_passes_match_the_spatial_passes_and_rnea() {
    for (axis, across) in [
        (Vector3::y(), Vector3::x()),
        (-Vector3::z(), Vector3::new(0.6, 0.8, 0.0)),
        // a general axis: the slider direction ⊥ it exactly in floating point
        (Vector3::new(1.0, 2.0, 2.0) / 3.0, Vector3::new(2.0, -1.0, 0.0) / 5f64.sqrt()),
    ] {
        let links = tree(axis, across);
        let mut planar = Model::new(&links).expect("valid");
        let want_axis = Model::new(&links[..1]).expect("valid").planar_axis();
        assert_eq!(planar.planar_axis(), want_axis, "axis {axis}");
        assert!(planar.planar_axis().is_some(), "axis {axis}");
        planar.gravity = Vector3::new(0.3, -9.81, 1.2);
        let mut spatial = planar.clone();
        spatial.disable_planar_reduction();
        assert!(spatial.planar_axis().is_none());
        let (q, v, tau, w) = state();
        let fast = planar.aba(&q, &v, &tau, Some(&w)).expect("definite");
        let slow = spatial.aba(&q, &v, &tau, Some(&w)).expect("definite");
        close(&fast, &slow, 1e-13);
        // the planar passes did the work (no fallback)
        let (mut out, mut s) = (vec![0.0; 5], planar.aba_scratch());
        let work = s.pl.as_mut().unwrap();
        work.gravity = planar.gravity;
        assert!(planar.planar.as_ref().unwrap().aba(&q, &v, &tau, Some(&w), &mut out, work));
        assert_eq!(out, fast);
        let id = planar.rnea(&q, &v, &fast, Some(&w)).expect("valid");
        close(&id.tau, &tau, 1e-12);
        // and without external wrenches
        let fast = planar.aba(&q, &v, &tau, None).expect("definite");
        let slow = spatial.aba(&q, &v, &tau, None).expect("definite");
        close(&fast, &slow, 1e-13);
    }
}

/// Exact derivatives go through the planar passes too: a dual-number ABA agrees with the
/// spatial passes' dual-number ABA in value and in the derivative along q.
#[test]
fn planar_passes_carry_dual_numbers() {
    let mut m = Model::new(&tree(Vector3::y(), Vector3::x())).expect("valid");
    m.gravity = Vector3::new(0.0, 0.0, -9.81);
    let mut s = m.clone();
    s.disable_planar_reduction();
    let (q, v, tau, _) = state();
    let seed = |m: &Model| {
        let d = m.cast::<Dual64>();
        assert_eq!(d.planar_axis().is_some(), m.planar_axis().is_some());
        let qd: Vec<Dual64> =
            q.iter().enumerate().map(|(k, &x)| Dual64::new(x, 0.3 * k as f64 - 0.5)).collect();
        let vd: Vec<Dual64> = v.iter().map(|&x| Dual64::from(x)).collect();
        let td: Vec<Dual64> = tau.iter().map(|&x| Dual64::from(x)).collect();
        d.aba(&qd, &vd, &td, None).expect("definite")
    };
    let (a, b) = (seed(&m), seed(&s));
    close(&a.iter().map(|x| x.re).collect::<Vec<_>>(), &b.iter().map(|x| x.re).collect::<Vec<_>>(), 1e-13);
    // the f64 passes take the joint angles' sines and cosines all at once (SIMD), the dual
    // ones one by one from libm: the same passes, each sine within an ulp of the other
    close(&a.iter().map(|x| x.re).collect::<Vec<_>>(), &m.aba(&q, &v, &tau, None).expect("definite"), 1e-14);
    close(&a.iter().map(|x| x.eps).collect::<Vec<_>>(), &b.iter().map(|x| x.eps).collect::<Vec<_>>(), 1e-12);
}

/// What is not planar keeps the spatial passes: pins about two axes, a placement that
/// rotates the joint frame (even about â), a ball, a slider along â, a free body.
#[test]
fn spatial_trees_are_not_reduced() {
    let j = Matrix3::from_diagonal(&Vector3::new(0.1, 0.2, 0.3));
    let pin = |parent, axis| Link::new(parent, Joint::Pin { axis }, Vector3::x(), 1.0, Vector3::x() * 0.5, j);
    let planar = Model::new(&[pin(None, Vector3::y()), pin(Some(0), Vector3::y())]).expect("valid");
    assert_eq!(planar.planar_axis(), Some(Vector3::y()));
    assert!(Model::revolute_chain(4, 1.0, 0.5).expect("valid").planar_axis().is_none());
    let mut turned = pin(Some(0), Vector3::y());
    turned.orientation = *Rotation3::from_axis_angle(&Vector3::y_axis(), 0.3).matrix();
    let cases = [
        vec![pin(None, Vector3::y()), turned],
        vec![
            pin(None, Vector3::y()),
            Link::new(Some(0), Joint::Ball, Vector3::x(), 1.0, Vector3::zeros(), j),
        ],
        vec![
            pin(None, Vector3::y()),
            Link::new(Some(0), Joint::Sleeve { axis: Vector3::y() }, Vector3::x(), 1.0, Vector3::zeros(), j),
        ],
        vec![Link::new(None, Joint::Free, Vector3::zeros(), 1.0, Vector3::zeros(), j)],
    ];
    for links in cases {
        assert!(Model::new(&links).expect("valid").planar_axis().is_none(), "{links:?}");
    }
}

/// An inert pin (a point mass on its axis, carrying a massless link) sends the planar
/// passes back to the spatial ones, which decide it exactly: the same v̇ as with the
/// reduction off, and the same error for a torque along the inert coordinate.
#[test]
fn inert_pin_falls_back_to_the_spatial_passes() {
    let z = Matrix3::zeros();
    let links = [
        Link::new(None, Joint::Pin { axis: Vector3::y() }, Vector3::zeros(), 1.0, Vector3::x(), z),
        Link::new(Some(0), Joint::Pin { axis: Vector3::y() }, Vector3::x(), 2.0, Vector3::zeros(), z),
    ];
    let mut m = Model::new(&links).expect("valid");
    m.gravity = Vector3::new(0.0, 0.0, -9.81);
    assert!(m.planar_axis().is_some());
    let mut s = m.clone();
    s.disable_planar_reduction();
    let (q, v) = ([0.4, -0.7], [0.3, 1.2]);
    let a = m.aba(&q, &v, &[0.0, 0.0], None).expect("inert pin, no torque");
    let b = s.aba(&q, &v, &[0.0, 0.0], None).expect("inert pin, no torque");
    assert_eq!(a, b);
    assert_eq!(a[1], 0.0);
    let e1 = m.aba(&q, &v, &[0.0, 1.0], None).expect_err("torque on an inert pin");
    let e2 = s.aba(&q, &v, &[0.0, 1.0], None).expect_err("torque on an inert pin");
    assert_eq!(e1.to_string(), e2.to_string());
}

/// A chain of pins (about +â or −â, offsets and centres off the plane) takes the passes
/// compiled for chains (`Planar::pin_chain`); with zero external wrenches it takes the
/// general passes, whose extra operations subtract zeros. The two give the same bits of v̇,
/// in f64 and in dual numbers, over 1–9 links and 200 states each; a branch, a slider or a
/// weld is not a pin chain.
#[test]
fn pin_chain_passes_give_the_general_passes_bits() {
    let mut rnd = uniform(0x9e37_79b9_7f4a_7c15);
    for n in 1..=9 {
        let m = random_chain(n, &mut rnd);
        assert!(m.planar.as_ref().expect("planar").pin_chain, "n = {n}");
        let zero = vec![JointWrench::default(); n];
        let bits = |x: &[f64]| x.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
        for _ in 0..200 {
            let q: Vec<f64> = (0..n).map(|_| 3.0 * rnd()).collect();
            let v: Vec<f64> = (0..n).map(|_| 2.0 * rnd()).collect();
            let tau: Vec<f64> = (0..n).map(|_| rnd()).collect();
            let chain = m.aba(&q, &v, &tau, None).expect("definite");
            let general = m.aba(&q, &v, &tau, Some(&zero)).expect("definite");
            assert_eq!(bits(&chain), bits(&general), "n = {n}, q = {q:?}");
            let d = m.cast::<Dual64>();
            let qd: Vec<Dual64> = q.iter().map(|&x| Dual64::new(x, rnd())).collect();
            let (vd, td): (Vec<Dual64>, Vec<Dual64>) =
                v.iter().zip(&tau).map(|(&a, &b)| (Dual64::from(a), Dual64::from(b))).unzip();
            let zd = vec![JointWrench::<Dual64>::default(); n];
            let a = d.aba(&qd, &vd, &td, None).expect("definite");
            let b = d.aba(&qd, &vd, &td, Some(&zd)).expect("definite");
            for (x, y) in a.iter().zip(&b) {
                assert_eq!(
                    (x.re.to_bits(), x.eps.to_bits()),
                    (y.re.to_bits(), y.eps.to_bits()),
                    "dual, n = {n}"
                );
            }
        }
    }
    let tree = Model::new(&tree(Vector3::y(), Vector3::x())).expect("valid");
    assert!(!tree.planar.as_ref().expect("planar").pin_chain);
}

/// `Model::aba_pair_unchecked` gives each state the bits of `aba_unchecked`: on pin chains of
/// 1–9 and 30 links (pins about +â and −â, gravity off the plane, torques), 100 pairs each,
/// angles up to 3 rad and some far beyond the SIMD kernel's range (its libm fall-back);
/// a tree (two calls); an inert pin in either lane (two calls, which decide it); lengths
/// refused with the argument named.
#[test]
fn paired_passes_give_each_state_the_bits_of_one_call() {
    let mut rnd = uniform(0x2545_f491_4f6c_dd1d);
    let bits = |x: &[f64]| x.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
    let check = |m: &Model, q: [&[f64]; 2], v: [&[f64]; 2], tau: &[f64], paired: bool| {
        let nv = m.nv();
        let mut s = m.aba_scratch();
        let (mut da, mut db) = (vec![0.0; nv], vec![0.0; nv]);
        let (mut ea, mut eb) = (vec![0.0; nv], vec![0.0; nv]);
        m.aba_pair_unchecked((q[0], v[0]), (q[1], v[1]), tau, (&mut da, &mut db), &mut s).expect("definite");
        m.aba_unchecked(q[0], v[0], tau, &mut ea, &mut s).expect("definite");
        m.aba_unchecked(q[1], v[1], tau, &mut eb, &mut s).expect("definite");
        assert_eq!((bits(&da), bits(&db)), (bits(&ea), bits(&eb)), "q = {q:?}");
        // and the paired passes themselves ran (not the two calls of the fall-back)
        if let Some(p) = m.planar.as_ref().filter(|p| p.pin_chain) {
            let n = p.segs.len();
            let (mut ps, mut tr) = (vec![super::pair::PairScratch::default(); n], vec![0.0; 6 * n]);
            let g = [-m.gravity.dot(&p.u), -m.gravity.dot(&p.w)];
            let (mut fa, mut fb) = (vec![0.0; nv], vec![0.0; nv]);
            let ran = p.aba_pair((q[0], v[0]), (q[1], v[1]), tau, g, (&mut fa, &mut fb), &mut ps, &mut tr);
            assert_eq!(ran, paired, "q = {q:?}");
            if ran {
                assert_eq!((bits(&fa), bits(&fb)), (bits(&ea), bits(&eb)), "q = {q:?}");
            }
        }
    };
    for n in (1..=9).chain([30]) {
        let m = random_chain(n, &mut rnd);
        assert!(m.aba_pairs(), "n = {n}");
        for k in 0..100 {
            let big = if k % 10 == 0 { 1e7 } else { 3.0 };
            let mut st = || -> Vec<f64> { (0..n).map(|_| big * rnd()).collect() };
            let (qa, qb, va, vb) = (st(), st(), st(), st());
            let tau: Vec<f64> = (0..n).map(|_| rnd()).collect();
            check(&m, [&qa, &qb], [&va, &vb], &tau, true);
        }
    }
    let tree = Model::new(&tree(Vector3::y(), Vector3::x())).expect("valid");
    assert!(!tree.aba_pairs());
    let (q, v, tau, _) = state();
    let q2: Vec<f64> = q.iter().map(|x| x + 0.3).collect();
    check(&tree, [&q, &q2], [&v, &v], &tau, false);
    // an inert pin (the chain of `inert_pin_falls_back_to_the_spatial_passes`)
    let z = Matrix3::zeros();
    let links = [
        Link::new(None, Joint::Pin { axis: Vector3::y() }, Vector3::zeros(), 1.0, Vector3::x(), z),
        Link::new(Some(0), Joint::Pin { axis: Vector3::y() }, Vector3::x(), 2.0, Vector3::zeros(), z),
    ];
    let inert = Model::new(&links).expect("valid");
    assert!(inert.aba_pairs());
    check(&inert, [&[0.4, -0.7], &[0.1, 0.2]], [&[0.3, 1.2], &[0.0, 0.5]], &[0.0, 0.0], false);
    let mut s = inert.aba_scratch();
    let (mut da, mut db) = (vec![0.0; 2], vec![0.0; 1]);
    let e = inert
        .aba_pair_unchecked(
            (&[0.0; 2], &[0.0; 2]),
            (&[0.0; 2], &[0.0; 2]),
            &[0.0; 2],
            (&mut da, &mut db),
            &mut s,
        )
        .expect_err("v̇_b of length 1");
    assert_eq!(e.to_string(), "v̇_b has length 1, expected 2");
}
