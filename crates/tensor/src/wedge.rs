//! Alternating tensors and the wedge product (book §3.7), determinant convention (3.7.17).
//!
//! T₁∧T₂ = (1/(p₁! p₂!)) Σ_σ sign(σ) (T₁⊗T₂)_σ, so x⃗∧y⃗ = x⃗⊗y⃗ − y⃗⊗x⃗ (3.7.1) with no ½ and
//! x⃗∧y⃗∧z⃗ is the six-term signed sum with coefficient 1 (3.7.11). Grades 1 and 2 are kept
//! compressed: x⃗∧y⃗ = 𝒥(x⃗×y⃗) is a [`Bivector`] (3.8.32), x⃗∧y⃗∧z⃗ = det[x y z]𝒥 a
//! [`Trivector`] (3.7.20). The dense permutation sum [`Tensor::wedge`] stays for general
//! alternating tensors and as the oracle the compressed formulas are tested against.

use crate::{Bivector, Scalar, Tensor, TensorError, Trivector, Vector};

/// Error-free product (Dekker/Veltkamp, no FMA needed): a·b = p + e exactly, p = fl(ab).
#[inline(always)]
fn two_product<T: Scalar>(a: T, b: T) -> (T, T) {
    // Veltkamp split constant 2^⌈m/2⌉ + 1 for an m-bit significand (2^27 + 1 for f64).
    let c = if T::eps() < 1e-10 { T::lit(134_217_729.0) } else { T::lit(4097.0) };
    let split = |x: T| {
        let t = c * x;
        let hi = t - (t - x);
        (hi, x - hi)
    };
    let p = a * b;
    let ((ah, al), (bh, bl)) = (split(a), split(b));
    let e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    (p, e)
}

/// a·b − c·d to a few ulps of the result, so that nearly parallel vectors keep the relative
/// accuracy of their wedge (ch. 3 notes, §3 "Cancellation"). Without cancellation
/// (|ab − cd| ≥ ½(|ab| + |cd|)) the plain formula is already within 3ε relative; otherwise
/// both products are taken error-free (Dekker) and the cancelling difference is exact
/// (Sterbenz), the same accuracy as Kahan's FMA algorithm without needing a hardware FMA.
#[inline(always)]
pub(crate) fn diff_of_products<T: Scalar>(a: T, b: T, c: T, d: T) -> T {
    let (ab, cd) = (a * b, c * d);
    let plain = ab - cd;
    if plain.abs() + plain.abs() >= ab.abs() + cd.abs() {
        return plain;
    }
    // ab − cd = (p₁ − p₂) + (e₁ − e₂), p₁ − p₂ exact since p₁ ≈ p₂.
    let ((p1, e1), (p2, e2)) = (two_product(a, b), two_product(c, d));
    let r = (p1 - p2) + (e1 - e2);
    // The split overflows for |x| ≳ 1e300; keep the plain value there.
    if r.re().is_finite() { r } else { plain }
}

impl<T: Scalar> Vector<T> {
    /// Wedge x⃗∧y⃗ = x⃗⊗y⃗ − y⃗⊗x⃗ (3.7.1), the oriented plane element 𝒥(x⃗×y⃗) (3.8.32) with
    /// area |x⃗∧y⃗| = |x⃗||y⃗| sin θ (3.7.9–10). Components by fused differences of products,
    /// accurate for nearly parallel vectors.
    ///
    /// Book: (3.7.1), (3.7.9), (3.8.32), Fact 3.7.3.
    #[inline]
    pub fn wedge(&self, y: &Vector<T>) -> Bivector<T> {
        let (x, y) = (&self.c, &y.c);
        Bivector {
            c: nalgebra::Vector3::new(
                diff_of_products(x.y, y.z, x.z, y.y),
                diff_of_products(x.z, y.x, x.x, y.z),
                diff_of_products(x.x, y.y, x.y, y.x),
            ),
        }
    }

    /// Wedge x⃗∧B of a vector and a bivector, equal to B∧x⃗ (graded commutativity,
    /// (−1)^{1·2} = 1, Problem 3.10.3).
    ///
    /// Book: (3.7.18), (3.7.20).
    #[inline]
    pub fn wedge_bivector(&self, b: &Bivector<T>) -> Trivector<T> {
        b.wedge(self)
    }

    /// Triple wedge x⃗∧y⃗∧z⃗ = det[x y z]𝒥 = ((x⃗×y⃗)·z⃗)𝒥 (3.7.20–21); its volume is
    /// |det[x y z]| (3.7.23).
    ///
    /// Book: (3.7.11), (3.7.20), (3.7.21), (3.7.23).
    #[inline]
    pub fn wedge3(&self, y: &Vector<T>, z: &Vector<T>) -> Trivector<T> {
        self.wedge(y).wedge(z)
    }
}

impl<T: Scalar> Bivector<T> {
    /// Wedge B∧z⃗ of a bivector and a vector: (x⃗∧y⃗)∧z⃗ = ((x⃗×y⃗)·z⃗)𝒥 (3.7.21).
    ///
    /// Book: (3.7.18), (3.7.21).
    #[inline]
    pub fn wedge(&self, z: &Vector<T>) -> Trivector<T> {
        Trivector { t: self.c.dot(&z.c) }
    }
}

/// Every permutation of 0..k with its sign.
fn permutations(k: usize) -> Vec<(Vec<usize>, i32)> {
    if k == 0 {
        return vec![(Vec::new(), 1)];
    }
    let mut out = Vec::new();
    for (perm, sign) in permutations(k - 1) {
        // Insert k−1 at position pos: it passes (k−1−pos) elements, each a transposition.
        for pos in 0..k {
            let mut p = perm.clone();
            p.insert(pos, k - 1);
            let s = if (k - 1 - pos).is_multiple_of(2) { sign } else { -sign };
            out.push((p, s));
        }
    }
    out
}

fn factorial(n: usize) -> f64 {
    (1..=n).map(|k| k as f64).product()
}

impl<T: Scalar> Tensor<T> {
    /// Wedge product T₁∧T₂ = (1/(p₁! p₂!)) Σ_σ sign(σ)(T₁⊗T₂)_σ (3.7.17) of alternating
    /// tensors of pure type, both contravariant (p, 0) or both covariant (0, q): the
    /// determinant convention. It is associative (3.7.18–19) and graded commutative,
    /// T₁∧T₂ = (−1)^{p₁p₂} T₂∧T₁ (Problem 3.10.3). In 3-D every alternating tensor of order
    /// above 3 is zero (3.8.28), which is returned without forming a permutation sum.
    ///
    /// Book: (3.7.17)–(3.7.19), (3.7.27), (3.7.29).
    ///
    /// # Errors
    /// [`TensorError::Shape`] when either factor is of mixed type or the kinds differ;
    /// [`TensorError::TooLarge`] from the cap.
    pub fn wedge(&self, other: &Tensor<T>) -> Result<Tensor<T>, TensorError> {
        let contravariant = self.q == 0 && other.q == 0;
        let covariant = self.p == 0 && other.p == 0;
        if !contravariant && !covariant {
            return Err(TensorError::Shape {
                detail: format!(
                    "the wedge is defined for pure types, both (p, 0) or both (0, q); got ({}, {}) and ({}, {})",
                    self.p, self.q, other.p, other.q
                ),
            });
        }
        let (k1, k2) = (self.order(), other.order());
        let k = k1 + k2;
        let (p, q) = if contravariant { (k, 0) } else { (0, k) };
        if k > 3 {
            // (3.8.28): no nonzero alternating tensor of order > 3 in 3-D.
            return Tensor::zeros_with_limit(p, q, self.joint_limit(other));
        }
        let product = self.otimes(other)?;
        let scale = T::lit(1.0 / (factorial(k1) * factorial(k2)));
        let mut sum = Tensor::zeros_with_limit(p, q, self.joint_limit(other))?;
        for (perm, sign) in permutations(k) {
            let one_based: Vec<usize> = perm.iter().map(|i| i + 1).collect();
            let t = product.permute(&one_based)?;
            let s = T::lit(f64::from(sign)) * scale;
            for (acc, &x) in sum.data.iter_mut().zip(&t.data) {
                *acc += s * x;
            }
        }
        Ok(sum)
    }

    /// `true` when the tensor is of pure type and alternating, T_σ = sign(σ) T (3.7.15), within
    /// `tol` relative to its largest component. Order 0 and 1 are trivially alternating.
    ///
    /// Book: (3.7.15).
    pub fn is_alternating(&self, tol: f64) -> bool {
        if self.p != 0 && self.q != 0 {
            return false;
        }
        let k = self.order();
        let scale = self.data.iter().fold(0.0f64, |m, x| m.max(x.re().abs())).max(f64::MIN_POSITIVE);
        permutations(k).into_iter().all(|(perm, sign)| {
            let one_based: Vec<usize> = perm.iter().map(|i| i + 1).collect();
            match self.permute(&one_based) {
                Ok(t) => t
                    .data
                    .iter()
                    .zip(&self.data)
                    .all(|(&a, &b)| (a - T::lit(f64::from(sign)) * b).re().abs() <= tol * scale),
                Err(_) => false,
            }
        })
    }

    /// Geometric magnitude of an alternating tensor of order k: ‖T‖_F/√(k!), which is the
    /// area |x⃗×y⃗| of x⃗∧y⃗ and the volume |det[x y z]| of x⃗∧y⃗∧z⃗ (3.7.9–10, 3.7.23, 3.7.26),
    /// not the Frobenius norm.
    ///
    /// Book: (3.7.9), (3.7.10), (3.7.23), (3.7.26).
    pub fn alternating_magnitude(&self) -> T {
        self.frobenius_norm() / T::lit(factorial(self.order()).sqrt())
    }
}

/// Checks that `dense` equals `expected` (a compressed element expanded) within `tol`.
pub(crate) fn check_alternating<T: Scalar>(
    dense: &Tensor<T>,
    expected: &Tensor<T>,
    tol: f64,
) -> Result<(), TensorError> {
    let scale = dense.data.iter().fold(0.0f64, |m, x| m.max(x.re().abs())).max(f64::MIN_POSITIVE);
    let defect = dense.data.iter().zip(&expected.data).fold(0.0f64, |m, (a, b)| m.max((*a - *b).re().abs()));
    if defect > tol * scale {
        return Err(TensorError::Shape {
            detail: format!(
                "the tensor is not alternating: its antisymmetric part differs by {defect:e} (tolerance {:e}); only alternating (k, 0) tensors compress",
                tol * scale
            ),
        });
    }
    Ok(())
}
