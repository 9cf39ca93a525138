//! §4.19–4.21: worked examples and problems with checkable claims.

use std::f64::consts::PI;

use vectrix::kinematics::*;
use vectrix::prelude::*;

use crate::paths::*;
use crate::support::{EPS, assert_printed, assert_printed_slice};

const TOL: f64 = 256.0 * EPS;

fn fixed_point(a: &LabeledFrame, r: Vector) -> VectorJet {
    VectorJet::fixed_in(a.label, r)
}

fn rotating(name: &'static str, a: &LabeledFrame, angle: f64, rate: f64, accel: f64) -> FrameMotion {
    let f = Frame::from_orientation_rel(&a.frame, &o3(angle), 1e-12).unwrap();
    let k = a.frame.k();
    FrameMotion::new(LabeledFrame::new(name, f), *a, k * rate, k * accel).unwrap()
}

// Ex 4.19.1: a disk of radius r rolls without slip inside a hoop of radius R. With ρ = r/R − 1,
// ω⃗_{C/A} = ρφ̇k̂, v⃗_{c/a/A} = αî_B + βĵ_B (α = ρr₀φ̇ sin φ, β = ρr₀φ̇ cos φ − ρrφ̇) and
// a⃗_{c/a/A} = ρ[r₀ sin φ φ̈ + (r²/R − ρr₀ cos φ)φ̇²]î_B + ρ[(r₀ cos φ − r)φ̈ + ρr₀ sin φ φ̇²]ĵ_B.
// Geometry (checked against the notes' simulation): arm B turns by (r/R)φ, disk C by ρφ, and
// r⃗_{c/a} = (R − r)î_B + r₀î_C. Notes: r = 0.3, R = 1, r₀ = 0.2, φ = 0.5 + 1.3t + 0.7t², t = 0.37
// gives a|_B = (−0.534362, 0.486255).
#[test]
fn example_4_19_1_disk_rolling_in_a_hoop() {
    let (r, big_r, r0) = (0.3, 1.0, 0.2);
    let t = 0.37;
    let (phi, phid, phidd) = (0.5 + 1.3 * t + 0.7 * t * t, 1.3 + 1.4 * t, 1.4);
    let rho = r / big_r - 1.0;
    let a = LabeledFrame::new("A", Frame::new());
    let q = r / big_r;
    let b_a = rotating("B", &a, q * phi, q * phid, q * phidd);
    let c_a = rotating("C", &a, rho * phi, rho * phid, rho * phidd);
    let c_b = c_a.compose(&b_a.inverse()).unwrap();
    assert!(dist(&c_a.omega(), &(a.frame.k() * (rho * phid))).abs() < TOL, "ω_{{C/A}} = ρφ̇k̂");
    // centre d fixed in B, then c fixed in C
    let fb = &b_a.body().frame;
    let d = fixed_point(&a, Vector::zero()).rigid_point(&b_a, fb.i() * (big_r - r)).unwrap();
    let c = d.rigid_point(&c_a, c_a.body().frame.i() * r0).unwrap();
    let v_b = c.rate().resolve(fb);
    let acc_b = c.second_rate().resolve(fb);
    let (al, be) = (rho * r0 * phid * phi.sin(), rho * r0 * phid * phi.cos() - rho * r * phid);
    assert!((v_b.x - al).abs() < TOL && (v_b.y - be).abs() < TOL, "v|_B = (α, β)");
    let ax = rho * (r0 * phi.sin() * phidd + (r * r / big_r - rho * r0 * phi.cos()) * phid * phid);
    let ay = rho * ((r0 * phi.cos() - r) * phidd + rho * r0 * phi.sin() * phid * phid);
    assert!((acc_b.x - ax).abs() < TOL && (acc_b.y - ay).abs() < TOL);
    assert_printed_slice(&[acc_b.x, acc_b.y], &["-0.534362", "0.486255"]);
    // no slip: the disk's contact point (r î_B from d) is at rest; the relative rate is θ̇ = −(r/R)φ̇
    let contact = d.rigid_point(&c_a, fb.i() * r).unwrap();
    assert!(contact.rate().norm() < TOL);
    assert!((c_b.omega().dot(&a.frame.k()) + phid).abs() < TOL);
}

// Ex 4.19.2: wheel of radius R pinned at b, pin P in the slot of an arm pinned at a, |ab| = L.
// θ̇ = (RL cos φ − R²)φ̇/q², θ̈ = RL(R² − L²) sin φ φ̇²/q⁴ (constant φ̇), θ_max at cos φ = R/L.
// Table of the notes (R = 2, L = 4, φ̇ = 1). θ̈ < 0 on (0, π): θ(t) is concave (the book's
// "convex" is wrong).
#[test]
fn example_4_19_2_slotted_arm_table() {
    let (big_r, l) = (2.0, 4.0);
    let a = LabeledFrame::new("A", Frame::new());
    let k = a.frame.k();
    // (φ°, θ°, θ̇, θ̈) as the notes print them; the closed forms below check every row exactly.
    let table = [
        (0.0, "0", "1", "0"),
        (60.0, "30", "0", "-0.57735"),
        (90.0, "26.5651", "-0.2", "-0.24"),
        // the notes print −0.106040 here; the closed form gives −96 sin 120°/784 = −0.1060439
        (120.0, "19.1066", "-0.285714", "-0.106044"),
        (180.0, "0", "-0.333333", "0"),
    ];
    for (phi_deg, th_deg, thd_want, thdd_want) in table {
        let phi = phi_deg * PI / 180.0;
        // the wheel frame W: î_W = (−cos φ, sin φ), ω_{W/A} = −φ̇k̂
        let w_a = rotating("W", &a, PI - phi, -1.0, 0.0);
        let b = fixed_point(&a, a.frame.i() * l);
        let p = b.rigid_point(&w_a, w_a.body().frame.i() * big_r).unwrap();
        let (r, v, acc) = (p.value(), p.rate(), p.second_rate());
        let q2 = r.norm_squared();
        let th = r.resolve(&a.frame).y.atan2(r.resolve(&a.frame).x);
        let thd = k.dot(&r.cross(&v)) / q2;
        let thdd = k.dot(&r.cross(&acc)) / q2 - 2.0 * r.dot(&v) * thd / q2;
        assert_printed(th * 180.0 / PI, th_deg);
        assert_printed(thd, thd_want);
        assert_printed(thdd, thdd_want);
        // the book's closed forms
        let q2b = big_r * big_r + l * l - 2.0 * big_r * l * phi.cos();
        assert!((thd - (big_r * l * phi.cos() - big_r * big_r) / q2b).abs() < TOL);
        assert!((thdd - big_r * l * (big_r * big_r - l * l) * phi.sin() / (q2b * q2b)).abs() < TOL);
    }
    // concave on (0, π)
    for i in 1..30 {
        let phi = PI * i as f64 / 30.0;
        let q2 = big_r * big_r + l * l - 2.0 * big_r * l * phi.cos();
        assert!(big_r * l * (big_r * big_r - l * l) * phi.sin() / (q2 * q2) < 0.0);
    }
}

// P4.21.1: (i) sidereal day 23 h 56 min 4.1 s; (ii) rotation relative to a Sun-fixed body frame
// (Sun spins once per 27 days) 24.852 h; (iii) synodic month 29.505 days — all by the summation
// ω⃗_{C/A} = ω⃗_{C/B} + ω⃗_{B/A} (4.6.2) of rates about one axis (rev/day).
#[test]
fn problem_4_21_1_sidereal_day_and_synodic_month() {
    let stars = LabeledFrame::new("stars", Frame::new());
    let k = stars.frame.k();
    let spin = |name: &'static str, rel: &LabeledFrame, rev_per_day: f64| {
        FrameMotion::new(LabeledFrame::new(name, stars.frame), *rel, k * rev_per_day, Vector::zero()).unwrap()
    };
    let sunline = spin("sun line", &stars, 1.0 / 365.25);
    let earth_sunline = spin("earth", sunline.body(), 1.0); // the solar day
    let earth = earth_sunline.compose(&sunline).unwrap();
    let sidereal_h = 24.0 / earth.omega().dot(&k);
    // 23 h 56 min 4.1 s: the seconds to the printed tenth
    assert_printed((sidereal_h - 23.0 - 56.0 / 60.0) * 3600.0, "4.1");
    let sun_body = spin("sun body", &stars, 1.0 / 27.0);
    let earth_sun_body = earth.compose(&sun_body.inverse()).unwrap();
    assert_printed(24.0 / earth_sun_body.omega().dot(&k), "24.852");
    let moon = spin("moon", &stars, 1.0 / 27.3);
    let moon_sunline = moon.compose(&sunline.inverse()).unwrap();
    assert_printed(1.0 / moon_sunline.omega().dot(&k), "29.505");
}

// P4.21.3 (gimbal; figure not in the text, 3-1-3 axes assumed as in the notes):
// ψ = 0.6 sin 20πt, θ = 0.3 sin 90πt, spin 700 rpm, at t = 0.01 s
// ω_{D/A}|_D = (−58.0614, 56.0779, 103.672), α_{D/A}|_D = (−3122.38, 7298.80, −1158.54).
#[test]
fn problem_4_21_3_gimbal_by_summation() {
    let t = 0.01;
    let (w1, w2) = (20.0 * PI, 90.0 * PI);
    let (psi, psid, psidd) =
        (0.6 * (w1 * t).sin(), 0.6 * w1 * (w1 * t).cos(), -0.6 * w1 * w1 * (w1 * t).sin());
    let (th, thd, thdd) = (0.3 * (w2 * t).sin(), 0.3 * w2 * (w2 * t).cos(), -0.3 * w2 * w2 * (w2 * t).sin());
    let spin = 700.0 * 2.0 * PI / 60.0;
    let a = LabeledFrame::new("A", Frame::new());
    let rot =
        |name, prev: &LabeledFrame, o: vectrix::nalgebra::Matrix3<f64>, axis: usize, rate: f64, acc: f64| {
            let f = Frame::from_orientation_rel(&prev.frame, &o, 1e-12).unwrap();
            let e = f.axis(axis).unwrap();
            FrameMotion::new(LabeledFrame::new(name, f), *prev, e * rate, e * acc).unwrap()
        };
    let b_a = rot("B", &a, o3(psi), 3, psid, psidd);
    let c_b = rot("C", b_a.body(), o1(th), 1, thd, thdd);
    let d_c = rot("D", c_b.body(), o3(spin * t), 3, spin, 0.0);
    let d_a = FrameMotion::chain(&[b_a, c_b, d_c]).unwrap();
    let fd = &d_a.body().frame;
    let w = d_a.omega().resolve(fd);
    let al = d_a.alpha().resolve(fd);
    // six significant digits, as the notes print them
    assert_printed_slice(w.as_slice(), &["-58.0614", "56.0779", "103.672"]);
    assert_printed_slice(al.as_slice(), &["-3122.38", "7298.80", "-1158.54"]);
    assert_printed(w.norm(), "131.392");
    assert_printed(al.norm(), "8022.7");
}

// P4.21.2 (vi): a disk rolling without slip at constant speed; the contact point's acceleration
// is −Rφ̇²ĵ_A... here ĵ points down, so it points up toward the centre, of magnitude Rφ̇².
#[test]
fn problem_4_21_2_contact_point_acceleration() {
    let a = LabeledFrame::new("A", Frame::new());
    let f = &a.frame;
    let (big_r, phid, x_b) = (0.5, 4.0, 1.3);
    let v = big_r * phid; // no slip
    let b_a = rotating("B", &a, 0.3, phid, 0.0); // ω_{B/A} = φ̇k̂_A, k̂ into the page
    let centre =
        VectorJet::new(a.label, f.vector([x_b, -big_r, 0.0]), f.vector([v, 0.0, 0.0]), Vector::zero())
            .unwrap();
    let contact = centre.rigid_point(&b_a, f.vector([0.0, big_r, 0.0])).unwrap();
    assert!(contact.rate().norm() < TOL, "(iv) v − Rφ̇ = 0");
    assert!(dist(&contact.second_rate(), &f.vector([0.0, -big_r * phid * phid, 0.0])) < TOL);
}

// P4.21.4: with constant ω about a pin (translating or not), a⃗_{y/x} = −ω²r⃗_{y/x} for r⃗ ⊥ ω⃗.
#[test]
fn problem_4_21_4_relative_acceleration_independent_of_pin() {
    let a = LabeledFrame::new("A", Frame::new());
    let f = &a.frame;
    let b_a = rotating("B", &a, 0.0, 3.0, 0.0);
    let r_yx = f.vector([0.4, -0.7, 0.0]);
    for pin_acc in [[0.0, 0.0, 0.0], [2.0, -1.0, 0.0]] {
        let x =
            VectorJet::new(a.label, f.vector([1.0, 1.0, 0.0]), f.vector([0.5, 0.0, 0.0]), f.vector(pin_acc))
                .unwrap();
        let y = x.rigid_point(&b_a, r_yx).unwrap();
        assert!(dist(&(y.second_rate() - x.second_rate()), &(r_yx * -9.0)) < TOL);
    }
}
