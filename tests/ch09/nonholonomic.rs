//! §9.12 Lagrangian dynamics for nonholonomic systems: velocity constraints A(q, t)q̇ + b = 0
//! with multipliers, on the rolling disk (§4.18) and the knife edge (Chaplygin sleigh).
//!
//! Book (§9.12, a stub in the text): "Consider systems with constraints on the generalized
//! velocities that cannot be integrated to yield constraints on generalized coordinates."
//! Rolling without slipping (Def 4.18.2: the colocated contact points have zero relative
//! velocity) is the book's example of such a constraint.

use vectrix::dynamics::constraints::{
    ConstrainedIntegrator, LagrangeForm, MapForm, map_constrained_accelerations,
};
use vectrix::nalgebra::{Matrix3, Vector3};
use vectrix::num_dual::{Dual64, HyperDual64};
use vectrix::ode::Adaptive;
use vectrix::prelude::*;
use vectrix::statics::{AppliedForce, MassProperties, Point, Wrench};

use super::mechanisms::{assert_abs, frame_from};
use super::rolling::{RollingDisk, Sleigh};

const EPS: f64 = f64::EPSILON;
const G: f64 = 9.81;

fn disk(incline: f64) -> RollingDisk {
    RollingDisk { m: 1.7, r: 0.35, g: G, incline, all_rows: false }
}

/// Centre acceleration a⃗_c, angular acceleration α⃗ and ω⃗ of the disk from (q, q̇, q̈):
/// a⃗_c = ∇²c[q̇, q̇] + ∇c q̈ from one hyper-dual evaluation, α⃗ from one dual evaluation.
pub fn disk_motion(
    d: &RollingDisk,
    q: &[f64],
    qd: &[f64],
    qdd: &[f64],
) -> (Vector3<f64>, Vector3<f64>, Vector3<f64>) {
    let qh: Vec<HyperDual64> = (0..5).map(|k| HyperDual64::new(q[k], qd[k], qd[k], qdd[k])).collect();
    let a_c = d.centre(&qh).map(|x| x.eps1eps2);
    let qf: Vec<Dual64> = (0..5).map(|k| Dual64::new(q[k], qd[k])).collect();
    let qdf: Vec<Dual64> = (0..5).map(|k| Dual64::new(qd[k], qdd[k])).collect();
    let alpha = d.omega(&qf, &qdf).map(|x| x.eps);
    (a_c, alpha, d.omega(q, qd))
}

/// Newton–Euler for the disk given its motion: the contact force F⃗ = m a⃗_c − m g⃗ (7.4.7) at
/// the contact point, with gravity at c, must give the angular acceleration α⃗ through
/// Euler's equation (7.8.13) as vectrix's [`RigidBody`] solves it. Returns (F⃗, α⃗_NE).
pub fn newton_euler(
    d: &RollingDisk,
    q: &[f64],
    qd: &[f64],
    a_c: &Vector3<f64>,
) -> (Vector3<f64>, Vector3<f64>) {
    let a = Frame::new();
    let g = Vector3::new(d.incline.sin(), 0.0, -d.incline.cos()) * d.g;
    let f = a_c * d.m - g * d.m;
    let (o_la, o_ba) = d.frames(q);
    let c = Point::at(a.vector(d.centre(q).into()));
    let p = c.displaced(a.vector((-o_la.row(2).transpose() * d.r).into()));
    let j_b = Matrix3::from_diagonal(&Vector3::new(0.25, 0.5, 0.25)) * (d.m * d.r * d.r);
    let props = MassProperties::new(d.m, c, frame_from(&o_ba).dyadic(&j_b)).unwrap();
    let body =
        RigidBody::new(props, a.vector(d.centre_velocity(q, qd).into()), a.vector(d.omega(q, qd).into()));
    let contact = Wrench::from_force(&AppliedForce::new(a.vector(f.into()), p), c);
    let weight = Wrench::from_force(&AppliedForce::new(a.vector((g * d.m).into()), c), c);
    let (_, alpha) = body.accelerations(&contact.plus(&weight)).unwrap();
    (f, alpha.resolve(&a))
}

/// The existing rolling result (examples/scenes/rolling_disk.toml, §4.18): a disk rolling
/// straight down a plane inclined at α has a = g sin α/(1 + J/(mr²)) = (2/3) g sin α, and
/// the friction force is m(a − g sin α) = −(1/3) mg sin α (so λ₁ = +(1/3) mg sin α: −λ is
/// the contact force along the row's direction î). Integrated for 1 s: x = ½at².
#[test]
fn section_9_12_rolling_disk_down_incline() {
    let alpha = 0.3;
    let d = disk(alpha);
    let q = [0.0; 5];
    let qd = d.rolling_rates(&q, [0.0, 0.0, 2.0]);
    let s = map_constrained_accelerations(&d, &q, &qd, 0.0).unwrap();
    let a = 2.0 / 3.0 * G * alpha.sin();
    assert_abs(s.qdd[0], a, 16.0 * EPS * G);
    for k in [1, 2, 3] {
        assert_abs(s.qdd[k], 0.0, 16.0 * EPS * G);
    }
    assert_abs(s.qdd[4], a / d.r, 16.0 * EPS * G / d.r);
    assert_abs(s.lambda[0], d.m * G * alpha.sin() / 3.0, 16.0 * EPS * d.m * G);
    assert_abs(s.lambda[1], 0.0, 16.0 * EPS * d.m * G);
    let run = ConstrainedIntegrator::new(Adaptive::dop853().rtol(1e-12).atol(1e-12))
        .integrate(&MapForm(&d), &q, &qd, 0.0, 1.0)
        .unwrap();
    let last = run.t.len() - 1;
    // the integrator's tolerance 1e-12 on a polynomial motion
    assert_abs(run.q(last)[0], qd[0] + 0.5 * a, 1e-10);
    assert!(run.max_constraint_violation.velocity <= 1e-12);
    // no dense output was asked for
    assert!(matches!(run.sample(0.5), Err(DynamicsError::Ode(vectrix::ode::OdeError::NoDenseOutput))));
}

/// Steady turning of a rolling disk, derived from Euler's equation about the centre in the
/// lean frame L (which turns at Ω k̂ while the motion is steady): with lean θ, heading rate
/// Ω and ω₂ = Ω sin θ + φ̇ the spin about the disk's axis, J = diag(A, C, A) in L,
/// A Ω² sin θ cos θ − (C + mr²) Ω ω₂ cos θ = m g r sin θ. For such a state vectrix gives
/// θ̈ = ψ̈ = φ̈ = 0 and the contact point on a circle (ẍ = −Ωẏ, ÿ = Ωẋ).
#[test]
fn section_9_12_rolling_disk_steady_turn() {
    let d = disk(0.0);
    let (a_j, c_j) = (0.25 * d.m * d.r * d.r, 0.5 * d.m * d.r * d.r);
    for &(lean, omega) in &[(0.3, 2.0), (-0.5, 4.0), (0.1, -7.0), (1.0, 0.8)] {
        let (s, c) = (f64::sin(lean), f64::cos(lean));
        let w2 = (a_j * omega * omega * s * c - d.m * G * d.r * s) / ((c_j + d.m * d.r * d.r) * omega * c);
        let q = [0.2, -0.1, 0.7, lean, 0.4];
        let qd = d.rolling_rates(&q, [omega, 0.0, w2 - omega * s]);
        let sol = map_constrained_accelerations(&d, &q, &qd, 0.0).unwrap();
        let scale = G / d.r + omega * omega + w2 * w2;
        for k in [2, 3, 4] {
            assert_abs(sol.qdd[k], 0.0, 64.0 * EPS * scale);
        }
        assert_abs(sol.qdd[0], -omega * qd[1], 64.0 * EPS * scale * d.r);
        assert_abs(sol.qdd[1], omega * qd[0], 64.0 * EPS * scale * d.r);
    }
}

/// Rolling without slip is workless (Table 1.4): a wobbling, turning disk conserves T + U
/// over 20 s, and the contact point's velocity stays zero (projected, ≤ 1e-9). The
/// multipliers are minus the horizontal contact force, and with that force Newton–Euler
/// ([`RigidBody::accelerations`]) reproduces the angular acceleration, at every sample.
#[test]
fn section_9_12_rolling_disk_energy_and_newton_euler() {
    let d = disk(0.0);
    let q0 = [0.0, 0.0, 0.0, 0.25, 0.0];
    let qd0 = d.rolling_rates(&q0, [1.5, 0.8, 9.0]);
    let run = ConstrainedIntegrator::new(Adaptive::dop853().rtol(1e-11).atol(1e-11))
        .integrate(&MapForm(&d), &q0, &qd0, 0.0, 20.0)
        .unwrap();
    assert!(run.max_constraint_violation.velocity <= 1e-9, "{:?}", run.max_constraint_violation);
    let e0 = d.energy(&q0, &qd0);
    for i in (0..run.t.len()).step_by(25) {
        let (q, qd) = (run.q(i), run.qd(i));
        // local tolerance 1e-11 over ~10³ steps
        assert_abs(d.energy(q, qd), e0, 1e-8 * e0);
        let s = map_constrained_accelerations(&d, q, qd, 0.0).unwrap();
        let (a_c, alpha, omega) = disk_motion(&d, q, qd, s.qdd.as_slice());
        let (f, alpha_ne) = newton_euler(&d, q, qd, &a_c);
        let scale = G + d.r * omega.norm_squared();
        assert_abs(s.lambda[0], -f.x, 1e-13 * d.m * scale);
        assert_abs(s.lambda[1], -f.y, 1e-13 * d.m * scale);
        // the disk stays on the plane: the normal force pushes up
        assert!(f.z > 0.0);
        assert!((alpha - alpha_ne).norm() <= 1e-12 * scale / d.r, "{alpha} vs {alpha_ne}");
    }
    // the disk leans and turns but does not fall in 20 s at this spin
    assert!(run.q(run.t.len() - 1)[3].abs() < 1.0);
}

/// Bad input: all three components of the no-slip condition as rows. The vertical one
/// vanishes identically (the height is already a function of the lean), so its row has no
/// gradient: `SingularConstraint` names row 2.
#[test]
fn section_9_12_rolling_disk_vertical_row_is_singular() {
    let d = RollingDisk { all_rows: true, ..disk(0.0) };
    let q = [0.0, 0.0, 0.3, 0.2, 0.0];
    let qd = d.rolling_rates(&q, [1.0, 0.5, 3.0]);
    let err = map_constrained_accelerations(&d, &q, &qd, 0.0).unwrap_err();
    assert!(matches!(err, DynamicsError::SingularConstraint { row: 2, .. }), "{err}");
}

/// Forward speed along the blade and heading rate of a sleigh state.
fn sleigh_speeds(q: &[f64], qd: &[f64]) -> (f64, f64) {
    (qd[0] * q[2].cos() + qd[1] * q[2].sin(), qd[2])
}

/// The Chaplygin sleigh with its centre of mass over the knife edge (a = 0): no force acts
/// along the blade and no moment about the contact, so the speed v along the blade and the
/// heading rate ω are constant, and the contact point runs on a circle of radius v/ω.
#[test]
fn section_9_12_chaplygin_sleigh_centre_on_the_edge() {
    let s = Sleigh { m: 2.0, i: 0.3, a: 0.0 };
    let (v, w) = (1.5, 0.6);
    let run = ConstrainedIntegrator::new(Adaptive::dop853().rtol(1e-12).atol(1e-12))
        .integrate(&LagrangeForm(&s), &[0.0; 3], &[v, 0.0, w], 0.0, 30.0)
        .unwrap();
    for i in 0..run.t.len() {
        let (q, qd) = (run.q(i), run.qd(i));
        let (vi, wi) = sleigh_speeds(q, qd);
        // constant in exact arithmetic: the integrator's 1e-12 accumulates over ~10² steps
        assert_abs(vi, v, 1e-10);
        assert_abs(wi, w, 1e-10);
        // centre of the circle at (0, v/ω)
        let rho = (q[0] * q[0] + (q[1] - v / w).powi(2)).sqrt();
        assert_abs(rho, v / w, 1e-9);
    }
}

/// The Chaplygin sleigh with its centre a distance a ahead of the edge: with I_P = I + ma²,
/// m v̇ = m a ω² and I_P ω̇ = −m a v ω, so E = ½mv² + ½I_Pω² is conserved and, with
/// v∞ = √(2E/m), k = a m v∞/I_P, u = kt + atanh(v₀/v∞):
/// v = v∞ tanh u, ω = ω₀/|ω₀| √(m/I_P) v∞ sech u, and the heading tends to a straight line,
/// ψ = ψ₀ + ω₀/|ω₀| √(m/I_P)(v∞/k)(gd u − gd u₀) with gd u = 2 atan(tanh(u/2)).
#[test]
fn section_9_12_chaplygin_sleigh_offset_centre_closed_form() {
    let s = Sleigh { m: 2.0, i: 0.3, a: 0.4 };
    let (v0, w0) = (-0.5, 2.0);
    let ip = s.i + s.m * s.a * s.a;
    let e = 0.5 * s.m * v0 * v0 + 0.5 * ip * w0 * w0;
    let v_inf = (2.0 * e / s.m).sqrt();
    let k = s.a * s.m * v_inf / ip;
    let u0 = (v0 / v_inf).atanh();
    let gd = |u: f64| 2.0 * (0.5 * u).tanh().atan();
    let integrator = ConstrainedIntegrator {
        dense: true,
        ..ConstrainedIntegrator::new(Adaptive::dop853().rtol(1e-12).atol(1e-12))
    };
    let run = integrator.integrate(&LagrangeForm(&s), &[0.0; 3], &[v0, 0.0, w0], 0.0, 40.0).unwrap();
    for i in 0..run.t.len() {
        let (t, q, qd) = (run.t[i], run.q(i), run.qd(i));
        let (v, w) = sleigh_speeds(q, qd);
        let u = k * t + u0;
        // local tolerance 1e-12 over ~10³ steps of a smooth solution
        assert_abs(v, v_inf * u.tanh(), 1e-9);
        assert_abs(w, (s.m / ip).sqrt() * v_inf / u.cosh(), 1e-9);
        assert_abs(q[2], (s.m / ip).sqrt() * v_inf / k * (gd(u) - gd(u0)), 1e-9);
        assert_abs(0.5 * s.m * v * v + 0.5 * ip * w * w, e, 1e-10 * e);
    }
    // after 40 s the sleigh runs straight ahead at v∞, centre first
    let (v, w) = sleigh_speeds(run.q(run.t.len() - 1), run.qd(run.t.len() - 1));
    assert!(w.abs() < 1e-6 && (v - v_inf).abs() < 1e-9);
    // between the steps, the dense output (DOP853's 7th-order interpolant)
    for t in [0.37, 3.3, 12.9, 39.99] {
        let y = run.sample(t).unwrap();
        let (v, _) = sleigh_speeds(&y.as_slice()[..3], &y.as_slice()[3..]);
        assert_abs(v, v_inf * (k * t + u0).tanh(), 1e-9);
    }
    assert!(matches!(run.sample(40.5), Err(DynamicsError::Ode(vectrix::ode::OdeError::OutOfRange { .. }))));
}
