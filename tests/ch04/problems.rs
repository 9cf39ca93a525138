//! §4.20 theoretical problems as property tests along random smooth paths (exact derivatives
//! from num-dual, independent of the transport theorem under test), and the applied problems
//! P4.21.5–7, whose figures the text lacks: the geometry each test assumes is stated with it.
//!
//! Setup of the property tests: F_A fixed, F_B along 𝓞_{B/A}(t) = `o_path(t, cb)`, a vector
//! with x|_B(t) = `vec_path(t, cx)`; then x|_A = 𝓞_{B/A}ᵀ x|_B, and the frame derivatives are
//! the physical vectors whose A- (B-) components are d/dt of the A- (B-) components (4.1.5).

use proptest::prelude::*;
use vectrix::kinematics::*;
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::num_dual::Dual2_64;
use vectrix::prelude::*;

use crate::paths::*;
use crate::support::{EPS, NanAmax, assert_abs, assert_rel, direction, triple};

/// Rounding of exact (num-dual) derivatives of O(1) paths through a few products.
const TOL: f64 = 1024.0 * EPS;

/// A random coefficient set for `o_path` and `vec_path`.
fn coeffs() -> impl Strategy<Value = [[f64; 3]; 3]> {
    proptest::array::uniform3(proptest::array::uniform3(-1.0..1.0f64))
}

/// The pieces of one scene at time t: the motion of F_B relative to F_A, and x with its A- and
/// B-derivatives as physical vectors (from the exact component derivatives).
struct Scene {
    m: FrameMotion,
    x: Vector,
    /// x⃗^{B•}, x⃗^{B••}
    xb: [Vector; 2],
    /// x⃗^{A•}, x⃗^{A••}
    xa: [Vector; 2],
}

fn scene(cb: [[f64; 3]; 3], cx: [[f64; 3]; 3], t: f64) -> Scene {
    let a = LabeledFrame::new("A", Frame::new());
    let m = motion_from_path("B", &a, |s| o_path(s, &cb), t);
    let fb = m.body().frame;
    let [xb, xbd, xbdd] = vec_jet(|s| vec_path(s, &cx), t);
    let [_, xad, xadd] = vec_jet(|s| o_path(s, &cb).transpose() * vec_path(s, &cx), t);
    let (in_a, in_b) = (|v: Vector3<f64>| a.frame.vector(arr(v)), |v: Vector3<f64>| fb.vector(arr(v)));
    Scene { m, x: in_b(xb), xb: [in_b(xbd), in_b(xbdd)], xa: [in_a(xad), in_a(xadd)] }
}

/// 𝓞, 𝓞̇, ω|_B and its derivative d/dt(ω|_B) along an orientation path, by the product rule on
/// exact derivatives: ω^× = −𝓞̇𝓞ᵀ, so d/dt ω^× = −𝓞̈𝓞ᵀ − 𝓞̇𝓞̇ᵀ (4.3.20).
fn omega_in_body(
    path: impl Fn(Dual2_64) -> Matrix3<Dual2_64>,
    t: f64,
) -> (Matrix3<f64>, Matrix3<f64>, Vector3<f64>, Vector3<f64>) {
    let [o0, o1, o2] = mat_jet(path, t);
    let vee = |m: Matrix3<f64>| {
        0.5 * Vector3::new(m[(2, 1)] - m[(1, 2)], m[(0, 2)] - m[(2, 0)], m[(1, 0)] - m[(0, 1)])
    };
    let w = vee(-o1 * o0.transpose());
    let wd = vee(-o2 * o0.transpose() - o1 * o1.transpose());
    (o0, o1, w, wd)
}

proptest! {
    /// P4.20.1: (4.6.1), ω⃗_{C/A} = ω⃗_{C/B} + ω⃗_{B/A}, from (4.2.3) Ω = −𝓞̇ᵀ… resolved in F_C:
    /// Ω_{C/A}|_C = Ω_{C/B}|_C + 𝓞_{C/B} Ω_{B/A}|_B 𝓞_{B/C}, each Ω from exact derivatives of
    /// its own orientation path; and vectrix's composition of the two motions agrees.
    #[test]
    fn problem_4_20_1_angular_velocities_add(cb in coeffs(), cc in coeffs(), t in -1.0..1.0f64) {
        let omega_x = |o: &Matrix3<f64>, od: &Matrix3<f64>| -od * o.transpose();
        let [o_ba, od_ba, _] = mat_jet(|s| o_path(s, &cb), t);
        let [o_cb, od_cb, _] = mat_jet(|s| o_path(s, &cc), t);
        let [o_ca, od_ca, _] = mat_jet(|s| o_path(s, &cc) * o_path(s, &cb), t);
        let lhs = omega_x(&o_ca, &od_ca);
        let rhs = omega_x(&o_cb, &od_cb) + o_cb * omega_x(&o_ba, &od_ba) * o_cb.transpose();
        prop_assert!((lhs - rhs).nan_amax() <= TOL, "{}", (lhs - rhs).nan_amax());
        // vectrix: compose(C/B, B/A) gives ω_{C/A}
        let a = LabeledFrame::new("A", Frame::new());
        let b_a = motion_from_path("B", &a, |s| o_path(s, &cb), t);
        let c_b = motion_from_path("C", b_a.body(), |s| o_path(s, &cc), t);
        let c_a = c_b.compose(&b_a).unwrap();
        let want = Vector3::new(lhs[(2, 1)], lhs[(0, 2)], lhs[(1, 0)]);
        let got = c_a.omega().resolve(&c_a.body().frame);
        prop_assert!((got - want).nan_amax() <= TOL, "{got} vs {want}");
    }

    /// P4.20.3: x̂ × y⃗ = 0 with y⃗̇ ≡ 0 and y⃗(t₀) ≠ 0 gives x̂̈(t₀) = 0. With x̂ = y⃗/|y⃗| (Prob
    /// 2.26.1: x̂ = ±ŷ), at any instant where y⃗̇ = 0, x̂̈ = P_{ŷ⊥} ÿ⃗/|y⃗|: it vanishes when
    /// y⃗ stays constant (ÿ⃗ = 0), and not when y⃗̇ vanishes only at t₀.
    #[test]
    fn problem_4_20_3_unit_vector_along_a_constant_vector_has_no_acceleration(
        y0 in direction(), y2 in triple(), t0 in -1.0..1.0f64,
    ) {
        let f = Frame::<Dual2_64>::identity();
        let unit_at = |y2: [f64; 3]| {
            // y⃗(t) = y⃗₀ + (t − t₀)² y⃗₂: y⃗̇(t₀) = 0, ÿ⃗ = 2y⃗₂
            let t = Dual2_64::new(t0, 1.0, 0.0);
            let dt = t - t0;
            let y = f.vector([0, 1, 2].map(|k| Dual2_64::from(y0[k]) + dt * dt * y2[k]));
            let x = y.unit().unwrap().resolve(&f);
            (x.map(|z| z.v1), x.map(|z| z.v2))
        };
        let (xd, xdd) = unit_at([0.0; 3]);
        prop_assert!(xd.nan_amax() <= 4.0 * EPS && xdd.nan_amax() <= 4.0 * EPS, "constant y: ẍ = {xdd}");
        let (xd, xdd) = unit_at(y2);
        prop_assert!(xd.nan_amax() <= 4.0 * EPS);
        let (y0v, y2v) = (Vector3::from(y0), Vector3::from(y2));
        let yh = y0v.normalize();
        let want = (2.0 * y2v - yh * yh.dot(&(2.0 * y2v))) / y0v.norm();
        prop_assert!((xdd - want).nan_amax() <= 64.0 * EPS * (1.0 + want.nan_amax()), "{xdd} vs {want}");
    }

    /// P4.20.6: for x⃗, y⃗ fixed in F_B, x⃗^{A•} = ω⃗ × x⃗ and (x⃗^{A•}·y⃗) ω⃗ = x⃗^{A•} × y⃗^{A•},
    /// that is (ω⃗ × x⃗)′y⃗ ω⃗ = (ω⃗ × x⃗) × (ω⃗ × y⃗).
    #[test]
    fn problem_4_20_6_rates_of_two_body_fixed_vectors(cb in coeffs(), x in triple(), y in triple(), t in -1.0..1.0f64) {
        let a = LabeledFrame::new("A", Frame::new());
        let m = motion_from_path("B", &a, |s| o_path(s, &cb), t);
        let fb = m.body().frame;
        let (x, y) = (fb.vector(x), fb.vector(y));
        let rate = |v: Vector| VectorJet::fixed_in(m.body().label, v).transported(&m).unwrap().rate();
        let (xd, yd) = (rate(x), rate(y));
        let lhs = m.omega() * xd.dot(&y);
        let rhs = xd.cross(&yd);
        let scale = m.omega().norm().powi(2) * x.norm() * y.norm();
        prop_assert!(dist(&lhs, &rhs) <= 64.0 * EPS * scale.max(EPS), "{}", dist(&lhs, &rhs));
    }

    /// P4.20.8: x⃗^{A••}|_A = d²/dt² (x⃗|_A): the second A-derivative transported by vectrix from
    /// the B description equals the exact second derivative of the A-components.
    #[test]
    fn problem_4_20_8_second_frame_derivative_resolves_to_second_component_derivative(
        cb in coeffs(), cx in coeffs(), t in -1.0..1.0f64,
    ) {
        let s = scene(cb, cx, t);
        let jb = VectorJet::new(s.m.body().label, s.x, s.xb[0], s.xb[1]).unwrap();
        let ja = jb.transported(&s.m).unwrap();
        prop_assert!(dist(&ja.second_rate(), &s.xa[1]) <= TOL);
        prop_assert!(dist(&ja.rate(), &s.xa[0]) <= TOL);
    }

    /// P4.20.9: the double transport theorem with A and B interchanged:
    /// x⃗^{B••} = x⃗^{A••} + α⃗_{A/B} × x⃗ + 2ω⃗_{A/B} × x⃗^{A•} + ω⃗_{A/B} × (ω⃗_{A/B} × x⃗), with
    /// ω⃗_{A/B} = −ω⃗_{B/A} and α⃗_{A/B} = −α⃗_{B/A}.
    #[test]
    fn problem_4_20_9_double_transport_with_the_frames_interchanged(cb in coeffs(), cx in coeffs(), t in -1.0..1.0f64) {
        let s = scene(cb, cx, t);
        let (w_ab, al_ab) = (-s.m.omega(), -s.m.alpha());
        let got = double_transport(&s.x, &s.xa[0], &s.xa[1], &w_ab, &al_ab);
        prop_assert!(dist(&got, &s.xb[1]) <= TOL, "{}", dist(&got, &s.xb[1]));
        // and the original direction, for contrast
        let fwd = double_transport(&s.x, &s.xb[0], &s.xb[1], &s.m.omega(), &s.m.alpha());
        prop_assert!(dist(&fwd, &s.xa[1]) <= TOL);
    }

    /// P4.20.10: ω⃗_{B/A}^{A•} = ω⃗_{B/A}^{B•} (= α⃗_{B/A}, since ω⃗ × ω⃗ = 0); for a third frame
    /// ω⃗_{C/B}^{A•} = ω⃗_{C/B}^{B•} + ω⃗_{B/A} × ω⃗_{C/B}, and α⃗_{C/A} = α⃗_{C/B} + α⃗_{B/A} +
    /// ω⃗_{B/A} × ω⃗_{C/B} (4.6.5). (The printed identities are garbled in our copy of the text;
    /// these are the transport-theorem forms the problem asks for.) Derivatives are exact: the
    /// components of ω are differentiated by the product rule on second-order dual numbers.
    #[test]
    fn problem_4_20_10_angular_acceleration_is_the_same_in_both_frames(cb in coeffs(), cc in coeffs(), t in -1.0..1.0f64) {
        let a = LabeledFrame::new("A", Frame::new());
        let (o, od, w_b, wd_b) = omega_in_body(|s| o_path(s, &cb), t);
        // ω|_A = 𝓞ᵀ ω|_B, so d/dt ω|_A = 𝓞̇ᵀ ω|_B + 𝓞ᵀ d/dt ω|_B
        let wd_a = od.transpose() * w_b + o.transpose() * wd_b;
        let b_a = motion_from_path("B", &a, |s| o_path(s, &cb), t);
        let fb = b_a.body().frame;
        let (alpha_a, alpha_b) = (a.frame.vector(arr(wd_a)), fb.vector(arr(wd_b)));
        prop_assert!(dist(&alpha_a, &alpha_b) <= TOL);
        prop_assert!(dist(&alpha_a, &b_a.alpha()) <= TOL);
        // a third frame C along 𝓞_{C/B}(t): α_{C/A} = d/dt(ω_{C/A}|_C) exactly, against (4.6.5)
        // and against vectrix's composition
        let c_b = motion_from_path("C", b_a.body(), |s| o_path(s, &cc), t);
        let c_a = c_b.compose(&b_a).unwrap();
        let (_, _, _, wd_ca) = omega_in_body(|s| o_path(s, &cc) * o_path(s, &cb), t);
        let exact = c_a.body().frame.vector(arr(wd_ca));
        let want = c_b.alpha() + b_a.alpha() + b_a.omega().cross(&c_b.omega());
        prop_assert!(dist(&exact, &want) <= TOL, "{}", dist(&exact, &want));
        prop_assert!(dist(&c_a.alpha(), &exact) <= TOL);
        // ω_{C/B} resolved in A: its A-derivative, exactly
        let (o_cb, od_cb, w_cb, wd_cb) = omega_in_body(|s| o_path(s, &cc), t);
        let o_ca = o_cb * o;
        let od_ca = od_cb * o + o_cb * od;
        let wd_cb_in_a = od_ca.transpose() * w_cb + o_ca.transpose() * wd_cb;
        let a_rate = a.frame.vector(arr(wd_cb_in_a));
        // its B-derivative: d/dt of ω_{C/B}|_B = 𝓞_{B/C} ω_{C/B}|_C
        let wd_cb_in_b = od_cb.transpose() * w_cb + o_cb.transpose() * wd_cb;
        let b_rate = fb.vector(arr(wd_cb_in_b));
        prop_assert!(dist(&a_rate, &(b_rate + b_a.omega().cross(&c_b.omega()))) <= TOL);
    }

    /// P4.20.11: x⃗^{A••} − x⃗^{B••} = α⃗ × x⃗ + ω⃗ × (x⃗^{A•} + x⃗^{B•}) (the symmetric form of the
    /// double transport theorem, from x⃗^{A•} = x⃗^{B•} + ω⃗ × x⃗), which with α⃗ = 0 is
    /// ω⃗ × (x⃗^{A•} + x⃗^{B•}). (The printed identities are garbled in our copy of the text.)
    #[test]
    fn problem_4_20_11_symmetric_double_transport(cb in coeffs(), cx in coeffs(), t in -1.0..1.0f64) {
        let s = scene(cb, cx, t);
        let (w, al) = (s.m.omega(), s.m.alpha());
        let lhs = s.xa[1] - s.xb[1];
        let rhs = al.cross(&s.x) + w.cross(&(s.xa[0] + s.xb[0]));
        prop_assert!(dist(&lhs, &rhs) <= TOL);
        prop_assert!(dist(&s.xa[0], &transport(&s.xb[0], &w, &s.x)) <= TOL);
    }
}

/// P4.20.11, the problem's example: x⃗ = î_B with constant ω⃗_{B/A} (α⃗ = 0): x⃗^{B•} = x⃗^{B••} = 0,
/// x⃗^{A•} = ω⃗ × î_B and x⃗^{A••} = ω⃗ × (ω⃗ × î_B) = ω⃗ × (x⃗^{A•} + x⃗^{B•}).
#[test]
fn problem_4_20_11_example_body_axis_with_constant_omega() {
    let a = LabeledFrame::new("A", Frame::new());
    let b = LabeledFrame::new("B", Frame::from_orientation_rel(&a.frame, &o3(0.4), 1e-12).unwrap());
    let w = a.frame.vector([0.3, -1.2, 2.0]);
    let m = FrameMotion::new(b, a, w, Vector::zero()).unwrap();
    let x = b.frame.i();
    let ja = VectorJet::fixed_in(b.label, x).transported(&m).unwrap();
    assert!(dist(&ja.rate(), &w.cross(&x)) <= 4.0 * EPS);
    assert!(dist(&ja.second_rate(), &w.cross(&ja.rate())) <= 16.0 * EPS);
}

/// P4.20.4: with ω⃗_{B/A} ∥ n̂_{B/A} and no angular acceleration, the eigenaxis n̂_{B/A} stays
/// fixed: its A- and B-derivatives vanish. F_B turns about a fixed n̂ at a constant rate; the axis
/// vectrix extracts from R⃗_{B/A}(t) is the same at every instant (θ ∈ (0, π)), and its
/// B-derivative by the transport theorem, n̂^{A•} − ω⃗ × n̂, is zero.
#[test]
fn problem_4_20_4_the_eigenaxis_of_a_steady_rotation_is_fixed() {
    let a = Frame::new();
    let n = a.vector([1.0, -2.0, 2.0]) * (1.0 / 3.0);
    let rate = 0.7;
    let axis_at = |t: f64| {
        let r = Rotation::from_axis_angle(&n, rate * t).unwrap();
        match r.axis_angle_in(&a) {
            AxisAngle::General { axis, .. } => axis,
            other => panic!("θ ∈ (0, π) expected, got {other:?}"),
        }
    };
    let (t0, h) = (1.5, 1e-3);
    let n0 = axis_at(t0);
    assert_abs(dist(&a.vector(arr(n0)), &n), 0.0, 4.0 * EPS);
    // central difference of the extracted axis: zero up to rounding of the extraction, ε/h
    let nd = (axis_at(t0 + h) - axis_at(t0 - h)) / (2.0 * h);
    assert!(nd.nan_amax() <= 16.0 * EPS / h, "{nd}");
    let omega = n * rate;
    let nd_b = transport(&a.vector(arr(nd)), &(-omega), &n);
    assert!(nd_b.norm() <= 16.0 * EPS / h);
}

/// P4.21.5 (Fig. 4.21.2 is not in the text; the test assumes the configuration it describes):
/// a bar ab of length 2R, a driven at constant v î along the surface (height 0), b a pin on the
/// rim of a disk of radius R rolling clockwise without slip, at the instant r⃗_{c/b} is
/// horizontal with b on the side of a (b at 9:00, so r⃗_{b/a} = (√3R, R)). Constraints give the
/// disk's clockwise rate ω = √3v/((√3 + 1)R), v⃗_c = Rω î = (3 − √3)v/2 î, and
/// ω̇ = −(√3 + 4/3)ω²/(√3 + 1), a⃗_c = Rω̇ î; vectrix's rigid-point kinematics, run from c through
/// the disk and the bar, must return a with velocity v î and zero acceleration.
#[test]
fn problem_4_21_5_bar_driving_a_rolling_disk() {
    let (big_r, v) = (0.4, 1.5);
    let g = LabeledFrame::new("G", Frame::new());
    let f = &g.frame;
    let s3 = 3f64.sqrt();
    let w = s3 * v / ((s3 + 1.0) * big_r);
    let wd = -(s3 + 4.0 / 3.0) * w * w / (s3 + 1.0);
    assert_rel(big_r * w, (3.0 - s3) / 2.0 * v, 4.0 * EPS);
    // bar: v_b − v_a = Ω k̂ × r_{b/a} with Ω = ω/√3, and Ω̇ from the perpendicular part of a_b
    let r_ba = f.vector([s3 * big_r, big_r, 0.0]);
    let a_b = f.vector([big_r * wd + w * w * big_r, wd * big_r, 0.0]);
    let bar_w = w / s3;
    let bar_wd = a_b.dot(&f.k().cross(&r_ba)) / r_ba.norm_squared();
    let disk = FrameMotion::new(LabeledFrame::new("D", *f), g, f.k() * -w, f.k() * -wd).unwrap();
    let bar = FrameMotion::new(LabeledFrame::new("L", *f), g, f.k() * bar_w, f.k() * bar_wd).unwrap();
    let c = VectorJet::new(
        g.label,
        f.vector([0.0, big_r, 0.0]),
        f.vector([big_r * w, 0.0, 0.0]),
        f.vector([big_r * wd, 0.0, 0.0]),
    )
    .unwrap();
    let b = c.rigid_point(&disk, f.vector([-big_r, 0.0, 0.0])).unwrap();
    assert!(dist(&b.second_rate(), &a_b) <= 16.0 * EPS * w * w);
    let a = b.rigid_point(&bar, -r_ba).unwrap();
    assert!(dist(&a.rate(), &f.vector([v, 0.0, 0.0])) <= 16.0 * EPS * v, "{:?}", a.rate().resolve(f));
    assert!(a.second_rate().norm() <= 64.0 * EPS * w * w * big_r, "{:?}", a.second_rate().resolve(f));
    // the contact point of the disk is at rest (no slip)
    let contact = c.rigid_point(&disk, f.vector([0.0, -big_r, 0.0])).unwrap();
    assert!(contact.rate().norm() <= 4.0 * EPS * v);
}

/// P4.21.6 (Fig. 4.21.3 is not in the text; the notes' conventions): the rod's pin at height d
/// above the centre slides in a slot through the centre, θ from the vertical, clockwise, the
/// wheel rolling clockwise without slip. Then v − Rθ̇ = d sec²θ θ̇:
/// θ̇ = v/(R + d sec²θ), θ̈ = −2dv² sec²θ tan θ/(R + d sec²θ)³. Check: with these rates the pin,
/// moving along the slot of the rolling wheel, has velocity v î and zero acceleration
/// (vectrix's moving-point kinematics with the Coriolis term).
#[test]
fn problem_4_21_6_pin_in_the_slot_of_a_rolling_wheel() {
    let (big_r, d, v) = (0.5, 0.8, 2.0);
    let g = LabeledFrame::new("G", Frame::new());
    let f = g.frame;
    for th in [-0.6f64, 0.0, 0.3, 1.0] {
        let sec2 = 1.0 / th.cos().powi(2);
        let thd = v / (big_r + d * sec2);
        let thdd = -2.0 * d * v * v * sec2 * th.tan() / (big_r + d * sec2).powi(3);
        // wheel frame W: ĵ_W along the slot (θ clockwise from the vertical)
        let w_frame = Frame::from_orientation_rel(&f, &o3(-th), 1e-12).unwrap();
        let wheel =
            FrameMotion::new(LabeledFrame::new("W", w_frame), g, f.k() * -thd, f.k() * -thdd).unwrap();
        let c = VectorJet::new(
            g.label,
            f.vector([big_r * th, big_r, 0.0]),
            f.vector([big_r * thd, 0.0, 0.0]),
            f.vector([big_r * thdd, 0.0, 0.0]),
        )
        .unwrap();
        // the pin at distance s = d sec θ along the slot, s(t) moving with θ
        let s = d / th.cos();
        let sd = d * th.tan() / th.cos() * thd;
        let sdd = d * ((1.0 + 2.0 * th.tan().powi(2)) / th.cos() * thd * thd + th.tan() / th.cos() * thdd);
        let e = w_frame.j();
        let rel = VectorJet::new(wheel.body().label, e * s, e * sd, e * sdd).unwrap();
        let pin = c.moving_point(&wheel, &rel).unwrap();
        assert_abs(pin.value().dot(&f.j()) - big_r, d, 8.0 * EPS);
        assert!(
            dist(&pin.rate(), &f.vector([v, 0.0, 0.0])) <= 32.0 * EPS * v,
            "θ = {th}: {:?}",
            pin.rate().resolve(&f)
        );
        assert!(
            pin.second_rate().norm() <= 64.0 * EPS * v * v / d,
            "θ = {th}: {:?}",
            pin.second_rate().resolve(&f)
        );
    }
}

/// P4.21.7 (Fig. 4.21.4 is not in the text; the notes' geometry): a wheel of radius r on a
/// horizontal axle from the hub a (on the vertical axis, at the wheel-centre height) rolls on a
/// circle of radius R; the hub turns at Ω about k̂, the wheel spins at ω about the axle. At the
/// contact point c: v⃗_{c/a/G} = 0, which needs ωr = ΩR; and a⃗_{c/a/G} = Ω²R ê_r + ω²r k̂ in the
/// hub frame (ê_r outward along the axle), the centripetal part of the centre reversed by the
/// Coriolis-like term 2ωΩr.
#[test]
fn problem_4_21_7_wheel_on_a_hub_rolling_on_a_circle() {
    let (r, big_r, big_w) = (0.3, 1.2, 0.8);
    let w = big_w * big_r / r; // the no-slip relation
    let g = LabeledFrame::new("G", Frame::new());
    let f = g.frame;
    for phi in [0.0, 0.7, 2.5] {
        // hub frame H: î_H = ê_r along the axle at azimuth φ
        let h_frame = Frame::from_orientation_rel(&f, &o3(phi), 1e-12).unwrap();
        let hub =
            FrameMotion::new(LabeledFrame::new("H", h_frame), g, f.k() * big_w, Vector::zero()).unwrap();
        // wheel relative to the hub: spin −ω ê_r, so that the contact point is at rest
        let wheel_h =
            FrameMotion::new(LabeledFrame::new("W", h_frame), *hub.body(), h_frame.i() * -w, Vector::zero())
                .unwrap();
        let wheel = wheel_h.compose(&hub).unwrap();
        let b = VectorJet::fixed_in(g.label, Vector::zero()).rigid_point(&hub, h_frame.i() * big_r).unwrap();
        let c = b.rigid_point(&wheel, f.k() * -r).unwrap();
        assert!(c.rate().norm() <= 16.0 * EPS * big_w * big_r, "v_c = {:?}", c.rate().resolve(&f));
        let want = h_frame.i() * (big_w * big_w * big_r) + f.k() * (w * w * r);
        assert!(
            dist(&c.second_rate(), &want) <= 64.0 * EPS * w * w * r,
            "{:?}",
            c.second_rate().resolve(&h_frame)
        );
        // ωr = ΩR is the only spin that keeps the contact point at rest
        let slip = FrameMotion::new(
            LabeledFrame::new("W", h_frame),
            *hub.body(),
            h_frame.i() * (-1.1 * w),
            Vector::zero(),
        )
        .unwrap()
        .compose(&hub)
        .unwrap();
        assert!(b.rigid_point(&slip, f.k() * -r).unwrap().rate().norm() > 0.05 * w * r);
    }
}
