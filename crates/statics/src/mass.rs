//! Mass properties of a body (book §6.1–6.2): mass, centre of mass, inertia about it.

use vectrix_frames::Frame;
use vectrix_tensor::{Dyadic, Rotor, Scalar, Vector};

use crate::inertia::{INERTIA_REL_TOL, check_inertia, parallel_axis, particle_inertia};
use crate::{InertiaCheck, Point, StaticsError};

/// Mass properties of a body B: m_B, its centre of mass c and J⃗_{B/c}, the physical
/// (frame-free) inertia matrix about c.
///
/// Everything else follows: the first moment m_B r⃗_{c/w}, J⃗_{B/z} about any point
/// ([`MassProperties::inertia_about`], (6.2.26)), principal axes
/// ([`MassProperties::principal_axes`]), the spatial inertia ([`MassProperties::spatial_inertia`]).
///
/// Book: §6.1, §6.2, (6.1.1)–(6.1.2), (6.2.1)–(6.2.3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassProperties<T: Scalar = f64> {
    mass: T,
    centre: Point<T>,
    j_c: Dyadic<T>,
}

pub(crate) fn check_mass<T: Scalar>(m: T, what: &'static str) -> Result<T, StaticsError> {
    let v = m.re();
    if !v.is_finite() || v < 0.0 {
        return Err(StaticsError::InvalidMass { what, mass: v });
    }
    Ok(m)
}

pub(crate) fn check_point<T: Scalar>(p: &Point<T>, what: &'static str) -> Result<(), StaticsError> {
    if p.is_finite() { Ok(()) } else { Err(StaticsError::NonFinite { what }) }
}

impl<T: Scalar> MassProperties<T> {
    /// Builds mass properties without validating J⃗_{B/c}: for constructors whose inertia is
    /// physical by construction (particles, shapes, sums).
    pub(crate) fn from_parts_unchecked(mass: T, centre: Point<T>, j_c: Dyadic<T>) -> Self {
        Self { mass, centre, j_c }
    }

    /// A single particle of mass m at y: c = y, J⃗_{B/c} = 0 (Fact 6.2.7 ii).
    ///
    /// Book: §6.1.
    ///
    /// # Errors
    /// [`StaticsError::InvalidMass`] for m < 0 or non-finite, [`StaticsError::ZeroMass`] for
    /// m = 0, [`StaticsError::NonFinite`] for a non-finite position.
    pub fn particle(m: T, at: Point<T>) -> Result<Self, StaticsError> {
        Self::from_particles(&[(m, at)])
    }

    /// A body of particles y_i with masses m_i: m_B = Σm_i (6.1.1),
    /// r⃗_{c/o} = Σm_i r⃗_{y_i/o}/m_B (6.1.2), J⃗_{B/c} = Σm_i(|r⃗_i|²I⃗ − r⃗_i r⃗_i′), r⃗_i = r⃗_{y_i/c}
    /// (6.2.3). Massless inertia points (m_i = 0) are allowed.
    ///
    /// Book: (6.1.1), (6.1.2), (6.2.3).
    ///
    /// # Errors
    /// [`StaticsError::InvalidMass`] for a negative or non-finite mass,
    /// [`StaticsError::NonFinite`] for a non-finite position, [`StaticsError::ZeroMass`] when
    /// the total mass is zero (no centre of mass), [`StaticsError::Overflow`] when the total
    /// mass Σmᵢ, the centre of mass or the inertia J⃗_{B/c} exceeds the largest finite f64
    /// (≈ 1.8e308; finite masses may sum past it).
    pub fn from_particles(particles: &[(T, Point<T>)]) -> Result<Self, StaticsError> {
        let mut m_b = T::zero();
        let mut first = Vector::zero();
        for (m, y) in particles {
            check_mass(*m, "particle")?;
            check_point(y, "particle position")?;
            m_b += *m;
            first += y.position() * *m;
        }
        // (6.1.1): m_B = Σ m_i, finite masses whose sum may overflow (issue 33)
        if !m_b.re().is_finite() {
            return Err(StaticsError::Overflow { what: "total mass Σmᵢ of the particles" });
        }
        if m_b.re() <= 0.0 {
            return Err(StaticsError::ZeroMass { what: "body of particles" });
        }
        // (6.1.2): r_{c/o} = Σ m_i r_{y_i/o} / m_B; where the first moment overflows although
        // the centre is finite (m = 1e300 at 1e10), the same sum with the weights m_i/m_B ≤ 1
        let mut r_c_o = first / m_b;
        if !r_c_o.is_finite() {
            r_c_o = particles.iter().fold(Vector::zero(), |s, (m, y)| s + y.position() * (*m / m_b));
        }
        if !r_c_o.is_finite() {
            return Err(StaticsError::Overflow { what: "centre of mass of the particles" });
        }
        let c = Point::at(r_c_o);
        // (6.2.3): J_{B/c} = Σ m_i (|r|² I − r r′), r = r_{y_i/c}
        let j_c =
            particles.iter().fold(Dyadic::zero(), |j, (m, y)| j + particle_inertia(*m, &y.position_rel(&c)));
        if !j_c.is_finite() {
            return Err(StaticsError::Overflow {
                what: "inertia of the particles about their centre of mass",
            });
        }
        Ok(Self { mass: m_b, centre: c, j_c })
    }

    /// User-given mass properties: mass m_B > 0, centre c and J⃗_{B/c}, validated as in
    /// [`check_inertia`] (symmetric, PSD, rank ≠ 1, λ1 ≤ λ2 + λ3) with [`INERTIA_REL_TOL`].
    ///
    /// Book: §6.2, Fact 6.2.7, Fact 6.2.8.
    ///
    /// # Errors
    /// Mass errors as [`MassProperties::from_particles`]; inertia errors as [`check_inertia`].
    pub fn new(mass: T, centre: Point<T>, j_c: Dyadic<T>) -> Result<Self, StaticsError> {
        check_mass(mass, "body")?;
        if mass.re() == 0.0 {
            return Err(StaticsError::ZeroMass { what: "body" });
        }
        check_point(&centre, "centre of mass")?;
        check_inertia(&j_c, INERTIA_REL_TOL)?;
        Ok(Self { mass, centre, j_c: j_c.symmetric_part() })
    }

    /// User-given inertia J⃗_{B/z} about a point z other than c: J⃗_{B/c} is recovered by the
    /// parallel-axis theorem (6.2.26) and validated.
    ///
    /// Book: (6.2.26).
    ///
    /// # Errors
    /// As [`MassProperties::new`], after the shift to c.
    pub fn with_inertia_about(
        mass: T,
        centre: Point<T>,
        z: &Point<T>,
        j_z: Dyadic<T>,
    ) -> Result<Self, StaticsError> {
        check_mass(mass, "body")?;
        // (6.2.26) solved for J_{B/c}: J_c = J_z − m(|r|²I − rr′), r = r_{z/c}
        let j_c = j_z - particle_inertia(mass, &z.position_rel(&centre));
        Self::new(mass, centre, j_c)
    }

    /// m_B (6.1.1).
    ///
    /// Book: §6.1–6.2, (6.1.1)–(6.1.2).
    #[inline]
    pub fn mass(&self) -> T {
        self.mass
    }

    /// The centre of mass c (6.1.2).
    ///
    /// Book: §6.1–6.2, (6.1.1)–(6.1.2).
    #[inline]
    pub fn centre_of_mass(&self) -> Point<T> {
        self.centre
    }

    /// The first moment of mass relative to w: m_B r⃗_{c/w} = Σ m_i r⃗_{y_i/w} (6.1.2).
    ///
    /// Book: §6.1–6.2, (6.1.1)–(6.1.2).
    #[inline]
    pub fn first_moment_about(&self, w: &Point<T>) -> Vector<T> {
        self.centre.position_rel(w) * self.mass
    }

    /// J⃗_{B/c}: the physical inertia matrix about the centre of mass.
    ///
    /// Book: §6.1–6.2, (6.1.1)–(6.1.2).
    #[inline]
    pub fn inertia_about_centre(&self) -> Dyadic<T> {
        self.j_c
    }

    /// J⃗_{B/z} about any point z, by the parallel-axis theorem
    /// J⃗_{B/z} = J⃗_{B/c} + m_B(|r⃗_{z/c}|²I⃗ − r⃗_{z/c}r⃗′_{z/c}).
    ///
    /// Book: Fact 6.2.12, (6.2.26).
    #[inline]
    pub fn inertia_about(&self, z: &Point<T>) -> Dyadic<T> {
        parallel_axis(&self.j_c, self.mass, &z.position_rel(&self.centre))
    }

    /// The union of two bodies: m = m₁ + m₂, c on the segment c₁c₂ (Problem 6.14.3),
    /// J⃗_{B₃/c} = J⃗_{B₁/c} + J⃗_{B₂/c} (6.2.23).
    ///
    /// Book: Fact 6.2.9, (6.2.23).
    pub fn combine(&self, other: &MassProperties<T>) -> MassProperties<T> {
        let m = self.mass + other.mass;
        // Problem 6.14.3: c = (m1 c1 + m2 c2)/(m1 + m2), measured from c1 to limit cancellation.
        let r_c2_c1 = other.centre.position_rel(&self.centre);
        let c = self.centre.displaced(r_c2_c1 * (other.mass / m));
        // (6.2.23), both about the new c
        let j = self.inertia_about(&c) + other.inertia_about(&c);
        MassProperties { mass: m, centre: c, j_c: j.symmetric_part() }
    }

    /// The union of many bodies (6.2.23). `None` for an empty list.
    ///
    /// Book: Fact 6.2.9, (6.2.23).
    pub fn composite(parts: &[MassProperties<T>]) -> Option<MassProperties<T>> {
        let (first, rest) = parts.split_first()?;
        Some(rest.iter().fold(*first, |acc, p| acc.combine(p)))
    }

    /// The body with the part `removed` taken out (a hole or cavity):
    /// m₃ = m₂ − m₁, m₃c₃ = m₂c₂ − m₁c₁, J⃗_{B₃/z} = J⃗_{B₂/z} − J⃗_{B₁/z} (6.2.24).
    ///
    /// Book: Fact 6.2.10, (6.2.24).
    ///
    /// # Errors
    /// [`StaticsError::RemovalExceedsMass`] unless m₁ < m₂; inertia errors (as
    /// [`check_inertia`]) when the part was not contained in the body and the result is not
    /// physical.
    pub fn remove(&self, removed: &MassProperties<T>) -> Result<MassProperties<T>, StaticsError> {
        let m = self.mass - removed.mass;
        if m.re() <= 0.0 {
            return Err(StaticsError::RemovalExceedsMass {
                mass: self.mass.re(),
                removed: removed.mass.re(),
            });
        }
        // m3 c3 = m2 c2 − m1 c1, measured from c2
        let r_c1_c2 = removed.centre.position_rel(&self.centre);
        let c = self.centre.displaced(r_c1_c2 * (-removed.mass / m));
        // (6.2.24) about the new c
        let j = (self.inertia_about(&c) - removed.inertia_about(&c)).symmetric_part();
        check_inertia(&j, INERTIA_REL_TOL)?;
        Ok(MassProperties { mass: m, centre: c, j_c: j })
    }

    /// The body translated by d⃗ (inertia about c unchanged).
    ///
    /// Book: §6.1–6.2, (6.1.1)–(6.1.2).
    ///
    /// # Errors
    /// [`StaticsError::NonFinite`] for a NaN or ∞ component of d⃗;
    /// [`StaticsError::Overflow`] when the displaced centre leaves the finite numbers.
    pub fn translated(&self, d: Vector<T>) -> Result<MassProperties<T>, StaticsError> {
        if !d.is_finite() {
            return Err(StaticsError::NonFinite { what: "translation d⃗" });
        }
        let centre = self.centre.displaced(d);
        check_point(&centre, "translated centre")
            .map_err(|_| StaticsError::Overflow { what: "translated centre" })?;
        Ok(MassProperties { centre, ..*self })
    }

    /// The body rotated by the rotor R about the pivot z: c′ = z + R r⃗_{c/z},
    /// J⃗_{B′/c′} = R⃗ J⃗_{B/c} R⃗′ (6.2.11).
    ///
    /// Book: Fact 6.2.4, (6.2.11), (6.2.13).
    pub fn rotated_by_rotor(&self, r: &Rotor<T>, pivot: &Point<T>) -> MassProperties<T> {
        self.rotated_unchecked(&r.to_dyadic(), pivot)
    }

    /// The body rotated by the physical rotation R⃗ (a proper orthogonal dyadic) about z,
    /// as [`MassProperties::rotated_by_rotor`] (6.2.11).
    ///
    /// Book: Fact 6.2.4, (6.2.11).
    ///
    /// # Errors
    /// [`StaticsError::Frame`] when R⃗ is not a rotation within `tol` (use
    /// [`vectrix_frames::ORTHONORMAL_TOL`]).
    pub fn rotated_by(
        &self,
        r: &Dyadic<T>,
        pivot: &Point<T>,
        tol: f64,
    ) -> Result<MassProperties<T>, StaticsError> {
        // Frame::rotated_by checks R⃗ is orthonormal and right-handed.
        Frame::<T>::identity().rotated_by(r, tol)?;
        Ok(self.rotated_unchecked(r, pivot))
    }

    fn rotated_unchecked(&self, r: &Dyadic<T>, pivot: &Point<T>) -> MassProperties<T> {
        let c = pivot.displaced(r.apply(&self.centre.position_rel(pivot)));
        // (6.2.11): J′ = R J R′
        let j = (*r * self.j_c * r.coform()).symmetric_part();
        MassProperties { mass: self.mass, centre: c, j_c: j }
    }

    /// Validates J⃗_{B/c} (Fact 6.2.7, Fact 6.2.8) and reports its principal moments and rank.
    ///
    /// Book: Fact 6.2.7, (6.2.19).
    ///
    /// # Errors
    /// As [`check_inertia`].
    pub fn check(&self, rel_tol: f64) -> Result<InertiaCheck, StaticsError> {
        check_inertia(&self.j_c, rel_tol)
    }
}
