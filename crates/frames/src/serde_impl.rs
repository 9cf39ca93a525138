//! serde for [`Frame`] (cargo feature `serde`).
//!
//! A frame is literally its three axes (book (2.4.3)), and axes are physical vectors with no
//! components; a file therefore holds them resolved in the **first frame** F₀ = [`Frame::new`]:
//!
//! ```json
//! {"i": [1.0, 0.0, 0.0], "j": [0.0, 1.0, 0.0], "k": [0.0, 0.0, 1.0]}
//! ```
//!
//! i.e. the rows of 𝓞_{F/F₀} (= the columns of 𝓡_{F/F₀}, book (2.10.14)). Reading checks the
//! axes as [`Frame::from_axes`] does with [`ORTHONORMAL_TOL`] (finite, orthonormal,
//! right-handed) and reports its [`crate::FrameError`] message; a round trip is exact.
//!
//! Book: §2.4, (2.4.3), (2.10.14). JSON forms: `docs/guide/interop.md`.

use nalgebra::Vector3;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use vectrix_tensor::frames_access::Hidden;
use vectrix_tensor::{Scalar, Vector};

use crate::{Frame, ORTHONORMAL_TOL};

/// The file form: î, ĵ, k̂ resolved in F₀.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Axes<T> {
    i: [T; 3],
    j: [T; 3],
    k: [T; 3],
}

/// `{"i": î|_{F₀}, "j": ĵ|_{F₀}, "k": k̂|_{F₀}}`.
impl<T: Scalar + Serialize> Serialize for Frame<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let col = |c: usize| [self.axes[(0, c)], self.axes[(1, c)], self.axes[(2, c)]];
        Axes { i: col(0), j: col(1), k: col(2) }.serialize(s)
    }
}

/// From the axes resolved in F₀, checked by [`Frame::from_axes`] with [`ORTHONORMAL_TOL`].
impl<'de, T: Scalar + Deserialize<'de>> Deserialize<'de> for Frame<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let Axes { i, j, k } = Axes::<T>::deserialize(d)?;
        let v = |x: [T; 3]| Vector::from_hidden(Vector3::from(x));
        Frame::from_axes(&v(i), &v(j), &v(k), ORTHONORMAL_TOL).map_err(serde::de::Error::custom)
    }
}
