//! §7.17 problems with the solutions of §7.18 (numbers from the notes, [C] = recomputed).

use vectrix::dynamics::lagrange::accelerations;
use vectrix::dynamics::multibody::{Joint, JointWrench, Link, Model};
use vectrix::nalgebra::{Matrix3, Rotation3, Vector3};
use vectrix::prelude::*;
use vectrix::statics::{MassProperties, Point};

use crate::support::{EPS, assert_abs, assert_abs_slice, assert_printed, assert_rel, assert_rel_slice};

/// P7.17.1: solid sphere (m, radius r) rolling without slip down the incline (angle θ) of a cart
/// M on a smooth floor; q = (X, s): cart position and distance rolled down the incline.
struct SphereOnWedge {
    m: f64,
    big_m: f64,
    theta: f64,
    g: f64,
}

impl Lagrangian for SphereOnWedge {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, _q: &[T], qd: &[T], _t: T) -> T {
        let (c, s) = (T::lit(self.theta.cos()), T::lit(self.theta.sin()));
        let (vx, vy) = (qd[0] + qd[1] * c, -qd[1] * s);
        // ½MẊ² + ½m|v_c|² + ½(2/5 m r²)(ṡ/r)²: rolling ties ω = ṡ/r, r cancels
        T::lit(0.5 * self.big_m) * qd[0] * qd[0]
            + T::lit(0.5 * self.m) * (vx * vx + vy * vy)
            + T::lit(0.2 * self.m) * qd[1] * qd[1]
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        -T::lit(self.m * self.g * self.theta.sin()) * q[1]
    }
}

/// P7.17.1 (§7.18): "D = 7M + (2 + 5 sin²θ)m; ẍ = 5(m + M)g sin θ/D; ÿ_cart = g tan θ − 7ẍ/(5 cos θ);
/// f_T = −2(m + M)mg sin θ/D; f_N = (mg/cos θ)(1 − 7(m + M) sin²θ/D)." [C] m = 1, M = 2,
/// θ = 30°, g = 9.81: ẍ = 4.265217, ÿ = −1.231262, f_T = −1.706087, f_N = 7.880078.
#[test]
fn problem_7_17_1_and_section_7_18_sphere_rolling_on_wedge_cart() {
    let p = SphereOnWedge { m: 1.0, big_m: 2.0, theta: 30f64.to_radians(), g: 9.81 };
    let a = accelerations(&p, &[0.0, 0.0], &[0.0, 0.0], 0.0).unwrap();
    let (cart, s) = (a[0], a[1]);
    // the notes give six decimals
    assert_printed(s, "4.265217");
    assert_printed(cart, "-1.231262");
    // reactions on the sphere in the incline frame: friction from the rotation
    // (2/5)m r² (s̈/r) = −f_T r, normal from the balance across the incline
    let f_t = -0.4 * p.m * s;
    let f_n = p.m * (p.g * p.theta.cos() + cart * p.theta.sin());
    assert_printed(f_t, "-1.706087");
    assert_printed(f_n, "7.880078");
    let d = 7.0 * p.big_m + (2.0 + 5.0 * p.theta.sin().powi(2)) * p.m;
    assert_rel(s, 5.0 * (p.m + p.big_m) * p.g * p.theta.sin() / d, 16.0 * EPS);
}

/// P7.17.2 (§7.18): platform spinning at ω2 about k̂ on a pin at a; a bar of length 2R with
/// spheres m at its ends, centre b = L ĵ, spins at ω1 about ĵ (bar along sin θ î + cos θ k̂):
/// "f_B = −2mLω̇2 î − 2mLω2² ĵ; H_{/b} = 2mR²[−ω2 sin θ cos θ î + ω1 ĵ + ω2 sin²θ k̂];
/// M_{/b} = mR²[−(ω̇2 sin 2θ + 4ω1ω2 cos²θ) î + (2ω̇1 − ω2² sin 2θ) ĵ + (2ω̇2 sin²θ + 2ω1ω2 sin 2θ) k̂]."
/// Solved twice: by RNEA on a platform–dumbbell tree (joint reaction at b), and frame-free.
#[test]
fn problem_7_17_2_platform_with_spinning_dumbbell() {
    let (m, r, l) = (0.6, 0.4, 1.1);
    let (th, w1, w2, w1d, w2d) = (0.5, 1.3, 0.7, -0.4, 0.9);
    let j = Matrix3::from_diagonal(&Vector3::new(2.0 * m * r * r, 2.0 * m * r * r, 0.0));
    let platform = Link::new(
        None,
        Joint::Pin { axis: Vector3::z() },
        Vector3::zeros(),
        1.0,
        Vector3::zeros(),
        Matrix3::identity(),
    );
    let dumbbell = Link::new(
        Some(0),
        Joint::Pin { axis: Vector3::y() },
        Vector3::new(0.0, l, 0.0),
        2.0 * m,
        Vector3::zeros(),
        j,
    );
    let model = Model::new(&[platform, dumbbell]).unwrap();
    let id = model.rnea(&[0.0, th], &[w2, w1], &[w2d, w1d], None).unwrap();
    // the joint wrench at b is resolved in the dumbbell frame: back to the platform frame
    let r_y = Rotation3::from_axis_angle(&Vector3::y_axis(), th);
    let f_b = r_y * id.wrenches[1].force;
    let m_b = r_y * id.wrenches[1].moment;
    assert_rel_slice(f_b.as_slice(), &[-2.0 * m * l * w2d, -2.0 * m * l * w2 * w2, 0.0], 64.0 * EPS);
    let (s2, c, s) = ((2.0 * th).sin(), th.cos(), th.sin());
    let want = [
        -m * r * r * (w2d * s2 + 4.0 * w1 * w2 * c * c),
        m * r * r * (2.0 * w1d - w2 * w2 * s2),
        m * r * r * (2.0 * w2d * s * s + 2.0 * w1 * w2 * s2),
    ];
    assert_abs_slice(m_b.as_slice(), &want, 64.0 * EPS);

    // frame-free: dumbbell of two particles, ω = ω2 k̂ + ω1 ĵ, α = ω̇2 k̂ + ω̇1 ĵ + ω2 k̂ × ω1 ĵ
    let a = Frame::new();
    let e = a.vector([s, 0.0, c]);
    let b = Point::at(a.vector([0.0, l, 0.0]));
    let props = MassProperties::from_particles(&[(m, b.displaced(e * r)), (m, b.displaced(e * -r))]).unwrap();
    let omega = a.vector([0.0, w1, w2]);
    let body = RigidBody::new(props, a.vector([-w2 * l, 0.0, 0.0]), omega);
    let h = body.angular_momentum_about_centre().resolve(&a);
    assert_abs_slice(
        h.as_slice(),
        &[-2.0 * m * r * r * w2 * s * c, 2.0 * m * r * r * w1, 2.0 * m * r * r * w2 * s * s],
        16.0 * EPS,
    );
    let alpha = a.vector([-w1 * w2, w1d, w2d]);
    let moment = props.inertia_about_centre().apply(&alpha) + body.gyroscopic_moment();
    assert_abs_slice(moment.resolve(&a).as_slice(), &want, 64.0 * EPS);
}

/// P7.17.5 (§7.18): a cylinder (m, radius r, height h) welded to a vertical shaft at c with its
/// axis tilted by θ, driven by a torque τ: "Ω̇ = 12τ/(m[6r² + (h² − 3r²) sin²θ])", and the
/// bearings carry f_ax = mΩ² sin 2θ (h² − 3r²)/(24L), f_ay = −mΩ̇ sin 2θ (h² − 3r²)/(24L): the
/// joint moment perpendicular to the shaft is L times these.
#[test]
fn problem_7_17_5_tilted_cylinder_on_shaft() {
    let (m, r, h, th, tau, omega) = (2.0, 0.3, 1.2, 0.4, 0.7, 3.0);
    // J_c of the cylinder about its own axis (ẑ before tilting), then tilted about ŷ by θ
    let jc = Matrix3::from_diagonal(&Vector3::new(
        m * (3.0 * r * r + h * h) / 12.0,
        m * (3.0 * r * r + h * h) / 12.0,
        m * r * r / 2.0,
    ));
    let rot = Rotation3::from_axis_angle(&Vector3::y_axis(), th).into_inner();
    let link = Link::new(
        None,
        Joint::Pin { axis: Vector3::z() },
        Vector3::zeros(),
        m,
        Vector3::zeros(),
        rot * jc * rot.transpose(),
    );
    let model = Model::new(&[link]).unwrap();
    let od = model.aba(&[0.0], &[omega], &[tau], None).unwrap()[0];
    let want = 12.0 * tau / (m * (6.0 * r * r + (h * h - 3.0 * r * r) * th.sin().powi(2)));
    assert_rel(od, want, 16.0 * EPS);
    let w = model.rnea(&[0.0], &[omega], &[od], None).unwrap().wrenches[0];
    let k = m * (2.0 * th).sin() * (h * h - 3.0 * r * r) / 24.0;
    // with J_xz = −k: M = (Ω̇ J_xz, Ω² J_xz, Ω̇ J_zz) in the shaft frame at φ = 0
    assert_abs(w.moment.x, -od * k, 64.0 * EPS);
    assert_abs(w.moment.y, -omega * omega * k, 64.0 * EPS);
    assert_abs(w.moment.z, tau, 64.0 * EPS);
}

/// The massless vertical shaft of P7.17.4 and P7.17.6: the root link, a pin about ẑ.
fn massless_vertical_shaft() -> Link {
    Link::new(
        None,
        Joint::Pin { axis: Vector3::z() },
        Vector3::zeros(),
        0.0,
        Vector3::zeros(),
        Matrix3::zeros(),
    )
}

/// The zero of an affine function x ↦ f(x) (a pin torque that is affine in an unknown force),
/// from its values at 0 and 1.
fn zero_of_affine(f: impl Fn(f64) -> f64) -> f64 {
    let (f0, f1) = (f(0.0), f(1.0));
    -f0 / (f1 - f0)
}

/// P7.17.3 (§7.18): a uniform shaft (m₁, length l₁, radius r₁) and a uniform disk (m₂,
/// thickness l₂, radius r₂) welded at distance d from the shaft's left end, the disk's normal
/// at θ to the shaft; J_{B₃/c₃} resolved in F_A (î_A along the shaft, the disk's normal in the
/// î_A–ĵ_A plane): "[[α₁ + δ₁, δ₂, 0], [δ₃, β₁ + m₁l₄² + δ₄ + m₂l₅², 0], [0, 0, β₁ + m₁l₄² +
/// β₂ + m₂l₅²]], m₃ = m₁ + m₂, l₃ = l₁/2 + (m₂/m₃)(d − l₁/2), l₄ = (m₂/m₃)(l₁/2 − d),
/// l₅ = d − l₁/2 + (m₂/m₃)(l₁/2 − d), α_i = ½m_ir_i², β_i = m_i(3r_i² + l_i²)/12,
/// δ₁ = α₂cos²θ + β₂sin²θ, δ₂ = δ₃ = (−α₂ + β₂) cos θ sin θ, δ₄ = α₂sin²θ + β₂cos²θ."
/// Interpretation (figure-based): the statement fixes ĵ_A only up to sign, and the printed
/// sign of δ₂ is the one for the disk normal n̂ = cos θ î_A − sin θ ĵ_A; with ĵ_A reversed
/// (n̂ = cos θ î_A + sin θ ĵ_A) the off-diagonal entries change sign, checked below.
#[test]
fn problem_7_17_3_disk_welded_on_shaft() {
    // F_A turned away from the base frame, so that no entry is exact by accident
    let base = Frame::new();
    let f_a = base.rotated_by_rotor(&Rotor::from_axis_angle(&base.vector([1.0, -2.0, 0.5]), 0.8).unwrap());
    let f_a_flipped = Frame::from_axes(&f_a.i(), &-f_a.j(), &-f_a.k(), ORTHONORMAL_TOL).unwrap();
    let left = Point::at(base.vector([0.3, -1.2, 0.8]));
    // (m₁, l₁, r₁, m₂, l₂, r₂, d, θ): disk off-centre, near the left end, at the middle
    // (l₄ = l₅ = 0), at the right end; θ = 0 and π/2 included
    for (m1, l1, r1, m2, l2, r2, d, th) in [
        (2.0, 1.5, 0.05, 3.0, 0.1, 0.4, 0.9, 0.3),
        (0.7, 2.0, 0.1, 1.3, 0.05, 0.6, 0.25, 1.2),
        (5.0, 0.8, 0.2, 0.5, 0.3, 0.25, 0.4, 0.0),
        (1.0, 3.0, 0.08, 4.0, 0.2, 1.0, 3.0, std::f64::consts::FRAC_PI_2),
    ] {
        let shaft =
            MassProperties::cylinder(m1, r1, l1, &f_a.i(), left.displaced(f_a.i() * (0.5 * l1))).unwrap();
        let normal = f_a.i() * th.cos() - f_a.j() * th.sin();
        let disk = MassProperties::cylinder(m2, r2, l2, &normal, left.displaced(f_a.i() * d)).unwrap();
        // (6.2.23): the union, about its own centre of mass
        let b3 = shaft.combine(&disk);

        let m3 = m1 + m2;
        let l3 = 0.5 * l1 + m2 / m3 * (d - 0.5 * l1);
        let l4 = m2 / m3 * (0.5 * l1 - d);
        let l5 = d - 0.5 * l1 + m2 / m3 * (0.5 * l1 - d);
        let (a1, a2) = (0.5 * m1 * r1 * r1, 0.5 * m2 * r2 * r2);
        let (b1, b2) = (m1 * (3.0 * r1 * r1 + l1 * l1) / 12.0, m2 * (3.0 * r2 * r2 + l2 * l2) / 12.0);
        let (c, s) = (th.cos(), th.sin());
        let (d1, d2, d3, d4) =
            (a2 * c * c + b2 * s * s, (b2 - a2) * c * s, (b2 - a2) * c * s, a2 * s * s + b2 * c * c);
        let yy = b1 + m1 * l4 * l4 + d4 + m2 * l5 * l5;
        let zz = b1 + m1 * l4 * l4 + b2 + m2 * l5 * l5;

        assert_rel(b3.mass(), m3, 4.0 * EPS);
        let r_c3 = b3.centre_of_mass().position_rel(&left).resolve(&f_a);
        assert_rel_slice(r_c3.as_slice(), &[l3, 0.0, 0.0], 64.0 * EPS);
        let j = b3.inertia_about_centre();
        let want = Matrix3::new(a1 + d1, d2, 0.0, d3, yy, 0.0, 0.0, 0.0, zz);
        assert_rel_slice(j.resolve(&f_a).as_slice(), want.as_slice(), 64.0 * EPS);
        // ĵ_A → −ĵ_A (and k̂_A → −k̂_A): only the signs of δ₂ = δ₃ change
        let flipped = Matrix3::new(a1 + d1, -d2, 0.0, -d3, yy, 0.0, 0.0, 0.0, zz);
        assert_rel_slice(j.resolve(&f_a_flipped).as_slice(), flipped.as_slice(), 64.0 * EPS);
    }
}

/// P7.17.4 (§7.18): a uniform bar (m, l) pinned at a on a vertical shaft that spins at the
/// constant rate Ω, at θ from the vertical, held by a horizontal cable: "T = ½mg tan θ +
/// ⅓mlΩ² sin θ, f_ay = −½mg tan θ + ⅙mlΩ² sin θ, f_az = mg."
/// Interpretation (figure-based): a is the bar's lower end, the pin axis is perpendicular to
/// the plane of shaft and bar, the bar leans outward and the cable runs horizontally from its
/// upper end to the shaft; ĵ is horizontal in that plane, pointing from the bar toward the
/// shaft (the cable's pull), and k̂ is up. The book prints no torque at a: [C] it is zero,
/// since Ḣ_{/a} = Ω k̂ × J_{/a} Ω k̂ lies along the pin axis, where gravity and the cable
/// balance it.
#[test]
fn problem_7_17_4_and_section_7_18_bar_on_spinning_shaft_held_by_cable() {
    // (m, l, θ, Ω, g), including the static case Ω = 0 of the hint
    for (m, l, th, omega, g) in [
        (1.5, 0.8, 0.6, 2.5, 9.81),
        (0.7, 2.0, 1.1, 0.9, 9.81),
        (2.0, 1.3, 0.3, 0.0, 9.81),
        (1.0, 1.0, 0.9, 4.0, 1.62),
    ] {
        // massless shaft about ẑ; the bar along its link ẑ, tilted outward (toward the shaft's
        // x̂) by the pin about ŷ at a, which sits on the shaft axis
        let shaft = massless_vertical_shaft();
        let j_c = Matrix3::from_diagonal(&Vector3::new(m * l * l / 12.0, m * l * l / 12.0, 0.0));
        let bar = Link::new(
            Some(0),
            Joint::Pin { axis: Vector3::y() },
            Vector3::new(0.0, 0.0, 0.4),
            m,
            Vector3::new(0.0, 0.0, 0.5 * l),
            j_c,
        );
        let mut model = Model::new(&[shaft, bar]).unwrap();
        model.gravity = Vector3::new(0.0, 0.0, -g);
        let r_y = Rotation3::from_axis_angle(&Vector3::y_axis(), th);
        // the cable pulls the upper end (l ẑ in the bar frame) by −T x̂ of the shaft frame
        let cable = |t: f64| {
            let f = r_y.inverse() * Vector3::new(-t, 0.0, 0.0);
            [JointWrench::default(), JointWrench { force: f, moment: Vector3::new(0.0, 0.0, l).cross(&f) }]
        };
        let (q, v, vdot) = ([0.7, th], [omega, 0.0], [0.0, 0.0]);
        let id = |t: f64| model.rnea(&q, &v, &vdot, Some(&cable(t))).unwrap();
        // θ stays constant with a frictionless pin: τ_pin(T) = 0, and τ_pin is affine in T
        let t = zero_of_affine(|t| id(t).tau[1]);
        let want_t = 0.5 * m * g * th.tan() + m * l * omega * omega * th.sin() / 3.0;
        assert_rel(t, want_t, 64.0 * EPS);

        // the joint wrench on the bar at a, back to the shaft frame: (ĵ, k̂) = (−x̂, ẑ)
        let w = id(t).wrenches[1];
        let f_a = r_y * w.force;
        let f_ay = -0.5 * m * g * th.tan() + m * l * omega * omega * th.sin() / 6.0;
        assert_rel_slice(f_a.as_slice(), &[-f_ay, 0.0, m * g], 64.0 * EPS);
        // no torque at a, and none to keep the shaft turning: scale m g l
        let scale = m * g * l;
        assert_abs_slice((r_y * w.moment / scale).as_slice(), &[0.0; 3], 64.0 * EPS);
        assert_abs(id(t).tau[0] / scale, 0.0, 64.0 * EPS);
    }
}

/// P7.17.6 (§7.18): a vertical shaft spinning at the constant rate Ω > 0 carries a horizontal
/// arm (length l₁) with a frictionless pin at its end; a slanted bar (m, l₂) hangs from the pin
/// at θ below the horizontal and its tip slides on the ground with friction μ:
/// "f_ay = −½mg sin θ − ⅙mΩ²[2l₂ + 6l₁cos θ + l₂cos²θ + 3l₁ tan θ sin θ],
/// f_az = −⅙mΩ² sin θ (3l₁ + l₂ cos θ) + ½mg cos θ, f_b = ⅙m[3g − Ω²(2l₂ sin θ + 3l₁ tan θ)],
/// f_ax = −μf_b, f_f = μf_b, M_az = μl₂f_b", in F_C: ĵ_C along the bar toward the ground,
/// î_C out of the page, k̂_C = î_C × ĵ_C. The notes verify f_b only; the other printed forms
/// are checked here too, and hold as printed.
/// Interpretation (figure-based): the bar slants outward (away from the shaft) and down, the
/// pin axis is î_C, and the tip moves into the page (−î_C) so that friction is +μf_b î_C;
/// M_az is the reaction couple of the pin on the bar (the total M_{B/c} also has the
/// gyroscopic component −(ml₂²/12)Ω² sin θ cos θ along î_C, so it cannot be meant).
#[test]
fn problem_7_17_6_slanted_bar_sliding_on_ground() {
    // (m, l₁, l₂, θ, Ω, μ, g), all with f_b > 0 (the tip stays on the ground)
    for (m, l1, l2, th, omega, mu, g) in [
        (1.2, 0.5, 1.0, 0.6, 1.5, 0.3, 9.81),
        (2.0, 1.0, 1.5, 1.0, 2.0, 0.5, 9.81),
        (0.8, 0.3, 0.7, 0.2, 3.0, 0.1, 9.81),
        (3.0, 0.0, 1.2, 0.8, 1.0, 0.8, 1.62),
    ] {
        // massless shaft and arm about ẑ; the bar along its link x̂, turned by θ about ŷ at the
        // pin, so that it points along cos θ x̂ − sin θ ẑ of the shaft frame: out and down
        let shaft = massless_vertical_shaft();
        let j_c = Matrix3::from_diagonal(&Vector3::new(0.0, m * l2 * l2 / 12.0, m * l2 * l2 / 12.0));
        let bar = Link::new(
            Some(0),
            Joint::Pin { axis: Vector3::y() },
            Vector3::new(l1, 0.0, 0.0),
            m,
            Vector3::new(0.5 * l2, 0.0, 0.0),
            j_c,
        );
        let mut model = Model::new(&[shaft, bar]).unwrap();
        model.gravity = Vector3::new(0.0, 0.0, -g);
        let r_y = Rotation3::from_axis_angle(&Vector3::y_axis(), th);
        let tip = Vector3::new(l2, 0.0, 0.0);
        // the tip moves along Ω ẑ × r_tip; friction opposes it with magnitude μ f_b
        let r_tip = Vector3::new(l1, 0.0, 0.0) + r_y * tip;
        let v_hat = Vector3::z().cross(&r_tip).normalize();
        let ground = |f_b: f64| {
            let f = r_y.inverse() * (Vector3::z() * f_b - v_hat * (mu * f_b));
            [JointWrench::default(), JointWrench { force: f, moment: tip.cross(&f) }]
        };
        let (q, v, vdot) = ([-0.4, th], [omega, 0.0], [0.0, 0.0]);
        let id = |f_b: f64| model.rnea(&q, &v, &vdot, Some(&ground(f_b))).unwrap();
        // θ stays constant with a frictionless pin: τ_pin(f_b) = 0, affine in f_b
        let f_b = zero_of_affine(|f_b| id(f_b).tau[1]);
        let (c, s, t) = (th.cos(), th.sin(), th.tan());
        let w2 = omega * omega;
        let want_fb = m / 6.0 * (3.0 * g - w2 * (2.0 * l2 * s + 3.0 * l1 * t));
        assert!(want_fb > 0.0, "parameters must keep the tip on the ground");
        // f_b is a difference of terms of size mg (the second case cancels to ~1% of mg):
        // the error is a few ε of mg, well inside 64ε·mg
        assert_abs(f_b, want_fb, 64.0 * EPS * m * g);

        // F_C in the bar's link frame: î_C = −ŷ, ĵ_C = x̂ (along the bar), k̂_C = ẑ
        let in_c = |x: Vector3<f64>| [-x.y, x.x, x.z];
        let w = id(f_b).wrenches[1];
        let f_ay =
            -0.5 * m * g * s - m * w2 / 6.0 * (2.0 * l2 + 6.0 * l1 * c + l2 * c * c + 3.0 * l1 * t * s);
        let f_az = -m * w2 / 6.0 * s * (3.0 * l1 + l2 * c) + 0.5 * m * g * c;
        assert_rel_slice(&in_c(w.force), &[-mu * f_b, f_ay, f_az], 64.0 * EPS);
        // the pin couple: M_az = μ l₂ f_b, the other components zero
        assert_rel_slice(&in_c(w.moment), &[0.0, 0.0, mu * l2 * f_b], 64.0 * EPS);
        // the ground's force in F_C: friction f_f = μ f_b along î_C
        let f_ground = ground(f_b)[1].force;
        assert_rel(in_c(f_ground)[0], mu * f_b, 64.0 * EPS);
    }
}

/// P7.17.7 (Fig. 7.17.7 is not in the text; the configuration it describes, with the arm's far
/// end free): a uniform disk (m₁, r) rolls without slip, turning clockwise by φ (its centre moves
/// rφ to the right); a thin uniform arm (m₂, ℓ) on a frictionless pin at the centre makes the
/// angle θ with the horizontal, its centre at (ℓ/2)(cos θ, sin θ) from the pin. Lagrange with
/// T = ¾m₁r²φ̇² + ½m₂|v⃗_G|² + (1/24)m₂ℓ²θ̇², U = ½m₂gℓ sin θ gives
/// [(3/2 m₁ + m₂)r², −½m₂rℓ sin θ; −½m₂rℓ sin θ, ⅓m₂ℓ²][φ̈; θ̈] = [½m₂rℓ cos θ θ̇²; −½m₂gℓ cos θ],
/// and the pin's force on the arm m₂a⃗_G − m₂g⃗. The hand-derived system is checked against
/// vectrix's Lagrange equations (automatic differentiation of the same T and U).
struct WheelAndArm {
    m1: f64,
    r: f64,
    m2: f64,
    l: f64,
    g: f64,
}

impl Lagrangian for WheelAndArm {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        let (r, l) = (T::lit(self.r), T::lit(self.l));
        let half = T::lit(0.5);
        // v_G = (rφ̇ − ½ℓ sin θ θ̇, ½ℓ cos θ θ̇)
        let vx = r * qd[0] - half * l * q[1].sin() * qd[1];
        let vy = half * l * q[1].cos() * qd[1];
        T::lit(0.75 * self.m1) * r * r * qd[0] * qd[0]
            + T::lit(0.5 * self.m2) * (vx * vx + vy * vy)
            + T::lit(self.m2 / 24.0) * l * l * qd[1] * qd[1]
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        T::lit(0.5 * self.m2 * self.g * self.l) * q[1].sin()
    }
}

#[test]
fn problem_7_17_7_rolling_wheel_with_a_pinned_arm() {
    let p = WheelAndArm { m1: 2.0, r: 0.4, m2: 0.8, l: 1.5, g: 9.81 };
    let (m1, r, m2, l, g) = (p.m1, p.r, p.m2, p.l, p.g);
    for (th, phid, thd) in [(0.5, 3.0, 1.2), (1.2, 0.5, 2.0), (-0.3, 1.0, 0.4)] {
        let got = accelerations(&p, &[0.0, th], &[phid, thd], 0.0).unwrap();
        let m = Matrix3::new(
            (1.5 * m1 + m2) * r * r,
            -0.5 * m2 * r * l * f64::sin(th),
            0.0,
            -0.5 * m2 * r * l * f64::sin(th),
            m2 * l * l / 3.0,
            0.0,
            0.0,
            0.0,
            1.0,
        );
        let rhs =
            Vector3::new(0.5 * m2 * r * l * f64::cos(th) * thd * thd, -0.5 * m2 * g * l * f64::cos(th), 0.0);
        let want = m.try_inverse().unwrap() * rhs;
        assert_rel_slice(got.as_slice(), &want.as_slice()[..2], 64.0 * EPS);
        // the pin's force on the arm: m₂ a⃗_G − m₂ g⃗ (g⃗ = −g ĵ), horizontal and vertical parts
        let (phidd, thdd) = (got[0], got[1]);
        let a_g = Vector3::new(
            r * phidd - 0.5 * l * (f64::cos(th) * thd * thd + f64::sin(th) * thdd),
            0.5 * l * (f64::cos(th) * thdd - f64::sin(th) * thd * thd),
            0.0,
        );
        let f_pin = m2 * a_g + Vector3::new(0.0, m2 * g, 0.0);
        // the arm's moment balance about the pin: ½ℓ ê × (−m₂g ĵ) + … = J_pin θ̈ with J_pin = m₂ℓ²/3
        // and the pin's acceleration rφ̈ î: ⅓m₂ℓ²θ̈ = −½m₂gℓ cos θ + ½m₂ℓ sin θ · rφ̈
        assert_abs(
            m2 * l * l / 3.0 * thdd,
            -0.5 * m2 * g * l * f64::cos(th) + 0.5 * m2 * l * f64::sin(th) * r * phidd,
            64.0 * EPS * m2 * g * l,
        );
        // the disk's horizontal balance: m₁ rφ̈ = −f_pin,x + friction, with friction from the
        // disk's rolling moment ½m₁r²φ̈ = −friction·r (clockwise positive): m₁rφ̈ + ½m₁rφ̈ = −f_pin,x
        assert_abs(1.5 * m1 * r * phidd, -f_pin.x, 64.0 * EPS * (m1 + m2) * g);
    }
}

/// P7.17.8 (no printed solution; the notes' [C] form): a cart w (mass M) on a smooth horizontal
/// surface at x, and a pendulum y (mass m) on a massless link ℓ at the angle θ from the downward
/// vertical: (M + m)ẍ + mℓ(θ̈ cos θ − θ̇² sin θ) = 0 and ℓθ̈ + ẍ cos θ + g sin θ = 0, so
/// ẍ = m sin θ(ℓθ̇² + g cos θ)/(M + m sin²θ); the link pulls y toward w with tension
/// m(ℓθ̇² + g cos θ − ẍ sin θ) and no tangential part; M → ∞ recovers ℓθ̈ + g sin θ = 0.
struct PendulumOnCart {
    big_m: f64,
    m: f64,
    l: f64,
    g: f64,
}

impl Lagrangian for PendulumOnCart {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        let l = T::lit(self.l);
        // y at (x + ℓ sin θ, −ℓ cos θ)
        let vx = qd[0] + l * q[1].cos() * qd[1];
        let vy = l * q[1].sin() * qd[1];
        T::lit(0.5 * self.big_m) * qd[0] * qd[0] + T::lit(0.5 * self.m) * (vx * vx + vy * vy)
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        -T::lit(self.m * self.g * self.l) * q[1].cos()
    }
}

#[test]
fn problem_7_17_8_pendulum_on_a_cart() {
    let (m, l, g) = (0.6, 1.1, 9.81);
    for big_m in [2.0, 1e12] {
        let p = PendulumOnCart { big_m, m, l, g };
        for (th, thd) in [(0.4f64, 1.3f64), (2.0, -0.5), (-1.0, 0.0)] {
            let qdd = accelerations(&p, &[0.3, th], &[0.2, thd], 0.0).unwrap();
            let (xdd, thdd) = (qdd[0], qdd[1]);
            let want_x = m * th.sin() * (l * thd * thd + g * th.cos()) / (big_m + m * th.sin().powi(2));
            assert_abs(xdd, want_x, 64.0 * EPS * (g + l * thd * thd));
            assert_abs(l * thdd + xdd * th.cos() + g * th.sin(), 0.0, 64.0 * EPS * (g + l * thd * thd));
            assert_abs(
                (big_m + m) * xdd + m * l * (thdd * th.cos() - thd * thd * th.sin()),
                0.0,
                64.0 * EPS * (big_m + m) * (g + l * thd * thd),
            );
            // the reaction on y: m a⃗_y − m g⃗ lies along the link ê = (sin θ, −cos θ)
            let a_y = Vector3::new(
                xdd + l * (thdd * th.cos() - thd * thd * th.sin()),
                l * (thdd * th.sin() + thd * thd * th.cos()),
                0.0,
            );
            let f_r = m * a_y + Vector3::new(0.0, m * g, 0.0);
            let e = Vector3::new(th.sin(), -th.cos(), 0.0);
            assert_abs(f_r.cross(&e).z, 0.0, 64.0 * EPS * m * (g + l * thd * thd));
            assert_abs(
                -f_r.dot(&e),
                m * (l * thd * thd + g * th.cos() - xdd * th.sin()),
                64.0 * EPS * m * (g + l * thd * thd),
            );
            if big_m == 1e12 {
                // the simple pendulum: corrections of order m/M = 6e-13
                assert_abs(thdd, -g / l * th.sin(), 1e-10);
            }
        }
    }
}
