//! §2.6–2.10: physical matrices (dyadics), projectors, the identity and rotation dyads, the
//! cross-product dyad, rotation and orientation matrices, invariants and Cayley–Hamilton; and
//! resolution of tensors (3.6.2) used by the frame-independence tests.

use crate::support::NanAmax;
use std::f64::consts::FRAC_PI_2;

use vectrix::frames::{change_frame_dyadic, change_frame_tensor};
use vectrix::nalgebra::{DMatrix, Matrix3, Vector3};
use vectrix::prelude::*;

use crate::geometry::{arr, assert_mat_abs, assert_mat_rel, frame_b};
use crate::support::*;

fn m3(rows: [[f64; 3]; 3]) -> Matrix3<f64> {
    Matrix3::from_rows(&rows.map(|r| Vector3::from(r).transpose()))
}

/// (2.6.1)–(2.6.6), (2.6.15): the dyad xy′ acts by (xy′)z = (y·z)x and z′(xy′) = (z·x)y′;
/// (xy′)(wv′) = (y·w)xv′; resolved, (xy′)|_A = x|_A y|_Aᵀ (the printed y′|_A is an erratum).
#[test]
fn eq_2_6_3_dyad_rules() {
    let (_, b) = frame_b();
    let (x, y, z) = (b.vector([1.0, 2.0, 3.0]), b.vector([-2.0, 0.5, 1.0]), b.vector([0.3, -1.0, 4.0]));
    let xy = x.outer(&y);
    assert_rel_slice(&arr((xy * z).resolve(&b)), &arr((x * y.dot(&z)).resolve(&b)), 8.0 * EPS);
    let zc = (z.coform() * xy).resolve(&b);
    assert_rel_slice(zc.as_slice(), (y.coform() * z.dot(&x)).resolve(&b).as_slice(), 8.0 * EPS);
    let (w, v) = (b.vector([0.0, 1.0, -1.0]), b.vector([2.0, 2.0, 1.0]));
    assert_mat_rel(&(xy * w.outer(&v)).resolve(&b), &(x.outer(&v) * y.dot(&w)).resolve(&b), 8.0 * EPS);
    assert_mat_rel(&xy.resolve(&b), &(x.resolve(&b) * y.resolve(&b).transpose()), 8.0 * EPS);
    // x⃗ y⃗′ written as a product of a vector and a covector.
    assert_eq!(x * y.coform(), xy);
}

/// (2.9.3): the frame-free form x^× = (î·x)(k̂ĵ′ − ĵk̂′) + (ĵ·x)(îk̂′ − k̂î′) + (k̂·x)(ĵî′ − îĵ′),
/// the same in every frame.
#[test]
fn eq_2_9_3_cross_dyad_from_any_frame() {
    let (a, b) = frame_b();
    let x = a.vector([1.0, 2.0, 3.0]);
    let (i, j, k) = (b.i(), b.j(), b.k());
    let xx = (k.outer(&j) - j.outer(&k)) * i.dot(&x)
        + (i.outer(&k) - k.outer(&i)) * j.dot(&x)
        + (j.outer(&i) - i.outer(&j)) * k.dot(&x);
    assert_mat_rel(&xx.resolve(&a), &x.cross_dyad().resolve(&a), 16.0 * EPS);
}

/// (2.6.9)–(2.6.12), Fact 2.6.1: (xy′)′ = yx′, (NL)′ = L′N′, (Mz)′ = z′M′; xy′ − yx′ is skew.
#[test]
fn fact_2_6_1_coform_and_skew_dyad() {
    let a = Frame::new();
    let (x, y, z) = (a.vector([1.0, 2.0, 3.0]), a.vector([-2.0, 0.5, 1.0]), a.vector([0.3, -1.0, 4.0]));
    assert_eq!(x.outer(&y).coform(), y.outer(&x));
    let (n, l) = (x.outer(&z) + Dyadic::identity(), z.outer(&y) * 2.0);
    assert_mat_rel(&(n * l).coform().resolve(&a), &(l.coform() * n.coform()).resolve(&a), 8.0 * EPS);
    let mz = (n * z).coform().resolve(&a);
    assert_rel_slice(mz.as_slice(), (z.coform() * n.coform()).resolve(&a).as_slice(), 8.0 * EPS);
    let s = x.outer(&y) - y.outer(&x);
    assert!(s.is_skew(EPS) && !s.is_symmetric(0.1));
    assert_eq!(s.coform(), -s);
}

/// Facts 2.6.2–2.6.5, (2.6.28): (Mz)|_A = M|_A z|_A, M′|_A = M|_Aᵀ, (MN)|_A = M|_A N|_A,
/// x′My = x|_Aᵀ M|_A y|_A, (M|_A)_{ij} = e_i′Me_j; M = N ⟺ M|_A = N|_A.
#[test]
fn fact_2_6_5_resolution_of_physical_matrices() {
    let (a, b) = frame_b();
    let mm = a.dyadic(&m3([[1.0, 2.0, 0.0], [-1.0, 3.0, 4.0], [0.5, 0.0, -2.0]]));
    let nn = b.dyadic(&m3([[0.0, 1.0, 1.0], [2.0, -1.0, 0.0], [1.0, 1.0, 1.0]]));
    let (x, z) = (b.vector([1.0, -2.0, 0.5]), b.vector([3.0, 0.0, 1.0]));
    let m_b = mm.resolve(&b);
    assert_rel_slice(&arr((mm * z).resolve(&b)), &arr(m_b * z.resolve(&b)), 16.0 * EPS);
    assert_mat_rel(&mm.coform().resolve(&b), &m_b.transpose(), 16.0 * EPS);
    assert_mat_rel(&(mm * nn).resolve(&b), &(m_b * nn.resolve(&b)), 32.0 * EPS);
    assert_rel(x.coform() * (mm * z), (x.resolve(&b).transpose() * m_b * z.resolve(&b))[0], 32.0 * EPS);
    assert_rel(m_b[(0, 2)], b.i().coform() * (mm * b.k()), 16.0 * EPS);
    // Fact 2.6.3: rebuilt from its components in B, the same dyadic.
    assert_mat_rel(&b.dyadic(&m_b).resolve(&a), &mm.resolve(&a), 32.0 * EPS);
}

/// Fact 2.6.7: an eigenpair (λ, x) of M is an eigenpair of M|_A, (λ, x|_A).
#[test]
fn fact_2_6_7_eigenpairs_carry_over() {
    let (a, b) = frame_b();
    let x = a.vector([1.0, 1.0, 0.0]);
    // M = 2 x̂x̂′ + (I − x̂x̂′): eigenvalue 2 along x.
    let p = Dyadic::projector_along(&x).unwrap();
    let mm = p * 2.0 + (Dyadic::identity() - p);
    let m_b = mm.resolve(&b);
    assert_rel_slice(&arr(m_b * x.resolve(&b)), &arr(x.resolve(&b) * 2.0), 16.0 * EPS);
}

/// (2.7.1)–(2.7.9), Fact 2.7.1: P_y = ŷŷ′, P_{y⊥} = I − P_y are idempotent and symmetric;
/// P_y x = (x·y/|y|²)y and |P_y x| = |x||cos θ_{y/x}|.
#[test]
fn fact_2_7_1_projectors() {
    let a = Frame::new();
    let (x, y) = (a.vector([3.0, -4.0, 0.0]), a.vector([-1.0, 5.0, -2.0]));
    let p = Dyadic::projector_along(&y).unwrap();
    let q = Dyadic::projector_perp(&y).unwrap();
    assert_mat_abs(&(p * p).resolve(&a), &p.resolve(&a), 8.0 * EPS);
    assert_mat_abs(&(q * q).resolve(&a), &q.resolve(&a), 8.0 * EPS);
    assert!(p.is_symmetric(EPS) && q.is_symmetric(EPS));
    let want = y * (x.dot(&y) / y.norm_squared());
    assert_rel_slice(&arr((p * x).resolve(&a)), &arr(want.resolve(&a)), 8.0 * EPS);
    assert_rel_slice(&arr(x.projection_along(&y).unwrap().resolve(&a)), &arr(want.resolve(&a)), 8.0 * EPS);
    assert_rel((p * x).norm(), x.norm() * x.angle(&y).cos().abs(), 8.0 * EPS);
    assert!(x.projection_perp(&y).unwrap().is_perpendicular(&y, 8.0 * EPS));
    assert!(
        Dyadic::projector_along(&Vector::<f64>::zero()).is_none()
            && x.projection_along(&Vector::zero()).is_none()
    );
}

/// (2.7.10)–(2.7.13), Prob 2.26.7: the plane projector P_{y,z} = P_{y − P_z y} + P_z, symmetric in
/// y and z, equals [|z|²yy′ − (y·z)(yz′ + zy′) + |y|²zz′]/(|y|²|z|² − (y·z)²) and I − n̂n̂′.
#[test]
fn problem_2_26_7_plane_projector() {
    let a = Frame::new();
    let (y, z) = (a.vector([1.0, 1.0, 0.0]), a.vector([1.0, 0.0, 1.0]));
    let p = Dyadic::projector_onto_plane(&y, &z).unwrap();
    let gs = Dyadic::projector_along(&(y - Dyadic::projector_along(&z).unwrap() * y)).unwrap()
        + Dyadic::projector_along(&z).unwrap();
    let (yy, zz, yz) = (y.norm_squared(), z.norm_squared(), y.dot(&z));
    let closed = (y.outer(&y) * zz - (y.outer(&z) + z.outer(&y)) * yz + z.outer(&z) * yy)
        * (1.0 / (yy * zz - yz * yz));
    assert_mat_abs(&p.resolve(&a), &gs.resolve(&a), 8.0 * EPS);
    assert_mat_abs(&p.resolve(&a), &closed.resolve(&a), 8.0 * EPS);
    assert!(Dyadic::projector_onto_plane(&y, &(y * 2.0)).is_none());
}

/// Prob 2.26.8 (erratum): Gram–Schmidt of x, y, z; the printed w = (I − P_x − P_y)z is not
/// orthogonal (u·w = −0.5 for x = (1,1,0), y = (1,0,1), z = (0,1,1)); with v = y − P_x y in
/// place of y, w = (I − P_u − P_v)z is.
#[test]
fn problem_2_26_8_gram_schmidt_corrected() {
    let a = Frame::new();
    let (x, y, z) = (a.vector([1.0, 1.0, 0.0]), a.vector([1.0, 0.0, 1.0]), a.vector([0.0, 1.0, 1.0]));
    let px = Dyadic::projector_along(&x).unwrap();
    let u = x;
    let printed = (Dyadic::identity() - px - Dyadic::projector_along(&y).unwrap()) * z;
    assert_abs(u.dot(&printed), -0.5, 8.0 * EPS);
    let v = (Dyadic::identity() - px) * y;
    let w = (Dyadic::identity() - px - Dyadic::projector_along(&v).unwrap()) * z;
    assert!(u.dot(&v).abs() < 8.0 * EPS && u.dot(&w).abs() < 8.0 * EPS && v.dot(&w).abs() < 8.0 * EPS);
}

/// (2.8.1)–(2.8.3), Fact 2.8.1: I = F_A𝓕′_A is the same for every frame: Ix = x, x′I = x′.
#[test]
fn fact_2_8_1_identity_is_frame_independent() {
    let (a, b) = frame_b();
    let x = b.vector([1.0, -2.0, 0.5]);
    let i_a = a.i().outer(&a.i()) + a.j().outer(&a.j()) + a.k().outer(&a.k());
    let i_b = b.i().outer(&b.i()) + b.j().outer(&b.j()) + b.k().outer(&b.k());
    assert_mat_abs(&i_a.resolve(&b), &Matrix3::identity(), 8.0 * EPS);
    assert_mat_abs(&i_b.resolve(&a), &Matrix3::identity(), 8.0 * EPS);
    assert_eq!(Dyadic::identity() * x, x);
    assert_eq!(x.coform() * Dyadic::identity(), x.coform());
}

/// (2.8.6)–(2.8.14), Facts 2.8.2–2.8.3: R_{B/A} = F_B𝓕′_A takes A's axes to B's (active);
/// R_{A/B} = R′_{B/A} = R⁻¹_{B/A}.
#[test]
fn fact_2_8_2_rotation_dyad_maps_axes() {
    let (a, b) = frame_b();
    let r_ba = b.rotation_dyadic_rel(&a);
    for (ea, eb) in [(a.i(), b.i()), (a.j(), b.j()), (a.k(), b.k())] {
        assert_abs_slice(&arr((r_ba * ea).resolve(&a)), &arr(eb.resolve(&a)), 8.0 * EPS);
    }
    let r_ab = a.rotation_dyadic_rel(&b);
    assert_mat_abs(&r_ab.resolve(&a), &r_ba.coform().resolve(&a), 8.0 * EPS);
    assert_mat_abs(&(r_ab * r_ba).resolve(&b), &Matrix3::identity(), 8.0 * EPS);
    // F_B = R_{B/A} F_A (Fact 2.8.3): rotating A by R_{B/A} gives B.
    let b2 = a.rotated_by(&r_ba, ORTHONORMAL_TOL).unwrap();
    assert_mat_abs(&b2.orientation_rel(&b), &Matrix3::identity(), 8.0 * EPS);
}

/// Facts 2.9.1–2.9.3, (2.9.2)–(2.9.7): x^×|_A = (x|_A)^×; x^×′ = −x^×; x^×x = 0; x′x^× = 0;
/// x^×² = xx′ − |x|²I; a skew M is the cross dyad of its vee (−M₂₃, M₁₃, −M₁₂).
#[test]
fn fact_2_9_2_cross_dyad_identities() {
    let (_, b) = frame_b();
    let x = b.vector([1.0, 2.0, 3.0]);
    let xx = x.cross_dyad();
    assert_mat_rel(&xx.resolve(&b), &x.resolve(&b).cross_matrix(), 8.0 * EPS);
    assert_eq!(xx.coform(), -xx);
    assert!((xx * x).norm() < 16.0 * EPS && (x.coform() * xx).norm() < 16.0 * EPS);
    let want = x.outer(&x) - Dyadic::identity() * x.norm_squared();
    assert_mat_rel(&(xx * xx).resolve(&b), &want.resolve(&b), 16.0 * EPS);
    let m = xx.resolve(&b);
    let vee = [-m[(1, 2)], m[(0, 2)], -m[(0, 1)]];
    assert_rel_slice(&arr(xx.vee().resolve(&b)), &vee, 8.0 * EPS);
    assert_rel_slice(&vee, &[1.0, 2.0, 3.0], 16.0 * EPS);
}

/// Fact 2.9.4, (2.9.8)–(2.9.17): (I + x^×)⁻¹ = (I + xx′ − x^×)/(1 + |x|²), and
/// (I + αx^× + βx^×²)⁻¹ by (2.9.16). Oracle: x = (1, 2, 3) gives (1/15)[[2,5,1],[−1,5,7],[5,5,10]].
#[test]
fn fact_2_9_4_cross_polynomial_inverse() {
    let a = Frame::new();
    let x = a.vector([1.0, 2.0, 3.0]);
    let inv = Dyadic::cross_polynomial_inverse(&x, 1.0, 0.0, 1e-12).unwrap();
    let want = m3([[2.0, 5.0, 1.0], [-1.0, 5.0, 7.0], [5.0, 5.0, 10.0]]) / 15.0;
    assert_mat_abs(&inv.resolve(&a), &want, 8.0 * EPS);
    let alt = (Dyadic::identity() + x.outer(&x) - x.cross_dyad()) * (1.0 / (1.0 + x.norm_squared()));
    assert_mat_abs(&alt.resolve(&a), &want, 8.0 * EPS);
    let (al, be) = (0.7, -0.3);
    let xx = x.cross_dyad();
    let m = Dyadic::identity() + xx * al + xx * xx * be;
    let inv = Dyadic::cross_polynomial_inverse(&x, al, be, 1e-12).unwrap();
    assert_mat_abs(&(inv * m).resolve(&a), &Matrix3::identity(), 64.0 * EPS);
    // D = 0 exactly when α = 0 and β|x|² = 1: singular.
    assert!(Dyadic::cross_polynomial_inverse(&x, 0.0, 1.0 / 14.0, 1e-12).is_err());
}

/// Fact 2.9.5, (2.9.18)–(2.9.23): (x × y)′ = −y′x^×, (x × y)^× = yx′ − xy′, x^×y^× = yx′ − (x·y)I.
#[test]
fn fact_2_9_5_cross_products_of_cross_dyads() {
    let a = Frame::new();
    let (x, y) = (a.vector([1.0, 2.0, 3.0]), a.vector([-2.0, 0.5, 1.0]));
    let lhs = x.cross(&y).coform().resolve(&a);
    assert_rel_slice(lhs.as_slice(), (-(y.coform() * x.cross_dyad())).resolve(&a).as_slice(), 8.0 * EPS);
    assert_mat_rel(
        &x.cross(&y).cross_dyad().resolve(&a),
        &(y.outer(&x) - x.outer(&y)).resolve(&a),
        8.0 * EPS,
    );
    let want = y.outer(&x) - Dyadic::identity() * x.dot(&y);
    assert_mat_rel(&(x.cross_dyad() * y.cross_dyad()).resolve(&a), &want.resolve(&a), 8.0 * EPS);
}

/// Fact 2.9.6 and the (2.9.25) erratum: the area of a parallelogram is |x × y|; the printed
/// chain "‖x × y‖ = ‖(x × y)^×‖_F" is off by √2 (‖v^×‖_F = √2‖v‖): 14.866 vs 21.024 for
/// Prob 2.26.3's data.
#[test]
fn fact_2_9_6_parallelogram_area_and_frobenius_erratum() {
    let a = Frame::new();
    let (x, y) = (a.vector([3.0, -4.0, 0.0]), a.vector([-1.0, 5.0, -2.0]));
    let area = x.cross(&y).norm();
    assert_rel(area, x.norm() * y.norm() * x.angle(&y).sin(), 8.0 * EPS);
    let f = (x.outer(&y) - y.outer(&x)).norm();
    assert_rel(f, 2f64.sqrt() * area, 8.0 * EPS);
    assert_rel(f, 2f64.sqrt() * 221f64.sqrt(), 8.0 * EPS); // √2·|x × y| = √442 = 21.0237960416…
    assert_rel((x.outer(&y) - y.outer(&x)).vee().norm(), area, 8.0 * EPS);
}

/// Facts 2.9.8–2.9.9, 2.10.12–2.10.14: (Rx)^× = Rx^×R′, R(x × y) = Rx × Ry; resolved,
/// 𝓞_{B/A}(x|_A × y|_A) = x|_B × y|_B and (2.10.42) corrected: 𝓞_{A/B}(x|_B)^× = (x|_A)^×𝓞_{A/B}.
#[test]
fn fact_2_9_8_rotation_invariance_of_cross() {
    let (a, b) = frame_b();
    let r = b.rotation_dyadic_rel(&a);
    let (x, y) = (a.vector([1.0, 2.0, 3.0]), a.vector([-2.0, 0.5, 1.0]));
    assert_mat_rel(
        &(r * x).cross_dyad().resolve(&a),
        &(r * x.cross_dyad() * r.coform()).resolve(&a),
        16.0 * EPS,
    );
    assert_rel_slice(
        &arr((r * x.cross(&y)).resolve(&a)),
        &arr((r * x).cross(&(r * y)).resolve(&a)),
        16.0 * EPS,
    );
    let o_ba = b.orientation_rel(&a);
    let (xa, ya, xb) = (x.resolve(&a), y.resolve(&a), x.resolve(&b));
    assert_rel_slice(&arr(o_ba * xa.cross(&ya)), &arr(xb.cross(&y.resolve(&b))), 16.0 * EPS);
    let o_ab = a.orientation_rel(&b);
    assert_mat_rel(&(o_ab * xb.cross_matrix()), &(xa.cross_matrix() * o_ab), 16.0 * EPS);
}

/// Fact 2.10.1, (2.10.2): 𝓡_{B/A} = R_{B/A}|_A = R_{B/A}|_B, whose columns are B's axes in A.
#[test]
fn fact_2_10_1_rotation_matrix_same_in_both_frames() {
    let (a, b) = frame_b();
    let r_ba = b.rotation_rel(&a);
    let rd = b.rotation_dyadic_rel(&a);
    assert_mat_abs(&rd.resolve(&a), &r_ba, 8.0 * EPS);
    assert_mat_abs(&rd.resolve(&b), &r_ba, 8.0 * EPS);
    let cols = Matrix3::from_columns(&[b.i().resolve(&a), b.j().resolve(&a), b.k().resolve(&a)]);
    assert_mat_abs(&r_ba, &cols, 8.0 * EPS);
}

/// Facts 2.10.2–2.10.5, (2.10.5), (2.10.12)–(2.10.15): 𝓞_{B/A} = 𝓡_{A/B} = 𝓡ᵀ_{B/A} = 𝓞ᵀ_{A/B};
/// entries are direction cosines; rows are B's axes in A; 𝓞 is orthogonal.
#[test]
fn fact_2_10_2_orientation_is_transpose_of_rotation() {
    let (a, b) = frame_b();
    let o_ba = b.orientation_rel(&a);
    assert_mat_abs(&o_ba, &a.rotation_rel(&b), 8.0 * EPS);
    assert_mat_abs(&o_ba, &b.rotation_rel(&a).transpose(), 8.0 * EPS);
    assert_mat_abs(&o_ba, &a.orientation_rel(&b).transpose(), 8.0 * EPS);
    assert_abs(o_ba[(0, 1)], b.i().angle(&a.j()).cos(), 8.0 * EPS);
    assert_abs_slice(&arr(o_ba.row(2).transpose()), &arr(b.k().resolve(&a)), 8.0 * EPS);
    assert_mat_abs(&(o_ba * o_ba.transpose()), &Matrix3::identity(), 8.0 * EPS);
    // (2.10.13): [î_B; ĵ_B; k̂_B] = 𝓞_{B/A} [î_A; ĵ_A; k̂_A], row by row.
    let fa = [a.i(), a.j(), a.k()];
    for (r, e_b) in [b.i(), b.j(), b.k()].iter().enumerate() {
        let sum = fa[0] * o_ba[(r, 0)] + fa[1] * o_ba[(r, 1)] + fa[2] * o_ba[(r, 2)];
        assert_abs_slice(&arr(sum.resolve(&a)), &arr(e_b.resolve(&a)), 8.0 * EPS);
    }
}

/// Facts 2.10.6–2.10.7, (2.10.29)–(2.10.31): x|_B = 𝓞_{B/A}x|_A; I = F_B𝓞_{B/A}𝓕′_A.
#[test]
fn fact_2_10_7_passive_change_of_frame() {
    let (a, b) = frame_b();
    let x = a.vector([0.3, -1.2, 2.0]);
    let o_ba = b.orientation_rel(&a);
    assert_rel_slice(&arr(x.resolve(&b)), &arr(o_ba * x.resolve(&a)), 8.0 * EPS);
    // F_B 𝓞_{B/A} 𝓕′_A = Σ_rc 𝓞_rc b_r a_c′
    let (fa, fb) = ([a.i(), a.j(), a.k()], [b.i(), b.j(), b.k()]);
    let mut sum = Dyadic::zero();
    for r in 0..3 {
        for c in 0..3 {
            sum = sum + fb[r].outer(&fa[c]) * o_ba[(r, c)];
        }
    }
    assert_mat_abs(&sum.resolve(&a), &Matrix3::identity(), 16.0 * EPS);
}

/// Fact 2.10.8 and the (2.10.34) erratum: for y = R_{B/A}x, y|_A = 𝓡_{B/A}x|_A = 𝓡²_{B/A}x|_B,
/// and y|_B = 𝓡_{B/A}x|_B = **x|_A** (the book prints x|_B). Oracle: R_{B/A} = R_{(0,.6,.8)}(1.3),
/// x|_A = (0.3, −1.2, 2).
#[test]
fn fact_2_10_8_active_rotation_corrected() {
    let a = Frame::new();
    let r = Rotor::from_axis_angle(&a.vector([0.0, 0.6, 0.8]), 1.3).unwrap();
    let b = a.rotated_by_rotor(&r);
    let x = a.vector([0.3, -1.2, 2.0]);
    let y = b.rotation_dyadic_rel(&a) * x;
    let r_ba = b.rotation_rel(&a);
    assert_rel_slice(&arr(y.resolve(&a)), &arr(r_ba * x.resolve(&a)), 8.0 * EPS);
    assert_rel_slice(&arr(y.resolve(&a)), &arr(r_ba * r_ba * x.resolve(&b)), 16.0 * EPS);
    assert_rel_slice(&arr(y.resolve(&b)), &[0.3, -1.2, 2.0], 8.0 * EPS);
    // notes ch1-2a §4c, twelve decimals
    assert_printed_slice(&arr(x.resolve(&b)), &["-2.001036031914", "-0.165491940363", "1.224118955273"]);
}

/// Fact 2.10.9: det 𝓞_{B/A} = 1.
#[test]
fn fact_2_10_9_orientation_determinant_is_one() {
    let (a, b) = frame_b();
    assert_abs(b.orientation_rel(&a).determinant(), 1.0, 8.0 * EPS);
}

/// Example 2.10.10: î_B = −k̂_A, ĵ_B = ĵ_A, k̂_B = î_A gives 𝓞_{B/A} = [[0,0,−1],[0,1,0],[1,0,0]]
/// (2.10.37), det 1; 𝓡_{B/A} = 𝓡₂(π/2) is its transpose (a quarter turn about ĵ_A).
#[test]
fn example_2_10_10_orientation_matrix() {
    let a = Frame::new();
    let b = Frame::from_axes(&-a.k(), &a.j(), &a.i(), ORTHONORMAL_TOL).unwrap();
    let o = m3([[0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]]);
    assert_eq!(b.orientation_rel(&a), o);
    assert_eq!(b.orientation_rel(&a).determinant(), 1.0);
    let r = Rotor::from_axis_angle(&a.j(), FRAC_PI_2).unwrap();
    assert_mat_abs(&a.rotated_by_rotor(&r).orientation_rel(&a), &o, 4.0 * EPS);
    assert_eq!(b.rotation_rel(&a), o.transpose());
    assert_eq!(Frame::from_orientation_rel(&a, &o, ORTHONORMAL_TOL), Ok(b));
}

/// Fact 2.10.11, (2.10.38): M|_B = 𝓞_{B/A}M|_A𝓞_{A/B}.
#[test]
fn fact_2_10_11_dyadic_change_of_frame() {
    let (a, b) = frame_b();
    let m_a = m3([[1.0, 2.0, 0.0], [-1.0, 3.0, 4.0], [0.5, 0.0, -2.0]]);
    let mm = a.dyadic(&m_a);
    let want = b.orientation_rel(&a) * m_a * a.orientation_rel(&b);
    assert_mat_rel(&mm.resolve(&b), &want, 16.0 * EPS);
    assert_mat_rel(&change_frame_dyadic(&m_a, &a, &b), &want, 16.0 * EPS);
}

/// Facts 2.10.15–2.10.16, (2.10.44)–(2.10.49): R_{C/A} = R_{C/B}R_{B/A}; 𝓞_{C/A} = 𝓞_{C/B}𝓞_{B/A};
/// 𝓡_{C/A} = 𝓡_{B/A}𝓡_{C/B} (order reversed); four frames chain likewise.
#[test]
fn fact_2_10_15_composition_orders() {
    let (a, b) = frame_b();
    let c = b.rotated_by_rotor(&Rotor::from_axis_angle(&b.vector([0.2, 1.0, -0.4]), -1.1).unwrap());
    let d = c.rotated_by_rotor(&Rotor::from_axis_angle(&a.vector([1.0, 0.0, 1.0]), 2.5).unwrap());
    let rd = |x: &Frame, y: &Frame| x.rotation_dyadic_rel(y);
    assert_mat_abs(&rd(&c, &a).resolve(&a), &(rd(&c, &b) * rd(&b, &a)).resolve(&a), 16.0 * EPS);
    assert_mat_abs(&c.orientation_rel(&a), &(c.orientation_rel(&b) * b.orientation_rel(&a)), 16.0 * EPS);
    assert_mat_abs(&c.rotation_rel(&a), &(b.rotation_rel(&a) * c.rotation_rel(&b)), 16.0 * EPS);
    let o = d.orientation_rel(&c) * c.orientation_rel(&b) * b.orientation_rel(&a);
    assert_mat_abs(&d.orientation_rel(&a), &o, 16.0 * EPS);
    let r = b.rotation_rel(&a) * c.rotation_rel(&b) * d.rotation_rel(&c);
    assert_mat_abs(&d.rotation_rel(&a), &r, 16.0 * EPS);
}

/// (2.10.50)–(2.10.54), Fact 2.10.17: tr and det are frame invariant; tr xy′ = y′x.
#[test]
fn fact_2_10_17_trace_of_dyad_and_invariants() {
    let (a, b) = frame_b();
    let (x, y) = (a.vector([1.0, 2.0, 3.0]), b.vector([-2.0, 0.5, 1.0]));
    assert_rel(x.outer(&y).trace(), y.coform() * x, 8.0 * EPS);
    let mm = a.dyadic(&m3([[1.0, 2.0, 0.0], [-1.0, 3.0, 4.0], [0.5, 0.0, -2.0]]));
    assert_rel(mm.resolve(&b).trace(), mm.resolve(&a).trace(), 16.0 * EPS);
    assert_rel(mm.resolve(&b).determinant(), mm.resolve(&a).determinant(), 64.0 * EPS);
}

/// Fact 2.10.18: −1 ≤ tr R ≤ 3 for a rotation, with 3 only for I and −1 at a half turn.
#[test]
fn fact_2_10_18_trace_bounds_of_rotation() {
    let a = Frame::new();
    for th in [0.0, 1e-8, 1.0, 3.0, std::f64::consts::PI] {
        let b = a.rotated_by_rotor(&Rotor::from_axis_angle(&a.vector([1.0, 2.0, 2.0]), th).unwrap());
        let t = b.rotation_dyadic_rel(&a).trace();
        assert!((-1.0 - 8.0 * EPS..=3.0 + 8.0 * EPS).contains(&t));
        assert_abs(t, 1.0 + 2.0 * th.cos(), 8.0 * EPS); // tr ∈ [−1, 3]
    }
}

/// Fact 2.10.19, (2.10.56)–(2.10.58): Cayley–Hamilton M³ − tr M M² + ½[(tr M)² − tr M²]M −
/// det M I = 0; det M from traces; tr M⁻¹ = [(tr M)² − tr M²]/(2 det M).
#[test]
fn fact_2_10_19_cayley_hamilton() {
    let a = Frame::new();
    let m_a = m3([[1.0, 2.0, 0.0], [-1.0, 3.0, 4.0], [0.5, 0.0, -2.0]]);
    let mm = a.dyadic(&m_a);
    assert!(mm.cayley_hamilton_residual().norm() < 256.0 * EPS);
    assert_rel(mm.determinant_from_traces(), m_a.determinant(), 64.0 * EPS);
    let inv = m_a.try_inverse().unwrap();
    assert_abs(mm.trace_of_inverse(1e-12).unwrap(), inv.trace(), 64.0 * EPS);
    let [i1, i2, i3] = mm.invariants();
    assert_eq!((i1, i3), (m_a.trace(), mm.determinant()));
    assert_rel(i2, 0.5 * (i1 * i1 - (m_a * m_a).trace()), 8.0 * EPS);
    // A singular dyadic has no inverse, also at huge and tiny scale (scale-free test).
    let sing = a.vector([1.0, 2.0, 3.0]).outer(&a.vector([1.0, 0.0, 1.0]));
    for s in [1.0, 1e-200, 1e200] {
        assert!(matches!((sing * s).inverse(1e-12), Err(TensorError::Singular { .. })));
        assert!((mm * s).inverse(1e-12).is_ok());
    }
    assert!(matches!(a.dyadic(&(m_a * f64::NAN)).inverse(1e-12), Err(TensorError::NonFinite { .. })));
}

/// Probs 2.26.16–2.26.17: for a rotation R with c = (tr R − 1)/2: (tr R)² = tr R² + 2 tr R,
/// R³ − tr R R² + tr R R − I = 0, R = (1+2c)/(2(1+c))I + (R² + R²′)/(4(1+c)) + (R − R′)/2.
#[test]
fn problem_2_26_17_rotation_identities() {
    let (a, b) = frame_b();
    let r = b.rotation_dyadic_rel(&a);
    let t = r.trace();
    let c = (t - 1.0) / 2.0;
    assert_rel(t * t, (r * r).trace() + 2.0 * t, 16.0 * EPS);
    let res = r * r * r - r * r * t + r * t - Dyadic::identity();
    assert!(res.norm() < 64.0 * EPS);
    let r2 = r * r;
    let rebuilt = Dyadic::identity() * ((1.0 + 2.0 * c) / (2.0 * (1.0 + c)))
        + (r2 + r2.coform()) * (1.0 / (4.0 * (1.0 + c)))
        + (r - r.coform()) * 0.5;
    assert_mat_abs(&rebuilt.resolve(&a), &r.resolve(&a), 64.0 * EPS);
}

/// Prob 2.26.3 (matrices; answers computed): M = xx′, N = yy′ with x = (3, −4, 0),
/// y = (−1, 5, −2): M|_A, N|_A, MN|_A = (x·y)xy′|_A, Mx|_A = |x|²x|_A = (75, −100, 0).
#[test]
fn problem_2_26_3_dyads_of_two_vectors() {
    let a = Frame::new();
    let (x, y) = (a.vector([3.0, -4.0, 0.0]), a.vector([-1.0, 5.0, -2.0]));
    let (mm, nn) = (x.outer(&x), y.outer(&y));
    assert_eq!(mm.resolve(&a), m3([[9.0, -12.0, 0.0], [-12.0, 16.0, 0.0], [0.0, 0.0, 0.0]]));
    assert_eq!(nn.resolve(&a), m3([[1.0, -5.0, 2.0], [-5.0, 25.0, -10.0], [2.0, -10.0, 4.0]]));
    let mn = m3([[69.0, -345.0, 138.0], [-92.0, 460.0, -184.0], [0.0, 0.0, 0.0]]);
    assert_eq!((mm * nn).resolve(&a), mn);
    assert_eq!(arr((mm * x).resolve(&a)), [75.0, -100.0, 0.0]);
}

/// (3.6.2) for p + q ≤ 2: a (1,0) tensor resolves to x|_A, a (1,1) tensor to M|_A; the change of
/// frame of T|_A is slotwise 𝓞_{B/A} (the tensor form of (2.10.31), (2.10.38)).
#[test]
fn eq_3_6_2_tensor_resolution_matches_vectors_and_dyadics() {
    let (a, b) = frame_b();
    let m_a = m3([[1.0, 2.0, 0.0], [-1.0, 3.0, 4.0], [0.5, 0.0, -2.0]]);
    let t = a.tensor(1, 1, &DMatrix::from_iterator(3, 3, m_a.iter().copied())).unwrap();
    let want = a.dyadic(&m_a).resolve(&b);
    assert!((t.resolve(&b) - DMatrix::from_iterator(3, 3, want.iter().copied())).nan_amax() < 16.0 * EPS);
    let x = a.vector([1.0, -2.0, 0.5]);
    let tx = a.tensor(1, 0, &DMatrix::from_column_slice(3, 1, &[1.0, -2.0, 0.5])).unwrap();
    assert_rel_slice(tx.resolve(&b).as_slice(), x.resolve(&b).as_slice(), 8.0 * EPS);
    let t3 = DMatrix::from_fn(9, 3, |r, c| (r as f64) - 2.0 * (c as f64) + 0.5);
    let tt = a.tensor(2, 1, &t3).unwrap();
    let moved = change_frame_tensor(&t3, 2, 1, &a, &b).unwrap();
    assert_rel_slice(tt.resolve(&b).as_slice(), moved.as_slice(), 64.0 * EPS);
    assert!(a.tensor(2, 1, &DMatrix::zeros(3, 9)).is_err());
}

/// docs/notation.md: for B = A turned by θ = 0.3 about k̂_A, sympy's `B.dcm(A)` is
/// [[c, s, 0], [−s, c, 0], [0, 0, 1]] and scipy's `Rotation.from_rotvec([0, 0, θ]).as_matrix()`
/// is its transpose (both checked with sympy/scipy); vectrix's 𝓞_{B/A} and 𝓡_{B/A} match.
#[test]
fn notation_orientation_rel_is_sympy_dcm_and_scipy_transpose() {
    let a = Frame::new();
    let th: f64 = 0.3;
    let b = a.rotated_by_rotor(&Rotor::from_axis_angle(&a.k(), th).unwrap());
    let (c, s) = (th.cos(), th.sin());
    let sympy_dcm = m3([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]]);
    // Printed by sympy: B.dcm(A) ≈ [[0.955336, 0.29552, 0], [−0.29552, 0.955336, 0], [0, 0, 1]].
    assert_printed(sympy_dcm[(0, 1)], "0.29552"); // sin 0.3 as sympy prints it
    assert_mat_abs(&b.orientation_rel(&a), &sympy_dcm, 4.0 * EPS);
    assert_mat_abs(&b.rotation_rel(&a), &sympy_dcm.transpose(), 4.0 * EPS);
}

/// Fact 3.6.1: (T₁⊗T₂)|_A = T₁|_A ⊗ T₂|_A (Kronecker product, first factor slowest), in any
/// frame; and a contraction computed frame-free equals the same contraction of the resolved
/// components (here (M⃗⊗x⃗)_(2,1) = M⃗x⃗, a resolved matrix–vector product).
#[test]
fn fact_3_6_1_resolution_of_tensor_product_is_kronecker() {
    let (a, b) = frame_b();
    let m = a.dyadic(&m3([[1.0, 2.0, 0.0], [-1.0, 3.0, 4.0], [0.5, 0.0, -2.0]]));
    let x = b.vector([0.3, -1.2, 2.0]);
    let (tm, tx) = (Tensor::from_dyadic(&m), Tensor::from_vector(&x));
    let prod = tm.otimes(&tx).unwrap();
    for f in [&a, &b] {
        let want = tm.resolve(f).kronecker(&tx.resolve(f));
        assert!((prod.resolve(f) - want).nan_amax() < 32.0 * EPS, "(T₁⊗T₂)|_A = T₁|_A ⊗ T₂|_A");
    }
    let mx = prod.contract(&[(2, 1)]).unwrap();
    assert_rel_slice(mx.resolve(&b).as_slice(), &arr(m.resolve(&b) * x.resolve(&b)), 32.0 * EPS);
}
