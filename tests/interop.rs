//! Interop users expect (issue 23, item 5; `docs/guide/interop.md`).
//!
//! 1. Every resolved attitude representation converts to and from nalgebra's `UnitQuaternion`
//!    and `Rotation3` and to mint's `Quaternion`; resolved vectors and matrices are nalgebra
//!    values and reach mint through nalgebra's `convert-mint`. The references are nalgebra's
//!    own constructors (`UnitQuaternion::from_axis_angle`, `Rotation3::from_euler_angles`),
//!    independent of vectrix's formulas.
//! 2. serde on the value types: rotations and every attitude representation, frames, mass
//!    properties, polynomials, transfer functions and state-space models. A round trip through
//!    JSON gives back the same value (`==`, bit for bit: serde_json writes the shortest
//!    round-tripping decimal and reads it back exactly with `float_roundtrip`), the JSON forms
//!    are the documented ones, and bad files are refused with the constructors' messages.

mod support;

use crate::support::NanAmax;
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};
use vectrix::lti::{Polynomial, StateSpace, TransferFunction};
use vectrix::nalgebra::{Matrix3, Rotation3, Unit, UnitQuaternion, Vector3};
use vectrix::prelude::*;
use vectrix::statics::{InertiaComponents, MassProperties, Point};

const EPS: f64 = f64::EPSILON;

/// max |got − want| over the entries ≤ `tol` (absolute: the entries are of order 1).
#[track_caller]
fn assert_abs_matrix(got: &Matrix3<f64>, want: &Matrix3<f64>, tol: f64) {
    let err = (got - want).nan_amax();
    assert!(err <= tol, "got {got}, want {want}, max |err| = {err:e} > {tol:e}");
}

/// Quaternions equal up to the sign ±q (both describe one rotation, §2.15), absolute `tol`.
#[track_caller]
fn assert_same_rotation(got: &UnitQuaternion<f64>, want: &UnitQuaternion<f64>, tol: f64) {
    let (g, w) = (got.as_ref().coords, want.as_ref().coords);
    let err = (g - w).nan_amax().min((g + w).nan_amax());
    assert!(err <= tol, "got {g}, want ±{w}, |err| = {err:e} > {tol:e}");
}

/// JSON out and back in.
fn round_trip<T: serde::Serialize + serde::de::DeserializeOwned>(x: &T) -> T {
    let text = serde_json::to_string(x).expect("serialisable");
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{text}: {e}"))
}

/// The error message of reading `text` as a `T`.
fn refusal<T: serde::de::DeserializeOwned + std::fmt::Debug>(text: &str) -> String {
    match serde_json::from_str::<T>(text) {
        Ok(v) => panic!("{text} was accepted as {v:?}"),
        Err(e) => e.to_string(),
    }
}

// ---------------------------------------------------------------------------------------
// nalgebra and mint conversions.

/// Book (2.15.20): q = (cos θ/2, sin θ/2 n̂). The axis–angle → `UnitQuaternion` conversion
/// agrees with nalgebra's own `from_axis_angle` to a few ulps (each part is one sin or cos
/// times a unit component: 4ε absolute), and comes back to the same axis–angle.
#[test]
fn eq_2_15_20_axis_angle_to_nalgebra_unit_quaternion() {
    let n = Vector3::new(1.0, -2.0, 2.0) / 3.0;
    for theta in [1e-8, 0.3, FRAC_PI_2, 3.0, PI - 1e-8] {
        let aa = AxisAngle::General { axis: n, angle: theta };
        let got = UnitQuaternion::from(aa);
        let want = UnitQuaternion::from_axis_angle(&Unit::new_normalize(n), theta);
        assert_same_rotation(&got, &want, 4.0 * EPS);
        // Rotation3: Rodrigues's 𝓡 (2.11.1) against nalgebra's, entries of order 1.
        let r = Rotation3::from(aa);
        assert_abs_matrix(r.matrix(), want.to_rotation_matrix().matrix(), 8.0 * EPS);
        // Back: the eigenangle by atan2, so θ is recovered to a few ulps of θ.
        let back = AxisAngle::from(got);
        assert!((back.angle() - theta).abs() <= 4.0 * EPS * theta, "θ = {theta}: {back:?}");
    }
}

/// Fact 2.11.5: at θ = π both ±n̂ are eigenaxes. From nalgebra's half turn vectrix returns the
/// `HalfTurn` variant with the canonical sign (first nonzero component positive), whichever
/// sign nalgebra chose.
#[test]
fn fact_2_11_5_half_turn_from_nalgebra_is_a_variant_with_canonical_axis() {
    for axis in [Vector3::new(-1.0, 0.0, 0.0), Vector3::new(0.0, -3.0, 4.0) / 5.0] {
        let q = UnitQuaternion::from_axis_angle(&Unit::new_normalize(axis), PI);
        match AxisAngle::from(q) {
            AxisAngle::HalfTurn(n) => {
                let first = n.iter().copied().find(|x| x.abs() > 0.5 * EPS).expect("unit axis");
                assert!(first > 0.0, "canonical sign: {n}");
                assert!((n - axis).nan_amax().min((n + axis).nan_amax()) <= 2.0 * EPS, "{n} vs ±{axis}");
            }
            // nalgebra's cos(π/2) = 6e-17 is not an exact zero: the variant is then General
            // with θ = π to the last ulp; the axis is still ±n̂.
            AxisAngle::General { axis: n, angle } => {
                assert!((angle - PI).abs() <= 2.0 * EPS * PI);
                assert!((n - axis).nan_amax().min((n + axis).nan_amax()) <= 2.0 * EPS, "{n} vs ±{axis}");
            }
            AxisAngle::Identity => panic!("a half turn is not the identity"),
        }
    }
}

/// Book (2.12.33) with 3-2-1 = (yaw Ψ, pitch Θ, roll Φ): 𝓡 = 𝓡₃(Ψ)𝓡₂(Θ)𝓡₁(Φ), which is
/// nalgebra's `Rotation3::from_euler_angles(roll, pitch, yaw)` (roll about x first, all about
/// fixed axes). Entries are sums of products of three sines and cosines: 8ε absolute.
#[test]
fn eq_2_12_33_euler_321_agrees_with_nalgebra_roll_pitch_yaw() {
    for [psi, theta, phi] in [[0.3, -0.4, 1.2], [-2.9, 1.5, 0.1], [1.0, FRAC_PI_2, -1.0], [PI, 0.0, -PI]] {
        let e = EulerAngles::new(EulerSequence::S321, [psi, theta, phi]);
        let want = Rotation3::from_euler_angles(phi, theta, psi);
        assert_abs_matrix(Rotation3::from(e).matrix(), want.matrix(), 8.0 * EPS);
        assert_same_rotation(
            &UnitQuaternion::from(e),
            &UnitQuaternion::from_rotation_matrix(&want),
            8.0 * EPS,
        );
        // mint's quaternion carries the same Hamilton parts as vectrix's, scalar first.
        let m: mint::Quaternion<f64> = e.into();
        let q = e.quaternion();
        assert_eq!([m.s, m.v.x, m.v.y, m.v.z], [q.a, q.b, q.c, q.d]);
    }
}

/// Book (2.15.14): 𝓡(q) assumes ‖q‖ = 1. A quaternion that is not unit is refused by the
/// conversions whose target type promises a rotation; a unit one passes with its parts kept.
#[test]
fn eq_2_15_14_only_unit_quaternions_become_rotations() {
    let q = Quaternion::new(1.0, 1.0, 0.0, 0.0);
    assert!(matches!(UnitQuaternion::try_from(q), Err(RotationError::NotUnit { .. })));
    assert!(matches!(Rotation3::try_from(q), Err(RotationError::NotUnit { .. })));
    let nan = Quaternion::new(f64::NAN, 0.0, 0.0, 0.0);
    assert!(matches!(UnitQuaternion::try_from(nan), Err(RotationError::NonFinite { .. })));
    let unit = q.normalize().expect("nonzero");
    let uq = UnitQuaternion::try_from(unit).expect("unit");
    assert_eq!([uq.w, uq.i, uq.j, uq.k], [unit.a, unit.b, unit.c, unit.d]);
    // And back through Rotation3 (Shepperd/Markley): the same canonical q to a few ulps.
    let back = Quaternion::from(Rotation3::try_from(unit).expect("unit"));
    assert!((back.to_vector4() - unit.to_vector4()).nan_amax() <= 4.0 * EPS, "{back:?} vs {unit:?}");
}

/// Resolved vectors and matrices are nalgebra values; nalgebra's `convert-mint` (enabled by
/// vectrix-rotation) gives mint's types, exactly. A mint column matrix stores 𝓡's columns (B's
/// axes in A, (2.10.2)); mint's `RowMatrix3` from it stores 𝓡's rows.
#[test]
fn eq_2_10_2_resolved_values_reach_mint_exactly() {
    let a = Frame::new();
    let r = Rotation::from_axis_angle(&a.vector([0.2, -0.5, 1.0]), 0.9).expect("nonzero axis");
    let b = r.apply_frame(&a);
    let r_ba = b.rotation_rel(&a);
    // (2.10.2): the columns of 𝓡_{B/A} are B's axes in A (entries of order 1: 4ε absolute).
    assert!((r_ba.column(0) - b.i().resolve(&a)).nan_amax() <= 4.0 * EPS);
    let col: mint::ColumnMatrix3<f64> = r_ba.into();
    assert_eq!([col.x.x, col.x.y, col.x.z], [r_ba[(0, 0)], r_ba[(1, 0)], r_ba[(2, 0)]], "x = first column");
    let row: mint::RowMatrix3<f64> = col.into();
    assert_eq!([row.x.x, row.x.y, row.x.z], [r_ba[(0, 0)], r_ba[(0, 1)], r_ba[(0, 2)]]);
    let v: mint::Vector3<f64> = r.angle_vector_in(&a).into();
    assert_eq!(Vector3::from(v), r.angle_vector_in(&a));
    let q: mint::Quaternion<f64> = r.quaternion_in(&a).into();
    assert_eq!(Quaternion::from(q), r.quaternion_in(&a));
}

// ---------------------------------------------------------------------------------------
// serde: documented JSON forms.

/// The JSON forms of `docs/guide/interop.md`, exactly.
#[test]
fn serde_json_forms_are_the_documented_ones() {
    let a = Frame::new();
    let json = |x: &dyn erased::Ser| x.json();
    assert_eq!(json(&Quaternion::<f64>::identity()), r#"{"a":1.0,"b":0.0,"c":0.0,"d":0.0}"#);
    assert_eq!(json(&EulerSequence::S321), r#"{"axes":[3,2,1],"kind":"intrinsic"}"#);
    assert_eq!(
        json(&EulerAngles::new(EulerSequence::S313.extrinsic(), [0.5, 0.25, -1.0])),
        r#"{"sequence":{"axes":[3,1,3],"kind":"extrinsic"},"angles":[0.5,0.25,-1.0]}"#
    );
    assert_eq!(json(&AxisAngle::<f64, Vector3<f64>>::Identity), r#""identity""#);
    assert_eq!(
        json(&AxisAngle::<f64, Vector3<f64>>::HalfTurn(Vector3::x())),
        r#"{"half_turn":[1.0,0.0,0.0]}"#
    );
    assert_eq!(
        json(&AxisAngle::General { axis: a.k(), angle: 0.5 }),
        r#"{"general":{"axis":[0.0,0.0,1.0],"angle":0.5}}"#
    );
    assert_eq!(json(&a), r#"{"i":[1.0,0.0,0.0],"j":[0.0,1.0,0.0],"k":[0.0,0.0,1.0]}"#);
    // A rotation about k̂ by 2 atan2(0.8, 0.6): its Euler parameters in F₀.
    let turn =
        Rotation::from_quaternion_in(&a, &Quaternion::new(0.6, 0.0, 0.0, 0.8), ROTATION_TOL).expect("unit");
    assert_eq!(json(&turn), r#"{"a":0.6,"b":0.0,"c":0.0,"d":0.8}"#);
    let bx = MassProperties::solid_box(12.0, [1.0, 2.0, 3.0], &a, Point::at(a.vector([0.0, 0.0, 1.0])))
        .expect("valid box");
    assert_eq!(
        json(&bx),
        r#"{"mass":12.0,"centre_of_mass":[0.0,0.0,1.0],"inertia_about_centre":[[13.0,0.0,0.0],[0.0,10.0,0.0],[0.0,0.0,5.0]]}"#
    );
    assert_eq!(
        json(&InertiaComponents { moments: [1.0, 2.0, 3.0], products: [0.5, 0.0, 0.0] }),
        r#"{"moments":[1.0,2.0,3.0],"products":[0.5,0.0,0.0]}"#
    );
    let g = TransferFunction::new(&[1.0], &[1.0, 2.0, 1.0]).expect("valid").with_delay(0.1).expect("τ ≥ 0");
    assert_eq!(json(&g), r#"{"num":[1.0],"den":[1.0,2.0,1.0],"delay":0.1}"#);
    let ss =
        StateSpace::from_rows(&[&[0.0, 1.0], &[-2.0, -3.0]], &[&[0.0], &[1.0]], &[&[1.0, 0.0]], &[&[0.0]])
            .expect("valid");
    assert_eq!(
        json(&ss),
        r#"{"states":2,"inputs":1,"outputs":1,"a":[[0.0,1.0],[-2.0,-3.0]],"b":[[0.0],[1.0]],"c":[[1.0,0.0]],"d":[[0.0]]}"#
    );
}

/// A static gain has no states: the sizes are written out so its empty A, B, C keep shape.
#[test]
fn eq_15_7_4_static_gain_state_space_keeps_its_shape() {
    let d = vectrix::nalgebra::DMatrix::from_row_slice(2, 3, &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    let empty = |r, c| vectrix::nalgebra::DMatrix::<f64>::zeros(r, c);
    let ss = StateSpace::new(empty(0, 0), empty(0, 3), empty(2, 0), d).expect("valid static gain");
    let back = round_trip(&ss);
    assert_eq!(back, ss);
    assert_eq!((back.n_states(), back.n_inputs(), back.n_outputs()), (0, 3, 2));
}

// ---------------------------------------------------------------------------------------
// serde: bad files are refused with the constructors' messages.

#[test]
fn serde_refuses_what_the_constructors_refuse() {
    // (2.15.20): a rotation's Euler parameters are unit.
    assert!(refusal::<Rotation>(r#"{"a":1.0,"b":1.0,"c":0.0,"d":0.0}"#).contains("not a unit quaternion"));
    // §2.4: a frame is orthonormal and right-handed.
    let left = r#"{"i":[1.0,0.0,0.0],"j":[0.0,1.0,0.0],"k":[0.0,0.0,-1.0]}"#;
    assert!(refusal::<Frame>(left).contains("left-handed"));
    let skew = r#"{"i":[1.0,0.0,0.0],"j":[0.1,1.0,0.0],"k":[0.0,0.0,1.0]}"#;
    assert!(refusal::<Frame>(skew).contains("not orthonormal"));
    // §2.12: no equal neighbours, axes 1–3 only.
    assert!(
        refusal::<EulerSequence>(r#"{"axes":[3,3,1],"kind":"intrinsic"}"#).contains("equal adjacent axes")
    );
    assert!(
        refusal::<EulerSequence>(r#"{"axes":[3,4,1],"kind":"intrinsic"}"#).contains("axis 4 does not exist")
    );
    assert!(refusal::<EulerKind>(r#""sideways""#).contains("unknown variant"));
    // §2.11: θ ∈ (0, π] for a general axis–angle, a unit axis.
    let wide = r#"{"general":{"axis":[0.0,0.0,1.0],"angle":4.0}}"#;
    assert!(refusal::<AxisAngle<f64, Vector3<f64>>>(wide).contains("must lie in (0, π]"));
    let long = r#"{"half_turn":[0.0,0.0,2.0]}"#;
    assert!(refusal::<AxisAngle<f64, Vector3<f64>>>(long).contains("finite unit vector"));
    // §6.1–6.2: positive mass, physical inertia (λ1 ≤ λ2 + λ3 fails for diag(5, 1, 1)).
    let c = r#""centre_of_mass":[0.0,0.0,0.0]"#;
    let negative =
        format!(r#"{{"mass":-1.0,{c},"inertia_about_centre":[[1.0,0.0,0.0],[0.0,1.0,0.0],[0.0,0.0,1.0]]}}"#);
    assert!(refusal::<MassProperties>(&negative).contains("mass = -1 is invalid"));
    let triangle =
        format!(r#"{{"mass":1.0,{c},"inertia_about_centre":[[5.0,0.0,0.0],[0.0,1.0,0.0],[0.0,0.0,1.0]]}}"#);
    assert!(refusal::<MassProperties>(&triangle).contains("triangle inequality"));
    // §15.11, (15.10.2): a nonzero denominator, τ ≥ 0.
    assert!(
        refusal::<TransferFunction>(r#"{"num":[1.0],"den":[0.0],"delay":0.0}"#).contains("zero denominator")
    );
    assert!(refusal::<TransferFunction>(r#"{"num":[1.0],"den":[1.0,1.0],"delay":-1.0}"#).contains("delay"));
    // §15.7: sizes that fit; unknown fields are an error, not ignored.
    let short = r#"{"states":2,"inputs":1,"outputs":1,"a":[[0.0,1.0]],"b":[[0.0],[1.0]],"c":[[1.0,0.0]],"d":[[0.0]]}"#;
    assert!(refusal::<StateSpace>(short).contains("dimension mismatch in A: expected 2×2, found 1 rows"));
    assert!(refusal::<Quaternion>(r#"{"a":1.0,"b":0.0,"c":0.0,"d":0.0,"e":0.0}"#).contains("unknown field"));
    assert!(refusal::<Polynomial>("[1.0, null]").contains("invalid type"));
}

// ---------------------------------------------------------------------------------------
// serde: exact round trips on the hard sets.

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// §2.8, (2.15.20): a rotation (any rotor sign, θ up to 2π) and the frame it makes come
    /// back bit for bit.
    #[test]
    fn section_2_8_rotation_and_frame_round_trip(n in support::direction(), theta in support::angle(), b in support::frame()) {
        let a = Frame::new();
        let r = Rotation::from_axis_angle(&a.vector(n), 2.0 * theta).expect("nonzero axis");
        prop_assert_eq!(round_trip(&r), r);
        prop_assert_eq!(round_trip(&b), b);
        let c = r.apply_frame(&b);
        prop_assert_eq!(round_trip(&c), c);
        let d = RigidDisplacement::new(r, b.vector(n));
        prop_assert_eq!(round_trip(&d), d);
    }

    /// §2.11–2.16: every resolved representation of a rotation comes back bit for bit.
    #[test]
    fn section_2_15_representations_round_trip(n in support::direction(), theta in support::angle(), k in 0usize..12, extrinsic in any::<bool>()) {
        let a = Frame::new();
        let r = Rotation::from_axis_angle(&a.vector(n), theta).expect("nonzero axis");
        let q = r.quaternion_in(&a);
        prop_assert_eq!(round_trip(&q), q);
        let resolved = q.axis_angle();
        prop_assert_eq!(round_trip(&resolved), resolved);
        let physical = r.axis_angle();
        prop_assert_eq!(round_trip(&physical), physical);
        let seq = if extrinsic { EulerSequence::ALL[k].extrinsic() } else { EulerSequence::ALL[k] };
        let e = r.euler_in(&a, seq).principal();
        prop_assert_eq!(round_trip(&e), e);
    }

    /// §6.1–6.2: a rotated, shifted box (J⃗_{B/c} with round-off off the diagonal) comes back
    /// bit for bit.
    #[test]
    fn section_6_2_mass_properties_round_trip(sides in [0.1..5.0f64, 0.1..5.0f64, 0.1..5.0f64], b in support::frame(), c in support::triple()) {
        let a = Frame::new();
        let bx = MassProperties::solid_box(3.5, sides, &b, Point::at(a.vector(c))).expect("valid box");
        prop_assert_eq!(round_trip(&bx), bx);
        let comps = InertiaComponents::of(&bx.inertia_about_centre(), &a);
        prop_assert_eq!(round_trip(&comps), comps);
    }

    /// §15.7, §15.14: transfer functions and state-space models come back bit for bit.
    #[test]
    fn section_15_14_lti_round_trip(num in prop::collection::vec(-10.0..10.0f64, 1..4), den in prop::collection::vec(0.1..10.0f64, 1..5), tau in 0.0..2.0f64) {
        let g = TransferFunction::new(&num, &den).expect("nonzero den").with_delay(tau).expect("τ ≥ 0");
        prop_assert_eq!(round_trip(&g), g.clone());
        let full_den = [&[1.0][..], &den].concat();
        let proper = TransferFunction::new(&num[..num.len().min(full_den.len())], &full_den).expect("nonzero den");
        let ss = StateSpace::from_tf(&proper).expect("proper");
        prop_assert_eq!(round_trip(&ss), ss);
    }
}

/// `&dyn` serialisation for the table of JSON forms above.
mod erased {
    pub trait Ser {
        fn json(&self) -> String;
    }
    impl<T: serde::Serialize> Ser for T {
        fn json(&self) -> String {
            serde_json::to_string(self).expect("serialisable")
        }
    }
}
