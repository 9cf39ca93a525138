//! Shared pieces of the chapter-14 problem and section tests: random stability derivatives
//! biased toward the hard cases, frequency-domain evaluation, and the printed 747 / F-104 data.

use proptest::prelude::*;
use vectrix::flight::*;
use vectrix::lti::Complex64;
use vectrix::nalgebra::DMatrix;

/// Half a unit in the last printed digit of a value printed with `digits` decimals.
pub fn printed(digits: i32) -> f64 {
    0.5 * 10f64.powi(-digits)
}

/// Longitudinal derivatives of an arbitrary aircraft: every entry of Table 14.1 nonzero
/// (including X_α̇, Z_α̇, M_α̇, which the business jet's data set to zero or near it), U₀ away from
/// Z_α̇ (Υ nonsingular).
pub fn longitudinal() -> impl Strategy<Value = LongitudinalDerivatives> {
    (
        100.0..1000.0f64,
        [-0.05..0.0f64, -2.0..2.0f64, 1.0..20.0f64, -5.0..5.0f64, -5.0..5.0f64, -0.01..0.01f64],
        [-0.5..0.0f64, -5.0..0.0f64, -800.0..-50.0f64, -5.0..5.0f64, -80.0..0.0f64, -0.01..0.01f64],
        [
            -0.01..0.01f64,
            -3.0..0.0f64,
            -20.0..-0.5f64,
            -1.0..0.5f64,
            -30.0..-1.0f64,
            -0.01..0.01f64,
            -1.0..1.0f64,
        ],
    )
        .prop_map(|(u0, x, z, m)| LongitudinalDerivatives {
            u0,
            g: 32.2,
            theta0: 0.0,
            x_u: x[0],
            x_q: x[1],
            x_alpha: x[2],
            x_alpha_dot: x[3],
            x_de: x[4],
            x_tu: x[5],
            z_u: z[0],
            z_q: z[1],
            z_alpha: z[2],
            z_alpha_dot: z[3],
            z_de: z[4],
            z_tu: z[5],
            m_u: m[0],
            m_q: m[1],
            m_alpha: m[2],
            m_alpha_dot: m[3],
            m_de: m[4],
            m_tu: m[5],
            m_talpha: m[6],
        })
}

/// Lateral derivatives of an arbitrary aircraft with every entry of Table 14.2 nonzero
/// (including the β̇ derivatives and J_xz).
pub fn lateral() -> impl Strategy<Value = LateralDerivatives> {
    (
        100.0..1000.0f64,
        [5_000.0..60_000.0f64, 5_000.0..60_000.0f64, -3_000.0..3_000.0f64],
        [-100.0..-5.0f64, -2.0..2.0f64, -2.0..2.0f64, -5.0..5.0f64, -2.0..2.0f64, 0.0..20.0f64],
        [-10.0..0.0f64, -2.0..0.0f64, -0.5..0.5f64, -1.0..1.0f64, 0.5..10.0f64, -2.0..2.0f64, -0.5..0.5f64],
        [0.5..5.0f64, -0.1..0.1f64, -0.5..0.0f64, -1.0..1.0f64, -1.0..0.0f64, -3.0..0.0f64, -0.5..0.5f64],
    )
        .prop_map(|(u0, j, y, l, n)| LateralDerivatives {
            u0,
            g: 32.2,
            jxx: j[0],
            jzz: j[1],
            jxz: j[2],
            y_beta: y[0],
            y_p: y[1],
            y_r: y[2],
            y_beta_dot: y[3],
            y_da: y[4],
            y_dr: y[5],
            l_beta: l[0],
            l_p: l[1],
            l_r: l[2],
            l_beta_dot: l[3],
            l_da: l[4],
            l_dr: l[5],
            l_tbeta: l[6],
            n_beta: n[0],
            n_p: n[1],
            n_r: n[2],
            n_beta_dot: n[3],
            n_da: n[4],
            n_dr: n[5],
            n_tbeta: n[6],
        })
        .prop_filter("a physical inertia", |d| d.jxz * d.jxz < 0.9 * d.jxx * d.jzz)
}

/// (sI − A)⁻¹B at complex s (n × m), by a complex LU solve.
pub fn resolvent_b(a: &DMatrix<f64>, b: &DMatrix<f64>, s: Complex64) -> DMatrix<Complex64> {
    let n = a.nrows();
    let m = DMatrix::from_fn(n, n, |i, j| if i == j { s } else { Complex64::new(0.0, 0.0) } - a[(i, j)]);
    let rhs = b.map(|x| Complex64::new(x, 0.0));
    m.lu().solve(&rhs).expect("s is not an eigenvalue")
}

/// The F-104 of P14.9.5 as printed, x = [u, δα, θ, θ̇] (u in m/s; the −32.2 is g in ft/s², the
/// units slip the notes flag in the 747 matrix these numbers come from).
pub fn f104() -> DMatrix<f64> {
    #[rustfmt::skip]
    let a = DMatrix::from_row_slice(4, 4, &[
        -2.02e-2, 7.88, -3.22e1, -6.5e-1,
        -2.54e-4, -1.02, 0.0, 9.05e-1,
        0.0, 0.0, 0.0, 1.0,
        7.95e-11, -2.5, 0.0, -1.39,
    ]);
    a
}

/// (A, B) extended by k states whose rates are linear in the state: row i of `rows` lists the
/// (column, coefficient) pairs of the i-th new rate, e.g. ψ̇ = r, ẏ = U₀(δβ + ψ) (14.3.17) or
/// ẋ = u, ḣ = U₀(θ − δα) (14.1.15). The new states have no input.
pub fn augment(a: &DMatrix<f64>, b: &DMatrix<f64>, rows: &[&[(usize, f64)]]) -> (DMatrix<f64>, DMatrix<f64>) {
    let (n, m, k) = (a.nrows(), b.ncols(), rows.len());
    let mut aa = DMatrix::zeros(n + k, n + k);
    aa.view_mut((0, 0), (n, n)).copy_from(a);
    for (i, row) in rows.iter().enumerate() {
        for &(j, c) in row.iter() {
            aa[(n + i, j)] = c;
        }
    }
    let mut bb = DMatrix::zeros(n + k, m);
    bb.view_mut((0, 0), (n, m)).copy_from(b);
    (aa, bb)
}
