//! `Accuracy` on stiff problems: the compiled stiff table is what the harness derives now
//! (f-evaluation counts are deterministic), and `Accuracy::RelTol` detects stiffness during
//! a run, switches, says why, and meets the requested error on problems with independent
//! references; on a non-stiff problem it stays explicit.
//!
//! Book: §4.11; HW §IV.1 (stiffness), §IV.10; Petzold 1983 (LSODA's switching).

use nalgebra::{Vector2, Vector3};
use vectrix_ode::harness::derive_stiff_accuracy;
use vectrix_ode::{Accuracy, STIFF_ACCURACY_TABLE};

#[test]
fn the_compiled_stiff_table_is_the_derived_one() {
    let derived = derive_stiff_accuracy();
    for d in &derived {
        println!("{:e} {} {:e} {}", d.target, d.method, d.rtol, d.fevals);
    }
    assert_eq!(derived.len(), STIFF_ACCURACY_TABLE.len());
    for (d, c) in derived.iter().zip(&STIFF_ACCURACY_TABLE) {
        assert_eq!((d.target, d.method, d.rtol), (c.target, c.method, c.rtol), "{d:?}");
    }
}

/// Largest |error| of a component over max(1, |wantᵢ|) (NaN if any is NaN).
fn mixed_error(got: &[f64], want: &[f64]) -> f64 {
    got.iter().zip(want).fold(0.0, |m: f64, (g, w)| {
        let e = (g - w).abs() / w.abs().max(1.0);
        if e.is_nan() || m.is_nan() { f64::NAN } else { m.max(e) }
    })
}

#[test]
fn accuracy_switches_to_the_stiff_method_on_van_der_pol_and_meets_the_error() {
    // VDPOL (ε = 1e-6) against the Test Set's y(2) = (1.706167732170483, −0.8928097010247975)
    let f = |_: f64, y: &Vector2<f64>| Vector2::new(y[1], ((1.0 - y[0] * y[0]) * y[1] - y[0]) / 1e-6);
    let want = [1.706167732170483, -0.8928097010247975];
    for tol in [1e-4, 1e-6, 1e-8] {
        let (sol, choice) =
            Accuracy::RelTol(tol).solve_with_choice(f, 0.0, &Vector2::new(2.0, 0.0), 2.0).unwrap();
        println!("{tol:e}: {choice} — {}", sol.work);
        assert_eq!(choice.method, "radau5", "{choice}");
        let ts = choice.switched_at.expect("switched");
        // DOP853 stays until two checks (50 steps) at its stability limit, a tiny stretch of 2 s
        assert!(ts < 1e-3, "{choice}");
        assert!(choice.reason.starts_with("stiff"), "{choice}");
        let err = mixed_error(sol.last().as_slice(), &want);
        assert!(err <= tol, "tol {tol:e}: error {err:e}");
        // DOP853 alone would need ≈ 6e5 steps (7e6 f-evaluations)
        assert!(sol.work.fevals < 100_000, "{}", sol.work);
        assert!(sol.work.fd_jacobian_fevals > 0, "f is f64 only: finite-difference Jacobians");
        assert_eq!(sol.t.len(), sol.y.len());
        assert!(sol.t.windows(2).all(|w| w[0] < w[1]));
    }
}

#[test]
fn accuracy_switches_on_robertson_once_the_kinetics_turn_stiff() {
    // Robertson to t = 40 against scipy Radau at rtol = 1e-13 (tests/data/stiff_reference.json);
    // at t = 0 the Jacobian's spectrum is {−0.04, 0, 0}, yet DOP853's first step (sized for
    // that spectrum) overflows in its stages once y₂ builds up: the switch happens there
    let f = |_: f64, y: &Vector3<f64>| {
        Vector3::new(
            -0.04 * y[0] + 1e4 * y[1] * y[2],
            0.04 * y[0] - 1e4 * y[1] * y[2] - 3e7 * y[1] * y[1],
            3e7 * y[1] * y[1],
        )
    };
    let want = [0.7158270687194058, 9.185534764557781e-06, 0.28416374574583];
    for tol in [1e-5, 1e-7] {
        let (sol, choice) =
            Accuracy::RelTol(tol).solve_with_choice(f, 0.0, &Vector3::new(1.0, 0.0, 0.0), 40.0).unwrap();
        println!("{tol:e}: {choice} — {}", sol.work);
        assert!(choice.switched_at.is_some_and(|t| t < 1.0), "{choice}");
        assert_eq!(choice.method, "radau5", "{choice}");
        let err = mixed_error(sol.last().as_slice(), &want);
        assert!(err <= tol, "tol {tol:e}: error {err:e}");
        assert!(sol.work.fevals < 50_000, "{}", sol.work);
    }
}

#[test]
fn accuracy_stays_explicit_on_a_non_stiff_problem_and_says_why() {
    // ẍ = −x from (1, 0) over 10 periods: x = cos t; the checks see h·ρ ≪ 3
    let f = |_: f64, y: &Vector2<f64>| Vector2::new(y[1], -y[0]);
    let t1 = 20.0 * std::f64::consts::PI;
    let (sol, choice) =
        Accuracy::RelTol(1e-8).solve_with_choice(f, 0.0, &Vector2::new(1.0, 0.0), t1).unwrap();
    assert_eq!(choice.method, "dop853", "{choice}");
    assert!(choice.switched_at.is_none() && choice.reason.contains("not stiff"), "{choice}");
    assert!((sol.last()[0] - 1.0).abs() <= 1e-8 && sol.last()[1].abs() <= 1e-8, "{:?}", sol.last());
    assert!(sol.work.jacobians == 0);
}

#[test]
fn stiff_accuracy_below_the_table_is_refused() {
    let f = |_: f64, y: &f64| -y;
    assert!(Accuracy::RelTol(1e-11).stiff_solver().is_err());
    assert!(Accuracy::RelTol(-1.0).solve_with_choice(f, 0.0, &1.0, 1.0).is_err());
    assert_eq!(Accuracy::RelTol(1e-6).stiff_solver().unwrap().name(), STIFF_ACCURACY_TABLE[3].method);
}
