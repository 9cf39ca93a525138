//! §2.19–2.22: additivity, commutators, rigid displacements, Chasles, chains; Ex 2.25.1 and
//! Probs 2.26.19–20.

use crate::support::NanAmax;
use std::f64::consts::PI;

use nalgebra::{Matrix3, Matrix4, Vector3, Vector4};
use vectrix::prelude::*;

use super::{assert_mat, assert_vec, rot};
use crate::support::*;

/// F2.19.1: for coplanar x, y, z with normal n̂, θ_{z/x/n} ≡ θ_{z/y/n} + θ_{y/x/n}, and
/// R_n(θ_{z/x}) = R_n(θ_{z/y})R_n(θ_{y/x}); parallel angle vectors add (wrapped), others do not.
#[test]
fn fact_2_19_1_coplanar_angle_vectors_add() {
    let a = Frame::new();
    let (x, y, z) = (a.vector([1.0, 0.0, 0.0]), a.vector([-1.0, 1.0, 0.0]), a.vector([0.2, -1.0, 0.0]));
    let n = a.k();
    let (t_zx, t_zy, t_yx) = (
        z.directed_angle_rel(&x, &n).unwrap(),
        z.directed_angle_rel(&y, &n).unwrap(),
        y.directed_angle_rel(&x, &n).unwrap(),
    );
    assert!(congruent(t_zx, t_zy + t_yx, 8.0 * EPS));
    let lhs = Rotation::from_axis_angle(&n, t_zx).unwrap();
    let rhs = Rotation::from_axis_angle(&n, t_zy).unwrap() * Rotation::from_axis_angle(&n, t_yx).unwrap();
    assert_mat(&lhs.rotation_matrix_in(&a), &rhs.rotation_matrix_in(&a), 8.0 * EPS);
    let sum = compose_coplanar(&(n * t_zy), &(n * t_yx), 1e-12).unwrap();
    assert_vec(&sum.resolve(&a), &(n * wrap_angle(t_zy + t_yx)).resolve(&a), 8.0 * EPS);
    assert_vec(&Rotation::exp(&sum).unwrap().log().resolve(&a), &rhs.log().resolve(&a), 16.0 * EPS);
    assert!(compose_coplanar(&a.i(), &a.j(), 1e-12).is_none());
}

/// F2.19.2: ((x̂×ŷ)·ẑ)² = 1 + 2c_{xy}c_{yz}c_{zx} − c_{xy}² − c_{yz}² − c_{zx}² (the Gram determinant).
#[test]
fn fact_2_19_2_gram_identity() {
    let a = Frame::new();
    let (x, y, z) = (
        a.vector([1.0, 2.0, 0.5]).unit().unwrap(),
        a.vector([-1.0, 0.3, 2.0]).unit().unwrap(),
        a.vector([0.2, -1.0, 1.0]).unit().unwrap(),
    );
    let (cxy, cyz, czx) = (x.dot(&y), y.dot(&z), z.dot(&x));
    let lhs = x.cross(&y).dot(&z).powi(2);
    assert_abs(lhs, 1.0 + 2.0 * cxy * cyz * czx - cxy * cxy - cyz * cyz - czx * czx, 16.0 * EPS);
}

/// F2.19.3–4: rotations commute ⟺ parallel axes, or one is I, or both are half-turns about
/// perpendicular axes; otherwise the commutator (2.19.6) is nonzero.
#[test]
fn fact_2_19_4_when_rotations_commute() {
    let a = Frame::new();
    let tol = 16.0 * EPS;
    assert!(rot(&a, [1.0, 2.0, 3.0], 0.4).commutes_with(&rot(&a, [-1.0, -2.0, -3.0], 2.0), tol));
    assert!(rot(&a, [1.0, 2.0, 3.0], 0.4).commutes_with(&Rotation::identity(), tol));
    assert!(rot(&a, [1.0, 0.0, 0.0], PI).commutes_with(&rot(&a, [0.0, 1.0, 1.0], PI), tol));
    assert!(!rot(&a, [1.0, 0.0, 0.0], PI).commutes_with(&rot(&a, [0.0, 1.0, 1.0], 1.0), 1e-3));
    assert!(!rot(&a, [1.0, 0.0, 0.0], 0.5).commutes_with(&rot(&a, [0.0, 1.0, 0.0], 0.5), 1e-3));
}

/// F2.20.2–3: a rotation about a point preserves distances, and each displacement is ⊥ the axis.
#[test]
fn fact_2_20_2_rotation_about_a_point() {
    let a = Frame::new();
    let r = rot(&a, [1.0, -1.0, 2.0], 1.3);
    let n = r.axis_angle().axis().unwrap();
    let (y1, y2) = (a.vector([1.0, 2.0, 3.0]), a.vector([-2.0, 0.5, 1.0]));
    assert_rel(r.apply(&y1).angle(&r.apply(&y2)), y1.angle(&y2), 8.0 * EPS);
    assert_rel((r.apply(&y1) - r.apply(&y2)).norm(), (y1 - y2).norm(), 8.0 * EPS);
    assert_abs(n.dot(&(r.apply(&y1) - y1)), 0.0, 8.0 * EPS);
}

/// F2.21.1–3: r_{y′/x} = R r_{y/x} + r preserves distances; r = r_{y_i′/x} − R r_{y_i/x} for every
/// point (**corrected** (2.21.2): y_i, printed y₁); n̂·(r_{y′/y} − r) = 0.
#[test]
fn fact_2_21_1_rigid_displacement() {
    let a = Frame::new();
    let d = RigidDisplacement::new(rot(&a, [0.0, 1.0, 1.0], 0.8), a.vector([0.5, -1.0, 2.0]));
    let n = d.rotation.axis_angle().axis().unwrap();
    let ys = [a.vector([1.0, 2.0, 3.0]), a.vector([-2.0, 0.5, 1.0]), a.vector([0.0, 0.0, -4.0])];
    for y in ys {
        assert_vec(&(d.apply(&y) - d.rotation.apply(&y)).resolve(&a), &d.translation.resolve(&a), 16.0 * EPS);
        assert_abs(n.dot(&(d.apply(&y) - y - d.translation)), 0.0, 16.0 * EPS);
    }
    assert_rel((d.apply(&ys[0]) - d.apply(&ys[1])).norm(), (ys[0] - ys[1]).norm(), 16.0 * EPS);
    let back = d.inverse().compose(&d);
    assert_vec(&back.apply(&ys[2]).resolve(&a), &ys[2].resolve(&a), 32.0 * EPS);
}

/// F2.21.4 (Chasles), constructive: axis point c = ½[r⊥ + cot(θ/2) n̂×r⊥], slide α = n̂·r;
/// checked at θ = 0.3, 1.7, π (notes ch2b §2), and `Screw::Translation` at θ = 0.
#[test]
fn fact_2_21_4_chasles_screw() {
    let a = Frame::new();
    let t = a.vector([1.0, -0.5, 2.0]);
    for th in [0.3, 1.7, PI] {
        let d = RigidDisplacement::new(rot(&a, [1.0, 2.0, 2.0], th), t);
        let Screw::General { point, axis, angle, slide } = d.screw(1e-12) else { panic!("general screw") };
        assert_abs(angle, th, 8.0 * EPS); // angle ∈ [0, π]
        assert_rel(slide, axis.dot(&t), 8.0 * EPS);
        // The axis point moves only along the axis: r_{z′/x} = c + αn̂.
        assert_vec(&d.apply(&point).resolve(&a), &(point + axis * slide).resolve(&a), 32.0 * EPS);
    }
    let d = RigidDisplacement::new(Rotation::identity(), t);
    assert_eq!(d.screw(1e-12), Screw::Translation(t));
}

/// (2.22.2–3): the forward sum and the backward (Horner) form give the same tip position, equal to
/// the frame-free sum of the link vectors.
#[test]
fn eq_2_22_2_chain_forward_and_backward() {
    let a = Frame::new();
    let b = rot(&a, [0.0, 0.0, 1.0], 0.4).apply_frame(&a);
    let c = Rotation::from_axis_angle(&b.j(), -0.9).unwrap().apply_frame(&b);
    let d = Rotation::from_axis_angle(&c.i(), 1.6).unwrap().apply_frame(&c);
    let (r_ba, r_cb, r_dc) =
        (b.vector([1.0, 0.2, 0.0]), c.vector([0.0, 2.0, -0.3]), d.vector([0.5, 0.0, 1.5]));
    let links = [
        ChainLink { o_child_parent: b.orientation_rel(&a), r_in_child: r_ba.resolve(&b) },
        ChainLink { o_child_parent: c.orientation_rel(&b), r_in_child: r_cb.resolve(&c) },
        ChainLink { o_child_parent: d.orientation_rel(&c), r_in_child: r_dc.resolve(&d) },
    ];
    let want = (r_ba + r_cb + r_dc).resolve(&a);
    assert_vec(&chain_forward(&links), &want, 16.0 * EPS);
    assert_vec(&chain_backward(&links), &want, 16.0 * EPS);
}

/// Ex 2.25.1 (three-bar linkage, 3-2-3): ℓ = (3, 4, 2), ψ = 30°, θ = −20°, φ = 45°;
/// r|_A = 𝓞₃ᵀ(ψ)[ℓ₃𝓞₂ᵀ(θ)𝓞₃ᵀ(φ) + ℓ₂𝓞₂ᵀ(θ) + ℓ₁I]e₁ = [6.29, 5.27, 1.85] printed (truncated; computed
/// [6.297043873556, 5.268593137352, 1.851770098599]).
#[test]
fn example_2_25_1_three_bar_linkage() {
    let (l1, l2, l3) = (3.0, 4.0, 2.0);
    let (psi, th, phi) = (30f64.to_radians(), (-20f64).to_radians(), 45f64.to_radians());
    let a = Frame::new();
    let b = Rotation::from_axis_angle(&a.k(), psi).unwrap().apply_frame(&a);
    let c = Rotation::from_axis_angle(&b.j(), th).unwrap().apply_frame(&b);
    let d = Rotation::from_axis_angle(&c.k(), phi).unwrap().apply_frame(&c);
    let r = (b.i() * l1 + c.i() * l2 + d.i() * l3).resolve(&a);
    let o = |i, t| orientation_about(Axis::from_index(i).unwrap(), t);
    let formula = o(3, psi).transpose()
        * (o(2, th).transpose() * o(3, phi).transpose() * l3
            + o(2, th).transpose() * l2
            + Matrix3::identity() * l1)
        * Vector3::x();
    assert_vec(&r, &formula, 16.0 * EPS);
    assert_printed_slice(r.as_slice(), &["6.297043873556", "5.268593137352", "1.851770098599"]);
    // The book prints [6.29, 5.27, 1.85]: 6.297 is chopped to 6.29 (rounding gives 6.30),
    // 5.2686 and 1.8518 are rounded.
    assert_truncated(r[0], "6.29");
    assert_printed_slice(&r.as_slice()[1..], &["5.27", "1.85"]);
    // The same through Euler angles 3-2-3 and a chain.
    let e = EulerAngles::new(EulerSequence::S323, [psi, th, phi]);
    assert_mat(&e.orientation_matrix(), &d.orientation_rel(&a), 8.0 * EPS);
    let links = [
        ChainLink { o_child_parent: b.orientation_rel(&a), r_in_child: Vector3::new(l1, 0.0, 0.0) },
        ChainLink { o_child_parent: c.orientation_rel(&b), r_in_child: Vector3::new(l2, 0.0, 0.0) },
        ChainLink { o_child_parent: d.orientation_rel(&c), r_in_child: Vector3::new(l3, 0.0, 0.0) },
    ];
    assert_vec(&chain_backward(&links), &r, 16.0 * EPS);
}

/// Probs 2.26.19–20: [[𝓞_{B/A}, r|_B], [0, 1]]⁻¹ = [[𝓞_{A/B}, −𝓞_{A/B} r|_B], [0, 1]].
#[test]
fn problem_2_26_19_homogeneous_inverse() {
    let a = Frame::new();
    let o_ba = EulerAngles::new(EulerSequence::S321, [0.3, -0.2, 1.0]).orientation_matrix();
    let r = Vector3::new(1.0, -2.0, 0.5);
    let h = homogeneous(&o_ba, &r);
    let inv = homogeneous_inverse(&h);
    assert!((h * inv - Matrix4::identity()).nan_amax() <= 8.0 * EPS);
    assert!((inv - homogeneous(&o_ba.transpose(), &-(o_ba.transpose() * r))).nan_amax() <= 0.0);
    // A displacement as a homogeneous transform acting on [r_{y/x}|_A; 1].
    let d = RigidDisplacement::new(rot(&a, [1.0, 0.0, 1.0], 0.6), a.vector([0.1, 0.2, 0.3]));
    let y = a.vector([2.0, -1.0, 0.5]);
    let hy = d.homogeneous_in(&a) * Vector4::new(2.0, -1.0, 0.5, 1.0);
    assert_vec(&hy.xyz(), &d.apply(&y).resolve(&a), 8.0 * EPS);
    let back = RigidDisplacement::from_homogeneous_in(&a, &d.homogeneous_in(&a), ROTATION_TOL).unwrap();
    assert_vec(&back.apply(&y).resolve(&a), &d.apply(&y).resolve(&a), 16.0 * EPS);
    let mut bad = d.homogeneous_in(&a);
    bad[(3, 0)] = 0.5;
    assert!(RigidDisplacement::from_homogeneous_in(&a, &bad, ROTATION_TOL).is_err());
}
