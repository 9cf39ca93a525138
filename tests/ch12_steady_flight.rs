//! Chapter 12: steady flight and trim (straight-line level, climbing and descending flight,
//! the coordinated level turn), and linearization at the trim point.
//!
//! Trim residuals are accelerations (ft/s², rad/s²); the solver stops at 1e-12 and the tests
//! require the brief's 1e-10.
#![allow(clippy::needless_range_loop)] // matrix entries read as the book's A(i, j)
mod support;

use support::{EPS, assert_abs, assert_rel, assert_rel_slice, nan_max};
use vectrix::flight::*;

const TRIM_TOL: f64 = 1e-10;

fn level() -> Trim {
    let ac = business_jet();
    trim(&ac, TrimSpec::Straight { airspeed: BUSINESS_JET_U0, gamma: 0.0 }, TrimLimits::default()).unwrap()
}

fn residual_of(ac: &Aircraft, t: &Trim) -> f64 {
    let f = ac.dynamics(&t.state, &t.controls).unwrap();
    // steady: U̇..Ṙ and Φ̇, Θ̇ vanish (position and heading may change)
    let a = f.to_array();
    [a[3], a[4], a[5], a[6], a[7], a[9], a[10], a[11]].iter().fold(0.0f64, |m, v| nan_max(m, v.abs()))
}

#[test]
fn eq_12_3_1_business_jet_level_trim_in_stability_axes() {
    // (12.3.1–5): the steady point Θ₀ = α₀, Φ₀ = β₀ = γ₀ = 0, P₀ = Q₀ = R₀ = 0. The jet's body
    // frame is the stability frame of this trim, so α₀ = 0, δe₀ = 0 and F_T = D = p_d0 S C_D0.
    let ac = business_jet();
    let t = level();
    assert!(t.residual <= TRIM_TOL);
    assert!(residual_of(&ac, &t) <= TRIM_TOL);
    assert_abs(t.state.aero_angles().alpha, 0.0, 1e-12);
    assert_abs(t.controls.elevator, 0.0, 1e-12);
    let qs = ac.dynamic_pressure(BUSINESS_JET_U0) * ac.geometry.area;
    assert_rel(t.controls.thrust, qs * 0.03, 1e-9);
}

#[test]
fn notes_12_1_straight_line_climb_conditions() {
    // Notes (12.1) [C]: straight-line trim satisfies F_T cos(α+Φ_T) − D − mg sin γ = 0,
    // L + F_T sin(α+Φ_T) − mg cos γ = 0, with Θ = α + γ.
    let ac = business_jet();
    for gamma in [-0.05, 0.0, 0.04, 0.08] {
        let t = trim(&ac, TrimSpec::Straight { airspeed: 650.0, gamma }, TrimLimits::default()).unwrap();
        assert!(t.residual <= TRIM_TOL, "γ = {gamma}: residual {}", t.residual);
        let a = t.state.aero_angles();
        let fm = ac.forces(&t.state, &t.controls, 0.0, 0.0);
        let w = ac.airframe.mass() * ac.g;
        let scale = 1e-10 * w;
        assert_abs(fm.thrust * a.alpha.cos() - fm.drag - w * gamma.sin(), 0.0, scale);
        assert_abs(fm.lift + fm.thrust * a.alpha.sin() - w * gamma.cos(), 0.0, scale);
        assert_abs(t.state.attitude.theta, a.alpha + gamma, 8.0 * EPS);
        // the flight-path angle of (10.8.4) is γ
        let fp = FlightPathAngles::from_attitude(&t.state.attitude, a.alpha, a.beta);
        assert_abs(fp.gamma, gamma, 8.0 * EPS);
    }
}

#[test]
fn section_12_1_coordinated_level_turn() {
    // §12.1: a horizontal circle is a trim: β = 0, Ż = 0, ω = Ψ̇ k̂_E constant.
    // Coordinated: bank tan Φ ≈ VΨ̇/g (exact for α = 0, no thrust tilt).
    let ac = business_jet();
    let turn_rate = 0.02;
    let t = trim(&ac, TrimSpec::LevelTurn { airspeed: BUSINESS_JET_U0, turn_rate }, TrimLimits::default())
        .unwrap();
    assert!(t.residual <= TRIM_TOL);
    assert!(residual_of(&ac, &t) <= TRIM_TOL);
    let a = t.state.aero_angles();
    assert_abs(a.beta, 0.0, 1e-12);
    let f = ac.dynamics(&t.state, &t.controls).unwrap();
    assert_abs(f.position[2], 0.0, 1e-9);
    assert_abs(f.attitude.psi, turn_rate, 1e-12);
    let approx = (BUSINESS_JET_U0 * turn_rate / ac.g).atan();
    // α ≠ 0 in the turn tilts the balance: a few percent
    assert!((t.state.attitude.phi - approx).abs() < 0.05 * approx);
}

#[test]
fn section_12_1_unreachable_trim_names_the_condition() {
    // Far too slow for the stall bound: the lift condition Ẇ = 0 cannot be met.
    let ac = business_jet();
    let err =
        trim(&ac, TrimSpec::Straight { airspeed: 150.0, gamma: 0.0 }, TrimLimits::default()).unwrap_err();
    match err {
        FlightError::TrimFailed { condition, .. } => {
            assert!(condition.contains('Ẇ') || condition.contains('Q'), "{condition}")
        }
        e => panic!("expected TrimFailed, got {e}"),
    }
    // Elevator travel too small for a steep climb's pitching moment: names a condition.
    let lim = TrimLimits { thrust: 1000.0, ..TrimLimits::default() };
    let err = trim(&ac, TrimSpec::Straight { airspeed: BUSINESS_JET_U0, gamma: 0.3 }, lim).unwrap_err();
    assert!(matches!(err, FlightError::TrimFailed { ref condition, .. } if condition.contains("U̇")), "{err}");
    assert!(matches!(
        trim(&ac, TrimSpec::Straight { airspeed: -1.0, gamma: 0.0 }, TrimLimits::default()),
        Err(FlightError::OutOfRange { .. })
    ));
}

#[test]
fn eq_14_5_1_level_trim_linearization_decouples() {
    // (14.5.1): at a straight, level, wings-level, β = 0 trim the 12-state model splits into
    // longitudinal and lateral blocks.
    let ac = business_jet();
    let lin = linearize(&ac, &level()).unwrap();
    assert!(lin.coupling() <= 1e-12, "coupling {}", lin.coupling());
}

#[test]
fn section_12_6_linearization_reproduces_tables_14_1_and_14_2() {
    // The nonlinear jet's coefficients invert Tables 14.1–14.2; its dual-number linearization
    // in stability axes must give the table's A and B (to roundoff of the inversion).
    let ac = business_jet();
    let lin = linearize(&ac, &level()).unwrap();
    let lon = lin.longitudinal().unwrap();
    // Relative to the largest entry of each matrix (A has entries 0 beside g = 32.2): the
    // inversion and the linearization round to a few dozen ε of that scale.
    let book = business_jet_longitudinal().state_space().unwrap();
    assert_rel_slice(lon.a().as_slice(), book.a().as_slice(), 64.0 * EPS);
    // the table's B has the elevator column only
    let lon_b: Vec<f64> = lon.b().column(0).iter().copied().collect();
    assert_rel_slice(&lon_b, book.b().as_slice(), 64.0 * EPS);
    let lat = lin.lateral().unwrap();
    let book = business_jet_lateral().state_space().unwrap();
    assert_rel_slice(lat.a().as_slice(), book.a().as_slice(), 64.0 * EPS);
    assert_rel_slice(lat.b().as_slice(), book.b().as_slice(), 64.0 * EPS);
}

#[path = "ch12/linearization.rs"]
mod linearization;

#[path = "ch12/problems.rs"]
mod problems;
