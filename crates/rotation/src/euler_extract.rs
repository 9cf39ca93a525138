//! Euler-angle extraction: one generic atan2/hypot algorithm for all 12 sequences
//! (book §2.13, Facts 2.13.3–8 with corrected signs; notes ch2b §3.7).
//!
//! Work on 𝓡 = 𝓡_i(α)𝓡_j(β)𝓡_k(γ) (intrinsic; an extrinsic sequence is the reversed intrinsic
//! one). With zero-based axes and ε = +1 when (i, j, k) is cyclic, −1 otherwise:
//!
//! - Tait–Bryan (i ≠ k): β = atan2(ε𝓡_ik, hypot(𝓡_ii, 𝓡_ij)), α = atan2(−ε𝓡_jk, 𝓡_kk),
//!   γ = atan2(−ε𝓡_ij, 𝓡_ii); lock when cos β = hypot(𝓡_ii, 𝓡_ij) ≈ 0.
//! - symmetric (k = i, m the third axis, ε the parity of (i, j, m)):
//!   β = atan2(hypot(𝓡_ij, 𝓡_im), 𝓡_ii), α = atan2(𝓡_ji, −ε𝓡_mi), γ = atan2(𝓡_ij, ε𝓡_im);
//!   lock when sin β ≈ 0.
//!
//! For 3-2-1 on 𝓞 = 𝓡ᵀ these are the notes' Ψ = atan2(o₁₂, o₁₁), Θ = atan2(−o₁₃,
//! hypot(o₁₁, o₁₂)), Φ = atan2(o₂₃, o₃₃), i.e. the book's F2.13.3 with the erratum
//! (2.13.17–18) corrected (b ≡ −asin r₁₃, never "b ≡ −r₁₃").

use nalgebra::Matrix3;
use vectrix_tensor::Scalar;

use crate::series::{angle_0_pi, angle_half_pi, atan2, wrap_near as wrap_angle};

use crate::{EulerAngles, EulerSequence, Quaternion, RotationError, check_rotation_matrix, rotation_about};

/// Default gimbal-lock tolerance on cos β (Tait–Bryan) or sin β (symmetric): 4ε. Below it only
/// a combination of the outer angles is determined.
pub const GIMBAL_LOCK_TOL: f64 = 4.0 * f64::EPSILON;

/// The outcome of Euler-angle extraction: two solutions, or gimbal lock as a value.
///
/// Book: Facts 2.13.3–8 (F2.13.5 and F2.13.8 for the lock, with the corrected signs of
/// (2.13.34/36)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EulerSolution<T: Scalar = f64> {
    /// Away from lock: the principal solution (β ∈ [−π/2, π/2] Tait–Bryan, β ∈ [0, π]
    /// symmetric; α, γ ∈ (−π, π]) and the alternate one (α+π, π−β, γ+π) Tait–Bryan or
    /// (α+π, −β, γ+π) symmetric, wrapped.
    Regular {
        /// Principal solution.
        principal: EulerAngles<T>,
        /// The other solution.
        alternate: EulerAngles<T>,
    },
    /// At lock (β = ±π/2 Tait–Bryan, β ∈ {0, π} symmetric) only α + sign·γ is determined.
    GimbalLock {
        /// The middle angle β.
        middle: T,
        /// The determined combination α + sign·γ ∈ (−π, π] (the first and last angle as
        /// applied, even for extrinsic sequences).
        combination: T,
        /// +1 when α + γ is determined, −1 when α − γ is.
        sign: i8,
        /// A representative: (combination, β, 0).
        representative: EulerAngles<T>,
    },
}

impl<T: Scalar> EulerSolution<T> {
    /// The principal solution, or the lock representative (γ = 0).
    pub fn principal(&self) -> EulerAngles<T> {
        match self {
            EulerSolution::Regular { principal, .. } => *principal,
            EulerSolution::GimbalLock { representative, .. } => *representative,
        }
    }

    /// `true` at gimbal lock.
    pub fn is_gimbal_lock(&self) -> bool {
        matches!(self, EulerSolution::GimbalLock { .. })
    }
}

/// Parity ε of the zero-based axes (i, j, k) all distinct: +1 cyclic, −1 anticyclic.
#[inline]
pub(crate) const fn parity(i: usize, j: usize) -> f64 {
    if (j + 3 - i) % 3 == 1 { 1.0 } else { -1.0 }
}

impl<T: Scalar> EulerAngles<T> {
    /// Extracts Euler angles of `sequence` from 𝓡_{D/A} (checked), lock tolerance
    /// [`GIMBAL_LOCK_TOL`].
    ///
    /// Book: §2.13, Facts 2.13.3–8.
    ///
    /// # Errors
    /// As [`check_rotation_matrix`] with `tol`.
    pub fn from_rotation_matrix(
        r: &Matrix3<T>,
        sequence: EulerSequence,
        tol: f64,
    ) -> Result<EulerSolution<T>, RotationError> {
        vectrix_tensor::check_tolerance(tol, "tol")?;
        check_rotation_matrix(r, tol)?;
        Ok(Self::from_rotation_matrix_unchecked(r, sequence, GIMBAL_LOCK_TOL))
    }

    /// Extraction from the Euler parameters q_{D/A}, straight from the quaternion (never
    /// through 𝓡(q)), lock tolerance [`GIMBAL_LOCK_TOL`].
    ///
    /// Why not through 𝓡(q)? Near gimbal lock the entries of 𝓡(q) that fix α and γ are
    /// O(cos β) but carry absolute rounding errors of order ε (e.g. 1 − 2(b² + c²)). So α and γ
    /// come out with independent errors ε/cos β, and the rebuilt rotation is off by as much:
    /// 0.2 at β = π/2 − 1e-15.
    ///
    /// Here the quaternion is split into two pairs whose angles are the half sum and half
    /// difference of the outer angles (Bernardes & Viollet 2022, the method scipy ≥ 1.11 uses).
    /// Near the lock only the ill-determined one of them is inexact, and that error cancels
    /// in the rotation. With q = q_i(α)⊗q_j(β)⊗q_k(γ), ε the parity of (i, j, ·), and q_i, q_j,
    /// q_k the components of q:
    ///
    /// - Tait–Bryan: A = η + q_j = (c + s) cos φ₊, B = q_i + εq_k = (c + s) sin φ₊,
    ///   C = η − q_j = (c − s) cos φ₋ and D = q_i − εq_k = (c − s) sin φ₋, where
    ///   (c, s) = (cos β/2, sin β/2) and φ± = (α ± εγ)/2. Then
    ///   β = atan2(2(ηq_j + εq_iq_k), |A, B|·|C, D|), α = φ₊ + φ₋ and γ = ε(φ₊ − φ₋).
    /// - Symmetric (m the third axis, ε the parity of (i, j, m)):
    ///   (η, q_i) = cos(β/2)(cos θ₊, sin θ₊) and (q_j, εq_m) = sin(β/2)(cos θ₋, sin θ₋), where
    ///   θ± = (α ± γ)/2. Then β = 2 atan2(|q_j, q_m|, |η, q_i|), α = θ₊ + θ₋ and γ = θ₊ − θ₋.
    ///
    /// The lock test is the one [`EulerAngles::from_rotation_matrix_unchecked`] applies:
    /// cos β = |A, B|·|C, D| (Tait–Bryan) or sin β = 2|η, q_i|·|q_j, q_m| (symmetric) at most
    /// 4ε. At the lock the determined combination is 2φ₊ or 2φ₋ (2θ₊ or 2θ₋).
    ///
    /// Book: §2.13 (Facts 2.13.3–8), §2.15; Bernardes & Viollet, "Quaternion to Euler angles
    /// conversion: a direct, general and computationally efficient method", PLoS ONE 17 (2022).
    #[inline]
    pub fn from_quaternion(q: &Quaternion<T>, sequence: EulerSequence) -> EulerSolution<T> {
        let (seq, reversed) = sequence.as_intrinsic_reversed();
        let [ai, aj, ak] = seq.axes();
        let (i, j, k) = (ai.i0(), aj.i0(), ak.i0());
        let comp = [q.b, q.c, q.d];
        let w = q.a;
        let two = T::lit(2.0);
        // The pairs A = a + ib and C = c + id (below) of either case, and from them everything:
        // |A|² = |q|²(1 + sin β), |C|² = |q|²(1 − sin β) (Tait–Bryan) or 2|q|²cos²(β/2),
        // 2|q|²sin²(β/2) (symmetric); arg(A·C) = α and arg(A·C̄) = ±γ in both cases. So one
        // square root and two atan2 (not three atan2 and two hypot); the lock only needs arg A
        // or arg C alone.
        let (a, b, c, d, e) = if i != k {
            let e = T::lit(parity(i, j));
            let (qi, qj, qk) = (comp[i], comp[j], comp[k]);
            (w + qj, qi + e * qk, w - qj, qi - e * qk, e)
        } else {
            let e = T::lit(parity(i, j));
            (w, comp[i], comp[j], e * comp[3 - i - j], e)
        };
        let (aa, cc) = (a * a + b * b, c * c + d * d);
        let n = aa + cc;
        if !(n.re() > 1e-290 && n.re() < 1e290) {
            // a quaternion far from unit length, whose squares would underflow or overflow:
            // extract from its direction (every formula here is scale-free)
            let m =
                [w, q.b, q.c, q.d].into_iter().fold(T::zero(), |m, x| if x.abs() > m { x.abs() } else { m });
            if m == T::zero() {
                // the zero quaternion is no rotation: every pair is 0, read as a lock at β = 0
                return assemble(sequence, reversed, [T::zero(); 3], Some((T::zero(), 1)));
            }
            if m.re().is_finite() {
                return Self::from_quaternion(&(*q * (T::one() / m)), sequence);
            }
        }
        // (sin β, cos β) Tait–Bryan, (sin β, cos β) symmetric, each over |A|² + |C|² = 2|q|²
        let (p, r) = ((aa - cc) / n, two * (aa * cc).sqrt() / n);
        let (alpha, beta, gamma, lock_measure, sign, use_a);
        // α = φ₊ + φ₋ = arg(A·C), and the difference φ₊ − φ₋ = arg(A·C̄)
        let sum = atan2(b * c + a * d, a * c - b * d);
        let diff = atan2(b * c - a * d, a * c + b * d);
        if i != k {
            // A = (c + s) e^{iφ₊}, C = (c − s) e^{iφ₋}, (c, s) = (cos β/2, sin β/2),
            // φ± = (α ± εγ)/2: sin β = (|A|² − |C|²)/(|A|² + |C|²), cos β = 2|A||C|/(…)
            beta = angle_half_pi(p, r);
            alpha = sum;
            gamma = e * diff;
            lock_measure = r.re();
            sign = if (e * beta).re() >= 0.0 { 1 } else { -1 };
            use_a = beta.re() >= 0.0;
        } else {
            // A = cos(β/2) e^{iθ₊}, C = sin(β/2) e^{iθ₋}, θ± = (α ± γ)/2: cos β = p, sin β = r
            beta = angle_0_pi(r, p);
            alpha = sum;
            gamma = diff;
            lock_measure = r.re();
            sign = if aa.re() >= cc.re() { 1 } else { -1 };
            use_a = sign > 0;
        }
        // At the lock the determined combination is 2 arg A or 2 arg C (the other pair ≈ 0).
        let lock = (lock_measure <= GIMBAL_LOCK_TOL)
            .then(|| (if use_a { two * atan2(b, a) } else { two * atan2(d, c) }, sign));
        assemble(sequence, reversed, [alpha, beta, gamma], lock)
    }

    /// The generic extraction without the orthonormality check, with the lock tolerance
    /// `lock_tol` on cos β (Tait–Bryan) or sin β (symmetric).
    ///
    /// Book: §2.13; notes ch2b §3.7 (atan2/hypot, never asin/acos).
    #[inline]
    pub fn from_rotation_matrix_unchecked(
        r: &Matrix3<T>,
        sequence: EulerSequence,
        lock_tol: f64,
    ) -> EulerSolution<T> {
        let (seq, reversed) = sequence.as_intrinsic_reversed();
        let [ai, aj, ak] = seq.axes();
        let (i, j, k) = (ai.i0(), aj.i0(), ak.i0());
        let (alpha, beta, gamma, lock_measure, sign);
        if i != k {
            // Tait–Bryan: 𝓡_ik = ε sin β, 𝓡_ii = cos β cos γ, 𝓡_ij = −ε cos β sin γ, …
            let e = T::lit(parity(i, j));
            let cb = hypot(r[(i, i)], r[(i, j)]);
            // β = atan2(ε𝓡_ik, cos β) as asin of the better conditioned of the normalised pair
            let sb = e * r[(i, k)];
            let row = hypot(sb, cb);
            beta = angle_half_pi(sb / row, cb / row);
            alpha = atan2(-e * r[(j, k)], r[(k, k)]);
            gamma = atan2(-e * r[(i, j)], r[(i, i)]);
            lock_measure = cb.re();
            // F2.13.5 generalised: at β = ±π/2, α + ε·sign(sin β)·γ is determined.
            sign = if (e * beta).re() >= 0.0 { 1 } else { -1 };
        } else {
            // Symmetric: 𝓡_ii = cos β, 𝓡_ij = sin β sin γ, 𝓡_im = ε sin β cos γ, …
            let m = 3 - i - j;
            let e = T::lit(parity(i, j));
            let sb = hypot(r[(i, j)], r[(i, m)]);
            let row = hypot(sb, r[(i, i)]);
            beta = angle_0_pi(sb / row, r[(i, i)] / row);
            alpha = atan2(r[(j, i)], -e * r[(m, i)]);
            gamma = atan2(r[(i, j)], e * r[(i, m)]);
            lock_measure = sb.re();
            // F2.13.8 (corrected): β = 0 fixes α + γ, β = π fixes α − γ.
            sign = if r[(i, i)].re() >= 0.0 { 1 } else { -1 };
        }
        // Gimbal lock: set γ = 0, then 𝓡_i(α) = 𝓡 𝓡_j(β)ᵀ and α is the combination.
        let lock = (lock_measure <= lock_tol).then(|| {
            let m = r * rotation_about(aj, -beta);
            let (p, q) = ((i + 1) % 3, (i + 2) % 3);
            (atan2(m[(q, p)], m[(p, p)]), sign)
        });
        assemble(sequence, reversed, [alpha, beta, gamma], lock)
    }
}

/// √(x² + y²) for the entries of a rotation (|x|, |y| ≤ 1 + rounding), by a plain square root
/// unless the sum of squares underflows (near a lock), where `hypot` keeps the digits.
#[inline]
fn hypot<T: Scalar>(x: T, y: T) -> T {
    let s = x * x + y * y;
    if s.re() > 1e-290 { s.sqrt() } else { x.hypot(y) }
}

/// The common end of both extractions: from the intrinsic angles (α, β, γ) of
/// `sequence.as_intrinsic_reversed()` (`reversed` for an extrinsic sequence), the solution in
/// the order applied. `lock` is `Some((α + sign·γ, sign))` at gimbal lock, unwrapped.
///
/// Book: Facts 2.13.3–8: the alternate solution is (α+π, π−β, γ+π) for Tait–Bryan sequences
/// and (α+π, −β, γ+π) for symmetric ones; at the lock (F2.13.5, F2.13.8 corrected) the
/// representative is (combination, β, 0).
#[inline]
pub(crate) fn assemble<T: Scalar>(
    sequence: EulerSequence,
    reversed: bool,
    [alpha, beta, gamma]: [T; 3],
    lock: Option<(T, i8)>,
) -> EulerSolution<T> {
    let out = |a: T, b: T, c: T| {
        let ang = if reversed { [c, b, a] } else { [a, b, c] };
        EulerAngles::new(sequence, ang.map(wrap_angle))
    };
    if let Some((combination, sign)) = lock {
        let combination = wrap_angle(combination);
        // Extrinsic: the reversed sequence fixes γ + sign·α = sign·(α + sign·γ).
        let applied = if reversed && sign < 0 { wrap_angle(-combination) } else { combination };
        return EulerSolution::GimbalLock {
            middle: beta,
            combination: applied,
            sign,
            representative: out(combination, beta, T::zero()),
        };
    }
    let pi = T::pi();
    let middle = if sequence.is_symmetric() { -beta } else { pi - beta };
    EulerSolution::Regular {
        principal: out(alpha, beta, gamma),
        alternate: out(alpha + pi, middle, gamma + pi),
    }
}
