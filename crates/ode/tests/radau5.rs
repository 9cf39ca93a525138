//! RADAU5 (Radau IIA 5 with Hairer–Wanner's control) against closed forms and stored
//! references: a stiff damped spring chain's modal solution, a pendulum on a stiff spring
//! against the rigid period with its O(mg/k) correction, Robertson's kinetics against scipy
//! Radau at rtol = 1e-13 (tests/data/stiff_reference.json, made by
//! scripts/stiff_reference.py), Van der Pol at ε = 1e-6 (μ = 1000) against the published Test
//! Set reference, the order of convergence, dense output, events located on
//! it, and the typed errors of the stiff failure modes.
//!
//! Book: §4.11; HW = Hairer & Wanner, *Solving ODEs II*, §IV.1 (test problems), §IV.5, §IV.8.

use std::f64::consts::PI;

use nalgebra::{DVector, SVector, Vector2, Vector3};
use vectrix_ode::{Direction, Event, OdeError, Radau5};

mod support;
use support::{nan_max, reference, rel_err, robertson, robertson_jac, vdpol, vdpol_jacobian};

/// A chain of `N` equal masses m between two walls, N + 1 springs k and dampers c = αk in
/// parallel (Rayleigh damping C = αK): ẍ = −(k/m)(L x) − (αk/m)(L ẋ), L = tridiag(−1, 2, −1).
/// L's eigenvalues are λⱼ = 4 sin²(jπ/(2(N+1))) with eigenvectors φⱼᵢ = sin(ijπ/(N+1)), so every
/// mode is a damped oscillator q̈ + α ω² q̇ + ω² q = 0, ω² = (k/m)λⱼ, solved in closed form.
const N: usize = 6;
const K_OVER_M: f64 = 1e6;
const ALPHA: f64 = 1e-2;

fn chain_rhs(_: f64, y: &SVector<f64, 12>) -> SVector<f64, 12> {
    let mut d = SVector::<f64, 12>::zeros();
    let lap = |v: &[f64], i: usize| {
        let l = if i > 0 { v[i - 1] } else { 0.0 };
        let r = if i + 1 < N { v[i + 1] } else { 0.0 };
        2.0 * v[i] - l - r
    };
    let (x, v) = (&y.as_slice()[..N], &y.as_slice()[N..]);
    for i in 0..N {
        d[i] = v[i];
        d[N + i] = -K_OVER_M * lap(x, i) - ALPHA * K_OVER_M * lap(v, i);
    }
    d
}

fn chain_jac(_: f64, _: &SVector<f64, 12>, j: &mut [f64]) {
    j.fill(0.0);
    let n = 2 * N;
    for i in 0..N {
        j[i * n + N + i] = 1.0;
        for (c, w) in [(i as isize - 1, -1.0), (i as isize, 2.0), (i as isize + 1, -1.0)] {
            if (0..N as isize).contains(&c) {
                let c = c as usize;
                j[(N + i) * n + c] = -K_OVER_M * w;
                j[(N + i) * n + N + c] = -ALPHA * K_OVER_M * w;
            }
        }
    }
}

/// The modal closed form at time t from x(0) = x0, ẋ(0) = 0.
fn chain_exact(x0: &[f64], t: f64) -> Vec<f64> {
    let mut x = vec![0.0; N];
    let norm = 2.0 / (N as f64 + 1.0); // Σᵢ φⱼᵢ² = (N+1)/2
    for j in 1..=N {
        let phi: Vec<f64> = (1..=N).map(|i| (PI * (i * j) as f64 / (N as f64 + 1.0)).sin()).collect();
        let q0: f64 = norm * phi.iter().zip(x0).map(|(p, x)| p * x).sum::<f64>();
        let w2 = K_OVER_M * 4.0 * (PI * j as f64 / (2.0 * (N as f64 + 1.0))).sin().powi(2);
        let zeta_w = 0.5 * ALPHA * w2; // ζω
        let disc = w2 - zeta_w * zeta_w;
        // q = q0 e^{−ζωt}(cos ωd t + (ζω/ωd) sin ωd t) (underdamped) or the overdamped form
        let q = if disc > 0.0 {
            let wd = disc.sqrt();
            q0 * (-zeta_w * t).exp() * ((wd * t).cos() + zeta_w / wd * (wd * t).sin())
        } else {
            let s = (-disc).sqrt();
            let (r1, r2) = (-zeta_w + s, -zeta_w - s);
            q0 * (r2 * (r1 * t).exp() - r1 * (r2 * t).exp()) / (r2 - r1)
        };
        for i in 0..N {
            x[i] += q * phi[i];
        }
    }
    x
}

#[test]
fn stiff_damped_chain_matches_the_modal_solution() {
    let mut y0 = SVector::<f64, 12>::zeros();
    let x0 = [1e-3, -2e-3, 0.5e-3, 1.5e-3, 0.0, -1e-3];
    y0.as_mut_slice()[..N].copy_from_slice(&x0);
    // the slowest mode (ω ≈ 445/s, ζ ≈ 2.2) decays over ~0.01 s; the fastest (ω ≈ 1950/s) is
    // overdamped with a rate up to αω² ≈ 4e4/s: stiff
    for t_end in [1e-3, 2e-2] {
        let sol = Radau5::new()
            .rtol(1e-8)
            .atol(1e-12)
            .solve_with_jacobian(chain_rhs, chain_jac, 0.0, &y0, t_end)
            .unwrap();
        let exact = chain_exact(&x0, t_end);
        let err = nan_max((0..N).map(|i| (sol.last()[i] - exact[i]).abs()));
        // global error within 10× rtol of the 2e-3 amplitude
        assert!(err <= 10.0 * 1e-8 * 2e-3, "t = {t_end}: error {err:e}, {}", sol.work);
    }
}

#[test]
fn robertson_matches_the_stored_reference() {
    for name in ["robertson_40", "robertson_1e5"] {
        let (t_end, want, unc) = reference(name);
        let y0 = Vector3::new(1.0, 0.0, 0.0);
        // atol scaled to y₂ ~ 1e-5 (the fast intermediate), as HW do
        let sol = Radau5::new()
            .rtol(1e-10)
            .atol(1e-16)
            .solve_with_jacobian(robertson, robertson_jac, 0.0, &y0, t_end)
            .unwrap();
        let err = rel_err(sol.last().as_slice(), &want);
        assert!(unc < 1e-9, "{name}: reference uncertainty {unc:e}");
        // relative error of every component (y₂ included) within 100 × rtol
        assert!(err < 1e-8, "{name}: relative error {err:e} ({})", sol.work);
        // and the finite-difference route says so in its work
        let fd = Radau5::new().rtol(1e-10).atol(1e-16).solve(robertson, 0.0, &y0, t_end).unwrap();
        assert!(rel_err(fd.last().as_slice(), &want) < 1e-8);
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
    for (rtol, bound) in [(1e-6, 1e-4), (1e-9, 1e-7)] {
        let sol = Radau5::new()
            .rtol(rtol)
            .atol(rtol)
            .solve_with_jacobian(vdpol, vdpol_jacobian, 0.0, &Vector2::new(2.0, 0.0), 2.0)
            .unwrap();
        let err = rel_err(sol.last().as_slice(), &want);
        // the global error through a relaxation jump: within 100 × rtol
        assert!(err < bound, "rtol {rtol:e}: relative error {err:e} ({})", sol.work);
        // an explicit method needs ≳ 2/(ε·3.3) ≈ 6e5 steps here; RADAU5 a few hundred
        assert!(sol.work.accepted < 5000, "{}", sol.work);
    }
}

#[test]
fn order_five_on_a_smooth_problem_at_fixed_steps() {
    // y″ = −y with loose tolerances and h₀ = h_max = h: every step accepted at size h, so
    // the end error follows C h⁵ (HW Table IV.5.6: Radau IIA s = 3 has order 2s − 1 = 5)
    let f = |_: f64, y: &Vector2<f64>| Vector2::new(y[1], -y[0]);
    let err = |h: f64| {
        let sol = Radau5::new()
            .rtol(0.5)
            .atol(0.5)
            .h0(h)
            .h_max(h)
            .solve(f, 0.0, &Vector2::new(1.0, 0.0), 4.0)
            .unwrap();
        assert_eq!(sol.work.rejected, 0);
        assert_eq!(sol.work.accepted, (4.0 / h).round() as usize);
        (sol.last()[0] - 4f64.cos()).abs().max((sol.last()[1] + 4f64.sin()).abs())
    };
    let (e1, e2) = (err(0.2), err(0.1));
    let slope = (e1 / e2).log2();
    assert!((4.7..5.3).contains(&slope), "observed order {slope} (errors {e1:e}, {e2:e})");
}

#[test]
fn dense_output_is_the_order_three_collocation_polynomial() {
    // y″ = −y at fixed steps h: the collocation polynomial of degree 3 interpolates with a
    // local error O(h⁴) (stage order 3, HW §IV.8 "dense output"), while the step ends carry
    // the order-5 error; the largest error at off-node times must fall like h⁴
    let f = |_: f64, y: &Vector2<f64>| Vector2::new(y[1], -y[0]);
    let err = |h: f64| {
        let sol = Radau5::new()
            .rtol(0.5)
            .atol(0.5)
            .h0(h)
            .h_max(h)
            .dense(true)
            .solve(f, 0.0, &Vector2::new(1.0, 0.0), 4.0)
            .unwrap();
        assert!(matches!(sol.sample(4.5), Err(OdeError::OutOfRange { .. })));
        nan_max((0..400).map(|k| {
            let t = 0.01 * k as f64 + 0.0037;
            (sol.sample(t).unwrap()[0] - t.cos()).abs()
        }))
    };
    let (e1, e2) = (err(0.2), err(0.1));
    let slope = (e1 / e2).log2();
    assert!((3.6..4.6).contains(&slope), "dense-output order {slope} (errors {e1:e}, {e2:e})");
    assert!(e2 < 1e-5, "{e2:e}");
}

#[test]
fn events_are_located_on_the_collocation_polynomial() {
    // same problem: y = 0 where cos t + 1e-3 sin t = 0 (the transient long gone), i.e.
    // t* = π/2 + atan(1e-3); terminal, falling
    let f = |t: f64, y: &f64| -1000.0 * (y - t.cos());
    let mut ev = [Event::new(|_, y: &f64| *y).direction(Direction::Falling).terminal(true)];
    let sol = Radau5::new().rtol(1e-10).atol(1e-12).solve_with_events(f, 0.0, &0.5, 10.0, &mut ev).unwrap();
    let t_star = PI / 2.0 + 1e-3f64.atan();
    assert!(sol.terminated);
    assert_eq!(sol.events.len(), 1);
    assert!((sol.events[0].t - t_star).abs() < 1e-8, "event at {} vs {t_star}", sol.events[0].t);
    assert!((sol.t.last().unwrap() - t_star).abs() < 1e-8);
}

#[test]
fn nan_in_the_jacobian_is_a_typed_error_naming_t_and_the_state() {
    let f = |_: f64, y: &Vector2<f64>| Vector2::new(y[1], -y[0]);
    let jac = |_: f64, _: &Vector2<f64>, j: &mut [f64]| j.copy_from_slice(&[0.0, 1.0, f64::NAN, 0.0]);
    let e = Radau5::new().solve_with_jacobian(f, jac, 0.0, &Vector2::new(1.0, 0.0), 1.0).unwrap_err();
    match &e {
        OdeError::JacobianNotFinite { t, row: 1, col: 0, value, state } => {
            assert_eq!(*t, 0.0);
            assert!(value.is_nan());
            assert_eq!(state, &vec![1.0, 0.0]);
        }
        other => panic!("expected JacobianNotFinite, got {other}"),
    }
    assert!(e.to_string().contains("[1, 0]"), "{e}");
}

#[test]
fn a_numerically_singular_iteration_matrix_is_a_typed_error() {
    // J = 2¹⁰⁰·[[1, 1], [1, 1]]: (γ/h)I − J rounds to −J (γ/h ≈ 3.6/h is below half an ulp
    // of 2¹⁰⁰ for h > 1e-13), exactly singular in floating point (a power of two keeps the
    // elimination exact); the step halves ten times, then the error names t and the state
    let f = |_: f64, y: &Vector2<f64>| Vector2::new(-y[0], -y[1]);
    let jac = |_: f64, _: &Vector2<f64>, j: &mut [f64]| j.fill(2f64.powi(100));
    let e = Radau5::new().solve_with_jacobian(f, jac, 0.0, &Vector2::new(1.0, 2.0), 1.0).unwrap_err();
    assert!(
        matches!(&e, OdeError::SingularIterationMatrix { t, state, .. } if *t == 0.0 && state == &vec![1.0, 2.0]),
        "{e}"
    );
}

#[test]
fn newton_failing_to_converge_is_a_typed_error_not_a_hang() {
    // f = −1e8 y but the Jacobian says +1e8: simplified Newton diverges until h < ~1e-8; ten
    // consecutive failures (h₀ = 1e-3 halved ten times) end the run with the state
    let f = |_: f64, y: &f64| -1e8 * y;
    let jac = |_: f64, _: &f64, j: &mut [f64]| j[0] = 1e8;
    let e = Radau5::new().h0(1e-3).solve_with_jacobian(f, jac, 0.0, &1.0, 1.0).unwrap_err();
    assert!(
        matches!(&e, OdeError::NewtonStalled { t, failures: 10, state, .. } if *t == 0.0 && state == &vec![1.0]),
        "{e}"
    );
}

#[test]
fn bad_input_is_refused() {
    let f = |_: f64, y: &f64| -y;
    assert!(matches!(
        Radau5::new().rtol(0.0).solve(f, 0.0, &1.0, 1.0),
        Err(OdeError::NonPositiveTolerance { .. })
    ));
    assert!(matches!(Radau5::new().solve(f, 1.0, &1.0, 0.0), Err(OdeError::InvalidInterval { .. })));
    assert!(matches!(Radau5::new().solve(f, 0.0, &f64::NAN, 1.0), Err(OdeError::NonFiniteState { .. })));
    assert!(matches!(
        Radau5::new().max_newton(0).solve(f, 0.0, &1.0, 1.0),
        Err(OdeError::NonPositiveTolerance { name: "max_newton", .. })
    ));
    assert!(matches!(
        Radau5::new().max_steps(3).solve(f, 0.0, &1.0, 1e6),
        Err(OdeError::TooManySteps { max_steps: 3, .. })
    ));
    // heap states work the same
    let g = |_: f64, y: &DVector<f64>| -y.clone();
    let sol = Radau5::new().rtol(1e-9).solve(g, 0.0, &DVector::from_element(3, 1.0), 1.0).unwrap();
    assert!(nan_max(sol.last().iter().map(|v| (v - (-1f64).exp()).abs())) < 1e-8);
}

#[test]
fn stiff_spring_pendulum_swings_with_the_rigid_period_corrected_by_the_static_stretch() {
    // A point mass m on a spring k of rest length l₀ in gravity g (Cartesian x, y, y up).
    // Linearized about the hanging equilibrium r = L = l₀ + mg/k, the swing θ and the stretch
    // decouple: L θ̈ + g θ = 0 (the spring force is radial, so it only balances gravity and
    // the centripetal term), hence T = 2π√(L/g) = 2π√(l₀/g)·(1 + mg/(2kl₀) + O((mg/kl₀)²)),
    // the rigid pendulum's period with the O(mg/k) correction; the amplitude θ₀ adds
    // θ₀²/16 (the rigid pendulum's first amplitude correction). Lynch, "The swinging spring",
    // Phys. D 2002, §2 (linear normal modes); Landau & Lifshitz, Mechanics, §25 problem.
    let (m, g, l0) = (1.0, 9.81, 1.0);
    for stretch in [1e-4, 1e-6] {
        // mg/(k l₀) = stretch: radial frequency √(k/m) is 1/√stretch times the swing's
        let k = m * g / (stretch * l0);
        let f = move |_: f64, s: &SVector<f64, 4>| {
            let r = (s[0] * s[0] + s[1] * s[1]).sqrt();
            let fr = -k * (r - l0) / (m * r);
            SVector::<f64, 4>::new(s[2], s[3], fr * s[0], fr * s[1] - g)
        };
        let theta0: f64 = 1e-3;
        let r0 = l0 + m * g * theta0.cos() / k; // radial balance at rest
        let y0 = SVector::<f64, 4>::new(r0 * theta0.sin(), -r0 * theta0.cos(), 0.0, 0.0);
        let big_l = l0 + m * g / k;
        let t_pred = 2.0 * PI * (big_l / g).sqrt() * (1.0 + theta0 * theta0 / 16.0);
        let t_rigid = 2.0 * PI * (l0 / g).sqrt() * (1.0 + theta0 * theta0 / 16.0);
        let mut ev = [Event::new(|_, s: &SVector<f64, 4>| s[0]).direction(Direction::Falling)];
        let sol = Radau5::new()
            .rtol(1e-11)
            .atol(1e-14)
            .solve_with_events(f, 0.0, &y0, 2.2 * t_pred, &mut ev)
            .unwrap();
        assert_eq!(sol.events.len(), 2, "{:?}", sol.events.iter().map(|e| e.t).collect::<Vec<_>>());
        let period = sol.events[1].t - sol.events[0].t;
        let rel = (period / t_pred - 1.0).abs();
        // the corrected period to 1e-8 (neglected: O(stretch²) and O(θ₀²·stretch) terms)
        assert!(
            rel < 1e-8 + 2.0 * stretch * stretch,
            "stretch {stretch:e}: period {period} vs {t_pred} ({rel:e}), {}",
            sol.work
        );
        // and the correction is really there: the rigid period misses by ≈ stretch/2
        let miss = period / t_rigid - 1.0;
        assert!((miss / (0.5 * stretch) - 1.0).abs() < 0.02, "stretch {stretch:e}: rigid miss {miss:e}");
    }
}
