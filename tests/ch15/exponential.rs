//! §15.5–15.6: the matrix exponential and eigensolutions; problems 15.20.10, 15.20.27 and 15.20.59.

use super::*;
use crate::support::NanAmax;
use nalgebra::{dmatrix, dvector};

#[test]
fn example_15_5_1_expm_of_diagonal() {
    // Ex 15.5.1: e^{diag(1,2)t} = diag(eᵗ, e²ᵗ).
    let t = 0.7;
    let e = expm(&dmatrix![t, 0.0; 0.0, 2.0 * t]).unwrap();
    assert_rel(e[(0, 0)], t.exp(), 4.0 * EPS);
    assert_rel(e[(1, 1)], (2.0 * t).exp(), 4.0 * EPS);
    assert_eq!(e[(0, 1)], 0.0);
}

#[test]
fn example_15_5_2_expm_of_rotation_generator() {
    // Ex 15.5.2: e^{[[0, ω], [−ω, 0]]t} = [[cos ωt, sin ωt], [−sin ωt, cos ωt]].
    // ERR: the book cites Ex 15.3.3 for the eigenvalues; it means Ex 15.3.4.
    for wt in [0.1f64, 1.0, 3.0, 25.0] {
        let e = expm(&dmatrix![0.0, wt; -wt, 0.0]).unwrap();
        let want = dmatrix![wt.cos(), wt.sin(); -wt.sin(), wt.cos()];
        // absolute: entries of size ≤ 1; scaling and squaring by 2ˢ ∝ ωt amplifies round-off
        assert!((e - want).nan_amax() <= 64.0 * EPS * wt.max(1.0), "ωt = {wt}");
    }
}

#[test]
fn eq_15_5_3_expm_of_defective_critical_damping() {
    // Notes §3.1: e^{[[0,1],[−1,−2]]t} = e^{−t}[[1+t, t], [−t, 1−t]] (a Jordan block, where an
    // eigendecomposition fails); at t = 1.3: [[0.62682, 0.35429], [−0.35429, −0.08176]].
    let t = 1.3;
    let e = expm(&dmatrix![0.0, t; -t, -2.0 * t]).unwrap();
    let f = (-t).exp();
    let want = dmatrix![f * (1.0 + t), f * t; -f * t, f * (1.0 - t)];
    assert!((&e - want).nan_amax() <= 16.0 * EPS); // absolute, entries below 1
    assert_printed(e[(0, 0)], 0.62682, 5);
    assert_printed(e[(1, 1)], -0.08176, 5);
}

#[test]
fn problem_15_20_27_damped_rigid_body_expm() {
    // 15.20.27: DRB e^{At} = [[1, (m/c)(1 − e^{−ct/m})], [0, e^{−ct/m}]] → [[1, m/c], [0, 0]].
    let (m, c) = (3.0, 4.0);
    let a = Sdof::new(m, c, 0.0).unwrap().to_state_space(SdofOutput::Position).unwrap().a().clone();
    for t in [0.5f64, 2.0, 40.0] {
        let e = expm(&(&a * t)).unwrap();
        assert_abs(e[(0, 1)], m / c * (1.0 - (-c * t / m).exp()), 16.0 * EPS);
        assert_abs(e[(1, 1)], (-c * t / m).exp(), 16.0 * EPS);
        assert_abs(e[(0, 0)], 1.0, 16.0 * EPS);
    }
}

#[test]
fn eq_15_5_3_expm_large_norm_uses_scaling_and_squaring() {
    // e^{[[σ, ω], [−ω, σ]]t} = e^{σt}[[cos ωt, sin ωt], [−sin ωt, cos ωt]] with ‖A‖ ~ 80: the
    // Padé-13 branch with squarings. Squaring s times amplifies round-off by ~2ˢ (s = 4 here).
    let (sigma, w, t) = (-0.5f64, 40.0f64, 2.0f64);
    let e = expm(&dmatrix![sigma * t, w * t; -w * t, sigma * t]).unwrap();
    let f = (sigma * t).exp();
    let want = dmatrix![f * (w * t).cos(), f * (w * t).sin(); -f * (w * t).sin(), f * (w * t).cos()];
    assert!((e - want).nan_amax() <= 1e3 * EPS, "expm with scaling");
}

#[test]
fn eq_15_5_3_expm_overflow_is_a_typed_error() {
    // Issue 22: the exponential of a large matrix came back as ∞ or NaN inside Ok. When the true
    // result exceeds the f64 range (e^{1000}), it is an Overflow error; when it does not (e^{−1000}
    // underflows to 0, a matrix of norm 1e308 whose exponential is a rotation), it is computed.
    assert!(matches!(expm(&dmatrix![1000.0]), Err(LtiError::Overflow { .. })));
    assert!(matches!(expm(&DMatrix::from_element(3, 3, 1e308)), Err(LtiError::Overflow { .. })));
    assert_eq!(expm(&dmatrix![-1000.0]).unwrap()[(0, 0)], 0.0);
    let r = expm(&dmatrix![0.0, 1e308; -1e308, 0.0]);
    // e^{[[0, θ], [−θ, 0]]} is a rotation by θ = 1e308 (mod 2π): finite, but the squaring loses
    // every digit of the angle; what matters is a typed outcome, never NaN or ∞ in Ok
    match r {
        Ok(e) => assert!(e.iter().all(|x| x.is_finite() && x.abs() <= 1.0 + 1e-6)),
        Err(err) => assert!(matches!(err, LtiError::Overflow { .. })),
    }
}

#[test]
fn problem_15_20_10_eigensolutions_spiral_in_circle_or_spiral_out() {
    // 15.20.10: ẋ = Ax with the eigenpair λ = σ + j, v = [3, 1] + j[1, 4]: the eigensolution
    // x(t) = Re(e^{λt}v) = e^{σt}(y cos t − z sin t) (15.6.2, y = [3, 1], z = [1, 4]) spirals in
    // for σ = −1, is a closed ellipse for σ = 0 and spirals out for σ = 1 (what Figs. 17.0.2–6
    // show). A = [y z]·[[σ, 1], [−1, σ]]·[y z]⁻¹ has that eigenpair; the free response from
    // x(0) = y is the eigensolution, and after one period 2π the state is e^{2πσ}·x(0).
    let (y, z) = (dvector![3.0, 1.0], dvector![1.0, 4.0]);
    let t_mat = dmatrix![3.0, 1.0; 1.0, 4.0];
    let t_inv = t_mat.clone().try_inverse().unwrap();
    for sigma in [-1.0f64, 0.0, 1.0] {
        let a = &t_mat * dmatrix![sigma, 1.0; -1.0, sigma] * &t_inv;
        let ev = sorted(linalg::eigenvalues(&a).unwrap());
        assert_abs(ev[1].re, sigma, 16.0 * EPS);
        assert_abs(ev[1].im, 1.0, 16.0 * EPS);
        let sys =
            StateSpace::new(a, DMatrix::zeros(2, 1), DMatrix::identity(2, 2), DMatrix::zeros(2, 1)).unwrap();
        let period = std::f64::consts::TAU;
        let t = time_grid(period, 65).unwrap();
        let r = initial(&sys, &[3.0, 1.0], &t).unwrap();
        for (k, &tk) in t.iter().enumerate() {
            let want = ((&y * tk.cos()) - (&z * tk.sin())) * (sigma * tk).exp();
            for i in 0..2 {
                // absolute in the units of the state, scaled by the envelope e^{σt}·|v|
                assert_abs(r.y[i][k], want[i], 64.0 * EPS * 5.0 * (sigma * tk).exp().max(1.0));
            }
        }
        // one turn: radius ratio e^{2πσ} (< 1 spiral in, = 1 ellipse, > 1 spiral out)
        let ratio = (r.y[0][64].powi(2) + r.y[1][64].powi(2)).sqrt() / 10f64.sqrt();
        assert_rel(ratio, (period * sigma).exp(), 1e3 * EPS);
    }
}

#[test]
fn fact_15_6_1_eigensolutions_of_a_third_order_system() {
    // Fact 15.6.1: for an eigenpair (λ, v), x(t) = Re(e^{λt}v) solves ẋ = Ax, x(0) = Re v.
    // A = T·blockdiag([[σ, ω], [−ω, σ]], μ)·T⁻¹ with T unimodular has λ = σ + jω,
    // v = T e₁ + jT e₂ (so y = T e₁, z = T e₂) and the real pair (μ, T e₃). The free response
    // from Re v is then e^{σt}(y cos ωt − z sin ωt) (15.6.2), and from T e₃ it is e^{μt}T e₃.
    let (sigma, omega, mu) = (-0.3, 2.0, -1.5);
    let t_mat = dmatrix![1.0, 2.0, 0.0; 0.0, 1.0, 1.0; 1.0, 0.0, 3.0];
    assert_eq!(t_mat.determinant(), 5.0);
    let t_inv = t_mat.clone().try_inverse().unwrap();
    let core = dmatrix![sigma, omega, 0.0; -omega, sigma, 0.0; 0.0, 0.0, mu];
    let a = &t_mat * core * &t_inv;
    let (y, z, w) =
        (t_mat.column(0).into_owned(), t_mat.column(1).into_owned(), t_mat.column(2).into_owned());
    // A v = λ v for v = y + jz: A y = σy − ωz and A z = ωy + σz.
    let (ay, az) = (&a * &y, &a * &z);
    for i in 0..3 {
        assert_abs(ay[i], sigma * y[i] - omega * z[i], 64.0 * EPS * 10.0);
        assert_abs(az[i], omega * y[i] + sigma * z[i], 64.0 * EPS * 10.0);
    }
    let sys =
        StateSpace::new(a, DMatrix::zeros(3, 1), DMatrix::identity(3, 3), DMatrix::zeros(3, 1)).unwrap();
    let t = time_grid(5.0, 51).unwrap();
    let osc = initial(&sys, y.as_slice(), &t).unwrap();
    let real = initial(&sys, w.as_slice(), &t).unwrap();
    for (k, &tk) in t.iter().enumerate() {
        let want = ((&y * (omega * tk).cos()) - (&z * (omega * tk).sin())) * (sigma * tk).exp();
        for i in 0..3 {
            // absolute: states are O(‖T‖) = O(3), amplified by the eigenvector condition ‖T‖‖T⁻¹‖
            assert_abs(osc.y[i][k], want[i], 1e3 * EPS);
            assert_abs(real.y[i][k], (mu * tk).exp() * w[i], 1e3 * EPS);
        }
    }
}

#[test]
fn problem_15_20_59_unstable_cancellation_by_exact_analysis() {
    // 15.20.59: G₁ = 1/(s − 1), G₂ = (s − 1)/(s + 1)², zero external inputs. The hint
    // e^{[[0,1],[−1,−2]]t} = e^{−t}[[1 + t, t], [−t, 1 − t]] is checked as the problem asks:
    // e^{A·0} = I and d/dt e^{At} = Ae^{At} (here against the closed-form derivative), and against
    // the library's expm.
    let a = dmatrix![0.0, 1.0; -1.0, -2.0];
    let phi = |t: f64| (-t).exp() * dmatrix![1.0 + t, t; -t, 1.0 - t];
    let dphi = |t: f64| (-t).exp() * dmatrix![-t, 1.0 - t; t - 1.0, t - 2.0];
    assert_eq!(phi(0.0), DMatrix::identity(2, 2));
    for t in [0.0f64, 0.5, 2.0, 7.0] {
        assert!((dphi(t) - &a * phi(t)).nan_amax() <= 16.0 * EPS * (1.0 + t), "t = {t}");
        assert!((expm(&(&a * t)).unwrap() - phi(t)).nan_amax() <= 64.0 * EPS * (1.0 + t), "t = {t}");
    }
    // G₂ in companion form (A as above, B₂ = [0, 1]ᵀ, C₂ = [−1, 1]) has the free response
    // F₂(s) = C₂(sI − A)⁻¹x₂(0), with (sI − A)⁻¹ = [[s + 2, 1], [−1, s]]/(s + 1)², so
    // C₂(sI − A)⁻¹ = [−s − 3, s − 1]/(s + 1)².
    let (x10, x2) = (0.5f64, [0.3f64, -0.2f64]);
    let f2 = |s: f64| ((-s - 3.0) * x2[0] + (s - 1.0) * x2[1]) / ((s + 1.0) * (s + 1.0));
    // G₁ precedes G₂: ŷ₂ = F₂ + G₂·x₁₀/(s − 1) = F₂ + x₁₀/(s + 1)²: the e^{t} of G₁ cancels
    // exactly and y₂ → 0, although y₁ = x₁₀eᵗ grows.
    let y2_hat = tf(&[x2[1] - x2[0], -3.0 * x2[0] - x2[1] + x10], &[1.0, 2.0, 1.0]);
    assert_eq!(y2_hat.final_value(AXIS_RTOL).unwrap(), FinalValue::Finite(0.0));
    for s in [0.5, 2.0, 9.0] {
        assert_rel(y2_hat.eval(Complex64::new(s, 0.0)).re, f2(s) + x10 / ((s + 1.0) * (s + 1.0)), 16.0 * EPS);
    }
    // G₂ precedes G₁: ŷ₁ = (x₁₀ + F₂)/(s − 1) keeps the pole at 1 with residue x₁₀ + F₂(1)
    // = x₁₀ − x₂ₐ, so y₁ grows like (x₁₀ − x₂ₐ)eᵗ unless the initial states are tuned.
    let num = poly(&[1.0, 2.0, 1.0])
        .scale(x10)
        .unwrap()
        .add(&poly(&[x2[1] - x2[0], -3.0 * x2[0] - x2[1]]))
        .unwrap();
    let y1_hat =
        TransferFunction::from_polynomials(num, poly(&[1.0, -1.0]).mul(&poly(&[1.0, 2.0, 1.0])).unwrap())
            .unwrap();
    let pf = y1_hat.partial_fractions(CLUSTER_RTOL).unwrap();
    let at_one = pf.terms.iter().find(|t| (t.pole.re - 1.0).abs() < 1e-9).unwrap();
    assert_rel(at_one.residue.re, x10 + f2(1.0), 64.0 * EPS);
    assert_rel(at_one.residue.re, x10 - x2[0], 64.0 * EPS);
    assert!(matches!(
        y1_hat.final_value(AXIS_RTOL).unwrap(),
        FinalValue::Illegal(Illegal::RightHalfPlanePole(_))
    ));
}
