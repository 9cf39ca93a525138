//! vectrix-lti under hostile input (docs/robustness.md): every public function of the
//! linear-systems crate, with its defining property checked by the test's own arithmetic —
//! roots evaluate to ~0 relative to the size of the terms, G(s) equals N(s)/D(s) by Horner
//! sums written here, e^{diag(d)} = diag(eᵈ), the eigenvalues sum to the trace, time responses
//! of 1/(s + 1) are the closed forms, crossovers satisfy |L| = 1 or Im L = 0, and tolerances
//! outside their range are refused (§3).

use crate::support::nan_max;
use nalgebra::DMatrix;
use vectrix::lti::linalg::{balance, eigenvalues, rank, singular_values};
use vectrix::lti::{
    AXIS_RTOL, AffineEquilibria, CLUSTER_RTOL, FinalValue, Hold, Illegal, InputKind, MAX_VALUES, Mode,
    Polynomial, Sdof, SdofKind, SdofOutput, StabilityClass, StateSpace, TimeResponse, TransferFunction, Zpk,
    affine_equilibria, cluster_roots, departure_angles, expm, final_value, initial, leads, logspace, lsim,
    modes, response, root_locus, routh, sensitivity_integral, stability_of_matrix, stability_of_polynomial,
    stable_gain_intervals, time_grid, time_shift, wrap_deg,
};

use crate::harness::{err_or, finite, hostile, none_or, refused};

type Complex64 = nalgebra::Complex<f64>;

const EPS: f64 = f64::EPSILON;

fn c(re: f64, im: f64) -> Complex64 {
    Complex64::new(re, im)
}

fn finite_c(z: Complex64) -> bool {
    z.re.is_finite() && z.im.is_finite()
}

fn nan_c(z: Complex64) -> bool {
    z.re.is_nan() || z.im.is_nan()
}

/// 1/z without forming |z|² (which over- or underflows far from |z| = 1).
fn inv(z: Complex64) -> Complex64 {
    let m = z.re.abs().max(z.im.abs());
    let w = z / m;
    w.conj() / (w.norm_sqr() * m)
}

/// p(s) by the test's own Horner sum, with the size of its terms Σ|cₖ||s|ᵏ.
fn horner(coeffs: &[f64], s: Complex64) -> (Complex64, f64) {
    coeffs.iter().fold((c(0.0, 0.0), 0.0), |(v, b), &ck| (v * s + ck, b * s.norm() + ck.abs()))
}

/// r is a root of p to k·ε relative to the size of p's terms at r; for |r| > 1 on p(r)/rⁿ (the
/// reversed polynomial at 1/r), so that no power overflows.
fn is_root(coeffs: &[f64], r: Complex64, k: f64) -> bool {
    let (v, b) = if r.norm() <= 1.0 {
        horner(coeffs, r)
    } else {
        let rev: Vec<f64> = coeffs.iter().rev().copied().collect();
        horner(&rev, inv(r))
    };
    finite_c(r) && v.norm() <= k * EPS * b + 1e-300
}

/// Every non-real root has its exact conjugate in the list (real coefficients).
fn paired(r: &[Complex64]) -> bool {
    r.iter().all(|z| {
        z.im == 0.0 || r.iter().filter(|w| **w == z.conj()).count() == r.iter().filter(|w| *w == z).count()
    })
}

/// N(s)/D(s) by the test's Horner sums and the size of its rounding error, `None` where the
/// sums overflow or D(s) = 0.
fn tf_at(num: &[f64], den: &[f64], s: Complex64) -> Option<(Complex64, f64)> {
    let (n, bn) = horner(num, s);
    let (d, bd) = horner(den, s);
    if !(finite_c(n) && finite_c(d) && bn.is_finite() && bd.is_finite()) || d.norm() == 0.0 {
        return None;
    }
    let q = n * inv(d);
    finite_c(q).then(|| (q, (bn + q.norm() * bd) / d.norm()))
}

/// G(s) = value to `k`·ε of the size of its rounding error, or (beyond the test's range) not NaN.
#[track_caller]
fn assert_tf_value(num: &[f64], den: &[f64], s: Complex64, got: Complex64, k: f64, what: &str) {
    if nan_c(s) {
        return;
    }
    match tf_at(num, den, s) {
        Some((want, bound)) if bound.is_finite() => {
            assert!(
                (got - want).norm() <= k * EPS * bound + 1e-300,
                "{what} at {s}: {got} ≠ {want} (bound {bound:e})"
            )
        }
        _ => assert!(!nan_c(got), "{what} at {s}: NaN"),
    }
}

/// The hostile complex points: each hostile value on the real and the imaginary axis, both,
/// and with unit imaginary part.
fn points() -> Vec<Complex64> {
    hostile().flat_map(|x| [c(x, 0.0), c(0.0, x), c(x, x), c(x, 1.0)]).collect()
}

/// Descending coefficients of the product a·b, and of |a|·|b| (the size of its terms).
fn conv(a: &[f64], b: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let mut p = vec![0.0; a.len() + b.len() - 1];
    let mut q = p.clone();
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            p[i + j] += x * y;
            q[i + j] += (x * y).abs();
        }
    }
    (p, q)
}

/// Descending coefficient lists added with their ends aligned.
fn add(a: &[f64], b: &[f64]) -> Vec<f64> {
    let n = a.len().max(b.len());
    let at = |v: &[f64], i: usize| if i + v.len() >= n { v[i + v.len() - n] } else { 0.0 };
    (0..n).map(|i| at(a, i) + at(b, i)).collect()
}

/// The polynomial has the coefficients `want` (descending) to 8ε of `size` (the size of the
/// terms that formed each).
fn poly_is(p: &Polynomial, want: &[f64], size: &[f64]) -> bool {
    let n = want.len();
    p.coeffs().len() <= n
        && (0..n).all(|k| (p.coeff(k) - want[n - 1 - k]).abs() <= 8.0 * EPS * size[n - 1 - k] + 1e-300)
}

/// C(sI − A)⁻¹B + D of a SISO model by the test's own complex LU.
fn ss_at(sys: &StateSpace, s: Complex64) -> Option<Complex64> {
    let n = sys.n_states();
    let m = DMatrix::from_fn(n, n, |i, j| if i == j { s } else { c(0.0, 0.0) } - c(sys.a()[(i, j)], 0.0));
    let b = DMatrix::from_fn(n, 1, |i, _| c(sys.b()[(i, 0)], 0.0));
    let x = m.lu().solve(&b)?;
    let y = (0..n).map(|j| x[(j, 0)] * sys.c()[(0, j)]).sum::<Complex64>() + sys.d()[(0, 0)];
    finite_c(y).then_some(y)
}

fn tf(num: &[f64], den: &[f64]) -> TransferFunction {
    TransferFunction::new(num, den).unwrap()
}

/// 1/(s + 1) in state-space form.
fn first_order() -> StateSpace {
    StateSpace::from_rows(&[&[-1.0]], &[&[1.0]], &[&[1.0]], &[&[0.0]]).unwrap()
}

/// The unit responses of 1/(s + 1) from rest at time t ≥ 0.
fn closed_form(kind: InputKind, t: f64) -> f64 {
    match kind {
        InputKind::Impulse => (-t).exp(),
        InputKind::Step => -(-t).exp_m1(),
        InputKind::Ramp => t + (-t).exp_m1(),
    }
}

/// Output 0 of a response equals `f(t)` at every sample to 1e-12 of `scale` (responses come
/// from an exact discretisation: the error is the matrix exponential's, a few ε per step).
fn follows(r: &TimeResponse, scale: f64, f: impl Fn(f64) -> f64) -> bool {
    r.y[0]
        .iter()
        .zip(&r.t)
        .all(|(y, &t)| y.is_finite() && (y - f(t)).abs() <= 1e-12 * scale * (1.0 + t) + 1e-300)
}

cases! {
    // Polynomials: coefficients must be finite; the roots of a polynomial evaluate to ~0
    // relative to the size of its terms.
    polynomials ["Polynomial::new", "Polynomial::constant", "Polynomial::s", "Polynomial::coeffs", "Polynomial::degree",
        "Polynomial::is_zero", "Polynomial::leading", "Polynomial::coeff", "Polynomial::norm_inf", "Polynomial::eval",
        "Polynomial::derivative", "Polynomial::add", "Polynomial::sub", "Polynomial::mul", "Polynomial::from_roots"] {
        for x in hostile() {
            err_or(Polynomial::new(&[1.0, x, 1.0]), "Polynomial::new", |p| p.coeffs().iter().all(|c| c.is_finite()));
        }
        // The empty coefficient list is the zero polynomial (documented), not an error.
        assert!(Polynomial::new(&[]).is_ok_and(|p| p.is_zero()));
        let p = Polynomial::new(&[1.0, -3.0, 2.0]).unwrap();
        assert_eq!((p.degree(), p.leading(), p.coeff(0)), (2, 1.0, 2.0));
        assert!(!p.is_zero() && Polynomial::constant(0.0).is_zero() && Polynomial::s().degree() == 1);
        assert_eq!(p.norm_inf(), 3.0);
        assert_eq!(p.eval(1.0), 0.0);
        assert_eq!(p.derivative().unwrap().coeffs(), &[2.0, -3.0]);
        assert!(p.add(&p).and_then(|q| q.sub(&p)).and_then(|q| q.mul(&Polynomial::s())).unwrap().degree() == 3);
        err_or(Polynomial::from_roots(&[Complex64::new(1.0, 0.0), Complex64::new(2.0, 0.0)]), "from_roots", |q| q.coeffs() == p.coeffs());
        refused(Polynomial::from_roots(&[Complex64::new(f64::NAN, 0.0)]), "from_roots(NaN)");
    }

    // Transfer functions, zero–pole–gain and state-space constructors validate their input
    // (NaN, zero denominators, mismatched dimensions, negative delays).
    constructors ["TransferFunction::new", "TransferFunction::gain", "TransferFunction::with_delay", "TransferFunction::num",
        "TransferFunction::den", "TransferFunction::delay", "TransferFunction::relative_degree", "TransferFunction::is_proper",
        "TransferFunction::is_strictly_proper", "Zpk::new", "Zpk::with_delay", "Zpk::zeros", "Zpk::poles", "Zpk::gain",
        "Zpk::delay", "StateSpace::new", "StateSpace::from_rows", "StateSpace::a", "StateSpace::b", "StateSpace::c",
        "StateSpace::d", "StateSpace::n_states", "StateSpace::n_inputs", "StateSpace::n_outputs", "Sdof::new",
        "Sdof::natural_frequency", "Sdof::damping_ratio", "logspace"] {
        for x in hostile() {
            err_or(TransferFunction::new(&[1.0], &[1.0, x]), "TransferFunction::new", |g| g.den().coeffs().iter().all(|c| c.is_finite()));
            err_or(TransferFunction::gain(x), "TransferFunction::gain", |g| g.num().coeffs()[0].is_finite());
            err_or(TransferFunction::new(&[1.0], &[1.0, 1.0]).unwrap().with_delay(x), "with_delay", |g| g.delay().is_finite() && g.delay() >= 0.0);
            err_or(Zpk::new(vec![], vec![Complex64::new(x, 0.0)], 1.0), "Zpk::new", |z| z.poles().iter().all(|p| p.is_finite()));
            err_or(Zpk::new(vec![], vec![], x), "Zpk::new(gain)", |z| z.gain().is_finite() && z.zeros().is_empty());
            err_or(Zpk::new(vec![], vec![], 1.0).unwrap().with_delay(x), "Zpk::with_delay", |z| z.delay().is_finite() && z.delay() >= 0.0);
            err_or(Sdof::new(1.0, x, 4.0), "Sdof::new", |s| s.natural_frequency().is_finite() && s.damping_ratio().is_none_or(|z| z.is_finite()));
            err_or(StateSpace::from_rows(&[&[x]], &[&[1.0]], &[&[1.0]], &[&[0.0]]), "StateSpace::from_rows", |s| s.a()[(0, 0)].is_finite());
            // 10^x underflows to 0 for x ≤ −324: the correctly rounded value, so ≥ 0.
            err_or(logspace(x, 1.0, 10), "logspace", |w| w.iter().all(|c| c.is_finite() && *c >= 0.0));
        }
        refused(TransferFunction::new(&[1.0], &[0.0]), "TransferFunction::new(zero denominator)");
        let g = TransferFunction::new(&[1.0, 0.0], &[1.0, 2.0, 1.0]).unwrap();
        assert!(g.is_proper() && g.is_strictly_proper() && g.relative_degree() == 1);
        refused(StateSpace::new(DMatrix::zeros(2, 2), DMatrix::zeros(3, 1), DMatrix::zeros(1, 2), DMatrix::zeros(1, 1)), "StateSpace::new(mismatched)");
        let s = StateSpace::from_rows(&[&[0.0, 1.0], &[-1.0, 0.0]], &[&[0.0], &[1.0]], &[&[1.0, 0.0]], &[&[0.0]]).unwrap();
        assert_eq!((s.n_states(), s.n_inputs(), s.n_outputs()), (2, 1, 1));
        assert!(s.b().iter().chain(s.c().iter()).chain(s.d().iter()).all(|c| c.is_finite()));
        refused(logspace(0.0, 1.0, 0), "logspace(n = 0)");
    }

    // Roots, trimming and scaling of polynomials: every root evaluates to ~0 relative to the
    // size of the terms (on the reversed polynomial beyond |r| = 1), complex roots come in
    // exact pairs; trim drops only leading coefficients ≤ rtol·max|c| (none for a NaN rtol: no
    // comparison holds); p(s) at complex points equals the test's Horner sum.
    polynomial_roots_and_scaling ["Polynomial::eval_c", "Polynomial::monic", "Polynomial::roots",
        "Polynomial::scale", "Polynomial::scale_variable", "Polynomial::trim", "Polynomial::zero_roots"] {
        for x in hostile() {
            let (Ok(p), Ok(q)) = (Polynomial::new(&[1.0, x, -2.0]), Polynomial::new(&[x, 1.0, 1.0])) else {
                continue;
            };
            for r in [&p, &q] {
                // normwise: the roots of the companion matrix are exact for coefficients perturbed
                // by ε·max|c| (a middle coefficient of 1e300 swamps the constant term)
                let normwise = |z: &Complex64| {
                    let size: Vec<f64> = r.coeffs().iter().map(|_| r.norm_inf()).collect();
                    let (v, _) = horner(r.coeffs(), *z);
                    let (_, b) = horner(&size, *z);
                    is_root(r.coeffs(), *z, 64.0) || v.norm() <= 64.0 * EPS * b
                };
                err_or(r.roots(), "roots", |z| z.len() == r.degree() && z.iter().all(normwise) && paired(z));
                for rtol in hostile() {
                    let t = r.trim(rtol);
                    let k = r.coeffs().len() - t.coeffs().len();
                    assert!(
                        r.coeffs().ends_with(t.coeffs()) && r.coeffs()[..k].iter().all(|c| c.abs() <= rtol * r.norm_inf()),
                        "trim({rtol}) of {r:?}: {t:?}"
                    );
                }
                for s in points() {
                    let got = r.eval_c(s);
                    let (want, b) = horner(r.coeffs(), s);
                    if finite_c(want) && b.is_finite() {
                        assert!((got - want).norm() <= 16.0 * EPS * b + 1e-300, "eval_c({s}) of {r:?}: {got} ≠ {want}");
                    } else if !nan_c(s) {
                        assert!(!nan_c(got), "eval_c({s}) of {r:?}: NaN");
                    }
                    if s.im == 0.0 && !s.re.is_nan() {
                        let got = r.eval(s.re);
                        if want.re.is_finite() && b.is_finite() {
                            assert!((got - want.re).abs() <= 16.0 * EPS * b + 1e-300, "eval({}) of {r:?}: {got} ≠ {}", s.re, want.re);
                        } else {
                            assert!(!got.is_nan(), "eval({}) of {r:?}: NaN", s.re);
                        }
                    }
                }
            }
            let l = q.leading();
            err_or(q.monic(), "monic", |m| {
                m.leading() == 1.0
                    && m.degree() == q.degree()
                    && (0..=q.degree()).all(|k| (m.coeff(k) * l - q.coeff(k)).abs() <= 4.0 * EPS * q.coeff(k).abs())
            });
            for a in hostile() {
                err_or(q.scale(a), "Polynomial::scale", |r| (0..=q.degree()).all(|k| r.coeff(k) == a * q.coeff(k)));
                // p(a·s) at s = ½ is p at a/2, to the size of the terms
                err_or(q.scale_variable(a), "scale_variable", |r| {
                    let (want, b) = horner(q.coeffs(), c(0.5 * a, 0.0));
                    r.coeffs().iter().all(|c| c.is_finite())
                        && (!b.is_finite() || (r.eval(0.5) - want.re).abs() <= 16.0 * EPS * b + 1e-300)
                });
            }
            if let Ok(sq) = q.mul(&Polynomial::s()).and_then(|r| r.mul(&Polynomial::s())) {
                assert_eq!((sq.zero_roots(), q.zero_roots()), (2, 0));
            }
        }
        refused(Polynomial::constant(0.0).roots(), "roots of the zero polynomial");
        refused(Polynomial::constant(0.0).monic(), "monic zero polynomial");
        refused(Polynomial::s().scale(f64::NAN), "scale(NaN)");
        refused(Polynomial::s().scale_variable(f64::INFINITY), "scale_variable(∞)");
        assert_eq!(Polynomial::constant(0.0).zero_roots(), 0);
        // the whole f64 range in one polynomial: roots ≈ ±1e-150j
        let wide = Polynomial::new(&[1e300, 0.0, 1.0]).unwrap();
        err_or(wide.roots(), "roots(1e300 s² + 1)", |z| z.iter().all(|z| is_root(wide.coeffs(), *z, 64.0)) && paired(z));
        // s + 1e300 at −1e300 + j is j exactly: in 1/s the sum 1e300·(1/s) + 1 cancels to 0
        let big_root = Polynomial::new(&[1.0, 1e300]).unwrap();
        assert_eq!(big_root.eval_c(c(-1e300, 1.0)), c(0.0, 1.0));
        // s² + 3s + f64::MAX: scaling by σⁿ would overflow the leading coefficient
        let top = Polynomial::new(&[1.0, 3.0, f64::MAX]).unwrap();
        err_or(top.roots(), "roots(s² + 3s + MAX)", |z| z.iter().all(|z| (z.im.abs() - f64::MAX.sqrt()).abs() <= 4.0 * EPS * f64::MAX.sqrt()) && paired(z));
    }

    // Transfer-function algebra: G(s) equals N(s)/D(s) by the test's Horner sums; poles and
    // zeros are roots of D and N; interconnections have the coefficients of the products and
    // sums (15.18.4); the DC gain is N(0)/D(0) or absent, never ∞.
    transfer_function_algebra ["TransferFunction::from_polynomials", "TransferFunction::eval", "TransferFunction::poles",
        "TransferFunction::zeros", "TransferFunction::dc_gain", "TransferFunction::to_zpk", "TransferFunction::neg",
        "TransferFunction::scale", "TransferFunction::series", "TransferFunction::parallel", "TransferFunction::feedback",
        "TransferFunction::sensitivity", "TransferFunction::time_scaled", "TransferFunction::minreal"] {
        refused(TransferFunction::from_polynomials(Polynomial::s(), Polynomial::constant(0.0)), "from_polynomials(N, 0)");
        for x in hostile() {
            let (Ok(n), Ok(d)) = (Polynomial::new(&[1.0, x]), Polynomial::new(&[x, 3.0, 2.0])) else { continue };
            let g = TransferFunction::from_polynomials(n, d).unwrap();
            let h = tf(&[1.0], &[1.0, x]);
            let (nc, dc) = (g.num().coeffs().to_vec(), g.den().coeffs().to_vec());
            for s in points() {
                assert_tf_value(&nc, &dc, s, g.eval(s), 64.0, "TransferFunction::eval");
                assert_tf_value(&[1.0], &[1.0, x], s, h.eval(s), 64.0, "TransferFunction::eval(h)");
            }
            err_or(g.poles(), "poles", |p| p.len() == g.den().degree() && p.iter().all(|z| is_root(&dc, *z, 64.0)));
            err_or(g.zeros(), "zeros", |z| z.len() == 1 && z.iter().all(|z| is_root(&nc, *z, 64.0)));
            for k in [&g, &h, &tf(&[1.0, x], &[1.0, 1e-300]), &tf(&[x], &[1.0, 0.0])] {
                let (n0, d0) = (k.num().coeff(0), k.den().coeff(0));
                none_or(k.dc_gain(), "dc_gain", |v| v.is_finite() && (d0 == 0.0 || (v - n0 / d0).abs() <= 2.0 * EPS * v.abs()));
            }
            err_or(g.to_zpk(), "to_zpk", |z| {
                z.gain() == g.num().leading() / g.den().leading()
                    && z.zeros().iter().all(|r| is_root(&nc, *r, 64.0))
                    && z.poles().iter().all(|r| is_root(&dc, *r, 64.0))
            });
            let m = g.neg();
            assert!((0..=1).all(|k| m.num().coeff(k) == -g.num().coeff(k)) && m.den() == g.den());
            for a in hostile() {
                err_or(g.scale(a), "TransferFunction::scale", |r| (0..=1).all(|k| r.num().coeff(k) == a * g.num().coeff(k)) && r.den() == g.den());
            }
            let (sn, sb) = conv(&nc, &[1.0]);
            let (sd, sdb) = conv(&dc, &[1.0, x]);
            err_or(g.series(&h), "series", |r| poly_is(r.num(), &sn, &sb) && poly_is(r.den(), &sd, &sdb));
            // N₁D₂ + N₂D₁ over D₁D₂
            let (a1, b1) = conv(&nc, &[1.0, x]);
            let (a2, b2) = conv(&[1.0], &dc);
            err_or(g.parallel(&h), "parallel", |r| poly_is(r.num(), &add(&a1, &a2), &add(&b1, &b2)) && poly_is(r.den(), &sd, &sdb));
            // G/(1 + GH) = N_g D_h/(D_g D_h + N_g N_h)
            let (fn_, fnb) = conv(&nc, &[1.0, x]);
            let (e1, f1) = conv(&dc, &[1.0, x]);
            let (e2, f2) = conv(&nc, &[1.0]);
            err_or(g.feedback(&h), "feedback", |r| poly_is(r.num(), &fn_, &fnb) && poly_is(r.den(), &add(&e1, &e2), &add(&f1, &f2)));
            // S = D/(D + N)
            let sum = add(&dc, &nc);
            let sumb = add(&dc.iter().map(|v| v.abs()).collect::<Vec<_>>(), &nc.iter().map(|v| v.abs()).collect::<Vec<_>>());
            let dcb: Vec<f64> = dc.iter().map(|v| v.abs()).collect();
            err_or(g.sensitivity(), "sensitivity", |r| poly_is(r.num(), &dc, &dcb) && poly_is(r.den(), &sum, &sumb));
            // G_a(a·s) = G(s): time a times faster, delay τ/a; N and D keep their degrees
            let delayed = g.clone().with_delay(2.0).unwrap();
            for a in hostile() {
                err_or(delayed.time_scaled(a), "time_scaled", |r| {
                    let s0 = c(0.3, 0.7);
                    let (want, got) = (delayed.eval(s0), r.eval(s0 * a));
                    assert_eq!((r.num().degree(), r.den().degree()), (g.num().degree(), g.den().degree()), "time_scaled({a}) of {g}: {r}");
                    assert!(r.delay() == 2.0 / a, "time_scaled({a}): delay {}", r.delay());
                    assert!(!(x.abs() <= 1e6 && (1e-6..=1e6).contains(&a)) || (got - want).norm() <= 1e-12 * want.norm(), "time_scaled({a}) of {g}: {got} ≠ {want}");
                    true
                });
            }
            for tol in hostile() {
                let cancel = tf(&[1.0, 1.0], &[1.0, 3.0, 2.0]);
                err_or(cancel.minreal(tol), "minreal", |r| {
                    let s0 = c(0.3, 0.7);
                    r.den().degree() <= 2
                        && 2 - r.den().degree() == 1 - r.num().degree().min(1)
                        && (tol > 1e-9 || (r.eval(s0) - cancel.eval(s0)).norm() <= 1e-9)
                });
            }
        }
        refused(tf(&[1.0], &[1.0, 1.0]).minreal(f64::NAN), "minreal(NaN)");
        refused(tf(&[1.0], &[1.0, 1.0]).minreal(-1.0), "minreal(−1)");
        refused(tf(&[1.0], &[1.0, 1.0]).with_delay(1.0).unwrap().parallel(&tf(&[1.0], &[1.0, 2.0])), "parallel with different delays");
        refused(tf(&[1.0], &[1.0, 1.0]).with_delay(1.0).unwrap().feedback(&tf(&[1.0], &[1.0])), "feedback with a delay");
        refused(TransferFunction::gain(1.0).unwrap().feedback(&TransferFunction::gain(-1.0).unwrap()), "1 + GH ≡ 0");
        refused(tf(&[1.0], &[1.0, 1.0]).time_scaled(0.0), "time_scaled(0)");
        // a pole at 0 has no DC gain; a removable one has
        assert_eq!(tf(&[1.0], &[1.0, 0.0]).dc_gain(), None);
        assert!(tf(&[1.0, 0.0], &[1.0, 2.0, 0.0]).dc_gain().is_some_and(|v| (v - 0.5).abs() <= 4.0 * EPS));
    }

    // Zero–pole–gain form: G(s) equals k∏(s − zᵢ)/∏(s − pᵢ) by the test's own product, the
    // phase is the argument of G(jω) modulo 360°, minreal removes equal numbers of zeros and
    // poles (none for a NaN tolerance), to_tf has the zeros and poles as roots.
    zpk_evaluation ["Zpk::eval", "Zpk::magnitude", "Zpk::phase_deg", "Zpk::minreal", "Zpk::to_tf", "Zpk::freqresp",
        "Zpk::bode"] {
        for x in hostile() {
            let Ok(z) = Zpk::new(vec![c(x, 0.0)], vec![c(-1.0, 1.0), c(-1.0, -1.0), c(0.0, 0.0), c(x, 0.0)], 2.0) else { continue };
            let Ok(g) = Zpk::new(vec![c(-1.0, 0.0)], vec![c(x, 0.0), c(-2.0, 0.0)], -3.0) else { continue };
            for zp in [&z, &g] {
                let product = |s: Complex64| {
                    let num = zp.zeros().iter().fold(c(zp.gain(), 0.0), |acc, r| acc * (s - r));
                    zp.poles().iter().fold(num, |acc, p| acc * inv(s - p))
                };
                for s in points() {
                    if nan_c(s) {
                        continue;
                    }
                    let (got, want) = (zp.eval(s), product(s));
                    if finite_c(want) && want.norm() > 1e-280 && want.norm() < 1e280 {
                        assert!((got - want).norm() <= 64.0 * EPS * want.norm(), "Zpk::eval({s}) of {zp:?}: {got} ≠ {want}");
                    } else {
                        assert!(!nan_c(got), "Zpk::eval({s}) of {zp:?}: NaN");
                    }
                }
                let omega: Vec<f64> = hostile().filter(|w| w.is_finite() && *w >= 0.0).chain([0.5, 1.0, 3.0]).collect();
                for &w in &omega {
                    let want = product(c(0.0, w));
                    let (mag, ph) = (zp.magnitude(w), zp.phase_deg(w));
                    assert!(!mag.is_nan() && mag >= 0.0 && ph.is_finite(), "magnitude/phase at {w}: {mag}, {ph}");
                    if finite_c(want) && want.norm() > 1e-280 && want.norm() < 1e280 {
                        assert!((mag - want.norm()).abs() <= 64.0 * EPS * want.norm(), "magnitude({w})");
                        assert!(wrap_deg(ph - want.arg().to_degrees()).abs() <= 1e-9, "phase_deg({w}) = {ph}, arg = {}", want.arg().to_degrees());
                    }
                }
                for f in [zp.freqresp(&omega).map(|r| (r, None)), zp.bode(&omega).map(|b| (b.response.clone(), Some(b)))] {
                    err_or(f, "Zpk::freqresp/bode", |(r, b)| {
                        r.len() == omega.len()
                            && r.iter().zip(&omega).all(|(g, &w)| {
                                let want = product(c(0.0, w));
                                !nan_c(*g) && (!(finite_c(want) && want.norm() > 1e-280 && want.norm() < 1e280) || (g - want).norm() <= 64.0 * EPS * want.norm())
                            })
                            && b.as_ref().is_none_or(|b| {
                                b.magnitude_db.iter().zip(&b.response).all(|(m, g)| !m.is_nan() && (!(g.norm() > 1e-280 && g.norm() < 1e280) || (m - 20.0 * g.norm().log10()).abs() <= 1e-9))
                                    && b.phase_deg.iter().zip(&b.response).all(|(p, g)| p.is_finite() && (!(g.norm() > 1e-280 && finite_c(*g)) || wrap_deg(p - g.arg().to_degrees()).abs() <= 1e-9))
                            })
                    });
                }
                for tol in hostile() {
                    let r = zp.minreal(tol);
                    let gone = |a: &[Complex64], b: &[Complex64]| b.iter().all(|v| a.contains(v)) && a.len() >= b.len();
                    assert!(
                        gone(zp.zeros(), r.zeros())
                            && gone(zp.poles(), r.poles())
                            && zp.zeros().len() - r.zeros().len() == zp.poles().len() - r.poles().len()
                            && r.gain() == zp.gain()
                            && (!tol.is_nan() || r == *zp),
                        "Zpk::minreal({tol}) of {zp:?}: {r:?}"
                    );
                }
                err_or(zp.to_tf(), "Zpk::to_tf", |t| {
                    t.den().leading() == 1.0
                        && t.num().leading() == zp.gain()
                        && t.den().degree() == zp.poles().len()
                        && zp.zeros().iter().all(|r| is_root(t.num().coeffs(), *r, 64.0))
                        && zp.poles().iter().all(|r| is_root(t.den().coeffs(), *r, 64.0))
                });
            }
        }
        let z = Zpk::new(vec![c(-1.0, 0.0)], vec![c(-1.0, 0.0), c(-2.0, 0.0)], 1.0).unwrap();
        assert_eq!(z.minreal(0.0).poles(), &[c(-2.0, 0.0)]);
        for bad in [-1.0, f64::NAN, f64::INFINITY] {
            refused(z.freqresp(&[1.0, bad]), "Zpk::freqresp(bad ω)");
            refused(z.bode(&[bad]), "Zpk::bode(bad ω)");
        }
        assert!(z.freqresp(&[]).is_ok_and(|r| r.is_empty()));
        // an imaginary-axis pole: infinite, not NaN
        let axis = Zpk::new(vec![], vec![c(0.0, 1.0), c(0.0, -1.0)], 1.0).unwrap();
        assert!(!nan_c(axis.eval(c(0.0, 1.0))) && axis.magnitude(1.0) == f64::INFINITY);
    }

    // Frequency response from the coefficients: G(jω) equals the test's N(jω)/D(jω) to the
    // size of the terms, dB and phase are 20 log₁₀|G| and arg G; Nyquist counts N = Z − P with
    // Z and P from the roots; a state-space channel's response is C(jωI − A)⁻¹B + D.
    frequency_response ["TransferFunction::freqresp", "TransferFunction::bode", "TransferFunction::nyquist",
        "StateSpace::bode"] {
        let omega: Vec<f64> = hostile().filter(|w| w.is_finite() && *w >= 0.0).chain([0.5, 1.0, 3.0]).collect();
        for x in hostile() {
            for g in [TransferFunction::new(&[1.0, x], &[1.0, 3.0, 2.0]), TransferFunction::new(&[1.0], &[1.0, x, 1.0]), TransferFunction::new(&[x, 1.0], &[1.0, 0.0, 1.0])] {
                let Ok(g) = g else { continue };
                let (nc, dc) = (g.num().coeffs().to_vec(), g.den().coeffs().to_vec());
                err_or(g.freqresp(&omega), "freqresp", |r| {
                    r.iter().zip(&omega).for_each(|(v, &w)| assert_tf_value(&nc, &dc, c(0.0, w), *v, 64.0, "freqresp"));
                    r.len() == omega.len()
                });
                err_or(g.bode(&omega), "bode", |b| {
                    b.response.iter().zip(&omega).for_each(|(v, &w)| assert_tf_value(&nc, &dc, c(0.0, w), *v, 64.0, "bode"));
                    b.magnitude_db.iter().zip(&b.response).all(|(m, v)| !m.is_nan() && (!(v.norm() > 1e-280 && v.norm() < 1e280) || (m - 20.0 * v.norm().log10()).abs() <= 1e-9))
                        && b.phase_deg.iter().zip(&b.response).all(|(p, v)| p.is_finite() && (!(v.norm() > 1e-280 && finite_c(*v)) || wrap_deg(p - v.arg().to_degrees()).abs() <= 1e-9))
                });
                for n in [0, 1, 16, usize::MAX] {
                    err_or(g.nyquist(n), "nyquist", |q| {
                        let rhp = |p: &Polynomial| p.roots().unwrap().iter().filter(|z| z.re > 1e-9 * z.norm().max(1.0)).count();
                        let closed = Polynomial::new(&add(&dc, &nc)).unwrap();
                        q.encirclements == q.closed_loop_rhp as isize - q.open_loop_rhp as isize
                            && q.open_loop_rhp == rhp(g.den())
                            && q.closed_loop_rhp == rhp(&closed)
                            && q.contour.len() == q.positive.len()
                            && q.contour.iter().all(|s| finite_c(*s) && s.re >= 0.0)
                            && q.positive.iter().all(|v| !nan_c(*v))
                    });
                }
            }
            let Ok(sys) = StateSpace::from_rows(&[&[0.0, 1.0], &[-x, -1.0]], &[&[0.0], &[1.0]], &[&[1.0, 0.0]], &[&[0.0]]) else { continue };
            err_or(sys.bode(0, 0, &omega), "StateSpace::bode", |b| {
                b.response.iter().zip(&omega).all(|(v, &w)| {
                    let want = ss_at(&sys, c(0.0, w));
                    !nan_c(*v) && (x.abs() > 1e6 || want.is_none_or(|want| (v - want).norm() <= 1e-9 * want.norm()))
                })
            });
            refused(sys.bode(1, 0, &omega), "StateSpace::bode(bad output)");
            refused(sys.bode(0, 1, &omega), "StateSpace::bode(bad input)");
        }
        let g = tf(&[1.0], &[1.0, 1.0]);
        refused(g.freqresp(&[-1.0]), "freqresp(−1)");
        refused(g.bode(&[f64::NAN]), "bode(NaN)");
        refused(g.clone().with_delay(1.0).unwrap().nyquist(16), "nyquist with a delay");
        refused(tf(&[1.0, 0.0, 0.0], &[1.0, 1.0]).nyquist(16), "nyquist of an improper loop");
        refused(tf(&[1.0], &[1.0, 0.0, 0.0]).nyquist(16), "−1 on the Nyquist plot");
        assert!(g.freqresp(&[]).is_ok_and(|r| r.is_empty()));
    }

    // State-space structure: poles sum to the trace; the transfer function of a channel is
    // C(sI − A)⁻¹B + D by the test's complex LU; the companion realisation reproduces G; the
    // Krylov matrices are [B AB], [C; CA]; equilibria satisfy [A B]v = 0; placed poles have
    // the requested trace and determinant.
    state_space_structure ["StateSpace::poles", "StateSpace::channel", "StateSpace::to_tf", "StateSpace::from_tf",
        "StateSpace::companion", "StateSpace::ctrb", "StateSpace::obsv", "StateSpace::is_controllable",
        "StateSpace::is_observable", "StateSpace::minreal", "StateSpace::series", "StateSpace::parallel",
        "StateSpace::unity_feedback", "StateSpace::equilibria", "StateSpace::place", "affine_equilibria"] {
        let s0 = c(0.3, 0.7);
        for x in hostile() {
            let Ok(sys) = StateSpace::from_rows(&[&[0.0, 1.0], &[-2.0, x]], &[&[0.0], &[1.0]], &[&[1.0, 0.0]], &[&[0.0]]) else { continue };
            let scale = x.abs().max(2.0);
            err_or(sys.poles(), "StateSpace::poles", |p| {
                p.len() == 2 && paired(p) && (p[0] + p[1] - x).norm() <= 64.0 * EPS * scale.max(p[0].norm()).max(p[1].norm())
            });
            assert!(sys.channel(0, 0).is_ok_and(|ch| ch.n_inputs() == 1 && ch.n_outputs() == 1));
            refused(sys.channel(1, 0), "channel(bad output)");
            refused(sys.channel(0, 1), "channel(bad input)");
            refused(sys.to_tf(0, 3), "to_tf(bad input)");
            // det(sI − A) = s² − x s + 2 to ε‖A‖ᵏ per coefficient (backward stability)
            err_or(sys.to_tf(0, 0), "StateSpace::to_tf", |g| {
                let tol = |k: i32| 256.0 * EPS * scale.powi(k);
                let l = g.den().leading();
                g.den().degree() == 2
                    && (g.den().coeff(1) / l + x).abs() <= tol(1)
                    && (g.den().coeff(0) / l - 2.0).abs() <= tol(2)
                    && (g.num().coeff(0) / l - 1.0).abs() <= tol(2)
            });
            assert_eq!(sys.ctrb(), DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 1.0, x]));
            assert_eq!(sys.obsv(), DMatrix::identity(2, 2));
            for rtol in hostile() {
                for r in [sys.is_controllable(rtol), sys.is_observable(rtol)] {
                    if rtol.is_nan() || rtol < 0.0 || rtol.is_infinite() {
                        refused(r, "controllable/observable(bad rtol)");
                    } else if x.abs() <= 1.0 {
                        // singular values of [B AB] and [C; CA] lie in [0.6, 1.7]
                        assert_eq!(r, Ok(rtol < 0.3), "rank test at rtol {rtol}");
                    }
                }
            }
            for rtol in hostile() {
                err_or(sys.equilibria(rtol), "equilibria", |v| {
                    let ab = DMatrix::from_row_slice(2, 3, &[0.0, 1.0, 0.0, -2.0, x, 1.0]);
                    let vtv = v.transpose() * v;
                    (0.0..1.0).contains(&rtol)
                        && v.iter().all(|e| e.is_finite())
                        && (&ab * v).norm() <= 64.0 * EPS * ab.norm()
                        && (vtv - DMatrix::identity(v.ncols(), v.ncols())).norm() <= 64.0 * EPS
                });
            }
            refused(sys.place(1, &[c(-1.0, 0.0), c(-2.0, 0.0)]), "place(bad input)");
            refused(sys.place(0, &[c(-1.0, 0.0)]), "place(wrong count)");
            refused(sys.place(0, &[c(-1.0, 1.0), c(-1.0, 2.0)]), "place(unpaired)");
            for y in hostile() {
                // A − bK = [[0, 1], [−2 − k₀, x − k₁]]: trace x − k₁ = y − 1, det 2 + k₀ = −y
                err_or(sys.place(0, &[c(y, 0.0), c(-1.0, 0.0)]), "place", |k| {
                    let (k0, k1) = (k[(0, 0)], k[(0, 1)]);
                    k.iter().all(|v| v.is_finite())
                        && (x - k1 - (y - 1.0)).abs() <= 64.0 * EPS * (x.abs() + k1.abs() + y.abs() + 1.0)
                        && (2.0 + k0 + y).abs() <= 64.0 * EPS * (2.0 + k0.abs() + y.abs())
                });
            }
            // G = x/(s + 1) as 1-state systems in series and parallel
            let one = |g: f64| StateSpace::from_rows(&[&[-1.0]], &[&[1.0]], &[&[g]], &[&[0.0]]);
            if let (Ok(a), Ok(b)) = (one(x), one(2.0)) {
                let (ga, gb) = (ss_at(&a, s0), ss_at(&b, s0));
                err_or(a.series(&b), "StateSpace::series", |r| {
                    r.n_states() == 2 && (x.abs() > 1e100 || ss_at(r, s0).zip(ga.zip(gb)).is_none_or(|(v, (p, q))| (v - p * q).norm() <= 1e-12 * (p * q).norm() + 1e-300))
                });
                err_or(a.parallel(&b), "StateSpace::parallel", |r| {
                    r.n_states() == 2 && (x.abs() > 1e100 || ss_at(r, s0).zip(ga.zip(gb)).is_none_or(|(v, (p, q))| (v - p - q).norm() <= 1e-12 * (p.norm() + q.norm()) + 1e-300))
                });
                err_or(a.unity_feedback(), "unity_feedback", |r| r.a()[(0, 0)] == -1.0 - x && r.b() == a.b() && r.c() == a.c());
            }
            for a0 in [vec![x], vec![x, 3.0], vec![]] {
                err_or(StateSpace::companion(&a0, 1.0), "companion", |s| {
                    let n = a0.len();
                    (0..n).all(|j| s.a()[(n - 1, j)] == -a0[j]) && s.b()[(n - 1, 0)] == 1.0 && s.c()[(0, 0)] == 1.0 && s.d()[(0, 0)] == 0.0
                });
            }
            for g in [TransferFunction::new(&[1.0, x], &[1.0, 3.0, 2.0]), TransferFunction::new(&[x, 1.0, 1.0], &[1.0, 3.0, 2.0])] {
                let Ok(g) = g else { continue };
                err_or(StateSpace::from_tf(&g), "from_tf", |r| {
                    r.n_states() == 2
                        && (x.abs() > 1e6 || ss_at(r, s0).is_some_and(|v| (v - g.eval(s0)).norm() <= 1e-12 * g.eval(s0).norm().max(1.0)))
                });
            }
            err_or(affine_equilibria(&DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 0.0, x]), &[1.0, 1.0], 0.0), "affine_equilibria", |e| match e {
                AffineEquilibria::Unique(v) => v.iter().all(|c| c.is_finite()) && (v[0] + 1.0).abs() <= 4.0 * EPS && (v[1] * x + 1.0).abs() <= 4.0 * EPS,
                AffineEquilibria::Family { particular, directions } => particular.iter().chain(directions.iter()).all(|c| c.is_finite()) && x == 0.0,
                AffineEquilibria::None => x.abs() < f64::MIN_POSITIVE,
            });
            for rtol in hostile() {
                err_or(affine_equilibria(&DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 0.0, x]), &[1.0, x], rtol), "affine_equilibria(rtol)", |e| {
                    let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 0.0, x]);
                    let b = nalgebra::DVector::from_column_slice(&[1.0, x]);
                    (0.0..1.0).contains(&rtol)
                        && match e {
                            AffineEquilibria::Unique(v) => v.iter().all(|c| c.is_finite()) && (&a * v + &b).norm() <= 1e-9 * b.norm(),
                            AffineEquilibria::Family { particular, directions } => {
                                particular.iter().chain(directions.iter()).all(|c| c.is_finite())
                                    && (&a * particular + &b).norm() <= 1e-9 * b.norm()
                                    && (&a * directions).norm() <= 1e-9 * a.norm().max(1.0)
                            }
                            AffineEquilibria::None => true,
                        }
                });
            }
        }
        refused(affine_equilibria(&DMatrix::zeros(2, 3), &[1.0, 1.0], 0.0), "affine_equilibria(non-square)");
        refused(affine_equilibria(&DMatrix::zeros(2, 2), &[1.0], 0.0), "affine_equilibria(short b)");
        refused(affine_equilibria(&DMatrix::zeros(1, 1), &[f64::NAN], 0.0), "affine_equilibria(NaN b)");
        assert_eq!(affine_equilibria(&DMatrix::zeros(1, 1), &[1.0], 1e-12), Ok(AffineEquilibria::None));
        let two = StateSpace::new(DMatrix::zeros(1, 1), DMatrix::zeros(1, 2), DMatrix::zeros(2, 1), DMatrix::zeros(2, 2)).unwrap();
        refused(two.minreal(1e-9), "minreal of a MIMO model");
        refused(two.series(&first_order()), "series(mismatched)");
        refused(two.parallel(&first_order()), "parallel(mismatched)");
        refused(StateSpace::from_rows(&[&[-1.0]], &[&[1.0]], &[&[1.0]], &[&[1.0]]).unwrap().unity_feedback(), "unity_feedback(D ≠ 0)");
        refused(first_order().place(0, &[c(f64::NAN, 0.0)]), "place(NaN)");
        let uncontrollable = StateSpace::from_rows(&[&[-1.0, 0.0], &[0.0, -2.0]], &[&[1.0], &[0.0]], &[&[1.0, 1.0]], &[&[0.0]]).unwrap();
        refused(uncontrollable.place(0, &[c(-3.0, 0.0), c(-4.0, 0.0)]), "place(uncontrollable)");
        assert_eq!(uncontrollable.is_controllable(1e-12), Ok(false));
        let cancel = StateSpace::from_tf(&tf(&[1.0, 1.0], &[1.0, 3.0, 2.0])).unwrap();
        err_or(cancel.minreal(1e-9), "StateSpace::minreal", |r| {
            r.n_states() == 1 && ss_at(r, s0).is_some_and(|v| (v - 1.0 / (s0 + 2.0)).norm() <= 1e-9)
        });
        refused(StateSpace::from_tf(&tf(&[1.0, 0.0, 0.0], &[1.0, 1.0])), "from_tf(improper)");
        refused(StateSpace::from_tf(&tf(&[1.0], &[1.0, 1.0]).with_delay(1.0).unwrap()), "from_tf(delay)");
        refused(StateSpace::companion(&[f64::NAN], 1.0), "companion(NaN)");
    }

    // Dense kernels: e^{diag(d)} = diag(eᵈ) and e^{[[0, x], [0, 0]]} = [[1, x], [0, 1]] (or
    // Overflow); eigenvalues sum to the trace; balancing keeps the diagonal and every product
    // aᵢⱼaⱼᵢ; Σσᵢ² = ‖A‖_F²; the rank counts σ > rtol·σ_max; modes of λ have ωn = |λ|,
    // ζ = −Re λ/|λ| ∈ [−1, 1] and finite optional fields.
    dense_kernels ["expm", "linalg::balance", "linalg::eigenvalues", "linalg::singular_values", "linalg::rank", "modes",
        "Mode::of"] {
        for x in hostile() {
            let diag = DMatrix::from_row_slice(2, 2, &[x, 0.0, 0.0, -1.0]);
            let ok_diag = |e: &DMatrix<f64>| {
                let want = [x.exp(), (-1.0f64).exp()];
                e.iter().all(|v| v.is_finite())
                    && e[(0, 1)] == 0.0
                    && e[(1, 0)] == 0.0
                    && (0..2).all(|i| (e[(i, i)] - want[i]).abs() <= 1e-13 * want[i])
            };
            if x.is_finite() {
                err_or(expm(&diag), "expm(diag)", ok_diag);
                err_or(expm(&DMatrix::from_row_slice(2, 2, &[0.0, x, 0.0, 0.0])), "expm(nilpotent)", |e| {
                    e[(0, 0)] == 1.0 && e[(1, 1)] == 1.0 && e[(1, 0)] == 0.0 && (e[(0, 1)] - x).abs() <= 4.0 * EPS * x.abs() + 1e-307
                });
                err_or(expm(&DMatrix::from_row_slice(2, 2, &[0.0, x, -x, 0.0])), "expm(rotation)", |e| {
                    // a rotation by x: orthogonal with det 1 (exactly cos x, sin x for moderate x)
                    let r = e.transpose() * e;
                    e.iter().all(|v| v.is_finite())
                        && (r - DMatrix::identity(2, 2)).norm() <= 1e-9
                        && (x.abs() > 1e3 || ((e[(0, 0)] - x.cos()).abs() <= 1e-12 && (e[(0, 1)] - x.sin()).abs() <= 1e-12))
                });
            } else {
                refused(expm(&diag), "expm(non-finite)");
            }
            for a in [diag.clone(), DMatrix::from_row_slice(2, 2, &[x, 1.0, -1.0, 0.0]), DMatrix::from_row_slice(2, 2, &[x, x, x, x]), DMatrix::from_row_slice(3, 3, &[0.0, x, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0])] {
                if !x.is_finite() {
                    refused(eigenvalues(&a), "eigenvalues(non-finite)");
                    refused(balance(&a), "balance(non-finite)");
                    refused(singular_values(&a), "singular_values(non-finite)");
                    refused(modes(&a), "modes(non-finite)");
                    continue;
                }
                let big = a.iter().fold(0.0f64, |m, v| nan_max(m, v.abs()));
                let trace = a.trace();
                err_or(eigenvalues(&a), "eigenvalues", |ev| {
                    let size = ev.iter().fold(big, |m, z| nan_max(m, z.norm()));
                    ev.len() == a.nrows() && paired(ev) && (ev.iter().sum::<Complex64>() - trace).norm() <= 64.0 * EPS * size * a.nrows() as f64
                });
                err_or(balance(&a), "balance", |b| {
                    (0..a.nrows()).all(|i| b[(i, i)] == a[(i, i)])
                        && (0..a.nrows()).all(|i| (0..a.nrows()).all(|j| {
                            let (p, q) = (a[(i, j)] * a[(j, i)], b[(i, j)] * b[(j, i)]);
                            !(p.is_normal() && q.is_finite()) || (p - q).abs() <= 2.0 * EPS * p.abs()
                        }))
                });
                err_or(singular_values(&a), "singular_values", |s| {
                    let f = a.iter().map(|v| (v / big).powi(2)).sum::<f64>();
                    let g = s.iter().map(|v| (v / big).powi(2)).sum::<f64>();
                    s.len() == a.nrows() && s.windows(2).all(|w| w[0] >= w[1]) && s.iter().all(|v| v.is_finite() && *v >= 0.0) && (big == 0.0 || (f - g).abs() <= 1e-12 * f)
                });
                err_or(modes(&a), "modes", |m| {
                    m.len() == a.nrows() && m.iter().all(|m| m.damping_ratio.is_none_or(|z| (-1.0..=1.0).contains(&z)))
                });
            }
            for rtol in hostile() {
                let r = rank(&DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 0.0, x]), rtol);
                if rtol.is_nan() || rtol < 0.0 || rtol.is_infinite() || !x.is_finite() {
                    refused(r, "rank(bad rtol or entry)");
                } else {
                    let (top, low) = (x.abs().max(1.0), x.abs().min(1.0));
                    if low != 0.0 && low < f64::MIN_POSITIVE {
                        // a subnormal singular value is below the SVD's resolution: either count
                        continue;
                    }
                    let want = usize::from(top > rtol * top) + usize::from(low > rtol * top && low > 0.0);
                    assert_eq!(r, Ok(want), "rank(diag(1, {x}), {rtol})");
                }
            }
            for y in hostile() {
                for l in [c(x, y), c(-x, y)] {
                    let m = Mode::of(l);
                    if !finite_c(l) {
                        continue;
                    }
                    let n = l.norm();
                    assert!(m.damped_frequency == l.im.abs() && (n.is_infinite() || m.natural_frequency == n), "Mode::of({l}): {m:?}");
                    assert!(m.damping_ratio.is_none_or(|z| z.is_finite() && (-1.0..=1.0).contains(&z)), "ζ of {l}: {m:?}");
                    assert!(m.time_constant.is_none_or(|t| t.is_finite() && t > 0.0 && (t * -l.re - 1.0).abs() <= 2.0 * EPS), "τ of {l}: {m:?}");
                    assert!(m.time_to_half.is_none_or(|t| t.is_finite() && t > 0.0), "t½ of {l}: {m:?}");
                }
            }
        }
        refused(expm(&DMatrix::zeros(2, 3)), "expm(non-square)");
        refused(expm(&DMatrix::from_element(1, 1, 1000.0)), "e^1000 overflows");
        assert!(expm(&DMatrix::zeros(0, 0)).is_ok_and(|e| e.is_empty()));
        refused(eigenvalues(&DMatrix::zeros(2, 3)), "eigenvalues(non-square)");
        refused(balance(&DMatrix::zeros(2, 3)), "balance(non-square)");
        refused(eigenvalues(&DMatrix::from_element(2, 2, 1e308)), "eigenvalue 2e308");
        refused(singular_values(&DMatrix::from_element(2, 2, f64::MAX)), "σ = 2·MAX");
        assert_eq!(eigenvalues(&DMatrix::zeros(0, 0)), Ok(vec![]));
        // far from normal: [[−3, −c], [1, 0]] has λ² + 3λ + c = 0, λ = −1.5 ± j√(c − 2.25), far
        // below the largest entry (the imaginary parts were once tidied away as round-off)
        for c in [1e300, f64::MAX] {
            let ev = eigenvalues(&DMatrix::from_row_slice(2, 2, &[-3.0, -c, 1.0, 0.0])).unwrap();
            let im = c.sqrt();
            assert!(ev.iter().all(|z| (z.im.abs() - im).abs() <= 4.0 * EPS * im && z.re.abs() <= 4.0 * EPS * im), "{ev:?}");
        }
        assert_eq!(singular_values(&DMatrix::zeros(0, 3)), Ok(vec![]));
        assert_eq!(rank(&DMatrix::zeros(0, 3), 1e-12), Ok(0));
    }

    // SDOF systems, stability classes and the Routh array: the kind follows the signs of c and
    // k; A = [[0, 1], [−k/m, −c/m]]; ωn = √k/√m and ζ = c/(2√m√k) where representable; diag(x, −1)
    // is unstable, semistable or asymptotically stable by the sign of x; Routh counts add up
    // to the degree and match the roots; a stable gain makes D + kN Hurwitz by its roots.
    sdof_and_stability ["Sdof::kind", "Sdof::to_state_space", "stability_of_matrix", "stability_of_polynomial",
        "StabilityClass::is_bibo", "routh", "RouthArray::lhp", "RouthArray::is_hurwitz", "stable_gain_intervals"] {
        for m in hostile() {
            for cc in hostile() {
                for k in hostile() {
                    let Ok(s) = Sdof::new(m, cc, k) else { continue };
                    let kind = match (cc > 0.0, k > 0.0) {
                        (false, false) => SdofKind::UndampedRigidBody,
                        (true, false) => SdofKind::DampedRigidBody,
                        (false, true) => SdofKind::UndampedOscillator,
                        (true, true) => SdofKind::DampedOscillator,
                    };
                    assert_eq!(s.kind(), kind);
                    let wn = k.sqrt() / m.sqrt();
                    assert!(!wn.is_finite() || (s.natural_frequency() - wn).abs() <= 4.0 * EPS * wn, "ωn of {s:?}: {}", s.natural_frequency());
                    let zeta = cc / (2.0 * m.sqrt() * k.sqrt());
                    if k > 0.0 && zeta.is_finite() {
                        assert!(s.damping_ratio().is_some_and(|z| (z - zeta).abs() <= 8.0 * EPS * zeta), "ζ of {s:?}: {:?}", s.damping_ratio());
                    }
                    for out in [SdofOutput::Position, SdofOutput::Velocity, SdofOutput::Acceleration] {
                        err_or(s.to_state_space(out), "Sdof::to_state_space", |ss| {
                            ss.a()[(0, 1)] == 1.0 && ss.a()[(1, 0)] == -k / m && ss.a()[(1, 1)] == -cc / m && ss.b()[(1, 0)] == 1.0 / m
                                && (out != SdofOutput::Acceleration || ss.d()[(0, 0)] == 1.0 / m)
                        });
                    }
                }
            }
        }
        refused(Sdof { m: f64::NAN, c: 0.0, k: 1.0 }.to_state_space(SdofOutput::Position), "to_state_space(NaN field)");
        let class_of = |x: f64| {
            if x > AXIS_RTOL * x.abs().max(1.0) {
                StabilityClass::Unstable
            } else if x < -AXIS_RTOL * x.abs().max(1.0) {
                StabilityClass::AsymptoticallyStable
            } else {
                StabilityClass::Semistable
            }
        };
        for x in hostile() {
            let a = DMatrix::from_row_slice(2, 2, &[x, 0.0, 0.0, -1.0]);
            let p = Polynomial::new(&[1.0, -x]);
            if !x.is_finite() {
                refused(stability_of_matrix(&a, AXIS_RTOL), "stability_of_matrix(non-finite)");
                continue;
            }
            let p = p.unwrap();
            err_or(stability_of_matrix(&a, AXIS_RTOL), "stability_of_matrix", |s| *s == class_of(x));
            err_or(stability_of_polynomial(&p, AXIS_RTOL), "stability_of_polynomial", |s| *s == class_of(x));
            for tol in hostile() {
                if tol.is_nan() || tol < 0.0 || tol.is_infinite() {
                    refused(stability_of_matrix(&a, tol), "stability_of_matrix(bad tol)");
                    refused(stability_of_polynomial(&p, tol), "stability_of_polynomial(bad tol)");
                }
            }
            // s² + x s + 1: roots −x/2 ± j√(1 − x²/4). The array's zero test is normwise
            // (1e3·ε·max|c|): beyond |x| = 1e10 the root −1/x counts as on the axis, never in the
            // wrong half plane.
            let q = Polynomial::new(&[1.0, x, 1.0]).unwrap();
            err_or(routh(&q), "routh", |r| {
                r.lhp() + r.rhp + r.imaginary == 2
                    && r.is_hurwitz() == (r.rhp == 0 && r.imaginary == 0)
                    && (x <= 0.0 || r.rhp == 0)
                    && (!(1e-10..1e10).contains(&x.abs()) || (r.is_hurwitz() == (x > 0.0) && (x > 0.0 || r.rhp == 2)))
            });
            let lead = Polynomial::new(&[x, 1.0, 1.0]).unwrap();
            err_or(routh(&lead), "routh(leading)", |r| r.lhp() + r.rhp + r.imaginary == lead.degree());
            err_or(stable_gain_intervals(&Polynomial::constant(1.0), &q), "stable_gain_intervals", |iv| {
                let hurwitz = |k: f64| {
                    let p = Polynomial::new(&[1.0, x, 1.0 + k]).unwrap();
                    p.roots().unwrap().iter().all(|z| z.re < 0.0)
                };
                iv.iter().all(|&(lo, hi)| lo < hi && {
                    let mid = if lo.is_finite() && hi.is_finite() { 0.5 * (lo + hi) } else if lo.is_finite() { lo + lo.abs().max(1.0) } else { hi - hi.abs().max(1.0) };
                    !mid.is_finite() || hurwitz(mid)
                }) && (!(1e-10..1e10).contains(&x.abs()) || iv.is_empty() == (x < 0.0))
            });
        }
        refused(routh(&Polynomial::constant(0.0)), "routh(0)");
        refused(stability_of_polynomial(&Polynomial::constant(0.0), AXIS_RTOL), "stability_of_polynomial(0)");
        refused(stable_gain_intervals(&Polynomial::constant(0.0), &Polynomial::s()), "stable_gain_intervals(N = 0)");
        assert_eq!(stability_of_matrix(&DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 0.0, 0.0]), AXIS_RTOL), Ok(StabilityClass::Unstable));
        assert_eq!(stability_of_matrix(&DMatrix::zeros(2, 2), AXIS_RTOL), Ok(StabilityClass::Semistable));
        assert_eq!(stability_of_polynomial(&Polynomial::new(&[1.0, 0.0, 0.0]).unwrap(), AXIS_RTOL), Ok(StabilityClass::Unstable));
        assert!(StabilityClass::AsymptoticallyStable.is_bibo() && !StabilityClass::Semistable.is_bibo());
        assert!(!StabilityClass::LyapunovStable.is_bibo() && !StabilityClass::Unstable.is_bibo());
        // (s + 1)³ + k: Hurwitz for −1 < k < 8
        let cube = Polynomial::new(&[1.0, 3.0, 3.0, 1.0]).unwrap();
        err_or(stable_gain_intervals(&Polynomial::constant(1.0), &cube), "stable_gain_intervals((s+1)³)", |iv| {
            iv.len() == 1 && (iv[0].0 + 1.0).abs() <= 1e-9 && (iv[0].1 - 8.0).abs() <= 1e-9
        });
    }

    // Time responses of 1/(s + 1) are the closed forms 1 − e^{−t}, e^{−t}, t − 1 + e^{−t}
    // times the amplitude, shifted by the delay; grids are uniform from 0 to t_end; sizes
    // beyond MAX_VALUES, empty, NaN, negative or non-uniform grids and mismatched lengths are
    // refused.
    time_responses ["time_grid", "response", "initial", "lsim", "TransferFunction::step", "TransferFunction::impulse",
        "TransferFunction::ramp"] {
        for t_end in hostile() {
            for n in [0, 1, 2, 3, 1000, MAX_VALUES + 1, usize::MAX] {
                err_or(time_grid(t_end, n), "time_grid", |t| {
                    t.len() == n && t[0] == 0.0 && t[n - 1] == t_end && t.windows(2).all(|w| w[0] < w[1]) && finite(t)
                });
            }
        }
        let sys = first_order();
        let grid = [0.0, 0.5, 1.0, 1.5];
        for x in hostile() {
            for kind in [InputKind::Impulse, InputKind::Step, InputKind::Ramp] {
                err_or(response(&sys, kind, 0, x, 0.0, &grid), "response(amplitude)", |r| follows(r, x.abs(), |t| x * closed_form(kind, t)));
                err_or(response(&sys, kind, 0, 1.0, x, &grid), "response(delay)", |r| {
                    follows(r, 1.0, |t| if t >= x { closed_form(kind, t - x) } else { 0.0 })
                });
                if x > 0.0 {
                    let spaced = [0.0, x, 2.0 * x];
                    err_or(response(&sys, kind, 0, 1.0, 0.0, &spaced), "response(spacing)", |r| follows(r, 1.0, |t| closed_form(kind, t)));
                    let unstable = StateSpace::from_rows(&[&[1.0]], &[&[1.0]], &[&[1.0]], &[&[0.0]]).unwrap();
                    err_or(response(&unstable, kind, 0, 1.0, 0.0, &spaced), "response(unstable)", |r| r.y[0].iter().all(|v| v.is_finite()));
                }
            }
            err_or(initial(&sys, &[x], &grid), "initial", |r| follows(r, x.abs(), |t| x * (-t).exp()));
            for hold in [Hold::Zoh, Hold::Foh] {
                // a constant input, delayed: the step response from t = delay
                err_or(lsim(&sys, 0, &[x; 4], &grid, &[0.0], hold, 0.0), "lsim(u)", |r| follows(r, x.abs(), |t| x * closed_form(InputKind::Step, t)));
                for d in [x, 0.25] {
                    err_or(lsim(&sys, 0, &[1.0; 4], &grid, &[0.0], hold, d), "lsim(delay)", |r| {
                        follows(r, 1.0, |t| if t >= d { closed_form(InputKind::Step, t - d) } else { 0.0 })
                    });
                }
                err_or(lsim(&sys, 0, &[0.0; 4], &grid, &[x], hold, 0.0), "lsim(x0)", |r| follows(r, x.abs(), |t| x * (-t).exp()));
            }
            // u = t held first-order is the ramp exactly
            err_or(lsim(&sys, 0, &grid, &grid, &[0.0], Hold::Foh, 0.0), "lsim(ramp)", |r| follows(r, 1.0, |t| closed_form(InputKind::Ramp, t)));
            let g = TransferFunction::new(&[x], &[1.0, 1.0]).and_then(|g| g.with_delay(0.5));
            if let Ok(g) = g {
                let shifted = |kind: InputKind| move |t: f64| if t >= 0.5 { x * closed_form(kind, t - 0.5) } else { 0.0 };
                err_or(g.step(&grid), "step", |r| follows(r, x.abs(), shifted(InputKind::Step)));
                err_or(g.impulse(&grid), "impulse", |r| follows(r, x.abs(), shifted(InputKind::Impulse)));
                err_or(g.ramp(&grid), "ramp", |r| follows(r, x.abs(), shifted(InputKind::Ramp)));
            }
        }
        for bad in [&[][..], &[f64::NAN][..], &[-1.0, 0.0][..], &[0.0, 1.0, 3.0][..], &[1.0, 0.0][..]] {
            refused(response(&sys, InputKind::Step, 0, 1.0, 0.0, bad), "response(bad grid)");
            refused(tf(&[1.0], &[1.0, 1.0]).step(bad), "step(bad grid)");
            refused(initial(&sys, &[1.0], bad), "initial(bad grid)");
            refused(lsim(&sys, 0, &vec![0.0; bad.len()], bad, &[0.0], Hold::Zoh, 0.0), "lsim(bad grid)");
        }
        refused(response(&sys, InputKind::Step, 1, 1.0, 0.0, &grid), "response(bad input)");
        refused(response(&sys, InputKind::Step, 0, 1.0, -1.0, &grid), "response(negative delay)");
        refused(initial(&sys, &[1.0, 2.0], &grid), "initial(wrong x0)");
        refused(initial(&sys, &[f64::NAN], &grid), "initial(NaN x0)");
        refused(lsim(&sys, 0, &[1.0; 3], &grid, &[0.0], Hold::Zoh, 0.0), "lsim(short u)");
        refused(lsim(&sys, 0, &[1.0; 4], &grid, &[], Hold::Zoh, 0.0), "lsim(empty x0)");
        refused(lsim(&sys, 0, &[f64::NAN; 4], &grid, &[0.0], Hold::Zoh, 0.0), "lsim(NaN u)");
        refused(lsim(&sys, 1, &[1.0; 4], &grid, &[0.0], Hold::Zoh, 0.0), "lsim(bad input)");
        refused(lsim(&sys, 0, &[1.0; 4], &grid, &[0.0], Hold::Zoh, f64::NAN), "lsim(NaN delay)");
        refused(tf(&[1.0, 0.0, 0.0], &[1.0, 1.0]).impulse(&grid), "impulse(improper)");
        let unstable = StateSpace::from_rows(&[&[1.0]], &[&[1.0]], &[&[1.0]], &[&[0.0]]).unwrap();
        refused(response(&unstable, InputKind::Step, 0, 1.0, 0.0, &[0.0, 1e3, 2e3]), "e^{2000} overflows");
    }

    // Laplace tools: the partial fractions sum back to G(s₀); the inverse transform of
    // (s + x)/((s + 1)(s + 2)) is (x − 1)e^{−t} + (2 − x)e^{−2t}; initial values of 1/(s + x)
    // are (−x)ᵏ; the final value of 1/(s(s + x)) is 1/x for x > 0 and illegal for x < 0;
    // clusters keep every root once.
    laplace ["TransferFunction::partial_fractions", "TransferFunction::inverse_laplace",
        "TransferFunction::initial_values", "TransferFunction::final_value", "final_value", "TimeFunction::eval",
        "cluster_roots"] {
        let s0 = c(0.3, 0.7);
        for x in hostile() {
            let Ok(g) = TransferFunction::new(&[1.0, x], &[1.0, 3.0, 2.0]) else { continue };
            for rtol in hostile() {
                let pf = g.partial_fractions(rtol);
                if rtol.is_nan() || rtol < 0.0 || rtol.is_infinite() {
                    refused(pf, "partial_fractions(bad rtol)");
                    refused(g.inverse_laplace(rtol), "inverse_laplace(bad rtol)");
                    continue;
                }
                err_or(pf, "partial_fractions", |pf| {
                    let terms: Vec<Complex64> = pf.terms.iter().map(|t| t.residue * inv(s0 - t.pole).powu(t.power as u32)).collect();
                    let size = terms.iter().map(|t| t.norm()).sum::<f64>();
                    let sum = terms.iter().sum::<Complex64>() + pf.direct.eval_c(s0);
                    // a tolerance ≥ ½ makes −1 and −2 one double pole (as asked): finite terms only
                    pf.terms.iter().all(|t| finite_c(t.residue))
                        && (rtol >= 0.5 || (sum - g.eval(s0)).norm() <= 1e-12 * size.max(g.eval(s0).norm()))
                });
            }
            err_or(g.inverse_laplace(CLUSTER_RTOL), "inverse_laplace", |y| {
                [0.0f64, 0.5, 1.0, 3.0].iter().all(|&t| {
                    let want = (x - 1.0) * (-t).exp() + (2.0 - x) * (-2.0 * t).exp();
                    (y.eval(t) - want).abs() <= 1e-12 * (x.abs() + 2.0)
                })
            });
            if let Ok(y) = g.clone().with_delay(0.25).unwrap().inverse_laplace(CLUSTER_RTOL) {
                assert!(y.eval(0.2) == 0.0 && (y.eval(1.25) - (x - 1.0) * (-1.0f64).exp() - (2.0 - x) * (-2.0f64).exp()).abs() <= 1e-12 * (x.abs() + 2.0));
                for t in hostile().filter(|t| t.is_finite()) {
                    assert!(!y.eval(t).is_nan(), "TimeFunction::eval({t})");
                }
            }
            let h = tf(&[1.0], &[1.0, x]);
            for count in [0, 1, 4, usize::MAX] {
                err_or(h.initial_values(count), "initial_values", |v| {
                    v.len() == count && v.iter().enumerate().all(|(k, v)| {
                        let want = (-x).powi(k as i32);
                        v.is_finite() && (v - want).abs() <= 8.0 * (k + 1) as f64 * EPS * want.abs()
                    })
                });
                err_or(h.clone().with_delay(1.0).unwrap().initial_values(count), "initial_values(delay)", |v| v.len() == count && v.iter().all(|v| *v == 0.0));
            }
            let yhat = tf(&[1.0], &[1.0, x, 0.0]);
            for tol in hostile() {
                for fv in [yhat.final_value(tol), final_value(&yhat, tol)] {
                    if tol.is_nan() || tol < 0.0 || tol.is_infinite() {
                        refused(fv, "final_value(bad tol)");
                        continue;
                    }
                    err_or(fv, "final_value", |v| match *v {
                        FinalValue::Finite(v) => v.is_finite() && x > tol * x.abs().max(1.0) && (v * x - 1.0).abs() <= 4.0 * EPS,
                        FinalValue::Infinite(sign) => sign == 1.0 && x == 0.0,
                        FinalValue::Illegal(Illegal::RightHalfPlanePole(p)) => x < 0.0 && p.re > 0.0,
                        FinalValue::Illegal(Illegal::ImaginaryAxisPole(p)) => p.re.abs() <= tol * p.norm().max(1.0),
                    });
                }
            }
            for rtol in hostile() {
                let roots = [c(x, 0.0), c(x, 0.0), c(-1.0, 0.0)];
                let g = cluster_roots(&roots, rtol);
                assert!(g.iter().map(|(_, m)| m).sum::<usize>() == 3, "cluster_roots({x}, {rtol}): {g:?}");
                assert!(!x.is_finite() || g.iter().all(|(r, _)| finite_c(*r)), "cluster_roots({x}, {rtol}): {g:?}");
                assert!(!rtol.is_nan() || g.len() == 3 || x == -1.0);
            }
        }
        assert!(cluster_roots(&[], 1e-5).is_empty());
        refused(tf(&[1.0], &[1.0, 1.0]).with_delay(1.0).unwrap().partial_fractions(1e-5), "partial_fractions(delay)");
        refused(tf(&[1.0, 0.0], &[1.0, 1.0]).initial_values(2), "initial_values(biproper)");
        // a repeated pole: 1/(s + 1)² is one term of power 2
        err_or(tf(&[1.0], &[1.0, 2.0, 1.0]).partial_fractions(CLUSTER_RTOL), "partial_fractions((s+1)²)", |pf| {
            pf.terms.len() == 2 && pf.terms.iter().any(|t| t.power == 2 && (t.residue - 1.0).norm() <= 1e-6)
        });
    }

    // Margins as python-control defines them: at a gain crossover |L(jω)| = 1, at a phase
    // crossover L(jω) is real ≤ 0 with GM·|L| = 1, a stability point's distance is |1 + L(jω)|,
    // and each selected margin is the extreme of its list; Bode's integral of an open- and
    // closed-loop stable loop of relative degree 2 is 0; wrap_deg lands in (−180°, 180°].
    margins ["TransferFunction::margins", "Margins::gain_margin", "Margins::phase_margin", "Margins::stability_margin",
        "Margins::gain_margin_db", "Margins::gain_margin_ratio", "Margins::phase_margin_deg",
        "Margins::gain_crossover_omega", "Margins::phase_crossover_omega", "Margins::stability_margin_distance",
        "sensitivity_integral", "wrap_deg"] {
        for x in hostile() {
            let r = wrap_deg(x);
            if x.is_finite() {
                assert!(r > -180.0 && r <= 180.0, "wrap_deg({x}) = {r}");
                if x.abs() <= 1e12 {
                    let turns = (x - r) / 360.0;
                    assert!((turns - turns.round()).abs() <= 1e-9, "wrap_deg({x}) = {r}");
                }
            }
            let Ok(l) = TransferFunction::new(&[x], &[1.0, 6.0, 11.0, 6.0]) else { continue };
            let (nc, dc) = (l.num().coeffs().to_vec(), l.den().coeffs().to_vec());
            let at = |w: f64| tf_at(&nc, &dc, c(0.0, w)).map(|(v, _)| v);
            err_or(l.margins(), "margins", |m| {
                m.phase_crossovers.iter().all(|p| {
                    p.omega >= 0.0 && at(p.omega).is_none_or(|v| {
                        (v.im.abs() <= 1e-8 * v.norm() && v.re <= 0.0 && (p.gain_margin * v.norm() - 1.0).abs() <= 1e-8)
                            || (v.norm() == 0.0 && p.gain_margin == f64::INFINITY)
                        || (p.gain_margin == f64::INFINITY && p.gain_margin_db > 20.0 * 308.0)
                    }) && (p.gain_margin == f64::INFINITY || (p.gain_margin_db - 20.0 * p.gain_margin.log10()).abs() <= 1e-8 * p.gain_margin_db.abs().max(1.0))
                }) && m.gain_crossovers.iter().all(|g| {
                    g.omega > 0.0
                        && (-180.0..180.0).contains(&g.phase_margin_deg)
                        && at(g.omega).is_none_or(|v| (v.norm() - 1.0).abs() <= 1e-8 && wrap_deg(g.phase_margin_deg - v.arg().to_degrees() + 180.0).abs() <= 1e-6)
                }) && m.stability_points.iter().all(|s| {
                    s.omega > 0.0 && s.distance >= 0.0 && at(s.omega).is_none_or(|v| (s.distance - (v + 1.0).norm()).abs() <= 1e-8 * s.distance.max(1.0))
                }) && m.gain_margin().is_none_or(|g| m.phase_crossovers.iter().filter(|p| p.gain_margin.is_finite()).all(|p| g.gain_margin.ln().abs() <= p.gain_margin.ln().abs()))
                    && m.phase_margin().is_none_or(|g| m.gain_crossovers.iter().all(|p| g.phase_margin_deg.abs() <= p.phase_margin_deg.abs()))
                    && m.stability_margin().is_none_or(|g| m.stability_points.iter().all(|p| g.distance <= p.distance))
                    && m.gain_margin_db() == m.gain_margin().map(|g| g.gain_margin_db)
                    && m.gain_margin_ratio() == m.gain_margin().map(|g| g.gain_margin)
                    && m.phase_crossover_omega() == m.gain_margin().map(|g| g.omega)
                    && m.phase_margin_deg() == m.phase_margin().map(|g| g.phase_margin_deg)
                    && m.gain_crossover_omega() == m.phase_margin().map(|g| g.omega)
                    && m.stability_margin_distance() == m.stability_margin().map(|g| g.distance)
            });
            // L = x/((s + 1)(s + 2)): closed loop s² + 3s + 2 + x, stable for x > −2
            let l2 = tf(&[x], &[1.0, 3.0, 2.0]);
            err_or(sensitivity_integral(&l2), "sensitivity_integral", |v| v.is_finite() && (x <= -2.0 || v.abs() <= 1e-6));
        }
        // 6/((s + 1)(s + 2)(s + 3)): the phase crosses −180° at ω = √11 with |L| = 6/60
        let m = tf(&[6.0], &[1.0, 6.0, 11.0, 6.0]).margins().unwrap();
        assert!(m.phase_crossover_omega().is_some_and(|w| (w - 11f64.sqrt()).abs() <= 1e-9));
        assert!(m.gain_margin_ratio().is_some_and(|g| (g - 10.0).abs() <= 1e-9));
        refused(sensitivity_integral(&tf(&[1.0], &[1.0, 1.0])), "sensitivity_integral(relative degree 1)");
        refused(sensitivity_integral(&tf(&[1.0], &[1.0, 3.0, 2.0]).with_delay(1.0).unwrap()), "sensitivity_integral(delay)");
    }

    // Root locus: every sampled root solves D + kN = 0 and the gains run from 0 to k_max;
    // departure angles satisfy the angle condition (15.18.9); ζ-line crossings lie on the line;
    // time shifts satisfy Δt·ω = −φ; `leads` is the book's 0 < φ̂ − φ ≤ 180° modulo 360°.
    root_locus_and_shifts ["root_locus", "departure_angles", "RootLocus::zeta_crossings", "time_shift", "leads"] {
        let g = tf(&[1.0], &[1.0, 2.0, 0.0]);
        let check = |rl: &vectrix::lti::RootLocus, k_max: f64| {
            assert!(rl.gains[0] == 0.0 && rl.gains.windows(2).all(|w| w[0] < w[1]), "gains {:?}", rl.gains);
            assert_eq!(*rl.gains.last().unwrap(), k_max);
            assert!(rl.branches.len() == 2 && rl.branches.iter().all(|b| b.len() == rl.gains.len()));
            for b in &rl.branches {
                for (s, k) in b.iter().zip(&rl.gains) {
                    assert!(is_root(&[1.0, 2.0, *k], *s, 1e3), "{s} is no root of s² + 2s + {k}");
                }
            }
            assert_eq!(rl.asymptote_center, Some(-1.0));
            true
        };
        for x in hostile() {
            if x.is_finite() && x > 0.0 {
                err_or(root_locus(&g, x, 0.1), "root_locus(k_max)", |rl| check(rl, x));
                err_or(root_locus(&g, 10.0, x), "root_locus(max_step)", |rl| check(rl, 10.0));
            } else {
                refused(root_locus(&g, x, 0.1), "root_locus(bad k_max)");
                refused(root_locus(&g, 10.0, x), "root_locus(bad max_step)");
            }
        }
        refused(root_locus(&g.clone().with_delay(1.0).unwrap(), 1.0, 0.1), "root_locus(delay)");
        refused(root_locus(&tf(&[1.0, 0.0, 0.0], &[1.0, 1.0]), 1.0, 0.1), "root_locus(improper)");
        let rl = root_locus(&g, 10.0, 0.05).unwrap();
        for zeta in hostile().chain([0.5, -0.5, 0.9]) {
            let crossings = rl.zeta_crossings(&g, zeta);
            let z = zeta.clamp(-1.0, 1.0);
            assert!(
                crossings.iter().all(|&(k, s)| (0.0..=10.0).contains(&k) && s.im > 0.0 && (s.re + z * s.norm()).abs() <= 1e-6 * s.norm() && is_root(&[1.0, 2.0, k], s, 1e7)),
                "zeta_crossings({zeta}): {crossings:?}"
            );
        }
        // a NaN ζ defines no damping line: no crossings (it used to report every sampled
        // segment, since a NaN side never has the sign of the one before)
        assert!(rl.zeta_crossings(&g, f64::NAN).is_empty(), "zeta_crossings(NaN)");
        assert!(rl.zeta_crossings(&g, -f64::NAN).is_empty(), "zeta_crossings(−NaN)");
        // s² + 2s + k meets ζ = ½ where −1 = −½√k: k = 4
        assert!(rl.zeta_crossings(&g, 0.5).iter().any(|&(k, _)| (k - 4.0).abs() <= 1e-6));
        for x in hostile() {
            let poles = [c(-1.0, x), c(-1.0, -x), c(0.0, 0.0)];
            let zeros = [c(-2.0, 0.0)];
            let d = departure_angles(&poles, &zeros);
            if !x.is_finite() {
                continue;
            }
            assert!(d.len() == 3 && d.iter().all(|(_, a)| *a > -180.0 && *a <= 180.0), "departure_angles({x}): {d:?}");
            if x.abs() >= 1e-3 {
                for (p, phi) in &d {
                    let sz: f64 = zeros.iter().map(|z| (p - z).arg().to_degrees()).sum();
                    let sp: f64 = poles.iter().filter(|q| *q != p).map(|q| (p - q).arg().to_degrees()).sum();
                    assert!((wrap_deg(sz - sp - phi) - 180.0).abs() <= 1e-9, "angle condition at {p}: {phi}");
                }
            }
        }
        assert!(departure_angles(&[], &[]).is_empty());
        for phi in hostile() {
            for w in hostile() {
                if phi.is_finite() && w.is_finite() {
                    // fmod is exact (rem_euclid of −5e-324 rounds to 360 and lost the sign)
                    let d = (phi % 360.0 - w % 360.0).rem_euclid(360.0);
                    assert_eq!(leads(phi, w), Ok(d > 0.0 && d <= 180.0), "leads({phi}, {w})");
                }
                let r = time_shift(phi, w);
                if !(phi.is_finite() && w.is_finite() && w > 0.0) {
                    refused(r, "time_shift(bad)");
                    continue;
                }
                err_or(r, "time_shift", |dt| dt.is_finite() && (dt * w + phi).abs() <= 2.0 * EPS * phi.abs() + w * 5e-324);
            }
            for w in [f64::NAN, f64::INFINITY] {
                refused(leads(phi, w), "leads(non-finite)");
            }
        }
    }
}
