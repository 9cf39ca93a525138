//! Homogeneous shapes (book §6.3, Examples 6.3.2–6.3.4, Problems 6.14.8–6.14.12).
//!
//! Each constructor takes the mass, the dimensions, where the centre of mass is, and the
//! shape's orientation as frame-free data: a `Frame` whose axes are the shape's edges, or a
//! symmetry axis as a `Vector` for axisymmetric shapes.

use vectrix_frames::Frame;
use vectrix_tensor::{Dyadic, Scalar, Vector};

use crate::mass::{check_mass, check_point};
use crate::{MassProperties, Point, StaticsError};

fn check_len<T: Scalar>(x: T, what: &'static str) -> Result<T, StaticsError> {
    let v = x.re();
    if !v.is_finite() || v < 0.0 {
        return Err(StaticsError::OutOfRange { what, value: v, valid: "a finite length ≥ 0" });
    }
    Ok(x)
}

impl<T: Scalar> MassProperties<T> {
    /// A shape's mass properties, with [`StaticsError::Overflow`] when its inertia (m r² for
    /// a radius near 1e154 and up) exceeds the largest finite number.
    fn shape(m: T, centre: Point<T>, j: Dyadic<T>) -> Result<Self, StaticsError> {
        if !j.is_finite() {
            return Err(StaticsError::Overflow { what: "shape inertia" });
        }
        Ok(Self::from_parts_unchecked(m, centre, j))
    }
}

fn check_body<T: Scalar>(m: T, c: &Point<T>) -> Result<(), StaticsError> {
    check_mass(m, "shape")?;
    if m.re() == 0.0 {
        return Err(StaticsError::ZeroMass { what: "shape" });
    }
    check_point(c, "shape centre")
}

/// α â â′ + β (I⃗ − â â′): the inertia of a body symmetric about the axis â.
fn axisymmetric<T: Scalar>(axis: &Vector<T>, axial: T, transverse: T) -> Result<Dyadic<T>, StaticsError> {
    if !axis.is_finite() {
        return Err(StaticsError::NonFinite { what: "symmetry axis" });
    }
    let a = axis.unit().ok_or(StaticsError::ZeroVector { what: "symmetry axis" })?;
    let p = a.outer(&a);
    Ok(p * axial + (Dyadic::identity() - p) * transverse)
}

impl<T: Scalar> MassProperties<T> {
    /// Homogeneous solid sphere of radius r: J⃗_{B/c} = (2/5) m r² I⃗.
    ///
    /// Book: Example 6.3.2, (6.3.13).
    ///
    /// # Errors
    /// [`StaticsError::InvalidMass`], [`StaticsError::ZeroMass`], [`StaticsError::OutOfRange`]
    /// for a negative or non-finite radius, [`StaticsError::NonFinite`] for the centre.
    pub fn solid_sphere(m: T, radius: T, centre: Point<T>) -> Result<Self, StaticsError> {
        check_body(m, &centre)?;
        let r = check_len(radius, "sphere radius")?;
        let j = Dyadic::identity() * (T::lit(0.4) * m * r * r);
        Self::shape(m, centre, j)
    }

    /// Homogeneous spherical shell with outer radius R and inner radius r ≤ R:
    /// J⃗_{B/c} = 2m(R⁵ − r⁵)/(5(R³ − r³)) I⃗, evaluated as
    /// (2m/5)(R⁴ + R³r + R²r² + Rr³ + r⁴)/(R² + Rr + r²), which has no 0/0 at r = R
    /// (the thin shell 2mR²/3).
    ///
    /// Book: Problem 6.14.11.
    ///
    /// # Errors
    /// As [`MassProperties::solid_sphere`]; [`StaticsError::OutOfRange`] when r > R.
    pub fn spherical_shell(m: T, outer: T, inner: T, centre: Point<T>) -> Result<Self, StaticsError> {
        check_body(m, &centre)?;
        let (big, r) = (check_len(outer, "outer radius")?, check_len(inner, "inner radius")?);
        if r.re() > big.re() {
            return Err(StaticsError::OutOfRange {
                what: "inner radius",
                value: r.re(),
                valid: "0 ≤ inner radius ≤ outer radius",
            });
        }
        let den = big * big + big * r + r * r;
        let moment = if den.re() == 0.0 {
            // R = r = 0: a particle.
            T::zero()
        } else {
            // (R⁵ − r⁵)/(R³ − r³) with the common factor (R − r) cancelled
            let num = big.powi(4) + big.powi(3) * r + big * big * r * r + big * r.powi(3) + r.powi(4);
            T::lit(0.4) * m * num / den
        };
        Self::shape(m, centre, Dyadic::identity() * moment)
    }

    /// Homogeneous rectangular solid with sides a, b, c along the axes î, ĵ, k̂ of `edges`:
    /// J_{B/c|B} = diag(m(b²+c²)/12, m(a²+c²)/12, m(a²+b²)/12).
    ///
    /// Book: Example 6.3.3, (6.3.14).
    ///
    /// # Errors
    /// As [`MassProperties::solid_sphere`] for the mass, sides and centre.
    pub fn solid_box(m: T, sides: [T; 3], edges: &Frame<T>, centre: Point<T>) -> Result<Self, StaticsError> {
        check_body(m, &centre)?;
        let [a, b, c] = [
            check_len(sides[0], "box side a")?,
            check_len(sides[1], "box side b")?,
            check_len(sides[2], "box side c")?,
        ];
        let k = m / T::lit(12.0);
        let d = nalgebra::Matrix3::from_diagonal(&nalgebra::Vector3::new(
            k * (b * b + c * c),
            k * (a * a + c * c),
            k * (a * a + b * b),
        ));
        Self::shape(m, centre, edges.dyadic(&d))
    }

    /// Thin rectangular plate with sides a along î and b along ĵ of `edges` (normal k̂):
    /// J_{B/c|B} = diag(mb²/12, ma²/12, m(a²+b²)/12); the triangle inequality holds with
    /// equality (Figure 6.2.1).
    ///
    /// Book: §6.3, Figure 6.2.1, Problem 6.14.9.
    ///
    /// # Errors
    /// As [`MassProperties::solid_box`].
    pub fn rectangular_plate(
        m: T,
        a: T,
        b: T,
        edges: &Frame<T>,
        centre: Point<T>,
    ) -> Result<Self, StaticsError> {
        Self::solid_box(m, [a, b, T::zero()], edges, centre)
    }

    /// Homogeneous solid cylinder (or disk) of radius r and length l about the unit axis â:
    /// J⃗_{B/c} = (mr²/2) â â′ + (m(3r² + l²)/12)(I⃗ − â â′).
    ///
    /// Book: Example 6.3.4, (6.3.15) (corrected: the isotropic case l = √3 r gives
    /// J_{B/c} = ½mr² I₃, not the printed (1/5)mr² I₃).
    ///
    /// # Errors
    /// As [`MassProperties::solid_sphere`]; [`StaticsError::ZeroVector`] for a zero axis.
    pub fn cylinder(
        m: T,
        radius: T,
        length: T,
        axis: &Vector<T>,
        centre: Point<T>,
    ) -> Result<Self, StaticsError> {
        check_body(m, &centre)?;
        let r = check_len(radius, "cylinder radius")?;
        let l = check_len(length, "cylinder length")?;
        let axial = m * r * r / T::lit(2.0);
        let transverse = m * (T::lit(3.0) * r * r + l * l) / T::lit(12.0);
        Self::shape(m, centre, axisymmetric(axis, axial, transverse)?)
    }

    /// Thin disk of radius r with normal â: the cylinder with l = 0, J = mr²/2 about â and
    /// mr²/4 about any diameter.
    ///
    /// Book: Example 6.3.4 with l = 0, Figure 6.2.1.
    ///
    /// # Errors
    /// As [`MassProperties::cylinder`].
    pub fn disk(m: T, radius: T, normal: &Vector<T>, centre: Point<T>) -> Result<Self, StaticsError> {
        Self::cylinder(m, radius, T::zero(), normal, centre)
    }

    /// Thin rod of length l along â: J⃗_{B/c} = (ml²/12)(I⃗ − â â′), of rank 2 (Fact 6.2.7 iv).
    ///
    /// Book: Example 6.3.4 with r = 0, Figure 6.2.1, Problem 6.14.8.
    ///
    /// # Errors
    /// As [`MassProperties::cylinder`].
    pub fn thin_rod(m: T, length: T, axis: &Vector<T>, centre: Point<T>) -> Result<Self, StaticsError> {
        Self::cylinder(m, T::zero(), length, axis, centre)
    }

    /// Thin homogeneous rod (a wire) from a to b: centre at the midpoint.
    ///
    /// Book: Problem 6.14.2 ii.
    ///
    /// # Errors
    /// As [`MassProperties::thin_rod`]; [`StaticsError::CoincidentPoints`] when a = b.
    pub fn thin_rod_between(m: T, a: &Point<T>, b: &Point<T>) -> Result<Self, StaticsError> {
        let r_b_a = b.position_rel(a);
        let l = r_b_a.norm();
        if l.re() == 0.0 {
            return Err(StaticsError::CoincidentPoints { what: "rod end points", distance: 0.0 });
        }
        Self::thin_rod(m, l, &r_b_a, a.displaced(r_b_a * T::lit(0.5)))
    }

    /// Flat annulus (ring) with outer radius R, inner radius r ≤ R and normal â:
    /// m(R² + r²)/4 about each diameter and m(R² + r²)/2 about â.
    ///
    /// Book: Problem 6.14.10.
    ///
    /// # Errors
    /// As [`MassProperties::spherical_shell`]; [`StaticsError::ZeroVector`] for a zero normal.
    pub fn annulus(
        m: T,
        outer: T,
        inner: T,
        normal: &Vector<T>,
        centre: Point<T>,
    ) -> Result<Self, StaticsError> {
        check_body(m, &centre)?;
        let (big, r) = (check_len(outer, "outer radius")?, check_len(inner, "inner radius")?);
        if r.re() > big.re() {
            return Err(StaticsError::OutOfRange {
                what: "inner radius",
                value: r.re(),
                valid: "0 ≤ inner radius ≤ outer radius",
            });
        }
        let s = m * (big * big + r * r);
        Self::shape(m, centre, axisymmetric(normal, s / T::lit(2.0), s / T::lit(4.0))?)
    }

    /// Thin homogeneous triangular plate with vertices p₁, p₂, p₃: c is the centroid and
    /// J⃗_{B/c} = (m/12) Σ_i (|d⃗_i|²I⃗ − d⃗_i d⃗_i′), d⃗_i = r⃗_{p_i/c}; the same as three particles
    /// of mass m/3 at the edge midpoints. A degenerate (collinear) triangle gives a rod.
    ///
    /// Book: Problem 6.14.12 (derived: the plate's second moment about c is (m/12)Σ d⃗_i d⃗_i′).
    ///
    /// # Errors
    /// [`StaticsError::InvalidMass`], [`StaticsError::ZeroMass`], [`StaticsError::NonFinite`].
    pub fn triangular_plate(m: T, vertices: [Point<T>; 3]) -> Result<Self, StaticsError> {
        for p in &vertices {
            check_point(p, "triangle vertex")?;
        }
        let [p1, p2, p3] = vertices;
        let c = p1.displaced((p2.position_rel(&p1) + p3.position_rel(&p1)) / T::lit(3.0));
        check_body(m, &c)?;
        let j = vertices.iter().fold(Dyadic::zero(), |j, p| {
            let d = p.position_rel(&c);
            j + (Dyadic::identity() * d.norm_squared() - d.outer(&d))
        }) * (m / T::lit(12.0));
        Self::shape(m, c, j)
    }
}
