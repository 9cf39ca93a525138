//! vectrix-ode under hostile input (docs/robustness.md): every integrator refuses NaN states,
//! invalid intervals and step counts, NaN/negative tolerances and a right-hand side that
//! returns NaN or the wrong length; step loops are bounded (TooManySteps), so nothing hangs.

use nalgebra::{SVector, Vector2, Vector3, Vector4};
use vectrix::frames::Frame;
use vectrix::ode::explicit::integrate_fixed;
use vectrix::ode::harness::elliptic::{elliptic_k, sncndn};
use vectrix::ode::harness::{
    Budget, Kepler, Method, Oscillator, Reference, RigidBody, Separable, cheapest, derive_accuracy,
    euler_equations, quaternion_rate, run_all, sweep, sweep_lie, sweep_verlet,
};
use vectrix::ode::lie::dexpinv;
use vectrix::ode::{
    Accuracy, Adaptive, DOP853, Direction, Event, GaussLegendre, LieGroup, LieMethod, OdeError, RK4, State,
    integrate_lie, quaternion_exact_step, stormer_verlet,
};
use vectrix::tensor::{Rotor, Vector};

use crate::harness::{err_or, hostile, refused};

fn fin(s: &[f64]) -> bool {
    s.iter().all(|x| x.is_finite())
}

/// y′ = −k(y − cos t), y(0) = 1, k = 1000: y = (k² cos t + k sin t + e^{−kt})/(k² + 1).
fn stiff_exact(t: f64) -> f64 {
    let k = 1000.0_f64;
    (k * k * t.cos() + k * t.sin() + (-k * t).exp()) / (k * k + 1.0)
}

cases! {
    // RADAU5 (issue 34) and the one stepping interface over it and the explicit pairs: hostile
    // tolerances, Newton caps, states and intervals are refused or give finite answers; on the
    // stiff y′ = −1000(y − cos t) every route ends on the closed form; the steppers reach t_end
    // exactly, give dense output between steps, restart and move their end; a NaN Jacobian is a
    // typed error.
    radau5 ["Solver::new", "Solver::rtol", "Solver::atol", "Solver::h0", "Solver::h_max", "Solver::max_steps",
        "Solver::max_newton", "Solver::dense", "Solver::solve", "Solver::solve_with_jacobian",
        "Solver::solve_with_events", "Solver::solve_with_jacobian_and_events",
        "RadauStepper::new", "Progress::t", "Progress::y", "Progress::step_start", "Progress::done",
        "Progress::work", "Progress::proposed_step", "Progress::end", "RadauStepper::exact_jacobian",
        "RadauStepper::step", "RadauStepper::dense", "RadauStepper::restart", "Progress::set_end",
        "Method::max_steps", "Method::with_max_steps", "Method::tolerances",
        "AnyStepper::new", "AnyStepper::step", "AnyStepper::dense", "AnyStepper::restart", "Method::is_implicit"] {
        use vectrix::ode::{AnyStepper, Method as OdeMethod, Radau5, RadauStepper};
        let f = |t: f64, y: &Vec<f64>| vec![-1000.0 * (y[0] - t.cos())];
        let jac = |_: f64, _: &Vec<f64>, out: &mut [f64]| out[0] = -1000.0;
        for x in hostile() {
            err_or(Radau5::new().rtol(x).solve(f, 0.0, &vec![1.0], 1.0), "solve(hostile rtol)", |s| fin(s.last()));
            err_or(Radau5::new().atol(x).solve(f, 0.0, &vec![1.0], 1.0), "solve(hostile atol)", |s| fin(s.last()));
            err_or(Radau5::new().h0(x).h_max(x).solve(f, 0.0, &vec![1.0], 1.0), "solve(hostile h)", |s| fin(s.last()));
            err_or(Radau5::new().solve(f, 0.0, &vec![x], 1.0), "solve(hostile y0)", |s| fin(s.last()));
            err_or(Radau5::new().solve(f, 0.0, &vec![1.0], x), "solve(hostile t1)", |s| fin(s.last()));
            err_or(RadauStepper::new(&Radau5::new(), f, Some(jac), 0.0, vec![x], 1.0), "stepper(hostile y0)", |s| fin(s.y()));
        }
        refused(Radau5::new().max_steps(3).solve(f, 0.0, &vec![1.0], 10.0), "max_steps(3)");
        refused(Radau5::new().max_newton(0).solve(f, 0.0, &vec![1.0], 1.0), "max_newton(0)");
        let nan_jac = |_: f64, _: &Vec<f64>, out: &mut [f64]| out[0] = f64::NAN;
        refused(Radau5::new().solve_with_jacobian(f, nan_jac, 0.0, &vec![1.0], 1.0), "NaN Jacobian");
        // every route ends on the closed form (rtol 1e-8: the end error is of that order)
        let r = Radau5::new().rtol(1e-8).atol(1e-10).dense(true);
        let ends = [
            r.solve(f, 0.0, &vec![1.0], 1.0).unwrap().last()[0],
            r.solve_with_jacobian(f, jac, 0.0, &vec![1.0], 1.0).unwrap().last()[0],
            r.solve_with_events(f, 0.0, &vec![1.0], 1.0, &mut []).unwrap().last()[0],
            r.solve_with_jacobian_and_events(f, jac, 0.0, &vec![1.0], 1.0, &mut []).unwrap().last()[0],
        ];
        for e in ends {
            assert!((e - stiff_exact(1.0)).abs() <= 1e-7, "{e} vs {}", stiff_exact(1.0));
        }
        // the stepper: to t_end exactly, dense output on the closed form, restart, new end
        let mut st = RadauStepper::new(&r, f, Some(jac), 0.0, vec![1.0], 1.0).unwrap();
        assert!(st.exact_jacobian() && st.step_start().is_none() && st.proposed_step() > 0.0);
        while !st.done() {
            st.step().unwrap();
            let tm = 0.5 * (st.step_start().unwrap() + st.t());
            let mid = st.dense().unwrap().eval(tm)[0];
            assert!((mid - stiff_exact(tm)).abs() <= 1e-5, "dense at {tm}");
        }
        assert_eq!((st.t(), st.end()), (1.0, 1.0));
        assert!(st.work().fevals > 0 && fin(st.y()));
        refused(st.restart(0.5, vec![f64::NAN]), "restart(NaN)");
        st.restart(1.0, vec![stiff_exact(1.0)]).unwrap();
        refused(st.set_end(f64::NAN), "set_end(NaN)");
        st.set_end(2.0).unwrap();
        while !st.done() { st.step().unwrap(); }
        assert!((st.y()[0] - stiff_exact(2.0)).abs() <= 1e-7);
        // one interface over both kinds
        let b = vectrix::ode::Bdf::new().rtol(1e-9).atol(1e-11);
        for m in [OdeMethod::Radau5(r), OdeMethod::Bdf(b), OdeMethod::Explicit(Adaptive::dop853().rtol(1e-8).atol(1e-10))] {
            assert_eq!(m.is_implicit(), !matches!(m, OdeMethod::Explicit(_)));
            let m = m.with_max_steps(100_000);
            assert_eq!(m.max_steps(), 100_000);
            let (rt, at) = m.tolerances();
            assert!(rt > 0.0 && at > 0.0);
            let mut s = AnyStepper::new(&m, f, Some(jac), 0.0, vec![1.0], 1.0).unwrap();
            while !s.done() {
                s.step().unwrap();
                let mid = 0.5 * (s.step_start().unwrap() + s.t());
                assert!(fin(&s.dense().unwrap().eval(mid)));
            }
            assert!((s.y()[0] - stiff_exact(1.0)).abs() <= 1e-7 && s.t() == s.end() && s.work().fevals > 0);
            s.restart(1.0, vec![stiff_exact(1.0)]).unwrap();
            s.set_end(1.5).unwrap();
            while !s.done() { s.step().unwrap(); }
            assert!((s.y()[0] - stiff_exact(1.5)).abs() <= 1e-7, "{}", s.y()[0]);
            err_or(AnyStepper::new(&m, f, Some(jac), 0.0, vec![f64::NAN], 1.0), "AnyStepper(NaN)", |s| fin(s.y()));
        }
    }

    // BDF (issue 34): hostile tolerances, orders, Newton caps, states and intervals are refused
    // or give finite answers; every route ends on the closed form of the stiff
    // y′ = −1000(y − cos t); the stepper reaches t_end exactly, interpolates between steps,
    // restarts at order 1 and moves its end.
    bdf ["Solver::max_order", "Solver::with_method", "BdfStepper::new", "BdfStepper::exact_jacobian",
        "BdfStepper::order", "BdfStepper::step", "BdfStepper::dense", "BdfStepper::restart"] {
        use vectrix::ode::{Bdf, BdfFormula, BdfStepper, Solver};
        let f = |t: f64, y: &Vec<f64>| vec![-1000.0 * (y[0] - t.cos())];
        let jac = |_: f64, _: &Vec<f64>, out: &mut [f64]| out[0] = -1000.0;
        for x in hostile() {
            err_or(Bdf::new().rtol(x).solve(f, 0.0, &vec![1.0], 1.0), "solve(hostile rtol)", |s| fin(s.last()));
            err_or(Bdf::new().h0(x).h_max(x).solve(f, 0.0, &vec![1.0], 1.0), "solve(hostile h)", |s| fin(s.last()));
            // a huge t1 ends in TooManySteps; 10⁴ steps say so as well as 10⁶ (the watchdog is 20 s)
            err_or(Bdf::new().max_steps(10_000).solve(f, 0.0, &vec![1.0], x), "solve(hostile t1)", |s| fin(s.last()));
            err_or(BdfStepper::new(&Bdf::new(), f, Some(jac), 0.0, vec![x], 1.0), "stepper(hostile y0)", |s| fin(s.y()));
        }
        for k in [0, 6, usize::MAX] {
            refused(Bdf::new().max_order(k).solve(f, 0.0, &vec![1.0], 1.0), "max_order out of 1..=5");
        }
        refused(Bdf::new().max_newton(0).solve(f, 0.0, &vec![1.0], 1.0), "max_newton(0)");
        refused(Bdf::new().max_steps(3).solve(f, 0.0, &vec![1.0], 10.0), "max_steps(3)");
        let nan_jac = |_: f64, _: &Vec<f64>, out: &mut [f64]| out[0] = f64::NAN;
        refused(Bdf::new().solve_with_jacobian(f, nan_jac, 0.0, &vec![1.0], 1.0), "NaN Jacobian");
        let b = Solver::with_method(BdfFormula { max_order: 5, max_newton: 4 }).rtol(1e-9).atol(1e-11);
        assert_eq!(b, Bdf::new().rtol(1e-9).atol(1e-11));
        let ends = [
            b.solve(f, 0.0, &vec![1.0], 1.0).unwrap().last()[0],
            b.solve_with_jacobian(f, jac, 0.0, &vec![1.0], 1.0).unwrap().last()[0],
            b.solve_with_events(f, 0.0, &vec![1.0], 1.0, &mut []).unwrap().last()[0],
            b.solve_with_jacobian_and_events(f, jac, 0.0, &vec![1.0], 1.0, &mut []).unwrap().last()[0],
        ];
        for e in ends {
            assert!((e - stiff_exact(1.0)).abs() <= 1e-7, "{e} vs {}", stiff_exact(1.0));
        }
        let mut st = BdfStepper::new(&b, f, Some(jac), 0.0, vec![1.0], 1.0).unwrap();
        assert!(st.exact_jacobian() && st.order() == 1 && st.step_start().is_none());
        assert!(st.dense().is_err());
        while !st.done() {
            st.step().unwrap();
            let tm = 0.5 * (st.step_start().unwrap() + st.t());
            let mid = st.dense().unwrap().eval(tm)[0];
            assert!((mid - stiff_exact(tm)).abs() <= 1e-5, "dense at {tm}");
        }
        assert_eq!((st.t(), st.end()), (1.0, 1.0));
        refused(st.restart(0.5, vec![f64::NAN]), "restart(NaN)");
        refused(st.restart(0.5, vec![1.0, 2.0]), "restart(wrong dimension)");
        st.restart(1.0, vec![stiff_exact(1.0)]).unwrap();
        assert_eq!(st.order(), 1);
        st.set_end(2.0).unwrap();
        while !st.done() { st.step().unwrap(); }
        assert!((st.y()[0] - stiff_exact(2.0)).abs() <= 1e-7);
    }

    // Accuracy on stiff problems (issue 34): hostile tolerances are refused by the stiff table
    // as by the explicit one; a stiff run switches and ends on the closed form of
    // y′ = −1000(y − cos t); the stiff calibration gives finite rows and its problems finite
    // errors, also for a method that cannot finish (a step cap of 3 is a typed error).
    stiff_accuracy ["Accuracy::solve_with_choice", "Accuracy::stiff_solver", "StiffProblem::run",
        "derive_stiff_accuracy", "robertson", "robertson_jacobian", "vdpol", "vdpol_jacobian"] {
        use vectrix::ode::harness::STIFF_PROBLEMS;
        use vectrix::ode::{Method as OdeMethod, Radau5};
        let f = |t: f64, y: &Vec<f64>| vec![-1000.0 * (y[0] - t.cos())];
        for x in hostile() {
            err_or(Accuracy::RelTol(x).stiff_solver(), "stiff_solver(hostile)", |m| m.tolerances().0 > 0.0);
            err_or(Accuracy::RelTol(x).solve_with_choice(f, 0.0, &vec![1.0], 10.0), "solve_with_choice(hostile tol)",
                |(s, _)| fin(s.last()));
            err_or(Accuracy::RelTol(1e-6).solve_with_choice(f, 0.0, &vec![x], 10.0), "solve_with_choice(hostile y0)",
                |(s, _)| fin(s.last()));
        }
        let (sol, choice) = Accuracy::RelTol(1e-6).solve_with_choice(f, 0.0, &vec![1.0], 10.0).unwrap();
        assert!(choice.switched_at.is_some(), "{choice}");
        // the table promises 1e-6 on its calibration problems; here the end error is 1.2e-6
        assert!((sol.last()[0] - stiff_exact(10.0)).abs() <= 1e-5, "{}", sol.last()[0]);
        for p in &STIFF_PROBLEMS {
            let (e, n) = p.run(&OdeMethod::Radau5(Radau5::new().rtol(1e-6).atol(1e-6))).unwrap();
            assert!(e.is_finite() && e < 1e-3 && n > 0, "{}: {e:e}", p.name);
            refused(p.run(&OdeMethod::Radau5(Radau5::new().max_steps(3))), "max_steps(3)");
        }
        // the harness right-hand sides at hostile states: finite or NaN/∞ out, never a panic,
        // and their Jacobians of the right size
        use vectrix::ode::harness::{robertson, robertson_jacobian, vdpol, vdpol_jacobian};
        let mut j3 = [0.0; 9];
        let mut j2 = [0.0; 4];
        for x in hostile() {
            let _ = robertson(0.0, &Vector3::new(x, x, x));
            robertson_jacobian(0.0, &Vector3::new(x, 1.0, 1.0), &mut j3);
            let _ = vdpol(0.0, &Vector2::new(x, x));
            vdpol_jacobian(0.0, &Vector2::new(x, 1.0), &mut j2);
        }
        robertson_jacobian(0.0, &Vector3::new(1.0, 0.0, 0.0), &mut j3);
        assert_eq!(j3, [-0.04, 0.0, 0.0, 0.04, 0.0, 0.0, 0.0, 0.0, 0.0]);
        vdpol_jacobian(0.0, &Vector2::new(2.0, 0.0), &mut j2);
        assert_eq!(j2, [0.0, 1.0, -1e6, -3e6]);
        assert_eq!(robertson(0.0, &Vector3::new(1.0, 0.0, 0.0)), Vector3::new(-0.04, 0.04, 0.0));
        assert_eq!(vdpol(0.0, &Vector2::new(2.0, 0.0)), Vector2::new(0.0, -2e6));
        for d in vectrix::ode::harness::derive_stiff_accuracy() {
            assert!(d.rtol > 0.0 && d.rtol <= d.target && d.fevals > 0, "{d:?}");
        }
    }

    // The step-by-step driver: hostile intervals, states, restarts and end times are refused;
    // one step at a time reaches t_end exactly; the interpolant agrees with e^{−t}; a restart
    // with the wrong dimension or a NaN state is refused; bracket_zero keeps its bracket even
    // when g is NaN or a step function.
    stepper ["Stepper::new", "Stepper::step", "Stepper::dense", "Stepper::restart", "Progress::set_end",
        "Progress::end", "Progress::done", "Progress::t", "Progress::y", "Progress::step_start", "Progress::work",
        "Progress::proposed_step", "bracket_zero"] {
        use vectrix::ode::explicit::{Stepper, bracket_zero};
        let f = |_t: f64, y: &Vec<f64>| vec![-y[0]];
        for x in hostile() {
            err_or(Stepper::new(&Adaptive::dop853(), f, 0.0, vec![x], 1.0), "new(hostile y0)", |s| fin(s.y()));
            err_or(Stepper::new(&Adaptive::dop853(), f, 0.0, vec![1.0], x), "new(hostile t_end)", |s| s.end().is_finite());
            err_or(Stepper::new(&Adaptive::dopri5().rtol(x), f, 0.0, vec![1.0], 1.0), "new(hostile rtol)", |s| fin(s.y()));
        }
        let mut st = Stepper::new(&Adaptive::dop853().rtol(1e-10).atol(1e-12), f, 0.0, vec![1.0], 1.0).unwrap();
        assert!(st.step_start().is_none());
        refused(st.dense().map(|d| d.h), "dense before a step");
        let mut n = 0;
        while !st.done() {
            st.step().unwrap();
            n += 1;
            assert!(n < 10_000 && st.proposed_step() > 0.0);
            let (a, b) = (st.step_start().unwrap(), st.t());
            let m = 0.5 * (a + b);
            assert!((st.dense().unwrap().eval(m)[0] - (-m).exp()).abs() < 1e-9);
        }
        assert_eq!(st.t(), 1.0);
        assert!((st.y()[0] - (-1.0f64).exp()).abs() < 1e-10 && st.work().accepted == n);
        st.step().unwrap(); // done: nothing happens
        assert_eq!(st.t(), 1.0);
        for x in hostile() {
            err_or(st.set_end(x).map(|()| st.end()), "set_end(hostile)", |e| e.is_finite() && *e > 1.0);
            err_or(st.restart(1.0, vec![x]).map(|()| st.y()[0]), "restart(hostile)", |y| y.is_finite());
        }
        refused(st.restart(1.0, vec![1.0, 2.0]), "restart with another dimension");
        refused(st.set_end(0.5), "set_end before t");
        // a right-hand side that changes length mid-run is refused, not truncated
        let mut calls = 0;
        let g = move |_t: f64, y: &Vec<f64>| {
            calls += 1;
            if calls > 5 { vec![0.0; 3] } else { vec![-y[0]] }
        };
        let mut bad = Stepper::new(&Adaptive::dopri5(), g, 0.0, vec![1.0], 1.0).unwrap();
        assert!(matches!(bad.step(), Err(OdeError::DimensionMismatch { .. })));
        // bracket_zero: a root of x² − 2 on [0, 2], a NaN function, a jump
        let (a, b) = bracket_zero(|x| x * x - 2.0, (0.0, -2.0), (2.0, 2.0));
        assert!(a <= 2f64.sqrt() && b >= 2f64.sqrt() && b - a <= 8.0 * f64::EPSILON);
        let (a, b) = bracket_zero(|_| f64::NAN, (0.0, -1.0), (1.0, 1.0));
        assert!(a.is_finite() && b.is_finite() && a <= b);
        let (a, b) = bracket_zero(|x| if x < 0.3 { -1.0 } else { 1.0 }, (0.0, -1.0), (1.0, 1.0));
        assert!(a < 0.3 && b >= 0.3 && b - a < 1e-12);
    }

    // Adaptive pairs (HNW II.4–II.6): y′ = −y from y0 gives y0 e^{−t}; every hostile
    // interval, state, tolerance and step setting is refused or solved finitely; a right-hand
    // side of the wrong length is a DimensionMismatch, not a silent truncation.
    adaptive_pairs ["Solver::dopri5", "Solver::dop853", "Solver::rtol", "Solver::atol", "Solver::h0",
        "Solver::h_max", "Solver::max_steps", "Solver::dense", "Solver::solve", "Solver::solve_with_events",
        "Solution::last", "Solution::sample", "DenseStep::eval", "Event::new", "Event::direction", "Event::terminal",
        "State::as_slice", "State::as_mut_slice", "State::dim", "State::add_scaled"] {
        // max_steps bounds every hostile configuration (h_max = 1e-300 now fails up front)
        for solver in [Adaptive::dopri5().max_steps(20_000), Adaptive::dop853().max_steps(20_000)] {
            let s = solver.dense(true).solve(|_, y: &Vec<f64>| vec![-y[0]], 0.0, &vec![1.0], 1.0).unwrap();
            assert!((s.last()[0] - (-1.0f64).exp()).abs() <= 1e-5);
            err_or(s.sample(0.5), "sample", |y| (y[0] - (-0.5f64).exp()).abs() <= 1e-5);
            refused(s.sample(2.0), "sample outside the interval");
            refused(s.sample(f64::NAN), "sample(NaN)");
            // The named bug: a right-hand side that returns the wrong length.
            assert!(matches!(
                solver.solve(|_, _y: &Vec<f64>| vec![1.0, 2.0, 3.0], 0.0, &vec![1.0, 0.0], 1.0),
                Err(OdeError::DimensionMismatch { .. })
            ));
            refused(solver.solve(|_, _y: &Vec<f64>| vec![1.0], 0.0, &vec![1.0, 0.0], 1.0), "short right-hand side");
            refused(solver.solve(|_, _y: &Vec<f64>| Vec::new(), 0.0, &vec![1.0], 1.0), "empty right-hand side");
            for x in hostile() {
                err_or(solver.solve(|_, y: &Vec<f64>| vec![-y[0]], 0.0, &vec![x], 1.0), "solve(hostile y0)", |s| fin(s.last()));
                err_or(solver.solve(|_, y: &Vec<f64>| vec![-y[0]], 0.0, &vec![1.0], x), "solve(hostile t1)", |s| fin(s.last()));
                err_or(solver.solve(|_, y: &Vec<f64>| vec![-y[0]], x, &vec![1.0], 1.0), "solve(hostile t0)", |s| fin(s.last()));
                err_or(solver.rtol(x).solve(|_, y: &Vec<f64>| vec![-y[0]], 0.0, &vec![1.0], 1.0), "rtol", |s| fin(s.last()));
                err_or(solver.atol(x).solve(|_, y: &Vec<f64>| vec![-y[0]], 0.0, &vec![1.0], 1.0), "atol", |s| fin(s.last()));
                err_or(solver.h0(x).solve(|_, y: &Vec<f64>| vec![-y[0]], 0.0, &vec![1.0], 1.0), "h0", |s| fin(s.last()));
                err_or(solver.h_max(x).solve(|_, y: &Vec<f64>| vec![-y[0]], 0.0, &vec![1.0], 1.0), "h_max", |s| fin(s.last()));
                err_or(solver.solve(move |_, _y: &Vec<f64>| vec![x], 0.0, &vec![1.0], 1.0), "solve(hostile f)", |s| fin(s.last()));
            }
            refused(solver.max_steps(3).solve(|_, y: &Vec<f64>| vec![-1e3 * y[0]], 0.0, &vec![1.0], 100.0), "max_steps bound");
            refused(solver.max_steps(0).solve(|_, y: &Vec<f64>| vec![-y[0]], 0.0, &vec![1.0], 1.0), "max_steps(0)");
            // An event function that returns NaN cannot make the solver loop or report NaN.
            let mut events = [Event::new(|_, _y: &Vec<f64>| f64::NAN).direction(Direction::Rising).terminal(true)];
            err_or(solver.solve_with_events(|_, y: &Vec<f64>| vec![-y[0]], 0.0, &vec![1.0], 1.0, &mut events), "NaN event", |s| {
                s.events.iter().all(|e| e.t.is_finite())
            });
            let mut ev = [Event::new(|_, y: &Vec<f64>| y[0] - 0.5).terminal(true)];
            let s = solver.dense(true).solve_with_events(|_, y: &Vec<f64>| vec![-y[0]], 0.0, &vec![1.0], 5.0, &mut ev).unwrap();
            assert!(s.terminated && (s.events[0].t - 2f64.ln()).abs() <= 1e-5);
            let mut st = vec![1.0, 2.0];
            st.add_scaled(2.0, &vec![1.0, 1.0]);
            assert_eq!(st.as_slice(), &[3.0, 4.0]);
            st.as_mut_slice()[0] = 0.0;
            assert_eq!(st.dim(), 2);
        }
    }

    // Fixed-step, implicit and symplectic methods: n = 0, n huge with a NaN interval,
    // mismatched q/v and non-finite right-hand sides are errors; results are finite.
    fixed_implicit_symplectic ["integrate_fixed", "Tableau::stages", "GaussLegendre::integrate",
        "GaussLegendre::integrate_with_jacobian", "GaussLegendre::name", "GaussLegendre::order", "GaussLegendre::stages",
        "stormer_verlet"] {
        assert_eq!(RK4.stages(), 4);
        for n in [0usize, 1, 10] {
            for t1 in hostile() {
                err_or(integrate_fixed(&RK4, |_, y: &Vec<f64>| vec![-y[0]], 0.0, &vec![1.0], t1, n, |_, _| {}), "integrate_fixed", |(y, _)| fin(y));
                for g in [GaussLegendre::Midpoint, GaussLegendre::Gauss4, GaussLegendre::Gauss6] {
                    assert!(!g.name().is_empty() && g.order() == 2 * g.stages() as u32);
                    err_or(g.integrate(|_, y: &Vec<f64>| vec![-y[0]], 0.0, &vec![1.0], t1, n, |_, _| {}), "Gauss", |(y, _)| fin(y));
                }
                err_or(stormer_verlet(|_, q: &Vec<f64>| vec![-q[0]], 0.0, &vec![1.0], &vec![0.0], t1, n, |_, _, _| {}), "Verlet", |((q, v), _)| fin(q) && fin(v));
            }
        }
        refused(integrate_fixed(&DOP853, |_, _y: &Vec<f64>| vec![1.0, 2.0], 0.0, &vec![1.0], 1.0, 4, |_, _| {}), "integrate_fixed(wrong length)");
        refused(GaussLegendre::Gauss4.integrate(|_, _y: &Vec<f64>| vec![1.0, 2.0], 0.0, &vec![1.0], 1.0, 4, |_, _| {}), "Gauss(wrong length)");
        refused(GaussLegendre::Gauss4.integrate_with_jacobian(|_, y: &Vec<f64>| vec![-y[0]], |_, _| vec![1.0, 2.0], 0.0, &vec![1.0], 1.0, 4, |_, _| {}), "Gauss(wrong Jacobian)");
        err_or(GaussLegendre::Gauss4.integrate_with_jacobian(|_, y: &Vec<f64>| vec![-y[0]], |_, _| vec![-1.0], 0.0, &vec![1.0], 1.0, 4, |_, _| {}), "Gauss with J", |(y, _)| fin(y));
        refused(stormer_verlet(|_, q: &Vec<f64>| vec![-q[0]], 0.0, &vec![1.0], &vec![0.0, 1.0], 1.0, 4, |_, _, _| {}), "Verlet(mismatched q, v)");
        refused(stormer_verlet(|_, _q: &Vec<f64>| vec![f64::NAN], 0.0, &vec![1.0], &vec![0.0], 1.0, 4, |_, _, _| {}), "Verlet(NaN a)");
    }

    // The stiff integrators' dense LU: every hostile value at every entry of a 3×3 matrix is
    // refused or gives a finite solution; wrong sizes and solves without factors are typed
    // errors; n = 0 is the empty system; the sealed scalar helpers on hostile values.
    dense_lu ["DenseLu::new", "DenseLu::dim", "DenseLu::factor", "DenseLu::factor_with", "DenseLu::solve",
        "LuScalar::size", "LuScalar::finite", "LuScalar::recip"] {
        use faer::c64;
        use vectrix::ode::implicit::{DenseLu, LuScalar};
        let mut lu = DenseLu::<f64>::new(3);
        assert_eq!(lu.dim(), 3);
        refused(lu.solve(&mut [1.0, 2.0, 3.0]), "solve before factor");
        for x in hostile() {
            for pos in 0..9 {
                let mut a = [4.0, 1.0, 0.0, 1.0, 4.0, 1.0, 0.0, 1.0, 4.0];
                a[pos] = x;
                let mut b = [1.0, 2.0, 3.0];
                err_or(lu.factor(&a).and_then(|()| lu.solve(&mut b)), "factor+solve(hostile entry)", |()| fin(&b));
                let mut lc = DenseLu::<c64>::new(2);
                let z = c64::new(x, 1.0);
                let mut bc = [c64::new(1.0, 0.0); 2];
                let ok = lc.factor_with(|i, j| if i == j { z } else { c64::new(0.5, 0.0) }).and_then(|()| lc.solve(&mut bc));
                err_or(ok, "complex factor_with+solve(hostile diagonal)", |()| bc.iter().all(|v| v.finite()));
            }
            assert!(x.size() >= 0.0 || x.is_nan());
            assert_eq!(x.finite(), x.is_finite());
            assert!(x.recip().is_nan() || x.recip() == 1.0 / x);
            // Smith's reciprocal: no overflow of |z|² at |z| ~ 1e300, z·(1/z) = 1 where 1/z is normal
            let z = c64::new(x, x);
            let rc = z.recip();
            if x.is_finite() && x.abs() > 1e-300 && x.abs() < 1e300 {
                assert!((rc * z - c64::new(1.0, 0.0)).norm() <= 4.0 * f64::EPSILON, "{z:?} {rc:?}");
            }
        }
        refused(lu.factor(&[1.0; 4]), "factor(wrong size)");
        lu.factor(&[4.0, 1.0, 0.0, 1.0, 4.0, 1.0, 0.0, 1.0, 4.0]).unwrap();
        refused(lu.solve(&mut [1.0]), "solve(wrong size)");
        refused(lu.factor(&[0.0; 9]).and_then(|()| lu.solve(&mut [1.0; 3])), "singular, then solve");
        let mut empty = DenseLu::<f64>::new(0);
        err_or(empty.factor(&[]).and_then(|()| empty.solve(&mut [])), "n = 0", |()| true);
    }

    // Lie-group methods (Munthe-Kaas, Crouch–Grossman): the rotor stays unit; NaN angular
    // velocities are refused.
    lie_methods ["integrate_lie", "LieMethod::name", "LieMethod::order", "dexpinv", "LieGroup::exp", "LieGroup::compose",
        "LieGroup::bracket", "LieGroup::axpy", "LieGroup::scale", "LieGroup::magnitude", "LieGroup::algebra_magnitude",
        "quaternion_exact_step"] {
        let a = Frame::new();
        for m in [LieMethod::Rkmk4, LieMethod::ExponentialEuler, LieMethod::CrouchGrossman3] {
            assert!(!m.name().is_empty() && m.order() >= 1);
            for w in hostile() {
                err_or(integrate_lie(m, move |_, _r: &Rotor| a.vector([0.0, 0.0, w]), 0.0, &Rotor::identity(), 1.0, 10, |_, _| {}), "integrate_lie", |(r, _)| {
                    (r.norm() - 1.0).abs() <= 1e-12
                });
            }
            refused(integrate_lie(m, |_, _r: &Rotor| a.k(), 0.0, &Rotor::identity(), f64::NAN, 10, |_, _| {}), "integrate_lie(NaN t1)");
        }
        let x = a.vector([0.1, 0.2, 0.3]);
        let r = <Rotor as LieGroup>::exp(&x);
        // magnitude = max(|s|, |B|) of a unit rotor: in [1/√2, 1]
        assert!(r.magnitude() >= 0.5f64.sqrt() - 1e-15 && r.magnitude() <= 1.0 + 1e-15);
        assert!(r.compose(&r).norm().is_finite() && <Rotor as LieGroup>::algebra_magnitude(&x).is_finite());
        let _: Vector = <Rotor as LieGroup>::bracket(&x, &x);
        assert!(<Rotor as LieGroup>::axpy(&x, 2.0, &x).is_finite() && <Rotor as LieGroup>::scale(2.0, &x).is_finite());
        assert!(dexpinv::<Rotor>(&x, &x).is_finite());
        for h in hostile() {
            let q = quaternion_exact_step(&Vector4::new(1.0, 0.0, 0.0, 0.0), &Vector3::new(0.0, 0.0, 1.0), h);
            if h.is_finite() && h.abs() < 1e300 {
                assert!((q.norm() - 1.0).abs() <= 1e-14, "quaternion_exact_step({h}) = {q}");
            }
        }
    }

    // The accuracy table (docs/accuracy.md): tolerances outside (0, ∞) and below the strictest
    // target are refused.
    accuracy_table ["Accuracy::row", "Accuracy::solver", "Accuracy::solve"] {
        for tol in hostile().chain([-1.0, 1e-30]) {
            err_or(Accuracy::RelTol(tol).row(), "Accuracy::row", |r| r.rtol.is_finite() && r.rtol > 0.0);
            err_or(Accuracy::RelTol(tol).solver(), "Accuracy::solver", |_| tol.is_finite() && tol > 0.0);
            err_or(Accuracy::RelTol(tol).solve(|_, y: &Vec<f64>| vec![-y[0]], 0.0, &vec![1.0], 1.0), "Accuracy::solve", |s| fin(s.last()));
        }
    }

    // The work–precision harness: references are exact solutions (elliptic functions within
    // their documented domain, Kepler's equation with a bounded Newton loop); sweeps report
    // finite errors; empty inputs give empty outputs.
    work_precision_harness ["harness::elliptic::elliptic_k", "harness::elliptic::sncndn", "Kepler::eccentric_anomaly",
        "Reference::name", "Reference::y0", "Reference::t_end", "Reference::rhs", "Reference::exact", "Reference::error",
        "Reference::drift", "Separable::accel", "RigidBody::exact_omega", "RigidBody::energy", "RigidBody::momentum",
        "RigidBody::drift", "RigidBody::lie_rhs", "RigidBody::lie_y0", "RigidBody::lie_error", "euler_equations",
        "quaternion_rate", "Method::name", "Method::order", "sweep", "sweep_verlet", "sweep_lie", "run_all", "cheapest",
        "derive_accuracy"] {
        for m in hostile().chain([0.5, 1.0, 2.0]) {
            err_or(elliptic_k(m).ok_or(()), "elliptic_k", |k| k.is_finite() && *k >= std::f64::consts::FRAC_PI_2);
            err_or(sncndn(0.3, m).ok_or(()), "sncndn", |(s, c, d)| (s * s + c * c - 1.0).abs() <= 1e-14 && d.is_finite());
            err_or(sncndn(m, 0.5).ok_or(()), "sncndn(u)", |(s, c, _)| (s * s + c * c - 1.0).abs() <= 1e-14);
            for e in [0.0, 0.5, 0.99, 1.5, f64::NAN] {
                let ea = Kepler { e }.eccentric_anomaly(m);
                if m.is_finite() && (0.0..1.0).contains(&e) {
                    // E − e sin E = M (mod 2π)
                    let r = (ea - e * ea.sin() - m.rem_euclid(2.0 * std::f64::consts::PI)).abs();
                    assert!(r <= 1e-12 * m.abs().max(1.0) || m.abs() > 1e15, "Kepler e={e} M={m}: {r}");
                }
            }
        }
        let osc = Oscillator;
        assert!(!osc.name().is_empty() && osc.t_end() > 0.0);
        assert!(osc.error(&osc.exact(osc.t_end())) == 0.0 && osc.rhs(0.0, &osc.y0()).iter().all(|c| c.is_finite()));
        assert!(osc.drift(&osc.y0()).is_none_or(|d| d.iter().all(|c| c.is_finite())));
        assert_eq!(osc.error(&Vector2::new(f64::NAN, 0.0)), f64::INFINITY);
        assert!(Separable::<1>::accel(&osc, &SVector::<f64, 1>::new(1.0))[0] == -1.0);
        let rb = RigidBody::default();
        let w = rb.exact_omega(1.0);
        assert!(w.iter().all(|c| c.is_finite()) && rb.energy(&w).is_finite() && rb.momentum(&w).is_finite());
        assert!(rb.drift(&w, 1.0).iter().all(|c| c.is_finite()));
        let a = Frame::new();
        let y0 = rb.lie_y0(&a);
        let f = rb.lie_rhs(&a);
        let (d0, d1) = f(0.0, &y0);
        assert!(d0.is_finite() && d1.is_finite());
        let (e, drift) = rb.lie_error(&a, &y0);
        assert!(e.is_finite() && drift.iter().all(|c| c.is_finite()));
        assert!(euler_equations(&rb.inertia, &w).iter().all(|c| c.is_finite()));
        assert!(quaternion_rate(&Vector4::new(1.0, 0.0, 0.0, 0.0), &w).iter().all(|c| c.is_finite()));
        let m = Method::Fixed(RK4);
        assert!(!m.name().is_empty() && m.order() == 4);
        let pts = sweep(&osc, m, Budget::Quick);
        assert!(!pts.is_empty() && pts.iter().all(|p| p.error.is_finite() && p.error >= 0.0));
        assert!(sweep_verlet::<2, 1, _>(&osc, Budget::Quick).iter().all(|p| p.error.is_finite()));
        assert!(sweep_lie(&rb, LieMethod::Rkmk4, Budget::Quick).iter().all(|p| p.error.is_finite()));
        assert!(cheapest(&pts, "no such problem", 1e-6).is_none() && cheapest(&[], "x", f64::NAN).is_none());
        assert!(derive_accuracy(&[]).is_empty());
        let _ = run_all as fn(Budget) -> Vec<vectrix::ode::harness::Point>;
        let _ = Vector3::<f64>::zeros();
    }

    // In-place right-hand sides (`InPlace`, issue 32): hostile states and ends are refused or
    // give finite answers through every constructor; an in-place f that writes NaN or changes
    // the state's length is refused with a typed error; on the stiff y′ = −1000(y − cos t) the
    // in-place and returning forms take the same steps to the bit in every method; `Rhs::call`
    // and `Rhs::call_into` give the closure's own value for every hostile input.
    in_place ["Stepper::new_in_place", "RadauStepper::new_in_place", "BdfStepper::new_in_place",
        "AnyStepper::new_in_place", "Rhs::call", "Rhs::call_into"] {
        use vectrix::ode::explicit::Stepper;
        use vectrix::ode::{AnyStepper, Bdf, BdfStepper, InPlace, Method as OdeMethod, Radau5, RadauStepper, Rhs};
        let f = |t: f64, y: &Vec<f64>| vec![-1000.0 * (y[0] - t.cos())];
        let g = |t: f64, y: &Vec<f64>, out: &mut Vec<f64>| out[0] = -1000.0 * (y[0] - t.cos());
        let jac = |_: f64, _: &Vec<f64>, out: &mut [f64]| out[0] = -1000.0;
        let (r, b) = (Radau5::new().rtol(1e-9).atol(1e-11), Bdf::new().rtol(1e-9).atol(1e-11));
        let e = Adaptive::dopri5().rtol(1e-9).atol(1e-11);
        for x in hostile() {
            err_or(Stepper::new_in_place(&e, g, 0.0, vec![x], 1.0), "Stepper(hostile y0)", |s| fin(s.y()));
            err_or(Stepper::new_in_place(&e, g, 0.0, vec![1.0], x), "Stepper(hostile end)", |s| fin(s.y()));
            err_or(RadauStepper::new_in_place(&r, g, Some(jac), 0.0, vec![x], 1.0), "Radau(hostile y0)", |s| fin(s.y()));
            err_or(BdfStepper::new_in_place(&b, g, Some(jac), 0.0, vec![x], x), "Bdf(hostile)", |s| fin(s.y()));
            // the trait on its own: the closure's value, bit for bit, NaN included
            let (mut fr, mut gi) = (f, InPlace(g));
            let y = vec![x];
            let want = f(x, &y)[0];
            let mut out = vec![0.0];
            gi.call_into(x, &y, &mut out);
            for got in [Rhs::call(&mut fr, x, &y)[0], gi.call(x, &y)[0], out[0]] {
                assert!(got.to_bits() == want.to_bits(), "Rhs at {x}: {got} against {want}");
            }
            let mut back = vec![7.0];
            fr.call_into(x, &y, &mut back);
            assert!(back[0].to_bits() == want.to_bits());
        }
        for m in [OdeMethod::Explicit(e), OdeMethod::Explicit(Adaptive::dop853().rtol(1e-9).atol(1e-11)),
            OdeMethod::Radau5(r), OdeMethod::Bdf(b)] {
            // a NaN from f, and a length that changes, are typed errors
            let nan = |t: f64, _: &Vec<f64>, out: &mut Vec<f64>| out[0] = if t > 0.25 { f64::NAN } else { 1.0 };
            let mut s = AnyStepper::new_in_place(&m, nan, None::<fn(f64, &Vec<f64>, &mut [f64])>, 0.0, vec![1.0], 1.0).unwrap();
            let end = loop {
                if let Err(e) = s.step() { break e; }
                assert!(!s.done(), "{}: finished through a NaN", m.name());
            };
            assert!(matches!(end, OdeError::RhsNotFinite { .. } | OdeError::StepSizeUnderflow { .. }), "{}: {end:?}", m.name());
            let grow = |_: f64, _: &Vec<f64>, out: &mut Vec<f64>| { out.clear(); out.extend([1.0, 2.0]); };
            refused(AnyStepper::new_in_place(&m, grow, None::<fn(f64, &Vec<f64>, &mut [f64])>, 0.0, vec![1.0], 1.0), "f of the wrong length");
            // the same steps as the returning form, and the closed form at the end
            let mut a = AnyStepper::new(&m, f, Some(jac), 0.0, vec![1.0], 1.0).unwrap();
            let mut s = AnyStepper::new_in_place(&m, g, Some(jac), 0.0, vec![1.0], 1.0).unwrap();
            while !a.done() {
                a.step().unwrap();
                s.step().unwrap();
                assert!(a.t().to_bits() == s.t().to_bits() && a.y()[0].to_bits() == s.y()[0].to_bits(), "{}", m.name());
            }
            assert!(s.done() && (s.y()[0] - stiff_exact(1.0)).abs() <= 1e-7, "{}: {}", m.name(), s.y()[0]);
        }
    }

    // Right-hand sides that evaluate two states at once (`Rhs::pairs`, `Rhs::call_pair_into`):
    // a closure's default pair is its own two values, bit for bit, NaN and ∞ included; GBS
    // through `solve_rhs` and `AnyStepper::with_rhs` refuses hostile settings, states and ends
    // as `solve` does, and otherwise takes the steps of `solve` to the bit, also when the
    // second lane of every pair is broken (NaN, or a state of another length).
    paired_rows ["Solver::solve_rhs", "AnyStepper::with_rhs", "Rhs::pairs", "Rhs::call_pair_into"] {
        use std::cell::Cell;
        use vectrix::ode::{AnyStepper, Extrapolation, InPlace, Method as OdeMethod, Rhs};
        struct Pairs<'a> { broken: u8, pairs: &'a Cell<usize> }
        impl Rhs<Vec<f64>> for Pairs<'_> {
            const IN_PLACE: bool = true;
            fn call(&mut self, t: f64, y: &Vec<f64>) -> Vec<f64> { vec![y[1], -y[0] + 0.1 * t.sin()] }
            fn call_into(&mut self, t: f64, y: &Vec<f64>, out: &mut Vec<f64>) { *out = self.call(t, y); }
            fn pairs(&self) -> bool { true }
            fn call_pair_into(&mut self, a: (f64, &Vec<f64>, &mut Vec<f64>), b: (f64, &Vec<f64>, &mut Vec<f64>)) {
                self.pairs.set(self.pairs.get() + 1);
                *a.2 = self.call(a.0, a.1);
                *b.2 = match self.broken { 0 => self.call(b.0, b.1), 1 => vec![f64::NAN; 2], _ => vec![1.0; 3] };
            }
        }
        let f = |t: f64, y: &Vec<f64>| vec![y[1], -y[0] + 0.1 * t.sin()];
        let g = |t: f64, y: &Vec<f64>, out: &mut Vec<f64>| *out = vec![y[1], -y[0] + 0.1 * t.sin()];
        let bits = |y: &[f64]| y.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        let (mut fr, mut gi) = (f, InPlace(g));
        assert!(!Rhs::<Vec<f64>>::pairs(&fr) && !Rhs::<Vec<f64>>::pairs(&gi));
        for x in hostile() {
            let (ya, yb) = (vec![x, 1.0], vec![0.5, x]);
            let (mut oa, mut ob) = (vec![0.0; 2], vec![0.0; 2]);
            fr.call_pair_into((x, &ya, &mut oa), (0.5, &yb, &mut ob));
            assert_eq!((bits(&oa), bits(&ob)), (bits(&f(x, &ya)), bits(&f(0.5, &yb))), "closure pair at {x}");
            gi.call_pair_into((0.5, &ya, &mut oa), (x, &yb, &mut ob));
            assert_eq!((bits(&oa), bits(&ob)), (bits(&f(0.5, &ya)), bits(&f(x, &yb))), "in-place pair at {x}");
            let pairs = Cell::new(0);
            let gbs = Extrapolation::gbs().max_steps(10_000);
            let p = || Pairs { broken: 0, pairs: &pairs };
            // (no tolerance: x is the hostile rtol, the run is refused or ends finite)
            err_or(gbs.rtol(x).solve_rhs(p(), 0.0, &vec![1.0, 0.0], 1.0), "solve_rhs(hostile rtol)", |s| fin(s.last()));
            err_or(gbs.solve_rhs(p(), 0.0, &vec![x, 0.0], 1.0), "solve_rhs(hostile y0)", |s| fin(s.last()));
            err_or(gbs.solve_rhs(p(), 0.0, &vec![1.0, 0.0], x), "solve_rhs(hostile t1)", |s| fin(s.last()));
            err_or(gbs.solve_rhs(p(), x, &vec![1.0, 0.0], 1.0), "solve_rhs(hostile t0)", |s| fin(s.last()));
            let m = OdeMethod::Gbs(gbs);
            let none = None::<fn(f64, &Vec<f64>, &mut [f64])>;
            err_or(AnyStepper::with_rhs(&m, p(), none, 0.0, vec![x, 1.0], 1.0), "with_rhs(hostile y0)", |s| fin(s.y()));
            err_or(AnyStepper::with_rhs(&m, p(), none, 0.0, vec![1.0, 1.0], x), "with_rhs(hostile end)", |s| fin(s.y()));
        }
        refused(Extrapolation::gbs().dense(true).solve_rhs(Pairs { broken: 0, pairs: &Cell::new(0) }, 0.0, &vec![1.0, 0.0], 1.0), "solve_rhs(dense)");
        let gbs = Extrapolation::gbs().rtol(1e-11).atol(1e-11);
        let plain = gbs.solve(f, 0.0, &vec![1.0, 0.0], 10.0).unwrap();
        for broken in 0..3 {
            let pairs = Cell::new(0);
            let s = gbs.solve_rhs(Pairs { broken, pairs: &pairs }, 0.0, &vec![1.0, 0.0], 10.0).unwrap();
            assert!(pairs.get() > 0 && s.t.len() == plain.t.len(), "broken lane {broken}");
            for (a, b) in s.y.iter().zip(&plain.y) {
                assert_eq!(bits(a), bits(b), "broken lane {broken}");
            }
            let m = OdeMethod::Gbs(gbs);
            let none = None::<fn(f64, &Vec<f64>, &mut [f64])>;
            let mut a = AnyStepper::new(&m, f, none, 0.0, vec![1.0, 0.0], 10.0).unwrap();
            let mut w = AnyStepper::with_rhs(&m, Pairs { broken, pairs: &pairs }, none, 0.0, vec![1.0, 0.0], 10.0).unwrap();
            while !a.done() {
                a.step().unwrap();
                w.step().unwrap();
                assert!(a.t().to_bits() == w.t().to_bits() && bits(a.y()) == bits(w.y()), "with_rhs, broken lane {broken}");
            }
        }
    }

    // Gragg–Bulirsch–Stoer extrapolation: hostile tolerances, steps, states, ends and column
    // counts are refused or give finite answers; the oscillator ends on cos/sin.
    extrapolation ["Solver::gbs", "Solver::max_columns"] {
        use vectrix::ode::Extrapolation;
        let f = |_: f64, y: &Vector2<f64>| Vector2::new(y[1], -y[0]);
        let y0 = Vector2::new(1.0, 0.0);
        for x in hostile() {
            // a step cap of 10⁴: a hostile end 1e300 away is refused after 10⁴ steps, not 10⁶
            let g = Extrapolation::gbs().max_steps(10_000);
            err_or(g.rtol(x).solve(f, 0.0, &y0, 1.0), "gbs(hostile rtol)", |s| fin(s.last().as_slice()));
            err_or(g.atol(x).solve(f, 0.0, &y0, 1.0), "gbs(hostile atol)", |s| fin(s.last().as_slice()));
            err_or(g.h0(x).h_max(x).solve(f, 0.0, &y0, 1.0), "gbs(hostile h)", |s| fin(s.last().as_slice()));
            err_or(g.solve(f, 0.0, &Vector2::new(x, 0.0), 1.0), "gbs(hostile y0)", |s| fin(s.last().as_slice()));
            err_or(g.solve(f, 0.0, &y0, x), "gbs(hostile t1)", |s| fin(s.last().as_slice()));
            err_or(g.solve(f, x, &y0, 1.0), "gbs(hostile t0)", |s| fin(s.last().as_slice()));
        }
        for km in [0, 1, 2, 13, 1000, usize::MAX] {
            refused(Extrapolation::gbs().max_columns(km).solve(f, 0.0, &y0, 1.0), "max_columns out of range");
        }
        refused(Extrapolation::gbs().dense(true).solve(f, 0.0, &y0, 1.0), "dense output");
        refused(Extrapolation::gbs().max_steps(2).solve(f, 0.0, &y0, 50.0), "max_steps(2)");
        for km in 3..=12 {
            let s = Extrapolation::gbs().max_columns(km).rtol(1e-10).atol(1e-10).solve(f, 0.0, &y0, 5.0).unwrap();
            let e = (s.last()[0] - 5f64.cos()).abs().max((s.last()[1] + 5f64.sin()).abs());
            // the global error after 5 time units: within 100× the local tolerance 1e-10 for
            // every column count (the oscillator's error stays near 1–3× tol at 9 columns)
            assert!(e <= 1e-8, "km {km}: {e}");
        }
    }

    // Extrapolation one step at a time (the scenes' `gbs`): hostile settings, states and ends are
    // refused or give finite answers; asking for an interpolant is a typed error; a restart
    // with NaN is refused and the run stays where it was; an f that turns NaN is refused.
    gbs_stepper ["GbsStepper::new", "GbsStepper::new_in_place", "GbsStepper::step", "GbsStepper::dense",
        "GbsStepper::restart", "Method::has_interpolant"] {
        use vectrix::ode::explicit::GbsStepper;
        use vectrix::ode::{AnyStepper, Extrapolation, Method as OdeMethod};
        let f = |_: f64, y: &Vec<f64>| vec![y[1], -y[0]];
        let g = |_: f64, y: &Vec<f64>, out: &mut Vec<f64>| {
            out[0] = y[1];
            out[1] = -y[0];
        };
        let cfg = Extrapolation::gbs().max_steps(10_000);
        for x in hostile() {
            fn run<F: vectrix::ode::Rhs<Vec<f64>>>(st: Result<GbsStepper<Vec<f64>, F>, OdeError>) -> Result<Vec<f64>, OdeError> {
                let mut s = st?;
                while !s.done() {
                    s.step()?;
                }
                Ok(s.y().clone())
            }
            err_or(run(GbsStepper::new(&cfg.rtol(x), f, 0.0, vec![1.0, 0.0], 1.0)), "hostile rtol", |y| fin(y));
            err_or(run(GbsStepper::new(&cfg.h0(x).h_max(x), f, 0.0, vec![1.0, 0.0], 1.0)), "hostile h", |y| fin(y));
            err_or(run(GbsStepper::new(&cfg, f, 0.0, vec![x, 0.0], 1.0)), "hostile y0", |y| fin(y));
            err_or(run(GbsStepper::new(&cfg, f, 0.0, vec![1.0, 0.0], x)), "hostile t_end", |y| fin(y));
            err_or(run(GbsStepper::new_in_place(&cfg, g, x, vec![1.0, 0.0], 1.0)), "hostile t0", |y| fin(y));
        }
        refused(GbsStepper::new(&cfg.max_columns(2), f, 0.0, vec![1.0, 0.0], 1.0), "max_columns(2)");
        let mut st = GbsStepper::new_in_place(&cfg.rtol(1e-10).atol(1e-10), g, 0.0, vec![1.0, 0.0], 2.0).unwrap();
        assert!(matches!(st.dense(), Err(OdeError::NoInterpolant { method: "gbs" })), "dense before a step");
        st.step().unwrap();
        assert!(matches!(st.dense(), Err(OdeError::NoInterpolant { .. })), "dense after a step");
        let (t, y) = (st.t(), st.y().clone());
        refused(st.restart(t, vec![f64::NAN, 0.0]), "restart with NaN");
        refused(st.restart(t, vec![1.0]), "restart of another length");
        refused(st.restart(3.0, y.clone()), "restart past the end");
        assert!(st.t() == t && st.y() == &y, "a refused restart moved the run");
        while !st.done() {
            st.step().unwrap();
        }
        // after the refused restarts the run goes on as before: on cos/sin at t = 2 within 100×
        // the local tolerance 1e-10 (the `extrapolation` case's bound)
        let e = (st.y()[0] - 2f64.cos()).abs().max((st.y()[1] + 2f64.sin()).abs());
        assert!(e < 1e-8, "gbs stepper: error {e:e} at t = 2");
        // f turns NaN past t = 0.5: refused, never stepped past it
        let nan_late = |t: f64, y: &Vec<f64>| vec![y[1], if t > 0.5 { f64::NAN } else { -y[0] }];
        let mut st = GbsStepper::new(&cfg, nan_late, 0.0, vec![1.0, 0.0], 2.0).unwrap();
        let err = loop {
            match st.step() {
                Ok(()) => assert!(st.t() <= 0.5, "stepped to {} past the NaN", st.t()),
                Err(e) => break e,
            }
        };
        assert!(matches!(err, OdeError::RhsNotFinite { .. }), "{err}");
        let m = OdeMethod::Gbs(cfg);
        assert!(!m.has_interpolant() && !m.is_implicit() && m.name() == "gbs");
        assert!(OdeMethod::Explicit(Adaptive::dop853()).has_interpolant());
        let mut a = AnyStepper::new(&m, f, None::<fn(f64, &Vec<f64>, &mut [f64])>, 0.0, vec![1.0, 0.0], 1.0).unwrap();
        a.step().unwrap();
        assert!(matches!(a.dense(), Err(OdeError::NoInterpolant { .. })), "AnyStepper::dense of gbs");
    }

    // Verner's 9(8) pair: hostile settings, states and ends are refused or solved finitely; it
    // keeps no interpolant, so dense output and events are refused up front with a typed error
    // (never a step taken first), and the stepper's dense() likewise; a scene-style run lands on
    // its times with set_end; an f that turns NaN is refused before it is stepped past.
    adaptive_vern9 ["Solver::vern9"] {
        use vectrix::ode::explicit::Stepper;
        use vectrix::ode::{AnyStepper, Method as OdeMethod};
        let f = |_: f64, y: &Vec<f64>| vec![y[1], -y[0]];
        let cfg = Adaptive::vern9().max_steps(20_000);
        for x in hostile() {
            err_or(cfg.solve(f, 0.0, &vec![x, 0.0], 1.0), "hostile y0", |s| fin(s.last()));
            err_or(cfg.solve(f, 0.0, &vec![1.0, 0.0], x), "hostile t1", |s| fin(s.last()));
            err_or(cfg.rtol(x).solve(f, 0.0, &vec![1.0, 0.0], 1.0), "hostile rtol", |s| fin(s.last()));
            err_or(cfg.atol(x).solve(f, 0.0, &vec![1.0, 0.0], 1.0), "hostile atol", |s| fin(s.last()));
            err_or(cfg.h0(x).h_max(x).solve(f, 0.0, &vec![1.0, 0.0], 1.0), "hostile h", |s| fin(s.last()));
        }
        let mut calls = 0;
        let counting = |_: f64, y: &Vec<f64>| {
            calls += 1;
            vec![y[1], -y[0]]
        };
        assert!(matches!(cfg.dense(true).solve(counting, 0.0, &vec![1.0, 0.0], 1.0), Err(OdeError::NoInterpolant { method: "vern9" })));
        assert_eq!(calls, 0, "vern9 with dense output evaluated f before refusing");
        let mut events = [Event::new(|_, y: &Vec<f64>| y[0])];
        assert!(matches!(cfg.solve_with_events(f, 0.0, &vec![1.0, 0.0], 1.0, &mut events), Err(OdeError::NoInterpolant { .. })));
        refused(cfg.solve(|_, _y: &Vec<f64>| vec![1.0], 0.0, &vec![1.0, 0.0], 1.0), "short right-hand side");
        let mut st = Stepper::new(&cfg.rtol(1e-12).atol(1e-12), f, 0.0, vec![1.0, 0.0], 0.5).unwrap();
        st.step().unwrap();
        assert!(matches!(st.dense(), Err(OdeError::NoInterpolant { method: "vern9" })), "stepper dense");
        for k in 1..=4 {
            let tk = 0.5 * k as f64;
            if k > 1 {
                st.set_end(tk).unwrap();
            }
            while !st.done() {
                st.step().unwrap();
            }
            // on cos/sin at every landing time within 100× the local tolerance 1e-12
            let e = (st.y()[0] - tk.cos()).abs().max((st.y()[1] + tk.sin()).abs());
            assert!(st.t() == tk && e < 1e-10, "landing {k}: t = {}, error {e:e}", st.t());
        }
        let nan_late = |t: f64, y: &Vec<f64>| vec![y[1], if t > 0.5 { f64::NAN } else { -y[0] }];
        let mut st = Stepper::new(&cfg, nan_late, 0.0, vec![1.0, 0.0], 2.0).unwrap();
        let err = loop {
            match st.step() {
                Ok(()) => assert!(st.t() <= 0.5, "stepped to {} past the NaN", st.t()),
                Err(e) => break e,
            }
        };
        assert!(matches!(err, OdeError::RhsNotFinite { .. }), "{err}");
        let m = OdeMethod::Explicit(cfg);
        assert!(!m.has_interpolant() && !m.is_implicit() && m.name() == "vern9");
        let mut a = AnyStepper::new(&m, f, None::<fn(f64, &Vec<f64>, &mut [f64])>, 0.0, vec![1.0, 0.0], 1.0).unwrap();
        a.step().unwrap();
        assert!(matches!(a.dense(), Err(OdeError::NoInterpolant { .. })), "AnyStepper::dense of vern9");
    }

    // The Taylor method: hostile tolerances, steps, states, ends and orders are refused or give
    // finite answers; each elementary function of the series at a hostile state is refused or
    // finite, at its singular point (√ and ln at 0, x^−1.5 at 0, e^x past overflow, a blow-up)
    // refused, and on the ODE it solves in closed form (y′ = g(y)) it ends on that solution.
    taylor ["Solver::order", "Solver::effective_order", "TaylorRhs::eval", "Var::constant", "Var::sqrt",
        "Var::powf", "Var::exp", "Var::ln", "Var::sin", "Var::cos", "Var::sin_cos", "Var::square"] {
        use vectrix::ode::taylor::{Taylor, TaylorRhs, Var};
        use nalgebra::Vector1;
        struct Osc;
        impl TaylorRhs<2> for Osc {
            fn eval<'a>(&self, _: Var<'a>, y: &[Var<'a>; 2]) -> [Var<'a>; 2] {
                [y[1], -y[0]]
            }
        }
        /// y′ = g(y) for one function g of the series.
        struct One(fn(Var<'_>) -> Var<'_>);
        impl TaylorRhs<1> for One {
            fn eval<'a>(&self, _: Var<'a>, y: &[Var<'a>; 1]) -> [Var<'a>; 1] {
                [(self.0)(y[0])]
            }
        }
        let y0 = Vector2::new(1.0, 0.0);
        // (g, y(0), the closed-form y(1)) for every function of the series
        let e = std::f64::consts::E;
        let cases: [(One, f64, f64); 9] = [
            (One(|v| v.constant(2.0)), 1.0, 3.0),
            (One(|v| v.sqrt()), 1.0, 2.25),
            (One(|v| v.powf(-1.0)), 1.0, 3f64.sqrt()),
            (One(|v| (-v).exp()), 0.0, 2f64.ln()),
            (One(|v| v * v.ln()), e, e.exp()),
            (One(|v| v.sin()), std::f64::consts::FRAC_PI_2, 2.0 * e.atan()),
            (One(|v| v.cos()), 0.0, 2.0 * (0.5f64).tanh().atan()),
            (One(|v| v.sin_cos().1), 0.0, 2.0 * (0.5f64).tanh().atan()),
            (One(|v| -v.square()), 1.0, 0.5),
        ];
        for (g, a, end) in &cases {
            let s = Taylor::new().rtol(1e-12).atol(1e-12).solve(g, 0.0, &Vector1::new(*a), 1.0).unwrap();
            // 100× the local tolerance over one time unit
            assert!((s.last()[0] - end).abs() <= 1e-10 * end.abs().max(1.0), "y(0) = {a}: {} vs {end}", s.last()[0]);
        }
        for x in hostile() {
            // a step cap of 10⁴: a hostile end 1e300 away is refused after 10⁴ steps, not 10⁶
            let t = Taylor::new().max_steps(10_000);
            err_or(t.rtol(x).solve(&Osc, 0.0, &y0, 1.0), "taylor(hostile rtol)", |s| fin(s.last().as_slice()));
            err_or(t.atol(x).solve(&Osc, 0.0, &y0, 1.0), "taylor(hostile atol)", |s| fin(s.last().as_slice()));
            err_or(t.h0(x).h_max(x).solve(&Osc, 0.0, &y0, 1.0), "taylor(hostile h)", |s| fin(s.last().as_slice()));
            err_or(t.solve(&Osc, 0.0, &Vector2::new(x, 0.0), 1.0), "taylor(hostile y0)", |s| fin(s.last().as_slice()));
            err_or(t.solve(&Osc, 0.0, &y0, x), "taylor(hostile t1)", |s| fin(s.last().as_slice()));
            err_or(t.solve(&Osc, x, &y0, 1.0), "taylor(hostile t0)", |s| fin(s.last().as_slice()));
            let p = Taylor::new().rtol(x).atol(x).effective_order();
            assert!((4..=30).contains(&p), "effective_order at tolerance {x}: {p}");
            for (g, _, _) in &cases {
                err_or(t.solve(g, 0.0, &Vector1::new(x), 1.0), "taylor(g, hostile y0)", |s| fin(s.last().as_slice()));
            }
        }
        for p in [0, 1, 61, 1000, usize::MAX] {
            refused(Taylor::new().order(p).solve(&Osc, 0.0, &y0, 1.0), "order out of range");
        }
        let singular: [(One, f64, &str); 5] = [
            (One(|v| v.sqrt()), 0.0, "√y at 0"),
            (One(|v| v.ln()), 0.0, "ln y at 0"),
            (One(|v| v.powf(-1.5)), 0.0, "y^−1.5 at 0"),
            (One(|v| v.exp()), 710.0, "e^y past overflow"),
            (One(|v| v.square()), 1.0, "y′ = y² blows up at t = 1"),
        ];
        for (g, a, what) in &singular {
            refused(Taylor::new().max_steps(10_000).solve(g, 0.0, &Vector1::new(*a), 2.0), what);
        }
    }
}
