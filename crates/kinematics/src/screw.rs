//! Instantaneous screw axis, IVCR (book §4.15) and IACR (book §4.16).
//!
//! All positions are relative to a reference point q fixed in the body, whose velocity
//! v⃗_q = v⃗_{q/O_A/A} and acceleration a⃗_q = a⃗_{q/O_A/A} are given; ω⃗ = ω⃗_{B/A}, α⃗ = α⃗_{B/A}.

use vectrix_tensor::{Dyadic, Scalar, Vector};

use crate::KinematicsError;
use crate::motion::finite_vector;

/// A line {p⃗ + λ d̂}: `point` is r⃗_{p/q} (the point of the line nearest q), `direction` is unit.
#[derive(Debug, Clone, Copy, PartialEq)]
///
/// Book: (4.15.6), §4.16.
pub struct Line<T: Scalar = f64> {
    /// r⃗_{p/q}, the foot of the perpendicular from q.
    pub point: Vector<T>,
    /// Unit direction d̂.
    pub direction: Vector<T>,
}

/// The instantaneous screw axis of a rigid body: the points p with
/// r⃗_{p/q} = ω⃗ × v⃗_q/|ω⃗|² + λω⃗ move along ω⃗ with velocity (pitch)·ω⃗.
///
/// Book: §4.15, §4.17 (Chasles).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScrewAxis<T: Scalar = f64> {
    /// The axis line (relative to q).
    pub axis: Line<T>,
    /// Pitch h = ω⃗·v⃗_q/|ω⃗|² (length per radian); the axis points move with h ω⃗.
    pub pitch: T,
}

/// The instantaneous motion of a rigid body classified by (ω⃗, v⃗_q).
///
/// Book: §4.15, §4.17.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum InstantaneousMotion<T: Scalar = f64> {
    /// ω⃗ = 0⃗ and v⃗_q = 0⃗: every point is at rest.
    Rest,
    /// ω⃗ = 0⃗, v⃗_q ≠ 0⃗: every point moves with the same velocity.
    Translation {
        /// The common velocity.
        velocity: Vector<T>,
    },
    /// ω⃗ ≠ 0⃗: a screw motion about a unique axis.
    Screw(ScrewAxis<T>),
}

/// The instantaneous screw axis from ω⃗ and v⃗_q: axis point r⃗_{p/q} = ω⃗ × v⃗_q/|ω⃗|²,
/// pitch ω⃗·v⃗_q/|ω⃗|² (ω⃗·v⃗_q is the same for every point of the body, (4.15.2)).
///
/// Book: §4.15, (4.15.2), (4.15.6); §4.17.
///
/// # Errors
/// [`KinematicsError::NonFinite`]; [`KinematicsError::Overflow`] when the axis point or pitch
/// exceeds f64::MAX (|ω⃗| subnormal).
pub fn screw_axis<T: Scalar>(
    omega: &Vector<T>,
    v_q: &Vector<T>,
) -> Result<InstantaneousMotion<T>, KinematicsError> {
    finite_vector(omega, "ω")?;
    finite_vector(v_q, "v_q")?;
    let Some(direction) = omega.unit() else {
        // ω = 0: no axis
        return Ok(if v_q.norm_squared() == T::zero() {
            InstantaneousMotion::Rest
        } else {
            InstantaneousMotion::Translation { velocity: *v_q }
        });
    };
    // ω⃗ × v⃗_q/|ω⃗|² = (ω̂ × v⃗_q)/|ω⃗| and ω⃗·v⃗_q/|ω⃗|² = ω̂·v⃗_q/|ω⃗|: no |ω⃗|² overflow or underflow
    let w = omega.norm();
    let point = direction.cross(v_q) / w;
    let pitch = direction.dot(v_q) / w;
    if !(point.is_finite() && pitch.re().is_finite()) {
        return Err(KinematicsError::Overflow { what: "screw axis point or pitch (|ω⃗| tiny)" });
    }
    Ok(InstantaneousMotion::Screw(ScrewAxis { axis: Line { point, direction }, pitch }))
}

/// The instantaneous velocity centre of rotation (IVCR): the line of body points p with
/// v⃗_{p/O_A/A} = 0⃗, solving (|ω⃗|²I − ω⃗ω⃗′) r⃗_{p/q} = ω⃗ × v⃗_q (4.15.6).
///
/// Exists iff ω⃗ ≠ 0⃗ and ω⃗·v⃗_q = 0 (Fact 4.15.3), tested relatively:
/// |ω⃗·v⃗_q| ≤ `rel_tol`·|ω⃗||v⃗_q|.
///
/// Book: §4.15, Fact 4.15.3, (4.15.6).
///
/// # Degenerate inputs
/// `Ok(None)` when ω⃗ = 0⃗ (the book requires ω⃗ ≠ 0⃗) or the pitch is nonzero.
///
/// # Errors
/// [`KinematicsError::NonFinite`].
pub fn ivcr<T: Scalar>(
    omega: &Vector<T>,
    v_q: &Vector<T>,
    rel_tol: f64,
) -> Result<Option<Line<T>>, KinematicsError> {
    vectrix_tensor::check_tolerance(rel_tol, "rel_tol").map_err(vectrix_frames::FrameError::from)?;
    match screw_axis(omega, v_q)? {
        InstantaneousMotion::Screw(s) => {
            let tol = rel_tol * omega.norm().re() * v_q.norm().re();
            Ok((omega.dot(v_q).re().abs() <= tol).then_some(s.axis))
        }
        _ => Ok(None),
    }
}

/// The instantaneous acceleration centre of rotation (IACR): body points p with
/// a⃗_{p/O_A/A} = 0⃗.
///
/// Book: §4.16, Facts 4.16.2–4.16.4.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Iacr<T: Scalar = f64> {
    /// ω⃗ × α⃗ ≠ 0⃗: det(α⃗^× + ω⃗^×ω⃗^×) = −|ω⃗ × α⃗|² ≠ 0, one point r⃗_{p/q}.
    Point(Vector<T>),
    /// ω⃗ ∥ α⃗ (or one of them zero) and the consistency condition holds: a line of points.
    Line(Line<T>),
    /// ω⃗ ∥ α⃗ but the consistency condition fails: no point has zero acceleration.
    None,
    /// ω⃗ = α⃗ = 0⃗: the book defines no IACR (every point has acceleration a⃗_q).
    Undefined,
}

/// The IACR from ω⃗, α⃗ and a⃗_q: solves α⃗ × r⃗ + ω⃗ × (ω⃗ × r⃗) + a⃗_q = 0⃗ (4.16.1).
///
/// Cases (relative tolerance `rel_tol`; ω⃗ counts as zero when |ω⃗|² ≤ tol·|α⃗|, α⃗ when
/// |α⃗| ≤ tol·|ω⃗|², both quantities in rad/s²):
/// * general: unique point, since det M = −|ω⃗ × α⃗|² (notes ch4-5; the book treats only the
///   singular cases);
/// * ω⃗ = 0⃗ (F4.16.2): needs α⃗·a⃗_q = 0, then r⃗ = α⃗ × a⃗_q/|α⃗|² + λα⃗ (corrected (4.16.2));
/// * α⃗ = 0⃗ (F4.16.3): needs ω⃗·a⃗_q = 0, then r⃗ = a⃗_q/|ω⃗|² + λω⃗;
/// * α⃗ ∥ ω⃗ (F4.16.4): needs ω⃗·a⃗_q = 0, then
///   r⃗ = (|ω⃗|² a⃗_q + α⃗ × a⃗_q)/(|ω⃗|⁴ + |α⃗|²) + λω⃗ (the printed denominator is garbled).
///
/// Book: §4.16, (4.16.1), Facts 4.16.2–4.16.4.
///
/// # Errors
/// [`KinematicsError::NonFinite`]; [`KinematicsError::Overflow`] when the centre lies beyond
/// f64::MAX; an invalid tolerance.
pub fn iacr<T: Scalar>(
    omega: &Vector<T>,
    alpha: &Vector<T>,
    a_q: &Vector<T>,
    rel_tol: f64,
) -> Result<Iacr<T>, KinematicsError> {
    let r = iacr_unchecked(omega, alpha, a_q, rel_tol)?;
    // A point or line beyond f64::MAX (|ω|⁴ overflowing for |ω| ≥ 1e77) is a typed error.
    let finite = match &r {
        Iacr::Point(p) => p.is_finite(),
        Iacr::Line(l) => l.point.is_finite() && l.direction.is_finite(),
        _ => true,
    };
    if finite { Ok(r) } else { Err(KinematicsError::Overflow { what: "instantaneous acceleration centre" }) }
}

fn iacr_unchecked<T: Scalar>(
    omega: &Vector<T>,
    alpha: &Vector<T>,
    a_q: &Vector<T>,
    rel_tol: f64,
) -> Result<Iacr<T>, KinematicsError> {
    vectrix_tensor::check_tolerance(rel_tol, "rel_tol").map_err(vectrix_frames::FrameError::from)?;
    finite_vector(omega, "ω")?;
    finite_vector(alpha, "α")?;
    finite_vector(a_q, "a_q")?;
    let (w2, al) = (omega.norm_squared(), alpha.norm());
    let (w2r, alr) = (w2.re(), al.re());
    if w2r == 0.0 && alr == 0.0 {
        return Ok(Iacr::Undefined);
    }
    let wxa = omega.cross(alpha);
    let aq = a_q.norm().re();
    if wxa.norm().re() > rel_tol * w2r.sqrt() * alr {
        // (4.16.1): M r = −a_q with M = α^× + ω^×ω^×, det M = −|ω×α|² ≠ 0
        let m = alpha.cross_dyad() + omega.cross_dyad() * omega.cross_dyad();
        let m_inv = m.inverse(0.0).map_err(|_| KinematicsError::SingularRateMap {
            representation: "IACR",
            detail: "α^× + ω^×ω^× is numerically singular although ω × α ≠ 0".into(),
        })?;
        return Ok(Iacr::Point(-(m_inv * *a_q)));
    }
    let line =
        |point: Vector<T>, dir: &Vector<T>| dir.unit().map(|d| Iacr::Line(Line { point, direction: d }));
    if w2r <= rel_tol * alr {
        // F4.16.2 (ω = 0): α·a_q = 0 needed; (|α|²I − αα′) r = α × a_q
        if alpha.dot(a_q).re().abs() > rel_tol * alr * aq {
            return Ok(Iacr::None);
        }
        return Ok(line(alpha.cross(a_q) / (al * al), alpha).unwrap_or(Iacr::Undefined));
    }
    // F4.16.3 (α = 0) and F4.16.4 (α ∥ ω): ω·a_q = 0 needed
    if omega.dot(a_q).re().abs() > rel_tol * w2r.sqrt() * aq {
        return Ok(Iacr::None);
    }
    let point = (*a_q * w2 + alpha.cross(a_q)) / (w2 * w2 + al * al);
    Ok(line(point, omega).unwrap_or(Iacr::Undefined))
}

/// Acceleration of a body point p: a⃗_p = a⃗_q + α⃗ × r⃗_{p/q} + ω⃗ × (ω⃗ × r⃗_{p/q}) (4.5.3),
/// for checking IACR results.
///
/// Book: (4.5.3), (4.16.1).
pub fn body_point_acceleration<T: Scalar>(
    omega: &Vector<T>,
    alpha: &Vector<T>,
    a_q: &Vector<T>,
    r_p_q: &Vector<T>,
) -> Vector<T> {
    *a_q + alpha.cross(r_p_q) + omega.cross(&omega.cross(r_p_q))
}

/// (|ω⃗|²I⃗ − ω⃗ω⃗′), the coefficient dyad of (4.15.6), exposed for checks.
///
/// Book: (4.15.6).
pub fn ivcr_coefficient<T: Scalar>(omega: &Vector<T>) -> Dyadic<T> {
    Dyadic::identity() * omega.norm_squared() - omega.outer(omega)
}
