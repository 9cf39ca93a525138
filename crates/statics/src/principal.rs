//! Principal axes and principal moments of inertia (book Fact 6.2.6, Fact 6.2.8).

use vectrix_frames::{Frame, ORTHONORMAL_TOL};
use vectrix_tensor::{Dyadic, Vector};

use crate::basis::vector;
use crate::inertia::analyse;
use crate::{MassProperties, Point, StaticsError};

/// Principal axes of J⃗_{B/z}: the moments λ1 ≥ λ2 ≥ λ3 ≥ 0, a right-handed frame whose
/// axes î, ĵ, k̂ are eigenvectors for λ1, λ2, λ3, the multiplicity of each moment and the rank.
///
/// Book: Fact 6.2.6 (a rotation diagonalises J; use −S when det S = −1), Fact 6.2.7, (6.2.19).
///
/// # Degenerate inputs
/// Repeated moments (sphere, cube, axisymmetric bodies, isotropic cylinder l = √3 r) have a
/// whole eigenspace of principal axes: the frame holds one orthonormal basis of it, and
/// [`PrincipalAxes::eigenspace_projector`] is the unique, basis-free object to compare.
/// Zero moments (thin rod: rank 2; particle at z: rank 0) are returned as exactly 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrincipalAxes {
    /// λ1 ≥ λ2 ≥ λ3 ≥ 0.
    pub moments: [f64; 3],
    /// Right-handed frame of principal axes: î ↔ λ1, ĵ ↔ λ2, k̂ ↔ λ3.
    pub frame: Frame,
    /// `multiplicity[i]` = how many of the moments equal moment i (1, 2 or 3) within tolerance.
    pub multiplicity: [usize; 3],
    /// Rank of J⃗_{B/z}: 0, 2 or 3 (never 1, Fact 6.2.7 iii).
    pub rank: usize,
}

impl PrincipalAxes {
    /// Principal axes of an inertia dyadic (validated first).
    ///
    /// Book: Fact 6.2.6, Fact 6.2.7.
    ///
    /// # Conventions
    /// `rel_tol` (use [`crate::INERTIA_REL_TOL`]) is relative to λ1; moments closer than
    /// rel_tol·λ1 are one repeated moment, moments below it are zero.
    ///
    /// # Errors
    /// As [`crate::check_inertia`].
    pub fn of(j: &Dyadic, rel_tol: f64) -> Result<Self, StaticsError> {
        let (check, s) = analyse(j, rel_tol)?;
        let lam = check.moments;
        let tol = rel_tol * lam[0];
        // Clusters of repeated moments (sorted, so neighbours suffice).
        let same01 = (lam[0] - lam[1]).abs() <= tol;
        let same12 = (lam[1] - lam[2]).abs() <= tol;
        let multiplicity = match (same01, same12) {
            (true, true) => [3, 3, 3],
            (true, false) => [2, 2, 1],
            (false, true) => [1, 2, 2],
            (false, false) => [1, 1, 1],
        };
        // Gram–Schmidt on the eigenvectors, then k̂ = î × ĵ: a proper rotation (Fact 6.2.6 i:
        // −S instead of S when det S = −1 amounts to the same choice of k̂ up to sign).
        let e1 = vector(&s.column(0).into_owned());
        let e2 = vector(&s.column(1).into_owned());
        let i = e1.unit().unwrap_or_else(|| Frame::new().i());
        let j2 = e2 - i * i.dot(&e2);
        let jj = j2.unit().unwrap_or_else(|| any_perpendicular(&i));
        let k = i.cross(&jj);
        let frame = Frame::from_axes(&i, &jj, &k, ORTHONORMAL_TOL)?;
        Ok(Self { moments: lam, frame, multiplicity, rank: check.rank })
    }

    /// The orthogonal projector onto the eigenspace of moment `index` ∈ {0, 1, 2}
    /// (λ1, λ2, λ3): Σ ê ê′ over the principal axes that share that moment. Unique even when
    /// the axes are not. `None` for an index above 2.
    ///
    /// Book: Fact 6.2.6, Problem 6.14.7.
    pub fn eigenspace_projector(&self, index: usize) -> Option<Dyadic> {
        if index > 2 {
            return None;
        }
        let axes = [self.frame.i(), self.frame.j(), self.frame.k()];
        // The cluster of equal moments that contains `index` (moments are sorted).
        let group: &[usize] = match (self.multiplicity, index) {
            ([3, 3, 3], _) => &[0, 1, 2],
            ([2, 2, 1], 0 | 1) => &[0, 1],
            ([1, 2, 2], 1 | 2) => &[1, 2],
            (_, 0) => &[0],
            (_, 1) => &[1],
            _ => &[2],
        };
        Some(group.iter().fold(Dyadic::zero(), |p, &n| p + axes[n].outer(&axes[n])))
    }

    /// min{λ2/λ3, λ1/λ2}, which lies in [1, (1+√5)/2] for a positive-definite inertia
    /// (6.2.20); `None` when λ3 = 0.
    ///
    /// Book: Fact 6.2.8 v, (6.2.20), Problem 6.14.9.
    pub fn golden_ratio_bound(&self) -> Option<f64> {
        let [l1, l2, l3] = self.moments;
        (l3 > 0.0).then(|| (l2 / l3).min(l1 / l2))
    }
}

fn any_perpendicular(i: &Vector) -> Vector {
    let a = Frame::new();
    let trial = if i.dot(&a.i()).abs() < 0.9 { a.i() } else { a.j() };
    (trial - *i * i.dot(&trial)).unit().unwrap_or_else(|| a.k())
}

impl MassProperties<f64> {
    /// Principal axes of J⃗_{B/z} about the point z (use the centre of mass for the central
    /// principal axes).
    ///
    /// Book: Fact 6.2.6.
    ///
    /// # Errors
    /// As [`crate::check_inertia`].
    pub fn principal_axes(&self, z: &Point, rel_tol: f64) -> Result<PrincipalAxes, StaticsError> {
        PrincipalAxes::of(&self.inertia_about(z), rel_tol)
    }
}
