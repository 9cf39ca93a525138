//! §15.10–15.13: Laplace transforms, partial fractions, initial- and final-value theorems;
//! problems 15.20.15–21, 15.20.25–26 and 15.20.28–31.

use super::*;

#[test]
fn example_15_11_4_partial_fractions_and_inverse() {
    // Ex 15.11.4: (s+2)(s+4)/(s(s+1)(s+3)) → 8/3 − 1.5e^{−t} − (1/6)e^{−3t}.
    let g = tf(&[1.0, 6.0, 8.0], &[1.0, 4.0, 3.0, 0.0]);
    let pf = g.partial_fractions(CLUSTER_RTOL).unwrap();
    let res = |p: f64| pf.terms.iter().find(|t| (t.pole.re - p).abs() < 1e-9).unwrap().residue.re;
    assert_rel(res(0.0), 8.0 / 3.0, 64.0 * EPS);
    assert_rel(res(-1.0), -1.5, 64.0 * EPS);
    assert_rel(res(-3.0), -1.0 / 6.0, 64.0 * EPS);
    let y = g.inverse_laplace(CLUSTER_RTOL).unwrap();
    for t in [0.0f64, 0.4, 2.0, 9.0] {
        let want = 8.0 / 3.0 - 1.5 * (-t).exp() - (-3.0 * t).exp() / 6.0;
        // absolute: three terms of size ≤ 8/3, each good to a few ε
        assert_abs(y.eval(t), want, 64.0 * EPS * 8.0 / 3.0);
    }
}

#[test]
fn problem_15_20_19_inverse_laplace_real_form() {
    // 15.20.19: 1/(s(s²+s+1)) → 1 − e^{−t/2}cos(√3t/2) − (1/√3)e^{−t/2}sin(√3t/2); notes (C):
    // the step response of 1/(s²+s+1) peaks at 1.1630 at t = 3.628.
    let y = tf(&[1.0], &[1.0, 1.0, 1.0, 0.0]).inverse_laplace(CLUSTER_RTOL).unwrap();
    let w = 3f64.sqrt() / 2.0;
    for t in [0.3f64, 1.0, 5.0] {
        let want = 1.0 - (-t / 2.0).exp() * ((w * t).cos() + (w * t).sin() / 3f64.sqrt());
        assert_abs(y.eval(t), want, 64.0 * EPS); // terms of size ≤ 1
    }
    // Peak: ẏ = 0 at ωd t = π, so t = 2π/√3 = 3.628 and y = 1 + e^{−π/√3} = 1.1630.
    let tp = std::f64::consts::PI / w;
    assert_printed(tp, 3.628, 3);
    assert_printed(y.eval(tp), 1.1630, 4);
    let step = tf(&[1.0], &[1.0, 1.0, 1.0]).step(&[0.0, tp]).unwrap();
    assert_rel(step.y[0][1], y.eval(tp), 1e3 * EPS);
}

#[test]
fn eq_15_15_9_repeated_pole_inverse() {
    // (15.15.9): critical damping, (1/m)/(s + ωn)² → (1/m) t e^{−ωn t}; and 2/(s+1)³ → t²e^{−t}.
    // The repeated roots split by ~√ε and ~ε^{1/3} (notes §3.2), which bounds the residues:
    // absolute errors 1e-7 and 1e-6 on values below 1.
    let y = tf(&[0.5], &[1.0, 4.0, 4.0]).inverse_laplace(CLUSTER_RTOL).unwrap();
    for t in [0.1f64, 1.0, 3.0] {
        assert_abs(y.eval(t), 0.5 * t * (-2.0 * t).exp(), 1e-7);
    }
    let y = tf(&[2.0], &[1.0, 3.0, 3.0, 1.0]).inverse_laplace(CLUSTER_RTOL).unwrap();
    for t in [0.1f64, 1.0, 3.0] {
        assert_abs(y.eval(t), t * t * (-t).exp(), 1e-6);
    }
}

#[test]
fn problem_15_20_17_harmonic_response() {
    // 15.20.17: v̇ + 2v = sin 5t (ERR: the statement says v̈ + 2v̇), v(0) = v₀:
    // v = (v₀ + 5/29)e^{−2t} − (5/29)cos 5t + (2/29)sin 5t.
    let v0 = 0.4;
    // V = (v₀(s²+25) + 5)/((s+2)(s²+25)).
    let v = tf(&[v0, 0.0, 25.0 * v0 + 5.0], &[1.0, 2.0, 25.0, 50.0]).inverse_laplace(CLUSTER_RTOL).unwrap();
    for t in [0.2f64, 1.0, 4.0] {
        let want = (v0 + 5.0 / 29.0) * (-2.0 * t).exp() - 5.0 / 29.0 * (5.0 * t).cos()
            + 2.0 / 29.0 * (5.0 * t).sin();
        assert_abs(v.eval(t), want, 256.0 * EPS);
    }
}

#[test]
fn problem_15_20_18_terminal_angular_velocity() {
    // 15.20.18: Jθ̈ + cθ̇ = τ₀·1(t) from rest: v = θ̇ = (τ₀/c)(1 − e^{−ct/J}) and the terminal
    // velocity τ₀/c, by the final-value theorem on v̂ = τ₀/(s(Js + c)) and by the exact step
    // response of 1/(Js + c).
    let (j, c, tau0) = (0.8, 2.5, 3.0);
    let v_hat = tf(&[tau0], &[j, c, 0.0]);
    assert_eq!(v_hat.final_value(AXIS_RTOL).unwrap(), FinalValue::Finite(tau0 / c));
    let t = time_grid(4.0, 41).unwrap();
    let r = tf(&[tau0], &[j, c]).step(&t).unwrap();
    for (k, &tk) in t.iter().enumerate() {
        assert_abs(r.y[0][k], tau0 / c * (1.0 - (-c * tk / j).exp()), 64.0 * EPS * tau0 / c);
    }
}

#[test]
fn problem_15_20_20_falling_body_without_drag() {
    // 15.20.20: q̈ = g: q̂ = q(0)/s + q̇(0)/s² + g/s³, so q(t) = q(0) + q̇(0)t + gt²/2.
    let (q0, v0, g) = (10.0, -2.0, 9.8);
    let q = tf(&[q0, v0, g], &[1.0, 0.0, 0.0, 0.0]).inverse_laplace(CLUSTER_RTOL).unwrap();
    for t in [0.0f64, 0.5, 3.0] {
        assert_rel(q.eval(t), q0 + v0 * t + 0.5 * g * t * t, 64.0 * EPS);
    }
    // the undamped rigid body (15.4.1) from (q0, v0) under a constant input g, exactly
    let urb = Sdof::new(1.0, 0.0, 0.0).unwrap().to_state_space(SdofOutput::Position).unwrap();
    let t = time_grid(3.0, 7).unwrap();
    let r = lsim(&urb, 0, &vec![g; t.len()], &t, &[q0, v0], Hold::Zoh, 0.0).unwrap();
    for (k, &tk) in t.iter().enumerate() {
        assert_rel(r.y[0][k], q0 + v0 * tk + 0.5 * g * tk * tk, 64.0 * EPS);
    }
}

#[test]
fn problem_15_20_21_falling_body_with_drag() {
    // 15.20.21: Mv̇ + Dv = Mg, v(0) = v₀: v = (v₀ − gM/D)e^{−Dt/M} + gM/D, and the final-value
    // theorem gives the terminal velocity Mg/D.
    let (m, d, g, v0) = (2.0, 0.7, 9.8, 1.5);
    // v̂ = v₀/(s + D/M) + (g/s)/(s + D/M) = (v₀s + g)/(s(s + D/M))
    let v_hat = tf(&[v0, g], &[1.0, d / m, 0.0]);
    let FinalValue::Finite(v_inf) = v_hat.final_value(AXIS_RTOL).unwrap() else { panic!("legal") };
    assert_rel(v_inf, m * g / d, 4.0 * EPS);
    let v = v_hat.inverse_laplace(CLUSTER_RTOL).unwrap();
    for t in [0.0f64, 1.0, 10.0] {
        let want = (v0 - g * m / d) * (-d * t / m).exp() + g * m / d;
        assert_rel(v.eval(t), want, 64.0 * EPS);
    }
}

#[test]
fn problem_15_20_25_rigid_body_sine_force_velocity() {
    // 15.20.25: G = 1/(ms), f = a sin ωt: v̂ = (1/(ms))·aω/(s² + ω²), v = (a/(mω))(1 − cos ωt).
    // The forced response of G to f is the impulse response of G·f̂, computed exactly.
    let (m, a, w) = (1.5, 2.0, 3.0);
    let v_hat = tf(&[1.0], &[m, 0.0]).series(&tf(&[a * w], &[1.0, 0.0, w * w])).unwrap();
    let t = time_grid(5.0, 51).unwrap();
    let r = v_hat.impulse(&t).unwrap();
    let v = v_hat.inverse_laplace(CLUSTER_RTOL).unwrap();
    for (k, &tk) in t.iter().enumerate() {
        let want = a / (m * w) * (1.0 - (w * tk).cos());
        // absolute in units of the amplitude 2a/(mω)
        assert_abs(r.y[0][k], want, 256.0 * EPS * 2.0 * a / (m * w));
        assert_abs(v.eval(tk), want, 256.0 * EPS * 2.0 * a / (m * w));
    }
}

#[test]
fn problem_15_20_26_forced_undamped_oscillator() {
    // 15.20.26: 2q̈ + 17q = 5 sin 2t from rest: q = (5/9)sin 2t − (10/9)√(2/17) sin(√(17/2) t).
    let den = Polynomial::new(&[2.0, 0.0, 17.0]).unwrap().mul(&poly(&[1.0, 0.0, 4.0])).unwrap();
    let q = tf(&[10.0], den.coeffs()).inverse_laplace(CLUSTER_RTOL).unwrap();
    let w = (17.0f64 / 2.0).sqrt();
    for t in [0.5f64, 3.0, 10.0] {
        let want = 5.0 / 9.0 * (2.0 * t).sin() - 10.0 / 9.0 * (2.0f64 / 17.0).sqrt() * (w * t).sin();
        assert_abs(q.eval(t), want, 256.0 * EPS);
    }
}

#[test]
fn example_15_13_2_final_value_theorem() {
    // Ex 15.13.2: 1 → 1; −t → −∞ (needs s → 0⁺); e^{−t} → 0; eᵗ → illegal (not 0).
    assert_eq!(final_value(&tf(&[1.0], &[1.0, 0.0]), AXIS_RTOL).unwrap(), FinalValue::Finite(1.0));
    assert_eq!(final_value(&tf(&[-1.0], &[1.0, 0.0, 0.0]), AXIS_RTOL).unwrap(), FinalValue::Infinite(-1.0));
    assert_eq!(final_value(&tf(&[1.0], &[1.0, 1.0]), AXIS_RTOL).unwrap(), FinalValue::Finite(0.0));
    assert!(matches!(
        final_value(&tf(&[1.0], &[1.0, -1.0]), AXIS_RTOL).unwrap(),
        FinalValue::Illegal(Illegal::RightHalfPlanePole(_))
    ));
    // sin t never settles: a pole on the imaginary axis.
    assert!(matches!(
        final_value(&tf(&[1.0], &[1.0, 0.0, 1.0]), AXIS_RTOL).unwrap(),
        FinalValue::Illegal(Illegal::ImaginaryAxisPole(_))
    ));
}

#[test]
fn problem_15_20_29_final_values() {
    // 15.20.29: i) −5/(s(s+7)²), u = 3e^{−2t}: y∞ = −15/98; ii) 5/(s−3): illegal (ORHP);
    // iii) −4/(s²+2.4s+0.3), u = 6t²: legal, −∞.
    let g = tf(&[-5.0], &[1.0, 14.0, 49.0, 0.0]).series(&tf(&[3.0], &[1.0, 2.0])).unwrap();
    let FinalValue::Finite(v) = g.final_value(AXIS_RTOL).unwrap() else { panic!("legal") };
    assert_rel(v, -15.0 / 98.0, 16.0 * EPS);
    let g = tf(&[5.0], &[1.0, -3.0]).series(&tf(&[7.0], &[1.0, 0.0])).unwrap();
    assert!(matches!(g.final_value(AXIS_RTOL).unwrap(), FinalValue::Illegal(Illegal::RightHalfPlanePole(_))));
    let g = tf(&[-4.0], &[1.0, 2.4, 0.3]).series(&tf(&[12.0], &[1.0, 0.0, 0.0, 0.0])).unwrap();
    assert_eq!(g.final_value(AXIS_RTOL).unwrap(), FinalValue::Infinite(-1.0));
}

#[test]
fn problem_15_20_30_routh_and_final_values() {
    // 15.20.30 i) (s²−1)/(s(3s³+2s²+4s+3)), u = 2δ: illegal, a₂a₁ − a₀ = −1/9 < 0 (ERR: "6/3"
    // should be 1); ii) 1/(s(s²+3s+1)), u = −2e^{−t}sin 2t: y∞ = −0.8.
    let cubic = poly(&[3.0, 2.0, 4.0, 3.0]);
    let ra = routh(&cubic).unwrap();
    assert_eq!(ra.rhp, 2);
    let m = cubic.monic().unwrap();
    assert_abs(m.coeff(2) * m.coeff(1) - m.coeff(0), -1.0 / 9.0, 16.0 * EPS);
    let y = tf(&[2.0, 0.0, -2.0], cubic.mul(&Polynomial::s()).unwrap().coeffs());
    assert!(matches!(y.final_value(AXIS_RTOL).unwrap(), FinalValue::Illegal(Illegal::RightHalfPlanePole(_))));
    // −2e^{−t}sin 2t ↦ −4/((s+1)² + 4).
    let y = tf(&[1.0], &[1.0, 3.0, 1.0, 0.0]).series(&tf(&[-4.0], &[1.0, 2.0, 5.0])).unwrap();
    let FinalValue::Finite(v) = y.final_value(AXIS_RTOL).unwrap() else { panic!("legal") };
    assert_rel(v, -0.8, 16.0 * EPS);
}

#[test]
fn problem_15_20_31_final_values() {
    // 15.20.31 i) DRB free response, m = 3, c = 4, q₀ = 1, q̇₀ = −2: q∞ = (mq̇₀ + cq₀)/c = −0.5
    // (corrected in the notes); ii) (4s²−12s−16)/(2s⁵+2s⁴+4s³+2s²+s), u = 3δ(t−1): Routh
    // 1.5 < 2 holds and y∞ = −48 (the delay e^{−s} is ignored at s = 0).
    let (m, c) = (3.0, 4.0);
    let q = tf(&[m * 1.0, c * 1.0 + m * -2.0], &[m, c, 0.0]);
    let FinalValue::Finite(v) = q.final_value(AXIS_RTOL).unwrap() else { panic!("legal") };
    assert_rel(v, -0.5, 16.0 * EPS);
    let sys = Sdof::new(m, c, 0.0).unwrap().to_state_space(SdofOutput::Position).unwrap();
    let r = initial(&sys, &[1.0, -2.0], &time_grid(60.0, 7).unwrap()).unwrap();
    // at t = 60 the transient e^{−80} is gone: the free response equals q∞ to rounding
    assert_abs(r.y[0][6], -0.5, 1e-12);
    let y = tf(&[12.0, -36.0, -48.0], &[2.0, 2.0, 4.0, 2.0, 1.0, 0.0]).with_delay(1.0).unwrap();
    assert!(routh(&poly(&[2.0, 2.0, 4.0, 2.0, 1.0])).unwrap().is_hurwitz());
    let FinalValue::Finite(v) = y.final_value(AXIS_RTOL).unwrap() else { panic!("legal") };
    assert_rel(v, -48.0, 16.0 * EPS);
}

#[test]
fn problem_15_20_15_16_initial_values() {
    // 15.20.15–16: t, t+1, sin 2t, cos 2t: y(0⁺) = 0, 1, 0, 1; ẏ(0⁺) = 1, 1, 2, 0 (Facts
    // 15.12.1–2, the derivative form as corrected: lim s[sŷ − y(0⁺)]).
    let cases = [
        (tf(&[1.0], &[1.0, 0.0, 0.0]), [0.0, 1.0]),
        (tf(&[1.0, 1.0], &[1.0, 0.0, 0.0]), [1.0, 1.0]),
        (tf(&[2.0], &[1.0, 0.0, 4.0]), [0.0, 2.0]),
        (tf(&[1.0, 0.0], &[1.0, 0.0, 4.0]), [1.0, 0.0]),
    ];
    for (y, want) in cases {
        assert_eq!(y.initial_values(2).unwrap(), want.to_vec());
    }
    // 15.20.28: y = 2e^{−6t}: ÿ(0⁺) = 72.
    assert_eq!(tf(&[2.0], &[1.0, 6.0]).initial_values(3).unwrap(), vec![2.0, -12.0, 72.0]);
}

#[test]
fn example_15_12_3_4_initial_value_and_slope() {
    // Ex 15.12.3: y = 1(t) and y = cos ωt have y(0⁺) = 1; Ex 15.12.4: the ramp has ẏ(0⁺) = 1.
    let omega = 3.0;
    assert_eq!(tf(&[1.0], &[1.0, 0.0]).initial_values(1).unwrap(), vec![1.0]);
    assert_eq!(tf(&[1.0, 0.0], &[1.0, 0.0, omega * omega]).initial_values(1).unwrap(), vec![1.0]);
    assert_eq!(tf(&[1.0], &[1.0, 0.0, 0.0]).initial_values(2).unwrap(), vec![0.0, 1.0]);
    // Facts 15.12.1–2 against an independent computation: the impulse response of G is
    // Ce^{At}B, so y(0⁺) = CB, ẏ(0⁺) = CAB, ÿ(0⁺) = CA²B of any realisation.
    let g = tf(&[3.0, -1.0, 2.0], &[2.0, 5.0, 1.0, 4.0]);
    let ss = StateSpace::from_tf(&g).unwrap();
    let (a, b, c) = (ss.a(), ss.b(), ss.c());
    let markov = [(c * b)[(0, 0)], (c * a * b)[(0, 0)], (c * a * a * b)[(0, 0)]];
    let iv = g.initial_values(3).unwrap();
    for (got, want) in iv.iter().zip(markov) {
        assert_abs(*got, want, 64.0 * EPS * want.abs().max(1.0));
    }
    assert_eq!(iv, vec![1.5, -4.25, 10.875]);
}

#[test]
fn example_15_10_2_damped_sine_by_the_s_shift() {
    // Ex 15.10.2: L{e^{−at} sin ωt} = ω/((s + a)² + ω²), the s-shift (15.10.3) of
    // L{sin ωt} = ω/(s² + ω²). Inverted by partial fractions and, independently, as the impulse
    // response of the same transfer function (exact discretisation of e^{At}).
    for (a, w) in [(0.5, 2.0), (3.0, 0.25), (-0.2, 5.0)] {
        let y_hat = tf(&[w], &[1.0, 2.0 * a, a * a + w * w]);
        let y = y_hat.inverse_laplace(CLUSTER_RTOL).unwrap();
        let t = time_grid(6.0, 61).unwrap();
        let r = y_hat.impulse(&t).unwrap();
        for (k, &tk) in t.iter().enumerate() {
            let want = (-a * tk).exp() * (w * tk).sin();
            // absolute, at the scale of the envelope e^{−at} (which grows for a < 0)
            let scale = (-a * tk).exp().max(1.0);
            assert_abs(y.eval(tk), want, 256.0 * EPS * scale);
            assert_abs(r.y[0][k], want, 1e3 * EPS * scale);
        }
    }
}

#[test]
fn example_15_11_1_damped_oscillator_free_and_forced() {
    // Ex 15.11.1: mq̈ + cq̇ + kq = f gives q̂ = (mq(0)s + cq(0) + mq̇(0))/(ms² + cs + k) (free)
    // + f̂/(ms² + cs + k) (forced). Checked against the state-space model of §15.7: the free part
    // is the initial-condition response, the forced part (f = f₀·1(t)) the step response.
    let (m, c, k) = (2.0, 0.6, 5.0);
    let (q0, v0, f0) = (0.3, -1.2, 4.0);
    let free = tf(&[m * q0, c * q0 + m * v0], &[m, c, k]).inverse_laplace(CLUSTER_RTOL).unwrap();
    let forced = tf(&[f0], &[m, c, k, 0.0]).inverse_laplace(CLUSTER_RTOL).unwrap();
    let sys = Sdof::new(m, c, k).unwrap().to_state_space(SdofOutput::Position).unwrap();
    let t = time_grid(10.0, 101).unwrap();
    let r_free = initial(&sys, &[q0, v0], &t).unwrap();
    let r_forced = response(&sys, InputKind::Step, 0, f0, 0.0, &t).unwrap();
    let r_both = lsim(&sys, 0, &vec![f0; t.len()], &t, &[q0, v0], Hold::Zoh, 0.0).unwrap();
    for (i, &ti) in t.iter().enumerate() {
        // absolute: responses of size ≤ 2f₀/k + |q0| + |v0|, a few hundred roundings
        let scale = 2.0 * f0 / k + q0.abs() + v0.abs();
        assert_abs(r_free.y[0][i], free.eval(ti), 1e3 * EPS * scale);
        assert_abs(r_forced.y[0][i], forced.eval(ti), 1e3 * EPS * scale);
        assert_abs(r_both.y[0][i], free.eval(ti) + forced.eval(ti), 1e3 * EPS * scale);
    }
    // q(0⁺) = q(0) and q̇(0⁺) = q̇(0) for the free part (Facts 15.12.1–2)
    let iv = tf(&[m * q0, c * q0 + m * v0], &[m, c, k]).initial_values(2).unwrap();
    assert_rel(iv[0], q0, 4.0 * EPS);
    assert_rel(iv[1], v0, 4.0 * EPS);
}

#[test]
fn example_15_11_3_position_impulse_equals_velocity_step() {
    // Ex 15.11.3: the damped rigid body q̈ + 2q̇ = u. Position under u = δ: q̂ = 1/(s² + 2s);
    // velocity v = q̇ obeys v̇ + 2v = u (ERR: printed "v̈ + 2v = u"), so under u = 1(t)
    // v̂ = 1/(s(s + 2)): the same transform, both (1 − e^{−2t})/2.
    let t = time_grid(5.0, 51).unwrap();
    let position_impulse = tf(&[1.0], &[1.0, 2.0, 0.0]).impulse(&t).unwrap();
    let velocity_step = tf(&[1.0], &[1.0, 2.0]).step(&t).unwrap();
    // and from the DRB state-space model (m = 1, c = 2) with each output
    let drb = Sdof::new(1.0, 2.0, 0.0).unwrap();
    let pos = drb.to_state_space(SdofOutput::Position).unwrap();
    let vel = drb.to_state_space(SdofOutput::Velocity).unwrap();
    let ss_impulse = response(&pos, InputKind::Impulse, 0, 1.0, 0.0, &t).unwrap();
    let ss_step = response(&vel, InputKind::Step, 0, 1.0, 0.0, &t).unwrap();
    for (k, &tk) in t.iter().enumerate() {
        let want = 0.5 * (1.0 - (-2.0 * tk).exp());
        for got in [position_impulse.y[0][k], velocity_step.y[0][k], ss_impulse.y[0][k], ss_step.y[0][k]] {
            assert_abs(got, want, 64.0 * EPS); // values ≤ 1/2
        }
    }
}

#[test]
fn problem_15_20_28_second_derivative_by_the_initial_value_theorem() {
    // 15.20.28: y = 2e^{−6t}, ŷ = 2/(s + 6). (17.0.21): ÿ(0⁺) = lim_{s→∞} s(s²ŷ − sy(0) − ẏ(0))
    // = lim 72s/(s + 6) = 72, the value of ÿ = 72e^{−6t} at t = 0.
    let y_hat = tf(&[2.0], &[1.0, 6.0]);
    let iv = y_hat.initial_values(3).unwrap();
    assert_eq!(iv, vec![2.0, -12.0, 72.0]);
    // the limit by hand: s(s²ŷ − sy(0) − ẏ(0)) = s(2s² − (2s − 12)(s + 6))/(s + 6) = 72s/(s + 6)
    let z_hat = tf(&[72.0, 0.0], &[1.0, 6.0]);
    assert_eq!(z_hat.relative_degree(), 0);
    assert_eq!(z_hat.num().leading() / z_hat.den().leading(), 72.0);
    for s in [10.0f64, 1e2, 1e3] {
        let direct = s * (s * s * 2.0 / (s + 6.0) - s * iv[0] - iv[1]);
        // cancellation of terms of size 2s³/(s + 6) ~ 2s², so the error grows like ε·2s²
        assert_abs(direct, 72.0 * s / (s + 6.0), 64.0 * EPS * 2.0 * s * s);
    }
    // the time-domain check: ÿ(t) = 72e^{−6t}, the inverse transform of s²ŷ − sy(0) − ẏ(0)
    let ydd = tf(&[72.0], &[1.0, 6.0]).inverse_laplace(CLUSTER_RTOL).unwrap();
    assert_rel(ydd.eval(0.0), 72.0, 4.0 * EPS);
}
