//! The Taylor integrator: every recurrence against the closed-form series of its function,
//! identities of series (property tests), whole runs against exact solutions, dense output,
//! and every refusal.

use nalgebra::{Vector1, Vector2};
use proptest::prelude::*;

use super::series::Tape;
use super::{Taylor, TaylorRhs, Var};
use crate::OdeError;
use crate::harness::{Kepler, Oscillator, Pendulum, Reference, RigidBody};

/// The series (orders 0..=p) of `op` applied to the input series `x` (all its orders given
/// up front), computed one order per pass as the integrator does.
fn series_of(x: &[f64], op: impl for<'a> Fn(Var<'a>) -> Var<'a>) -> Vec<f64> {
    let p = x.len() - 1;
    let tape = Tape::new(p, 1);
    let at = op(tape.input(0)).at();
    let mut c = vec![0.0; tape.store_len()];
    c[..=p].copy_from_slice(x);
    for k in 0..=p {
        tape.pass(k, &mut c);
    }
    c[at..=at + p].to_vec()
}

/// Relative difference of two coefficients (absolute below 1).
fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs().max(1.0)
}

/// Binomial coefficient C(α, k) for real α.
fn binom(alpha: f64, k: usize) -> f64 {
    (0..k).fold(1.0, |c, i| c * (alpha - i as f64) / (i + 1) as f64)
}

fn factorial(k: usize) -> f64 {
    (1..=k).fold(1.0, |f, i| f * i as f64)
}

/// Coefficient k of a closed-form series.
type Coefficient = Box<dyn Fn(usize) -> f64>;

#[test]
fn recurrences_give_the_series_of_each_function() {
    // x(s) = a + s: every function's series is known in closed form (Abramowitz & Stegun 3.6,
    // 4.1, 4.2, 4.3): √, x^α and 1/x by the binomial series, eˣ, ln x, sin x, cos x by
    // Taylor's theorem; relative 1e-13 (the recurrences' round-off over 16 orders)
    let (a, p) = (1.7f64, 16);
    let mut x = vec![0.0; p + 1];
    (x[0], x[1]) = (a, 1.0);
    let cases: Vec<(&str, Vec<f64>, Coefficient)> = vec![
        ("sqrt", series_of(&x, |v| v.sqrt()), Box::new(move |k| binom(0.5, k) * a.powf(0.5 - k as f64))),
        (
            "powf",
            series_of(&x, |v| v.powf(-1.5)),
            Box::new(move |k| binom(-1.5, k) * a.powf(-1.5 - k as f64)),
        ),
        ("exp", series_of(&x, |v| v.exp()), Box::new(move |k| a.exp() / factorial(k))),
        (
            "ln",
            series_of(&x, |v| v.ln()),
            Box::new(move |k| {
                if k == 0 { a.ln() } else { (-1f64).powi(k as i32 + 1) / (k as f64 * a.powi(k as i32)) }
            }),
        ),
        (
            "sin",
            series_of(&x, |v| v.sin()),
            Box::new(move |k| (a + k as f64 * core::f64::consts::FRAC_PI_2).sin() / factorial(k)),
        ),
        (
            "cos",
            series_of(&x, |v| v.cos()),
            Box::new(move |k| (a + k as f64 * core::f64::consts::FRAC_PI_2).cos() / factorial(k)),
        ),
        (
            "recip",
            series_of(&x, |v| 1.0 / v),
            Box::new(move |k| (-1f64).powi(k as i32) / a.powi(k as i32 + 1)),
        ),
        (
            "div",
            series_of(&x, |v| v.constant(2.0) / v),
            Box::new(move |k| 2.0 * (-1f64).powi(k as i32) / a.powi(k as i32 + 1)),
        ),
        (
            "square",
            series_of(&x, |v| v.square()),
            Box::new(move |k| [a * a, 2.0 * a, 1.0].get(k).copied().unwrap_or(0.0)),
        ),
        (
            "mul",
            series_of(&x, |v| v * (v + 1.0)),
            Box::new(move |k| [a * (a + 1.0), 2.0 * a + 1.0, 1.0].get(k).copied().unwrap_or(0.0)),
        ),
        (
            "affine",
            series_of(&x, |v| 3.0 - v * 2.0 + 1.0),
            Box::new(move |k| [4.0 - 2.0 * a, -2.0].get(k).copied().unwrap_or(0.0)),
        ),
        (
            "neg/sub",
            series_of(&x, |v| -(v - 0.5) / 4.0),
            Box::new(move |k| [-(a - 0.5) / 4.0, -0.25].get(k).copied().unwrap_or(0.0)),
        ),
    ];
    for (name, got, want) in cases {
        for (k, g) in got.iter().enumerate() {
            assert!(close(*g, want(k), 1e-13), "{name}: coefficient {k} is {g}, expected {}", want(k));
        }
    }
}

/// A random input series: a₀ ∈ [0.5, 3] (away from the singular points of √, ln, x^α), the
/// others in [−1, 1].
fn input_series() -> impl Strategy<Value = Vec<f64>> {
    (0.5f64..3.0, proptest::collection::vec(-1.0f64..1.0, 12)).prop_map(|(a0, rest)| {
        let mut x = vec![a0];
        x.extend(rest);
        x
    })
}

proptest! {
    /// Identities of series for any input series: sin² + cos² = 1, exp(ln x) = x, √x·√x = x,
    /// (x/y)·y = x, x^α·x^β = x^(α+β) (coefficient k to (k + 1)·1e-12 of the largest expected
    /// coefficient so far: each sums k + 1 rounded products).
    #[test]
    fn series_identities(x in input_series(), alpha in -2.0f64..2.0, beta in -2.0f64..2.0) {
        let checks: Vec<(&str, Vec<f64>, Vec<f64>)> = vec![
            ("sin²+cos²", series_of(&x, |v| v.sin().square() + v.cos().square()), {
                let mut one = vec![0.0; x.len()];
                one[0] = 1.0;
                one
            }),
            ("exp(ln x)", series_of(&x, |v| v.ln().exp()), x.clone()),
            ("√x·√x", series_of(&x, |v| v.sqrt() * v.sqrt()), x.clone()),
            ("(x/(x+2))·(x+2)", series_of(&x, |v| (v / (v + 2.0)) * (v + 2.0)), x.clone()),
            ("x^α·x^β", series_of(&x, |v| v.powf(alpha) * v.powf(beta)), series_of(&x, |v| v.powf(alpha + beta))),
        ];
        for (name, got, want) in checks {
            // coefficient k sums k + 1 products: (k + 1)·1e-12 relative to the largest expected
            // coefficient up to k (at least 1: the inputs are O(1))
            let mut scale: f64 = 1.0;
            for (k, (g, w)) in got.iter().zip(&want).enumerate() {
                scale = scale.max(w.abs());
                prop_assert!((g - w).abs() <= (k + 1) as f64 * 1e-12 * scale, "{} coefficient {}: {} vs {}", name, k, g, w);
            }
        }
    }
}

impl TaylorRhs<2> for Oscillator {
    fn eval<'a>(&self, _: Var<'a>, y: &[Var<'a>; 2]) -> [Var<'a>; 2] {
        [y[1], -y[0]]
    }
}

#[test]
fn runs_reach_the_exact_solutions() {
    // the harness's closed forms (cos t; Kepler's equation; Jacobi's sn, cn; Euler's equations
    // by elliptic functions); each bound is about 10× the error measured at the given
    // tolerance (oscillator 1.1e-15, Kepler 5.6e-11, pendulum 3.2e-11, rigid body 6.9e-13),
    // so a regression in the step control shows
    let cases: [(&str, f64, f64); 4] = [
        ("oscillator", 1e-14, run_error(&Oscillator, 1e-14)),
        ("Kepler e = 0.9", 5e-10, run_error(&Kepler { e: 0.9 }, 1e-11)),
        ("pendulum θ₀ = 3", 3e-10, run_error(&Pendulum { theta0: 3.0 }, 1e-11)),
        (
            "rigid body",
            7e-12,
            run_error(&RigidBody { inertia: [1.0, 2.0, 3.0], omega13: [1.0, 0.5], t_end: 20.0 }, 1e-11),
        ),
    ];
    for (name, bound, err) in cases {
        assert!(err <= bound, "{name}: error {err:e} above {bound:e}");
    }
}

fn run_error<const N: usize, P: Reference<N> + TaylorRhs<N>>(p: &P, tol: f64) -> f64 {
    let sol = Taylor::new().rtol(tol).atol(tol).solve(p, 0.0, &p.y0(), p.t_end()).unwrap();
    assert_eq!(*sol.t.last().unwrap(), p.t_end(), "the last step lands on t_end");
    assert_eq!(sol.work.accepted + 1, sol.t.len());
    p.error(sol.last())
}

#[test]
fn dense_output_is_the_series_of_each_step() {
    // the oscillator sampled between steps: cos t to 1e-12 everywhere (each step's series
    // has order 28 at 1e-14, its tail below 1e-14)
    let sol = Taylor::new()
        .rtol(1e-14)
        .atol(1e-14)
        .dense(true)
        .solve(&Oscillator, 0.0, &Vector2::new(1.0, 0.0), 10.0)
        .unwrap();
    for i in 0..=200 {
        let t = 0.05 * i as f64;
        let y = sol.sample(t).unwrap();
        assert!((y[0] - t.cos()).abs() < 1e-12 && (y[1] + t.sin()).abs() < 1e-12, "t = {t}: {y:?}");
    }
    // the sample at a step's end is that step's end state to round-off
    let (t1, y1) = (sol.t[3], sol.y[3]);
    assert!((sol.sample(t1).unwrap() - y1).amax() < 1e-14);
}

/// y′ = √y from y = 0: the series of √y is singular at 0.
struct SqrtAtZero;
impl TaylorRhs<1> for SqrtAtZero {
    fn eval<'a>(&self, _: Var<'a>, y: &[Var<'a>; 1]) -> [Var<'a>; 1] {
        [y[0].sqrt()]
    }
}

/// y′ = −y written as 300 operations (a long tape).
struct Long;
impl TaylorRhs<1> for Long {
    fn eval<'a>(&self, t: Var<'a>, y: &[Var<'a>; 1]) -> [Var<'a>; 1] {
        let mut v = y[0] * 1.0;
        for _ in 0..299 {
            v = v + t.constant(0.0);
        }
        [-v]
    }
}

#[test]
fn bad_input_and_failures_are_refused_with_what_was_wrong() {
    let y0 = Vector2::new(1.0, 0.0);
    let run = |t: Taylor| t.solve(&Oscillator, 0.0, &y0, 1.0);
    for p in [0, 1, 61] {
        assert!(
            matches!(run(Taylor::new().order(p)), Err(OdeError::InvalidSetting { name: "order", value, .. }) if value == p)
        );
    }
    assert!(matches!(
        run(Taylor::new().rtol(-1.0)),
        Err(OdeError::NonPositiveTolerance { name: "rtol", .. })
    ));
    assert!(matches!(
        run(Taylor::new().atol(f64::NAN)),
        Err(OdeError::NonPositiveTolerance { name: "atol", .. })
    ));
    assert!(matches!(Taylor::new().solve(&Oscillator, 1.0, &y0, 1.0), Err(OdeError::InvalidInterval { .. })));
    assert!(matches!(
        Taylor::new().solve(&Oscillator, 0.0, &Vector2::new(f64::NAN, 0.0), 1.0),
        Err(OdeError::NonFiniteState { index: 0, .. })
    ));
    assert!(matches!(
        Taylor::new().max_steps(1).solve(&Oscillator, 0.0, &y0, 10.0),
        Err(OdeError::TooManySteps { max_steps: 1, .. })
    ));
    assert!(matches!(
        Taylor::new().solve(&SqrtAtZero, 0.0, &Vector1::new(0.0), 1.0),
        Err(OdeError::RhsNotFinite { index: 0, .. })
    ));
}

#[test]
fn a_long_right_hand_side_records_every_operation() {
    let sol = Taylor::new().rtol(1e-12).atol(1e-12).solve(&Long, 0.0, &Vector1::new(1.0), 2.0).unwrap();
    assert!((sol.last()[0] - (-2f64).exp()).abs() < 1e-12, "{}", sol.last()[0]);
}

#[test]
fn the_order_follows_the_tolerance_or_the_setting() {
    // Jorba & Zou (3.5): ⌈1 − ½ ln ε⌉
    assert_eq!(Taylor::new().rtol(1e-9).atol(1e-9).effective_order(), 12);
    assert_eq!(Taylor::new().rtol(1e-16).atol(1e-3).effective_order(), 20);
    assert_eq!(Taylor::new().rtol(0.5).atol(0.5).effective_order(), 4);
    assert_eq!(Taylor::new().order(7).effective_order(), 7);
}
