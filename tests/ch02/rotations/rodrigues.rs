//! §2.11 Rodrigues's formula and Euler's theorem; §2.8–2.10 rotation basics used by them.

use crate::support::NanAmax;
use std::f64::consts::{FRAC_PI_2, PI};

use nalgebra::{Matrix3, Vector3};
use vectrix::frames::max_abs_diff_in;
use vectrix::prelude::*;

use super::{assert_mat, assert_vec, rodrigues, rot, unit};
use crate::support::*;

/// (2.8.7–9): R⃗_{B/A} = F_B𝓕′_A takes the axes of A to those of B; R⃗_{A/B} = R⃗_{B/A}⁻¹ (2.8.12–14).
#[test]
fn eq_2_8_7_rotation_between_frames() {
    let a = Frame::new();
    let b = rot(&a, [1.0, 2.0, 2.0], 0.7).apply_frame(&a);
    let r_ba = Rotation::between(&b, &a);
    assert_vec(&r_ba.apply(&a.i()).resolve(&a), &b.i().resolve(&a), 4.0 * EPS);
    assert_vec(&r_ba.apply(&a.k()).resolve(&a), &b.k().resolve(&a), 4.0 * EPS);
    let r_ab = Rotation::between(&a, &b);
    assert_mat(&r_ab.rotation_matrix_in(&a), &r_ba.inverse().rotation_matrix_in(&a), 4.0 * EPS);
    // Fact 2.10.1: 𝓡_{B/A} = R⃗_{B/A}|_A = R⃗_{B/A}|_B, columns = B's axes in A.
    assert_mat(&r_ba.rotation_matrix_in(&a), &b.rotation_rel(&a), 4.0 * EPS);
    assert_mat(&r_ba.rotation_matrix_in(&b), &b.rotation_rel(&a), 4.0 * EPS);
    assert_mat(&r_ba.orientation_matrix_in(&a), &b.orientation_rel(&a), 4.0 * EPS);
}

/// (2.10.33–34) corrected: for y⃗ = R⃗_{B/A}x⃗, y|_B = x|_A (the printed "x|_B" is an erratum).
#[test]
fn eq_2_10_34_corrected_components() {
    let a = Frame::new();
    let r_ba = rot(&a, [0.0, 0.6, 0.8], 1.3);
    let b = r_ba.apply_frame(&a);
    let x = a.vector([0.3, -1.2, 2.0]);
    let y = r_ba.apply(&x);
    assert_vec(&y.resolve(&b), &x.resolve(&a), 8.0 * EPS);
    // Oracle (notes ch1-2a §4c): x|_B = (−2.001036031914, −0.165491940363, 1.224118955273).
    assert_printed_slice(x.resolve(&b).as_slice(), &["-2.001036031914", "-0.165491940363", "1.224118955273"]);
}

/// (2.11.1–6): R_n(θ) = cosθ I + (1−cosθ)nn′ + sinθ n^× = I + (1−cosθ)n^{×2} + sinθ n^×.
#[test]
fn eq_2_11_1_rodrigues_formula() {
    let a = Frame::new();
    for &(n, th) in &[([1.0, 2.0, 2.0], 0.4), ([0.0, 0.0, 1.0], -2.5), ([-3.0, 1.0, 0.5], 3.0)] {
        let r = rot(&a, n, th).rotation_matrix_in(&a);
        assert_mat(&r, &rodrigues(&unit(n), th), 8.0 * EPS);
        let nx = unit(n).cross_matrix();
        assert_mat(&r, &(Matrix3::identity() + nx * nx * (1.0 - th.cos()) + nx * th.sin()), 8.0 * EPS);
    }
    // Oracles (notes ch1-2a §4c).
    let r = rot(&a, [1.0, 1.0, 1.0], 2.0 * PI / 3.0).rotation_matrix_in(&a);
    assert_mat(&r, &Matrix3::new(0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0), 4.0 * EPS);
    let r = rot(&a, [1.0, 2.0, 2.0], FRAC_PI_2).rotation_matrix_in(&a);
    assert_mat(&r, &(Matrix3::new(1.0, -4.0, 8.0, 8.0, 4.0, 1.0, -4.0, 7.0, 4.0) / 9.0), 4.0 * EPS);
}

/// Fact 2.11.1: R n = n (2.11.14); R_n(−θ) = R_{−n}(θ) = R_n(θ)′ (2.11.15–16);
/// cosθ = (tr R − 1)/2 (2.11.17); sinθ n^× = (R − R′)/2 (2.11.18).
#[test]
fn fact_2_11_1_rodrigues_properties() {
    let a = Frame::new();
    let (n, th) = ([2.0, -1.0, 0.5], 1.1);
    let r = rot(&a, n, th);
    let m = r.rotation_matrix_in(&a);
    assert_vec(&(m * unit(n)), &unit(n), 4.0 * EPS);
    let m_neg = rot(&a, n, -th).rotation_matrix_in(&a);
    assert_mat(&m_neg, &rot(&a, [-2.0, 1.0, -0.5], th).rotation_matrix_in(&a), 4.0 * EPS);
    assert_mat(&m_neg, &m.transpose(), 4.0 * EPS);
    assert_abs((m.trace() - 1.0) / 2.0, th.cos(), 4.0 * EPS);
    assert_mat(&(unit(n).cross_matrix() * th.sin()), &((m - m.transpose()) / 2.0), 4.0 * EPS);
}

/// Fact 2.11.2 (2.11.21–22): y = (|y|/|x|)[cosθ x + sinθ n×x] with θ = θ_{y/x/n}.
#[test]
fn fact_2_11_2_rotating_one_vector_onto_another() {
    let a = Frame::new();
    let (x, y) = (a.vector([1.0, 2.0, 0.0]), a.vector([-3.0, 0.5, 0.0]));
    let n = a.k();
    let th = y.directed_angle_rel(&x, &n).unwrap();
    let want = (x * th.cos() + n.cross(&x) * th.sin()) * (y.norm() / x.norm());
    assert_vec(&want.resolve(&a), &y.resolve(&a), 8.0 * EPS);
    let r = Rotation::from_axis_angle(&n, th).unwrap();
    assert_vec(&(r.apply(&x) * (y.norm() / x.norm())).resolve(&a), &y.resolve(&a), 8.0 * EPS);
}

/// Fact 2.11.4: tr R = 3 ⇒ R = I, θ = 0, every axis is an eigenaxis.
#[test]
fn fact_2_11_4_identity() {
    let a = Frame::new();
    let r = Rotation::between(&a, &a);
    assert_eq!(r.axis_angle(), AxisAngle::Identity);
    assert_eq!(r.axis_angle_in(&a).angle(), 0.0);
    assert_eq!(r.angle_vector_in(&a), Vector3::zeros());
    assert_eq!(
        Quaternion::from_rotation_matrix(&Matrix3::<f64>::identity(), ROTATION_TOL).unwrap(),
        Quaternion::identity()
    );
}

/// Fact 2.11.5: tr R = −1 ⇒ θ = π about ±n, nn′ = (R + I)/2, R = −I + 2nnᵀ (2.11.33); vectrix
/// returns the canonical sign (first nonzero component positive).
#[test]
fn fact_2_11_5_half_turn() {
    let a = Frame::new();
    let want = Matrix3::new(-7.0, 4.0, 4.0, 4.0, -1.0, 8.0, 4.0, 8.0, -1.0) / 9.0;
    for n in [[1.0, 2.0, 2.0], [-1.0, -2.0, -2.0]] {
        let m = rodrigues(&unit(n), PI);
        assert_mat(&m, &want, 4.0 * EPS);
        assert_abs(m.trace(), -1.0, 4.0 * EPS);
        let r = Rotation::from_rotation_matrix_in(&a, &want, ROTATION_TOL).unwrap();
        match r.axis_angle_in(&a) {
            AxisAngle::HalfTurn(axis) => assert_vec(&axis, &unit([1.0, 2.0, 2.0]), 4.0 * EPS),
            other => panic!("expected a half turn, got {other:?}"),
        }
        let nn = unit([1.0, 2.0, 2.0]) * unit([1.0, 2.0, 2.0]).transpose();
        assert_mat(&((want + Matrix3::identity()) / 2.0), &nn, 4.0 * EPS);
        assert_mat(&(-Matrix3::identity() + nn * 2.0), &want, 4.0 * EPS);
    }
    // Canonical sign where the first component is zero: n = (0, −1, 0) → (0, 1, 0).
    let r =
        Rotation::from_rotation_matrix_in(&a, &Matrix3::from_diagonal(&Vector3::new(-1.0, 1.0, -1.0)), 0.0)
            .unwrap();
    assert_eq!(r.axis_angle_in(&a), AxisAngle::HalfTurn(Vector3::new(0.0, 1.0, 0.0)));
    assert_eq!(r.angle_vector_in(&a), Vector3::new(0.0, PI, 0.0));
}

/// (2.11.49–51): for −1 < tr < 3, θ ∈ (0, π) and n̂ is unique; θ_{B/A} = θ_{A/B},
/// n̂_{B/A} = −n̂_{A/B}.
#[test]
fn eq_2_11_49_general_eigenaxis() {
    let a = Frame::new();
    let r = rot(&a, [1.0, -2.0, 0.5], 2.2);
    let (AxisAngle::General { axis: n_ba, angle: t_ba }, AxisAngle::General { axis: n_ab, angle: t_ab }) =
        (r.axis_angle_in(&a), r.inverse().axis_angle_in(&a))
    else {
        panic!("general rotation expected");
    };
    assert_rel(t_ba, 2.2, 4.0 * EPS);
    assert_rel(t_ab, t_ba, 0.0);
    assert_vec(&n_ba, &unit([1.0, -2.0, 0.5]), 4.0 * EPS);
    assert_vec(&n_ab, &-n_ba, 0.0);
    // F2.11.7: −n with θ − 2π is the same rotation; the eigenangle stays in [0, π].
    let r2 = rot(&a, [-1.0, 2.0, -0.5], 2.2 - 2.0 * PI);
    assert_rel(r2.axis_angle().angle(), 2.2, 8.0 * EPS);
}

/// Fact 2.11.8 (2.11.53–58): R_{A/B} flips the sign of the sinθ n^× term.
#[test]
fn fact_2_11_8_inverse() {
    let a = Frame::new();
    let (n, th) = (unit([0.3, 0.4, -1.0]), 0.9);
    let r_ab = rot(&a, [0.3, 0.4, -1.0], th).inverse().rotation_matrix_in(&a);
    let want =
        Matrix3::identity() * th.cos() + n * n.transpose() * (1.0 - th.cos()) - n.cross_matrix() * th.sin();
    assert_mat(&r_ab, &want, 4.0 * EPS);
}

/// Fact 2.11.9: the rotation taking x to y (|x| = |y|) is R_{θ̂_{y/x}}(θ_{y/x}); any axis ⊥ x for
/// parallel or anti-parallel vectors (the printed "unique" over-claims).
#[test]
fn fact_2_11_9_rotation_taking_x_to_y() {
    let a = Frame::new();
    let cases = [
        ([1.0, 2.0, 3.0], [-2.0, 0.5, 1.0]),
        ([1.0, 0.0, 0.0], [1.0, 1e-9, 0.0]),
        ([1.0, 0.0, 0.0], [-1.0, 1e-9, 0.0]),
        ([1.0, 2.0, 3.0], [-1.0, -2.0, -3.0]),
        ([0.0, 0.0, 2.0], [0.0, 0.0, 5.0]),
    ];
    for (x, y) in cases {
        let (x, y) = (a.vector(x), a.vector(y));
        let r = Rotation::taking(&x, &y).unwrap();
        let got = r.apply(&x.unit().unwrap());
        assert_vec(&got.resolve(&a), &y.unit().unwrap().resolve(&a), 16.0 * EPS);
        if let Some(n) = y.unit_angle_vector_rel(&x) {
            // Minimal: the angle is θ_{y/x} about θ̂_{y/x}.
            assert_abs(r.axis_angle().angle(), x.angle(&y), 16.0 * EPS); // angle ∈ [0, π]
            if x.angle(&y) > 1e-6 && x.angle(&y) < PI - 1e-6 {
                assert_vec(&r.axis_angle().axis().unwrap().resolve(&a), &n.resolve(&a), 1e-9);
            }
        }
    }
    assert!(Rotation::taking(&Vector::zero(), &a.i()).is_none());
}

/// Fact 2.11.10 (2.11.59): for n⃗ = v⃗ × w⃗, n⃗^× = w⃗v⃗′ − v⃗w⃗′, a statement about physical
/// vectors: vectrix's cross product, cross dyad and outer products, built in a turned frame and
/// compared frame-free (the Frobenius norm of the difference), then resolved in a second frame.
#[test]
fn fact_2_11_10_cross_replacement() {
    let a = Frame::new();
    let b = rot(&a, [1.0, -1.0, 2.0], 0.9).apply_frame(&a);
    let (v, w) = (b.vector([1.0, -2.0, 0.5]), b.vector([0.3, 0.7, 2.0]));
    let lhs = v.cross(&w).cross_dyad();
    let rhs = w.outer(&v) - v.outer(&w);
    // products of O(1)–O(2) components, resolved through one rotation: a few ε at scale |v||w|
    let scale = v.norm() * w.norm();
    assert_abs((lhs - rhs).norm(), 0.0, 16.0 * EPS * scale);
    // and in components: (v×w)|_A^× = w|_A v|_Aᵀ − v|_A w|_Aᵀ
    let (va, wa) = (v.resolve(&a), w.resolve(&a));
    assert_mat(&lhs.resolve(&a), &(wa * va.transpose() - va * wa.transpose()), 16.0 * EPS * scale);
    // the order matters: v⃗w⃗′ − w⃗v⃗′ is −n⃗^×, which differs by 2|n⃗|
    assert!(((v.outer(&w) - w.outer(&v)) - lhs).norm() > scale * 0.1);
}

/// Fact 2.11.11 (2.11.60–61, corrected: csc(θ_{C/A}/2), and the lost ×): composition of
/// eigenaxis rotations is quaternion multiplication.
#[test]
fn fact_2_11_11_composition_of_eigenaxis_rotations() {
    let a = Frame::new();
    let (n_cb, t_cb, n_ba, t_ba) = (Vector3::x(), 0.9, Vector3::new(0.0, 0.6, 0.8), 1.3);
    let r_ca = rot(&a, n_cb.into(), t_cb) * rot(&a, n_ba.into(), t_ba);
    let AxisAngle::General { axis, angle } = r_ca.axis_angle_in(&a) else { panic!("general") };
    // Oracle (notes ch1-2a §4c).
    assert_rel(angle, 1.5430984177761988, 4.0 * EPS);
    assert_printed_slice(axis.as_slice(), &["0.496623456355", "0.166906264287", "0.851767246106"]);
    // (2.11.60) and the corrected (2.11.61).
    let (c1, s1, c2, s2) = ((t_cb / 2.0).cos(), (t_cb / 2.0).sin(), (t_ba / 2.0).cos(), (t_ba / 2.0).sin());
    assert_abs((angle / 2.0).cos(), c1 * c2 - s1 * s2 * n_cb.dot(&n_ba), 4.0 * EPS);
    let n = (n_cb * (s1 * c2) + n_ba * (c1 * s2) + n_cb.cross(&n_ba) * (s1 * s2)) / (angle / 2.0).sin();
    assert_vec(&axis, &n, 8.0 * EPS);
}

/// Prob 2.26.9: F_B is F_A turned by θ_{B/A} = π/2 about k̂_A (right-hand rule). Determine
/// R⃗_{B/A}, 𝓡_{B/A} (as R⃗_{B/A}|_A and as R⃗_{B/A}|_B), n_{B/A} and q_{B/A}, then verify
/// (2.11.39), (2.11.45) and (2.15.30). Answers (notes ch1-2a, ch2b [C]): 𝓡_{B/A} =
/// [[0,−1,0],[1,0,0],[0,0,1]] in both frames, 𝓞_{B/A} = 𝓡ᵀ, θ = π/2, n = (0, 0, 1),
/// q = [√2/2, 0, 0, √2/2]. The three identities are checked with the θ, n and q that vectrix
/// extracts, not with the answers.
#[test]
fn problem_2_26_9_quarter_turn() {
    let a = Frame::new();
    let r = rot(&a, [0.0, 0.0, 1.0], FRAC_PI_2);
    let b = r.apply_frame(&a);
    let want = Matrix3::new(0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0);
    // entries of a rotation have scale 1; cos(π/2) ≈ 6e-17 and the quaternion products round
    let tol = 4.0 * EPS;
    let r_in_a = r.rotation_matrix_in(&a);
    assert_mat(&r_in_a, &want, tol);
    assert_mat(&r.rotation_matrix_in(&b), &want, tol);
    // the same from the two frames: 𝓡_{B/A} = R⃗_{B/A}|_A = R⃗_{B/A}|_B (Fact 2.10.1)
    assert_mat(&b.rotation_rel(&a), &want, tol);
    assert_mat(&b.rotation_dyadic_rel(&a).resolve(&b), &want, tol);
    assert_mat(&r.orientation_matrix_in(&a), &want.transpose(), tol);
    assert_mat(&b.orientation_rel(&a), &want.transpose(), tol);
    let AxisAngle::General { axis: n, angle: theta } = r.axis_angle_in(&a) else {
        panic!("a quarter turn is neither the identity nor a half turn")
    };
    assert_abs(theta, FRAC_PI_2, tol);
    assert_vec(&n, &Vector3::z(), tol);
    let q = r.quaternion_in(&a);
    let h = std::f64::consts::FRAC_1_SQRT_2;
    assert!(super::q_err(&q, &Quaternion::new(h, 0.0, 0.0, h)) <= tol);
    // (2.11.39): cos θ = ½(tr R − 1), here 0
    assert_abs(theta.cos(), 0.5 * (r_in_a.trace() - 1.0), tol);
    // (2.11.45): R = I + (1 − cos θ)n^{×2} + (sin θ)n^×
    let nx = n.cross_matrix();
    assert_mat(&r_in_a, &(Matrix3::identity() + nx * nx * (1.0 - theta.cos()) + nx * theta.sin()), tol);
    // (2.15.30): R = I + 2ηε^× + 2ε^{×2}, q = [η, ε]
    let ex = Vector3::new(q.b, q.c, q.d).cross_matrix();
    assert_mat(&r_in_a, &(Matrix3::identity() + ex * (2.0 * q.a) + ex * ex * 2.0), tol);
}

/// Prob 2.26.13: R_{Sn}(θ) = S R_n(θ) Sᵀ for a rotation S.
#[test]
fn problem_2_26_13_conjugated_axis() {
    let a = Frame::new();
    let s = rot(&a, [1.0, 1.0, 0.0], 0.8);
    let n = a.vector([0.2, -0.4, 1.0]);
    let lhs = Rotation::from_axis_angle(&s.apply(&n), 1.7).unwrap().rotation_matrix_in(&a);
    let sm = s.rotation_matrix_in(&a);
    let rhs = sm * Rotation::from_axis_angle(&n, 1.7).unwrap().rotation_matrix_in(&a) * sm.transpose();
    assert_mat(&lhs, &rhs, 8.0 * EPS);
}

/// Probs 2.26.15–18: eig R = {1, e^{±jθ}}; (tr R)² = tr R² + 2 tr R; Cayley–Hamilton
/// R³ − tR² + tR − I = 0; R symmetric ⟺ tr ∈ {−1, 3}.
#[test]
fn problems_2_26_15_to_18_trace_identities() {
    let a = Frame::new();
    let m = rot(&a, [1.0, 2.0, -1.0], 1.2).rotation_matrix_in(&a);
    let t = m.trace();
    assert_rel(t * t, (m * m).trace() + 2.0 * t, 16.0 * EPS);
    let ch = m * m * m - m * m * t + m * t - Matrix3::identity();
    assert!(ch.nan_amax() <= 32.0 * EPS);
    let eig = m.complex_eigenvalues();
    let mut args: Vec<f64> = eig.iter().map(|z| z.im.atan2(z.re).abs()).collect();
    args.sort_by(f64::total_cmp);
    // eigenvalues of a normal matrix are perturbed by O(ε‖M‖): arguments 0 and ±1.2 to a few ε
    assert_abs(args[0], 0.0, 16.0 * EPS);
    assert_abs(args[2], 1.2, 16.0 * EPS);
    let half = rodrigues(&unit([1.0, 2.0, -1.0]), PI);
    assert_mat(&half, &half.transpose(), 4.0 * EPS);
    assert!(mat_is_not_symmetric(&m));
}

fn mat_is_not_symmetric(m: &Matrix3<f64>) -> bool {
    (m - m.transpose()).nan_amax() > 1e-3
}

/// §2.8, §2.10 (2.10.38), §3.6: a rotation carries vectors, dyads, frames and tensors: vector
/// factors x⃗ ↦ R⃗x⃗, covector factors a⃗′ ↦ a⃗′R⃗⁻¹ (so evaluations are invariant), M⃗ ↦ R⃗M⃗R⃗′.
#[test]
fn sec_2_8_rotation_carries_vectors_dyads_frames_tensors() {
    let a = Frame::new();
    let r = rot(&a, [0.3, -1.0, 0.4], 2.1);
    let (x, y, z) = (a.vector([1.0, 2.0, -0.5]), a.vector([0.0, -1.0, 3.0]), a.vector([2.0, 0.5, 1.0]));
    let m = x.outer(&y) + y.outer(&z) * 0.5;
    let rm = r.to_dyadic();
    assert_mat(&r.apply_dyadic(&m).resolve(&a), &(rm * m * rm.coform()).resolve(&a), 16.0 * EPS);
    let b = r.apply_frame(&a);
    assert_vec(&b.k().resolve(&a), &r.apply(&a.k()).resolve(&a), 4.0 * EPS);
    // Tensors of type (1,0), (1,1), (2,0), (0,2) and (1,2).
    let close = |got: &Tensor, want: &Tensor| {
        let e = max_abs_diff_in(got, want, &a).expect("same type, finite");
        assert!(e <= 64.0 * EPS, "tensor differs by {e:e}");
    };
    let (rx, ry, rz) = (r.apply(&x), r.apply(&y), r.apply(&z));
    close(&r.apply_tensor(&Tensor::from_vector(&x)).unwrap(), &Tensor::from_vector(&rx));
    close(&r.apply_tensor(&Tensor::from_dyadic(&m)).unwrap(), &Tensor::from_dyadic(&r.apply_dyadic(&m)));
    let t20 = Tensor::from_factors(&[x, y], &[]).unwrap();
    close(&r.apply_tensor(&t20).unwrap(), &Tensor::from_factors(&[rx, ry], &[]).unwrap());
    let t02 = Tensor::from_factors(&[], &[x.coform(), y.coform()]).unwrap();
    close(&r.apply_tensor(&t02).unwrap(), &Tensor::from_factors(&[], &[rx.coform(), ry.coform()]).unwrap());
    let t12 = Tensor::from_factors(&[z], &[x.coform(), y.coform()]).unwrap();
    close(&r.apply_tensor(&t12).unwrap(), &Tensor::from_factors(&[rz], &[rx.coform(), ry.coform()]).unwrap());
    let t21 = Tensor::from_factors(&[z, x], &[y.coform()]).unwrap();
    close(&r.apply_tensor(&t21).unwrap(), &Tensor::from_factors(&[rz, rx], &[ry.coform()]).unwrap());
}
