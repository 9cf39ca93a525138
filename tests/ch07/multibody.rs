//! §7.11 chains and trees: RNEA with joint reactions, ABA, CRBA, and the typed errors.

use vectrix::dynamics::multibody::{Joint, Link, Model};
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::prelude::DynamicsError;

use crate::support::{EPS, assert_abs_slice, assert_rel_slice};

fn body(parent: Option<usize>, joint: Joint, offset: [f64; 3]) -> Link {
    Link::new(
        parent,
        joint,
        Vector3::from(offset),
        1.5,
        Vector3::new(0.2, -0.1, 0.3),
        Matrix3::from_diagonal(&Vector3::new(0.2, 0.3, 0.4)),
    )
}

/// A tree with every joint of the book (§1.5: pin, sleeve, collar, slot, ball) plus weld and free.
pub fn all_joints_tree() -> Model {
    let z = Vector3::z();
    let links = vec![
        body(None, Joint::Free, [0.0, 0.0, 0.0]),
        body(Some(0), Joint::Pin { axis: Vector3::new(1.0, 2.0, 0.5) }, [0.5, 0.0, 0.0]),
        body(Some(1), Joint::Sleeve { axis: Vector3::x() }, [0.0, 0.4, 0.0]),
        body(Some(0), Joint::Collar { axis: z }, [0.0, -0.5, 0.1]),
        body(Some(3), Joint::Slot { axis: z, direction: Vector3::y() }, [0.3, 0.0, 0.0]),
        body(Some(4), Joint::Ball, [0.0, 0.0, 0.6]),
        body(Some(5), Joint::Weld, [0.2, 0.2, 0.0]),
    ];
    let mut m = Model::new(&links).unwrap();
    m.gravity = Vector3::new(0.0, 0.0, -9.81);
    m
}

/// §7.11: forward dynamics by ABA agrees with CRBA + Cholesky, and RNEA inverts both, on a
/// tree with every joint type.
#[test]
fn section_7_11_aba_crba_rnea_agree_on_all_joint_types() {
    let model = all_joints_tree();
    assert_eq!((model.nq(), model.nv()), (7 + 1 + 1 + 2 + 2 + 4, 6 + 1 + 1 + 2 + 2 + 3));
    let mut q = model.neutral();
    for (k, x) in q.iter_mut().enumerate() {
        *x += 0.1 * (k as f64).sin();
    }
    let v: Vec<f64> = (0..model.nv()).map(|k| 0.3 * (1.7 * k as f64).cos()).collect();
    let tau: Vec<f64> = (0..model.nv()).map(|k| 0.5 * (0.9 * k as f64).sin()).collect();
    let a1 = model.aba(&q, &v, &tau, None).unwrap();
    let a2 = model.forward_dynamics_crba(&q, &v, &tau, None).unwrap();
    // both solve a 15-dof system with condition ~1e3
    assert_rel_slice(&a1, &a2, 1e-10);
    let back = model.rnea(&q, &v, &a1, None).unwrap();
    assert_abs_slice(&back.tau, &tau, 1e-10);
    let h = model.crba(&q).unwrap();
    assert!((&h - h.transpose()).norm() <= 64.0 * EPS * h.norm());
    assert!(h.clone().cholesky().is_some());
}

/// Bad input: zero-length axes, disconnected and cyclic trees, non-PSD inertia, slot axes not
/// perpendicular, non-finite states.
#[test]
fn model_rejects_bad_input() {
    let bad_axis = [body(None, Joint::Pin { axis: Vector3::zeros() }, [0.0; 3])];
    assert!(matches!(Model::new(&bad_axis), Err(DynamicsError::ZeroAxis { link: 0, .. })));
    let disconnected = [body(Some(3), Joint::Pin { axis: Vector3::z() }, [0.0; 3])];
    assert!(matches!(Model::new(&disconnected), Err(DynamicsError::Disconnected { link: 0, parent: 3, .. })));
    let cyclic = [body(Some(1), Joint::Ball, [0.0; 3]), body(Some(0), Joint::Ball, [0.0; 3])];
    assert!(matches!(Model::new(&cyclic), Err(DynamicsError::Cyclic { .. })));
    let mut not_psd = body(None, Joint::Ball, [0.0; 3]);
    not_psd.inertia = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -0.5));
    assert!(matches!(Model::new(&[not_psd]), Err(DynamicsError::InvalidInertia { .. })));
    let slot =
        [body(None, Joint::Slot { axis: Vector3::z(), direction: Vector3::new(0.0, 1.0, 1.0) }, [0.0; 3])];
    assert!(matches!(Model::new(&slot), Err(DynamicsError::JointGeometry { .. })));
    let model = all_joints_tree();
    let mut q = model.neutral();
    q[1] = f64::NAN;
    let zeros = vec![0.0; model.nv()];
    assert!(matches!(model.rnea(&q, &zeros, &zeros, None), Err(DynamicsError::NonFinite { .. })));
    assert!(matches!(
        model.aba(&model.neutral(), &zeros[1..], &zeros, None),
        Err(DynamicsError::DimensionMismatch { .. })
    ));
}

/// A massless leaf makes the joint-space inertia singular: ABA says so instead of dividing by 0.
#[test]
fn massless_leaf_is_a_singular_mass_matrix() {
    let mut l = body(None, Joint::Pin { axis: Vector3::z() }, [0.0; 3]);
    l.mass = 0.0;
    l.inertia = Matrix3::zeros();
    let model = Model::new(&[l]).unwrap();
    assert!(matches!(model.aba(&[0.0], &[0.0], &[1.0], None), Err(DynamicsError::SingularMassMatrix { .. })));
}
