//! serde for the kernel's physical objects (cargo feature `serde`).
//!
//! A physical object has no components (book §1.3), so a file holds its components in the
//! **first frame** F₀ = `Frame::new()` of crate `vectrix-frames`, whose axes are the hidden
//! basis: a [`Vector`] is `[x, y, z]` = x⃗|_{F₀} and a [`Dyadic`] is its rows
//! `[[m11, m12, m13], [m21, m22, m23], [m31, m32, m33]]` = M⃗|_{F₀} (book (2.4.14), (2.10.22)).
//! Reading builds the same object (a round trip is exact). Non-finite components are refused
//! with an error naming the object, as `Frame::try_vector` refuses them.
//!
//! Book: §1.3, (2.4.14)–(2.4.15); DESIGN §1.1. JSON forms: `docs/guide/interop.md`.

use nalgebra::{Matrix3, Vector3};
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::{Dyadic, Scalar, Vector};

fn finite<T: Scalar, E: serde::de::Error>(xs: &[T], what: &str) -> Result<(), E> {
    if xs.iter().all(|x| x.re().is_finite()) {
        Ok(())
    } else {
        Err(E::custom(format!("non-finite component in {what}: every component must be a finite number")))
    }
}

/// x⃗|_{F₀} as `[x, y, z]`.
impl<T: Scalar + Serialize> Serialize for Vector<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        [self.c.x, self.c.y, self.c.z].serialize(s)
    }
}

/// From `[x, y, z]` = x⃗|_{F₀}; non-finite components are an error.
impl<'de, T: Scalar + Deserialize<'de>> Deserialize<'de> for Vector<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let c = <[T; 3]>::deserialize(d)?;
        finite(&c, "a vector")?;
        Ok(Vector { c: Vector3::from(c) })
    }
}

/// M⃗|_{F₀} as three rows.
impl<T: Scalar + Serialize> Serialize for Dyadic<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let m = &self.m;
        let row = |r: usize| [m[(r, 0)], m[(r, 1)], m[(r, 2)]];
        [row(0), row(1), row(2)].serialize(s)
    }
}

/// From three rows of M⃗|_{F₀}; non-finite entries are an error.
impl<'de, T: Scalar + Deserialize<'de>> Deserialize<'de> for Dyadic<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let rows = <[[T; 3]; 3]>::deserialize(d)?;
        finite(rows.as_flattened(), "a dyadic")?;
        Ok(Dyadic { m: Matrix3::from_fn(|r, c| rows[r][c]) })
    }
}
