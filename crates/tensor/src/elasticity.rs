//! Stress, strain and elasticity (book §3.4): the stiffness tensor 𝒦 of type (2, 2), Hooke's
//! law σ = (𝒦⊗ε)_(2,3),(3,1) (3.4.4), and the isotropic material (3.4.11–16).
//!
//! With 𝒦 = Σ c_klmn ê_k⊗ê_l⊗ê′_m⊗ê′_n the law reads σ_kn = Σ_lm c_klmn ε_ml (3.4.5); the
//! conventional C_ijkl of σ_ij = C_ijkl ε_kl is C_ijkl = c_ilkj (ch. 3 notes).

use core::marker::PhantomData;

use nalgebra::{SMatrix, SVector};

use crate::{Dyadic, FastPath, Scalar, Tensor, TensorError};

/// Hooke's law σ = (𝒦⊗ε)_(2,3),(3,1) by the general fused contraction (3.4.4).
///
/// Book: (3.4.4), (3.4.5).
///
/// # Errors
/// [`TensorError::Shape`] when 𝒦 is not of type (2, 2).
pub fn hooke<T: Scalar>(k: &Tensor<T>, eps: &Dyadic<T>) -> Result<Dyadic<T>, TensorError> {
    check_stiffness(k)?;
    let sigma = k.contracted_product(&Tensor::from_dyadic(eps), &[(2, 3), (3, 1)])?;
    sigma.to_dyadic().ok_or_else(|| TensorError::Shape { detail: "Hooke's law gives a (1, 1) tensor".into() })
}

fn check_stiffness<T: Scalar>(k: &Tensor<T>) -> Result<(), TensorError> {
    if (k.p, k.q) != (2, 2) {
        return Err(TensorError::Shape {
            detail: format!("a stiffness tensor has type (2, 2), got ({}, {})", k.p, k.q),
        });
    }
    Ok(())
}

/// Hooke's law as a linear map on the 9 components, precomputed from 𝒦 once: for many strains
/// it is the same contraction σ = (𝒦⊗ε)_(2,3),(3,1) as [`hooke`] at 81 multiply-adds each.
///
/// Book: (3.4.4), (3.4.5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HookeMap<T: Scalar = f64> {
    /// vec(σ) = H vec(ε), vec stacking the hidden components column by column.
    pub(crate) h: SMatrix<T, 9, 9>,
}

impl<T: Scalar> HookeMap<T> {
    /// The map of the stiffness tensor 𝒦 (type (2, 2)).
    ///
    /// # Errors
    /// [`TensorError::Shape`] when 𝒦 is not of type (2, 2).
    pub fn new(k: &Tensor<T>) -> Result<Self, TensorError> {
        check_stiffness(k)?;
        let mut h = SMatrix::<T, 9, 9>::zeros();
        // (3.4.5): σ_kn = Σ_lm c_klmn ε_ml; column-major vec index of (r, c) is r + 3c.
        for (idx, &c) in k.data.iter().enumerate() {
            let (kk, l, m, n) = (idx / 27, (idx / 9) % 3, (idx / 3) % 3, idx % 3);
            h[(kk + 3 * n, m + 3 * l)] += c;
        }
        Ok(Self { h })
    }

    /// σ = (𝒦⊗ε)_(2,3),(3,1) for one strain.
    #[inline]
    pub fn apply(&self, eps: &Dyadic<T>) -> Dyadic<T> {
        let e = SVector::<T, 9>::from_column_slice(eps.m.as_slice());
        let s = self.h * e;
        Dyadic { m: nalgebra::Matrix3::from_column_slice(s.as_slice()) }
    }

    /// σ_k = (𝒦⊗ε_k)_(2,3),(3,1) for every strain, written into `out`.
    ///
    /// # Errors
    /// [`TensorError::Shape`] when the slices differ in length.
    pub fn apply_many(&self, eps: &[Dyadic<T>], out: &mut [Dyadic<T>]) -> Result<(), TensorError> {
        if eps.len() != out.len() {
            return Err(TensorError::Shape {
                detail: format!(
                    "{} strains but room for {} stresses: the lengths must agree",
                    eps.len(),
                    out.len()
                ),
            });
        }
        // f64: the 81 multiply-adds column by column in SIMD (`crate::f64::hooke`)
        T::fast_path::<ApplyMany<'_>>((self, eps, out));
        Ok(())
    }
}

/// [`HookeMap::apply_many`] after the length check: [`HookeMap::apply`] strain by strain, or
/// the `f64` kernel.
struct ApplyMany<'a>(PhantomData<&'a ()>);

impl<'a> FastPath for ApplyMany<'a> {
    type Input<T: Scalar> = (&'a HookeMap<T>, &'a [Dyadic<T>], &'a mut [Dyadic<T>]);
    type Output<T: Scalar> = ();

    fn generic<T: Scalar>((map, eps, out): Self::Input<T>) {
        for (s, e) in out.iter_mut().zip(eps) {
            *s = map.apply(e);
        }
    }

    fn f64((map, eps, out): Self::Input<f64>) {
        crate::f64::hooke::apply_many(&map.h, eps, out);
    }
}

/// An isotropic linear elastic material given by its Lamé constants λ, μ (3.4.11).
///
/// Book: §3.4, (3.4.11)–(3.4.16).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Isotropic<T: Scalar = f64> {
    lambda: T,
    mu: T,
}

impl<T: Scalar> Isotropic<T> {
    /// From the Lamé constants. Positive definiteness of the strain energy needs μ > 0 and
    /// 3λ + 2μ > 0 (bulk modulus K > 0).
    ///
    /// # Errors
    /// [`TensorError::OutOfRange`] for non-finite values, μ ≤ 0 or 3λ + 2μ ≤ 0.
    pub fn from_lame(lambda: T, mu: T) -> Result<Self, TensorError> {
        if !lambda.re().is_finite() || !mu.re().is_finite() {
            return Err(TensorError::NonFinite { what: "Lamé constants λ, μ" });
        }
        if mu.re() <= 0.0 {
            return Err(TensorError::OutOfRange {
                what: "shear modulus μ", value: mu.re(), valid: "μ > 0"
            });
        }
        let k3 = T::lit(3.0) * lambda + T::lit(2.0) * mu;
        if k3.re() <= 0.0 {
            return Err(TensorError::OutOfRange {
                what: "3λ + 2μ", value: k3.re(), valid: "3λ + 2μ > 0"
            });
        }
        Self { lambda, mu }.checked()
    }

    /// From Young's modulus E and Poisson's ratio ν (3.4.16): μ = E/(2(1+ν)),
    /// λ = Eν/((1+ν)(1−2ν)).
    ///
    /// Book: (3.4.16).
    ///
    /// # Errors
    /// [`TensorError::OutOfRange`] unless E > 0 and −1 < ν < ½.
    pub fn from_young_poisson(e: T, nu: T) -> Result<Self, TensorError> {
        if !(e.re() > 0.0 && e.re().is_finite()) {
            return Err(TensorError::OutOfRange {
                what: "Young's modulus E",
                value: e.re(),
                valid: "finite E > 0",
            });
        }
        if !(nu.re() > -1.0 && nu.re() < 0.5) {
            return Err(TensorError::OutOfRange {
                what: "Poisson's ratio ν",
                value: nu.re(),
                valid: "−1 < ν < 1/2",
            });
        }
        let one = T::one();
        let mu = e / (T::lit(2.0) * (one + nu));
        let lambda = e * nu / ((one + nu) * (one - T::lit(2.0) * nu));
        Self { lambda, mu }.checked()
    }

    /// `Ok` when every derived modulus (E, ν, K, 3λ + 2μ) is finite, else
    /// [`TensorError::Overflow`]: λ = 1e308 is finite but 3λ + 2μ is not.
    fn checked(self) -> Result<Self, TensorError> {
        let derived = [self.lambda, self.mu, self.young(), self.poisson(), self.bulk()];
        if derived.iter().all(|x| x.re().is_finite()) {
            Ok(self)
        } else {
            Err(TensorError::Overflow { what: "elastic moduli" })
        }
    }

    /// Lamé's λ.
    pub fn lambda(&self) -> T {
        self.lambda
    }

    /// Shear modulus μ.
    pub fn mu(&self) -> T {
        self.mu
    }

    /// Young's modulus E = μ(3λ+2μ)/(λ+μ) (3.4.15).
    ///
    /// Book: (3.4.15).
    pub fn young(&self) -> T {
        self.mu * (T::lit(3.0) * self.lambda + T::lit(2.0) * self.mu) / (self.lambda + self.mu)
    }

    /// Poisson's ratio ν = λ/(2(λ+μ)) (3.4.15).
    ///
    /// Book: (3.4.15).
    pub fn poisson(&self) -> T {
        self.lambda / (T::lit(2.0) * (self.lambda + self.mu))
    }

    /// Bulk modulus K = λ + 2μ/3.
    pub fn bulk(&self) -> T {
        self.lambda + T::lit(2.0) * self.mu / T::lit(3.0)
    }

    /// The stiffness tensor 𝒦 with c_klmn = μ(δ_km δ_ln + δ_kl δ_mn) + λ δ_kn δ_lm, so that
    /// (𝒦⊗ε)_(2,3),(3,1) = μ(ε + ε′) + λ (tr ε) I, which is 2μ ε + λ (tr ε) I (3.4.11) for the
    /// symmetric strains of (3.4.2).
    ///
    /// Book: (3.4.5), (3.4.11), (3.4.12).
    ///
    /// # Conventions
    /// Of the tensors giving (3.4.11) on symmetric strains, this is the one with the
    /// symmetries the book derives in §3.4: c_iklj = c_jkli (σ symmetric; the book's L3981
    /// prints "c_jklj"), symmetry in the strain slots, and the major symmetry. The book's
    /// (3.4.12) form 2μ(U4⊗ε)_(2,3),(3,1) + λ(U4⊗ε)_(2,3),(3,2) agrees on symmetric ε.
    pub fn stiffness(&self) -> Tensor<T> {
        let d = |i: usize, j: usize| if i == j { T::one() } else { T::zero() };
        let data = (0..81).map(|idx| {
            let (k, l, m, n) = (idx / 27, (idx / 9) % 3, (idx / 3) % 3, idx % 3);
            self.mu * (d(k, m) * d(l, n) + d(k, l) * d(m, n)) + self.lambda * d(k, n) * d(l, m)
        });
        Tensor { p: 2, q: 2, data: data.collect(), limit: crate::DEFAULT_MAX_COMPONENTS }
    }

    /// Stress σ = 2μ ε + λ (tr ε) I (3.4.11), the closed form of Hooke's law; evaluated as
    /// μ(ε + ε′) + λ (tr ε) I so that it equals [`Isotropic::stiffness`] contracted with any ε
    /// (the two agree on the symmetric strains of (3.4.2)).
    ///
    /// Book: (3.4.11).
    #[inline]
    pub fn stress(&self, eps: &Dyadic<T>) -> Dyadic<T> {
        (*eps + eps.coform()) * self.mu + Dyadic::identity() * (self.lambda * eps.trace())
    }

    /// Strain from stress by the compliance law ε = (1+ν)/E σ − ν/E (tr σ) I (3.4.14).
    ///
    /// Book: (3.4.14).
    #[inline]
    pub fn strain(&self, sigma: &Dyadic<T>) -> Dyadic<T> {
        let (e, nu) = (self.young(), self.poisson());
        *sigma * ((T::one() + nu) / e) - Dyadic::identity() * (nu / e * sigma.trace())
    }
}
