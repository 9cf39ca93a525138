//! Carrying tensors by a rotation (book §2.10 for dyads, §3.6 for tensors of any type).

use vectrix_tensor::{Scalar, Tensor};

use crate::{Rotation, RotationError};

impl<T: Scalar> Rotation<T> {
    /// The tensor carried by R⃗ (push-forward): every vector factor x⃗ becomes R⃗x⃗ and every
    /// covector factor a⃗′ becomes a⃗′R⃗⁻¹, so (R⃗·T)(a⃗′R⃗⁻¹, …, R⃗y⃗, …) = T(a⃗′, …, y⃗, …). For a
    /// vector this is R⃗x⃗; for a dyad R⃗M⃗R⃗′ ([`Rotation::apply_dyadic`]).
    ///
    /// Book: §3.6 (change of frame of tensors), (2.10.38) for dyads.
    ///
    /// # Errors
    /// [`RotationError::Tensor`] when an intermediate product would exceed the tensor size cap.
    pub fn apply_tensor(&self, t: &Tensor<T>) -> Result<Tensor<T>, RotationError> {
        let r = Tensor::from_dyadic(&self.to_dyadic());
        let r_inv = Tensor::from_dyadic(&self.inverse().to_dyadic());
        let (p, q) = (t.p(), t.q());
        let n = p + q;
        let mut cur = t.clone();
        for k in 1..=p {
            // (R⊗T)_(k+1, 1): R's covector slot eats T's k-th vector slot; R's vector slot
            // comes out first and is moved back to position k.
            let x = r.contracted_product(&cur, &[(k + 1, 1)])?;
            let sigma: Vec<usize> = (1..=n)
                .map(|m| match m {
                    1 => k,
                    m if m <= k => m - 1,
                    m => m,
                })
                .collect();
            cur = x.permute(&sigma)?;
        }
        for j in 1..=q {
            // (T⊗R⁻¹)_(p+1, j): R⁻¹'s vector slot eats T's j-th covector slot; R⁻¹'s covector
            // slot comes out last and is moved back to position j.
            let x = cur.contracted_product(&r_inv, &[(p + 1, j)])?;
            let sigma: Vec<usize> = (1..=n)
                .map(|s| {
                    if s <= p {
                        return s;
                    }
                    let m = s - p;
                    if m < j {
                        s
                    } else if m < q {
                        s + 1
                    } else {
                        p + j
                    }
                })
                .collect();
            cur = x.permute(&sigma)?;
        }
        Ok(cur)
    }
}
