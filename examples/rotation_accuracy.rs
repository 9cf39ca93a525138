//! Accuracy of every rotation conversion over the hard sets, vectrix beside nalgebra.
//!
//! Run: `cargo run --release --example rotation_accuracy`.
//!
//! Hard sets (DESIGN §6): θ ∈ {0, 1e-300, 1e-16, 1e-8, 1e-4, π−1e-4, π−1e-8, π−1e-12, π} about
//! four axes (a coordinate axis, (1,2,2)/3, a skewed axis, an axis with a 1e-9 component), and
//! 3-2-1 Euler angles with the pitch at ±π/2 ± 10⁻ᵏ (k = 2..16). Each library gets the same
//! input; the output is compared with the value known from (n̂, θ). Errors are absolute, in
//! units of ε = 2.2e-16 (angle vectors relative to max(θ, 1)); quaternions up to sign.

use std::f64::consts::{FRAC_PI_2, PI};

use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};
use vectrix::prelude::*;

const EPS: f64 = f64::EPSILON;
const HARD: [f64; 9] = [0.0, 1e-300, 1e-16, 1e-8, 1e-4, PI - 1e-4, PI - 1e-8, PI - 1e-12, PI];

fn axes() -> [Vector3<f64>; 4] {
    [
        Vector3::x(),
        Vector3::new(1.0, 2.0, 2.0) / 3.0,
        Vector3::new(-0.3, 0.1, 0.95).normalize(),
        Vector3::new(0.0, -1.0, 1e-9).normalize(),
    ]
}

/// max |p − q| up to sign.
fn q_err(p: [f64; 4], q: [f64; 4]) -> f64 {
    let d = (0..4).map(|i| (p[i] - q[i]).abs()).fold(0.0, f64::max);
    let s = (0..4).map(|i| (p[i] + q[i]).abs()).fold(0.0, f64::max);
    d.min(s)
}

fn na4(q: &UnitQuaternion<f64>) -> [f64; 4] {
    [q.w, q.i, q.j, q.k]
}

fn vx4(q: &Quaternion) -> [f64; 4] {
    [q.a, q.b, q.c, q.d]
}

/// Rodrigues (2.11.1) from the exact (n̂, θ): the reference matrix.
fn rodrigues(n: &Vector3<f64>, th: f64) -> Matrix3<f64> {
    // (1 − cos θ) = 2 sin²(θ/2) keeps tiny angles exact.
    let h = (th / 2.0).sin();
    Matrix3::identity() * th.cos() + n * n.transpose() * (2.0 * h * h) + n.cross_matrix() * th.sin()
}

/// Worst error of each library for one conversion, as a table row.
struct Row {
    name: &'static str,
    vectrix: f64,
    nalgebra: Option<f64>,
    note: &'static str,
}

fn fmt(e: f64) -> String {
    if e.is_nan() {
        "NaN".into()
    } else if e / EPS < 1e4 {
        format!("{:.1} ε", e / EPS)
    } else {
        format!("{e:.1e}")
    }
}

/// One conversion's error on (n̂, θ): (vectrix, nalgebra if it has one).
type Case<'a> = &'a dyn Fn(&Vector3<f64>, f64) -> (f64, Option<f64>);

fn main() {
    let mut rows = Vec::new();
    let mut worst = |name, note, f: Case| {
        let (mut v, mut n, mut has_n) = (0.0f64, 0.0f64, false);
        for ax in axes() {
            for &th in &HARD {
                let (ev, en) = f(&ax, th);
                v = if ev.is_nan() { f64::NAN } else { v.max(ev) };
                if let Some(en) = en {
                    has_n = true;
                    n = if en.is_nan() || n.is_nan() { f64::NAN } else { n.max(en) };
                }
            }
        }
        rows.push(Row { name, vectrix: v, nalgebra: has_n.then_some(n), note });
    };
    let truth_q = |n: &Vector3<f64>, th: f64| {
        let (s, c) = (th / 2.0).sin_cos();
        [c, s * n.x, s * n.y, s * n.z]
    };
    let input_m = |n: &Vector3<f64>, th: f64| rodrigues(n, th);

    worst("matrix → quaternion", "nalgebra: UnitQuaternion::from_rotation_matrix", &|n, th| {
        let m = input_m(n, th);
        let v = Quaternion::from_rotation_matrix(&m, ROTATION_TOL).expect("rotation");
        let na = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(m));
        (q_err(vx4(&v), truth_q(n, th)), Some(q_err(na4(&na), truth_q(n, th))))
    });
    worst(
        "matrix → quaternion (iterative)",
        "nalgebra: Rotation3::from_matrix (nalgebra#1078)",
        &|n, th| {
            let m = input_m(n, th);
            let v = Quaternion::from_rotation_matrix(&m, ROTATION_TOL).expect("rotation");
            let na = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix(&m));
            (q_err(vx4(&v), truth_q(n, th)), Some(q_err(na4(&na), truth_q(n, th))))
        },
    );
    worst("quaternion → matrix", "nalgebra: to_rotation_matrix", &|n, th| {
        let q = truth_q(n, th);
        let want = rodrigues(n, th);
        let v = Quaternion::new(q[0], q[1], q[2], q[3]).rotation_matrix();
        let na = UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(q[0], q[1], q[2], q[3]))
            .to_rotation_matrix();
        ((v - want).amax(), Some((na.matrix() - want).amax()))
    });
    worst("quaternion → angle vector", "nalgebra: UnitQuaternion::scaled_axis", &|n, th| {
        let q = truth_q(n, th);
        let want = n * th;
        let v = Quaternion::new(q[0], q[1], q[2], q[3]).angle_vector();
        let na =
            UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(q[0], q[1], q[2], q[3])).scaled_axis();
        // At θ = π both ±πn̂ are correct: compare with the nearer one.
        let e =
            |x: Vector3<f64>| (x - want).amax().min(if th == PI { (x + want).amax() } else { f64::INFINITY });
        (e(v) / th.max(1.0), Some(e(na) / th.max(1.0)))
    });
    worst("matrix → angle vector", "nalgebra: Rotation3::scaled_axis", &|n, th| {
        let m = input_m(n, th);
        let want = n * th;
        let v = Quaternion::angle_vector_of_rotation_matrix(&m);
        let na = Rotation3::from_matrix_unchecked(m).scaled_axis();
        let e =
            |x: Vector3<f64>| (x - want).amax().min(if th == PI { (x + want).amax() } else { f64::INFINITY });
        (e(v) / th.max(1.0), Some(e(na) / th.max(1.0)))
    });
    worst("angle vector → quaternion", "nalgebra: UnitQuaternion::from_scaled_axis", &|n, th| {
        let v = Quaternion::from_angle_vector(&(n * th));
        let na = UnitQuaternion::from_scaled_axis(n * th);
        (q_err(vx4(&v), truth_q(n, th)), Some(q_err(na4(&na), truth_q(n, th))))
    });
    worst("angle vector → matrix", "nalgebra: Rotation3::from_scaled_axis", &|n, th| {
        let want = rodrigues(n, th);
        let v = Quaternion::from_angle_vector(&(n * th)).rotation_matrix();
        let na = Rotation3::from_scaled_axis(n * th);
        ((v - want).amax(), Some((na.matrix() - want).amax()))
    });
    worst("quaternion → eigenangle θ", "nalgebra: UnitQuaternion::angle", &|n, th| {
        let q = truth_q(n, th);
        let v = Quaternion::new(q[0], q[1], q[2], q[3]).axis_angle().angle();
        let na = UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(q[0], q[1], q[2], q[3])).angle();
        ((v - th).abs() / th.max(1e-300), Some((na - th).abs() / th.max(1e-300)))
    });
    worst("matrix → eigenangle θ (relative)", "nalgebra: Rotation3::angle (acos)", &|n, th| {
        let m = input_m(n, th);
        let v = Rotation::from_rotation_matrix_in(&Frame::new(), &m, ROTATION_TOL).expect("rotation").angle();
        let na = Rotation3::from_matrix_unchecked(m).angle();
        ((v - th).abs() / th.max(1e-300), Some((na - th).abs() / th.max(1e-300)))
    });
    worst("quaternion → Gibbs → quaternion", "no nalgebra equivalent", &|n, th| {
        let q = Quaternion::from_axis_angle(n, th).expect("axis");
        let e = q.gibbs().map_or(0.0, |g| q_err(vx4(&Quaternion::from_gibbs(&g)), vx4(&q)));
        (e, None)
    });
    worst("quaternion → MRP → quaternion", "no nalgebra equivalent", &|n, th| {
        let q = Quaternion::from_axis_angle(n, th).expect("axis");
        (q_err(vx4(&Quaternion::from_mrp(&q.mrp())), vx4(&q)), None)
    });
    worst(
        "quaternion → Euler (24 sequences) → quaternion",
        "nalgebra: 3-2-1 only (euler_angles)",
        &|n, th| {
            let q = Quaternion::from_axis_angle(n, th).expect("axis");
            let mut e = 0.0f64;
            for s in EulerSequence::ALL.into_iter().flat_map(|s| [s, s.extrinsic()]) {
                let p = EulerAngles::from_quaternion(&q, s).principal();
                e = e.max(q_err(vx4(&p.quaternion()), vx4(&q)));
            }
            let uq = q.to_unit_quaternion();
            let (r, p, y) = uq.euler_angles();
            (e, Some(q_err(na4(&UnitQuaternion::from_euler_angles(r, p, y)), vx4(&q))))
        },
    );
    // The batched (SIMD) conversions on the whole hard set in one call each.
    {
        let cases: Vec<(Vector3<f64>, f64)> =
            axes().into_iter().flat_map(|n| HARD.iter().map(move |&th| (n, th))).collect();
        let thetas: Vec<Vector3<f64>> = cases.iter().map(|(n, th)| n * *th).collect();
        let qs = Quaternion::from_angle_vectors(&thetas).expect("finite");
        let v = cases.iter().zip(&qs).map(|((n, th), q)| q_err(vx4(q), truth_q(n, *th))).fold(0.0, f64::max);
        let na = cases
            .iter()
            .map(|(n, th)| q_err(na4(&UnitQuaternion::from_scaled_axis(n * *th)), truth_q(n, *th)))
            .fold(0.0, f64::max);
        rows.push(Row {
            name: "angle vector → quaternion, batched",
            vectrix: v,
            nalgebra: Some(na),
            note: "`Quaternion::from_angle_vectors`; nalgebra one by one (no batch call)",
        });
        let unit: Vec<Quaternion> =
            cases.iter().map(|(n, th)| Quaternion::from_axis_angle(n, *th).expect("axis")).collect();
        let mut e = 0.0f64;
        for s in EulerSequence::ALL.into_iter().flat_map(|s| [s, s.extrinsic()]) {
            let batch = EulerAngles::from_quaternions(&unit, s).expect("unit");
            for (i, q) in unit.iter().enumerate() {
                let p = batch.principal(i).expect("in range");
                e = e.max(q_err(vx4(&p.quaternion()), vx4(q)));
            }
        }
        rows.push(Row {
            name: "quaternion → Euler (24 sequences) → quaternion, batched",
            vectrix: e,
            nalgebra: None,
            note: "`EulerAngles::from_quaternions`; no nalgebra batch",
        });
    }
    // Gimbal lock: 3-2-1 with the pitch at ±π/2 ± 10⁻ᵏ.
    let (mut v_mid, mut n_mid, mut v_reb, mut n_reb) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    let (mut b_mid, mut b_reb, mut q_reb, mut nq_reb) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for lock in [FRAC_PI_2, -FRAC_PI_2] {
        for k in 2..=16 {
            for side in [-1.0, 1.0] {
                let pitch = lock + side * 10f64.powi(-k);
                let e = EulerAngles::new(EulerSequence::S321, [0.7, pitch, -2.3]);
                let m = e.rotation_matrix();
                let want = if pitch.abs() > FRAC_PI_2 { PI.copysign(pitch) - pitch } else { pitch };
                let p = EulerAngles::from_rotation_matrix(&m, EulerSequence::S321, ROTATION_TOL)
                    .expect("rotation")
                    .principal();
                v_mid = v_mid.max((p.angles[1] - want).abs());
                let q = e.quaternion();
                let one = EulerAngles::from_quaternion(&q, EulerSequence::S321).principal();
                q_reb = q_reb.max((one.rotation_matrix() - m).amax());
                let (r, pi, y) = q.to_unit_quaternion().euler_angles();
                nq_reb = nq_reb.max((Rotation3::from_euler_angles(r, pi, y).matrix() - m).amax());
                let b = EulerAngles::from_quaternions(&[q], EulerSequence::S321).expect("unit");
                let pb = b.principal(0).expect("one");
                b_mid = b_mid.max((pb.angles[1] - want).abs());
                b_reb = b_reb.max((pb.rotation_matrix() - m).amax());
                v_reb = v_reb.max((p.rotation_matrix() - m).amax());
                let (r, pi, y) = Rotation3::from_matrix_unchecked(m).euler_angles();
                n_mid = n_mid.max((pi - want).abs());
                n_reb = n_reb.max((Rotation3::from_euler_angles(r, pi, y).matrix() - m).amax());
            }
        }
    }
    rows.push(Row {
        name: "matrix → 3-2-1 pitch, ±π/2 ± 1e-k",
        vectrix: v_mid,
        nalgebra: Some(n_mid),
        note: "nalgebra: Rotation3::euler_angles (asin)",
    });
    rows.push(Row {
        name: "matrix → 3-2-1 → matrix, ±π/2 ± 1e-k",
        vectrix: v_reb,
        nalgebra: Some(n_reb),
        note: "rebuild error",
    });

    rows.push(Row {
        name: "quaternion → 3-2-1 → matrix, ±π/2 ± 1e-k",
        vectrix: q_reb,
        nalgebra: Some(nq_reb),
        note: "rebuild error; nalgebra: UnitQuaternion::euler_angles",
    });
    rows.push(Row {
        name: "quaternion → 3-2-1 pitch, ±π/2 ± 1e-k, batched",
        vectrix: b_mid,
        nalgebra: None,
        note: "`EulerAngles::from_quaternions`",
    });
    rows.push(Row {
        name: "quaternion → 3-2-1 → matrix, ±π/2 ± 1e-k, batched",
        vectrix: b_reb,
        nalgebra: None,
        note: "rebuild error",
    });

    println!("| conversion | vectrix worst | nalgebra worst | peer call |");
    println!("|---|---|---|---|");
    for r in rows {
        let na = r.nalgebra.map_or("—".to_string(), fmt);
        println!("| {} | {} | {} | {} |", r.name, fmt(r.vectrix), na, r.note);
    }
}
