//! §4.2–4.6: angular velocity, angular acceleration, Poisson's equation, summation.

use vectrix::kinematics::*;
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::prelude::*;

use crate::paths::*;
use crate::support::{EPS, NanAmax};

/// Exact derivatives through num-dual leave only rounding: a few hundred ε on O(1) data.
const TOL: f64 = 256.0 * EPS;

fn frame_a() -> LabeledFrame {
    LabeledFrame::new("A", Frame::new())
}

/// (4.10.7–9): ω_{D/A}|_D = S(Φ,Θ)[Φ̇, Θ̇, Ψ̇] for 3-2-1 angles, written out independently.
fn euler321_body_rate(c: &[[f64; 3]; 3], t: f64) -> Vector3<f64> {
    let jet = |k: usize| {
        let x = angle(vectrix::num_dual::Dual2_64::new(t, 1.0, 0.0), c[k]);
        (x.re, x.v1)
    };
    let ((_, psid), (th, thd), (ph, phd)) = (jet(0), jet(1), jet(2));
    let s = Matrix3::new(
        1.0,
        0.0,
        -th.sin(),
        0.0,
        ph.cos(),
        ph.sin() * th.cos(),
        0.0,
        -ph.sin(),
        ph.cos() * th.cos(),
    );
    s * Vector3::new(phd, thd, psid)
}

// Fact 4.3.6, (4.3.20): ω^×_{B/A|B} = −𝓞̇_{B/A}𝓞_{A/B}; checked against the 3-2-1 body-rate
// matrix (4.10.7–9), an independent formula.
#[test]
fn eq_4_3_20_poisson_omega_from_orientation_rate() {
    for t in [0.0, 0.4, 1.3] {
        let [o, od, _] = mat_jet(|t| o_path(t, &C1), t);
        let w = omega_body_from_orientation_rate(&o, &od).unwrap();
        let want = euler321_body_rate(&C1, t);
        assert!((w - want).nan_amax() < TOL, "t = {t}: {w} vs {want}");
    }
}

// (4.3.17): 𝓡̇_{B/A} = 𝓡_{B/A}ω^×_{B/A|B}; spatial form 𝓡̇ = ω^×_{B/A|A}𝓡.
#[test]
fn eq_4_3_17_poisson_equation_reproduces_the_derivative() {
    let [o, od, _] = mat_jet(|t| o_path(t, &C2), 0.7);
    let (r, rd) = (o.transpose(), od.transpose());
    let w_b = omega_body_from_orientation_rate(&o, &od).unwrap();
    assert!((poisson_rate(&r, &w_b) - rd).nan_amax() < TOL);
    let w_a = omega_spatial_from_rotation_rate(&r, &rd).unwrap();
    assert!((w_a - r * w_b).nan_amax() < TOL, "ω|_A = 𝓡_{{B/A}} ω|_B");
    assert!((poisson_rate_spatial(&r, &w_a) - rd).nan_amax() < TOL);
}

// Def 4.2.3, Fact 4.2.4, (4.2.19), (4.2.24): Ω⃗_{B/A} is skew, Ω|_B = −𝓞̇_{B/A}𝓞_{A/B}, and
// Ω⃗_{A/B} = −Ω⃗_{B/A}.
#[test]
fn def_4_2_3_angular_velocity_dyad_is_skew() {
    let a = frame_a();
    let m = motion_from_path("B", &a, |t| o_path(t, &C1), 0.3);
    let [o, od, _] = mat_jet(|t| o_path(t, &C1), 0.3);
    let om = m.omega_dyad();
    let om_b = om.resolve(&m.body().frame);
    assert!((om_b + om_b.transpose()).nan_amax() < TOL, "skew (F4.2.4)");
    assert!((om_b - (-od * o.transpose())).nan_amax() < TOL, "(4.2.24)");
    assert!((m.inverse().omega_dyad() + om).norm() < TOL, "(4.2.19)");
}

// P4.20.5: ω⃗ = ½Σ ê_B × ê_B^{A•} and the projection form; (4.3.13–15) ê^{A•} = ω⃗ × ê.
#[test]
fn problem_4_20_5_omega_from_axis_rates() {
    let a = frame_a();
    let t = 0.9;
    let m = motion_from_path("B", &a, |t| o_path(t, &C3), t);
    let [_, od, _] = mat_jet(|t| o_path(t, &C3), t);
    // rows of 𝓞_{B/A} are B's axes in A, so rows of 𝓞̇ are their A-derivatives
    let d = |k: usize| a.frame.vector([od[(k, 0)], od[(k, 1)], od[(k, 2)]]);
    let b = &m.body().frame;
    let w = m.omega();
    assert!(dist(&omega_from_axis_rates(b, &d(0), &d(1), &d(2)), &w) < TOL);
    assert!(dist(&omega_from_axis_rates_projections(b, &d(0), &d(1), &d(2)), &w) < TOL);
    let rates = axis_rates(b, &w);
    for (k, rate) in rates.iter().enumerate() {
        assert!(dist(rate, &d(k)) < TOL, "(4.3.13–15) axis {k}");
    }
}

// (4.4.3), (4.4.6): α_{B/A}|_B = d/dt ω_{B/A}|_B, from the second derivative of 𝓞_{B/A}.
#[test]
fn eq_4_4_6_angular_acceleration_is_the_derivative_of_omega_in_b() {
    let f = |t: f64| {
        let [o, od, _] = mat_jet(|t| o_path(t, &C2), t);
        omega_body_from_orientation_rate(&o, &od).unwrap()
    };
    let t = 0.45;
    let h = 1e-5;
    // central difference: truncation ~h²·|ω‴| ≈ 1e-10, rounding ~ε/h ≈ 2e-11
    let fd = (f(t + h) - f(t - h)) / (2.0 * h);
    let [o, _, odd] = mat_jet(|t| o_path(t, &C2), t);
    let al = alpha_body_from_orientation_rates(&o, &odd).unwrap();
    assert!((al - fd).nan_amax() < 1e-8, "{al} vs {fd}");
    // α^{A•} = α^{B•}: resolved in A it is d/dt ω|_A as well (4.4.3)
    let g = |t: f64| {
        let [o, od, _] = mat_jet(|t| o_path(t, &C2), t);
        o.transpose() * omega_body_from_orientation_rate(&o, &od).unwrap()
    };
    let fd_a = (g(t + h) - g(t - h)) / (2.0 * h);
    assert!((o.transpose() * al - fd_a).nan_amax() < 1e-8);
}

// (4.3.8): ω⃗_{A/B} = −ω⃗_{B/A}; Fact 4.3.2: resolved, ω_{B/A}|_B = −𝓞_{B/A}ω_{A/B}|_A, which is
// not −ω_{A/B}|_A in general (the classic bug the physical vectors prevent).
#[test]
fn eq_4_3_8_inverse_and_fact_4_3_2_caution() {
    let a = frame_a();
    let m = motion_from_path("B", &a, |t| o_path(t, &C1), 0.6);
    let inv = m.inverse();
    assert_eq!(inv.body().label, FrameLabel::new("A"));
    assert!(dist(&inv.omega(), &(-m.omega())) < TOL);
    assert!(dist(&inv.alpha(), &(-m.alpha())) < TOL);
    let (fa, fb) = (&a.frame, &m.body().frame);
    let w_ba_b = m.omega().resolve(fb);
    let w_ab_a = inv.omega().resolve(fa);
    assert!((w_ba_b + m.o_b_a() * w_ab_a).nan_amax() < TOL, "F4.3.2");
    assert!((w_ba_b + w_ab_a).nan_amax() > 0.1, "F4.3.3: the naive sign flip is wrong here");
    assert_eq!(inv.inverse(), m);
}

/// The motion of C relative to A along 𝓞_{C/A} = 𝓞_{C/B}𝓞_{B/A} (2.10.46 order).
fn composed_paths() -> (LabeledFrame, FrameMotion, FrameMotion, FrameMotion) {
    let a = frame_a();
    let t = 0.8;
    let b_a = motion_from_path("B", &a, |t| o_path(t, &C1), t);
    let c_b = motion_from_path("C", b_a.body(), |t| o_path(t, &C2), t);
    let c_a = motion_from_path("C", &a, |t| o_path(t, &C2) * o_path(t, &C1), t);
    (a, b_a, c_b, c_a)
}

// (4.6.2), (4.6.5): ω⃗_{C/A} = ω⃗_{C/B} + ω⃗_{B/A}; α⃗_{C/A} = α⃗_{C/B} + α⃗_{B/A} − ω⃗_{C/B}×ω⃗_{B/A}.
#[test]
fn eq_4_6_2_and_4_6_5_summation_of_two_frames() {
    let (_, b_a, c_b, c_a) = composed_paths();
    let sum = c_b.compose(&b_a).unwrap();
    assert!(dist(&sum.omega(), &c_a.omega()) < TOL);
    assert!(dist(&sum.alpha(), &c_a.alpha()) < TOL);
    // the ω×ω term matters here
    assert!(dist(&(c_b.alpha() + b_a.alpha()), &c_a.alpha()) > 0.1);
}

// (4.6.6–7): α⃗_{D/A} = Σα⃗ − ω⃗_{D/C}×ω⃗_{C/B} − ω⃗_{D/B}×ω⃗_{B/A}, and the chain recursion.
#[test]
fn eq_4_6_7_summation_of_four_frames() {
    let a = frame_a();
    let t = 0.25;
    let b_a = motion_from_path("B", &a, |t| o_path(t, &C1), t);
    let c_b = motion_from_path("C", b_a.body(), |t| o_path(t, &C2), t);
    let d_c = motion_from_path("D", c_b.body(), |t| o_path(t, &C3), t);
    let d_a = motion_from_path("D", &a, |t| o_path(t, &C3) * o_path(t, &C2) * o_path(t, &C1), t);
    let chain = FrameMotion::chain(&[b_a, c_b, d_c]).unwrap();
    assert_eq!(chain.body().label, FrameLabel::new("D"));
    assert_eq!(chain.reference().label, FrameLabel::new("A"));
    assert!(dist(&chain.omega(), &d_a.omega()) < TOL);
    assert!(dist(&chain.alpha(), &d_a.alpha()) < TOL);
    // the printed four-frame form (4.6.7)
    let w_d_b = d_c.omega() + c_b.omega();
    let printed =
        b_a.alpha() + c_b.alpha() + d_c.alpha() - d_c.omega().cross(&c_b.omega()) - w_d_b.cross(&b_a.omega());
    assert!(dist(&printed, &d_a.alpha()) < TOL);
}

// (4.4.4): α⃗_{B/A/C} = ω⃗_{B/A}^{C•}, the derivative of ω_{B/A}|_C (components in C).
#[test]
fn eq_4_4_4_mixed_angular_acceleration() {
    let (_, b_a, _, c_a) = composed_paths();
    let mixed = b_a.mixed_alpha(&c_a).unwrap();
    let w_in_c = |t: f64| {
        let [o_ba, od_ba, _] = mat_jet(|t| o_path(t, &C1), t);
        let o_ca = mat_jet(|t| o_path(t, &C2) * o_path(t, &C1), t)[0];
        // ω_{B/A}|_C = 𝓞_{C/A}𝓞_{A/B} ω_{B/A}|_B
        o_ca * o_ba.transpose() * omega_body_from_orientation_rate(&o_ba, &od_ba).unwrap()
    };
    let (t, h) = (0.8, 1e-5);
    let fd = (w_in_c(t + h) - w_in_c(t - h)) / (2.0 * h);
    // central difference error ~1e-10 (see eq_4_4_6)
    assert!((mixed.resolve(&c_a.body().frame) - fd).nan_amax() < 1e-8);
    assert!(matches!(c_a.mixed_alpha(&b_a.inverse()), Err(KinematicsError::FrameMismatch { .. })));
}

// Frame identity is checked: composing C/B with D/A is an error, never a silent mix.
#[test]
fn compose_with_wrong_frame_is_an_error() {
    let (a, b_a, c_b, _) = composed_paths();
    assert!(matches!(b_a.compose(&c_b), Err(KinematicsError::FrameMismatch { .. })));
    let same = FrameMotion::new(a, a, Vector::zero(), Vector::zero());
    assert!(matches!(same, Err(KinematicsError::SameFrame { .. })));
    let b = *b_a.body();
    let nan = FrameMotion::new(b, a, a.frame.vector([f64::NAN, 0.0, 0.0]), Vector::zero());
    assert!(matches!(nan, Err(KinematicsError::NonFinite { .. })));
    assert!(matches!(FrameMotion::<f64>::chain(&[]), Err(KinematicsError::EmptyChain { .. })));
}

mod prop {
    use super::*;
    use crate::support::{frame, triple};
    use proptest::prelude::*;

    fn motion(
        b: &'static str,
        a: &'static str,
        fb: Frame,
        fa: Frame,
        w: [f64; 3],
        al: [f64; 3],
    ) -> FrameMotion {
        FrameMotion::new(LabeledFrame::new(b, fb), LabeledFrame::new(a, fa), fa.vector(w), fa.vector(al))
            .unwrap()
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(96))]

        // (4.6.2), (4.6.5) are associative: both groupings of D/C∘C/B∘B/A agree.
        #[test]
        fn summation_is_associative(fa in frame(), fb in frame(), fc in frame(), fd in frame(),
                                    w in [triple(), triple(), triple()], al in [triple(), triple(), triple()]) {
            let b_a = motion("B", "A", fb, fa, w[0], al[0]);
            let c_b = motion("C", "B", fc, fb, w[1], al[1]);
            let d_c = motion("D", "C", fd, fc, w[2], al[2]);
            let left = d_c.compose(&c_b).unwrap().compose(&b_a).unwrap();
            let right = d_c.compose(&c_b.compose(&b_a).unwrap()).unwrap();
            let scale = 1.0 + 100.0 * 3.0;
            prop_assert!(dist(&left.omega(), &right.omega()) < 64.0 * EPS * scale);
            prop_assert!(dist(&left.alpha(), &right.alpha()) < 64.0 * EPS * scale * scale);
        }

        // (4.3.8): inverting twice is the identity; ω⃗_{B/A} + ω⃗_{A/B} = 0⃗.
        #[test]
        fn inverse_round_trip(fa in frame(), fb in frame(), w in triple(), al in triple()) {
            let m = motion("B", "A", fb, fa, w, al);
            prop_assert_eq!(m.inverse().inverse(), m);
            prop_assert_eq!(m.inverse().omega() + m.omega(), Vector::zero());
        }
    }
}
