//! §15.8–15.9, §15.13, §15.15: time responses by exact discretisation; problems 15.20.9,
//! 15.20.22–23 and 15.20.32.

use super::*;

#[test]
fn example_15_13_3_and_problem_15_20_32_nonminimum_phase_undershoot() {
    // Ex 15.13.3: step f₀ into (s − z)/(s² + 2ζωn s + ωn²): y∞ = −f₀z/ωn², y(0⁺) = 0,
    // ẏ(0⁺) = f₀; z > 0 gives an initial undershoot. 15.20.32: (4s − 3)/(s² + 0.8s + 4):
    // y(0⁺) = 0, ẏ(0⁺) = 4, y∞ = −0.75, poles −0.4 ± 1.96j; (C) max 1.0875 at 0.531 s,
    // min −1.7177 at 2.134 s (what the snapshot figure step_15_20_32 shows).
    let g = tf(&[4.0, -3.0], &[1.0, 0.8, 4.0]);
    let y = g.series(&tf(&[1.0], &[1.0, 0.0])).unwrap();
    assert_eq!(y.initial_values(2).unwrap(), vec![0.0, 4.0]);
    assert_eq!(y.final_value(AXIS_RTOL).unwrap(), FinalValue::Finite(-0.75));
    let p = g.poles().unwrap();
    assert_printed(p[0].re, -0.4, 2);
    assert_printed(p[0].im.abs(), 1.96, 2);
    let t = time_grid(4.0, 4001).unwrap();
    let r = g.step(&t).unwrap();
    let (kmax, ymax) = r.y[0].iter().enumerate().max_by(|a, b| a.1.total_cmp(b.1)).unwrap();
    let (kmin, ymin) = r.y[0].iter().enumerate().min_by(|a, b| a.1.total_cmp(b.1)).unwrap();
    assert_printed(*ymax, 1.0875, 4);
    assert_printed(t[kmax], 0.531, 3);
    assert_printed(*ymin, -1.7177, 4);
    assert_printed(t[kmin], 2.134, 3);
    // The sampled step agrees with the inverse transform everywhere (exact discretisation);
    // absolute, the response is of size ≤ 2.
    let exact = y.inverse_laplace(CLUSTER_RTOL).unwrap();
    for k in (0..t.len()).step_by(397) {
        assert_abs(r.y[0][k], exact.eval(t[k]), 2e3 * EPS);
    }
}

#[test]
fn eq_15_15_8_underdamped_impulse_response() {
    // (15.15.8): f₀δ into (1/m)/(s² + 2ζωn s + ωn²) gives (f₀/(mωd))e^{−ζωn t} sin ωd t.
    let (m, wn, zeta, f0) = (2.0, 3.0, 0.1, 0.7);
    let s =
        Sdof::new(m, 2.0 * zeta * wn * m, wn * wn * m).unwrap().to_state_space(SdofOutput::Position).unwrap();
    let t = time_grid(10.0, 501).unwrap();
    let r = response(&s, InputKind::Impulse, 0, f0, 0.0, &t).unwrap();
    let wd = wn * (1.0 - zeta * zeta).sqrt();
    let amp = f0 / (m * wd);
    for k in (0..t.len()).step_by(50) {
        let want = amp * (-zeta * wn * t[k]).exp() * (wd * t[k]).sin();
        // absolute in units of the initial amplitude; 500 steps of Φ each add ~ε
        assert_abs(r.y[0][k], want, 1e3 * EPS * amp);
    }
    assert_eq!(r.impulse_weight, vec![0.0]);
}

#[test]
fn eq_15_10_2_delayed_step_is_exact_off_grid() {
    // (15.10.2): a step delayed by 0.35 (not a multiple of h = 0.1) into 1/(s+1):
    // y = 1 − e^{−(t−0.35)}, exact at every sample.
    let g = tf(&[1.0], &[1.0, 1.0]).with_delay(0.35).unwrap();
    let t = time_grid(5.0, 51).unwrap();
    let r = g.step(&t).unwrap();
    for (k, &tk) in t.iter().enumerate() {
        let want = if tk < 0.35 { 0.0 } else { 1.0 - (-(tk - 0.35)).exp() };
        assert_abs(r.y[0][k], want, 64.0 * EPS);
    }
}

#[test]
fn problem_15_20_23_drb_ramp_velocity() {
    // 15.20.23: DRB, ramp f₀t, velocity output: v = f₀(−m/c² + t/c + (m/c²)e^{−ct/m}).
    let (m, c, f0) = (2.0, 0.5, 3.0);
    let sys = Sdof::new(m, c, 0.0).unwrap().to_state_space(SdofOutput::Velocity).unwrap();
    let t = time_grid(20.0, 41).unwrap();
    let r = response(&sys, InputKind::Ramp, 0, f0, 0.0, &t).unwrap();
    let vmax = f0 * 20.0 / c; // the largest velocity on the grid
    for (k, &tk) in t.iter().enumerate() {
        let want = f0 * (-m / (c * c) + tk / c + m / (c * c) * (-c * tk / m).exp());
        assert_abs(r.y[0][k], want, 1e3 * EPS * vmax);
    }
    // lsim with first-order hold of the sampled ramp is exact too, also with an off-grid delay.
    let u: Vec<f64> = t.iter().map(|&tk| f0 * tk).collect();
    let l = lsim(&sys, 0, &u, &t, &[0.0, 0.0], Hold::Foh, 0.0).unwrap();
    for k in 0..t.len() {
        assert_abs(l.y[0][k], r.y[0][k], 1e3 * EPS * vmax);
    }
    let d = 0.3; // h = 0.5
    let rd = response(&sys, InputKind::Ramp, 0, f0, d, &t).unwrap();
    let ld = lsim(&sys, 0, &u, &t, &[0.0, 0.0], Hold::Foh, d).unwrap();
    for k in 0..t.len() {
        // the off-grid breakpoint is located to 1e-9·h, which moves the response by ~1e-9·f₀h
        assert_abs(ld.y[0][k], rd.y[0][k], 1e-8 * vmax);
    }
}

#[test]
fn problem_15_20_9_first_order_free_and_forced() {
    // 15.20.8–9: ẋ = −2x + 8: x = e^{−2t}(x₀ − 4) + 4; x₀ = 5 gives e^{−2t} + 4 (ERR: the M-file
    // uses exp(−3t)).
    let sys = StateSpace::from_rows(&[&[-2.0]], &[&[8.0]], &[&[1.0]], &[&[0.0]]).unwrap();
    let t = time_grid(3.0, 31).unwrap();
    let free = initial(&sys, &[5.0], &t).unwrap();
    let forced = response(&sys, InputKind::Step, 0, 1.0, 0.0, &t).unwrap();
    for (k, &tk) in t.iter().enumerate() {
        assert_rel(free.y[0][k] + forced.y[0][k], (-2.0 * tk).exp() + 4.0, 64.0 * EPS);
    }
    // lsim with ZOH of a constant input and x₀ gives the same; and x₀ = −4: −8e^{−2t} + 4.
    let l = lsim(&sys, 0, &vec![1.0; t.len()], &t, &[5.0], Hold::Zoh, 0.0).unwrap();
    let l2 = lsim(&sys, 0, &vec![1.0; t.len()], &t, &[-4.0], Hold::Zoh, 0.0).unwrap();
    for (k, &tk) in t.iter().enumerate() {
        assert_rel(l.y[0][k], (-2.0 * tk).exp() + 4.0, 64.0 * EPS);
        assert_abs(l2.y[0][k], -8.0 * (-2.0 * tk).exp() + 4.0, 64.0 * EPS * 8.0);
    }
}

#[test]
fn problem_15_20_22_heavier_body_falls_faster_with_drag() {
    // 15.20.22: without drag v̇ = g for any mass; with the same drag D, v̇ + (D/M)v = g from rest
    // gives v = (gM/D)(1 − e^{−Dt/M}), and the heavier body is faster at every t > 0 (the book's
    // proof; D = 1, g = 9.8, M = 1 and 2 as in its M-file). The exact step responses show it.
    let (d, g) = (1.0, 9.8);
    let t = time_grid(10.0, 101).unwrap();
    let v = |m: f64| tf(&[g], &[1.0, d / m]).step(&t).unwrap().y[0].clone();
    let (v1, v2) = (v(1.0), v(2.0));
    for k in 1..t.len() {
        assert!(v2[k] > v1[k], "t = {}: {} vs {}", t[k], v2[k], v1[k]);
        for (vm, m) in [(&v1, 1.0), (&v2, 2.0)] {
            assert_abs(vm[k], g * m / d * (1.0 - (-d * t[k] / m).exp()), 256.0 * EPS * g * m / d);
        }
    }
    // without drag both accelerate at g: the same velocity gt
    let urb = |m: f64| Sdof::new(m, 0.0, 0.0).unwrap().to_state_space(SdofOutput::Velocity).unwrap();
    for m in [1.0, 2.0] {
        let r = response(&urb(m), InputKind::Step, 0, m * g, 0.0, &t).unwrap();
        assert_rel(r.y[0][100], g * 10.0, 64.0 * EPS);
    }
}

#[test]
fn eq_15_8_4_free_plus_forced_response_with_a_ramp() {
    // (15.8.3)–(15.8.4): y = Ce^{At}x₀ + ∫₀ᵗ Ce^{A(t−τ)}Bu(τ)dτ. For ẋ = −ax + bu, u(t) = t:
    // free x₀e^{−at}, forced b[t/a − (1 − e^{−at})/a²]. A first-order hold is exact for the
    // ramp, so lsim agrees to rounding, and it equals the sum of the separately computed
    // free (`initial`) and forced (`response`, Ramp) parts.
    let (a, b, x0) = (2.0, 8.0, 5.0);
    let sys = StateSpace::from_rows(&[&[-a]], &[&[b]], &[&[1.0]], &[&[0.0]]).unwrap();
    let t = time_grid(4.0, 41).unwrap();
    let l = lsim(&sys, 0, &t, &t, &[x0], Hold::Foh, 0.0).unwrap();
    let free = initial(&sys, &[x0], &t).unwrap();
    let forced = response(&sys, InputKind::Ramp, 0, 1.0, 0.0, &t).unwrap();
    for (k, &tk) in t.iter().enumerate() {
        let e = (-a * tk).exp();
        let want = x0 * e + b * (tk / a - (1.0 - e) / (a * a));
        // relative to the largest term, b·t/a ≤ 16 (the parts cancel only partly)
        let scale = x0 + b * tk / a;
        assert_abs(l.y[0][k], want, 64.0 * EPS * scale);
        assert_abs(free.y[0][k] + forced.y[0][k], want, 64.0 * EPS * scale);
    }
}

#[test]
fn sec_15_9_impulse_is_a_free_response_with_changed_velocity() {
    // §15.9: "An impulse at t = 0 imparts a nonzero initial velocity but zero change in
    // position": the response of mq̈ + cq̇ + kq = f₀δ(t) equals the free response from
    // q(0) = 0, q̇(0) = f₀/m. Definition 15.9.3: the ramp response of 1/s is t²/2.
    let (m, f0) = (2.0, 3.0);
    let sys = Sdof::new(m, 0.8, 5.0).unwrap().to_state_space(SdofOutput::Position).unwrap();
    let t = time_grid(6.0, 61).unwrap();
    let imp = response(&sys, InputKind::Impulse, 0, f0, 0.0, &t).unwrap();
    assert_eq!(imp.impulse_weight, vec![0.0]);
    let free = initial(&sys, &[0.0, f0 / m], &t).unwrap();
    for k in 0..t.len() {
        assert_abs(imp.y[0][k], free.y[0][k], 64.0 * EPS * f0 / m);
    }
    let integrator = StateSpace::from_rows(&[&[0.0]], &[&[1.0]], &[&[1.0]], &[&[0.0]]).unwrap();
    let ramp = response(&integrator, InputKind::Ramp, 0, 1.0, 0.0, &t).unwrap();
    for (k, &tk) in t.iter().enumerate() {
        assert_rel(ramp.y[0][k], tk * tk / 2.0, 16.0 * EPS);
    }
}
