//! Mass properties of the shapes a scene declares.
//!
//! Book: §6.1–6.2 (inertia of shapes), §6.4 (a body's principal moments).

use nalgebra::{Matrix3, Vector3};

use super::parts::v3;
use super::spec::MassSpec;

/// Mass m and J_{B/c} (link components) of a mass spec; on error the offending key and why.
///
/// Book: §6.1–6.2 (inertia of shapes); an inertia matrix must be symmetric and positive
/// semidefinite with principal moments obeying the triangle inequality J₁ ≤ J₂ + J₃ (§6.4).
pub(crate) fn mass_props(m: &MassSpec) -> Result<(f64, Matrix3<f64>), (&'static str, String)> {
    let pos = |x: f64, what: &'static str| {
        if x > 0.0 && x.is_finite() {
            Ok(x)
        } else {
            Err((what, format!("{what} = {x}; valid: a finite number > 0")))
        }
    };
    let (mass, j) = match m {
        MassSpec::Particle { mass } => (pos(*mass, "mass")?, Matrix3::zeros()),
        MassSpec::Massless {} => (0.0, Matrix3::zeros()),
        MassSpec::Sphere { mass, radius } => {
            let (m, r) = (pos(*mass, "mass")?, pos(*radius, "radius")?);
            (m, Matrix3::identity() * (0.4 * m * r * r))
        }
        MassSpec::Box { mass, sides } => {
            let m = pos(*mass, "mass")?;
            let [a, b, c] = [pos(sides[0], "sides")?, pos(sides[1], "sides")?, pos(sides[2], "sides")?];
            let d = Vector3::new(b * b + c * c, a * a + c * c, a * a + b * b) * (m / 12.0);
            (m, Matrix3::from_diagonal(&d))
        }
        MassSpec::Rod { mass, length } => {
            let (m, l) = (pos(*mass, "mass")?, pos(*length, "length")?);
            (m, Matrix3::from_diagonal(&Vector3::new(0.0, m * l * l / 12.0, m * l * l / 12.0)))
        }
        MassSpec::Cylinder { mass, radius, length } => {
            let (m, r, h) = (pos(*mass, "mass")?, pos(*radius, "radius")?, pos(*length, "length")?);
            let jt = m * (3.0 * r * r + h * h) / 12.0;
            (m, Matrix3::from_diagonal(&Vector3::new(jt, jt, m * r * r / 2.0)))
        }
        MassSpec::Disk { mass, radius } => {
            let (m, r) = (pos(*mass, "mass")?, pos(*radius, "radius")?);
            (m, Matrix3::from_diagonal(&Vector3::new(m * r * r / 4.0, m * r * r / 4.0, m * r * r / 2.0)))
        }
        MassSpec::Aircraft { model } => {
            let ac = super::aero::catalogue(model).ok_or(("model", super::aero::unknown_aircraft(model)))?;
            (ac.airframe.mass(), ac.airframe.inertia_matrix())
        }
        MassSpec::Value { mass, principal, matrix } => {
            let m = pos(*mass, "mass")?;
            let (key, j) = match (principal, matrix) {
                (Some(p), None) => ("principal", Matrix3::from_diagonal(&v3(*p))),
                (None, Some(r)) => ("matrix", Matrix3::from_fn(|i, j| r[i][j])),
                _ => return Err(("mass", "give exactly one of `principal` or `matrix`".into())),
            };
            check_inertia(&j).map_err(|msg| (key, msg))?;
            (m, j)
        }
    };
    if !j.iter().all(|x| x.is_finite()) {
        return Err((
            "mass",
            "the inertia overflows; valid: mass and size whose product m·l² is finite".into(),
        ));
    }
    Ok((mass, j))
}

/// A given inertia matrix must be symmetric and positive semidefinite with principal moments
/// obeying the triangle inequality (a physical body, §6.4).
fn check_inertia(j: &Matrix3<f64>) -> Result<(), String> {
    let scale = j.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let tol = 64.0 * f64::EPSILON * scale;
    if (j - j.transpose()).iter().any(|x| x.abs() > tol) {
        return Err("the inertia matrix is not symmetric; valid: rows of a symmetric matrix".into());
    }
    let mut p: Vec<f64> = j.symmetric_eigenvalues().iter().copied().collect();
    p.sort_by(f64::total_cmp);
    if p[0] < -tol || p[2] > p[0] + p[1] + tol {
        return Err(format!(
            "principal moments {:?} are not those of a body; valid: each ≥ 0 and the largest ≤ the sum of the \
             other two (§6.4)",
            p
        ));
    }
    Ok(())
}
