//! Sections of chapter 10 without a worked example: the degrees of freedom (§10.1), the earth
//! frame and gravity (§10.2), the stability and wind frames as directed angles (§10.4–10.5),
//! range, drift, plunge and altitude (§10.7), and frame derivatives (§10.10, whose printed
//! decomposition (10.10.1) is garbled; the corrected double transport theorem is checked).

use std::f64::consts::{FRAC_PI_2, PI};

use proptest::prelude::*;
use vectrix::flight::*;
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::num_dual::{Dual64, HyperDual64};
use vectrix::prelude::*;

use crate::support::{EPS, NanAmax};

/// An angle in (−π, π] biased toward 0, ±π/2 and π.
fn any_angle() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -PI..PI,
        1 => prop::sample::select(vec![0.0, FRAC_PI_2, -FRAC_PI_2, PI, 1e-9]),
    ]
}

/// A pitch away from gimbal lock (|cos Θ| ≥ 0.01), biased toward the ends.
fn pitch() -> impl Strategy<Value = f64> {
    prop_oneof![4 => -1.56..1.56f64, 1 => prop::sample::select(vec![0.0, 1.5607, -1.5607])]
}

/// A body velocity component, biased toward 0 and tiny values.
fn speed() -> impl Strategy<Value = f64> {
    prop_oneof![4 => -300.0..300.0f64, 1 => Just(0.0), 1 => Just(1e-7)]
}

/// Table 10.1 and §10.1: "six degrees of freedom … 12 first-order differential equations";
/// X, Θ, Z are longitudinal and Φ, Y, Ψ lateral. At the business jet's straight, level trim the
/// linearized 12-state model couples no longitudinal state [X Z U W Θ Q] to a lateral one
/// [Y V Φ Ψ P R] (the classification of Table 10.1; the block split of (14.5.1)).
#[test]
fn section_10_1_twelve_states_split_longitudinal_and_lateral() {
    let x = AircraftState::from_array(std::array::from_fn(|i| i as f64));
    assert_eq!(x.to_array().len(), 12);
    assert_eq!(x.to_array(), std::array::from_fn::<f64, 12, _>(|i| i as f64));
    let ac = business_jet();
    let t = trim(&ac, TrimSpec::Straight { airspeed: BUSINESS_JET_U0, gamma: 0.0 }, TrimLimits::default())
        .unwrap();
    let a = linearize(&ac, &t).unwrap().state_space.a().clone();
    // indices of (11.5.1): X Y Z U V W Φ Θ Ψ P Q R
    let longitudinal = [0usize, 2, 3, 5, 7, 10];
    let lateral = [1usize, 4, 6, 8, 9, 11];
    let scale = a.nan_amax();
    for &i in &longitudinal {
        for &j in &lateral {
            // dual-number Jacobian entries at a symmetric trim: zero to rounding of the trim
            assert!(a[(i, j)].abs() <= 1e-12 * scale, "A[{i},{j}] = {}", a[(i, j)]);
            assert!(a[(j, i)].abs() <= 1e-12 * scale, "A[{j},{i}] = {}", a[(j, i)]);
        }
    }
}

/// §10.2: "g⃗ = g k̂_E with k̂_E down, g = 9.8 m/s² ≈ 32.2 ft/s²", and (10.2.2) a falling
/// particle unaffected by the air accelerates at a⃗ = g⃗. The aircraft's centre of mass with
/// no aerodynamic force or thrust: its acceleration in F_E, 𝓞_{E/AC}(V̇|_AC + ω × V) by the
/// transport theorem, is (0, 0, g) whatever the attitude, rates and velocity.
#[test]
fn eq_10_2_2_free_fall_accelerates_along_k_e() {
    // 9.8 m/s² in ft/s² (1 ft = 0.3048 m exactly) is 32.15…, printed 32.2 (half a unit of the
    // printed last digit)
    assert!((9.8 / 0.3048 - 32.2f64).abs() <= 0.05);
    let frame = Airframe::new(1200.0, 900.0, 2500.0, 3000.0, 80.0).unwrap();
    let mut runner = proptest::test_runner::TestRunner::new(ProptestConfig::with_cases(128));
    let strat = (
        any_angle(),
        pitch(),
        any_angle(),
        [speed(), speed(), speed()],
        [-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64],
    );
    runner
        .run(&strat, |(psi, theta, phi, uvw, pqr)| {
            let x = AircraftState {
                position: [0.0; 3],
                velocity: uvw,
                attitude: Euler321::new(psi, theta, phi),
                omega: pqr,
            };
            let f = state_derivative(&frame, 9.8, &x, &ForcesMoments::default()).unwrap();
            let v = Vector3::from(uvw);
            let a_ac = Vector3::from(f.velocity) + Vector3::from(pqr).cross(&v);
            let a_e = x.attitude.o_ac_e().transpose() * a_ac;
            // |ω × V| ≤ 520: rounding of the Coriolis terms that cancel
            let tol = 64.0 * EPS * (9.8 + Vector3::from(pqr).norm() * v.norm());
            prop_assert!((a_e - Vector3::new(0.0, 0.0, 9.8)).nan_amax() <= tol, "{a_e}");
            Ok(())
        })
        .unwrap();
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// §10.4, (10.4.3)–(10.4.12): î_S is the unit vector of the projection of V⃗ on the plane of
    /// î_AC and k̂_AC; α is the directed angle from î_S to î_AC about ĵ_AC; F_S = F_AC turned by
    /// −α about ĵ_AC, so 𝓞_{S/AC} = 𝓞₂(−α) and 𝓞_{AC/S} = 𝓞₂(α) = 𝓞_{S/AC}ᵀ. Frame-free.
    #[test]
    fn section_10_4_stability_frame_from_the_projected_velocity(
        u in speed(), v in speed(), w in speed(), psi in any_angle(), theta in pitch(), phi in any_angle(),
    ) {
        prop_assume!(u * u + w * w > 0.0);
        let e = Frame::new();
        let ac = Frame::from_orientation_rel(&e, &Euler321::new(psi, theta, phi).o_ac_e(), 1e-12).unwrap();
        let vel = ac.vector([u, v, w]);
        // (10.4.3): V⃗_proj = (î î′ + k̂ k̂′)V⃗
        let proj = ac.i() * vel.dot(&ac.i()) + ac.k() * vel.dot(&ac.k());
        let i_s = proj.unit().unwrap();
        let alpha = ac.i().directed_angle_rel(&i_s, &ac.j()).unwrap();
        let angles = AeroAngles::from_body_velocity([u, v, w]);
        // atan2 of components vs the directed angle of vectors; the projection of V⃗ built in
        // F_E loses |V|/Ū digits when V⃗ is nearly along the wing; ±π agree mod 2π
        let tol = 64.0 * EPS * (1.0 + vel.norm() / u.hypot(w));
        let d = (alpha - angles.alpha + PI).rem_euclid(2.0 * PI) - PI;
        prop_assert!(d.abs() <= tol, "α = {alpha} vs {}", angles.alpha);
        let s = Frame::from_orientation_rel(&ac, &o_s_ac(angles.alpha), 1e-12).unwrap();
        prop_assert!((s.i() - i_s).norm() <= tol);
        prop_assert!((s.j() - ac.j()).norm() <= 64.0 * EPS);
        prop_assert!((ac.orientation_rel(&s) - o2(angles.alpha)).nan_amax() <= 64.0 * EPS);
        prop_assert!((o2(angles.alpha) - o_s_ac(angles.alpha).transpose()).nan_amax() <= 4.0 * EPS);
    }

    /// §10.5, (10.5.1)–(10.5.10): î_W = V̂; β is the directed angle from î_S to î_W about k̂_S;
    /// F_W = F_S turned by β about k̂_S = k̂_W (the book writes k̂_AC in (10.5.4), a slip), and
    /// F_E → F_W is the 3-2-1-2-3 sequence Ψ, Θ, Φ, −α, β:
    /// 𝓞_{W/E} = 𝓞₃(β)𝓞₂(−α)𝓞₁(Φ)𝓞₂(Θ)𝓞₃(Ψ); V⃗|_W = (V_AC, 0, 0).
    #[test]
    fn section_10_5_wind_frame_from_the_velocity(
        u in speed(), v in speed(), w in speed(), psi in any_angle(), theta in pitch(), phi in any_angle(),
    ) {
        prop_assume!(u * u + w * w > 0.0);
        let e = Frame::new();
        let euler = Euler321::new(psi, theta, phi);
        let ac = Frame::from_orientation_rel(&e, &euler.o_ac_e(), 1e-12).unwrap();
        let vel = ac.vector([u, v, w]);
        let angles = AeroAngles::from_body_velocity([u, v, w]);
        let s = Frame::from_orientation_rel(&ac, &o_s_ac(angles.alpha), 1e-12).unwrap();
        let wf = Frame::from_orientation_rel(&s, &o_w_s(angles.beta), 1e-12).unwrap();
        let beta = wf.i().directed_angle_rel(&s.i(), &s.k()).unwrap();
        prop_assert!((beta - angles.beta).abs() <= 64.0 * EPS, "β = {beta} vs {}", angles.beta);
        prop_assert!((wf.i() - vel.unit().unwrap()).norm() <= 64.0 * EPS);
        prop_assert!((wf.k() - s.k()).norm() <= 64.0 * EPS);
        let seq = o3(angles.beta) * o2(-angles.alpha) * o1(phi) * o2(theta) * o3(psi);
        prop_assert!((wf.orientation_rel(&e) - seq).nan_amax() <= 64.0 * EPS);
        let v_w = vel.resolve(&wf);
        let speed = vel.norm();
        prop_assert!((v_w - Vector3::new(speed, 0.0, 0.0)).nan_amax() <= 64.0 * EPS * speed);
        prop_assert!((angles.airspeed - speed).abs() <= 4.0 * EPS * speed);
    }

    /// §10.7, (10.7.1)–(10.7.5): r⃗_AC = Xî_E + Yĵ_E + Zk̂_E, H = −Z, and
    /// [Ẋ, Ẏ, Ż] = 𝓞_{E/AC}[U, V, W]: the body velocity V⃗ = Uî_AC + Vĵ_AC + Wk̂_AC resolved in
    /// F_E (frame-free) is the position rate of the equations of motion; Ḣ = −Ż.
    #[test]
    fn section_10_7_range_drift_plunge_rates(
        u in speed(), v in speed(), w in speed(), psi in any_angle(), theta in pitch(), phi in any_angle(),
    ) {
        let e = Frame::new();
        let euler = Euler321::new(psi, theta, phi);
        let ac = Frame::from_orientation_rel(&e, &euler.o_ac_e(), 1e-12).unwrap();
        let vel = ac.i() * u + ac.j() * v + ac.k() * w;
        let frame = Airframe::new(1200.0, 900.0, 2500.0, 3000.0, 80.0).unwrap();
        let x = AircraftState { position: [10.0, -20.0, -3000.0], velocity: [u, v, w], attitude: euler, omega: [0.0; 3] };
        let f = state_derivative(&frame, 9.8, &x, &ForcesMoments::default()).unwrap();
        let scale = 64.0 * EPS * vel.norm();
        prop_assert!((Vector3::from(f.position) - vel.resolve(&e)).nan_amax() <= scale);
        // altitude H = −Z = 3000 rises at Ḣ = −Ż = the upward component of V⃗
        prop_assert!((-f.position[2] - vel.dot(&(-e.k()))).abs() <= scale);
    }
}

/// §10.10, (10.10.1) corrected and (10.10.4): with r⃗|_AC(t) and the attitude (Ψ, Θ, Φ)(t)
/// given as functions of time, r̈⃗^{E••} = r̈⃗^{AC••} + 2ω⃗ × r⃗^{AC•} + α⃗ × r⃗ + ω⃗ × (ω⃗ × r⃗)
/// (Coriolis, angular-acceleration and centripetal terms; the printed decomposition mixes
/// E- and AC-derivatives, so the double transport theorem (4.5.1) is what is checked);
/// α⃗ = ω⃗^{E•} = ω⃗^{AC•}; and (ω⃗ × r⃗)|_AC = [P, Q, R]^× r|_AC. Reference: r|_E(t) =
/// 𝓞_{E/AC}(t) r|_AC(t) differentiated twice by a hyper-dual number.
/// c0 + c1 t + c2 t².
fn poly<T: Scalar>(t: T, c: [f64; 3]) -> T {
    T::lit(c[0]) + T::lit(c[1]) * t + T::lit(c[2]) * t * t
}

/// The attitude path (Ψ, Θ, Φ)(t) and its rates (Φ̇, Θ̇, Ψ̇) of the §10.10 test.
const PSI: [f64; 3] = [0.3, 0.4, -0.2];
const THETA: [f64; 3] = [-0.2, 0.3, 0.1];
const PHI: [f64; 3] = [0.5, -0.7, 0.3];
/// The body components r|_AC(t).
const R_AC: [[f64; 3]; 3] = [[3.0, 1.0, -0.5], [-1.0, 2.0, 0.0], [-0.2, 0.0, 0.5]];

fn attitude<T: Scalar>(t: T) -> Euler321<T> {
    Euler321::new(poly(t, PSI), poly(t, THETA), poly(t, PHI))
}

fn rate<T: Scalar>(t: T, c: [f64; 3]) -> T {
    T::lit(c[1]) + T::lit(2.0 * c[2]) * t
}

#[test]
fn eq_10_10_1_double_transport_in_the_aircraft_frame() {
    for t0 in [0.0, 0.8, -1.3] {
        let t = HyperDual64::new(t0, 1.0, 1.0, 0.0);
        let r_ac = Vector3::from_fn(|i, _| poly(t, R_AC[i]));
        let r_e = attitude(t).o_ac_e().transpose() * r_ac;
        let a_e_ref = r_e.map(|x| x.eps1eps2);
        let o = attitude(t0).o_ac_e();
        let (r, r1, r2) = (r_ac.map(|x| x.re), r_ac.map(|x| x.eps1), r_ac.map(|x| x.eps1eps2));
        // ω|_AC = S(Φ, Θ)[Φ̇, Θ̇, Ψ̇] (10.9.8) along the path, α|_AC = its derivative (a dual number)
        let td = Dual64::new(t0, 1.0);
        let w_dual =
            Vector3::from(body_rates(&attitude(td), [rate(td, PHI), rate(td, THETA), rate(td, PSI)]));
        let (w, alpha) = (w_dual.map(|x| x.re), w_dual.map(|x| x.eps));
        // all terms resolved in F_AC, then brought to F_E
        let a_ac = r2 + 2.0 * w.cross(&r1) + alpha.cross(&r) + w.cross(&w.cross(&r));
        let a_e = o.transpose() * a_ac;
        // terms of size ≈ 10: a few dozen roundings
        assert!((a_e - a_e_ref).nan_amax() <= 256.0 * EPS * 10.0, "{a_e} vs {a_e_ref}");
        // (10.10.4)
        let [p, q, rr] = [w[0], w[1], w[2]];
        let wx = Matrix3::new(0.0, -rr, q, rr, 0.0, -p, -q, p, 0.0);
        assert!((wx * r - w.cross(&r)).nan_amax() <= 4.0 * EPS * 10.0);
        // α⃗ is the same derivative in both frames: d/dt(ω|_E) = 𝓞_{E/AC} α|_AC
        let w_e = attitude(td).o_ac_e().transpose() * w_dual;
        assert!((w_e.map(|x| x.eps) - o.transpose() * alpha).nan_amax() <= 64.0 * EPS);
    }
}
