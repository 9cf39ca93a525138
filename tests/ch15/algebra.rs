//! §15.1–15.3: matrices, complex numbers, eigenvalues and polynomial roots; problems
//! 15.20.1–15.20.7; atan2 (Ex 15.18.1).

use super::*;
use crate::support::NanAmax;
use nalgebra::{Matrix3, dmatrix, dvector};
use vectrix::prelude::{Dyadic, Frame, Resolve};
use vectrix::tensor::adjugate;

/// The physical matrix whose resolution in the first frame F_A is `m` (a 3 × 3 math matrix).
fn physical(m: [[f64; 3]; 3]) -> (Frame, Dyadic) {
    let a = Frame::new();
    let d = a.dyadic(&Matrix3::from_fn(|i, j| m[i][j]));
    (a, d)
}

#[test]
fn problem_15_20_1_determinant_and_inverse() {
    // 15.20.1: A = [[3,0,2],[4,3,5],[7,2,6]], "manually compute the determinant and inverse".
    // Printed: det A = 3(3·6 − 2·5) − 0(4·6 − 7·5) + 2(4·2 − 7·3) = −2 by cofactors along row 1,
    // A⁻¹ = [[−4,−2,3],[−5.5,−2,3.5],[6.5,3,−4.5]].
    // Through vectrix: the cofactors are `tensor::adjugate` (adj A = Cᵀ, products of small
    // integers, exact), the expansion along row 1 is row₁(A)·col₁(adj A); the determinant of the
    // physical matrix by `Dyadic::determinant` and from traces (2.10.57); the inverse by
    // `Dyadic::inverse` (adjugate over det of the scaled matrix: halves, a few ε); and
    // det A = ∏λ (15.3.7) with the eigenvalues of `linalg::eigenvalues`.
    let (a, m) = physical([[3.0, 0.0, 2.0], [4.0, 3.0, 5.0], [7.0, 2.0, 6.0]]);
    let m_a = m.resolve(&a);
    let adj = adjugate(&m_a);
    assert_eq!(adj, Matrix3::new(8.0, 4.0, -6.0, 11.0, 4.0, -7.0, -13.0, -6.0, 9.0));
    let cofactor_row_1 = (0..3).map(|j| m_a[(0, j)] * adj[(j, 0)]).sum::<f64>();
    assert_eq!(cofactor_row_1, -2.0);
    assert_eq!(m_a * adj, Matrix3::identity() * -2.0);
    // nalgebra's 3 × 3 determinant and the trace form: sums of products up to tr A³ ≈ 1000
    assert_abs(m.determinant(), -2.0, 16.0 * EPS * 7.0f64.powi(3));
    assert_abs(m.determinant_from_traces(), -2.0, 64.0 * EPS * (m * m * m).trace().abs());
    let inv = m.inverse(1e-12).unwrap();
    let want = [[-4.0, -2.0, 3.0], [-5.5, -2.0, 3.5], [6.5, 3.0, -4.5]];
    // the inverse is computed from A/7 (inexact entries), and det A = −2 comes from terms of
    // size Σ|a₁ⱼC₁ⱼ| = 50: the cancellation κ = 25 multiplies the entries' rounding
    let kappa = (0..3).map(|j| (m_a[(0, j)] * adj[(j, 0)]).abs()).sum::<f64>() / 2.0;
    for (i, row) in want.iter().enumerate() {
        for (j, w) in row.iter().enumerate() {
            assert_abs(inv.resolve(&a)[(i, j)], *w, 4.0 * EPS * kappa * 6.5);
        }
    }
    // AB = I, so B = A⁻¹ (§15.1)
    assert!(((m * inv).resolve(&a) - Matrix3::identity()).nan_amax() <= 4.0 * EPS * kappa * 6.5 * 7.0 * 3.0);
    let eig = DMatrix::from_fn(3, 3, |i, j| m_a[(i, j)]);
    let prod = linalg::eigenvalues(&eig).unwrap().iter().fold(Complex64::new(1.0, 0.0), |p, l| p * l);
    // the smallest eigenvalue −0.0905 is the worst conditioned factor (|λ|·κ ≈ 10² ε)
    assert_abs(prod.re, -2.0, 1e3 * EPS);
    assert_eq!(prod.im, 0.0);
}

#[test]
fn facts_15_1_1_to_15_1_3_solutions_of_a_linear_system() {
    // §15.1: Ax = 0 has the solution x = 0 (Fact 15.1.1), and it is the only one iff
    // det A ≠ 0 (Fact 15.1.2); Ax = b has a unique solution iff det A ≠ 0, namely x = A⁻¹b
    // (Fact 15.1.3); otherwise none or infinitely many (A(αx) = 0 for every α).
    // Through vectrix: the equilibria of ẋ = Ax − b are the solutions of Ax = b
    // (`affine_equilibria`, by the SVD), det A by `Dyadic::determinant`, A⁻¹b by
    // `Dyadic::inverse` applied to the physical vector b⃗.
    let (a, m) = physical([[3.0, 0.0, 2.0], [4.0, 3.0, 5.0], [7.0, 2.0, 6.0]]);
    let b = [1.0, -2.0, 0.5];
    assert!(m.determinant().abs() > 1.0);
    let x = m.inverse(1e-12).unwrap() * a.vector(b);
    let eqm = |d: &Dyadic, rhs: [f64; 3]| {
        let mm = d.resolve(&a);
        let neg: Vec<f64> = rhs.iter().map(|v| -v).collect();
        affine_equilibria(&DMatrix::from_fn(3, 3, |i, j| mm[(i, j)]), &neg, 1e-12).unwrap()
    };
    let AffineEquilibria::Unique(xs) = eqm(&m, b) else { panic!("det A = −2: one solution") };
    // κ(A) ≈ 200: the SVD solve and the adjugate agree to a few hundred ε of |x| ≈ 15
    assert!((&xs - x.resolve(&a)).nan_amax() <= 1e3 * EPS * 15.0, "{xs} vs {x:?}");
    let AffineEquilibria::Unique(zero) = eqm(&m, [0.0; 3]) else { panic!("det A ≠ 0: x = 0 only") };
    assert!(zero.nan_amax() == 0.0);
    // a singular A (row 3 = row 1 + row 2): det A = 0 and no inverse
    let (_, s) = physical([[3.0, 0.0, 2.0], [4.0, 3.0, 5.0], [7.0, 3.0, 7.0]]);
    assert_eq!(s.determinant(), 0.0);
    assert!(s.inverse(1e-12).is_err());
    // Ax = 0: x = 0 and every multiple of the null direction (−9, −7, 27)/|·|
    let AffineEquilibria::Family { particular, directions } = eqm(&s, [0.0; 3]) else {
        panic!("det A = 0: infinitely many solutions of Ax = 0")
    };
    assert!(particular.nan_amax() <= 4.0 * EPS);
    assert_eq!(directions.ncols(), 1);
    let n = a.vector([directions[0], directions[1], directions[2]]);
    assert!((s * n).norm() <= 64.0 * EPS * 10.0);
    assert!((s * (n * 3.5)).norm() <= 64.0 * EPS * 35.0);
    // Ax = b: none when b is outside the range (the third entry breaks row 3 = row 1 + row 2),
    // infinitely many when inside
    assert_eq!(eqm(&s, [1.0, -2.0, 0.5]), AffineEquilibria::None);
    assert!(matches!(eqm(&s, [1.0, -2.0, -1.0]), AffineEquilibria::Family { .. }));
}

#[test]
fn section_15_1_table_15_1_special_matrices() {
    // Table 15.1's examples, embedded as the upper-left block of a physical matrix with a 1 in
    // the third diagonal entry (2 × 2 determinants ad − bc, §15.1): symmetric, skew symmetric,
    // orthogonal (A⁻¹ = Aᵀ), nilpotent [[1,1],[−1,−1]]² = 0, idempotent ½[[1,1],[1,1]]² = itself,
    // nonsingular [[1,2],[3,4]] (det = −2).
    let block = |m: [[f64; 2]; 2], corner: f64| {
        physical([[m[0][0], m[0][1], 0.0], [m[1][0], m[1][1], 0.0], [0.0, 0.0, corner]])
    };
    let (a, sym) = block([[1.0, 2.0], [2.0, 5.0]], 1.0);
    assert!(sym.is_symmetric(0.0) && !sym.is_skew(0.5));
    let (_, skew) = block([[0.0, 2.0], [-2.0, 0.0]], 0.0);
    assert!(skew.is_skew(0.0) && !skew.is_symmetric(0.5));
    let (_, orth) = block([[1.0, 0.0], [0.0, 1.0]], 1.0);
    assert_eq!(orth.inverse(1e-12).unwrap().resolve(&a), orth.coform().resolve(&a));
    let (_, nil) = block([[1.0, 1.0], [-1.0, -1.0]], 0.0);
    assert_eq!((nil * nil).resolve(&a), Matrix3::zeros());
    assert_eq!(nil.determinant(), 0.0);
    let (_, idem) = block([[0.5, 0.5], [0.5, 0.5]], 0.0);
    assert_eq!((idem * idem).resolve(&a), idem.resolve(&a));
    let (_, nonsingular) = block([[1.0, 2.0], [3.0, 4.0]], 1.0);
    assert_abs(nonsingular.determinant(), 1.0 * 4.0 - 2.0 * 3.0, 4.0 * EPS * 4.0);
    assert!(nonsingular.inverse(1e-12).is_ok());
}

#[test]
fn example_15_3_3_diagonal_eigenvalues() {
    // Ex 15.3.3: diag(1, 2) has eigenvalues 1 and 2, exactly.
    let ev = sorted(linalg::eigenvalues(&dmatrix![1.0, 0.0; 0.0, 2.0]).unwrap());
    assert_eq!(ev, vec![Complex64::new(1.0, 0.0), Complex64::new(2.0, 0.0)]);
}

#[test]
fn example_15_3_4_rotation_generator_eigenvalues() {
    // Ex 15.3.4: [[0, −1], [1, 0]] has eigenvalues ±j, an exact conjugate pair.
    let ev = linalg::eigenvalues(&dmatrix![0.0, -1.0; 1.0, 0.0]).unwrap();
    assert_eq!(ev.len(), 2);
    assert_eq!(ev[0], ev[1].conj());
    assert_abs(ev[0].re, 0.0, 4.0 * EPS);
    assert_abs(ev[0].im.abs(), 1.0, 4.0 * EPS);
}

#[test]
fn problem_15_20_2_eigenvalues_trace_determinant() {
    // 15.20.2: A = [[3,0,2],[4,3,5],[7,2,6]]: eig 9.8467, 2.2438, −0.0905; Σλ = tr A = 12,
    // ∏λ = det A = −2 (15.3.7–8); eig(A²) = λ² and eig(A⁻¹) = 1/λ (Facts 15.3.11–12).
    // ERR: the book's second listing {10.6031, 0.1515, 1.2454} is wrong and "A.^2" should be A².
    let a = dmatrix![3.0, 0.0, 2.0; 4.0, 3.0, 5.0; 7.0, 2.0, 6.0];
    let ev = sorted(linalg::eigenvalues(&a).unwrap());
    for (got, want) in ev.iter().zip([-0.0905, 2.2438, 9.8467]) {
        assert_printed(got.re, want, 4);
        assert_eq!(got.im, 0.0);
    }
    let sum: f64 = ev.iter().map(|z| z.re).sum();
    let prod: f64 = ev.iter().map(|z| z.re).product();
    assert_rel(sum, 12.0, 32.0 * EPS);
    assert_rel(prod, -2.0, 1e3 * EPS); // λ₃ ≈ −0.09 amplifies the relative error ~100×
    let ev2 = sorted(linalg::eigenvalues(&(&a * &a)).unwrap());
    for (got, want) in ev2.iter().zip([0.0082, 5.0349, 96.9570]) {
        assert_printed(got.re, want, 4);
    }
    let inv = a.clone().try_inverse().unwrap();
    let evi = sorted(linalg::eigenvalues(&inv).unwrap());
    for (got, want) in evi.iter().zip([-11.0472, 0.1016, 0.4457]) {
        assert_printed(got.re, want, 4);
    }
}

#[test]
fn problem_15_20_3_a_at_is_positive_semidefinite() {
    // 15.20.3: the printed 4×2 "rand" A; AAᵀ is symmetric with eigenvalues {0, 0, 0.2632,
    // 2.8813} (rank 2: two exact zeros), so it is positive semidefinite, and xᵀAAᵀx = |Aᵀx|² ≥ 0.
    // The notes recompute 2.8812 from the printed (rounded) A; the book's 2.8813 came from the
    // unrounded matrix.
    let a = dmatrix![0.9501, 0.8913; 0.2311, 0.7621; 0.6068, 0.4565; 0.4860, 0.0185];
    let m = &a * a.transpose();
    let ev = sorted(linalg::eigenvalues(&m).unwrap());
    let scale = m.nan_amax();
    for z in &ev[..2] {
        // a rank-2 matrix: the two zero eigenvalues to the eigensolver's ~10ε‖M‖
        assert_abs(z.re, 0.0, 64.0 * EPS * scale);
    }
    assert_printed(ev[2].re, 0.2632, 4);
    assert_printed(ev[3].re, 2.8812, 4);
    assert!(ev.iter().all(|z| z.im == 0.0));
    for x in [dvector![1.0, -2.0, 0.5, 3.0], dvector![0.3, 0.1, -0.9, 0.0], dvector![-1.0, 1.0, 1.0, -1.0]] {
        let z = a.transpose() * &x;
        assert_rel((x.transpose() * &m * &x)[(0, 0)], z.norm_squared(), 16.0 * EPS);
    }
}

#[test]
fn problem_15_20_5_roots_equal_companion_eigenvalues() {
    // 15.20.5: p = s³ + 3s² + 5s − 2 has roots −1.6641 ± 1.8230j and 0.3283.
    let r = sorted(poly(&[1.0, 3.0, 5.0, -2.0]).roots().unwrap());
    assert_printed(r[0].re, -1.6641, 4);
    assert_printed(r[0].im, -1.8230, 4);
    assert_eq!(r[0], r[1].conj());
    assert_printed(r[2].re, 0.3283, 4);
    // p(A) = 0 for its companion matrix (Cayley–Hamilton, 15.20.4).
    let sys = StateSpace::companion(&[-2.0, 5.0, 3.0], 1.0).unwrap();
    let a = sys.a();
    let pa = a * a * a + 3.0 * a * a + 5.0 * a - 2.0 * DMatrix::<f64>::identity(3, 3);
    assert!(pa.nan_amax() <= 64.0 * EPS, "p(A) = {pa}");
}

#[test]
fn problem_15_20_6_rotation_and_reflection() {
    // 15.20.6: A = [[cos θ, sin θ], [−sin θ, cos θ]] and B = [[cos θ, sin θ], [sin θ, −cos θ]] are
    // orthogonal with det A = 1, det B = −1, eigenvalues cos θ ± j sin θ and ±1; for θ = 76°,
    // A[1, 1]ᵀ = [1.2122, −0.7284] and B[1, 1]ᵀ = [1.2122, 0.7284], both of length √2.
    let th = 76f64.to_radians();
    let (c, s) = (th.cos(), th.sin());
    let a = dmatrix![c, s; -s, c];
    let b = dmatrix![c, s; s, -c];
    for (m, det) in [(&a, 1.0), (&b, -1.0)] {
        assert!((m * m.transpose() - DMatrix::<f64>::identity(2, 2)).nan_amax() <= 4.0 * EPS);
        assert_abs(m.determinant(), det, 4.0 * EPS);
    }
    let ea = sorted(linalg::eigenvalues(&a).unwrap());
    assert_abs(ea[0].re, c, 4.0 * EPS);
    assert_abs(ea[1].im, s, 4.0 * EPS);
    assert_eq!(ea[0], ea[1].conj());
    let eb = sorted(linalg::eigenvalues(&b).unwrap());
    assert_abs(eb[0].re, -1.0, 4.0 * EPS);
    assert_abs(eb[1].re, 1.0, 4.0 * EPS);
    let one = dvector![1.0, 1.0];
    let (ya, yb) = (&a * &one, &b * &one);
    assert_printed(ya[0], 1.2122, 4);
    assert_printed(ya[1], -0.7284, 4);
    assert_printed(yb[0], 1.2122, 4);
    assert_printed(yb[1], 0.7284, 4);
    assert_rel(ya.norm(), 2f64.sqrt(), 4.0 * EPS);
    assert_rel(yb.norm(), 2f64.sqrt(), 4.0 * EPS);
}

#[test]
fn problem_15_20_7_angle_by_the_dot_product() {
    // 15.20.7: the angle between [3, 2] and [−2, 4]: cos θ = 2/(√13·√20) = 0.1240,
    // θ = 1.4464 rad = 82.875° (vectrix's angle uses atan2 of |x × y| and x·y).
    let f = vectrix::prelude::Frame::new();
    let (x, y) = (f.vector([3.0, 2.0, 0.0]), f.vector([-2.0, 4.0, 0.0]));
    let th = x.angle(&y);
    assert_printed(th.cos(), 0.1240, 4);
    assert_printed(th, 1.4464, 4);
    assert_printed(th.to_degrees(), 82.875, 3);
    assert_rel(th, (2.0 / (13f64.sqrt() * 20f64.sqrt())).acos(), 4.0 * EPS);
}

#[test]
fn eq_15_3_5_eigenvalues_of_matrices_that_stall_plain_qr() {
    // (15.3.5): the cyclic permutation matrices are fixed points of the unshifted and of the
    // plain Francis double-shift QR step: only the exceptional shifts move them. Their
    // eigenvalues are the n-th roots of unity.
    for n in [3usize, 4, 5, 8, 13] {
        let a = DMatrix::from_fn(n, n, |i, j| if i == (j + 1) % n { 1.0 } else { 0.0 });
        let ev = linalg::eigenvalues(&a).unwrap();
        assert_eq!(ev.len(), n);
        for z in &ev {
            assert_abs(z.norm(), 1.0, 64.0 * EPS);
            // z is an n-th root of unity: zⁿ = 1
            assert!((z.powu(n as u32) - Complex64::new(1.0, 0.0)).norm() <= 1e3 * EPS, "n = {n}: {z}");
        }
    }
    // a Jordan block with a tiny corner: eigenvalues on a circle of radius δ^{1/n} (δ = 1e-12,
    // n = 6: radius 1e-2) — the textbook example of eigenvalue sensitivity; |δλ| ≈ ε^{1/6}·…
    // is hidden because the perturbation is structured, 1e-12 absolute is what the QR reaches.
    let n = 6;
    let a = DMatrix::from_fn(n, n, |i, j| {
        if j == i + 1 {
            1.0
        } else if i == n - 1 && j == 0 {
            1e-12
        } else {
            0.0
        }
    });
    for z in linalg::eigenvalues(&a).unwrap() {
        assert_abs(z.norm(), 1e-2, 1e-12);
    }
    // zero, identity and a 1×1 matrix
    assert!(linalg::eigenvalues(&DMatrix::zeros(4, 4)).unwrap().iter().all(|z| z.norm() == 0.0));
    assert!(
        linalg::eigenvalues(&DMatrix::identity(5, 5)).unwrap().iter().all(|z| *z == Complex64::new(1.0, 0.0))
    );
    assert_eq!(linalg::eigenvalues(&dmatrix![-3.5]).unwrap(), vec![Complex64::new(-3.5, 0.0)]);
}

#[test]
fn eq_15_3_5_eigenvalues_anywhere_in_the_float_range() {
    // Issue 22: entries of 1e308 hung the balancing loop. The eigenvalues scale with the
    // matrix: diag(1e308, −1e300)·[[1, 1], [0, 1]]-like matrices keep theirs, a matrix whose
    // eigenvalue exceeds the range is an Overflow error (not [1e308, 1e308]), and tiny entries
    // (1e-300) keep their complex pairs.
    let big = dmatrix![1e308, 1e308; 0.0, -1e308];
    let ev = sorted(linalg::eigenvalues(&big).unwrap());
    assert_eq!(ev, vec![Complex64::new(-1e308, 0.0), Complex64::new(1e308, 0.0)]);
    let over = dmatrix![1e308, 1e308; 1e308, 1e308]; // eigenvalues 0 and 2e308
    assert!(matches!(linalg::eigenvalues(&over), Err(LtiError::Overflow { .. })));
    assert!(matches!(
        StateSpace::from_rows(
            &[&[1e308, 1e308], &[1e308, 1e308]],
            &[&[0.0], &[1.0]],
            &[&[1.0, 0.0]],
            &[&[0.0]]
        )
        .unwrap()
        .poles(),
        Err(LtiError::Overflow { .. })
    ));
    let tiny = dmatrix![0.0, -1e-300; 1e-300, 0.0];
    let ev = sorted(linalg::eigenvalues(&tiny).unwrap());
    assert_abs(ev[1].im, 1e-300, 4.0 * EPS * 1e-300);
    assert_eq!(ev[0], ev[1].conj());
    // balancing a matrix of huge entries is bounded and exact
    let b = linalg::balance(&dmatrix![1e308, 1e300; 1e-300, 1.0]).unwrap();
    assert!(b.iter().all(|x| x.is_finite()));
}

#[test]
fn eq_15_18_7_roots_across_the_float_range() {
    // (15.18.7), `roots`: exact roots at 0 stay exact (integrators, DRB); ss → tf round-off in the
    // leading coefficient is trimmed (notes §3.3: 1.1e-16 gave a spurious zero at −1.04e16); and
    // 1e300 s² + s + 1, whose roots are −5e-301 ± j·1e-150 to 16 digits, keeps its imaginary
    // parts (issue 22: the companion matrix underflowed them away before the variable was
    // scaled).
    let p = poly(&[1.0, 1.0, 0.0, 0.0]);
    let r = sorted(p.roots().unwrap());
    assert_eq!(r[1], Complex64::new(0.0, 0.0));
    assert_eq!(r[2], Complex64::new(0.0, 0.0));
    let noisy = poly(&[1.1e-16, 1.151, 0.1774]);
    assert_eq!(noisy.trim(TRIM_RTOL).degree(), 1);
    let r = sorted(poly(&[1e300, 1.0, 1.0]).roots().unwrap());
    // exact: s = (−1 ± j√(4e300 − 1))/(2e300): Re = −5e-301, |Im| = √(1e300 − ¼)/1e300 ≈ 1e-150
    assert_rel(r[1].im, 1e-150, 8.0 * EPS);
    assert_rel(r[1].re, -5e-301, 8.0 * EPS);
    assert_eq!(r[0], r[1].conj());
    // and the mirror: s² + s + 1e300 has roots ≈ −½ ± j·1e150
    let r = sorted(poly(&[1.0, 1.0, 1e300]).roots().unwrap());
    assert_rel(r[1].im, 1e150, 8.0 * EPS);
    assert_rel(r[1].re, -0.5, 8.0 * EPS);
}

#[test]
fn problem_15_20_4_cayley_hamilton_for_companion_matrices() {
    // 15.20.4: A = [[0, 1], [−a₀, −a₁]] has p(s) = s² + a₁s + a₀ and p(A) = A² + a₁A + a₀I = 0,
    // with A² = [[−a₀, −a₁], [a₀a₁, −a₀ + a₁²]] as printed; the 3 × 3 companion matrix has
    // p(s) = s³ + a₂s² + a₁s + a₀ and p(A) = 0 with the printed A² and A³. Integer coefficients
    // keep every product exact, so the identities hold exactly in floating point.
    for (a0, a1, a2) in [(-2.0, 5.0, 3.0), (6.0, 11.0, 6.0), (1.0, -4.0, 7.0), (0.0, 0.0, 0.0)] {
        let a = dmatrix![0.0, 1.0; -a0, -a1];
        let a_sq = &a * &a;
        assert_eq!(a_sq, dmatrix![-a0, -a1; a0 * a1, -a0 + a1 * a1]);
        let p = &a_sq + a1 * &a + a0 * DMatrix::identity(2, 2);
        assert_eq!(p, DMatrix::zeros(2, 2));
        let a = dmatrix![0.0, 1.0, 0.0; 0.0, 0.0, 1.0; -a0, -a1, -a2];
        let (a_sq, a_cu) = (&a * &a, &a * &a * &a);
        assert_eq!(a_sq, dmatrix![0.0, 0.0, 1.0; -a0, -a1, -a2; a0 * a2, -a0 + a1 * a2, -a1 + a2 * a2]);
        let printed_a_cu = dmatrix![
            -a0, -a1, -a2;
            a0 * a2, -a0 + a1 * a2, -a1 + a2 * a2;
            a0 * a1 - a0 * a2 * a2, a1 * a1 - a2 * (-a0 + a1 * a2), -a0 + a1 * a2 - a2 * (-a1 + a2 * a2)
        ];
        assert_eq!(a_cu, printed_a_cu);
        let p = &a_cu + a2 * &a_sq + a1 * &a + a0 * DMatrix::identity(3, 3);
        assert_eq!(p, DMatrix::zeros(3, 3));
        // p(s) = det(sI − A): the characteristic polynomial rebuilt from the eigenvalues
        let p_of_ev = Polynomial::from_roots(&linalg::eigenvalues(&a).unwrap()).unwrap();
        for (got, want) in p_of_ev.coeffs().iter().zip([1.0, a2, a1, a0]) {
            // the roots are good to ~1e-15 relative to the largest coefficient (up to 11 here)
            assert_abs(*got, want, 1e3 * EPS * 11.0);
        }
    }
    // at non-integer coefficients p(A) vanishes to rounding, relative to the size of A³
    let (a0, a1, a2) = (0.37f64, -1.9f64, 2.6f64);
    let a = dmatrix![0.0, 1.0, 0.0; 0.0, 0.0, 1.0; -a0, -a1, -a2];
    let a_cu = &a * &a * &a;
    let p: DMatrix<f64> = &a_cu + a2 * (&a * &a) + a1 * &a + a0 * DMatrix::<f64>::identity(3, 3);
    assert!(p.nan_amax() <= 64.0 * EPS * a_cu.nan_amax());
}

#[test]
fn example_15_18_1_atan2_quadrants() {
    // Ex 15.18.1: atan2(1, 1) = π/4 and atan2(−1, −1) = −3π/4, the angle in (−π, π] of x + jy.
    // As phases of a frequency response: G(s) = 2/(1 − s) has G(j) = 1 + j and −G has
    // G(j) = −1 − j; the wrapped Bode phases are 45° and −135°.
    use std::f64::consts::PI;
    let g = tf(&[-2.0], &[1.0, -1.0]);
    let z = g.freqresp(&[1.0]).unwrap()[0];
    assert_abs(z.re, 1.0, 4.0 * EPS);
    assert_abs(z.im, 1.0, 4.0 * EPS);
    assert_rel(z.arg(), PI / 4.0, 4.0 * EPS);
    let zn = g.neg().freqresp(&[1.0]).unwrap()[0];
    assert_rel(zn.arg(), -3.0 * PI / 4.0, 4.0 * EPS);
    assert_rel(wrap_deg(g.bode(&[1.0]).unwrap().phase_deg[0]), 45.0, 16.0 * EPS);
    assert_rel(wrap_deg(g.neg().bode(&[1.0]).unwrap().phase_deg[0]), -135.0, 16.0 * EPS);
    // the interval is half-open: the negative real axis is +π, not −π
    assert_eq!(wrap_deg(-180.0), 180.0);
    assert_eq!(Complex64::new(-1.0, 0.0).arg(), PI);
}
