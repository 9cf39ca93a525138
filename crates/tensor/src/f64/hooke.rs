//! Hooke's law over many strains in `f64` ([`crate::HookeMap::apply_many`]): vec(σ) = H vec(ε)
//! column by column, the nine rows of a column side by side (SIMD, AVX2 where the CPU has it).
//!
//! Book: (3.4.4), (3.4.5).

use nalgebra::SMatrix;
use vectrix_simd::{FUSED_LOOPS, madd};

use crate::Dyadic;

/// σ_k = H ε_k for every strain, H of [`crate::HookeMap`]. The same products, summed in the
/// same order as nalgebra's `H * vec(ε)` (the generic code): the first column's products,
/// then each further column added, so without fusion the bits of the generic code.
pub(crate) fn apply_many(h: &SMatrix<f64, 9, 9>, eps: &[Dyadic<f64>], out: &mut [Dyadic<f64>]) {
    let mut cols = [0.0f64; 81];
    cols.copy_from_slice(h.as_slice());
    apply_all_dispatched(&cols, eps, out);
}

vectrix_simd::dispatch! {
    fn apply_all_dispatched(h: &[f64; 81], eps: &[Dyadic<f64>], out: &mut [Dyadic<f64>]) = apply_all::<FUSED_LOOPS>;
}

/// The body of [`apply_many`], H column-major; fused multiply–add when `F`.
#[inline(always)]
pub(crate) fn apply_all<const F: bool>(h: &[f64; 81], eps: &[Dyadic<f64>], out: &mut [Dyadic<f64>]) {
    for (s, e) in out.iter_mut().zip(eps) {
        let x = e.m.as_slice();
        // (3.4.5) as vec(σ) = Σⱼ Hⱼ xⱼ, Hⱼ the j-th column of H
        let mut acc = [0.0f64; 9];
        for (a, &c) in acc.iter_mut().zip(&h[..9]) {
            *a = c * x[0];
        }
        for (col, &xj) in h[9..].chunks_exact(9).zip(&x[1..]) {
            for (a, &c) in acc.iter_mut().zip(col) {
                *a = madd::<F>(c, xj, *a);
            }
        }
        s.m.as_mut_slice().copy_from_slice(&acc);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{HookeMap, Isotropic, Tensor};

    fn xorshift(s: &mut u64) -> f64 {
        *s ^= *s << 13;
        *s ^= *s >> 7;
        *s ^= *s << 17;
        (*s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    }

    /// Strains that stress the summation: zeros of both signs (the sign of a zero sum depends
    /// on the first product), subnormal, huge and mixed-magnitude components, plus random ones.
    fn hard_strains() -> Vec<Dyadic<f64>> {
        let mut s = 0x9E37_79B9_7F4A_7C15u64;
        let mut v: Vec<Dyadic<f64>> = [0.0, -0.0, 5e-324, 1e-300, 1e-16, 1.0, 1e300]
            .iter()
            .map(|&x| Dyadic { m: nalgebra::Matrix3::from_element(x) })
            .collect();
        v.push(Dyadic { m: nalgebra::Matrix3::new(-0.0, 0.0, -0.0, 1e-8, -1e8, 0.0, 3.0, -0.0, 1e-300) });
        v.extend((0..300).map(|_| Dyadic { m: nalgebra::Matrix3::from_fn(|_, _| xorshift(&mut s)) }));
        v
    }

    /// The `f64` kernel against [`HookeMap::apply`] (nalgebra's product, the generic code) on
    /// an isotropic and a random (2, 2) stiffness: without fusion the same bits, with it within
    /// 9 roundings of the sum of |products|; and the public, dispatched call (AVX2 here when
    /// the CPU has it) gives the portable body's bits.
    #[test]
    fn f64_hooke_kernel_matches_the_generic_code_bitwise() {
        let mut seed = 0x2545_F491_4F6C_DD1Du64;
        let random = Tensor {
            p: 2,
            q: 2,
            data: (0..81).map(|_| xorshift(&mut seed)).collect(),
            limit: crate::DEFAULT_MAX_COMPONENTS,
        };
        let iso = Isotropic::from_lame(1.2, 0.8).unwrap().stiffness();
        let eps = hard_strains();
        for k in [iso, random] {
            let map = HookeMap::new(&k).unwrap();
            let mut cols = [0.0f64; 81];
            cols.copy_from_slice(map.h.as_slice());
            let (mut plain, mut fused, mut public) = (eps.clone(), eps.clone(), eps.clone());
            apply_all::<false>(&cols, &eps, &mut plain);
            apply_all::<true>(&cols, &eps, &mut fused);
            map.apply_many(&eps, &mut public).unwrap();
            let mut portable = eps.clone();
            apply_all::<FUSED_LOOPS>(&cols, &eps, &mut portable);
            for (i, e) in eps.iter().enumerate() {
                let want = map.apply(e);
                let abs = map.h.abs() * nalgebra::SVector::<f64, 9>::from_column_slice(e.m.abs().as_slice());
                for r in 0..9 {
                    let (w, p, f) = (want.m[r], plain[i].m[r], fused[i].m[r]);
                    assert_eq!(p.to_bits(), w.to_bits(), "strain {i}, entry {r}");
                    assert!(
                        (f - w).abs() <= 9.0 * f64::EPSILON * abs[r],
                        "strain {i}, entry {r}: {f:e} vs {w:e}"
                    );
                    assert_eq!(public[i].m[r].to_bits(), portable[i].m[r].to_bits(), "strain {i}, entry {r}");
                }
            }
        }
    }
}
