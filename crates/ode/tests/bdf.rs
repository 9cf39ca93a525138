//! The variable-order BDF (orders 1–5) against independent references: Robertson's kinetics
//! against scipy Radau at rtol = 1e-13 (tests/data/stiff_reference.json, made by
//! scripts/stiff_reference.py), Van der Pol at ε = 1e-6 (μ = 1000) against the published
//! Test Set end state, a linear stiff problem with a closed-form solution (the order of each
//! formula from the slope of error against steps), the stiff damped chain's modal solution,
//! dense output and events located on the interpolating polynomial, and the typed errors of
//! the stiff failure modes.
//!
//! Book: §4.11; HW = Hairer & Wanner, *Solving ODEs II*, §III.5 (BDF), §IV.1 (test problems),
//! §V.5; Shampine & Reichelt 1997.

use std::f64::consts::PI;

use nalgebra::{Vector2, Vector3};
use vectrix_ode::{Bdf, BdfStepper, Direction, Event, OdeError};

mod support;
use support::{nan_max, reference, rel_err, robertson, robertson_jac, vdpol, vdpol_jacobian};

#[test]
fn robertson_matches_the_stored_reference() {
    for name in ["robertson_40", "robertson_1e5"] {
        let (t_end, want, unc) = reference(name);
        let y0 = Vector3::new(1.0, 0.0, 0.0);
        // atol scaled to y₂ ~ 1e-5 (the fast intermediate), as HW do
        let sol = Bdf::new()
            .rtol(1e-10)
            .atol(1e-16)
            .solve_with_jacobian(robertson, robertson_jac, 0.0, &y0, t_end)
            .unwrap();
        let err = rel_err(sol.last().as_slice(), &want);
        assert!(unc < 1e-9, "{name}: reference uncertainty {unc:e}");
        println!("{name}: BDF rtol 1e-10 relative error {err:e} ({})", sol.work);
        // BDF's global error runs above its local tolerance (error propagates over 10⁴–10⁵
        // steps): every component (y₂ included) within 1000 × rtol
        assert!(err < 1e-7, "{name}: relative error {err:e} ({})", sol.work);
        // the finite-difference route agrees and says so in its work
        let fd = Bdf::new().rtol(1e-10).atol(1e-16).solve(robertson, 0.0, &y0, t_end).unwrap();
        assert!(rel_err(fd.last().as_slice(), &want) < 1e-7, "{}", fd.work);
        assert_eq!(sol.work.fd_jacobian_fevals, 0);
        assert_eq!(fd.work.fd_jacobian_fevals, 3 * fd.work.jacobians);
        assert!(fd.work.to_string().contains("finite differences"));
    }
}

#[test]
fn van_der_pol_matches_the_published_test_set_reference() {
    // VDPOL of the Test Set for IVP Solvers (Mazzia & Magherini, Univ. Bari; HW II §IV.10):
    // y₁′ = y₂, y₂′ = ((1 − y₁²) y₂ − y₁)/ε, ε = 1e-6 (μ = 1000 in scaled time), y(0) = (2, 0),
    // t ∈ [0, 2]; reference end state y(2) = (1.706167732170483, −0.8928097010247975).
    let want = [1.706167732170483, -0.8928097010247975];
    for (rtol, bound) in [(1e-6, 1e-3), (1e-9, 1e-6)] {
        let sol = Bdf::new()
            .rtol(rtol)
            .atol(rtol)
            .solve_with_jacobian(vdpol, vdpol_jacobian, 0.0, &Vector2::new(2.0, 0.0), 2.0)
            .unwrap();
        let err = rel_err(sol.last().as_slice(), &want);
        println!("VDPOL rtol {rtol:e}: relative error {err:e} ({})", sol.work);
        // the global error through a relaxation jump: within 1000 × rtol
        assert!(err < bound, "rtol {rtol:e}: relative error {err:e} ({})", sol.work);
        // an explicit method needs ≳ 2/(ε·3.3) ≈ 6e5 steps here
        assert!(sol.work.accepted < 20_000, "{}", sol.work);
    }
}

/// A linear stiff system with a closed-form solution: y₁′ = −y₁, y₂′ = −10⁴(y₂ − y₁) − y₁,
/// eigenvalues −1 and −10⁴; from y(0) = (1, 1) the fast mode is not excited and
/// y = e^{−t}(1, 1) exactly, so the end error is the method's alone.
fn linear(_: f64, y: &Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-y[0], -1e4 * (y[1] - y[0]) - y[0])
}

fn linear_jac(_: f64, _: &Vector2<f64>, j: &mut [f64]) {
    j.copy_from_slice(&[-1.0, 0.0, 1e4 - 1.0, -1e4]);
}

#[test]
fn each_order_converges_at_its_rate_on_a_linear_stiff_problem() {
    // at max_order = k the global error of the slow mode is C·hᵏ (HW Theorem III.4.5 with
    // the stiff mode damped), so log(error)/log(steps) → −k: the slope between two
    // tolerances measures the order of the formula the run settles on
    for k in 1..=5 {
        let run = |tol: f64| {
            let sol = Bdf::new()
                .max_order(k)
                .rtol(tol)
                .atol(tol)
                .solve_with_jacobian(linear, linear_jac, 0.0, &Vector2::new(1.0, 1.0), 5.0)
                .unwrap();
            let want = (-5f64).exp();
            (nan_max(sol.last().iter().map(|y| ((y - want) / want).abs())), sol.work.accepted as f64)
        };
        // order 1 at rtol = 1e-11 would take 4e5 steps: its pair is four decades looser
        let (tight, loose) = if k == 1 { (1e-9, 1e-5) } else { (1e-11, 1e-7) };
        let (e1, n1) = run(loose);
        let (e2, n2) = run(tight);
        let slope = -(e2 / e1).ln() / (n2 / n1).ln();
        println!("order {k}: errors {e1:e} → {e2:e}, steps {n1} → {n2}, slope {slope:.2}");
        // the first steps run at orders below k (a larger share of a short run), which steepens
        // the measured slope of the higher orders: k − 0.25 ≤ slope ≤ k + 1.5
        assert!(slope >= k as f64 - 0.25 && slope <= k as f64 + 1.5, "order {k}: slope {slope}");
    }
}

/// y′ = −1000 (y − cos t): y = (10⁶ cos t + 10³ sin t + (y₀ − 10⁶/(10⁶+1))(10⁶+1) e^{−1000t})/(10⁶ + 1).
fn forced(t: f64, y: &f64) -> f64 {
    -1000.0 * (y - t.cos())
}

fn forced_exact(t: f64, y0: f64) -> f64 {
    let k2 = 1e6;
    (k2 * t.cos() + 1e3 * t.sin() + (y0 * (k2 + 1.0) - k2) * (-1000.0 * t).exp()) / (k2 + 1.0)
}

#[test]
fn dense_output_interpolates_between_the_steps() {
    // the interpolating polynomial of order k between steps: within 10 × rtol of the closed
    // form at 200 points of [0.1, 3] (the transient long gone)
    let sol = Bdf::new().rtol(1e-9).atol(1e-12).dense(true).solve(forced, 0.0, &0.5, 3.0).unwrap();
    let err = nan_max((0..200).map(|i| {
        let t = 0.1 + 2.9 * i as f64 / 199.0;
        (sol.sample(t).unwrap() - forced_exact(t, 0.5)).abs()
    }));
    assert!(err < 1e-8, "dense-output error {err:e}");
    assert!((sol.sample(3.0).unwrap() - sol.last()).abs() < 1e-15);
}

#[test]
fn events_are_located_on_the_interpolating_polynomial() {
    // y = 0 where cos t + 1e-3 sin t = 0 (the transient long gone): t* = π/2 + atan(1e-3);
    // terminal, falling
    let mut ev = [Event::new(|_, y: &f64| *y).direction(Direction::Falling).terminal(true)];
    let sol = Bdf::new().rtol(1e-10).atol(1e-12).solve_with_events(forced, 0.0, &0.5, 10.0, &mut ev).unwrap();
    let t_star = PI / 2.0 + 1e-3f64.atan();
    assert!(sol.terminated);
    assert_eq!(sol.events.len(), 1);
    assert!((sol.events[0].t - t_star).abs() < 1e-8, "event at {} vs {t_star}", sol.events[0].t);
    assert!((sol.t.last().unwrap() - t_star).abs() < 1e-8);
}

#[test]
fn the_stepper_restarts_after_a_jump_and_moves_its_end() {
    // y′ = −1000(y − cos t) to t = 1, then y jumps to 2 and the run continues to t = 2: the
    // closed form from the new start, and the order begins again at 1
    let jac = |_: f64, _: &f64, j: &mut [f64]| j[0] = -1000.0;
    let mut st =
        BdfStepper::new(&Bdf::new().rtol(1e-9).atol(1e-12), forced, Some(jac), 0.0, 0.5, 1.0).unwrap();
    while !st.done() {
        st.step().unwrap();
    }
    assert!(st.order() > 1, "order {}", st.order());
    assert!((st.y() - forced_exact(1.0, 0.5)).abs() < 1e-8);
    st.set_end(2.0).unwrap();
    st.restart(1.0, 2.0).unwrap();
    assert_eq!(st.order(), 1);
    assert!(matches!(st.dense(), Err(OdeError::NoDenseOutput)));
    while !st.done() {
        st.step().unwrap();
    }
    // from (1, 2): the same closed form shifted in time (cos and sin of t, not t − 1)
    let k2 = 1e6;
    let particular = |t: f64| (k2 * t.cos() + 1e3 * t.sin()) / (k2 + 1.0);
    let want = particular(2.0) + (2.0 - particular(1.0)) * (-1000.0f64).exp();
    assert_eq!(st.t(), 2.0);
    assert!((st.y() - want).abs() < 1e-8, "{} vs {want}", st.y());
    assert!(st.exact_jacobian());
}

#[test]
fn nan_in_the_jacobian_is_a_typed_error_naming_t_and_the_state() {
    let f = |_: f64, y: &Vector2<f64>| Vector2::new(y[1], -y[0]);
    let jac = |_: f64, _: &Vector2<f64>, j: &mut [f64]| j.copy_from_slice(&[0.0, 1.0, f64::NAN, 0.0]);
    let e = Bdf::new().solve_with_jacobian(f, jac, 0.0, &Vector2::new(1.0, 0.0), 1.0).unwrap_err();
    match &e {
        OdeError::JacobianNotFinite { t, row: 1, col: 0, value, state } => {
            assert_eq!(*t, 0.0);
            assert!(value.is_nan());
            assert_eq!(state, &vec![1.0, 0.0]);
        }
        other => panic!("expected JacobianNotFinite, got {other}"),
    }
}

#[test]
fn a_numerically_singular_iteration_matrix_is_a_typed_error() {
    // J = 2¹⁰⁰·[[1, 1], [1, 1]] scaled by c = h/γₖ: I − cJ rounds to −cJ for any h the floor
    // allows before ten halvings, singular in floating point; the error names t and the state
    let f = |_: f64, y: &Vector2<f64>| Vector2::new(-y[0], -y[1]);
    let jac = |_: f64, _: &Vector2<f64>, j: &mut [f64]| j.fill(2f64.powi(100));
    let e = Bdf::new().h0(1e-3).solve_with_jacobian(f, jac, 0.0, &Vector2::new(1.0, 2.0), 1.0).unwrap_err();
    assert!(
        matches!(&e, OdeError::SingularIterationMatrix { t, state, .. } if *t == 0.0 && state == &vec![1.0, 2.0]),
        "{e}"
    );
}

#[test]
fn newton_failing_to_converge_is_a_typed_error_not_a_hang() {
    // f = −1e8 y but the Jacobian says +1e8: simplified Newton diverges for h ≳ 1e-8, also
    // with the refreshed (equally wrong) Jacobian; ten halvings from h₀ = 1e-3 end the run
    let f = |_: f64, y: &f64| -1e8 * y;
    let jac = |_: f64, _: &f64, j: &mut [f64]| j[0] = 1e8;
    let e = Bdf::new().h0(1e-3).solve_with_jacobian(f, jac, 0.0, &1.0, 1.0).unwrap_err();
    assert!(
        matches!(&e, OdeError::NewtonStalled { t, failures: 10, state, .. } if *t == 0.0 && state == &vec![1.0]),
        "{e}"
    );
}

#[test]
fn bad_input_is_refused() {
    let f = |_: f64, y: &f64| -y;
    for k in [0, 6] {
        assert!(matches!(
            Bdf::new().max_order(k).solve(f, 0.0, &1.0, 1.0),
            Err(OdeError::InvalidSetting { name: "max_order", .. })
        ));
    }
    assert!(matches!(
        Bdf::new().max_newton(0).solve(f, 0.0, &1.0, 1.0),
        Err(OdeError::InvalidSetting { name: "max_newton", .. })
    ));
    assert!(matches!(
        Bdf::new().rtol(-1.0).solve(f, 0.0, &1.0, 1.0),
        Err(OdeError::NonPositiveTolerance { .. })
    ));
    assert!(matches!(Bdf::new().solve(f, 1.0, &1.0, 0.0), Err(OdeError::InvalidInterval { .. })));
    assert!(matches!(Bdf::new().solve(f, 0.0, &f64::NAN, 1.0), Err(OdeError::NonFiniteState { .. })));
    assert!(matches!(Bdf::new().max_steps(3).solve(f, 0.0, &1.0, 10.0), Err(OdeError::TooManySteps { .. })));
}
