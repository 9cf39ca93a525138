//! §7.17 problems with the solutions of §7.18 (numbers from the notes, [C] = recomputed).

use vectrix::dynamics::lagrange::accelerations;
use vectrix::dynamics::multibody::{Joint, Link, Model};
use vectrix::nalgebra::{Matrix3, Rotation3, Vector3};
use vectrix::prelude::*;
use vectrix::statics::{MassProperties, Point};

use crate::support::{EPS, assert_close, assert_close_slice};

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
fn problem_7_17_1_sphere_rolling_on_wedge_cart() {
    let p = SphereOnWedge { m: 1.0, big_m: 2.0, theta: 30f64.to_radians(), g: 9.81 };
    let a = accelerations(&p, &[0.0, 0.0], &[0.0, 0.0], 0.0).unwrap();
    let (cart, s) = (a[0], a[1]);
    // the notes give six decimals
    assert_close(s, 4.265217, 1e-6);
    assert_close(cart, -1.231262, 1e-6);
    // reactions on the sphere in the incline frame: friction from the rotation
    // (2/5)m r² (s̈/r) = −f_T r, normal from the balance across the incline
    let f_t = -0.4 * p.m * s;
    let f_n = p.m * (p.g * p.theta.cos() + cart * p.theta.sin());
    assert_close(f_t, -1.706087, 1e-6);
    assert_close(f_n, 7.880078, 1e-6);
    let d = 7.0 * p.big_m + (2.0 + 5.0 * p.theta.sin().powi(2)) * p.m;
    assert_close(s, 5.0 * (p.m + p.big_m) * p.g * p.theta.sin() / d, 16.0 * EPS);
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
    assert_close_slice(f_b.as_slice(), &[-2.0 * m * l * w2d, -2.0 * m * l * w2 * w2, 0.0], 64.0 * EPS);
    let (s2, c, s) = ((2.0 * th).sin(), th.cos(), th.sin());
    let want = [
        -m * r * r * (w2d * s2 + 4.0 * w1 * w2 * c * c),
        m * r * r * (2.0 * w1d - w2 * w2 * s2),
        m * r * r * (2.0 * w2d * s * s + 2.0 * w1 * w2 * s2),
    ];
    assert_close_slice(m_b.as_slice(), &want, 64.0 * EPS);

    // frame-free: dumbbell of two particles, ω = ω2 k̂ + ω1 ĵ, α = ω̇2 k̂ + ω̇1 ĵ + ω2 k̂ × ω1 ĵ
    let a = Frame::new();
    let e = a.vector([s, 0.0, c]);
    let b = Point::at(a.vector([0.0, l, 0.0]));
    let props = MassProperties::from_particles(&[(m, b.displaced(e * r)), (m, b.displaced(e * -r))]).unwrap();
    let omega = a.vector([0.0, w1, w2]);
    let body = RigidBody::new(props, a.vector([-w2 * l, 0.0, 0.0]), omega);
    let h = body.angular_momentum_about_centre().resolve(&a);
    assert_close_slice(
        h.as_slice(),
        &[-2.0 * m * r * r * w2 * s * c, 2.0 * m * r * r * w1, 2.0 * m * r * r * w2 * s * s],
        16.0 * EPS,
    );
    let alpha = a.vector([-w1 * w2, w1d, w2d]);
    let moment = props.inertia_about_centre().apply(&alpha) + body.gyroscopic_moment();
    assert_close_slice(moment.resolve(&a).as_slice(), &want, 64.0 * EPS);
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
    assert_close(od, want, 16.0 * EPS);
    let w = model.rnea(&[0.0], &[omega], &[od], None).unwrap().wrenches[0];
    let k = m * (2.0 * th).sin() * (h * h - 3.0 * r * r) / 24.0;
    // with J_xz = −k: M = (Ω̇ J_xz, Ω² J_xz, Ω̇ J_zz) in the shaft frame at φ = 0
    assert_close(w.moment.x, -od * k, 64.0 * EPS);
    assert_close(w.moment.y, -omega * omega * k, 64.0 * EPS);
    assert_close(w.moment.z, tau, 64.0 * EPS);
}
