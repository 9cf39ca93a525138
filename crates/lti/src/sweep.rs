//! The fast frequency sweep: G(jω) over a whole grid from the zero–pole–gain factors, one
//! factor at a time across all frequencies (structure of arrays, so the inner loops
//! vectorise), with the continuous phase obtained from one atan2 per frequency by counting
//! the turns of the running product.
//!
//! Book: §16.2–16.3; notes §3.4–3.5.

use crate::zpk::Zpk;
use num_complex::Complex64;

/// G(jω) and the continuous phase in radians (the branch of [`Zpk::phase_deg`]).
pub(crate) fn sweep(zpk: &Zpk, omega: &[f64], with_phase: bool) -> (Vec<Complex64>, Vec<f64>) {
    let n = omega.len();
    let mut re = vec![1.0; n];
    let mut im = vec![0.0; n];
    let mut turns = vec![0i32; n];
    // Interleave zeros and poles so that the running product stays moderate (no overflow).
    let (z, p) = (zpk.zeros(), zpk.poles());
    for i in 0..z.len().max(p.len()) {
        if let Some(r) = z.get(i) {
            mul_factor(&mut re, &mut im, &mut turns, omega, r, false, with_phase);
        }
        if let Some(r) = p.get(i) {
            mul_factor(&mut re, &mut im, &mut turns, omega, r, true, with_phase);
        }
    }
    let k = zpk.gain();
    let tau = zpk.delay();
    let response = (0..n)
        .map(|i| {
            let g = Complex64::new(k * re[i], k * im[i]);
            if tau == 0.0 { g } else { g * Complex64::from_polar(1.0, -omega[i] * tau) }
        })
        .collect();
    let phase = if with_phase {
        let off = zpk.branch_offset();
        (0..n)
            .map(|i| im[i].atan2(re[i]) + std::f64::consts::TAU * turns[i] as f64 + off - omega[i] * tau)
            .collect()
    } else {
        Vec::new()
    };
    (response, phase)
}

/// P ← P·(jω − r) for a zero, P ← P/(jω − r) for a pole, counting the 2π turns that the
/// principal argument of P loses, plus the [0, 2π) branch of right-half-plane roots.
#[allow(clippy::too_many_arguments)] // the structure-of-arrays state of the sweep
fn mul_factor(
    re: &mut [f64],
    im: &mut [f64],
    turns: &mut [i32],
    omega: &[f64],
    r: &Complex64,
    pole: bool,
    with_phase: bool,
) {
    let rhp = r.re > 0.0;
    for i in 0..omega.len() {
        // f = jω − r = a + jb, or its reciprocal conj(f)/|f|² for a pole.
        let a = -r.re;
        let b = omega[i] - r.im;
        let (fa, fb) = if pole {
            let d = a * a + b * b;
            (a / d, -b / d)
        } else {
            (a, b)
        };
        // `+ 0.0` turns −0.0 into +0.0, so that Im ≥ 0 ⇔ arg ∈ [0, π] also for atan2.
        let fb = fb + 0.0;
        let (pa, pb) = (re[i], im[i]);
        let qa = pa * fa - pb * fb;
        let qb = pa * fb + pb * fa + 0.0;
        re[i] = qa;
        im[i] = qb;
        if with_phase {
            // arg P + arg f = arg Q + 2πk: both in [0, π] and Q below the axis ⇒ k = 1; both in
            // (−π, 0) and Q on or above it ⇒ k = −1. Pole factors: arg f = −arg(jω − r),
            // except that f on the negative real axis has arg π instead of −π.
            let up_p = pb >= 0.0;
            let up_f = fb >= 0.0;
            let up_q = qb >= 0.0;
            // Edge: arg P = arg f = π gives arg P + arg f = 2π with Q on the positive real axis.
            let both_pi = up_p && up_f && qb == 0.0 && qa > 0.0 && pa < 0.0;
            let mut k = (up_p && up_f && (!up_q || both_pi)) as i32 - (!up_p && !up_f && up_q) as i32;
            // Correct a pole factor on the negative real axis: we want −π, not π.
            if pole && fb == 0.0 && fa < 0.0 {
                k -= 1;
            }
            // Branch [0, 2π) for right-half-plane roots: arg(jω − r) gets +2π when b < 0.
            if rhp && b < 0.0 {
                k += if pole { -1 } else { 1 };
            }
            turns[i] += k;
        }
    }
}
