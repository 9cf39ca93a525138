//! The analytical derivatives against forward-mode dual numbers through the generic RNEA and
//! ABA, on a tree with every joint type, external wrenches and oblique gravity.

use nalgebra::{Matrix3, Vector3};
use num_dual::Dual64;

use super::*;
use crate::multibody::{Joint, JointWrench, Link};

/// Link k of the test trees: mass 1 + 0.3k, centre (0.1k, −0.2, 0.15), one central inertia.
fn plain(parent: Option<usize>, joint: Joint, offset: [f64; 3], k: f64) -> Link {
    Link::new(
        parent,
        joint,
        Vector3::from(offset),
        1.0 + 0.3 * k,
        Vector3::new(0.1 * k, -0.2, 0.15),
        Matrix3::new(0.3, 0.01, 0.02, 0.01, 0.4, -0.03, 0.02, -0.03, 0.5),
    )
}

/// A tree with every joint type, off-axis centres, rotated joint frames and gravity.
fn tree() -> Model {
    let body = |parent, joint, offset: [f64; 3], k: f64| {
        let mut l = plain(parent, joint, offset, k);
        l.orientation = nalgebra::Rotation3::from_scaled_axis(Vector3::new(0.2 * k, -0.1, 0.3)).into_inner();
        l
    };
    let z = Vector3::z();
    let links = vec![
        body(None, Joint::Free, [0.1, 0.0, 0.2], 0.0),
        body(Some(0), Joint::Pin { axis: Vector3::new(1.0, 2.0, 0.5) }, [0.5, 0.0, 0.0], 1.0),
        body(Some(1), Joint::Sleeve { axis: Vector3::x() }, [0.0, 0.4, 0.0], 2.0),
        body(Some(0), Joint::Collar { axis: z }, [0.0, -0.5, 0.1], 3.0),
        body(Some(3), Joint::Slot { axis: z, direction: Vector3::y() }, [0.3, 0.0, 0.0], 4.0),
        body(Some(4), Joint::Ball, [0.0, 0.0, 0.6], 5.0),
        body(Some(5), Joint::Weld, [0.2, 0.2, 0.0], 6.0),
        body(Some(6), Joint::Pin { axis: Vector3::y() }, [0.0, 0.3, 0.1], 7.0),
    ];
    let mut m = Model::new(&links).unwrap();
    m.gravity = Vector3::new(0.3, -0.2, -9.81);
    m
}

fn state(m: &Model) -> (Vec<f64>, Vec<f64>, Vec<f64>, Vec<JointWrench>) {
    let mut q = m.neutral();
    for (k, x) in q.iter_mut().enumerate() {
        *x += 0.4 * (1.3 * k as f64 + 0.2).sin();
    }
    let v: Vec<f64> = (0..m.nv()).map(|k| 0.7 * (1.7 * k as f64).cos()).collect();
    let a: Vec<f64> = (0..m.nv()).map(|k| 0.5 * (0.9 * k as f64 + 1.0).sin()).collect();
    let f: Vec<JointWrench> = (0..m.links())
        .map(|l| JointWrench {
            force: Vector3::new(0.3, -0.1 * l as f64, 0.2),
            moment: Vector3::new(-0.05, 0.02, 0.01 * l as f64),
        })
        .collect();
    (q, v, a, f)
}

/// Tangent-space directional derivative of any generic computation by one Dual64 pass.
fn seeded(m: &Model, q: &[f64], k: usize) -> Vec<Dual64> {
    let dual = m.cast::<Dual64>();
    let qd: Vec<Dual64> = q.iter().map(|&x| Dual64::from(x)).collect();
    let e: Vec<Dual64> = (0..m.nv())
        .map(|i| if i == k { Dual64::from(0.0).derivative() } else { Dual64::from(0.0) })
        .collect();
    dual.integrate(&qd, &e, Dual64::from(1.0)).unwrap()
}

fn lift(x: &[f64]) -> Vec<Dual64> {
    x.iter().map(|&x| Dual64::from(x)).collect()
}

fn lift_wrenches(f: &[JointWrench]) -> Vec<JointWrench<Dual64>> {
    f.iter()
        .map(|w| JointWrench { force: w.force.map(Dual64::from), moment: w.moment.map(Dual64::from) })
        .collect()
}

/// The analytical ∂τ/∂q and ∂τ/∂v agree with forward-mode dual numbers through the
/// generic RNEA to rounding; ∂τ/∂v̇ is the CRBA mass matrix.
#[test]
fn rnea_derivatives_match_dual_numbers() {
    let m = tree();
    let (q, v, a, f) = state(&m);
    let d = m.rnea_derivatives(&q, &v, &a, Some(&f)).unwrap();
    let tau = m.rnea(&q, &v, &a, Some(&f)).unwrap().tau;
    let dual = m.cast::<Dual64>();
    let fd = lift_wrenches(&f);
    let scale = 1.0 + d.dtau_dq.amax().max(d.dtau_dv.amax());
    for (x, y) in d.tau.iter().zip(&tau) {
        assert!((x - y).abs() <= 1e-13 * scale, "τ {x} vs {y}");
    }
    for k in 0..m.nv() {
        let qk = seeded(&m, &q, k);
        let t = dual.rnea(&qk, &lift(&v), &lift(&a), Some(&fd)).unwrap().tau;
        for (r, tr) in t.iter().enumerate() {
            assert!(
                (tr.eps - d.dtau_dq[(r, k)]).abs() <= 1e-13 * scale,
                "dq ({r},{k}): {} vs {}",
                tr.eps,
                d.dtau_dq[(r, k)]
            );
        }
        let mut vk = lift(&v);
        vk[k].eps = 1.0;
        let t = dual.rnea(&lift(&q), &vk, &lift(&a), Some(&fd)).unwrap().tau;
        for (r, tr) in t.iter().enumerate() {
            assert!(
                (tr.eps - d.dtau_dv[(r, k)]).abs() <= 1e-13 * scale,
                "dv ({r},{k}): {} vs {}",
                tr.eps,
                d.dtau_dv[(r, k)]
            );
        }
    }
    let h = m.crba(&q).unwrap();
    assert!((&h - &d.mass_matrix).amax() <= 1e-14 * h.amax());
}

/// ∂v̇/∂(q, v, τ) agree with dual numbers through the generic ABA.
#[test]
fn aba_derivatives_match_dual_numbers() {
    let m = tree();
    let (q, v, tau, f) = state(&m);
    let d = m.aba_derivatives(&q, &v, &tau, Some(&f)).unwrap();
    let dual = m.cast::<Dual64>();
    let fd = lift_wrenches(&f);
    let scale = 1.0 + d.dvdot_dq.amax().max(d.dvdot_dv.amax()).max(d.dvdot_dtau.amax());
    for k in 0..m.nv() {
        let qk = seeded(&m, &q, k);
        let a = dual.aba(&qk, &lift(&v), &lift(&tau), Some(&fd)).unwrap();
        for (r, ar) in a.iter().enumerate() {
            assert!((ar.eps - d.dvdot_dq[(r, k)]).abs() <= 1e-12 * scale, "dq ({r},{k})");
        }
        let mut vk = lift(&v);
        vk[k].eps = 1.0;
        let a = dual.aba(&lift(&q), &vk, &lift(&tau), Some(&fd)).unwrap();
        for (r, ar) in a.iter().enumerate() {
            assert!((ar.eps - d.dvdot_dv[(r, k)]).abs() <= 1e-12 * scale, "dv ({r},{k})");
        }
        let mut tk = lift(&tau);
        tk[k].eps = 1.0;
        let a = dual.aba(&lift(&q), &lift(&v), &tk, Some(&fd)).unwrap();
        for (r, ar) in a.iter().enumerate() {
            assert!((ar.eps - d.dvdot_dtau[(r, k)]).abs() <= 1e-12 * scale, "dτ ({r},{k})");
        }
    }
}

/// Two legs standing on the ground (two roots, no common ancestor coordinate): M⁻¹, like M,
/// has a zero block between them.
fn two_roots() -> Model {
    let body = plain;
    let pin = |x: f64, y: f64, z: f64| Joint::Pin { axis: Vector3::new(x, y, z) };
    let links = vec![
        body(None, pin(0.0, 0.0, 1.0), [0.0, 0.0, 0.0], 0.0),
        body(Some(0), Joint::Ball, [0.5, 0.0, 0.0], 1.0),
        body(None, Joint::Sleeve { axis: Vector3::x() }, [0.0, 1.0, 0.0], 2.0),
        body(Some(2), pin(1.0, 0.0, 0.2), [0.0, 0.4, 0.0], 3.0),
    ];
    let mut m = Model::new(&links).unwrap();
    m.gravity = Vector3::new(0.3, -0.2, -9.81);
    m
}

/// The `_into` hot paths clear only the entries that are zero whatever the state (those
/// between branches) and write every other one: output buffers full of NaN (stale, or the
/// caller's) give the same bits as fresh ones, a reused work space too, and the entries between
/// branches of M, ∂τ/∂q and ∂τ/∂v are exactly zero.
#[test]
fn into_paths_overwrite_stale_buffers() {
    for m in [tree(), two_roots()] {
        let (q, v, a, f) = state(&m);
        let n = m.nv();
        let nan = |k: &mut DMatrix<f64>| k.fill(f64::NAN);
        let h = m.crba(&q).unwrap();
        let (mut h2, mut cs) = (DMatrix::from_element(n, n, f64::NAN), m.crba_scratch());
        m.crba_into(&q, &mut h2, &mut cs);
        assert_eq!(h2, h, "crba_into");
        let rd = m.rnea_derivatives(&q, &v, &a, Some(&f)).unwrap();
        let ad = m.aba_derivatives(&q, &v, &a, Some(&f)).unwrap();
        let mut s = m.derivative_scratch();
        for _ in 0..2 {
            let mut ro = RneaDerivatives::zeros(&m);
            [&mut ro.dtau_dq, &mut ro.dtau_dv, &mut ro.mass_matrix].into_iter().for_each(nan);
            m.rnea_derivatives_into(&q, &v, &a, Some(&f), &mut ro, &mut s);
            assert_eq!(ro, rd, "rnea_derivatives_into");
            let mut ao = AbaDerivatives::zeros(&m);
            [&mut ao.dvdot_dq, &mut ao.dvdot_dv, &mut ao.dvdot_dtau].into_iter().for_each(nan);
            m.aba_derivatives_into(&q, &v, &a, Some(&f), &mut ao, &mut s).unwrap();
            assert_eq!(ao, ad, "aba_derivatives_into");
        }
        let above = |i: usize, j: usize| {
            let mut c = m.parent_col[j];
            while let Some(p) = c {
                if p == i {
                    return true;
                }
                c = m.parent_col[p];
            }
            false
        };
        let unrelated: Vec<(usize, usize)> = (0..n)
            .flat_map(|i| (0..n).map(move |j| (i, j)))
            .filter(|&(i, j)| i != j && !above(i, j) && !above(j, i))
            .collect();
        assert!(!unrelated.is_empty(), "the model has branches");
        for (i, j) in unrelated {
            assert_eq!(
                [h[(i, j)], rd.dtau_dq[(i, j)], rd.dtau_dv[(i, j)], rd.mass_matrix[(i, j)]],
                [0.0; 4],
                "({i}, {j})"
            );
        }
    }
    // with no common ancestor, M⁻¹ is zero between the two legs too
    let m = two_roots();
    let (q, v, a, _) = state(&m);
    let ad = m.aba_derivatives(&q, &v, &a, None).unwrap();
    assert_eq!(ad.dvdot_dtau[(0, 4)], 0.0);
    assert_eq!(ad.dvdot_dtau[(4, 0)], 0.0);
}

/// CRBA's picks for sliders along ground axes (`Model::ground_axis_columns`): a root sleeve
/// along −x̂ carrying a sleeve along ŷ and a pin gives the H of the same model with +x̂ at −q₀
/// with row and column 0 negated (S₀ flips sign), exactly; a root sleeve behind a turned
/// placement is not a pick.
#[test]
fn crba_picks_follow_the_slider_direction() {
    let j = Matrix3::new(0.2, 0.01, 0.0, 0.01, 0.15, 0.02, 0.0, 0.02, 0.1);
    let build = |x: f64, turned: bool| {
        let mut root = Link::new(
            None,
            Joint::Sleeve { axis: Vector3::new(x, 0.0, 0.0) },
            Vector3::zeros(),
            0.0,
            Vector3::zeros(),
            Matrix3::zeros(),
        );
        if turned {
            root.orientation =
                nalgebra::Rotation3::from_scaled_axis(Vector3::new(0.0, 0.0, 0.3)).into_inner();
        }
        let links = [
            root,
            Link::new(
                Some(0),
                Joint::Sleeve { axis: Vector3::y() },
                Vector3::zeros(),
                0.5,
                Vector3::new(0.1, 0.0, 0.0),
                j,
            ),
            Link::new(
                Some(1),
                Joint::Pin { axis: Vector3::z() },
                Vector3::new(0.3, 0.1, 0.0),
                1.5,
                Vector3::new(0.4, -0.1, 0.05),
                j,
            ),
        ];
        Model::new(&links).unwrap()
    };
    let (minus, plus) = (build(-1.0, false), build(1.0, false));
    assert_eq!(minus.ground_axis_columns()[..2], [Some((3, true)), Some((4, false))]);
    assert_eq!(build(1.0, true).ground_axis_columns()[..2], [None, None]);
    let q = [0.4, -0.3, 0.7];
    let (hm, hp) = (minus.crba(&q).unwrap(), plus.crba(&[-0.4, -0.3, 0.7]).unwrap());
    for r in 0..3 {
        for c in 0..3 {
            let sign = if (r == 0) != (c == 0) { -1.0 } else { 1.0 };
            assert_eq!(hm[(r, c)], sign * hp[(r, c)], "({r}, {c})");
        }
    }
}
