//! §3.4: stress, strain and the isotropic Hooke's law σ = (𝒦⊗ε)_(2,3),(3,1).

use nalgebra::Matrix3;
use vectrix::prelude::*;

use crate::common::*;
use crate::support::{EPS, assert_abs, assert_abs_slice, assert_printed, assert_printed_slice, assert_rel};

/// A symmetric strain (3.4.2) in frame `a`.
fn strain(a: &Frame, e: [f64; 6]) -> Dyadic {
    a.dyadic(&Matrix3::new(e[0], e[3], e[4], e[3], e[1], e[5], e[4], e[5], e[2]))
}

#[test]
fn eq_3_4_12_isotropic_hooke_law_by_contraction() {
    // (3.4.4), (3.4.11), (3.4.12): σ = (𝒦⊗ε)_(2,3),(3,1) = 2μ ε + λ (tr ε) I
    //   = 2μ (U4⊗ε)_(2,3),(3,1) + λ (U4⊗ε)_(2,3),(3,2).
    let a = Frame::new();
    let m = Isotropic::from_lame(1.2, 0.8).unwrap();
    let eps = strain(&a, [1e-3, -2e-4, 5e-4, 3e-4, -1e-4, 2e-4]);
    let by_contraction = hooke(&m.stiffness(), &eps).unwrap();
    assert_dyadic_abs(&by_contraction, &m.stress(&eps), &a, TOL);
    let u4 = Tensor::u4();
    let te = Tensor::from_dyadic(&eps);
    let first = u4.contracted_product(&te, &[(2, 3), (3, 1)]).unwrap().to_dyadic().unwrap();
    let second = u4.contracted_product(&te, &[(2, 3), (3, 2)]).unwrap().to_dyadic().unwrap();
    assert_dyadic_abs(&(first * (2.0 * m.mu()) + second * m.lambda()), &by_contraction, &a, TOL);
    let map = HookeMap::new(&m.stiffness()).unwrap();
    assert_dyadic_abs(&map.apply(&eps), &by_contraction, &a, TOL);
}

#[test]
fn eq_3_4_5_hooke_map_for_many_strains() {
    // HookeMap::apply_many (f64: the fused kernel, AVX2 + FMA where the CPU has them) against
    // σ_kn = Σ_lm c_klmn ε_ml written out from (3.4.5) with the components in frame a, for a
    // stiffness with 81 distinct entries (no symmetry to hide an index slip) and 37 strains
    // (not a multiple of any vector width). Each σ entry is a sum of 9 products of size ≤ 6
    // with |ε| ≤ 1: 16ε relative to the sum of magnitudes, bounded here by 9·6 = 54.
    let a = Frame::new();
    let data: Vec<f64> = (0..81).map(|i| (((i * 37) % 81) as f64 - 40.0) / 7.0).collect();
    let k = tensor_from(&a, 2, 2, &data);
    let kr = k.resolve(&a);
    let c = |i: usize, j: usize, p: usize, q: usize| kr[(3 * i + j, 3 * p + q)];
    let mut seed = 5u64;
    let mut next = || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        ((seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    };
    let strains: Vec<Dyadic> = (0..37).map(|_| a.dyadic(&Matrix3::from_fn(|_, _| next()))).collect();
    let map = HookeMap::new(&k).unwrap();
    let mut out = vec![Dyadic::zero(); strains.len()];
    map.apply_many(&strains, &mut out).unwrap();
    for (e, got) in strains.iter().zip(&out) {
        let er = e.resolve(&a);
        let want = Matrix3::from_fn(|kk, n| {
            (0..3)
                .flat_map(|l| (0..3).map(move |m| (l, m)))
                .map(|(l, m)| c(kk, l, m, n) * er[(m, l)])
                .sum::<f64>()
        });
        assert_abs_slice(got.resolve(&a).as_slice(), want.as_slice(), 16.0 * EPS * 54.0);
    }
    // other scalar types take the generic path: dual numbers carry the same values
    use vectrix::num_dual::Dual64;
    let ad = Frame::<Dual64>::identity();
    let kd = ad.tensor(2, 2, &kr.map(Dual64::from)).unwrap();
    let mapd = HookeMap::new(&kd).unwrap();
    let strains_d: Vec<Dyadic<Dual64>> =
        strains.iter().map(|e| ad.dyadic(&e.resolve(&a).map(Dual64::from))).collect();
    let mut out_d = vec![Dyadic::<Dual64>::zero(); strains.len()];
    mapd.apply_many(&strains_d, &mut out_d).unwrap();
    for (d, f) in out_d.iter().zip(&out) {
        let re: Vec<f64> = d.resolve(&ad).iter().map(|x| x.re).collect();
        assert_abs_slice(&re, f.resolve(&a).as_slice(), 16.0 * EPS * 54.0);
    }
}

#[test]
fn eq_3_4_5_component_form_and_conventional_c() {
    // (3.4.5): σ_ij = Σ_kl c_iklj ε_lk with c_klmn = μ(δ_km δ_ln + δ_kl δ_mn) + λ δ_kn δ_lm;
    // the conventional C_ijkl (σ_ij = C_ijkl ε_kl) is C_ijkl = c_ilkj (ch. 3 notes), here the
    // textbook λ δ_ij δ_kl + μ(δ_ik δ_jl + δ_il δ_jk).
    let a = Frame::new();
    let m = Isotropic::from_lame(2.0, 0.5).unwrap();
    let k = m.stiffness().resolve(&a);
    let c = |i: usize, j: usize, k_: usize, l: usize| k[(3 * i + j, 3 * k_ + l)];
    let d = |i: usize, j: usize| if i == j { 1.0 } else { 0.0 };
    for i in 0..3 {
        for j in 0..3 {
            for p in 0..3 {
                for q in 0..3 {
                    let want =
                        m.mu() * (d(i, p) * d(j, q) + d(i, j) * d(p, q)) + m.lambda() * d(i, q) * d(j, p);
                    assert_eq!(c(i, j, p, q), want);
                    // Conventional C_ijpq = c_iqpj.
                    let conventional =
                        m.lambda() * d(i, j) * d(p, q) + m.mu() * (d(i, p) * d(j, q) + d(i, q) * d(j, p));
                    assert_eq!(c(i, q, p, j), conventional);
                    // L3981 erratum: the symmetry is c_iklj = c_jkli (printed "c_jklj").
                    assert_eq!(c(i, j, p, q), c(q, j, p, i));
                }
            }
        }
    }
}

#[test]
fn eq_3_4_16_steel_lame_constants_and_stress() {
    // (3.4.15–16) for steel, E = 200 GPa, ν = 0.3: μ = 76.923 GPa, λ = 115.385 GPa,
    // K = 166.667 GPa; ε = diag(1e-3, 0, 0) gives σ = diag(269.23, 115.38, 115.38) MPa
    // (ch. 3 notes §4). The closed forms are exact: μ = E/(2(1+ν)) = 200/2.6,
    // λ = Eν/((1+ν)(1−2ν)) = 60/0.52, K = E/(3(1−2ν)) = 200/1.2 GPa, and σ = λ tr ε I + 2μ ε,
    // so σ₁₁ = (λ + 2μ)·10⁻³ and σ₂₂ = σ₃₃ = λ·10⁻³: checked to a few ε, then to the printed digits.
    let a = Frame::new();
    let steel = Isotropic::from_young_poisson(200e9, 0.3).unwrap();
    let (mu, lambda, bulk) = (200.0 / 2.6, 60.0 / 0.52, 200.0 / 1.2);
    assert_rel(steel.mu() / 1e9, mu, 4.0 * EPS);
    assert_rel(steel.lambda() / 1e9, lambda, 4.0 * EPS);
    assert_rel(steel.bulk() / 1e9, bulk, 4.0 * EPS);
    assert_printed(steel.mu() / 1e9, "76.923");
    assert_printed(steel.lambda() / 1e9, "115.385");
    assert_printed(steel.bulk() / 1e9, "166.667");
    let sigma = steel.stress(&strain(&a, [1e-3, 0.0, 0.0, 0.0, 0.0, 0.0])).resolve(&a) / 1e6;
    assert_rel(sigma[(0, 0)], lambda + 2.0 * mu, 8.0 * EPS);
    assert_rel(sigma[(1, 1)], lambda, 8.0 * EPS);
    assert_rel(sigma[(2, 2)], lambda, 8.0 * EPS);
    assert_printed_slice(&[sigma[(0, 0)], sigma[(1, 1)], sigma[(2, 2)]], &["269.23", "115.38", "115.38"]);
    assert_eq!(sigma[(0, 1)], 0.0, "no shear from a normal strain");
}

#[test]
fn eq_3_4_15_lame_and_engineering_constants_round_trip() {
    // (3.4.15) ν = λ/(2(λ+μ)), E = μ(3λ+2μ)/(λ+μ) inverts (3.4.16).
    for (e, nu) in [(200e9, 0.3), (1.0, 0.0), (70e9, 0.33), (5.0, -0.5), (1.0, 0.499)] {
        let m = Isotropic::from_young_poisson(e, nu).unwrap();
        assert_abs(m.young() / e, 1.0, 1e3 * EPS); // 1 − 2ν amplifies rounding near ν = ½
        assert_abs(m.poisson(), nu, 1e3 * EPS);
    }
}

#[test]
fn eq_3_4_14_compliance_inverts_hooke() {
    // (3.4.14): ε = (1+ν)/E σ − ν/E (tr σ) I recovers the strain (the notes report 1e-19
    // absolute for 1e-3 strains in steel).
    let a = Frame::new();
    let steel = Isotropic::from_young_poisson(200e9, 0.3).unwrap();
    let eps = strain(&a, [1e-3, -3e-4, 2e-4, 5e-4, 0.0, -1e-4]);
    assert_dyadic_abs(&steel.strain(&steel.stress(&eps)), &eps, &a, 1e-18);
}

#[test]
fn isotropic_stiffness_is_the_same_in_every_frame() {
    // Notes §2 item 1: isotropic 𝒦 is invariant, 𝒦|_B = 𝒦|_A for all right-handed B.
    let a = Frame::new();
    let b = a.rotated_by_rotor(&Rotor::from_axis_angle(&a.vector([1.0, -2.0, 0.5]), 2.3).unwrap());
    let k = Isotropic::from_lame(1.5, 0.7).unwrap().stiffness();
    crate::support::assert_rel_slice(k.resolve(&b).as_slice(), k.resolve(&a).as_slice(), TOL);
}

#[test]
fn invalid_materials_and_stiffness_types_are_errors() {
    assert!(matches!(Isotropic::from_young_poisson(200e9, 0.5), Err(TensorError::OutOfRange { .. })));
    assert!(matches!(Isotropic::from_young_poisson(-1.0, 0.3), Err(TensorError::OutOfRange { .. })));
    assert!(matches!(Isotropic::from_young_poisson(f64::NAN, 0.3), Err(TensorError::OutOfRange { .. })));
    assert!(matches!(Isotropic::from_lame(1.0, 0.0), Err(TensorError::OutOfRange { .. })));
    assert!(matches!(Isotropic::from_lame(-1.0, 1.0), Err(TensorError::OutOfRange { .. })));
    assert!(matches!(Isotropic::from_lame(f64::INFINITY, 1.0), Err(TensorError::NonFinite { .. })));
    let eps = Dyadic::<f64>::identity();
    assert!(matches!(hooke(&Tensor::identity(), &eps), Err(TensorError::Shape { .. })));
    assert!(matches!(HookeMap::new(&Tensor::<f64>::levi_civita()), Err(TensorError::Shape { .. })));
    let map = HookeMap::new(&Tensor::u4()).unwrap();
    assert!(matches!(map.apply_many(&[eps], &mut []), Err(TensorError::Shape { .. })));
}

mod prop {
    use proptest::prelude::*;
    use vectrix::prelude::*;

    use crate::common::*;
    use crate::support::frame;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Hooke's law is frame-free: σ|_B from the frame-free contraction equals the numeric
        /// contraction of 𝒦|_B ⊗ ε|_B (notes §2 items 1 and 6).
        #[test]
        fn hooke_commutes_with_resolution(
            b in frame(), lam in 0.1..3.0f64, mu in 0.1..3.0f64, e in proptest::array::uniform6(-1.0..1.0f64),
        ) {
            let a = Frame::new();
            let m = Isotropic::from_lame(lam, mu).unwrap();
            let eps = super::strain(&a, e);
            let sigma = hooke(&m.stiffness(), &eps).unwrap();
            let prod = m.stiffness().resolve(&b).kronecker(&Tensor::from_dyadic(&eps).resolve(&b));
            let want = contract_array(&flat(&prod), 3, 3, &[(2, 3), (3, 1)]);
            let got: Vec<f64> = sigma.resolve(&b).transpose().iter().copied().collect();
            crate::support::assert_rel_slice(&got, &want, 16.0 * TOL);
            assert_dyadic_abs(&m.strain(&m.stress(&eps)), &eps, &a, 1e3 * TOL);
        }
    }
}
