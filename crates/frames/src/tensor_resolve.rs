//! Resolution of tensors of type (p, q) in a standard frame, and back (book §3.6, (3.6.2)).
//!
//! T|_A is the 3^p × 3^q matrix (3.6.2)
//!
//! ```text
//! T|_A = Σ_r w_{1r}|_A ⊗ … ⊗ w_{pr}|_A ⊗ z′_{1r}|_A ⊗ … ⊗ z′_{qr}|_A
//! ```
//!
//! (Kronecker products, first factor slowest): the row index is the mixed-radix number
//! (i₁ … i_p) of the vector slots, first slot slowest, and the column index is (j₁ … j_q) of the
//! covector slots. Entry (i, j) is T(î_{i₁}′, …, î_{i_p}′, î_{j₁}, …, î_{j_q}). In a standard
//! frame a covector slot transforms like a vector slot (x⃗′|_A = x|_Aᵀ, (2.4.20)), so every slot
//! is resolved by the same 3 × 3 map, one slot at a time: cost 3^(p+q+1)·(p+q), never the
//! 3^(p+q) × 3^(p+q) Kronecker matrix.
//!
//! The matrix type is nalgebra's [`DMatrix`], which is generic over every [`Scalar`]
//! (dual numbers included); faer's `Mat` is not.

use nalgebra::{DMatrix, Matrix3};
use vectrix_tensor::frames_access::HiddenTensor;
use vectrix_tensor::{DEFAULT_MAX_COMPONENTS, Scalar, Tensor};

use crate::{Frame, FrameError, Resolve};

/// Applies the 3 × 3 map `m` to every slot of a dense tensor stored with the first slot
/// slowest: out[… i_s …] = Σ_h m[i_s, h] data[… h …] for s = 1, …, order.
fn map_every_slot<T: Scalar>(data: &[T], order: usize, m: &Matrix3<T>) -> Vec<T> {
    let mut cur = data.to_vec();
    let mut next = vec![T::zero(); cur.len()];
    // Slot s has stride 3^(order−1−s); the blocks of 3·stride repeat `outer` times.
    let mut stride = cur.len() / 3;
    for _ in 0..order {
        let block = 3 * stride;
        for base in (0..cur.len()).step_by(block) {
            for inner in 0..stride {
                let at = |h: usize| base + h * stride + inner;
                let v = [cur[at(0)], cur[at(1)], cur[at(2)]];
                for r in 0..3 {
                    next[at(r)] = m[(r, 0)] * v[0] + m[(r, 1)] * v[1] + m[(r, 2)] * v[2];
                }
            }
        }
        core::mem::swap(&mut cur, &mut next);
        stride /= 3;
    }
    cur
}

/// The 3^p × 3^q matrix whose row-major entries are `flat` (first slot slowest).
fn matrix_from_flat<T: Scalar>(p: usize, q: usize, flat: &[T]) -> DMatrix<T> {
    DMatrix::from_row_slice(3usize.pow(p as u32), 3usize.pow(q as u32), flat)
}

/// T|_A, the 3^p × 3^q Kronecker matrix of (3.6.2): rows are the vector slots (first slot
/// slowest), columns the covector slots. A (0, 0) tensor gives a 1 × 1 matrix, a (1, 0) tensor
/// a column (= x⃗|_A), a (0, 1) tensor a row (= x⃗′|_A), a (1, 1) tensor M⃗|_A.
///
/// Book: §3.6, (3.6.2), Fact 3.6.1 ((T₁⊗T₂)|_A = T₁|_A ⊗ T₂|_A).
///
/// # Conventions
/// Entry (i, j) = T(î_{i₁}′, …, î_{i_p}′, î_{j₁}, …, î_{j_q}) with i = Σ i_s 3^(p−s)
/// (0-based components), j likewise: nalgebra's `kronecker` order.
impl<T: Scalar> Resolve<T> for Tensor<T> {
    type Output = DMatrix<T>;
    fn resolve(&self, a: &Frame<T>) -> DMatrix<T> {
        // Each slot: x|_A = 𝓕_A x, i.e. the map axesᵀ on hidden components (2.4.14).
        let flat = map_every_slot(self.hidden(), self.order(), &a.axes.transpose());
        matrix_from_flat(self.p(), self.q(), &flat)
    }
}

/// `true` when every entry's real part is finite.
fn all_finite<T: Scalar>(m: &DMatrix<T>) -> bool {
    m.iter().all(|x| x.re().is_finite())
}

/// Checks that `m` is 3^p × 3^q; the error says which shape is valid.
fn check_shape<T: Scalar>(p: usize, q: usize, m: &DMatrix<T>) -> Result<(), FrameError> {
    // Fails with TooLarge before 3^(p+q) could overflow.
    Tensor::<T>::components_for(p + q, usize::MAX)?;
    let (rows, cols) = (3usize.pow(p as u32), 3usize.pow(q as u32));
    if m.shape() != (rows, cols) {
        return Err(FrameError::Shape {
            detail: format!(
                "a ({p}, {q}) tensor resolves to a {rows} × {cols} matrix (3^p × 3^q), got {} × {}",
                m.nrows(),
                m.ncols()
            ),
        });
    }
    Ok(())
}

impl<T: Scalar> Frame<T> {
    /// The tensor of type (p, q) whose resolution in this frame is `t_in_a` (inverse of
    /// [`Resolve::resolve`] for [`Tensor`]): T = Σ T|_A entries × î_{i₁} ⊗ … ⊗ î′_{j_q}. It
    /// carries the kernel's default cap on stored components, [`DEFAULT_MAX_COMPONENTS`].
    ///
    /// Book: §3.6, (3.6.1–2); the tensor analogue of x⃗ = F_A x|_A (2.4.16).
    ///
    /// # Errors
    /// [`FrameError::Shape`] unless `t_in_a` is 3^p × 3^q; [`FrameError::NonFinite`] for NaN or
    /// ∞ entries; [`FrameError::Tensor`] (`TooLarge`) when 3^(p+q) exceeds
    /// [`DEFAULT_MAX_COMPONENTS`] (use [`Frame::tensor_with_limit`] for more).
    pub fn tensor(&self, p: usize, q: usize, t_in_a: &DMatrix<T>) -> Result<Tensor<T>, FrameError> {
        self.tensor_with_limit(p, q, t_in_a, DEFAULT_MAX_COMPONENTS)
    }

    /// [`Frame::tensor`] for a tensor carrying the cap `limit` on stored components
    /// ([`Tensor::max_components`]), for orders above the default cap.
    ///
    /// Book: §3.6, (3.6.1–2), (2.4.16).
    ///
    /// # Errors
    /// As [`Frame::tensor`], with `TooLarge` when 3^(p+q) exceeds `limit`.
    pub fn tensor_with_limit(
        &self,
        p: usize,
        q: usize,
        t_in_a: &DMatrix<T>,
        limit: usize,
    ) -> Result<Tensor<T>, FrameError> {
        Tensor::<T>::components_for(p.saturating_add(q), limit)?;
        check_shape(p, q, t_in_a)?;
        if !all_finite(t_in_a) {
            return Err(FrameError::NonFinite { what: "resolved tensor" });
        }
        let flat: Vec<T> = t_in_a.transpose().iter().copied().collect(); // row-major
        // Each slot: hidden = F_A x|_A (2.4.16), i.e. the map `axes`.
        let hidden = map_every_slot(&flat, p + q, &self.axes);
        Ok(Tensor::from_hidden(p, q, hidden, limit)?)
    }
}

/// Largest |entry| of (X − Y)|_A: the worst component difference of two tensors of the same
/// type, both resolved in the frame A as the 3^p × 3^q matrices of (3.6.2). Components depend
/// on the frame (the largest |entry| is not invariant under a rotation), so the comparison
/// names its frame; for a frame-independent size use [`Tensor::frobenius_norm`] of X − Y.
///
/// Book: §3.6, (3.6.2).
///
/// # Errors
/// [`FrameError::Tensor`] (`Shape`) when the types differ; [`FrameError::NonFinite`] when a
/// component of either tensor is NaN or ∞; [`FrameError::Overflow`] when the difference
/// resolved in A exceeds f64::MAX.
pub fn max_abs_diff_in<T: Scalar>(x: &Tensor<T>, y: &Tensor<T>, a: &Frame<T>) -> Result<T, FrameError> {
    if !x.is_finite() || !y.is_finite() {
        return Err(FrameError::NonFinite { what: "tensor compared" });
    }
    let diff = x.try_sub(y)?.resolve(a);
    let mut worst = T::zero();
    for e in diff.iter().map(|e| e.abs()) {
        if !e.re().is_finite() {
            // finite components near f64::MAX can differ, or rotate, beyond it (∞, or the
            // NaN of 0·∞ in the resolution)
            return Err(FrameError::Overflow { what: "tensor difference resolved in the frame" });
        }
        if e.re() > worst.re() {
            worst = e;
        }
    }
    Ok(worst)
}

/// Change of frame of a resolved tensor: T|_B = (⊗^p 𝓞_{B/A}) T|_A (⊗^q 𝓞_{B/A})ᵀ, each slot
/// transformed by 𝓞_{B/A} (2.10.31), the tensor form of (2.10.38).
///
/// Book: §3.6, (3.6.2) with (2.10.31), (3.5.10).
///
/// # Errors
/// As [`Frame::tensor`] for the shape and finiteness of `t_in_a`; [`FrameError::Overflow`]
/// when a component in the new frame exceeds f64::MAX.
pub fn change_frame_tensor<T: Scalar>(
    t_in_a: &DMatrix<T>,
    p: usize,
    q: usize,
    a: &Frame<T>,
    b: &Frame<T>,
) -> Result<DMatrix<T>, FrameError> {
    check_shape(p, q, t_in_a)?;
    if !all_finite(t_in_a) {
        return Err(FrameError::NonFinite { what: "resolved tensor" });
    }
    let o_ba = b.orientation_rel(a);
    let flat: Vec<T> = t_in_a.transpose().iter().copied().collect();
    let t_in_b = matrix_from_flat(p, q, &map_every_slot(&flat, p + q, &o_ba));
    if !all_finite(&t_in_b) {
        // components near f64::MAX can rotate to a component beyond it
        return Err(FrameError::Overflow { what: "tensor resolved in the new frame" });
    }
    Ok(t_in_b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use vectrix_tensor::frames_access::Hidden;
    use vectrix_tensor::{Dyadic, Rotor, Vector};

    fn frame_b() -> Frame<f64> {
        let a = Frame::new();
        let r = Rotor::from_axis_angle(&a.vector([1.0, -2.0, 0.5]), 0.7).expect("nonzero axis");
        a.rotated_by_rotor(&r)
    }

    /// Largest |entry| of `m`, NaN if any entry is NaN (so a `<= tol` check fails on NaN).
    fn worst(m: &DMatrix<f64>) -> f64 {
        m.iter().fold(0.0, |w: f64, e| if w.is_nan() || e.abs() <= w { w } else { e.abs() })
    }

    #[test]
    fn type_1_1_tensor_resolves_like_its_dyadic() {
        // (3.6.2) with p = q = 1 is M⃗|_A (2.6.28).
        let a = Frame::new();
        let m = a.dyadic(&Matrix3::new(1.0, 2.0, 3.0, -4.0, 5.0, 6.0, 7.0, -8.0, 9.0));
        let h = m.hidden();
        let t =
            Tensor::from_hidden(1, 1, (0..9).map(|k| h[(k / 3, k % 3)]).collect(), DEFAULT_MAX_COMPONENTS)
                .unwrap();
        let b = frame_b();
        let got = t.resolve(&b);
        let want = Dyadic::resolve(&m, &b);
        assert!(worst(&(got - DMatrix::from_iterator(3, 3, want.iter().copied()))) < 1e-14);
    }

    #[test]
    fn tensor_round_trip_and_change_of_frame() {
        let (a, b) = (Frame::new(), frame_b());
        let t_in_a = DMatrix::from_fn(9, 3, |r, c| (r * 3 + c) as f64 - 7.5);
        let t = a.tensor(2, 1, &t_in_a).unwrap();
        assert!(worst(&(t.resolve(&a) - &t_in_a)) < 1e-13);
        let t_in_b = change_frame_tensor(&t_in_a, 2, 1, &a, &b).unwrap();
        assert!(worst(&(t.resolve(&b) - t_in_b)) < 1e-13);
        // A (1, 0) tensor is a vector: its column is x⃗|_B.
        let x = Vector::from_hidden(nalgebra::Vector3::new(1.0, 2.0, 3.0));
        let tx = a.tensor(1, 0, &DMatrix::from_column_slice(3, 1, x.resolve(&a).as_slice())).unwrap();
        assert!(
            worst(&(tx.resolve(&b) - DMatrix::from_column_slice(3, 1, x.resolve(&b).as_slice()))) < 1e-14
        );
    }

    #[test]
    fn wrong_shape_and_non_finite_are_errors() {
        let a = Frame::new();
        assert!(matches!(a.tensor(1, 1, &DMatrix::zeros(3, 2)), Err(FrameError::Shape { .. })));
        let mut m = DMatrix::zeros(3, 3);
        m[(1, 1)] = f64::NAN;
        assert!(matches!(a.tensor(1, 1, &m), Err(FrameError::NonFinite { .. })));
        assert!(matches!(a.tensor(40, 40, &DMatrix::zeros(1, 1)), Err(FrameError::Tensor(_))));
    }

    #[test]
    fn max_abs_diff_in_is_the_worst_entry_of_the_resolved_difference() {
        // In the frame the tensors were built in, (X − Y)|_A = X|_A − Y|_A entry by entry
        // (3.6.2): the worst entry is read off the two matrices; entry (4, 2) differs by 2.5.
        let (a, b) = (Frame::new(), frame_b());
        let x_in_a = DMatrix::from_fn(9, 3, |r, c| (r * 3 + c) as f64 - 7.5);
        let mut y_in_a = x_in_a.clone();
        y_in_a[(4, 2)] -= 2.5;
        y_in_a[(0, 0)] += 1.0;
        let (x, y) = (b.tensor(2, 1, &x_in_a).unwrap(), b.tensor(2, 1, &y_in_a).unwrap());
        let d = max_abs_diff_in(&x, &y, &b).unwrap();
        assert!((d - 2.5).abs() <= 16.0 * f64::EPSILON * 20.0, "{d}");
        // the same tensors compared in another frame: the largest |entry| of the rotated
        // difference, and never above its Frobenius norm √(2.5² + 1²)
        let in_a = max_abs_diff_in(&x, &y, &a).unwrap();
        assert!(in_a <= (2.5f64.powi(2) + 1.0).sqrt() * (1.0 + 1e-14) && in_a > 0.0);
        assert!(matches!(max_abs_diff_in(&x, &Tensor::identity(), &a), Err(FrameError::Tensor(_))));
        let huge = a.tensor(1, 0, &DMatrix::from_column_slice(3, 1, &[f64::MAX, 0.0, 0.0])).unwrap();
        let neg = a.tensor(1, 0, &DMatrix::from_column_slice(3, 1, &[-f64::MAX, 0.0, 0.0])).unwrap();
        assert!(matches!(max_abs_diff_in(&huge, &neg, &a), Err(FrameError::Overflow { .. })));
    }

    #[test]
    fn tensor_with_limit_carries_its_cap() {
        let a = Frame::new();
        let m = DMatrix::from_element(27, 1, 1.0);
        assert!(matches!(a.tensor_with_limit(3, 0, &m, 26), Err(FrameError::Tensor(_))));
        let t = a.tensor_with_limit(3, 0, &m, 27).unwrap();
        assert_eq!(t.max_components(), 27);
        assert_eq!(a.tensor(3, 0, &m).unwrap().max_components(), DEFAULT_MAX_COMPONENTS);
    }
}
