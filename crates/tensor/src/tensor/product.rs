//! Tensor product (3.2.6), contraction (3.2.2–3), the fused contracted product, evaluation
//! (3.1.14) and partial evaluation (3.3.2).

use super::Tensor;
use crate::{Covector, Scalar, TensorError, Vector};

/// An argument of a partial evaluation (3.3.2): a covector fills a vector slot, a vector
/// fills a covector slot.
///
/// Book: (3.3.2).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Arg<T: Scalar = f64> {
    /// A covector argument x⃗′, paired with a vector factor.
    Covector(Covector<T>),
    /// A vector argument y⃗, paired with a covector factor.
    Vector(Vector<T>),
}

/// Where a slot of T₁⊗T₂ lives: its stride in operand 1 and in operand 2 (one of them 0).
#[derive(Clone, Copy, Default)]
struct Stride {
    a: usize,
    b: usize,
}

/// Row-major strides of an order-n array of 3s: slot k has stride 3^(n−1−k).
pub(super) fn strides(n: usize) -> Vec<usize> {
    let mut s = vec![1usize; n];
    for k in (0..n.saturating_sub(1)).rev() {
        s[k] = s[k + 1] * 3;
    }
    s
}

impl<T: Scalar> Tensor<T> {
    /// Tensor product T₁⊗T₂ of type (p₁+p₂, q₁+q₂) with the book's slot shuffle (3.2.6):
    /// [vectors of T₁, vectors of T₂, covectors of T₁, covectors of T₂]; e.g.
    /// (x⃗⊗y⃗′)⊗(w⃗⊗z⃗′) = x⃗⊗w⃗⊗y⃗′⊗z⃗′ (3.2.12).
    ///
    /// Book: (3.2.6), (3.2.12), Fact 3.6.1.
    ///
    /// # Errors
    /// [`TensorError::TooLarge`] when the product's 3^(k₁+k₂) components exceed the cap.
    pub fn otimes(&self, other: &Tensor<T>) -> Result<Tensor<T>, TensorError> {
        let (p, q) = (self.p + other.p, self.q + other.q);
        let limit = self.joint_limit(other);
        let n = Self::checked_len(p, q, limit)?;
        let (na1, nc1) = (3usize.pow(self.p as u32), 3usize.pow(self.q as u32));
        let (na2, nc2) = (3usize.pow(other.p as u32), 3usize.pow(other.q as u32));
        let mut data = Vec::with_capacity(n);
        // (3.2.6): (T₁⊗T₂)[a₁ a₂ c₁ c₂] = T₁[a₁ c₁] T₂[a₂ c₂]
        for a1 in 0..na1 {
            for a2 in 0..na2 {
                for c1 in 0..nc1 {
                    let t1 = self.data[a1 * nc1 + c1];
                    let row = &other.data[a2 * nc2..(a2 + 1) * nc2];
                    data.extend(row.iter().map(|&t2| t1 * t2));
                }
            }
        }
        Ok(Tensor { p, q, data, limit })
    }

    /// Contraction (T)_(i₁,j₁),(i₂,j₂),… (3.2.2–3): each pair joins the i-th vector slot
    /// (1..=p) with the j-th covector slot (1..=q), all numbered in T's *original* slots; the
    /// remaining slots keep their order. The result has type (p − r, q − r).
    ///
    /// Book: (3.2.2), (3.2.3); the book's "1 ≤ k ≤ q" bound for the vector index reads ≤ p.
    ///
    /// # Errors
    /// [`TensorError::Shape`] for an index outside its group or a slot used twice.
    pub fn contract(&self, pairs: &[(usize, usize)]) -> Result<Tensor<T>, TensorError> {
        fused(self, &Tensor { limit: self.limit, ..Tensor::scalar(T::one()) }, pairs)
    }

    /// The contracted product (T₁⊗T₂)_S (3.3.5), computed in one fused loop that never
    /// materialises T₁⊗T₂: cost 3^(k₁+k₂−r) multiply-adds for r pairs instead of 3^(k₁+k₂).
    /// `pairs` number the slots of T₁⊗T₂ in the shuffled order of (3.2.6): vector slots
    /// 1..=p₁ are T₁'s and p₁+1..=p₁+p₂ are T₂'s, likewise for covector slots.
    ///
    /// Hooke's law σ = (𝒦⊗ε)_(2,3),(3,1) (3.4.4) is `k.contracted_product(&eps, &[(2, 3), (3, 1)])`.
    ///
    /// Book: (3.2.3), (3.3.5), §3.4.
    ///
    /// # Errors
    /// [`TensorError::Shape`] for bad pairs; [`TensorError::TooLarge`] when the *result*
    /// exceeds the cap (the product itself is never stored).
    pub fn contracted_product(
        &self,
        other: &Tensor<T>,
        pairs: &[(usize, usize)],
    ) -> Result<Tensor<T>, TensorError> {
        fused(self, other, pairs)
    }

    /// Evaluation T(x⃗′₁,…,x⃗′_p, y⃗₁,…,y⃗_q) (3.1.14): covector arguments for the p vector
    /// slots, vector arguments for the q covector slots. For a product tensor this is
    /// Π(x⃗′_i w⃗_i)·Π(z⃗′_j y⃗_j).
    ///
    /// Book: (3.1.14); equal to the total contraction (3.2.11).
    ///
    /// # Errors
    /// [`TensorError::Shape`] when the argument counts are not (p, q).
    pub fn eval(&self, covectors: &[Covector<T>], vectors: &[Vector<T>]) -> Result<T, TensorError> {
        if covectors.len() != self.p || vectors.len() != self.q {
            return Err(TensorError::Shape {
                detail: format!(
                    "a ({}, {}) tensor takes {} covectors and {} vectors, got {} and {}",
                    self.p,
                    self.q,
                    self.p,
                    self.q,
                    covectors.len(),
                    vectors.len()
                ),
            });
        }
        // Fold the last slot away, one argument at a time: T[.., m] ↦ Σ_m T[.., m] u_m.
        let args = covectors.iter().map(|x| x.c).chain(vectors.iter().map(|y| y.c)).collect::<Vec<_>>();
        let mut cur = self.data.clone();
        for u in args.iter().rev() {
            cur = cur.chunks_exact(3).map(|t| t[0] * u.x + t[1] * u.y + t[2] * u.z).collect();
        }
        Ok(cur[0])
    }

    /// Partial evaluation T(a₁, …, a_m; s₁, …, s_m) (3.3.2): argument a_k fills factor slot
    /// s_k, a covector filling vector slot s_k ∈ 1..=p, a vector filling covector slot
    /// s_k ∈ 1..=q. The unfilled slots keep their order. Equal to the contracted product with
    /// the tensor product of the arguments (3.3.5).
    ///
    /// Book: (3.3.2), (3.3.5). Example: T₁(x⃗′, y⃗₁, y⃗₂; 3, 2, 1) for T₁ of type (3, 2).
    ///
    /// # Errors
    /// [`TensorError::Shape`] when the lists differ in length, a slot is out of its range or
    /// used twice.
    pub fn partial_eval(&self, args: &[Arg<T>], slots: &[usize]) -> Result<Tensor<T>, TensorError> {
        if args.len() != slots.len() {
            return Err(TensorError::Shape {
                detail: format!(
                    "{} arguments but {} slot numbers: give one slot per argument",
                    args.len(),
                    slots.len()
                ),
            });
        }
        // (3.3.3): T₂ = (vector arguments)⊗(covector arguments), in argument order.
        let vecs: Vec<_> =
            args.iter().filter_map(|a| if let Arg::Vector(y) = a { Some(*y) } else { None }).collect();
        let covs: Vec<_> =
            args.iter().filter_map(|a| if let Arg::Covector(x) = a { Some(*x) } else { None }).collect();
        let t2 = Tensor::from_factors_with_limit(&vecs, &covs, self.limit)?;
        // (3.3.5): a covector fills vector slot s ↔ pair (s, q + its index); a vector fills
        // covector slot s ↔ pair (p + its index, s).
        let (mut iv, mut ic) = (0, 0);
        let pairs: Vec<(usize, usize)> = args
            .iter()
            .zip(slots)
            .map(|(a, &s)| match a {
                Arg::Covector(_) => {
                    ic += 1;
                    (s, self.q + ic)
                }
                Arg::Vector(_) => {
                    iv += 1;
                    (self.p + iv, s)
                }
            })
            .collect();
        // The slot ranges refer to T itself, not to T⊗T₂.
        for (a, &s) in args.iter().zip(slots) {
            let (kind, max) = match a {
                Arg::Covector(_) => ("vector", self.p),
                Arg::Vector(_) => ("covector", self.q),
            };
            if s == 0 || s > max {
                return Err(TensorError::Shape {
                    detail: format!(
                        "slot {s} for a {} argument: it fills a {kind} slot, valid 1..={max} for a ({}, {}) tensor",
                        if kind == "vector" { "covector" } else { "vector" },
                        self.p,
                        self.q
                    ),
                });
            }
        }
        fused(self, &t2, &pairs)
    }
}

/// The fused contracted product (A⊗B)_S: one loop over the free slots and the summation
/// indices, never storing A⊗B.
fn fused<T: Scalar>(
    a: &Tensor<T>,
    b: &Tensor<T>,
    pairs: &[(usize, usize)],
) -> Result<Tensor<T>, TensorError> {
    let (p, q) = (a.p + b.p, a.q + b.q);
    let (sa, sb) = (strides(a.order()), strides(b.order()));
    // Slots of A⊗B in the (3.2.6) order, each with its stride in A or in B.
    let vector_slot = |i: usize| -> Stride {
        if i < a.p { Stride { a: sa[i], b: 0 } } else { Stride { a: 0, b: sb[i - a.p] } }
    };
    let covector_slot = |j: usize| -> Stride {
        if j < a.q { Stride { a: sa[a.p + j], b: 0 } } else { Stride { a: 0, b: sb[b.p + j - a.q] } }
    };
    let (mut used_v, mut used_c) = (vec![false; p], vec![false; q]);
    let mut sums = Vec::with_capacity(pairs.len());
    for &(i, j) in pairs {
        if i == 0 || i > p || j == 0 || j > q {
            return Err(TensorError::Shape {
                detail: format!(
                    "contraction ({i}, {j}) on a ({p}, {q}) tensor: the first index is a vector slot in 1..={p}, the second a covector slot in 1..={q}"
                ),
            });
        }
        if used_v[i - 1] || used_c[j - 1] {
            return Err(TensorError::Shape {
                detail: format!("contraction ({i}, {j}) reuses a slot: each slot may be contracted once"),
            });
        }
        used_v[i - 1] = true;
        used_c[j - 1] = true;
        let (v, c) = (vector_slot(i - 1), covector_slot(j - 1));
        sums.push(Stride { a: v.a + c.a, b: v.b + c.b });
    }
    let free: Vec<Stride> = (0..p)
        .filter(|&i| !used_v[i])
        .map(vector_slot)
        .chain((0..q).filter(|&j| !used_c[j]).map(covector_slot))
        .collect();
    let r = pairs.len();
    let limit = a.joint_limit(b);
    let n_out = Tensor::<T>::checked_len(p - r, q - r, limit)?;
    // Offsets of every summation combination, computed once.
    let mut offs = vec![(0usize, 0usize)];
    for s in &sums {
        offs = offs.iter().flat_map(|&(x, y)| (0..3).map(move |m| (x + m * s.a, y + m * s.b))).collect();
    }
    let mut data = Vec::with_capacity(n_out);
    let mut digits = vec![0usize; free.len()];
    let (mut oa, mut ob) = (0usize, 0usize);
    for _ in 0..n_out {
        // σ[free] = Σ_sum A[oa + da] B[ob + db]
        let mut acc = T::zero();
        for &(da, db) in &offs {
            acc += a.data[oa + da] * b.data[ob + db];
        }
        data.push(acc);
        // Odometer over the free slots, last slot fastest.
        for k in (0..free.len()).rev() {
            if digits[k] < 2 {
                digits[k] += 1;
                oa += free[k].a;
                ob += free[k].b;
                break;
            }
            digits[k] = 0;
            oa -= 2 * free[k].a;
            ob -= 2 * free[k].b;
        }
    }
    Ok(Tensor { p: p - r, q: q - r, data, limit })
}
