//! Rotations and mass properties as the model formats state them: URDF's roll–pitch–yaw,
//! MJCF's quaternions, Euler sequences and axis–angle, rigid bodies merged (a fixed joint),
//! checks of a stated inertia, and the inertias MuJoCo's compiler derives from geoms.
//!
//! Book: §2.10 (orientation), §6.1–6.2 (mass properties, parallel axis (6.2.x)).

use nalgebra::{Matrix3, Rotation3, Unit, UnitQuaternion, Vector3};

/// URDF `rpy`: R = R_z(yaw) R_y(pitch) R_x(roll) (fixed-axis roll, pitch, yaw), whose columns
/// are the child frame's axes in the parent.
///
/// Book: §2.10 (3-2-1 sequence); URDF `<origin rpy>`.
pub(crate) fn rpy(r: [f64; 3]) -> Matrix3<f64> {
    let a = |axis: Vector3<f64>, t: f64| *Rotation3::from_axis_angle(&Unit::new_unchecked(axis), t).matrix();
    a(Vector3::z(), r[2]) * a(Vector3::y(), r[1]) * a(Vector3::x(), r[0])
}

/// The rotation about `axis` by `angle` (active).
pub(crate) fn axis_angle(axis: Vector3<f64>, angle: f64) -> Option<Matrix3<f64>> {
    let n = axis.norm();
    (n > 0.0).then(|| *Rotation3::from_axis_angle(&Unit::new_unchecked(axis / n), angle).matrix())
}

/// The rotation of a quaternion (w, x, y, z), normalized first (as MuJoCo's compiler does).
pub(crate) fn quat(q: [f64; 4]) -> Option<Matrix3<f64>> {
    let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
    (n > 0.0).then(|| {
        let u =
            UnitQuaternion::new_unchecked(nalgebra::Quaternion::new(q[0] / n, q[1] / n, q[2] / n, q[3] / n));
        *u.to_rotation_matrix().matrix()
    })
}

/// The rows of `r` (the scene's `orientation`).
pub(crate) fn rows(r: &Matrix3<f64>) -> [[f64; 3]; 3] {
    [0, 1, 2].map(|i| [r[(i, 0)], r[(i, 1)], r[(i, 2)]])
}

/// A rigid body's mass properties in some frame: m, centre c and J about c.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct MassProps {
    pub m: f64,
    pub c: Vector3<f64>,
    pub j: Matrix3<f64>,
}

impl MassProps {
    pub fn zero() -> Self {
        Self { m: 0.0, c: Vector3::zeros(), j: Matrix3::zeros() }
    }

    /// The same body seen from a frame in which this frame sits at `p` turned by `r` (columns:
    /// this frame's axes): c' = p + R c, J' = R J Rᵀ.
    pub fn moved(&self, r: &Matrix3<f64>, p: &Vector3<f64>) -> Self {
        Self { m: self.m, c: p + r * self.c, j: r * self.j * r.transpose() }
    }

    /// Two bodies as one (parallel-axis theorem about the joint centre).
    ///
    /// Book: (6.2.x) parallel-axis theorem.
    pub fn merged(&self, o: &MassProps) -> Self {
        let m = self.m + o.m;
        if m == 0.0 {
            return Self::zero();
        }
        let c = (self.c * self.m + o.c * o.m) / m;
        let shift = |b: &MassProps| {
            let d = b.c - c;
            (Matrix3::identity() * d.norm_squared() - d * d.transpose()) * b.m
        };
        Self { m, c, j: self.j + o.j + shift(self) + shift(o) }
    }
}

/// A stated inertia is usable: m > 0, J symmetric positive definite and its principal moments
/// obey the triangle inequality (Fact 6.2.7) to a relative 1e-9.
///
/// # Errors
/// What is wrong, and what would be valid.
pub(crate) fn check_stated(m: f64, j: &Matrix3<f64>) -> Result<(), String> {
    if m.is_nan() || m <= 0.0 {
        return Err(format!("mass {m}; valid: a mass > 0 (leave out <inertial> for a massless link)"));
    }
    if !j.iter().all(|x| x.is_finite()) {
        return Err("inertia entries not finite; valid: finite numbers".into());
    }
    let e = j.symmetric_eigen().eigenvalues;
    let (lo, hi) = (e.min(), e.max());
    if !(lo > 1e-12 * hi && hi > 0.0) {
        return Err(format!(
            "inertia with principal moments {:.6e}, {:.6e}, {:.6e} is not positive definite; valid: moments > 0",
            e[0], e[1], e[2]
        ));
    }
    let tri = (0..3).all(|k| e[k] <= e[(k + 1) % 3] + e[(k + 2) % 3] + 1e-9 * hi);
    if !tri {
        return Err(format!(
            "principal moments {:.6e}, {:.6e}, {:.6e} break the triangle inequality (Fact 6.2.7); valid: each at most the sum of the other two",
            e[0], e[1], e[2]
        ));
    }
    Ok(())
}

/// MuJoCo's primitive geoms: volume and the inertia of unit density about the centre, in the
/// geom frame (MuJoCo `user_objects.cc`, `mjCGeom::GetVolume`/`SetInertia`: capsule = cylinder
/// + two hemispheres shifted to their ends).
///
/// Book: §6.2 (shapes); MuJoCo XML reference, `<geom type size>`.
pub(crate) fn geom_unit(kind: &str, size: &[f64]) -> Option<(f64, Vector3<f64>)> {
    use std::f64::consts::PI;
    let s = |k: usize| size.get(k).copied();
    Some(match kind {
        "sphere" => {
            let r = s(0)?;
            let v = 4.0 * PI * r.powi(3) / 3.0;
            (v, Vector3::repeat(v * 2.0 * r * r / 5.0))
        }
        "capsule" => {
            let (r, h) = (s(0)?, 2.0 * s(1)?);
            let sphere = 4.0 * PI * r.powi(3) / 3.0;
            let cyl = PI * r * r * h;
            let lat = cyl * (3.0 * r * r + h * h) / 12.0
                + sphere * (2.0 * r * r / 5.0 + h * h / 4.0 + 3.0 * h * r / 8.0);
            (sphere + cyl, Vector3::new(lat, lat, cyl * r * r / 2.0 + sphere * 2.0 * r * r / 5.0))
        }
        "cylinder" => {
            let (r, h) = (s(0)?, 2.0 * s(1)?);
            let v = PI * r * r * h;
            let lat = v * (3.0 * r * r + h * h) / 12.0;
            (v, Vector3::new(lat, lat, v * r * r / 2.0))
        }
        "ellipsoid" => {
            let (a, b, c) = (s(0)?, s(1)?, s(2)?);
            let v = 4.0 * PI * a * b * c / 3.0;
            (v, Vector3::new(b * b + c * c, a * a + c * c, a * a + b * b) * (v / 5.0))
        }
        "box" => {
            let (a, b, c) = (s(0)?, s(1)?, s(2)?);
            let v = 8.0 * a * b * c;
            (v, Vector3::new(b * b + c * c, a * a + c * c, a * a + b * b) * (v / 3.0))
        }
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rpy_is_yaw_pitch_roll_about_fixed_axes() {
        // a quarter turn of yaw alone sends x̂ to ŷ
        let r = rpy([0.0, 0.0, std::f64::consts::FRAC_PI_2]);
        assert!((r * Vector3::x() - Vector3::y()).norm() < 1e-15);
        // roll then yaw (fixed axes): R = R_z R_x, so ŷ → (x̂ turned by roll is x̂) ẑ then ẑ stays
        let r = rpy([std::f64::consts::FRAC_PI_2, 0.0, std::f64::consts::FRAC_PI_2]);
        assert!((r * Vector3::y() - Vector3::z()).norm() < 1e-15);
    }

    #[test]
    fn merging_two_point_masses_gives_the_parallel_axis_inertia() {
        // two 1 kg points at ±1 on x: J = diag(0, 2, 2) about the middle
        let p = |x: f64| MassProps { m: 1.0, c: Vector3::new(x, 0.0, 0.0), j: Matrix3::zeros() };
        let b = p(1.0).merged(&p(-1.0));
        assert_eq!(b.m, 2.0);
        assert_eq!(b.c, Vector3::zeros());
        assert_eq!(b.j, Matrix3::from_diagonal(&Vector3::new(0.0, 2.0, 2.0)));
    }

    #[test]
    fn a_rod_or_a_nan_inertia_is_refused() {
        assert!(check_stated(1.0, &Matrix3::from_diagonal(&Vector3::new(0.0, 1.0, 1.0))).is_err());
        assert!(check_stated(1.0, &Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, 3.0))).is_err());
        assert!(check_stated(f64::NAN, &Matrix3::identity()).is_err());
        assert!(check_stated(1.0, &(Matrix3::identity() * f64::NAN)).is_err());
        assert!(check_stated(1.0, &Matrix3::identity()).is_ok());
    }
}
