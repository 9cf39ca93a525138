//! Bode's sensitivity integral (16.8.8–16.8.9) and typed errors of the frequency tools.

use super::*;

#[test]
fn problem_16_8_8_and_16_8_9_sensitivity_integral() {
    // (16.8.8)–(16.8.9): ∫₀^∞ ln|S(jω)| dω = π Σ Re pᵢ over ORHP poles of L. 16.8.8 solves
    // L = −1/(s² + 2s + 3) (ERR: the statement says 10/(s² + 2s + 1)); the book's Riemann sum
    // gives 0.0021, the exact value is 0 for both loops. 16.8.9: L = 4/((s−1)(s+2)), pole at 1:
    // π (book 3.1412). The adaptive Gauss–Kronrod quadrature is asked for 1e-11 (absolute, the
    // integrands are of order one); it reaches 4.4e-16 and π to the last bit.
    for l in [tf(&[-1.0], &[1.0, 2.0, 3.0]), tf(&[10.0], &[1.0, 2.0, 1.0])] {
        assert_abs(sensitivity_integral(&l).unwrap(), 0.0, 1e-11);
    }
    let v = sensitivity_integral(&tf(&[4.0], &[1.0, 1.0, -2.0])).unwrap();
    assert_abs(v, std::f64::consts::PI, 1e-11);
    // S = (s² + s − 2)/(s² + s + 2), poles (−1 ± j√7)/2 (printed without the j).
    let s = tf(&[4.0], &[1.0, 1.0, -2.0]).sensitivity().unwrap();
    let p = s.poles().unwrap();
    assert_rel(p[0].re, -0.5, 16.0 * EPS);
    assert_rel(p[0].im.abs(), 7f64.sqrt() / 2.0, 16.0 * EPS);
}

#[test]
fn frequency_tools_reject_bad_input() {
    let g = tf(&[1.0, 0.0], &[1.0, 1.0]);
    assert!(matches!(sensitivity_integral(&g), Err(LtiError::InvalidArgument { .. })));
    assert!(matches!(tf(&[1.0, 0.0, 0.0], &[1.0, 1.0]).nyquist(50), Err(LtiError::Improper { .. })));
    assert!(matches!(g.bode(&[-1.0]), Err(LtiError::InvalidArgument { .. })));
    assert!(matches!(g.freqresp(&[f64::NAN]), Err(LtiError::InvalidArgument { .. })));
    assert!(matches!(logspace(2.0, 1.0, 10), Err(LtiError::InvalidArgument { .. })));
    assert!(matches!(root_locus(&g, -1.0, 0.1), Err(LtiError::InvalidArgument { .. })));
    // −1 on the Nyquist plot: L = 1/s² gives the closed loop s² + 1 with poles ±j.
    assert!(matches!(tf(&[1.0], &[1.0, 0.0, 0.0]).nyquist(50), Err(LtiError::InvalidArgument { .. })));
    assert!(matches!(leads(f64::NAN, 0.0), Err(LtiError::NonFinite { .. })));
}
