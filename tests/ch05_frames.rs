//! Chapter 5: alternative frames (book §5.1–5.7): cylindrical, spherical and Frenet–Serret
//! frames, plus the Bishop (parallel-transport) frame the notes recommend where κ = 0.
//!
//! Oracles: exact derivatives by num-dual (`Dual2_64` for coordinates, `Dual3_64` for curves).

mod support;

use std::f64::consts::PI;

use vectrix::kinematics::*;
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::num_dual::{Dual2_64, Dual3_64, DualNum};
use vectrix::prelude::*;

use support::{EPS, NanAmax, assert_printed, assert_printed_slice};

/// Exact derivatives: rounding only, on O(1)–O(10) data.
const TOL: f64 = 1024.0 * EPS;

fn arr(v: Vector3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

fn dist(x: &Vector, y: &Vector) -> f64 {
    (*x - *y).norm()
}

/// Coordinates q(t) = c₀ + c₁t + c₂t² with exact first and second derivatives.
fn coords(c: [[f64; 3]; 3], t: f64) -> ([f64; 3], [f64; 3], [f64; 3]) {
    let q = |k: usize| c[k][0] + c[k][1] * t + c[k][2] * t * t;
    let qd = |k: usize| c[k][1] + 2.0 * c[k][2] * t;
    let qdd = |k: usize| 2.0 * c[k][2];
    ([q(0), q(1), q(2)], [qd(0), qd(1), qd(2)], [qdd(0), qdd(1), qdd(2)])
}

/// r|_A(t) and its derivatives from a position map applied to dual coordinates.
fn position_jet(
    c: [[f64; 3]; 3],
    t: f64,
    map: impl Fn([Dual2_64; 3]) -> Vector3<Dual2_64>,
) -> [Vector3<f64>; 3] {
    let (q, qd, qdd) = coords(c, t);
    let d = |k: usize| Dual2_64::new(q[k], qd[k], qdd[k]);
    let r = map([d(0), d(1), d(2)]);
    [r.map(|x| x.re), r.map(|x| x.v1), r.map(|x| x.v2)]
}

const CYL: [[f64; 3]; 3] = [[1.5, 0.4, -0.3], [0.3, 1.2, 0.5], [-0.2, 0.7, 0.25]];
const SPH: [[f64; 3]; 3] = [[2.0, -0.5, 0.4], [0.8, 0.9, -0.6], [0.35, -0.4, 0.3]];

// §5.1–5.2: cylindrical coordinates. v|_cyl = (ṙ_r, r_rθ̇, ṙ_a) and
// a|_cyl = (r̈_r − r_rθ̇², r_rθ̈ + 2ṙ_rθ̇, r̈_a) ((5.2.10), whose OCR line is garbled), against exact
// derivatives of r|_A = (r_r cos θ, r_r sin θ, r_a); ω⃗_{cyl/A} = θ̇ê_a.
#[test]
fn eq_5_2_10_cylindrical_velocity_and_acceleration() {
    let a = Frame::new();
    for t in [0.0, 0.6, 1.7] {
        let (q, qd, qdd) = coords(CYL, t);
        let cyl = Cylindrical { q, q_dot: qd, q_ddot: qdd };
        let [r, v, acc] = position_jet(CYL, t, |[rr, th, ra]| Vector3::new(rr * th.cos(), rr * th.sin(), ra));
        assert!((cyl.position_in_a() - r).nan_amax() < TOL);
        let [w, vel, accel] = cyl.kinematics(&a).unwrap();
        assert!(dist(&vel, &a.vector(arr(v))) < TOL, "v at t = {t}");
        assert!(dist(&accel, &a.vector(arr(acc))) < TOL, "a at t = {t}");
        assert!(dist(&w, &(a.k() * qd[1])) < TOL);
        let back = Cylindrical::from_position(arr(r)).unwrap();
        assert!((back.q[0] - q[0]).abs() < TOL && congruent(back.q[1], q[1], TOL));
    }
    // θ := 0 on the axis (the book's choice)
    assert_eq!(Cylindrical::from_position([0.0, 0.0, 2.0]).unwrap().q, [0.0, 0.0, 2.0]);
    assert!(matches!(
        Cylindrical::from_position([f64::NAN, 0.0, 0.0]),
        Err(KinematicsError::NonFinite { .. })
    ));
}

/// r|_A = r_u(cos φ cos θ, cos φ sin θ, −sin φ) (5.3.41–43).
fn sph_map([r, th, ph]: [Dual2_64; 3]) -> Vector3<Dual2_64> {
    Vector3::new(r * ph.cos() * th.cos(), r * ph.cos() * th.sin(), -r * ph.sin())
}

// §5.3 (sign quirk): φ is positive *below* the î–ĵ plane; 𝓞_{sph/A} = 𝓞₂(φ)𝓞₃(θ) with rows
// ê_u = (cφcθ, cφsθ, −sφ), ê_e = (−sθ, cθ, 0), ê_n = (sφcθ, sφsθ, cφ).
#[test]
fn eq_5_3_13_spherical_frame_and_sign_of_phi() {
    let below = Spherical::from_position([1.0, 1.0, -1.0]).unwrap();
    assert!(below.q[2] > 0.0, "below the plane: φ > 0");
    assert!((below.q[2] - (1.0 / 2f64.sqrt()).atan()).abs() < TOL);
    assert!((below.q[1] - PI / 4.0).abs() < TOL && (below.q[0] - 3f64.sqrt()).abs() < TOL);
    let (th, ph) = (0.7, -0.4);
    let s = Spherical { q: [1.0, th, ph], q_dot: [0.0; 3], q_ddot: [0.0; 3] };
    let (c, sn) = (|x: f64| x.cos(), |x: f64| x.sin());
    let want = Matrix3::new(
        c(ph) * c(th),
        c(ph) * sn(th),
        -sn(ph),
        -sn(th),
        c(th),
        0.0,
        sn(ph) * c(th),
        sn(ph) * sn(th),
        c(ph),
    );
    assert!((s.o_sph_a() - want).nan_amax() < TOL);
    // the poles and origin get atan2's values, never NaN
    assert_eq!(Spherical::from_position([0.0, 0.0, 0.0]).unwrap().q, [0.0, 0.0, 0.0]);
    assert!((Spherical::from_position([0.0, 0.0, -2.0]).unwrap().q[2] - PI / 2.0).abs() < TOL);
}

// §5.4: ω|_sph = (−θ̇ sin φ, φ̇, θ̇ cos φ) (5.4.2); v|_sph = (ṙ, rθ̇cφ, −rφ̇); the acceleration
// (5.4.10) with the north term −rφ̈ − 2ṙφ̇ − rθ̇² sin φ cos φ (the collected line prints +; its
// underbrace form is right); Coriolis 2ṙ(θ̇cφ ê_e − φ̇ ê_n) (5.4.11).
#[test]
fn eq_5_4_10_spherical_velocity_and_acceleration_corrected() {
    let a = Frame::new();
    for t in [0.0, 0.5, 1.1] {
        let (q, qd, qdd) = coords(SPH, t);
        let s = Spherical { q, q_dot: qd, q_ddot: qdd };
        let [r, v, acc] = position_jet(SPH, t, sph_map);
        assert!((s.position_in_a() - r).nan_amax() < TOL);
        let [w, vel, accel] = s.kinematics(&a).unwrap();
        assert!(dist(&vel, &a.vector(arr(v))) < TOL, "v at t = {t}");
        assert!(dist(&accel, &a.vector(arr(acc))) < TOL, "a at t = {t}");
        // ω from Poisson (4.3.20) on 𝓞_{sph/A}(t)
        let o = |t: Dual2_64| {
            let (q, qd, qdd) = coords(SPH, t.re);
            let ang = |k: usize| Dual2_64::new(q[k], qd[k] * t.v1, qdd[k]);
            let (th, ph) = (ang(1), ang(2));
            let (st, ct, sp, cp) = (th.sin(), th.cos(), ph.sin(), ph.cos());
            let z = Dual2_64::from(0.0);
            Matrix3::new(cp * ct, cp * st, -sp, -st, ct, z, sp * ct, sp * st, cp)
        };
        let m = o(Dual2_64::new(t, 1.0, 0.0));
        let (o0, od) = (m.map(|x| x.re), m.map(|x| x.v1));
        let w_b = omega_body_from_orientation_rate(&o0, &od).unwrap();
        assert!((w_b - s.omega_in_sph()).nan_amax() < TOL);
        assert!(dist(&w, &s.frame(&a).unwrap().vector(arr(w_b))) < TOL);
        // the printed "+" in the collected north term would be wrong here
        let [r_u, _, ph] = q;
        let printed_north = -r_u * qdd[2] - 2.0 * qd[0] * qd[2] + r_u * qd[1] * qd[1] * ph.sin() * ph.cos();
        assert!((s.acceleration_in_sph().z - printed_north).abs() > 1e-3);
        let cor = s.coriolis_in_sph();
        assert!(
            (cor - Vector3::new(0.0, 2.0 * qd[0] * qd[1] * ph.cos(), -2.0 * qd[0] * qd[2])).nan_amax() < TOL
        );
    }
}

// P5.7.1 (bowling, Coriolis): a ball rolled with speed v down a lane l long at latitude λ north,
// the lane in any horizontal direction: the Coriolis acceleration and the ball's lateral
// position at the end of the lane. Inputs as in the notes (λ = 45°, l = 60 ft = 18.288 m,
// v = 8 m/s, Ω = 7.2921e-5 rad/s); notes [C]: horizontal Coriolis acceleration 2Ωv sin λ =
// 8.25e-4 m/s² for every heading, deflecting to the right, and a lateral offset ≈ 2.16 mm.
//
// Computed through vectrix: the Coriolis term 2ω⃗×v⃗ of (4.5.1) by `double_transport`, its
// horizontal part by the projector off ê_u, and the ball's path by integrating the horizontal
// relative motion a⃗ = −P_h(2ω⃗×v⃗) with DOP853 to the end of the lane (a terminal event). The
// vertical Coriolis part is carried by the lane's normal force and the centrifugal term is part
// of local gravity. That motion is a circle of radius ρ = v/(2Ω sin λ) at speed v, so at the
// end of the lane the offset is ρ(1 − √(1 − (l/ρ)²)) ≈ Ω sin λ l²/v exactly.
#[test]
fn problem_5_7_1_bowling_coriolis() {
    use vectrix::nalgebra::Vector4;
    use vectrix::ode::{Adaptive, Direction, Event};
    let (omega, lat, l, v) = (7.2921e-5, PI / 4.0, 18.288, 8.0);
    // local spherical frame at (θ, φ): ê_u up, ê_e east, ê_n north; Earth spins about k̂_A
    let s = Spherical { q: [6.371e6, 0.3, -lat], q_dot: [0.0; 3], q_ddot: [0.0; 3] };
    let a = Frame::new();
    let f = s.frame(&a).unwrap();
    let w = a.k() * omega;
    assert!((w.dot(&f.i()) - omega * lat.sin()).abs() < 1e-18, "up component Ω sin λ");
    let horizontal = Dyadic::projector_perp(&f.i()).unwrap();
    // the closed form of the horizontal Coriolis motion: a circle of radius ρ
    let rho = v / (2.0 * omega * lat.sin());
    let offset = rho * (1.0 - (1.0 - (l / rho).powi(2)).sqrt());
    let mut offsets = Vec::new();
    for heading in [0.0, 0.8, 2.0, -2.5] {
        // along the lane ĥ and to its right r̂ = ĥ × ê_u (east for a lane heading north)
        let h = f.k() * heading.cos() + f.j() * heading.sin();
        let right = h.cross(&f.i());
        // horizontal Coriolis acceleration of (4.5.1), 2ω⃗×v⃗ with v⃗ = vĥ
        let coriolis = |vel: &Vector| {
            horizontal * double_transport(&Vector::zero(), vel, &Vector::zero(), &w, &Vector::zero())
        };
        let cor = coriolis(&(h * v));
        assert!((cor.norm() - 2.0 * omega * v * lat.sin()).abs() < 8.0 * EPS * cor.norm());
        assert_printed(cor.norm(), "8.25e-4");
        // y = (s, d, ṡ, ḋ) along and to the right of the lane; relative acceleration −P_h 2ω⃗×v⃗
        let rhs = |_: f64, y: &Vector4<f64>| {
            let acc = -coriolis(&(h * y[2] + right * y[3]));
            Vector4::new(y[2], y[3], acc.dot(&h), acc.dot(&right))
        };
        let mut end =
            [Event::new(|_, y: &Vector4<f64>| y[0] - l).direction(Direction::Rising).terminal(true)];
        let sol = Adaptive::dop853()
            .rtol(1e-13)
            .atol(1e-13)
            .solve_with_events(rhs, 0.0, &Vector4::new(0.0, 0.0, v, 0.0), 10.0, &mut end)
            .unwrap();
        assert!(sol.terminated, "the ball reaches the end of the lane");
        let hit = &sol.events[0];
        assert!((hit.y[0] - l).abs() <= 1e-12 * l);
        // to the right in the northern hemisphere, for every heading
        assert!(hit.y[1] > 0.0);
        // DOP853 at rtol = atol = 1e-13 over ~2.3 s of a nearly straight path: the lateral
        // coordinate (≈ 2e-3 m, beside s ≈ 18 m) is good to ~1e-12 m; 1e-10 m leaves margin
        assert!((hit.y[1] - offset).abs() <= 1e-10, "heading {heading}: {} vs {offset}", hit.y[1]);
        // the speed is unchanged (the Coriolis force does no work): the time is ≈ l/v
        assert!((hit.t - (l / rho).asin() * rho / v).abs() <= 1e-10);
        offsets.push(hit.y[1]);
    }
    assert_printed(offsets[0], "2.16e-3");
    // the first-order offset the notes quote, Ω sin λ l²/v, differs by O((l/ρ)²) ≈ 1e-7 relative
    assert!((offset - omega * lat.sin() * l * l / v).abs() <= 1e-6 * offset);
}

/// r′, r″, r‴ of a curve given over `Dual3_64`.
fn curve(f: impl Fn(Dual3_64) -> [Dual3_64; 3], alpha: f64) -> [Vector; 3] {
    let a = Frame::new();
    let r = f(Dual3_64::new(alpha, 1.0, 0.0, 0.0));
    [a.vector(r.map(|x| x.v1)), a.vector(r.map(|x| x.v2)), a.vector(r.map(|x| x.v3))]
}

fn fs(f: impl Fn(Dual3_64) -> [Dual3_64; 3], alpha: f64) -> Result<FrenetSerret, KinematicsError> {
    let [r1, r2, r3] = curve(f, alpha);
    FrenetSerret::from_derivatives(&r1, &r2, &r3, 1e-12, 1e-12)
}

fn helix(r: f64, h: f64) -> impl Fn(Dual3_64) -> [Dual3_64; 3] {
    move |s| {
        let c = (r * r + h * h).sqrt();
        [(s / c).cos() * r, (s / c).sin() * r, s * (h / c)]
    }
}

// P5.6.2: the helix in arc length has κ = r/(r² + h²), τ = h/(r² + h²); with r = 2, h = 0.5:
// κ = 0.470588, τ = 0.117647 (notes). Unit speed confirms the arc-length parametrization.
#[test]
fn problem_5_6_2_helix() {
    let (r, h) = (2.0, 0.5);
    for s in [0.0, 1.0, 7.5] {
        let f = fs(helix(r, h), s).unwrap();
        assert!((f.speed - 1.0).abs() < TOL);
        assert!((f.curvature - r / (r * r + h * h)).abs() < TOL);
        assert!((f.torsion - h / (r * r + h * h)).abs() < TOL);
        assert_printed_slice(&[f.curvature, f.torsion], &["0.470588", "0.117647"]);
        // the normal points at the axis
        let p = Frame::new().vector([(s / 4.25f64.sqrt()).cos(), (s / 4.25f64.sqrt()).sin(), 0.0]);
        assert!(dist(&f.normal, &(-p)) < TOL);
    }
}

// P5.6.3: the logarithmic spiral e^α(cos α, sin α) has κ = 1/s only with s measured from the pole,
// s = √2 e^α (notes: with s from α = 0 as in (5.5.7) the claim fails). At α = 0.4, κ = 0.473988.
#[test]
fn problem_5_6_3_log_spiral_arc_length_from_the_pole() {
    let spiral = |a: Dual3_64| [a.exp() * a.cos(), a.exp() * a.sin(), Dual3_64::from(0.0)];
    for alpha in [-1.0, 0.4, 2.0] {
        let f = fs(spiral, alpha).unwrap();
        let s_pole = 2f64.sqrt() * alpha.exp();
        assert!((f.curvature - 1.0 / s_pole).abs() < TOL);
        assert!(f.torsion.abs() < TOL, "planar");
    }
    let f = fs(spiral, 0.4).unwrap();
    assert_printed(f.curvature, "0.473988");
    let s_from_zero = 2f64.sqrt() * (0.4f64.exp() - 1.0);
    assert!((f.curvature - 1.0 / s_from_zero).abs() > 0.5);
}

// P5.6.4 (catenary, corrected): r(α) = αî + a cosh(α/a)ĵ (the printed x-component "a" should be
// α) has κ = a/(s² + a²), not the printed a/(s² + a). At a = 1.5, α = 0.8: κ = 0.507953.
#[test]
fn problem_5_6_4_catenary_corrected() {
    let a = 1.5;
    let cat = move |x: Dual3_64| [x, (x / a).cosh() * a, Dual3_64::from(0.0)];
    for x in [0.0, 0.8, -2.0] {
        let f = fs(cat, x).unwrap();
        let s = a * (x / a).sinh();
        assert!((f.curvature - a / (s * s + a * a)).abs() < TOL);
    }
    let f = fs(cat, 0.8).unwrap();
    assert_printed(f.curvature, "0.507953");
    let s = a * (0.8 / a).sinh();
    assert!((f.curvature - a / (s * s + a)).abs() > 1e-2, "the printed form is wrong");
}

/// A general space curve with nonzero curvature and torsion.
fn twisted(t: Dual3_64) -> [Dual3_64; 3] {
    [t.cos() * 1.3 + t * 0.2, (t * 2.0).sin(), t * t * 0.3 + t.powi(3) * 0.05]
}

// (5.5.43), (5.5.49), (5.5.53): d ê/dα = s′ ω⃗_s × ê for the Darboux vector ω⃗_s = τê_t + κê_b;
// (5.5.38): both torsion forms agree; (5.5.66–69): a⃗ = v̇ê_t + (v²/ρ)ê_n.
#[test]
fn eq_5_5_43_frenet_relations_and_darboux_vector() {
    let alpha = 0.7;
    let f = fs(twisted, alpha).unwrap();
    let h = 1e-5;
    let (fp, fm) = (fs(twisted, alpha + h).unwrap(), fs(twisted, alpha - h).unwrap());
    let d = |p: Vector, m: Vector| (p - m) / (2.0 * h);
    let w = f.darboux_per_parameter();
    // central differences of exact frames: error ~h²·|ê‴| ≈ 1e-9
    for (e, dp) in [
        (f.tangent, d(fp.tangent, fm.tangent)),
        (f.normal, d(fp.normal, fm.normal)),
        (f.binormal, d(fp.binormal, fm.binormal)),
    ] {
        assert!(dist(&w.cross(&e), &dp) < 1e-8);
    }
    let [r1, r2, r3] = curve(twisted, alpha);
    let rho = f.radius_of_curvature();
    let tau_printed = -(rho * rho / f.speed.powi(6)) * r2.dot(&r1.cross(&r3));
    assert!((tau_printed - f.torsion).abs() < TOL);
    assert!(dist(&f.acceleration(), &r2) < TOL, "(5.5.69) with α = t");
    assert!((f.speed_rate - r1.dot(&r2) / r1.norm()).abs() < TOL);
    assert!(f.frame().is_ok());
}

// (5.5.33), P5.6.5, notes §3: Frenet–Serret is undefined where κ = 0 (straight line, inflection)
// or s′ = 0 (cusp): typed errors, never NaN.
#[test]
fn frenet_serret_errors_at_zero_curvature_and_zero_speed() {
    let line = |t: Dual3_64| [t * 2.0, t * -1.0, t * 0.5];
    assert!(matches!(fs(line, 0.3), Err(KinematicsError::ZeroCurvature { .. })));
    let cubic = |t: Dual3_64| [t, t.powi(3), Dual3_64::from(0.0)];
    assert!(matches!(fs(cubic, 0.0), Err(KinematicsError::ZeroCurvature { .. })));
    assert!(fs(cubic, 0.1).is_ok());
    let cusp = |t: Dual3_64| [t.powi(3), t.powi(2), Dual3_64::from(0.0)];
    assert!(matches!(fs(cusp, 0.0), Err(KinematicsError::ZeroSpeed { .. })));
    let a = Frame::new();
    let nan = FrenetSerret::from_derivatives(&a.vector([f64::NAN, 0.0, 0.0]), &a.i(), &a.j(), 0.0, 0.0);
    assert!(matches!(nan, Err(KinematicsError::NonFinite { .. })));
}

// P5.6.2 with dual numbers (DESIGN §1.4): curvature is generic over the scalar, so its exact
// derivative with respect to the helix radius comes out of one evaluation:
// dκ/dr = (h² − r²)/(r² + h²)².
#[test]
fn problem_5_6_2_helix_curvature_sensitivity_with_dual_numbers() {
    use vectrix::num_dual::Dual64;
    let (r, h, s) = (Dual64::new(2.0, 1.0), Dual64::from(0.5), 0.7);
    let a = Frame::<Dual64>::identity();
    let c = (r * r + h * h).sqrt();
    let (ca, sa) = ((Dual64::from(s) / c).cos(), (Dual64::from(s) / c).sin());
    // r′, r″, r‴ of the arc-length helix, written out
    let r1 = a.vector([-r * sa / c, r * ca / c, h / c]);
    let r2 = a.vector([-r * ca / (c * c), -r * sa / (c * c), Dual64::from(0.0)]);
    let r3 = a.vector([r * sa / (c * c * c), -r * ca / (c * c * c), Dual64::from(0.0)]);
    let f = FrenetSerret::from_derivatives(&r1, &r2, &r3, 1e-12, 1e-12).unwrap();
    let (rr, hh) = (2.0f64, 0.5f64);
    assert!((f.curvature.re - rr / (rr * rr + hh * hh)).abs() < TOL);
    let want = (hh * hh - rr * rr) / (rr * rr + hh * hh).powi(2);
    assert!((f.curvature.eps - want).abs() < TOL, "{} vs {want}", f.curvature.eps);
}

/// Samples (positions, unit tangents) of a curve on [a, b].
fn samples(f: impl Fn(Dual3_64) -> [Dual3_64; 3], a: f64, b: f64, n: usize) -> (Vec<Vector>, Vec<Vector>) {
    let fa = Frame::new();
    (0..=n)
        .map(|i| {
            let t = a + (b - a) * i as f64 / n as f64;
            let r = f(Dual3_64::new(t, 1.0, 0.0, 0.0));
            (fa.vector(r.map(|x| x.re)), fa.vector(r.map(|x| x.v1)).unit().unwrap())
        })
        .unzip()
}

// Bishop frame (notes §3 remedy): on the helix, û₁ = cos ψ ê_n + sin ψ ê_b with ψ′ = −τ (arc
// length), i.e. the Frenet frame untwisted by ∫τ ds.
#[test]
fn bishop_frame_on_the_helix_untwists_frenet() {
    let (r, h) = (2.0, 0.5);
    let n = 400;
    let s_end = 6.0;
    let (p, t) = samples(helix(r, h), 0.0, s_end, n);
    let f0 = fs(helix(r, h), 0.0).unwrap();
    let frames = bishop_frames(&p, &t, &f0.normal).unwrap();
    let tau = h / (r * r + h * h);
    for (i, fr) in frames.iter().enumerate().step_by(50) {
        let s = s_end * i as f64 / n as f64;
        let f = fs(helix(r, h), s).unwrap();
        let psi = -tau * s;
        let want = f.normal * psi.cos() + f.binormal * psi.sin();
        // double reflection is 4th order in the spacing 0.015: error ≲ 1e-8
        assert!(dist(&fr.j(), &want) < 1e-7, "s = {s}");
        assert!(dist(&fr.i(), &f.tangent) < TOL);
    }
}

// Bishop frame through an inflection (y = x³ at x = 0, where Frenet–Serret fails and its
// normal flips): the Bishop normal stays continuous.
#[test]
fn bishop_frame_through_an_inflection() {
    let cubic = |t: Dual3_64| [t, t.powi(3), t * 0.0];
    let (p, t) = samples(cubic, -1.0, 1.0, 200);
    let a = Frame::new();
    let frames = bishop_frames(&p, &t, &a.k()).unwrap();
    for w in frames.windows(2) {
        assert!(w[0].j().dot(&w[1].j()) > 0.999);
    }
    // planar curve: the out-of-plane normal stays k̂
    assert!(frames.iter().all(|f| dist(&f.j(), &a.k()) < 1e-12));
    assert!(fs(cubic, 0.0).is_err());
    assert!(fs(cubic, -0.5).unwrap().normal.dot(&fs(cubic, 0.5).unwrap().normal) < 0.0, "FS normal flips");
    assert!(matches!(bishop_frames(&p, &t[1..], &a.k()), Err(KinematicsError::OutOfRange { .. })));
    assert!(matches!(bishop_frames(&p, &t, &t[0]), Err(KinematicsError::Zero { .. })));
}

mod prop {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        // Cartesian → spherical → Cartesian round trip, with the book's sign for φ.
        #[test]
        fn spherical_round_trip(r in support::triple()) {
            let s = Spherical::from_position(r).unwrap();
            prop_assert!(s.q[2].abs() <= PI / 2.0);
            prop_assert!((s.q[2] > 0.0) == (r[2] < 0.0) || r[2] == 0.0);
            let back = s.position_in_a();
            let scale = 1.0 + Vector3::from(r).norm();
            prop_assert!((back - Vector3::from(r)).nan_amax() < 16.0 * EPS * scale);
            let c = Cylindrical::from_position(r).unwrap();
            prop_assert!((c.position_in_a() - Vector3::from(r)).nan_amax() < 16.0 * EPS * scale);
        }

        // The Frenet frame is orthonormal and right-handed wherever it is defined; κ ≥ 0.
        #[test]
        fn frenet_frame_is_orthonormal(r1 in support::direction(), r2 in support::triple(), r3 in support::triple()) {
            let a = Frame::new();
            if let Ok(f) = FrenetSerret::from_derivatives(&a.vector(r1), &a.vector(r2), &a.vector(r3), 1e-12, 1e-9) {
                prop_assert!(f.frame().is_ok());
                prop_assert!(f.curvature > 0.0);
                prop_assert!(dist(&f.tangent.cross(&f.normal), &f.binormal) < 16.0 * EPS);
            }
        }
    }
}

// §5.1: the cylindrical frame F_cyl = R⃗_{k̂_A}(θ)F_A (5.1.1) with ê_r = cos θ î + sin θ ĵ,
// ê_t = −sin θ î + cos θ ĵ, ê_a = k̂ (5.1.14–16), 𝓞_{cyl/A} = 𝓞₃(θ) (5.1.13); in it r⃗ has
// r_t = 0 (5.1.21), r_r = √(r₁² + r₂²), θ = atan2(r₂, r₁), r_a = r₃ (5.1.30–32); θ := 0 on the
// axis, and r₁ = 0 gives θ = ±π/2 with the sign of r₂ (text after (5.1.25)).
#[test]
fn section_5_1_cylindrical_frame_and_coordinates() {
    let a = Frame::new();
    for r in [[1.0f64, 2.0, -0.5], [-3.0, -0.1, 2.0], [0.0, -2.0, 1.0], [0.0, 4.0, 0.0], [-2.0, 0.0, 1.0]] {
        let c = Cylindrical::from_position(r).unwrap();
        let [rr, th, ra] = c.q;
        assert_eq!(th, r[1].atan2(r[0]));
        assert_eq!(ra, r[2]);
        assert!((rr - r[0].hypot(r[1])).abs() <= 2.0 * EPS * rr);
        let f = c.frame(&a).unwrap();
        let o3 = Matrix3::new(th.cos(), th.sin(), 0.0, -th.sin(), th.cos(), 0.0, 0.0, 0.0, 1.0);
        assert!((f.orientation_rel(&a) - o3).nan_amax() <= 4.0 * EPS);
        assert!((c.o_cyl_a() - o3).nan_amax() <= 4.0 * EPS);
        // r⃗ in F_cyl: (r_r, 0, r_a)
        let in_cyl = a.vector(r).resolve(&f);
        assert!((in_cyl - Vector3::new(rr, 0.0, ra)).nan_amax() <= 8.0 * EPS * (1.0 + rr), "{in_cyl}");
    }
    assert_eq!(Cylindrical::from_position([0.0, -2.0, 1.0]).unwrap().q[1], -PI / 2.0);
    assert_eq!(Cylindrical::from_position([0.0, 3.0, 1.0]).unwrap().q[1], PI / 2.0);
    assert_eq!(Cylindrical::from_position([-2.0, 0.0, 1.0]).unwrap().q[1], PI);
    assert_eq!(Cylindrical::from_position([0.0, 0.0, 5.0]).unwrap().q, [0.0, 0.0, 5.0]);
}

/// A body-fixed point's path in F_A: r(t) = p(t) + 𝓡₃(φ(t)) x_B, with a cubic translation p and
/// φ = c₀t + c₁t² (φ ≡ 0 for a translating body), as exact third-order jets.
fn body_point(p: [[f64; 3]; 3], phi: [f64; 2], x_b: [f64; 3]) -> impl Fn(Dual3_64) -> [Dual3_64; 3] {
    move |t: Dual3_64| {
        let q = |k: usize| t * p[k][0] + t * t * p[k][1] + t * t * t * p[k][2];
        let f = t * phi[0] + t * t * phi[1];
        let (s, c) = (f.sin(), f.cos());
        [q(0) + c * x_b[0] - s * x_b[1], q(1) + s * x_b[0] + c * x_b[1], q(2) + x_b[2]]
    }
}

mod problems {
    use proptest::prelude::*;

    use super::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        /// P5.6.1: if dΘ_{B/A}/dα = 0 (the frames do not turn relative to each other as α varies),
        /// then d r⃗/dα is the same with respect to F_A and to F_B: the α-derivative of the
        /// A-components, made physical in F_A, equals that of the B-components in F_B.
        #[test]
        fn problem_5_6_1_parameter_derivative_is_frame_independent_without_relative_rotation(
            b in support::frame(), c in proptest::array::uniform3(proptest::array::uniform3(-1.0..1.0f64)), alpha in -1.0..1.0f64,
        ) {
            let a = Frame::new();
            let o_ba = b.orientation_rel(&a);
            let r_a = |s: Dual2_64| Vector3::from_fn(|k, _| s * c[k][0] + s * s * c[k][1] + (s * c[k][2]).sin());
            let da = r_a(Dual2_64::new(alpha, 1.0, 0.0)).map(|x| x.v1);
            let db = (o_ba.map(Dual2_64::from) * r_a(Dual2_64::new(alpha, 1.0, 0.0))).map(|x| x.v1);
            prop_assert!(dist(&a.vector(arr(da)), &b.vector(arr(db))) <= TOL);
        }

        /// P5.6.5: τ ≠ 0 ⇒ κ ≠ 0. With κ = |r⃗′×r⃗″|/|r⃗′|³ and τ = (r⃗′×r⃗″)·r⃗‴/|r⃗′×r⃗″|²,
        /// κ²|r⃗′|⁶τ = (r⃗′×r⃗″)·r⃗‴, which vanishes with κ; vectrix returns τ only where κ > 0.
        #[test]
        fn problem_5_6_5_torsion_needs_curvature(
            r1 in support::direction(), r2 in support::triple(), r3 in support::triple(), s in -2.0..2.0f64,
        ) {
            let a = Frame::new();
            let (r1, r2, r3) = (a.vector(r1), a.vector(r2), a.vector(r3));
            if let Ok(f) = FrenetSerret::from_derivatives(&r1, &r2, &r3, 1e-12, 1e-9) {
                let triple = r1.cross(&r2).dot(&r3);
                let lhs = f.curvature.powi(2) * r1.norm().powi(6) * f.torsion;
                prop_assert!((lhs - triple).abs() <= 64.0 * EPS * r1.norm() * r2.norm() * r3.norm());
                prop_assert!(f.torsion == 0.0 || f.curvature > 0.0);
            }
            // κ = 0 (r⃗″ ∥ r⃗′): the triple product is zero whatever r⃗‴, and τ is refused
            let flat = r1 * s;
            prop_assert!(r1.cross(&flat).dot(&r3).abs() <= 8.0 * EPS * r1.norm() * flat.norm() * r3.norm());
            let refused = matches!(
                FrenetSerret::from_derivatives(&r1, &flat, &r3, 1e-12, 1e-9),
                Err(KinematicsError::ZeroCurvature { .. })
            );
            prop_assert!(refused);
        }

        /// P5.6.6: the Frenet–Serret frames of two points x, y fixed in a rigid body B relate
        /// through the body's motion; when B only translates (ω⃗_{B/A} = 0) the two curves are
        /// translates of each other and R⃗_{FS_y/A} = R⃗_{FS_x/A}. A turning body separates them.
        #[test]
        fn problem_5_6_6_frenet_frames_of_two_body_points(
            p in proptest::array::uniform3(proptest::array::uniform3(-1.0..1.0f64)),
            x in support::triple(), y in support::triple(), t in -1.0..1.0f64,
        ) {
            let a = Frame::new();
            let frame_of = |phi: [f64; 2], pt: [f64; 3]| fs(body_point(p, phi, pt), t).and_then(|f| f.frame());
            if let (Ok(fx), Ok(fy)) = (frame_of([0.0, 0.0], x), frame_of([0.0, 0.0], y)) {
                let r = Rotation::between(&fy, &a).to_dyadic() - Rotation::between(&fx, &a).to_dyadic();
                prop_assert!(r.norm() <= 64.0 * EPS, "translating body: {}", r.norm());
            }
        }
    }

    /// P5.6.6, the contrast: a turning body gives two points different Frenet frames.
    #[test]
    fn problem_5_6_6_turning_body_separates_the_frames() {
        let a = Frame::new();
        let p = [[1.0, 0.2, 0.1], [0.5, -0.3, 0.2], [0.2, 0.1, -0.1]];
        let fx = fs(body_point(p, [0.8, 0.3], [1.0, 0.0, 0.0]), 0.4).unwrap().frame().unwrap();
        let fy = fs(body_point(p, [0.8, 0.3], [-0.5, 2.0, 0.3]), 0.4).unwrap().frame().unwrap();
        let r = Rotation::between(&fy, &a).to_dyadic() - Rotation::between(&fx, &a).to_dyadic();
        assert!(r.norm() > 0.1);
    }
}
