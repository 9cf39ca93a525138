//! §7.11 chains and trees: RNEA with joint reactions, ABA, CRBA, the typed errors, joints whose
//! articulated inertia is singular (particles on ball and free joints, massless links) against
//! closed forms, and the tree algorithms over dual numbers.

use vectrix::dynamics::multibody::{Joint, JointWrench, Link, Model};
use vectrix::nalgebra::{DMatrix, Matrix3, Quaternion, UnitQuaternion, Vector3};
use vectrix::num_dual::{Dual64, DualSVec64, HyperDual64};
use vectrix::prelude::DynamicsError;

use crate::support::{EPS, NanAmax, nan_max};

/// max |got − want| ≤ tol × max(|want|) (relative to the largest entry).
#[track_caller]
fn assert_rel_to_max(got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len(), "length mismatch");
    let scale = want.iter().fold(0.0f64, |m, w| nan_max(m, w.abs()));
    let err = got.iter().zip(want).fold(0.0f64, |m, (g, w)| nan_max(m, (g - w).abs()));
    assert!(err <= tol * scale, "got {got:?}, want {want:?}, max |err| = {err:e} > {tol:e} × {scale:e}");
}

/// |got − want| ≤ tol (absolute).
#[track_caller]
fn assert_abs(got: f64, want: f64, tol: f64) {
    assert!(
        (got - want).abs() <= tol,
        "got {got:e}, want {want:e}, |err| = {:e} > {tol:e}",
        (got - want).abs()
    );
}

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

fn all_joints_state(model: &Model) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let mut q = model.neutral();
    for (k, x) in q.iter_mut().enumerate() {
        *x += 0.1 * (k as f64).sin();
    }
    let v: Vec<f64> = (0..model.nv()).map(|k| 0.3 * (1.7 * k as f64).cos()).collect();
    let tau: Vec<f64> = (0..model.nv()).map(|k| 0.5 * (0.9 * k as f64).sin()).collect();
    (q, v, tau)
}

/// §7.11: forward dynamics by ABA agrees with CRBA + Cholesky, and RNEA inverts both, on a
/// tree with every joint type. (Consistency of three vectrix routes; the independent
/// reference is Pinocchio in tests/multibody_reference.rs.)
#[test]
fn section_7_11_aba_crba_rnea_agree_on_all_joint_types() {
    let model = all_joints_tree();
    assert_eq!((model.nq(), model.nv()), (7 + 1 + 1 + 2 + 2 + 4, 6 + 1 + 1 + 2 + 2 + 3));
    let (q, v, tau) = all_joints_state(&model);
    let a1 = model.aba(&q, &v, &tau, None).unwrap();
    let a2 = model.forward_dynamics_crba(&q, &v, &tau, None).unwrap();
    let h = model.crba(&q).unwrap();
    let eig = h.clone().symmetric_eigen().eigenvalues;
    let cond = eig.max() / eig.min();
    // both solve with M: rounding ε·κ(M) of the largest entry, with 64 for the O(n) sums
    assert_rel_to_max(&a1, &a2, 64.0 * EPS * cond);
    let back = model.rnea(&q, &v, &a1, None).unwrap();
    assert_rel_to_max(&back.tau, &tau, 64.0 * EPS * cond);
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
    let mut q = model.neutral();
    q[3..7].copy_from_slice(&[0.0; 4]);
    assert!(matches!(model.aba(&q, &zeros, &zeros, None), Err(DynamicsError::OutOfRange { .. })));
    assert!(matches!(
        model.integrate(&model.neutral(), &zeros, f64::NAN),
        Err(DynamicsError::NonFinite { what: "dt" })
    ));
}

/// Finite inputs whose results overflow (v = 1e200: the bias forces hold v² ≈ 1e400) give a
/// typed error, never non-finite numbers inside `Ok`.
#[test]
fn hard_case_huge_velocity_is_an_overflow_error() {
    let model = all_joints_tree();
    let (q, _, tau) = all_joints_state(&model);
    let v = vec![1e200; model.nv()];
    assert!(matches!(model.aba(&q, &v, &tau, None), Err(DynamicsError::Overflow { .. })));
    assert!(matches!(model.rnea(&q, &v, &tau, None), Err(DynamicsError::Overflow { .. })));
    assert!(matches!(model.forward_dynamics_crba(&q, &v, &tau, None), Err(DynamicsError::Overflow { .. })));
    assert!(matches!(model.kinetic_energy(&q, &v), Err(DynamicsError::Overflow { .. })));
    assert!(matches!(model.rnea_derivatives(&q, &v, &tau, None), Err(DynamicsError::Overflow { .. })));
}

/// A massless leaf link has no inertia about its pin: a torque on it would give infinite
/// acceleration (a typed error), and without a torque its coordinate is inert (v̇ = 0), while
/// the mass matrix is singular and CRBA + Cholesky says so.
#[test]
fn section_7_11_massless_leaf_is_inert() {
    let mut l = body(None, Joint::Pin { axis: Vector3::z() }, [0.0; 3]);
    l.mass = 0.0;
    l.inertia = Matrix3::zeros();
    let model = Model::new(&[l]).unwrap();
    let err = model.aba(&[0.0], &[0.0], &[1.0], None).unwrap_err();
    assert!(matches!(err, DynamicsError::InertJointForce { coordinate: 0, .. }), "{err}");
    assert_eq!(model.aba(&[0.3], &[2.0], &[0.0], None).unwrap(), vec![0.0]);
    assert!(matches!(
        model.forward_dynamics_crba(&[0.0], &[0.0], &[0.0], None),
        Err(DynamicsError::SingularMassMatrix { .. })
    ));
}

/// Degenerate trees: no links, and weld-only links (no coordinates): every algorithm returns
/// empty results instead of failing, and the weld-only tree still has poses and a weight.
#[test]
fn hard_case_empty_and_weld_only_trees() {
    let empty = Model::new(&[]).unwrap();
    let weld = {
        let mut m = Model::new(&[
            body(None, Joint::Weld, [0.0, 0.0, 1.0]),
            body(Some(0), Joint::Weld, [0.5, 0.0, 0.0]),
        ])
        .unwrap();
        m.gravity = Vector3::new(0.0, 0.0, -9.81);
        m
    };
    for m in [&empty, &weld] {
        assert_eq!(m.nv(), 0);
        let q = m.neutral();
        assert!(m.aba(&q, &[], &[], None).unwrap().is_empty());
        assert!(m.rnea(&q, &[], &[], None).unwrap().tau.is_empty());
        assert_eq!(m.crba(&q).unwrap().shape(), (0, 0));
        let d = m.aba_derivatives(&q, &[], &[], None).unwrap();
        assert_eq!(d.dvdot_dq.shape(), (0, 0));
        assert_eq!(m.kinetic_energy(&q, &[]).unwrap(), 0.0);
    }
    // two welded bodies of 1.5 kg with centres at z = 1.3 and 1.3: U = −Σ m g·r_c
    let poses = weld.poses(&[]).unwrap();
    assert_eq!(poses[1].1, Vector3::new(0.5, 0.0, 1.0));
    assert_abs(weld.potential_energy(&[]).unwrap(), 2.0 * 1.5 * 9.81 * 1.3, 8.0 * EPS * 40.0);
}

/// A deterministic pseudo-random sequence in [−1, 1) (no test dependency on a generator).
fn lcg(seed: &mut u64) -> f64 {
    *seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
    ((*seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
}

/// The spherical pendulum: a particle of mass m at distance L below a ball joint (zero
/// rotational inertia, so Dᵢ = m L²(1 − ê êᵀ) is singular along the rod ê).
pub fn spherical_pendulum(m: f64, l: f64, g: f64) -> Model {
    let link =
        Link::new(None, Joint::Ball, Vector3::zeros(), m, Vector3::new(0.0, 0.0, -l), Matrix3::zeros());
    let mut model = Model::new(&[link]).unwrap();
    model.gravity = Vector3::new(0.0, 0.0, -g);
    model
}

/// Position, velocity and acceleration of the spherical pendulum's particle from the ball
/// joint's state (q = quaternion, v = ω in the link) and ω̇ from ABA.
pub fn pendulum_motion(model: &Model, q: &[f64], w: &Vector3<f64>, l: f64) -> [Vector3<f64>; 4] {
    let wd = Vector3::from_column_slice(&model.aba(q, w.as_slice(), &[0.0; 3], None).unwrap());
    let r = model.poses(q).unwrap()[0].0.transpose();
    let c = Vector3::new(0.0, 0.0, -l);
    [r * c, r * w.cross(&c), r * (wd.cross(&c) + w.cross(&w.cross(&c))), wd]
}

/// The spherical pendulum (a particle on a ball joint, issue 16 item 4): ABA handles the
/// singular joint inertia exactly. Closed forms, θ the angle from the downward vertical and
/// φ the azimuth: θ̈ = sin θ cos θ φ̇² − (g/L) sin θ and d/dt(sin²θ φ̇) = 0, i.e.
/// φ̈ = −2 cot θ θ̇ φ̇; in Cartesian form (valid at the poles too) p̈ = g − (g·p̂)p̂ − (|ṗ|²/L²) p.
/// The spin about the rod carries no inertia and gets ω̇·ê = 0.
#[test]
fn section_7_11_spherical_pendulum_matches_closed_form() {
    let (m, l, g) = (1.3, 0.8, 9.81);
    let model = spherical_pendulum(m, l, g);
    let gv = Vector3::new(0.0, 0.0, -g);
    let mut seed = 7u64;
    for _ in 0..300 {
        let e = Quaternion::new(lcg(&mut seed), lcg(&mut seed), lcg(&mut seed), lcg(&mut seed));
        let q = UnitQuaternion::new_normalize(e);
        let qv = [q.w, q.i, q.j, q.k];
        let w = Vector3::new(lcg(&mut seed), lcg(&mut seed), lcg(&mut seed)) * 3.0;
        let [p, pd, pdd, wd] = pendulum_motion(&model, &qv, &w, l);
        // every term is a product of at most a few numbers of size g or L|ω|²: rounding of a
        // few dozen ε of that scale
        let scale = g + l * w.norm_squared();
        let tol = 64.0 * EPS * scale;
        let cartesian = gv - p * (gv.dot(&p) / (l * l)) - p * (pd.norm_squared() / (l * l));
        for k in 0..3 {
            assert_abs(pdd[k], cartesian[k], tol);
        }
        assert_abs(wd.z, 0.0, tol / l);
        // spherical angles (away from the poles, where φ is defined)
        let theta = (p.xy().norm()).atan2(-p.z);
        if theta.sin() < 0.05 {
            continue;
        }
        let phi = p.y.atan2(p.x);
        let e_theta = Vector3::new(theta.cos() * phi.cos(), theta.cos() * phi.sin(), theta.sin());
        let e_phi = Vector3::new(-phi.sin(), phi.cos(), 0.0);
        let (thd, phd) = (e_theta.dot(&pd) / l, e_phi.dot(&pd) / (l * theta.sin()));
        // p̈ = L θ̈ e_θ + L sin θ φ̈ e_φ + (terms in θ̇², φ̇², θ̇φ̇), projected on e_θ and e_φ
        let thdd = e_theta.dot(&pdd) / l + theta.sin() * theta.cos() * phd * phd;
        let phdd = (e_phi.dot(&pdd) - 2.0 * l * theta.cos() * thd * phd) / (l * theta.sin());
        let want_thdd = theta.sin() * theta.cos() * phd * phd - g / l * theta.sin();
        let want_phdd = -2.0 * theta.cos() / theta.sin() * thd * phd;
        // the projections divide by L and by sin θ ≥ 0.05
        assert_abs(thdd, want_thdd, 2.0 * tol / (l * 0.05));
        assert_abs(phdd, want_phdd, 2.0 * tol / (l * 0.05 * 0.05));
    }
}

/// The singular joint inertia in single precision: `Model<f32>` takes the same pseudo-inverse
/// path with f32's rounding level (64 ε₃₂), and agrees with the f64 model to f32 accuracy.
#[test]
fn section_7_11_spherical_pendulum_in_single_precision() {
    let model = spherical_pendulum(1.3, 0.8, 9.81);
    let m32 = model.cast::<f32>();
    let q = UnitQuaternion::from_scaled_axis(Vector3::new(0.4, -0.7, 0.2));
    let qv = [q.w, q.i, q.j, q.k];
    let w = [0.9, -1.4, 2.2];
    let a64 = model.aba(&qv, &w, &[0.0; 3], None).unwrap();
    let to32 = |x: &[f64]| x.iter().map(|&y| y as f32).collect::<Vec<f32>>();
    let a32 = m32.aba(&to32(&qv), &to32(&w), &[0.0; 3], None).unwrap();
    let got: Vec<f64> = a32.iter().map(|&x| f64::from(x)).collect();
    // f32 rounding (1.2e-7) over a few dozen operations
    assert_rel_to_max(&got, &a64, 64.0 * f64::from(f32::EPSILON));
}

/// The spherical pendulum cannot take a torque about its own rod (infinite acceleration):
/// typed error; a torque perpendicular to the rod is fine.
#[test]
fn section_7_11_spherical_pendulum_refuses_torque_about_the_rod() {
    let model = spherical_pendulum(1.0, 0.5, 9.81);
    let q = [1.0, 0.0, 0.0, 0.0];
    let err = model.aba(&q, &[0.0; 3], &[0.0, 0.0, 0.2], None).unwrap_err();
    assert!(matches!(err, DynamicsError::InertJointForce { coordinate: 0, .. }), "{err}");
    // τ = (0.25, 0, 0) about x̂: θ̈ = τ/(m L²) = 1 about x̂
    let a = model.aba(&q, &[0.0; 3], &[0.25, 0.0, 0.0], None).unwrap();
    assert_rel_to_max(&a, &[1.0, 0.0, 0.0], 4.0 * EPS);
}

/// A point mass on a free joint: its translation obeys m ẍ = m g + F exactly, whatever its
/// attitude; its spin carries no inertia (ω̇ = 0), and a moment on it is refused. With the
/// particle off the link origin (at c), its own acceleration is still g + F/m:
/// p̈ = ẍ + R(ω̇ × c + ω × (ω × c)).
#[test]
fn section_7_11_point_mass_on_free_joint_is_exact() {
    let g = Vector3::new(0.5, -1.0, -9.81);
    for c in [Vector3::zeros(), Vector3::new(0.3, -0.2, 0.4)] {
        let link = Link::new(None, Joint::Free, Vector3::zeros(), 2.0, c, Matrix3::zeros());
        let mut model = Model::new(&[link]).unwrap();
        model.gravity = g;
        let mut seed = 11u64;
        for _ in 0..50 {
            let e = Quaternion::new(lcg(&mut seed), lcg(&mut seed), lcg(&mut seed), lcg(&mut seed));
            let uq = UnitQuaternion::new_normalize(e);
            let q = [lcg(&mut seed), lcg(&mut seed), lcg(&mut seed), uq.w, uq.i, uq.j, uq.k];
            let w = Vector3::new(lcg(&mut seed), lcg(&mut seed), lcg(&mut seed)) * 2.0;
            let v = [lcg(&mut seed), lcg(&mut seed), lcg(&mut seed), w.x, w.y, w.z];
            // a force through the particle, in link components: F = R_linkᵀ F_ground
            let f_link = Vector3::new(lcg(&mut seed), lcg(&mut seed), lcg(&mut seed)) * 4.0;
            let wrench = [JointWrench { force: f_link, moment: c.cross(&f_link) }];
            let a = model.aba(&q, &v, &[0.0; 6], Some(&wrench)).unwrap();
            let r = model.poses(&q).unwrap()[0].0.transpose();
            let wd = Vector3::new(a[3], a[4], a[5]);
            let pdd = Vector3::new(a[0], a[1], a[2]) + r * (wd.cross(&c) + w.cross(&w.cross(&c)));
            let want = g + r * f_link / 2.0;
            let tol = 64.0 * EPS * (g.norm() + f_link.norm() + w.norm_squared());
            for k in 0..3 {
                assert_abs(pdd[k], want[k], tol);
            }
            // the inert spin: zero about the axis through the particle (all axes when c = 0)
            let along = if c == Vector3::zeros() { wd.norm() } else { wd.dot(&c.normalize()).abs() };
            assert_abs(along, 0.0, tol);
        }
        let q = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0];
        let moment = [JointWrench { force: Vector3::zeros(), moment: Vector3::new(0.0, 0.0, 1.0) + c }];
        let err = model.aba(&q, &[0.0; 6], &[0.0; 6], Some(&moment)).unwrap_err();
        assert!(matches!(err, DynamicsError::InertJointForce { coordinate: 3, .. }), "{err}");
    }
}

/// A pin about ẑ at the ground origin carrying a link of zero mass and inertia.
fn massless_pin() -> Link {
    Link::new(
        None,
        Joint::Pin { axis: Vector3::z() },
        Vector3::zeros(),
        0.0,
        Vector3::zeros(),
        Matrix3::zeros(),
    )
}

/// A rigid link on a pin about ẑ at (l1, 0, 0) of link 0: mass m, centre at c along x̂,
/// J_zz = jz about the centre.
fn rod_on_pin(l1: f64, m: f64, c: f64, jz: f64) -> Link {
    Link::new(
        Some(0),
        Joint::Pin { axis: Vector3::z() },
        Vector3::new(l1, 0.0, 0.0),
        m,
        Vector3::new(c, 0.0, 0.0),
        Matrix3::from_diagonal(&Vector3::new(0.01, jz, jz)),
    )
}

/// The two-link pendulum with a massless first link (zero mass and inertia between two pins)
/// and a rigid second link (mass m, centre at c along it, J about the centre), gravity −g ŷ,
/// relative angles (θ1, θ2): the closed form of the textbook two-link arm,
/// M = [[m(l1² + c² + 2 l1 c cos θ2) + J, m(c² + l1 c cos θ2) + J], [·, m c² + J]],
/// C = h(−2θ̇1θ̇2 − θ̇2², θ̇1²) with h = m l1 c sin θ2, G = m g (l1 cos θ1 + c cos θ12, c cos θ12),
/// M q̈ = τ − C − G (solved here by Cramer's rule).
#[test]
fn section_7_11_massless_intermediate_link_matches_two_link_closed_form() {
    let (l1, m, c, jz, g) = (0.7, 1.9, 0.35, 0.05, 9.81);
    let mut model = Model::new(&[massless_pin(), rod_on_pin(l1, m, c, jz)]).unwrap();
    model.gravity = Vector3::new(0.0, -g, 0.0);
    let mut seed = 3u64;
    for _ in 0..200 {
        let (t1, t2) = (3.0 * lcg(&mut seed), 3.0 * lcg(&mut seed));
        let (w1, w2) = (2.0 * lcg(&mut seed), 2.0 * lcg(&mut seed));
        let tau = [lcg(&mut seed), lcg(&mut seed)];
        let a = model.aba(&[t1, t2], &[w1, w2], &tau, None).unwrap();
        let m11 = m * (l1 * l1 + c * c + 2.0 * l1 * c * t2.cos()) + jz;
        let m12 = m * (c * c + l1 * c * t2.cos()) + jz;
        let m22 = m * c * c + jz;
        let h = m * l1 * c * t2.sin();
        let rhs1 = tau[0] + h * (2.0 * w1 * w2 + w2 * w2) - m * g * (l1 * t1.cos() + c * (t1 + t2).cos());
        let rhs2 = tau[1] - h * w1 * w1 - m * g * c * (t1 + t2).cos();
        let det = m11 * m22 - m12 * m12;
        let want = [(rhs1 * m22 - m12 * rhs2) / det, (m11 * rhs2 - m12 * rhs1) / det];
        // a 2×2 solve whose condition is at most (m11 + m22)²/det
        let cond = (m11 + m22).powi(2) / det;
        assert_rel_to_max(&a, &want, 64.0 * EPS * cond);
    }
}

/// Two coaxial pins joined by a massless link: the first joint's direction carries no inertia
/// of its own (the second pin absorbs the motion), so it gets q̈₁ = 0 and the body swings as a
/// single pendulum about the common axis; the massless link transmits torque unchanged, so
/// τ₁ = τ₂ is required, and τ₁ ≠ τ₂ (an infinite acceleration) is refused.
#[test]
fn section_7_11_coaxial_pins_with_massless_link_are_exact() {
    let (m, c, jz, g) = (1.2, 0.4, 0.03, 9.81);
    let mut model = Model::new(&[massless_pin(), rod_on_pin(0.0, m, c, jz)]).unwrap();
    model.gravity = Vector3::new(0.0, -g, 0.0);
    let (t1, t2, tau) = (0.4, -1.1, 0.7);
    let a = model.aba(&[t1, t2], &[0.5, -0.3], &[tau, tau], None).unwrap();
    // single pendulum about the common axis: (m c² + J) φ̈ = τ − m g c cos φ, φ = θ1 + θ2
    let want = (tau - m * g * c * (t1 + t2).cos()) / (m * c * c + jz);
    assert_abs(a[0], 0.0, 64.0 * EPS * want.abs());
    assert_abs(a[1], want, 64.0 * EPS * want.abs());
    let err = model.aba(&[t1, t2], &[0.5, -0.3], &[tau, 0.0], None).unwrap_err();
    assert!(matches!(err, DynamicsError::InertJointForce { coordinate: 0, .. }), "{err}");
}

/// DESIGN §1.4: the tree algorithms run over num-dual's numbers. ∂T/∂vₖ by `Dual64` is the
/// generalized momentum (M v)ₖ; ∂²T/∂vᵢ∂vⱼ by `HyperDual64` is Mᵢⱼ (T = ½ vᵀMv, §9.3); the
/// gradient of V along the tangent directions is the gravity torque RNEA(q, 0, 0); and three
/// directional derivatives of ABA at once by `DualSVec64<3>` equal three `Dual64` passes.
#[test]
fn generic_scalar_dual_numbers_through_the_tree_algorithms() {
    let model = all_joints_tree();
    let (q, v, tau) = all_joints_state(&model);
    let n = model.nv();
    let h = model.crba(&q).unwrap();
    let p = &h * DMatrix::from_column_slice(n, 1, &v);
    let gravity = model.rnea(&q, &vec![0.0; n], &vec![0.0; n], None).unwrap().tau;
    let d1 = model.cast::<Dual64>();
    let lift = |x: &[f64]| x.iter().map(|&x| Dual64::from(x)).collect::<Vec<_>>();
    let hd = model.cast::<HyperDual64>();
    let hlift = |x: &[f64]| x.iter().map(|&x| HyperDual64::from(x)).collect::<Vec<_>>();
    let tol = 64.0 * EPS * h.nan_amax() * (1.0 + v.iter().fold(0.0f64, |a, x| nan_max(a, x.abs())));
    // gravity torques are at most the total weight (7 links of 1.5 kg) times a lever below 2 m
    let torque_scale = 9.81 * 1.5 * 7.0 * 2.0;
    for k in 0..n {
        let mut vk = lift(&v);
        vk[k].eps = 1.0;
        assert_abs(d1.kinetic_energy(&lift(&q), &vk).unwrap().eps, p[k], tol);
        // q ⊕ ε eₖ: ∂V/∂qₖ in the tangent space equals the k-th gravity torque
        let mut e = lift(&vec![0.0; n]);
        e[k].eps = 1.0;
        let qk = d1.integrate(&lift(&q), &e, Dual64::from(1.0)).unwrap();
        assert_abs(d1.potential_energy(&qk).unwrap().eps, gravity[k], 64.0 * EPS * torque_scale);
        for j in 0..n {
            let mut vh = hlift(&v);
            vh[k].eps1 += 1.0;
            vh[j].eps2 += 1.0;
            let t = hd.kinetic_energy(&hlift(&q), &vh).unwrap();
            assert_abs(t.eps1eps2, h[(k, j)], 64.0 * EPS * h.nan_amax());
        }
    }
    // three directions at once: ∂v̇/∂τ₀, ∂v̇/∂τ₁, ∂v̇/∂v₂
    let dv = model.cast::<DualSVec64<3>>();
    let slift = |x: &[f64]| x.iter().map(|&x| DualSVec64::<3>::from(x)).collect::<Vec<_>>();
    let (mut ts, mut vs) = (slift(&tau), slift(&v));
    let unit =
        |k: usize| vectrix::num_dual::Derivative::some(vectrix::nalgebra::SVector::<f64, 3>::ith(k, 1.0));
    ts[0].eps = unit(0);
    ts[1].eps = unit(1);
    vs[2].eps = unit(2);
    let a3 = dv.aba(&slift(&q), &vs, &ts, None).unwrap();
    let seeds: [(usize, bool); 3] = [(0, true), (1, true), (2, false)];
    for (d, &(k, is_tau)) in seeds.iter().enumerate() {
        let (mut t1, mut v1) = (lift(&tau), lift(&v));
        if is_tau {
            t1[k].eps = 1.0;
        } else {
            v1[k].eps = 1.0;
        }
        let a1 = d1.aba(&lift(&q), &v1, &t1, None).unwrap();
        for (a3r, a1r) in a3.iter().zip(&a1) {
            let got = a3r.eps.unwrap_generic(vectrix::nalgebra::Const::<3>, vectrix::nalgebra::Const::<1>)[d];
            assert_abs(got, a1r.eps, 16.0 * EPS * (1.0 + a1r.eps.abs()));
        }
    }
    // f32 runs the same algorithms (single precision: ~1e-5 of the f64 result)
    let m32 = model.cast::<f32>();
    let a32 = m32
        .aba(
            &q.iter().map(|&x| x as f32).collect::<Vec<_>>(),
            &v.iter().map(|&x| x as f32).collect::<Vec<_>>(),
            &tau.iter().map(|&x| x as f32).collect::<Vec<_>>(),
            None,
        )
        .unwrap();
    let a64 = model.aba(&q, &v, &tau, None).unwrap();
    let got: Vec<f64> = a32.iter().map(|&x| f64::from(x)).collect();
    // f32 rounding (6e-8) amplified by κ(M) ≈ 1e2 and the O(n) sums
    assert_rel_to_max(&got, &a64, 1e-4);
}

/// Fact 8.4.1 (E = T + U is conserved when every force is potential), with the joint forces
/// τ as the only non-potential ones: d(T + U)/dt = τᵀv along the motion (work (8.2.1)).
/// Differentiated exactly by one `Dual64` pass: the state (q ⊕ ε v, v + ε v̇), v̇ from ABA.
#[test]
fn fact_8_4_1_energy_rate_equals_power_of_joint_forces() {
    let model = all_joints_tree();
    let (q, v, tau) = all_joints_state(&model);
    let a = model.aba(&q, &v, &tau, None).unwrap();
    let d = model.cast::<Dual64>();
    let lift = |x: &[f64]| x.iter().map(|&x| Dual64::from(x)).collect::<Vec<_>>();
    let eps_dir: Vec<Dual64> = v.iter().map(|&x| Dual64::new(0.0, x)).collect();
    let qe = d.integrate(&lift(&q), &eps_dir, Dual64::from(1.0)).unwrap();
    let ve: Vec<Dual64> = v.iter().zip(&a).map(|(&x, &y)| Dual64::new(x, y)).collect();
    let rate = d.kinetic_energy(&qe, &ve).unwrap().eps + d.potential_energy(&qe).unwrap().eps;
    let power: f64 = tau.iter().zip(&v).map(|(t, w)| t * w).sum();
    // power of the weight (7 links of 1.5 kg, levers below 2 m) and of τ, per unit speed
    let speed = v.iter().fold(0.0f64, |m, x| nan_max(m, x.abs()));
    let scale = (9.81 * 1.5 * 7.0 * 2.0 + tau.iter().map(|t| t.abs()).sum::<f64>()) * speed;
    assert_abs(rate, power, 256.0 * EPS * scale);
}

/// (8.1.19): T = ½ Σ (m|v_c|² + ωᵀJ_cω) over the links, with v_c = v + ω × r_{c/origin} from
/// the link twists (transport theorem), equals the tree's kinetic energy ½ Σ 𝒱ᵀ𝒥𝒱.
#[test]
fn eq_8_1_19_twists_give_the_kinetic_energy() {
    let model = all_joints_tree();
    let (q, v, _) = all_joints_state(&model);
    let tw = model.twists(&q, &v).unwrap();
    let poses = model.poses(&q).unwrap();
    let (m, c, j) = (1.5, Vector3::new(0.2, -0.1, 0.3), Matrix3::from_diagonal(&Vector3::new(0.2, 0.3, 0.4)));
    let mut t = 0.0;
    for (k, tk) in tw.iter().enumerate() {
        let r = poses[k].0.transpose();
        let vc = tk.velocity_of(&(r * c));
        let w_link = poses[k].0 * tk.omega;
        t += 0.5 * (m * vc.norm_squared() + w_link.dot(&(j * w_link)));
    }
    assert_abs(model.kinetic_energy(&q, &v).unwrap(), t, 64.0 * EPS * t);
}
