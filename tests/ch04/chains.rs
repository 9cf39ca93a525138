//! §4.13–4.14: 6D velocity and acceleration of a chain of rigid bodies, against exact
//! derivatives of the joint positions r_{z_k/z_0}|_A(t) = Σ_j 𝓞_{A/j}(t) r_{z_j/z_{j−1}}|_j.

use vectrix::kinematics::*;
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::num_dual::Dual2_64;
use vectrix::prelude::*;
use vectrix::tensor::Scalar;

use crate::paths::*;
use crate::support::{EPS, NanAmax};

const TOL: f64 = 1024.0 * EPS;
const T0: f64 = 0.35;
const PATHS: [[[f64; 3]; 3]; 3] = [C1, C2, C3];
const OFFSETS: [[f64; 3]; 3] = [[0.5, 0.1, -0.2], [0.0, 0.8, 0.3], [-0.4, 0.2, 0.6]];

/// 𝓞_{k/0}(t) for body k = 1..3.
fn o_k0<T: Scalar>(t: T, k: usize) -> Matrix3<T> {
    (0..k).fold(Matrix3::identity(), |acc, j| o_path(t, &PATHS[j]) * acc)
}

/// r_{z_k/z_0}|_A(t).
fn joint<T: Scalar>(t: T, k: usize) -> Vector3<T> {
    (1..=k).fold(Vector3::zeros(), |acc, j| {
        acc + o_k0(t, j).transpose() * Vector3::from(OFFSETS[j - 1]).map(T::lit)
    })
}

fn build() -> (LabeledFrame, Vec<FrameMotion>, Vec<LinkMotion>) {
    let a = LabeledFrame::new("A", Frame::new());
    let names = ["B", "C", "D"];
    let mut rel = Vec::new();
    let mut prev = a;
    for k in 0..3 {
        let m = motion_from_path(names[k], &prev, move |t| o_path(t, &PATHS[k]), T0);
        prev = *m.body();
        rel.push(m);
    }
    let links = rel
        .iter()
        .enumerate()
        .map(|(k, m)| LinkMotion {
            body: *m.body(),
            omega_rel_prev: m.omega(),
            alpha_rel_prev: m.alpha(),
            r_joint_prev_joint: m.body().frame.vector(OFFSETS[k]),
        })
        .collect();
    (a, rel, links)
}

// (4.13.33–38), (4.14.1–16): linear rows are joint velocities and (mixed) accelerations; the
// angular rows belong to the next body (the off-by-one pairing); true a = mixed + ω_{k/A}×v.
#[test]
fn eq_4_13_36_and_4_14_6_chain_velocity_and_acceleration() {
    let (a, rel, links) = build();
    let ChainKinematics { twists, accels } = chain_kinematics(&links).unwrap();
    assert_eq!(twists.len(), 4);
    let abs: Vec<FrameMotion> = (1..=3).map(|k| FrameMotion::chain(&rel[..k]).unwrap()).collect();
    for k in 0..=3 {
        let [_, v, acc] = vec_jet(|t: Dual2_64| joint(t, k), T0);
        let (tw, ac) = (&twists[k], &accels[k]);
        assert_eq!((tw.joint, ac.joint), (k, k));
        let v_want = a.frame.vector(arr(v));
        assert!(dist(&tw.v_joint, &v_want) < TOL, "v at z_{k}");
        assert!(dist(&ac.a_joint, &a.frame.vector(arr(acc))) < TOL, "a at z_{k}");
        // the pairing: body k+1, or the last body at the end effector
        let body = (k + 1).min(3);
        assert_eq!((tw.body, ac.body), (body, body));
        assert!(dist(&tw.omega_body, &abs[body - 1].omega()) < TOL);
        assert!(dist(&ac.alpha_body, &abs[body - 1].alpha()) < TOL);
        if k >= 1 {
            // mixed acceleration w.r.t. body k (4.14.1)
            let jet = VectorJet::new(a.label, Vector::zero(), v_want, a.frame.vector(arr(acc))).unwrap();
            let mixed = jet.mixed_acceleration(&abs[k - 1]).unwrap();
            assert!(dist(&ac.a_joint_mixed, &mixed) < TOL, "mixed a at z_{k}");
        }
    }
}

// (4.13.33–38) resolved form: 𝒱_k|_k from 𝓞_{k/k−1}, ω_{k/k−1}|_k and r|_k only (𝓞_{B/A} is not
// needed) equals the physical recursion resolved in body k.
#[test]
fn eq_4_13_38_resolved_chain_velocity() {
    let (_, rel, links) = build();
    let twists = chain_kinematics(&links).unwrap().twists;
    let resolved: Vec<ResolvedLink> = rel
        .iter()
        .enumerate()
        .map(|(k, m)| ResolvedLink {
            o_k_prev: m.o_b_a(),
            omega_rel_prev_in_k: m.omega().resolve(&m.body().frame),
            r_joint_prev_joint_in_k: Vector3::from(OFFSETS[k]),
        })
        .collect();
    let out = chain_velocity_resolved(&resolved).unwrap();
    for k in 0..=3 {
        let f = &links[k.max(1) - 1].body.frame; // 𝒱_0 is resolved in body 1
        let v = twists[k].v_joint.resolve(f);
        let w = twists[k].omega_body.resolve(f);
        let want = vectrix::nalgebra::Vector6::new(v.x, v.y, v.z, w.x, w.y, w.z);
        assert!((out[k] - want).nan_amax() < TOL, "𝒱_{k}");
    }
    assert!(matches!(chain_velocity_resolved::<f64>(&[]), Err(KinematicsError::EmptyChain { .. })));
    assert!(matches!(chain_kinematics::<f64>(&[]), Err(KinematicsError::EmptyChain { .. })));
}
