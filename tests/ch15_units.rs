//! Chapter 15, §15.19 (dimensions and units), Problem 15.20.24, and the typed units layer on
//! the book's kinds of physical vectors (§1.6) (issue 21).
//!
//! References: the exact definitions of the units (ft = 0.3048 m, lb = 0.45359237 kg,
//! g₀ = 9.80665 m/s²: 1959 international yard and pound, CGPM 1901), the book's printed
//! roundings (4.4 N, 14.59 kg, 9.8 N, 32.2 lb) checked to half a unit of their last digit,
//! and closed forms.

mod support;

use crate::support::nan_min;
use vectrix::flight::{
    TrimLimits, TrimSpec, business_jet_in, business_jet_lateral_in, business_jet_longitudinal_in,
    lateral_modes, linearize, longitudinal_modes, trim,
};
use vectrix::lti::{CLUSTER_RTOL, TransferFunction};
use vectrix::prelude::*;
use vectrix::units::kind::{
    AngularVelocity, Force, Length, Mass, Moment, MomentOfInertia, Momentum, Velocity,
};
use vectrix::units::{
    AsPhysical, Dimension, Measure, Physical, Quantity, TypedMassProperties, Unit, UnitSystem,
    principal_mass_properties,
};

/// Unit roundoff u = 2⁻⁵³: one correctly rounded operation errs by at most u relative.
const U: f64 = f64::EPSILON / 2.0;

fn si(text: &str, d: Dimension) -> f64 {
    Quantity::parse(text).and_then(|q| q.to_si(d)).unwrap_or_else(|e| panic!("{text}: {e}"))
}

fn in_unit(text: &str, unit: &str) -> f64 {
    let u = Unit::parse(unit).unwrap();
    Quantity::parse(text).and_then(|q| q.to_unit(&u)).unwrap_or_else(|e| panic!("{text} in {unit}: {e}"))
}

/// |got − want| ≤ half a unit of the last digit the book prints (`half_unit`).
fn assert_printed(got: f64, want: f64, half_unit: f64) {
    assert!((got - want).abs() <= half_unit, "got {got}, book prints {want} (± {half_unit})");
}

fn assert_rel(got: f64, want: f64, tol: f64) {
    assert!((got - want).abs() <= tol * want.abs(), "got {got:e}, want {want:e}, rel tol {tol:e}");
}

#[test]
fn eq_15_19_1_pound_force_is_slug_foot_per_second_squared() {
    // (15.19.1): 1 lb = 1 slug·ft/sec² = 4.4 N (the book's "lb" is the pound-force, `lbf`).
    // The identity is exact: slug = lbf·s²/ft by definition, so both strings are the same
    // rational, rounded once to the same double; that double is lb·g₀ = 4.4482216152605 N.
    let lbf = si("1 lbf", Dimension::FORCE);
    assert_eq!(lbf.to_bits(), si("1 slug*ft/s^2", Dimension::FORCE).to_bits());
    assert_eq!(lbf, 4.448_221_615_260_5);
    assert_eq!(in_unit("1 slug*ft/s^2", "lbf"), 1.0);
    // the book rounds to 4.4 N
    assert_printed(lbf, 4.4, 0.05);
}

#[test]
fn eq_15_19_2_slug_is_14_59_kg() {
    // (15.19.2): 1 slug = 14.59 kg. Exactly 0.45359237 · 9.80665 / 0.3048 kg
    // = 14.5939029372063648… kg, rounded once.
    let slug = si("1 slug", Dimension::MASS);
    assert_eq!(slug, 14.593_902_937_206_364);
    assert_printed(slug, 14.59, 0.005);
    // half a unit of the printed 14.59 is 0.005 kg, i.e. 0.005/14.59 slug
    assert_printed(in_unit("14.59 kg", "slug"), 1.0, 0.005 / 14.59);
}

#[test]
fn sec_15_19_1_weights_of_a_kilogram_and_a_slug() {
    // §15.19.1: "On the surface of the Earth, 1 kg weighs 9.8 N, while 1 slug weighs 32.2 lb."
    // Weight = m g₀: 1 kg·g₀ = 9.80665 N exactly; 1 slug·g₀ = g₀/ft lbf = 32.17404855643… lbf.
    assert_eq!(in_unit("1 kg*g0", "N"), 9.806_65);
    assert_printed(in_unit("1 kg*g0", "N"), 9.8, 0.05);
    let w = in_unit("1 slug*g0", "lbf");
    // g₀/ft rounded once: Python's Fraction('9.80665')/Fraction('0.3048') → float gives
    // 32.17404855643045; the f64 expression 9.80665 / 0.3048 rounds three times and gives
    // 32.17404855643044, one ulp off
    assert_eq!(w, 32.174_048_556_430_45);
    assert_printed(w, 32.2, 0.05);
}

#[test]
fn eq_15_19_3_impulse_has_units_of_inverse_time() {
    // (15.19.3): [δ(t)] = 1/sec, because ∫δ(t) dt = 1 is dimensionless.
    let delta = Dimension::DIMENSIONLESS.checked_div(&Dimension::TIME).unwrap();
    assert_eq!(delta, Dimension::FREQUENCY);
    assert_eq!(Quantity::parse("1 1/s").unwrap().dimension(), delta);
    // and not an angular rate: 1/s has no angle
    assert_ne!(delta, Dimension::ANGULAR_VELOCITY);
}

#[test]
fn eq_15_19_4_force_impulse_coefficient_is_momentum() {
    // (15.19.4): for f(t) = f₀δ(t), [f₀] = [f]/[δ] = kg·m/sec, the units of momentum.
    let f0 = Dimension::FORCE.checked_div(&Dimension::FREQUENCY).unwrap();
    assert_eq!(f0, Dimension::MOMENTUM);
    assert_eq!(f0.to_string(), "momentum or impulse (kg*m/s)");
    assert_eq!(si("1 N*s", f0), si("1 kg*m/s", f0));
    // the English engineering system is coherent: 1 lbf·s = 1 slug·ft/s exactly
    assert_eq!(in_unit("1 lbf*s", "slug*ft/s"), 1.0);
}

#[test]
fn eq_15_19_5_specific_impulse_is_velocity() {
    // (15.19.5): [f₀/m] = m/sec, a velocity. An impulse of 10 lbf·s on 2 slug changes the
    // velocity by 5 ft/s = 1.524 m/s; in SI the quotient of the two converted values carries
    // three roundings (two conversions and the division).
    assert_eq!(Dimension::MOMENTUM.checked_div(&Dimension::MASS), Some(Dimension::VELOCITY));
    let dv = si("10 lbf*s", Dimension::MOMENTUM) / si("2 slug", Dimension::MASS);
    assert_rel(dv, 1.524, 3.0 * U * (1.0 + U));
    let dv = Measure::<Velocity>::from_si(dv);
    assert_rel(dv.value_in("ft/s").unwrap(), 5.0, 4.0 * U * (1.0 + U));
}

#[test]
fn problem_15_20_24_same_form_different_dimensions() {
    // P15.20.24 (solution (17.0.15)–(17.0.16)): for the undamped rigid body m q̈ = f,
    // 1) position output, impulse input f = f₀δ:  q̂(s) = f₀/(m s²);
    // 2) velocity output, step input f = f₀·1(t): v̂(s) = (1/(m s))(f₀/s) = f₀/(m s²).
    // The same expression, because f₀ is a momentum in case 1 and a force in case 2:
    // [q̂] = m·sec and [v̂] = m.
    let m = 2.0;
    let g_position = TransferFunction::new(&[1.0], &[m, 0.0, 0.0]).unwrap(); // 1/(m s²)
    let g_velocity = TransferFunction::new(&[1.0], &[m, 0.0]).unwrap(); // 1/(m s)
    let impulse = TransferFunction::new(&[1.0], &[1.0]).unwrap(); // 𝓛{δ} = 1
    let step = TransferFunction::new(&[1.0], &[1.0, 0.0]).unwrap(); // 𝓛{1(t)} = 1/s
    let q_hat = g_position.series(&impulse).unwrap();
    let v_hat = g_velocity.series(&step).unwrap();
    assert_eq!(q_hat.num().coeffs(), v_hat.num().coeffs());
    assert_eq!(q_hat.den().coeffs(), v_hat.den().coeffs());
    // both are the ramp f₀t/m (per unit f₀): 𝓛⁻¹{1/(m s²)} = t/m
    let ramp = q_hat.inverse_laplace(CLUSTER_RTOL).unwrap();
    for t in [0.0, 0.5, 3.0] {
        assert!((ramp.eval(t) - t / m).abs() <= 4.0 * f64::EPSILON * (1.0 + t / m), "t = {t}");
    }
    // Dimensions: [s] = 1/time, [𝓛{y}] = [y]·time; case 1 [f₀] = momentum, case 2 force.
    let per_ms2 = |f0: Dimension| {
        f0.checked_div(&Dimension::MASS).and_then(|d| d.checked_mul(&Dimension::TIME.checked_pow(2).unwrap()))
    };
    assert_eq!(per_ms2(Dimension::MOMENTUM), Dimension::LENGTH.checked_mul(&Dimension::TIME)); // m·sec
    assert_eq!(per_ms2(Dimension::FORCE), Some(Dimension::LENGTH)); // m
    // and with numbers in the book's units: 3 lbf·s on 2 slug gives q(t) = 1.5 ft/s · t;
    // 3 lbf on 2 slug gives v(t) = 1.5 ft/s² · t; the same slope f₀/m, in different units
    let slope1 = si("3 lbf*s", Dimension::MOMENTUM) / si("2 slug", Dimension::MASS);
    let slope2 = si("3 lbf", Dimension::FORCE) / si("2 slug", Dimension::MASS);
    assert_rel(slope1, si("1.5 ft/s", Dimension::VELOCITY), 4.0 * U);
    assert_rel(slope2, si("1.5 ft/s^2", Dimension::ACCELERATION), 4.0 * U);
}

#[test]
fn sec_1_6_kinds_of_physical_vectors_are_typed() {
    // §1.6: position, force, moment, velocity, momentum, angular velocity are distinct kinds
    // of physical vectors; the typed layer keeps them apart and gives products their kind:
    // M⃗ = r⃗ × f⃗ (§6.3), ω⃗ × r⃗ is a velocity (§4.8), p⃗ = m v⃗.
    let a = Frame::new();
    let b = a.rotated_by_rotor(&Rotor::from_axis_angle(&a.vector([1.0, 2.0, -0.5]), 0.9).unwrap());
    let r: Physical<Length> = Physical::parse(&a, ["2 ft", "-1 ft", "0.5 ft"]).unwrap();
    let f: Physical<Force> = Physical::in_unit(&a, [3.0, 0.0, -4.0], "lbf").unwrap();
    let m: Physical<Moment> = r.cross(&f);
    // in the book's units the moment is the cross product of the printed numbers (ft·lbf):
    // (−1·−4 − 0.5·0, 0.5·3 − 2·−4, 2·0 − (−1)·3) = (4, 9.5, 3); each component has the
    // roundings of r and f in SI, the cross product, and the conversion back (≤ 8u relative
    // to the largest term)
    let got = m.resolve_in(&a, "ft*lbf").unwrap();
    for (g, w) in got.iter().zip([4.0, 9.5, 3.0]) {
        assert!((g - w).abs() <= 8.0 * U * 9.5, "{got:?}");
    }
    // the same moment in N·m is the ft·lbf value times 0.3048 · 4.4482216152605 exactly
    let nm = m.resolve_in(&a, "N*m").unwrap();
    let factor = Unit::parse("ft*lbf").unwrap().factor().unwrap();
    for (n, g) in nm.iter().zip(got) {
        assert!((n - g * factor).abs() <= 4.0 * U * 9.5 * factor);
    }
    // frame independence: resolving in B gives O_B/A times the A components
    let o_ba = b.orientation_rel(&a);
    let m_b = m.resolve(&b).map(Measure::si);
    let m_a = nalgebra::Vector3::from(m.resolve(&a).map(Measure::si));
    let rotated = o_ba * m_a;
    for i in 0..3 {
        assert!((m_b[i] - rotated[i]).abs() <= 16.0 * f64::EPSILON * m.magnitude().si());
    }
    // ω⃗ × r⃗ is a velocity; m v⃗ a momentum
    let omega: Physical<AngularVelocity> = Physical::parse(&a, ["0 rpm", "0 rpm", "60 rpm"]).unwrap();
    let v: Physical<Velocity> = omega.cross(&r);
    let p: Physical<Momentum> = Measure::<Mass>::new(1.0, "slug").unwrap() * v;
    assert!(
        (v.magnitude().si() - std::f64::consts::TAU * (2.0f64.powi(2) + 1.0).sqrt() * 0.3048).abs() <= 1e-15
    );
    assert!(
        (p.magnitude().si() - 14.593_902_937_206_364 * v.magnitude().si()).abs()
            <= 4.0 * U * p.magnitude().si()
    );
    // kernel results read out typed: the untyped vector tagged, for free
    let v_kernel = omega.si().cross(&r.si());
    assert_eq!(v_kernel.as_physical::<Velocity>(), v);
}

#[test]
fn sec_6_2_mass_properties_from_book_units() {
    // §6.1–6.2 with the business jet's printed inertia (Table 14.2: J_xx = 27,915,
    // J_zz = 47,085 slug·ft²) and an assumed J_yy: the typed constructor converts to the SI
    // kernel exactly, and the typed read gives back the printed numbers within two roundings.
    let a = Frame::new();
    let j = |t: &str| Measure::<MomentOfInertia>::parse(t).unwrap();
    let mp = principal_mass_properties(
        &a,
        Measure::new(13_000.0 / 32.2, "slug").unwrap(),
        Physical::zero(),
        [j("27915 slug*ft^2"), j("25000 slug*ft^2"), j("47085 slug*ft^2")],
    )
    .unwrap();
    assert_eq!(
        mp.inertia_about_centre().resolve(&a)[(0, 0)],
        si("27915 slug*ft^2", Dimension::MOMENT_OF_INERTIA)
    );
    let back = mp.inertia_resolved(&a);
    for (k, want) in [(0, 27_915.0), (1, 25_000.0), (2, 47_085.0)] {
        let got = back[k][k].value_in("slug*ft^2").unwrap();
        assert!((got - want).abs() <= 2.0 * U * want, "J[{k}] = {got}");
    }
    assert!((mp.mass_measure().value_in("slug").unwrap() - 13_000.0 / 32.2).abs() <= 2.0 * U * 404.0);
    // a wrong unit is a typed error, not a wrong inertia
    let e = Measure::<MomentOfInertia>::parse("27915 slug*ft").unwrap_err();
    assert!(e.to_string().contains("expected moment of inertia (kg*m^2)"), "{e}");
}

#[test]
fn sec_15_19_business_jet_modes_are_unit_independent() {
    // Tables 14.1–14.2 converted exactly to SI describe the same aircraft: eigenvalues (in
    // 1/s) do not depend on the unit of length, since the SI state matrix is D A D⁻¹ with
    // D = diag(0.3048, 1, 1, 1) up to one rounding per entry. A backward-stable eigensolver
    // then moves a well-conditioned eigenvalue by at most about n·u·‖A‖_F per system; the
    // bound below is 4 n u ‖A‖_F (n = 4) for the pair of systems (measured: ≤ 3u·|λ|).
    let lon_a = |s| business_jet_longitudinal_in(s).state_space().unwrap().a().clone();
    let lat_a = |s| business_jet_lateral_in(s).state_space().unwrap().a().clone();
    let (ai, am) = (lon_a(UnitSystem::Imperial), lon_a(UnitSystem::Si));
    let tol = 16.0 * U * ai.norm();
    let (li, ls) = (longitudinal_modes(&ai).unwrap(), longitudinal_modes(&am).unwrap());
    for (a, b) in [(li.short_period, ls.short_period), (li.phugoid, ls.phugoid)] {
        assert!((a.eigenvalue() - b.eigenvalue()).norm() <= tol, "{a:?} vs {b:?}");
    }
    let (ai, am) = (lat_a(UnitSystem::Imperial), lat_a(UnitSystem::Si));
    let tol = 16.0 * U * ai.norm();
    let (ti, ts) = (lateral_modes(&ai).unwrap(), lateral_modes(&am).unwrap());
    for (a, b) in [(ti.dutch_roll, ts.dutch_roll), (ti.roll, ts.roll), (ti.spiral, ts.spiral)] {
        assert!((a.eigenvalue() - b.eigenvalue()).norm() <= tol, "{a:?} vs {b:?}");
    }
}

#[test]
fn sec_15_19_business_jet_trims_alike_in_si_and_imperial() {
    // The nonlinear aircraft built from the exactly converted data is the same aircraft:
    // nondimensional coefficients agree to rounding, the level trim at U₀ = 400 kt has the same
    // angle of attack and elevator (radians) and thrust (converted lbf → N), and the
    // linearization's modes agree. Tolerances: each coefficient is a formula of about a dozen
    // converted data and operations, each rounding once (2⁵u; measured ≤ 5u). The trims stop
    // at an acceleration residual ≤ 1e-10 (ft/s² or m/s²); with ∂(Z accel)/∂α ≈ −136 m/s²
    // per rad that allows ≈ 1e-12 rad of disagreement in α and δe, and with u̇ = T/m − … a
    // thrust disagreement ≈ 1e-10·m/T ≤ 1e-10 relative; poles move by O(1)/rad, so
    // 1e-10 (1 + |p|) (measured: angles equal, thrust 4e-16, poles 8e-16).
    let (imp, met) = (business_jet_in(UnitSystem::Imperial), business_jet_in(UnitSystem::Si));
    let (ci, cm) = (imp.coefficients, met.coefficients);
    for (a, b) in
        [(ci.cl0, cm.cl0), (ci.cl_alpha, cm.cl_alpha), (ci.cm_alpha, cm.cm_alpha), (ci.cn_beta, cm.cn_beta)]
    {
        assert!((a - b).abs() <= 32.0 * U * a.abs(), "{a} vs {b}");
    }
    let level = |ac: &vectrix::flight::Aircraft| {
        let spec = TrimSpec::Straight { airspeed: ac.coefficients.u_ref, gamma: 0.0 };
        trim(ac, spec, TrimLimits::default()).unwrap()
    };
    let (ti, tm) = (level(&imp), level(&met));
    assert!((ti.state.attitude.theta - tm.state.attitude.theta).abs() <= 1e-12);
    assert!((ti.controls.elevator - tm.controls.elevator).abs() <= 1e-12);
    let thrust_n = Measure::<Force>::new(ti.controls.thrust, "lbf").unwrap().si();
    assert!(
        (thrust_n - tm.controls.thrust).abs() <= 1e-10 * thrust_n,
        "{thrust_n} vs {}",
        tm.controls.thrust
    );
    let (mi, mm) = (linearize(&imp, &ti).unwrap(), linearize(&met, &tm).unwrap());
    let (pi, pm) = (mi.longitudinal().unwrap().poles().unwrap(), mm.longitudinal().unwrap().poles().unwrap());
    for p in &pi {
        let nearest = pm.iter().map(|q| (q - p).norm()).fold(f64::INFINITY, nan_min);
        assert!(nearest <= 1e-10 * (1.0 + p.norm()), "pole {p} has no SI twin (off by {nearest:e})");
    }
}

#[test]
fn eq_14_7_3_boeing_747_gravity_entry_is_in_feet() {
    // (14.7.3) prints A(1,4) = −3.22e1 for the 747 while the book states u in m/s (P14.9.5):
    // the entry is −g in ft/s² (g₀ = 32.174 ft/s², printed as 32.2 to half a unit of its last
    // digit), not in m/s² (9.80665). The catalogue keeps it as printed.
    let a = vectrix::flight::boeing_747_longitudinal_a();
    let g_ft = in_unit("1 g0", "ft/s^2");
    assert_printed(-a[(0, 3)], g_ft, 0.05);
    assert!((-a[(0, 3)] - si("1 g0", Dimension::ACCELERATION)).abs() > 20.0);
}
