//! Jacobi elliptic functions sn, cn, dn and the complete elliptic integral K, by the
//! arithmetic–geometric mean (descending Landen / Gauss transformation).
//!
//! They give the exact solutions of the large-amplitude pendulum and of the torque-free
//! asymmetric rigid body used by the work–precision harness.
//!
//! Book: §4.11 (reference motions); A&S §16.4 (descending Landen transformation), §17.6
//! (AGM for K); Bulirsch (1965), Numer. Math. 7.

/// Complete elliptic integral of the first kind K(m) = π / (2·AGM(1, √(1−m))), parameter
/// m = k² ∈ [0, 1). Returns `None` outside [0, 1) (K(1) = ∞).
///
/// Book: A&S (17.6.1)–(17.6.3).
pub fn elliptic_k(m: f64) -> Option<f64> {
    if !(0.0..1.0).contains(&m) {
        return None;
    }
    let (mut a, mut b) = (1.0_f64, (1.0 - m).sqrt());
    // AGM: aₙ₊₁ = (aₙ + bₙ)/2, bₙ₊₁ = √(aₙbₙ), quadratic convergence
    for _ in 0..40 {
        if (a - b).abs() <= f64::EPSILON * a {
            break;
        }
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    Some(core::f64::consts::FRAC_PI_2 / a)
}

/// (sn, cn, dn)(u | m) for the parameter m = k² ∈ [0, 1], by the descending Gauss
/// (Landen) transformation in Bulirsch's form. Returns `None` for m outside [0, 1] or
/// non-finite u.
///
/// # Degenerate inputs
/// m = 0 gives (sin u, cos u, 1); m = 1 gives (tanh u, sech u, sech u).
///
/// Book: A&S (16.4.1)–(16.4.4), (16.6.1)–(16.6.3) for the limits.
pub fn sncndn(u: f64, m: f64) -> Option<(f64, f64, f64)> {
    if !(0.0..=1.0).contains(&m) || !u.is_finite() {
        return None;
    }
    let mut emc = 1.0 - m;
    if emc == 0.0 {
        // m = 1: the functions degenerate to hyperbolic ones (A&S 16.6)
        let sech = 1.0 / u.cosh();
        return Some((u.tanh(), sech, sech));
    }
    // convergence threshold: the next iterate's error is CA², below ε
    const CA: f64 = 1e-8;
    let (mut em, mut en) = ([0.0_f64; 16], [0.0_f64; 16]);
    let (mut a, mut c, mut dn) = (1.0_f64, 1.0_f64, 1.0_f64);
    let mut l = 0;
    // descending transformation: aₙ₊₁ = (aₙ + √(aₙ² m′ₙ))/2 (the AGM of 1 and √(1−m))
    for i in 0..16 {
        l = i;
        em[i] = a;
        emc = emc.sqrt();
        en[i] = emc;
        c = 0.5 * (a + emc);
        if (a - emc).abs() <= CA * a {
            break;
        }
        emc *= a;
        a = c;
    }
    let u = u * c;
    let (mut sn, mut cn) = (u.sin(), u.cos());
    if sn != 0.0 {
        // ascend back through the transformations
        let mut a = cn / sn;
        c *= a;
        for ii in (0..=l).rev() {
            let b = em[ii];
            a *= c;
            c *= dn;
            dn = (en[ii] + a) / (b + a);
            a = c / b;
        }
        // 1/√(c² + 1) by hypot: c = cn/sn is huge near the zeros of sn, where c² overflows
        let s = 1.0 / c.hypot(1.0);
        sn = if sn >= 0.0 { s } else { -s };
        cn = c * sn;
    }
    // Rounding of u·c for |u| near f64::MAX can still leave a non-number: none then.
    (sn.is_finite() && cn.is_finite() && dn.is_finite()).then_some((sn, cn, dn))
}

#[cfg(test)]
mod tests {
    use super::*;

    // The identities sn² + cn² = 1, dn² + m sn² = 1 (A&S 16.9.1) and sn(K) = 1 (A&S 16.5).
    #[test]
    fn identities_and_quarter_period() {
        for &m in &[0.0, 1e-6, 0.3, 0.9, 0.99, 0.999999] {
            for i in 0..50 {
                let u = -7.0 + 0.3 * i as f64;
                let (sn, cn, dn) = sncndn(u, m).unwrap();
                assert!((sn * sn + cn * cn - 1.0).abs() < 8.0 * f64::EPSILON);
                assert!((dn * dn + m * sn * sn - 1.0).abs() < 8.0 * f64::EPSILON);
            }
            let k = elliptic_k(m).unwrap();
            let (sn, cn, _) = sncndn(k, m).unwrap();
            assert!((sn - 1.0).abs() < 1e-14 && cn.abs() < 1e-7, "m = {m}: sn(K) = {sn}, cn = {cn}");
        }
    }

    // d sn/du = cn dn (A&S 16.16.1), checked by a central difference.
    #[test]
    fn derivative_of_sn() {
        let (m, h) = (0.7, 1e-5);
        for i in 0..20 {
            let u = 0.37 * i as f64;
            let (_, cn, dn) = sncndn(u, m).unwrap();
            let d = (sncndn(u + h, m).unwrap().0 - sncndn(u - h, m).unwrap().0) / (2.0 * h);
            // central difference error h²/6·|sn‴| ≲ 1e-10
            assert!((d - cn * dn).abs() < 1e-9);
        }
    }

    #[test]
    fn limits_and_bad_input() {
        let (sn, cn, dn) = sncndn(0.8, 0.0).unwrap();
        assert!(
            (sn - 0.8f64.sin()).abs() < 4.0 * f64::EPSILON && (cn - 0.8f64.cos()).abs() < 4.0 * f64::EPSILON
        );
        assert_eq!(dn, 1.0);
        assert!((elliptic_k(0.0).unwrap() - core::f64::consts::FRAC_PI_2).abs() < 4.0 * f64::EPSILON);
        assert!(sncndn(1.0, 1.5).is_none() && elliptic_k(1.0).is_none() && sncndn(f64::NAN, 0.5).is_none());
    }
}
