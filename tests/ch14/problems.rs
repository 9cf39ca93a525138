//! Problems 14.9.1–3 and 14.9.5–8 (P14.9.4 is in the chapter root). The book prints no
//! solutions; P14.9.5–6 use the same numbers as the 747 of §14.7.1, whose printed results they
//! must reproduce (reordered), and the rest are checked against closed forms at random and
//! hard stability derivatives.

use std::f64::consts::{LN_2, PI};

use proptest::prelude::*;
use vectrix::flight::*;
use vectrix::lti::{Complex64, FinalValue, StateSpace, expm, final_value, routh};
use vectrix::nalgebra::{DMatrix, DVector};
use vectrix::num_dual::{Dual64, DualNum};

use crate::common::{augment, f104, longitudinal, printed};
use crate::support::{EPS, nan_max};

/// Sample points s for frequency-domain identities: on and off the imaginary axis.
const S: [(f64, f64); 4] = [(0.0, 0.3), (0.1, 1.7), (-0.2, 4.0), (2.0, -0.5)];

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// P14.9.1: "the numerator of the transfer function from δe to θ is second order: CB = 0"
    /// (§15.14). For the output θ, C = e₄ᵀ and the fourth entry of B = Υ⁻¹B₀ is 0, so the s³
    /// coefficient CB of the numerator vanishes; and G_q = sG_θ because θ̇ = q. (The book's
    /// (14.2.7)/(14.2.8) swap the labels: θ/δe is the quadratic one, notes [T].)
    #[test]
    fn problem_14_9_1_pitch_numerator_is_quadratic(d in longitudinal()) {
        let sys = d.state_space().unwrap();
        prop_assert_eq!(sys.b()[(3, 0)], 0.0);
        let theta = sys.to_tf(3, 0).unwrap();
        let q = sys.to_tf(2, 0).unwrap();
        let lead = theta.den().leading();
        // the s³ coefficient is CB = 0 up to the rounding of the polynomial arithmetic
        let num = theta.num().coeffs();
        let cubic = if num.len() == 4 { num[0] / lead } else { 0.0 };
        let scale = num.iter().fold(0.0f64, |m, c| nan_max(m, c.abs())) / lead.abs();
        prop_assert!(cubic.abs() <= 1e-12 * scale, "s³ coefficient {cubic} (numerator {num:?})");
        for (re, im) in S {
            let s = Complex64::new(re, im);
            let (gq, gt) = (q.eval(s), theta.eval(s));
            // two transfer functions built from polynomial coefficients spanning ≈ 1e6 (U₀, Z_α
            // against X_u, M_u): 1e-10 absolute-or-relative leaves a factor 100 over what they lose
            prop_assert!((gq - s * gt).norm() <= 1e-10 * (gq.norm() + 1.0), "G_q = {gq}, sG_θ = {}", s * gt);
        }
    }

    /// P14.9.2: "determine A_u, A_α, B_θ in terms of the stability parameters": the leading
    /// numerator coefficients are CB (14.2.9): A_u = X_δe + X_α̇Z_δe/(U₀ − Z_α̇),
    /// A_α = Z_δe/(U₀ − Z_α̇), B_θ = M_δe + M_α̇Z_δe/(U₀ − Z_α̇) (the s² coefficient of θ/δe, the
    /// s³ coefficient of q/δe). Checked with every derivative nonzero.
    #[test]
    fn problem_14_9_2_leading_numerator_coefficients(d in longitudinal()) {
        let sys = d.state_space().unwrap();
        let k = d.z_de / (d.u0 - d.z_alpha_dot);
        let want = [d.x_de + d.x_alpha_dot * k, k, d.m_de + d.m_alpha_dot * k, 0.0];
        for (out, w) in want.iter().enumerate() {
            let g = sys.to_tf(out, 0).unwrap();
            let lead = g.den().leading();
            let num = g.num().coeffs();
            // the s³ coefficient (zero-padded when the numerator is shorter); the polynomial
            // arithmetic of to_tf rounds relative to the largest coefficient, hence `scale`
            let c3 = if num.len() == 4 { num[0] / lead } else { 0.0 };
            let scale = num.iter().fold(0.0f64, |m, c| nan_max(m, c.abs())) / lead.abs();
            prop_assert!((c3 - w).abs() <= 1e-12 * scale.max(w.abs()), "output {out}: {c3} vs {w}");
        }
        let theta = sys.to_tf(3, 0).unwrap();
        let num = theta.num().trim(1e-12).coeffs().to_vec();
        let b_theta = num[num.len() - 3] / theta.den().leading();
        prop_assert!((b_theta - want[2]).abs() <= 1e-12 * want[2].abs().max(1.0));
    }
}

/// P14.9.3 with the business jet of Table 14.2: the yaw response to the rudder, ψ/δr =
/// (A s³ + B s² + C s + D)/(s(s⁴ + E′s³ + F′s² + G′s + H′)) (14.4.20), has a pole at s = 0, so it
/// is not asymptotically stable; it is semistable iff the quartic is Hurwitz, by Routh
/// (15.17.2): E′, F′, G′, H′ > 0 and H′E′² + G′² < E′F′G′. A rudder impulse δr̄δ(t) leaves
/// ψ∞ = (D_r,δr/H′)δr̄ (14.4.21; notes [C] −170.25 rad per rad·s) and, from (14.4.10), δβ∞ = 0: a
/// new heading, no lasting sideslip. Pitch is different: θ/δe has no pole at 0 (gravity fixes
/// the horizon), so θ returns to 0 after an elevator impulse. Checked also in the time domain,
/// x(t) = e^{At}B, after 40 spiral time constants.
#[test]
fn problem_14_9_3_rudder_impulse_leaves_a_new_heading() {
    let lat = business_jet_lateral();
    let sys4 = lat.state_space().unwrap();
    // augmented with ψ̇ = r (12.4.17): x = [r, δβ, p, φ, ψ]
    let (a, b) = augment(sys4.a(), sys4.b(), &[&[(0, 1.0)]]);
    let sys = StateSpace::new(a.clone(), b.clone(), DMatrix::identity(5, 5), DMatrix::zeros(5, 2)).unwrap();
    let psi = sys.to_tf(4, 1).unwrap();
    assert_eq!(psi.den().zero_roots(), 1, "ψ/δr has exactly one pole at s = 0");
    // the quartic: den = s·p(s)
    let c = psi.den().monic().unwrap().coeffs().to_vec();
    let (e, f, g, h) = (c[1], c[2], c[3], c[4]);
    assert!(e > 0.0 && f > 0.0 && g > 0.0 && h > 0.0);
    assert!(h * e * e + g * g < e * f * g, "Routh n = 4 (15.17.2)");
    let quartic = vectrix::lti::Polynomial::new(&c[..5]).unwrap();
    assert!(routh(&quartic).unwrap().is_hurwitz());
    // final values of the impulse responses (ŷ = G for δr̄ = 1)
    match final_value(&psi, 1e-9).unwrap() {
        FinalValue::Finite(v) => assert!((v - -170.25).abs() <= printed(2), "ψ∞ = {v}"),
        other => panic!("ψ∞: {other:?}"),
    }
    let beta = sys.to_tf(1, 1).unwrap();
    assert_eq!(final_value(&beta, 1e-9).unwrap(), FinalValue::Finite(0.0));
    // time domain: ψ(t) = [e^{At}B]₄₂ at t = 40 τ_s ≈ 39 400 s
    let t = 40.0 * 985.0;
    let x = expm(&(&a * t)).unwrap() * b.column(1);
    assert!((x[4] - -170.25).abs() <= printed(2), "ψ({t}) = {}", x[4]);
    // the slowest decaying mode left in δβ (the spiral) is down by e^{−40} ≈ 4e−18 per unit of
    // its amplitude; the rest is the rounding of expm over a long horizon
    assert!(x[1].abs() <= 1e-12, "δβ({t}) = {}", x[1]);
    // pitch: θ/δe has no pole at 0, θ∞ = 0 after an elevator impulse
    let lon = business_jet_longitudinal().state_space().unwrap();
    let theta = lon.to_tf(3, 0).unwrap();
    assert_eq!(theta.den().zero_roots(), 0);
    assert_eq!(final_value(&theta, 1e-9).unwrap(), FinalValue::Finite(0.0));
}

/// P14.9.5: the F-104 model ẋ = Ax, x = [u, δα, θ, θ̇], is the 747 matrix of (14.7.3) with the
/// states reordered (a permutation similarity, so the same eigenvalues). Printed for those
/// numbers (§14.7.1, Table 14.3): λ_ph = −0.0087 ± 0.074j, λ_sp = −1.206 ± 1.49j,
/// ω_n = 0.0745, 1.92; ζ = 0.117, 0.628; ω_d = 0.074, 1.49; T = 2π/ω_n = 84.34, 3.27 s;
/// T½ = ln 2/(ζω_n) = 79.5, 0.57 s. Each at half a unit of its last printed digit, except where
/// the book computed from its own rounded values: ζ_sp = 0.6286 is printed truncated (0.628),
/// and T_ph, T½,ph follow from the rounded ω_n = 0.0745 and ζω_n = 0.0087 — checked to lie in
/// the interval those roundings allow.
#[test]
fn problem_14_9_5_f104_modes() {
    let a = f104();
    let b747 = boeing_747_longitudinal_a();
    // P (747 order [u, δα, q, θ] → [u, δα, θ, θ̇]) A₇₄₇ Pᵀ = A_F104, exactly
    let perm = [0usize, 1, 3, 2];
    for i in 0..4 {
        for j in 0..4 {
            assert_eq!(a[(i, j)], b747[(perm[i], perm[j])]);
        }
    }
    let m = longitudinal_modes(&a).unwrap();
    let (ph, sp) = (m.phugoid, m.short_period);
    let close = |what: &str, got: f64, want: f64, tol: f64| {
        assert!((got - want).abs() <= tol, "{what}: {got} vs {want}")
    };
    close("σ_ph", ph.eigenvalue().re, -0.0087, printed(4));
    close("ω_d,ph", ph.eigenvalue().im, 0.074, printed(3));
    close("σ_sp", sp.eigenvalue().re, -1.206, printed(3));
    close("ω_d,sp", sp.eigenvalue().im, 1.49, printed(2));
    close("ω_n,ph", ph.natural_frequency(), 0.0745, printed(4));
    close("ω_n,sp", sp.natural_frequency(), 1.92, printed(2));
    close("ζ_ph", ph.damping_ratio(), 0.117, printed(3));
    close("ζ_sp (truncated)", sp.damping_ratio(), 0.628, 1e-3);
    close("T_sp", sp.period().unwrap(), 3.27, printed(2));
    close("T½,sp", sp.time_to_half().unwrap(), 0.57, printed(2));
    // T = 2π/ω_n with ω_n ∈ 0.0745 ± 0.00005; T½ = ln 2/(ζω_n) with ζω_n ∈ 0.0087 ± 0.00005
    let (t_lo, t_hi) = (2.0 * PI / 0.07455, 2.0 * PI / 0.07445);
    let (h_lo, h_hi) = (LN_2 / 0.00875, LN_2 / 0.00865);
    for (what, v, lo, hi) in [
        ("T_ph", ph.period().unwrap(), t_lo, t_hi),
        ("T_ph printed", 84.34, t_lo, t_hi),
        ("T½,ph", ph.time_to_half().unwrap(), h_lo, h_hi),
        ("T½,ph printed", 79.5, h_lo, h_hi),
    ] {
        assert!((lo..=hi).contains(&v), "{what} = {v} outside [{lo}, {hi}]");
    }
}

/// P14.9.6: the phugoid eigenvector of the F-104 with u normalised to 1, in magnitude and angle:
/// the 747's (14.7.5)–(14.7.7) reordered, |v| = (1, 9.6e−5, 2.33e−3, 1.74e−4),
/// ∠v = (0, −179.7°, −99.48°, ∠q) = (0, −3.137, −1.736, −0.0484) rad. The book prints
/// ∠q = −2.83°; −0.0484 rad is −2.774° (erratum, notes [T]). Tolerances: half a unit of the
/// printed digit, one unit where the book truncated (−99.485° printed −99.48°, −3.1365 rad
/// printed −3.137 here and −3.136 in (14.7.10)).
#[test]
fn problem_14_9_6_f104_phugoid_eigenvector() {
    let a = f104();
    let ph = longitudinal_modes(&a).unwrap().phugoid;
    let v = eigenvector(&a, ph.eigenvalue(), 0).unwrap();
    // the eigenvector equation itself
    let av: Vec<Complex64> = (0..4)
        .map(|i| (0..4).map(|j| v[j] * a[(i, j)]).fold(Complex64::new(0.0, 0.0), |s, x| s + x))
        .collect();
    for i in 0..4 {
        // entries of A ≤ 32.2 and |v_i| ≤ 1: a few dozen roundings
        assert!((av[i] - ph.eigenvalue() * v[i]).norm() <= 64.0 * EPS * 32.2);
    }
    let mag = [1.0, 9.6e-5, 2.33e-3, 1.74e-4];
    let mag_tol = [0.0, 0.05e-5, 0.005e-3, 0.005e-4];
    for k in 0..4 {
        assert!((v[k].norm() - mag[k]).abs() <= mag_tol[k] + 4.0 * EPS, "|v{k}| = {}", v[k].norm());
    }
    let deg = |z: Complex64| z.arg().to_degrees();
    assert!((deg(v[1]) - -179.7).abs() <= printed(1));
    assert!((deg(v[2]) - -99.48).abs() <= 2.0 * printed(2), "∠θ = {}", deg(v[2]));
    assert!((v[1].arg() - -3.137).abs() <= 2.0 * printed(3), "∠δα = {}", v[1].arg());
    assert!((v[2].arg() - -1.736).abs() <= printed(3));
    assert!((v[3].arg() - -0.0484).abs() <= printed(4));
    assert!((deg(v[3]) - -2.774).abs() <= printed(3));
    assert!((deg(v[3]) - -2.83).abs() > 0.05, "the printed −2.83° is a typo");
}

/// P14.9.7: the phugoid eigenflight of the F-104 with θ(0) = 0.5° and U₀ = 500 mph = 223.52 m/s,
/// over three full oscillations, with the altitude h and range x of (12.4.5), (12.4.8):
/// ẋ = u, ḣ = U₀(θ − δα). The eigenvector's complex scale is fixed by taking v_θ = 0.5° (real):
/// θ(t) = 0.5° e^{σt} cos ω_d t. Closed forms: x(t) = Re[c v_u (e^{λt} − 1)/λ],
/// h(t) = U₀ Re[c(v_θ − v_α)(e^{λt} − 1)/λ]; checked against e^{Ãt} of the augmented 6-state
/// model.
#[test]
fn problem_14_9_7_f104_phugoid_eigenflight() {
    let a = f104();
    let u0: f64 = 500.0 * 0.447_04;
    // 1 mph = 0.44704 m/s exactly; 500 mph = 223.52 m/s up to the rounding of the product
    assert!((u0 - 223.52).abs() <= 4.0 * EPS * 223.52);
    let lam = longitudinal_modes(&a).unwrap().phugoid.eigenvalue();
    let v = eigenvector(&a, lam, 0).unwrap();
    let theta0 = 0.5f64.to_radians();
    let c = Complex64::new(theta0, 0.0) / v[2];
    let x0: Vec<f64> = v.iter().map(|z| (c * z).re).collect();
    assert!((x0[2] - theta0).abs() <= 4.0 * EPS * theta0);
    // augmented state [u, δα, θ, θ̇, x, h]
    let (aa, _) = augment(&a, &DMatrix::zeros(4, 1), &[&[(0, 1.0)], &[(1, -u0), (2, u0)]]);
    let y0 = DVector::from_iterator(6, x0.iter().copied().chain([0.0, 0.0]));
    let period = 2.0 * PI / lam.im;
    for k in 1..=30 {
        let t = 3.0 * period * k as f64 / 30.0;
        let y = expm(&(&aa * t)).unwrap() * &y0;
        let e = ((lam * t).exp() - 1.0) / lam;
        let x_range = (c * v[0] * e).re;
        let h = u0 * (c * (v[2] - v[1]) * e).re;
        let state = eigenflight(lam, &v.iter().map(|z| c * z).collect::<Vec<_>>(), t);
        // expm of A·t for t ≤ 255 s against the closed form: 1e-9 of the state's size (the states
        // are ≤ 1 here; expm's relative accuracy degrades with ‖At‖ ≈ 8000)
        for i in 0..4 {
            assert!(
                (y[i] - state[i]).abs() <= 1e-9 * (1.0 + state[i].abs()),
                "x{i}({t}) = {} vs {}",
                y[i],
                state[i]
            );
        }
        // expm over t ≤ 255 s of a matrix with entries ≈ 200: 1e-9 of each oscillation's
        // amplitude |c v (1 + |e^{λt}|)/λ| (the values themselves cross zero)
        let amp_x = (c * v[0] / lam).norm() * 2.0;
        let amp_h = u0 * (c * (v[2] - v[1]) / lam).norm() * 2.0;
        assert!((y[4] - x_range).abs() <= 1e-9 * amp_x, "range {t}: {} vs {x_range}", y[4]);
        assert!((y[5] - h).abs() <= 1e-9 * amp_h, "altitude {t}: {} vs {h}", y[5]);
    }
}

/// P14.9.8: with q(t) and θ(t) the eigensolution expressions (14.7.11)–(14.7.12),
/// x(t) = r e^{σt} cos(ω_d t + φ) per component, show θ̇(t) = q(t).
///
/// Computed for the 747 of §14.7.3 (vectrix's catalog matrix) and the business jet of Table
/// 14.1, both modes each: λ from `longitudinal_modes`, v from `eigenvector` with u = 1 (the
/// book's normalisation), θ(t) in the polar form (14.7.12) with r_θ = |v_θ|, φ_θ = arg v_θ
/// differentiated exactly by a dual number in t, against q(t) from vectrix's `eigenflight`. The
/// 747 phugoid's (14.7.11)–(14.7.12) are printed: r_q = 1.74e-4, φ_q = −0.0484,
/// r_θ = 2.33e-3, φ_θ = −1.736, checked to their printed digits. θ̇ = q is the last row of A;
/// in the polar numbers it reads r_q = |λ|r_θ, φ_q = φ_θ + arg λ.
#[test]
fn problem_14_9_8_pitch_rate_is_the_derivative_of_pitch() {
    let boeing = boeing_747_longitudinal_a();
    let jet = business_jet_longitudinal().state_space().unwrap().a().clone();
    for (name, a) in [("747", &boeing), ("business jet", &jet)] {
        let modes = longitudinal_modes(a).unwrap();
        for mode in [modes.phugoid, modes.short_period] {
            let lam = mode.eigenvalue();
            let v = eigenvector(a, lam, 0).unwrap();
            let (r_theta, phi_theta) = (v[3].norm(), v[3].arg());
            // the eigenvector is good to its backward error, ~ε(‖A‖ + |λ|)‖v‖ per entry (‖v‖ ≈ 1
            // with u = 1), far below |v_q| here; the polar form loses ε·ω_d t in its argument
            let scale = a.iter().fold(lam.norm(), |m, x| nan_max(m, x.abs()));
            for t in [0.0, 1.3, 17.0, 120.0] {
                let tt = Dual64::new(t, 1.0);
                // (14.7.12): θ(t) = r_θ e^{σt} cos(ω_d t + φ_θ)
                let theta = (tt * lam.re).exp() * (tt * lam.im + phi_theta).cos() * r_theta;
                let x = eigenflight(lam, &v, t);
                assert!((theta.re - x[3]).abs() <= 16.0 * EPS * r_theta * (1.0 + lam.im.abs() * t));
                let tol = 64.0 * EPS * scale * (lam.re * t).exp() * (1.0 + lam.norm() * t);
                assert!(
                    (theta.eps - x[2]).abs() <= tol,
                    "{name} λ = {lam}, t = {t}: θ̇ = {} vs q = {}",
                    theta.eps,
                    x[2]
                );
            }
            // in the polar numbers of (14.7.11)–(14.7.12)
            let (r_q, phi_q) = (v[2].norm(), v[2].arg());
            assert!((r_q - lam.norm() * r_theta).abs() <= 64.0 * EPS * scale, "{name} λ = {lam}");
            let turn = (phi_q - phi_theta - lam.arg()).rem_euclid(2.0 * PI);
            assert!(turn.min(2.0 * PI - turn) <= 64.0 * EPS * scale / r_q, "{name} λ = {lam}");
        }
    }
    // the printed 747 phugoid eigensolution (14.7.11)–(14.7.12)
    let lam = longitudinal_modes(&boeing).unwrap().phugoid.eigenvalue();
    let v = eigenvector(&boeing, lam, 0).unwrap();
    assert!((v[2].norm() - 1.74e-4).abs() <= printed(6));
    assert!((v[2].arg() - -0.0484).abs() <= printed(4));
    assert!((v[3].norm() - 2.33e-3).abs() <= printed(5));
    assert!((v[3].arg() - -1.736).abs() <= printed(3));
}

/// The business jet's θ/δe and q/δe of Table 14.1 (P14.9.1 on the book's data): the numerator
/// of θ/δe is exactly quadratic.
#[test]
fn problem_14_9_1_business_jet() {
    let sys = business_jet_longitudinal().state_space().unwrap();
    let theta = sys.to_tf(3, 0).unwrap();
    assert_eq!(theta.num().trim(1e-12).degree(), 2);
}
