//! §2.11–2.22 and Ex 2.25.1: rotations in every representation, the executable textbook.
//!
//! Each test opens with the book statement it checks; errata (notes ch1-2a §4d, ch2b §2) are
//! tested in their corrected form and say so. Split by section into `rotations/*.rs`.

use crate::support::NanAmax;
use nalgebra::{Matrix3, Vector3};
use vectrix::prelude::*;

#[path = "rotations/euler.rs"]
mod euler;
#[path = "rotations/parameters.rs"]
mod parameters;
#[path = "rotations/rigid.rs"]
mod rigid;
#[path = "rotations/rodrigues.rs"]
mod rodrigues;

/// max |a − b| over the entries.
pub fn mat_err(a: &Matrix3<f64>, b: &Matrix3<f64>) -> f64 {
    (a - b).nan_amax()
}

/// Asserts max |a − b| ≤ tol.
#[track_caller]
pub fn assert_mat(a: &Matrix3<f64>, b: &Matrix3<f64>, tol: f64) {
    let e = mat_err(a, b);
    assert!(e <= tol, "matrices differ by {e:e} > {tol:e}:\n{a}\n{b}");
}

/// Asserts max |a − b| ≤ tol for resolved vectors.
#[track_caller]
pub fn assert_vec(a: &Vector3<f64>, b: &Vector3<f64>, tol: f64) {
    let e = (a - b).nan_amax();
    assert!(e <= tol, "vectors differ by {e:e} > {tol:e}: {a} vs {b}");
}

/// Distance between quaternions up to sign (q and −q are the same rotation, F2.15.7).
pub fn q_err(p: &Quaternion, q: &Quaternion) -> f64 {
    let d = (p.to_vector4() - q.to_vector4()).nan_amax();
    let s = (p.to_vector4() + q.to_vector4()).nan_amax();
    d.min(s)
}

/// The unit vector along v (resolved components).
pub fn unit(v: [f64; 3]) -> Vector3<f64> {
    Vector3::from(v).normalize()
}

/// Rodrigues's formula (2.11.1) written out: cosθ I + (1 − cosθ) nnᵀ + sinθ n^×.
pub fn rodrigues(n: &Vector3<f64>, theta: f64) -> Matrix3<f64> {
    let n = n.normalize();
    Matrix3::identity() * theta.cos()
        + n * n.transpose() * (1.0 - theta.cos())
        + n.cross_matrix() * theta.sin()
}

/// R⃗_{n̂}(θ) with n̂ given in frame `a`.
pub fn rot(a: &Frame, n: [f64; 3], theta: f64) -> Rotation {
    Rotation::from_axis_angle(&a.vector(n), theta).expect("nonzero axis")
}

mod prop {
    //! Property tests over random rotations biased toward the hard sets (DESIGN §6).
    use proptest::prelude::*;

    use super::*;
    use crate::support::*;

    fn rotation() -> impl Strategy<Value = Rotation> {
        (
            direction(),
            prop_oneof![3 => 0.0..std::f64::consts::PI, 2 => proptest::sample::select(HARD_ANGLES.to_vec())],
        )
            .prop_map(|(n, th)| rot(&Frame::new(), n, th))
    }

    fn sequence() -> impl Strategy<Value = EulerSequence> {
        (proptest::sample::select(EulerSequence::ALL.to_vec()), any::<bool>())
            .prop_map(|(s, ext)| if ext { s.extrinsic() } else { s })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        /// Frame independence (DESIGN §6): R⃗|_B = 𝓞_{B/A} R⃗|_A 𝓞_{B/A}ᵀ, and applying R⃗ commutes
        /// with resolution.
        #[test]
        fn frame_independence(r in rotation(), b in frame(), x in triple()) {
            let a = Frame::new();
            let o_ba = b.orientation_rel(&a);
            assert_mat(&r.rotation_matrix_in(&b), &(o_ba * r.rotation_matrix_in(&a) * o_ba.transpose()), 16.0 * EPS);
            let xv = a.vector(x);
            let scale = 1.0 + xv.norm();
            assert_vec(&r.apply(&xv).resolve(&b), &(r.rotation_matrix_in(&b) * xv.resolve(&b)), 16.0 * EPS * scale);
        }

        /// (2.10.44–46): R⃗_{C/A} = R⃗_{C/B}R⃗_{B/A}, 𝓞_{C/A} = 𝓞_{C/B}𝓞_{B/A},
        /// 𝓡_{C/A} = 𝓡_{B/A}𝓡_{C/B}, q_{C/A} = ±q_{B/A}⊗q_{C/B} (F2.15.7 corrected), Gibbs (2.17.11).
        #[test]
        fn composition_orders(r_ba in rotation(), r_cb_a in rotation()) {
            let a = Frame::new();
            let b = r_ba.apply_frame(&a);
            let c = r_cb_a.apply_frame(&b);
            let (r_cb, r_ca) = (Rotation::between(&c, &b), Rotation::between(&c, &a));
            // six rounded steps apart (two frame rotations, two `between`, a product, a
            // resolution), each a few ε per entry: 21ε seen over 2·10⁴ cases, 32ε allowed
            assert_mat(&(r_cb * r_ba).rotation_matrix_in(&a), &r_ca.rotation_matrix_in(&a), 32.0 * EPS);
            let (o_cb, o_ba, o_ca) = (c.orientation_rel(&b), b.orientation_rel(&a), c.orientation_rel(&a));
            assert_mat(&compose_orientation(&o_cb, &o_ba), &o_ca, 16.0 * EPS);
            let (rm_cb, rm_ba) = (c.rotation_rel(&b), b.rotation_rel(&a));
            assert_mat(&compose_rotation_matrix(&rm_cb, &rm_ba), &c.rotation_rel(&a), 16.0 * EPS);
            let q_cb = Quaternion::from_rotation_matrix(&rm_cb, 1e-13).unwrap();
            let q_ba = Quaternion::from_rotation_matrix(&rm_ba, 1e-13).unwrap();
            let q_ca = Quaternion::from_rotation_matrix(&c.rotation_rel(&a), 1e-13).unwrap();
            prop_assert!(q_err(&compose_quaternion(&q_cb, &q_ba), &q_ca) <= 16.0 * EPS);
            // (2.17.11) amplifies rounding by (1 + |g|²)² near π, where Gibbs vectors blow up.
            let gibbs = (q_cb.gibbs(), q_ba.gibbs(), q_ca.gibbs());
            if let (Some(g_cb), Some(g_ba), Some(g_ca)) = gibbs
                && let Some(g) = compose_gibbs(&g_cb, &g_ba)
            {
                let scale = 1.0 + g_ca.norm() * g_ca.norm() + g_cb.norm() * g_ba.norm();
                prop_assert!((g - g_ca).nan_amax() <= 1e3 * EPS * scale * scale);
            }
        }

        /// §2.13 extraction, all 12 sequences intrinsic and extrinsic: every solution rebuilds
        /// the matrix (quaternions compared up to sign).
        #[test]
        fn euler_round_trip(r in rotation(), seq in sequence()) {
            let a = Frame::new();
            let q = r.quaternion_in(&a);
            match r.euler_in(&a, seq) {
                EulerSolution::Regular { principal, alternate } => {
                    prop_assert!(q_err(&principal.quaternion(), &q) <= 16.0 * EPS);
                    prop_assert!(q_err(&alternate.quaternion(), &q) <= 16.0 * EPS);
                }
                EulerSolution::GimbalLock { representative, .. } => {
                    prop_assert!(q_err(&representative.quaternion(), &q) <= 16.0 * EPS);
                }
            }
        }

        /// Every representation round-trips through the quaternion (item 7 on random input).
        #[test]
        fn representation_round_trips(r in rotation()) {
            let a = Frame::new();
            let q = r.quaternion_in(&a);
            prop_assert!(q_err(&Quaternion::from_rotation_matrix_unchecked(&q.rotation_matrix()), &q) <= 8.0 * EPS);
            prop_assert!(q_err(&Quaternion::from_angle_vector(&q.angle_vector()), &q) <= 8.0 * EPS);
            prop_assert!(q_err(&Quaternion::from_mrp(&q.mrp()), &q) <= 8.0 * EPS);
            if let Some(g) = q.gibbs() {
                prop_assert!(q_err(&Quaternion::from_gibbs(&g), &q) <= 8.0 * EPS);
            }
            let s = mrp_shadow(&q.mrp());
            if let Ok(s) = s {
                prop_assert!(q_err(&Quaternion::from_mrp(&s), &q) <= 64.0 * EPS);
            }
        }

        /// F2.19.4 (2.19.6): the commutator formula for general rotations.
        #[test]
        fn fact_2_19_4_commutator_formula(n1 in direction(), t1 in angle(), n2 in direction(), t2 in angle()) {
            let a = Frame::new();
            let (ra, rb) = (rot(&a, n1, t1), rot(&a, n2, t2));
            let (n1, n2) = (unit(n1), unit(n2));
            let (s1, c1, s2, c2) = (t1.sin(), t1.cos(), t2.sin(), t2.cos());
            let x = |v: Vector3<f64>| v.cross_matrix();
            let want = x(n1.cross(&n2)) * (s1 * s2)
                + (x(n1) * n2 * n2.transpose() - n2 * n2.transpose() * x(n1)) * (s1 * (1.0 - c2))
                + (n1 * n1.transpose() * x(n2) - x(n2) * n1 * n1.transpose()) * (s2 * (1.0 - c1))
                + (n1 * n2.transpose() - n2 * n1.transpose()) * ((1.0 - c1) * (1.0 - c2) * n1.dot(&n2));
            assert_mat(&ra.commutator(&rb).resolve(&a), &want, 64.0 * EPS);
        }

        /// Chasles (F2.21.4): the constructed screw reproduces the displacement at every point.
        #[test]
        fn fact_2_21_4_chasles_reconstructs(r in rotation(), t in triple(), y in triple()) {
            let a = Frame::new();
            let d = RigidDisplacement::new(r, a.vector(t));
            let y = a.vector(y);
            let moved = d.apply(&y);
            match d.screw(1e-12) {
                Screw::Translation(v) => assert_vec(&moved.resolve(&a), &(y + v).resolve(&a), 1e-9),
                Screw::General { point, axis, angle, slide } => {
                    let rz = Rotation::from_axis_angle(&axis, angle).unwrap();
                    let want = point + rz.apply(&(y - point)) + axis * slide;
                    let scale = 1.0 + point.norm();
                    assert_vec(&moved.resolve(&a), &want.resolve(&a), 1e3 * EPS * scale * 20.0);
                }
            }
        }
    }
}
