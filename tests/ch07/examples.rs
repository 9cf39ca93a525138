//! §7.15 worked examples, solved with the multibody tree (RNEA for reactions, ABA for motion).

use vectrix::dynamics::multibody::{Joint, Link, Model};
use vectrix::nalgebra::{Matrix3, SVector, Vector3};
use vectrix::ode::Adaptive;

use crate::support::{EPS, assert_abs, assert_printed, assert_rel};

const G: f64 = 9.81;

/// A pendulum on a pin about ẑ at the ground origin, centre of mass at distance ℓ along −ŷ of
/// the link (θ = 0 hangs down), J0 about c, gravity −g ĵ.
fn pendulum(m: f64, l: f64, j0: f64) -> Model {
    let link = Link::new(
        None,
        Joint::Pin { axis: Vector3::z() },
        Vector3::zeros(),
        m,
        Vector3::new(0.0, -l, 0.0),
        Matrix3::from_diagonal(&Vector3::new(j0, j0, j0)),
    );
    let mut model = Model::new(&[link]).unwrap();
    model.gravity = Vector3::new(0.0, -G, 0.0);
    model
}

/// Ex 7.15.1 (simple pendulum): "ℓθ̈ + g sin θ = 0 (the printed 'mg' is an erratum, l.9709);
/// f_R = −m(ℓθ̇² + g cos θ) k̂_B": the rod pulls the bob towards the pivot with the tension
/// m(ℓθ̇² + g cos θ) and exerts no tangential force.
#[test]
fn example_7_15_1_simple_pendulum_tension() {
    let (m, l) = (0.8, 1.3);
    let model = pendulum(m, l, 0.0);
    let (th, thd) = (0.7, 1.4);
    let thdd = model.aba(&[th], &[thd], &[0.0], None).unwrap()[0];
    assert_rel(thdd, -G * th.sin() / l, 16.0 * EPS);
    let w = model.rnea(&[th], &[thd], &[thdd], None).unwrap().wrenches[0];
    // link frame: −ŷ points from the pivot to the bob, so the pull is +ŷ
    assert_rel(w.force.y, m * (l * thd * thd + G * th.cos()), 16.0 * EPS);
    assert!(w.force.x.abs() <= 64.0 * EPS * m * G, "{}", w.force.x);
    assert_abs(w.moment.z, 0.0, 16.0 * EPS);
}

/// Ex 7.15.2 (physical pendulum): "θ̈ + ℓmg sin θ/(J0 + mℓ²) = 0; f1 = −mgJ0 sin θ/(J0 + mℓ²)"
/// (sign corrected, notes errata l.9782), "f2 = −m(ℓθ̇² + g cos θ)". Thin bar of length ℓ0 = 2ℓ:
/// "θ̈ + (3g/2ℓ0) sin θ = 0, f1 = −¼ mg sin θ"; f2 = −m(½ℓ0θ̇² + g cos θ) (corrected, l.9806).
#[test]
fn example_7_15_2_physical_pendulum_reactions() {
    let (m, l, j0) = (1.2, 0.6, 0.15);
    let model = pendulum(m, l, j0);
    let (th, thd) = (-0.9, 0.8);
    let thdd = model.aba(&[th], &[thd], &[0.0], None).unwrap()[0];
    assert_rel(thdd, -l * m * G * th.sin() / (j0 + m * l * l), 16.0 * EPS);
    let w = model.rnea(&[th], &[thd], &[thdd], None).unwrap().wrenches[0];
    // tangential component along +x̂ of the link (direction of increasing θ at c); the book's
    // f1 is along the opposite axis, hence the sign
    assert_rel(-w.force.x, -m * G * j0 * th.sin() / (j0 + m * l * l), 16.0 * EPS);
    assert_rel(-w.force.y, -m * (l * thd * thd + G * th.cos()), 16.0 * EPS);

    // thin bar ℓ0 = 2ℓ pivoted at its end: J0 = mℓ0²/12
    let l0 = 1.0;
    let bar = pendulum(m, l0 / 2.0, m * l0 * l0 / 12.0);
    let thdd = bar.aba(&[th], &[thd], &[0.0], None).unwrap()[0];
    assert_rel(thdd, -1.5 * G / l0 * th.sin(), 16.0 * EPS);
    // small-angle frequency ω² = 3g/2ℓ0 = 14.715 s⁻², period 1.63795 s (notes [C])
    assert_printed(2.0 * std::f64::consts::PI / (1.5 * G / l0).sqrt(), "1.63795");
    let w = bar.rnea(&[th], &[thd], &[thdd], None).unwrap().wrenches[0];
    assert_rel(-w.force.x, -0.25 * m * G * th.sin(), 16.0 * EPS);
    assert_rel(-w.force.y, -m * (0.5 * l0 * thd * thd + G * th.cos()), 16.0 * EPS);
}

/// The rotating wire of Ex 7.15.3: a pin about ẑ (wire, inertia J about the axis) carrying a
/// sleeve along the wire's x̂ (bead of mass m, a particle).
fn wire(j: f64, m: f64) -> Model {
    let wire = Link::new(
        None,
        Joint::Pin { axis: Vector3::z() },
        Vector3::zeros(),
        1.0,
        Vector3::zeros(),
        Matrix3::from_diagonal(&Vector3::new(j, j, j)),
    );
    let bead = Link::new(
        Some(0),
        Joint::Sleeve { axis: Vector3::x() },
        Vector3::zeros(),
        m,
        Vector3::zeros(),
        Matrix3::zeros(),
    );
    Model::new(&[wire, bead]).unwrap()
}

/// Ex 7.15.3, constant ω: "ẍ = ω²x, f_R = 2mωẋ (Coriolis)".
#[test]
fn example_7_15_3_bead_on_wire_constant_rate() {
    let (m, w, x, xd) = (0.7, 2.0, 0.9, 0.4);
    let model = wire(1.0, m);
    // prescribe θ̇ = ω, θ̈ = 0 and free bead (zero sleeve force): ẍ from the sleeve equation
    let id = model.rnea(&[0.3, x], &[w, xd], &[0.0, w * w * x], None).unwrap();
    assert_abs(id.tau[1], 0.0, 64.0 * EPS);
    assert_rel(id.wrenches[1].force.y, 2.0 * m * w * xd, 16.0 * EPS);
}

/// Ex 7.15.3, free wire: "(J + mx²)θ̈ + 2mxẋθ̇ = 0" (the printed 'Jθ̈ + mx²' is an erratum,
/// l.9889); c0 = (J + mx²)θ̇ and E are constant, θ̇ → 0 and θ converges. With
/// J = m = x0 = θ̇0 = 1 the notes give θ∞ = 1.8540747 (= K(k² = ½)). The motion is integrated
/// (ABA, DOP853) to t = 30 and the remaining angle ∫_{x(T)}^∞ √2 dx/√(x⁴ − 1) is added by its
/// series in u = 1/x.
#[test]
fn example_7_15_3_free_wire_limit_angle() {
    let model = wire(1.0, 1.0);
    let f = |_t: f64, y: &SVector<f64, 4>| {
        let a = model.aba(&[y[0], y[1]], &[y[2], y[3]], &[0.0, 0.0], None).unwrap();
        SVector::<f64, 4>::new(y[2], y[3], a[0], a[1])
    };
    let y0 = SVector::<f64, 4>::new(0.0, 1.0, 1.0, 0.0);
    let sol = Adaptive::dop853().rtol(1e-12).atol(1e-13).solve(f, 0.0, &y0, 30.0).unwrap();
    for y in &sol.y {
        let c0 = (1.0 + y[1] * y[1]) * y[2];
        let e = 0.5 * (1.0 + y[1] * y[1]) * y[2] * y[2] + 0.5 * y[3] * y[3];
        // invariants of the flow, kept to the integrator's tolerance (rtol 10⁻¹²) over t ≤ 30
        assert_rel(c0, 2.0, 1e-9);
        assert_abs(e, 1.0, 1e-9);
    }
    let y = sol.last();
    let u = 1.0 / y[1];
    // √2 ∫_0^u (1 − s⁴)^(−½) ds = √2 (u + u⁵/10 + u⁹/24 + 5u¹³/208 + …)
    let tail = 2f64.sqrt() * (u + u.powi(5) / 10.0 + u.powi(9) / 24.0 + 5.0 * u.powi(13) / 208.0);
    assert_printed(y[0] + tail, "1.8540747");
    let k_half = vectrix::ode::harness::elliptic::elliptic_k(0.5).unwrap();
    // DOP853 at rtol 1e-12 over 30 time units, and the series tail beyond u¹³ (u = 1/x(30))
    assert_rel(y[0] + tail, k_half, 1e-9);
}

/// Ex 7.15.4 (beam with a bead-like ball, rolling inertia ignored): "ẍ = θ̇²x − g sin θ;
/// (J_zz + mx²)θ̈ = −x(mg cos θ + 2mθ̇ẋ) + τ; f_R = mg cos θ + 2mθ̇ẋ + mθ̈x."
#[test]
fn example_7_15_4_ball_on_beam() {
    let (jzz, m, tau) = (0.9, 0.4, 0.6);
    let beam = Link::new(
        None,
        Joint::Pin { axis: Vector3::z() },
        Vector3::zeros(),
        2.0,
        Vector3::zeros(),
        Matrix3::from_diagonal(&Vector3::new(jzz, jzz, jzz)),
    );
    let ball = Link::new(
        Some(0),
        Joint::Sleeve { axis: Vector3::x() },
        Vector3::zeros(),
        m,
        Vector3::zeros(),
        Matrix3::zeros(),
    );
    let mut model = Model::new(&[beam, ball]).unwrap();
    model.gravity = Vector3::new(0.0, -G, 0.0);
    let (th, x, thd, xd) = (0.3, 0.8, -0.5, 0.2);
    let a = model.aba(&[th, x], &[thd, xd], &[tau, 0.0], None).unwrap();
    assert_rel(a[1], thd * thd * x - G * th.sin(), 64.0 * EPS);
    assert_rel(a[0], (-x * (m * G * th.cos() + 2.0 * m * thd * xd) + tau) / (jzz + m * x * x), 64.0 * EPS);
    let w = model
        .rnea(&[th, x], &[thd, xd], &a, Some(&[Default::default(), Default::default()]))
        .unwrap()
        .wrenches[1];
    assert_rel(w.force.y, m * G * th.cos() + 2.0 * m * thd * xd + m * a[0] * x, 64.0 * EPS);
}
