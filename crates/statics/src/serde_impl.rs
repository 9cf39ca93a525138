//! serde for mass properties (cargo feature `serde`).
//!
//! | type | JSON |
//! |---|---|
//! | [`Point`] | `[x, y, z]`: r⃗_{y/o} resolved in the first frame F₀ |
//! | [`MassProperties`] | `{"mass": m_B, "centre_of_mass": [x, y, z], "inertia_about_centre": [[…], […], […]]}` |
//! | [`InertiaComponents`] | `{"moments": [J_xx, J_yy, J_zz], "products": [J_xy, J_xz, J_yz]}` (the book's positive sums) |
//!
//! Vectors and dyadics are frame-free, so a file holds them resolved in the **first frame**
//! F₀ = `Frame::new()` (rows of J⃗_{B/c}|_{F₀} for the inertia). Reading checks what
//! [`MassProperties::new`] checks (mass finite and > 0, finite centre, J⃗_{B/c} symmetric,
//! positive semidefinite, rank ≠ 1 and λ1 ≤ λ2 + λ3 within [`INERTIA_REL_TOL`]) and reports its
//! [`crate::StaticsError`] message. The inertia is kept as written (not re-symmetrised), so a
//! round trip is exact.
//!
//! Book: §6.1–6.2, (6.1.1)–(6.1.2), (6.2.4)–(6.2.8), Facts 6.2.7–6.2.8. JSON forms:
//! `docs/guide/interop.md`.

use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use vectrix_tensor::{Dyadic, Scalar, Vector};

use crate::mass::{check_mass, check_point};
use crate::{INERTIA_REL_TOL, InertiaComponents, MassProperties, Point, StaticsError, check_inertia};

/// r⃗_{y/o} resolved in F₀, as `[x, y, z]`.
impl<T: Scalar + Serialize> Serialize for Point<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.position().serialize(s)
    }
}

/// From r⃗_{y/o}|_{F₀} (finite components only).
impl<'de, T: Scalar + Deserialize<'de>> Deserialize<'de> for Point<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        Ok(Point::at(Vector::deserialize(d)?))
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct MassRepr<T: Scalar> {
    mass: T,
    centre_of_mass: Point<T>,
    inertia_about_centre: Dyadic<T>,
}

/// m_B, c and J⃗_{B/c} (book §6.1–6.2), vectors and the dyadic resolved in F₀.
impl<T: Scalar + Serialize> Serialize for MassProperties<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        MassRepr {
            mass: self.mass(),
            centre_of_mass: self.centre_of_mass(),
            inertia_about_centre: self.inertia_about_centre(),
        }
        .serialize(s)
    }
}

/// Checked as [`MassProperties::new`]; the inertia is kept as written.
impl<'de, T: Scalar + Deserialize<'de>> Deserialize<'de> for MassProperties<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let MassRepr { mass, centre_of_mass, inertia_about_centre } = MassRepr::<T>::deserialize(d)?;
        let check = || -> Result<(), StaticsError> {
            check_mass(mass, "body")?;
            if mass.re() == 0.0 {
                return Err(StaticsError::ZeroMass { what: "body" });
            }
            check_point(&centre_of_mass, "centre of mass")?;
            check_inertia(&inertia_about_centre, INERTIA_REL_TOL)?;
            Ok(())
        };
        check().map_err(D::Error::custom)?;
        Ok(MassProperties::from_parts_unchecked(mass, centre_of_mass, inertia_about_centre))
    }
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct ComponentsRepr<T> {
    moments: [T; 3],
    products: [T; 3],
}

/// The book's moments and (positive-sum) products of inertia, (6.2.4)–(6.2.8).
impl<T: Scalar + Serialize> Serialize for InertiaComponents<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        ComponentsRepr { moments: self.moments, products: self.products }.serialize(s)
    }
}

/// Any finite moments and products (they are plain numbers in a frame; validate the dyadic
/// with [`check_inertia`] where physical inertia is required).
impl<'de, T: Scalar + Deserialize<'de>> Deserialize<'de> for InertiaComponents<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let ComponentsRepr { moments, products } = ComponentsRepr::<T>::deserialize(d)?;
        if !moments.iter().chain(&products).all(|x| x.re().is_finite()) {
            return Err(D::Error::custom(
                "non-finite moment or product of inertia: every entry must be finite",
            ));
        }
        Ok(InertiaComponents { moments, products })
    }
}
