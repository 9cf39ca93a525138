//! §4.1, §4.4–4.5: frame derivatives as tagged data, the transport theorems and points.
//!
//! Setup: F_A fixed, F_B moving along 𝓞_{B/A}(t) = `o_path(t, C1)`. A vector's A-frame
//! derivative is the physical vector whose A-components are d/dt(x|_A) (4.1.5); likewise for B.

use vectrix::kinematics::*;
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::num_dual::Dual2_64;
use vectrix::prelude::*;

use crate::paths::*;
use crate::support::{EPS, NanAmax};

/// Exact (num-dual) derivatives: rounding only.
const TOL: f64 = 512.0 * EPS;
/// Central differences of exact second derivatives (h = 1e-4): truncation h²·|x⁽⁵⁾| ≲ 1e-7.
const FD3_TOL: f64 = 1e-6;

const T0: f64 = 0.55;

fn setup() -> (LabeledFrame, FrameMotion) {
    let a = LabeledFrame::new("A", Frame::new());
    let m = motion_from_path("B", &a, |t| o_path(t, &C1), T0);
    (a, m)
}

/// x|_A(t) = 𝓞_{A/B}(t) x|_B(t) for x|_B = `vec_path(t, C2)`.
fn x_in_a<T: vectrix::tensor::Scalar>(t: T) -> Vector3<T> {
    o_path(t, &C1).transpose() * vec_path(t, &C2)
}

fn jets(a: &LabeledFrame, m: &FrameMotion) -> (VectorJet, VectorJet) {
    let fb = &m.body().frame;
    let [xb, xbd, xbdd] = vec_jet(|t| vec_path(t, &C2), T0);
    let [xa, xad, xadd] = vec_jet(x_in_a, T0);
    let jb = VectorJet::new(m.body().label, fb.vector(arr(xb)), fb.vector(arr(xbd)), fb.vector(arr(xbdd)))
        .unwrap();
    let v = |x| a.frame.vector(arr(x));
    let ja = VectorJet::new(a.label, v(xa), v(xad), v(xadd)).unwrap();
    (jb, ja)
}

fn jet_dist(x: &VectorJet, y: &VectorJet) -> f64 {
    assert_eq!(x.wrt(), y.wrt());
    dist(&x.value(), &y.value()).max(dist(&x.rate(), &y.rate())).max(dist(&x.second_rate(), &y.second_rate()))
}

// Fact 4.4.1, (4.4.1) and (4.5.1): x⃗^{A•} = x⃗^{B•} + ω⃗×x⃗ and the double transport theorem,
// against exact derivatives of the components.
#[test]
fn fact_4_4_1_transport_and_eq_4_5_1_double_transport() {
    let (a, m) = setup();
    let (jb, ja) = jets(&a, &m);
    let got = jb.transported(&m).unwrap();
    assert_eq!(got.wrt(), FrameLabel::new("A"));
    assert!(jet_dist(&got, &ja) < TOL, "B → A");
    let back = ja.transported(&m).unwrap();
    assert!(jet_dist(&back, &jb) < TOL, "A → B");
    // the plain functions agree with the tagged form
    let w = m.omega();
    assert!(dist(&transport(&jb.rate(), &w, &jb.value()), &ja.rate()) < TOL);
    let dd = double_transport(&jb.value(), &jb.rate(), &jb.second_rate(), &w, &m.alpha());
    assert!(dist(&dd, &ja.second_rate()) < TOL);
}

// P4.20.12 (triple transport; the printed version is garbled, the corrected form of the notes
// is tested): x⃗^{A•••} against central differences of exact second derivatives.
#[test]
fn problem_4_20_12_triple_transport_corrected() {
    let (a, m) = setup();
    let (jb, _) = jets(&a, &m);
    let fb = &m.body().frame;
    let h = 1e-4;
    let d3 = |f: &dyn Fn(f64) -> Vector3<f64>| (f(T0 + h) - f(T0 - h)) / (2.0 * h);
    let xa3 = d3(&|t| vec_jet(x_in_a, t)[2]);
    let xb3 = d3(&|t| vec_jet(|t| vec_path(t, &C2), t)[2]);
    // α^{B•}_{B/A}: derivative of α_{B/A}|_B
    let al_b = |t: f64| {
        let [o, _, odd] = mat_jet(|t| o_path(t, &C1), t);
        alpha_body_from_orientation_rates(&o, &odd).unwrap()
    };
    let al_dot = d3(&al_b);
    let got = triple_transport(
        &jb.value(),
        &jb.rate(),
        &jb.second_rate(),
        &fb.vector(arr(xb3)),
        &m.omega(),
        &m.alpha(),
        &fb.vector(arr(al_dot)),
    );
    let want = a.frame.vector(arr(xa3));
    assert!(dist(&got, &want) < FD3_TOL * want.norm().max(1.0), "{:?} vs {:?}", got, want);
}

// (4.4.12): M⃗^{A•} = M⃗^{B•} + Ω⃗M⃗ − M⃗Ω⃗ for a dyad with moving B-components.
#[test]
fn eq_4_4_12_transport_of_dyads() {
    let (a, m) = setup();
    let mb = |t: Dual2_64| -> Matrix3<Dual2_64> {
        o_path(t, &C3) + vec_path(t, &C2) * vec_path(t, &C1).transpose()
    };
    let ma = |t: Dual2_64| o_path(t, &C1).transpose() * mb(t) * o_path(t, &C1);
    let [b0, b1, _] = mat_jet(mb, T0);
    let [_, a1, _] = mat_jet(ma, T0);
    let fb = &m.body().frame;
    let jet = DyadicJet::new(m.body().label, fb.dyadic(&b0), fb.dyadic(&b1)).unwrap();
    let got = jet.transported(&m).unwrap();
    let want = a.frame.dyadic(&a1);
    assert!((got.rate_wrt(a.label).unwrap() - want).norm() < TOL);
    let back = got.transported(&m).unwrap();
    assert!((back.rate_wrt(m.body().label).unwrap() - fb.dyadic(&b1)).norm() < TOL);
    assert!(matches!(jet.rate_wrt(a.label), Err(KinematicsError::FrameMismatch { .. })));
}

// (4.1.16–18): a⃗_{y/x/A/B} = (v⃗_{y/x/A})^{B•}; resolved in B it is
// 𝓞̇_{B/A}ṙ|_A + 𝓞_{B/A}r̈|_A (4.1.18, whose first dot the OCR drops).
#[test]
fn eq_4_1_18_mixed_acceleration() {
    let (a, m) = setup();
    let [r, rd, rdd] = vec_jet(|t| vec_path(t, &C3), T0);
    let v = |x| a.frame.vector(arr(x));
    let jet = VectorJet::new(a.label, v(r), v(rd), v(rdd)).unwrap();
    let got = jet.mixed_acceleration(&m).unwrap();
    let [o, od, _] = mat_jet(|t| o_path(t, &C1), T0);
    let want = m.body().frame.vector(arr(od * rd + o * rdd));
    assert!(dist(&got, &want) < TOL);
    // tagged with the wrong frame: an error, not a silent mix
    let jb = VectorJet::fixed_in(m.body().label, v(r));
    assert!(matches!(jb.mixed_acceleration(&m), Err(KinematicsError::FrameMismatch { .. })));
}

// (4.4.9), (4.5.3): points y, z fixed in a rigid body B.
#[test]
fn eq_4_4_9_and_4_5_3_rigid_body_points() {
    let (a, m) = setup();
    let r_zy_b = Vector3::new(0.4, -0.2, 0.7);
    let [y, yd, ydd] = vec_jet(|t| vec_path(t, &C3), T0);
    let z_path = |t: Dual2_64| vec_path(t, &C3) + o_path(t, &C1).transpose() * r_zy_b.map(Dual2_64::from);
    let [z, zd, zdd] = vec_jet(z_path, T0);
    let v = |x| a.frame.vector(arr(x));
    let jy = VectorJet::new(a.label, v(y), v(yd), v(ydd)).unwrap();
    let jz = jy.rigid_point(&m, m.body().frame.vector(arr(r_zy_b))).unwrap();
    let want = VectorJet::new(a.label, v(z), v(zd), v(zdd)).unwrap();
    assert!(jet_dist(&jz, &want) < TOL);
}

// Fact 4.4.4, (4.4.11), (4.5.3): a point moving in a moving frame with a moving origin.
#[test]
fn eq_4_4_11_and_4_5_3_point_in_moving_frame() {
    let (a, m) = setup();
    let (rel, _) = jets(&a, &m); // r_{x/O_B} with B-derivatives
    let [o, od, odd] = vec_jet(|t| vec_path(t, &C3), T0);
    let v = |x| a.frame.vector(arr(x));
    let origin = VectorJet::new(a.label, v(o), v(od), v(odd)).unwrap();
    let got = origin.moving_point(&m, &rel).unwrap();
    let total = |t: Dual2_64| vec_path(t, &C3) + x_in_a(t);
    let [x, xd, xdd] = vec_jet(total, T0);
    let want = VectorJet::new(a.label, v(x), v(xd), v(xdd)).unwrap();
    assert!(jet_dist(&got, &want) < TOL);
    // swapped tags are rejected
    assert!(matches!(rel.moving_point(&m, &origin), Err(KinematicsError::FrameMismatch { .. })));
}

// Fact 4.1.1: v⃗_{z/x/A} = v⃗_{z/y/A} + v⃗_{y/x/A}; adding derivatives taken in different frames
// is an error.
#[test]
fn fact_4_1_1_velocity_additivity() {
    let (a, m) = setup();
    let (jb, ja) = jets(&a, &m);
    let sum = ja.plus(&ja).unwrap();
    assert!(dist(&sum.rate(), &(ja.rate() * 2.0)) < TOL);
    assert!(matches!(ja.plus(&jb), Err(KinematicsError::FrameMismatch { .. })));
    assert!(matches!(jb.rate_wrt(a.label), Err(KinematicsError::FrameMismatch { .. })));
    assert!(jb.rate_wrt(m.body().label).is_ok());
    let c = FrameLabel::new("C");
    assert!(matches!(
        VectorJet::fixed_in(c, ja.value()).transported(&m),
        Err(KinematicsError::FrameMismatch { .. })
    ));
}

// (4.2.1): (R⃗_{B/A}x⃗)^{B•} = R⃗_{B/A}x⃗^{A•}, since (R⃗_{B/A}x⃗)|_B = x|_A.
#[test]
fn eq_4_2_1_mixed_dot_identity() {
    let (a, m) = setup();
    let (_, ja) = jets(&a, &m);
    let fb = &m.body().frame;
    let r_ba = fb.rotation_dyadic_rel(&a.frame);
    let rx = r_ba * ja.value();
    assert!((rx.resolve(fb) - ja.value().resolve(&a.frame)).nan_amax() < TOL);
    // B-derivative of R x has B-components d/dt(x|_A)
    let rx_dot_b = fb.vector(arr(ja.rate().resolve(&a.frame)));
    assert!(dist(&rx_dot_b, &(r_ba * ja.rate())) < TOL);
}

// P4.20.2: d|x⃗|/dt = x⃗^{A•}·x⃗/|x⃗|, the same in every frame; a constant length means x⃗ ⊥ x⃗^{A•}.
#[test]
fn problem_4_20_2_rate_of_length() {
    let (a, m) = setup();
    let (jb, ja) = jets(&a, &m);
    let len = |t: f64| vec_jet(|t| vec_path(t, &C2), t)[0].norm();
    let h = 1e-5;
    // central difference, error ~1e-10
    let fd = (len(T0 + h) - len(T0 - h)) / (2.0 * h);
    let x = ja.value();
    assert!((ja.rate().dot(&x) / x.norm() - fd).abs() < 1e-8);
    assert!((jb.rate().dot(&x) / x.norm() - fd).abs() < 1e-8);
}

mod prop {
    use super::*;
    use crate::support::{frame, triple};
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        // A → B → A round trip of a jet (Fact 4.4.1 and (4.5.1) both ways).
        #[test]
        fn transport_round_trip(fa in frame(), fb in frame(), w in triple(), al in triple(),
                                x in [triple(), triple(), triple()]) {
            let a = LabeledFrame::new("A", fa);
            let b = LabeledFrame::new("B", fb);
            let m = FrameMotion::new(b, a, fa.vector(w), fa.vector(al)).unwrap();
            let j = VectorJet::new(a.label, fa.vector(x[0]), fa.vector(x[1]), fa.vector(x[2])).unwrap();
            let jb = j.transported(&m).unwrap();
            prop_assert_eq!(jb.wrt(), b.label);
            let back = jb.transported(&m).unwrap();
            prop_assert_eq!(back.wrt(), a.label);
            // |ω|²|x| ≲ 3·10²·17: scale the rounding tolerance by the data
            let scale = 1.0 + 300.0 * 20.0;
            prop_assert!(jet_dist(&back, &j) < 256.0 * EPS * scale);
            // the transport is by the inverse motion as well
            let via_inverse = j.transported(&m.inverse()).unwrap();
            prop_assert!(jet_dist(&via_inverse, &jb) < 256.0 * EPS * scale);
        }
    }
}
