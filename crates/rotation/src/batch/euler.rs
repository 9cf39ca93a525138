//! Euler angles of many rotations at once ([`EulerAngles::from_quaternions`]).
//!
//! Book: §2.13, Facts 2.13.3–8 (corrected signs), (2.15.14).

use vectrix_simd::vmath::atan2;
use vectrix_simd::{FUSED_LOOPS, madd};

use super::BLOCK;
use crate::euler_extract::{GIMBAL_LOCK_TOL, assemble, parity};
use crate::series::wrap_near;
use crate::{EulerAngles, EulerSequence, EulerSolution, Quaternion, ROTATION_TOL, RotationError};

vectrix_simd::dispatch! {
    fn euler_simd(
        qs: &[Quaternion<f64>],
        sequence: EulerSequence,
        angles: &mut [[f64; 3]],
        locks: &mut Vec<(usize, EulerSolution<f64>)>
    ) -> Result<(), RotationError> = euler_all::<FUSED_LOOPS>;
}

/// Principal Euler angles of many rotations, from [`EulerAngles::from_quaternions`]: one
/// `[α, β, γ]` per rotation (in the order applied), the gimbal-locked elements listed with
/// their full [`EulerSolution`], and the alternate solutions on request.
///
/// Book: §2.13, Facts 2.13.3–8.
#[derive(Debug, Clone, PartialEq)]
pub struct EulerBatch {
    sequence: EulerSequence,
    angles: Vec<[f64; 3]>,
    locks: Vec<(usize, EulerSolution<f64>)>,
}

impl EulerBatch {
    /// The sequence of every element.
    pub fn sequence(&self) -> EulerSequence {
        self.sequence
    }

    /// Number of rotations.
    pub fn len(&self) -> usize {
        self.angles.len()
    }

    /// `true` for an empty batch.
    pub fn is_empty(&self) -> bool {
        self.angles.is_empty()
    }

    /// The principal angles [α, β, γ] (order applied) of each rotation; at gimbal lock the
    /// representative (combination, β, 0), as scipy's `as_euler` does (scipy also warns).
    pub fn angles(&self) -> &[[f64; 3]] {
        &self.angles
    }

    /// The angles, consuming the batch.
    pub fn into_angles(self) -> Vec<[f64; 3]> {
        self.angles
    }

    /// The gimbal-locked elements, ascending: (index, [`EulerSolution::GimbalLock`]).
    pub fn gimbal_locks(&self) -> &[(usize, EulerSolution<f64>)] {
        &self.locks
    }

    /// Element `i` as [`EulerAngles`] (the principal solution or the lock representative);
    /// `None` past the end.
    pub fn principal(&self, i: usize) -> Option<EulerAngles<f64>> {
        self.angles.get(i).map(|a| EulerAngles::new(self.sequence, *a))
    }

    /// Element `i` as the full [`EulerSolution`], what [`EulerAngles::from_quaternion`] returns
    /// for it: `Regular` with the principal and the alternate solution, or `GimbalLock`.
    /// `None` past the end.
    ///
    /// Book: Facts 2.13.3–8 (the alternate is (α+π, π−β, γ+π) for Tait–Bryan sequences and
    /// (α+π, −β, γ+π) for symmetric ones, wrapped into (−π, π]).
    pub fn solution(&self, i: usize) -> Option<EulerSolution<f64>> {
        let a = *self.angles.get(i)?;
        if let Ok(k) = self.locks.binary_search_by_key(&i, |(j, _)| *j) {
            return Some(self.locks[k].1);
        }
        // Back to the intrinsic order the extraction works in, then its common ending.
        let (_, reversed) = self.sequence.as_intrinsic_reversed();
        let intrinsic = if reversed { [a[2], a[1], a[0]] } else { a };
        Some(assemble(self.sequence, reversed, intrinsic, None))
    }
}

impl EulerAngles<f64> {
    /// Euler angles of many rotations at once from their Euler parameters q_{D/A}, in SIMD:
    /// the quaternion-pair extraction of [`EulerAngles::from_quaternion`] (accurate through
    /// gimbal lock, where the route through 𝓡(q) is not). Element by element it agrees with
    /// [`EulerAngles::from_quaternion`] to a few ulps, and gimbal lock is decided by that
    /// function itself. scipy's `Rotation.as_euler(seq)` is the peer.
    ///
    /// Book: §2.13, Facts 2.13.3–8 (corrected signs), (2.15.14).
    ///
    /// # Errors
    /// [`RotationError::AtElement`] for the first quaternion that is not finite
    /// ([`RotationError::NonFinite`]) or not a unit quaternion within [`ROTATION_TOL`]
    /// ([`RotationError::NotUnit`]).
    ///
    /// ```
    /// use vectrix_rotation::{EulerAngles, EulerSequence, Quaternion};
    ///
    /// let e = EulerAngles::new(EulerSequence::S321, [0.3, -0.2, 0.1]);
    /// let batch = EulerAngles::from_quaternions(&[e.quaternion(); 3], EulerSequence::S321)?;
    /// assert!((batch.angles()[2][0] - 0.3).abs() < 1e-15);
    /// assert!(batch.gimbal_locks().is_empty());
    /// # Ok::<(), vectrix_rotation::RotationError>(())
    /// ```
    #[doc(alias = "as_euler")]
    pub fn from_quaternions(
        qs: &[Quaternion<f64>],
        sequence: EulerSequence,
    ) -> Result<EulerBatch, RotationError> {
        let mut batch = EulerBatch { sequence, angles: vec![[0.0; 3]; qs.len()], locks: Vec::new() };
        let (angles, locks) = (&mut batch.angles, &mut batch.locks);
        euler_simd(qs, sequence, angles, locks)?;
        Ok(batch)
    }
}

/// Euler extraction over all blocks (see [`EulerAngles::from_quaternions`]): one loop per
/// intrinsic sequence (i, j, k), monomorphised so the component indices are constants, straight
/// from the quaternions into the angles.
#[inline(always)]
fn euler_all<const F: bool>(
    qs: &[Quaternion<f64>],
    sequence: EulerSequence,
    angles: &mut [[f64; 3]],
    locks: &mut Vec<(usize, EulerSolution<f64>)>,
) -> Result<(), RotationError> {
    let (seq, reversed) = sequence.as_intrinsic_reversed();
    let [ai, aj, ak] = seq.axes();
    macro_rules! by_sequence {
        ($(($i:literal, $j:literal, $k:literal)),*) => {
            match (ai.i0(), aj.i0(), ak.i0()) {
                $(($i, $j, $k) => euler_seq::<F, $i, $j, $k>(qs, sequence, reversed, angles, locks),)*
                _ => unreachable!("EulerSequence holds distinct adjacent axes"),
            }
        };
    }
    by_sequence!(
        (0, 1, 2),
        (0, 2, 1),
        (1, 2, 0),
        (1, 0, 2),
        (2, 0, 1),
        (2, 1, 0),
        (0, 1, 0),
        (0, 2, 0),
        (1, 2, 1),
        (1, 0, 1),
        (2, 0, 2),
        (2, 1, 2)
    )
}

/// [`euler_all`] for the intrinsic sequence (I, J, K) (zero-based; `reversed` for an extrinsic
/// one, whose angles come out in the opposite order).
#[inline(always)]
fn euler_seq<const F: bool, const I: usize, const J: usize, const K: usize>(
    qs: &[Quaternion<f64>],
    sequence: EulerSequence,
    reversed: bool,
    angles: &mut [[f64; 3]],
    locks: &mut Vec<(usize, EulerSolution<f64>)>,
) -> Result<(), RotationError> {
    let e = parity(I, J);
    let m = 3 - I - J; // the third axis of a symmetric sequence (I = K)
    // Flag lanes near the lock for the one-rotation code, which decides (its hypot may differ
    // from sqrt(x² + y²) in the last bit).
    let lock_flag = 2.0 * GIMBAL_LOCK_TOL;
    for (blk, (inp, outp)) in qs.chunks(BLOCK).zip(angles.chunks_mut(BLOCK)).enumerate() {
        let mut rare = false;
        for (q, out) in inp.iter().zip(outp.iter_mut()) {
            // The half-sum/half-difference pairs of `EulerAngles::from_quaternion` (Bernardes &
            // Viollet), the same formulas in the same order.
            let (w, comp) = (q.a, [q.b, q.c, q.d]);
            let (alpha, beta, gamma, measure);
            if I != K {
                let (qi, qj, qk) = (comp[I], comp[J], comp[K]);
                let (a, b, c, d) = (w + qj, qi + e * qk, w - qj, qi - e * qk);
                measure = madd::<F>(a, a, b * b).sqrt() * madd::<F>(c, c, d * d).sqrt();
                beta = atan2::<F>(2.0 * (w * qj + e * qi * qk), measure);
                let (phi_p, phi_m) = (atan2::<F>(b, a), atan2::<F>(d, c));
                alpha = phi_p + phi_m;
                gamma = e * (phi_p - phi_m);
            } else {
                let (a, b, c, d) = (w, comp[I], comp[J], e * comp[m]);
                let (h_ab, h_cd) = (madd::<F>(a, a, b * b).sqrt(), madd::<F>(c, c, d * d).sqrt());
                beta = 2.0 * atan2::<F>(h_cd, h_ab);
                let (th_p, th_m) = (atan2::<F>(b, a), atan2::<F>(d, c));
                alpha = th_p + th_m;
                gamma = th_p - th_m;
                measure = 2.0 * h_ab * h_cd;
            }
            let (alpha, gamma) = (wrap_near(alpha), wrap_near(gamma));
            *out = if reversed { [gamma, beta, alpha] } else { [alpha, beta, gamma] };
            let n2 =
                madd::<F>(w, w, madd::<F>(comp[0], comp[0], madd::<F>(comp[1], comp[1], comp[2] * comp[2])));
            rare |= (measure <= lock_flag) | n2.is_nan() | ((n2 - 1.0).abs() > ROTATION_TOL);
        }
        if rare {
            for (l, (q, out)) in inp.iter().zip(outp.iter_mut()).enumerate() {
                let index = blk * BLOCK + l;
                q.check_unit(ROTATION_TOL).map_err(|err| RotationError::at(index, err))?;
                let s = EulerAngles::from_quaternion(q, sequence);
                if let EulerSolution::GimbalLock { representative, .. } = s {
                    *out = representative.angles;
                    locks.push((index, s));
                }
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::tests::thetas;

    /// Both builds of the Euler extraction agree with the one-rotation code in every sequence.
    #[test]
    fn both_builds_of_the_euler_extraction_match_one_by_one() {
        let qs: Vec<Quaternion<f64>> = thetas().iter().map(Quaternion::from_angle_vector).collect();
        for seq in EulerSequence::ALL.into_iter().flat_map(|s| [s, s.extrinsic()]) {
            for fused in [false, true] {
                let (mut angles, mut locks) = (vec![[0.0; 3]; qs.len()], Vec::new());
                if fused {
                    euler_all::<true>(&qs, seq, &mut angles, &mut locks)
                } else {
                    euler_all::<false>(&qs, seq, &mut angles, &mut locks)
                }
                .unwrap();
                assert!(locks.is_empty());
                for (q, a) in qs.iter().zip(&angles) {
                    let one = EulerAngles::from_quaternion(q, seq).principal().angles;
                    for (x, y) in a.iter().zip(&one) {
                        let d = wrap_near(x - y).abs();
                        assert!(d <= 4.0 * f64::EPSILON * 4.0, "{seq:?} fused = {fused}: {a:?} vs {one:?}");
                    }
                }
            }
        }
    }

    /// The public, dispatched extraction (AVX2 here when the CPU has it) gives the bits of the
    /// portable body of the build's choice, also at gimbal lock (β = ±π/2) and near it.
    #[test]
    fn dispatched_euler_extraction_is_the_portable_body_bitwise() {
        let mut qs: Vec<Quaternion<f64>> = thetas().iter().map(Quaternion::from_angle_vector).collect();
        let half_pi = core::f64::consts::FRAC_PI_2;
        for b in [half_pi, -half_pi, half_pi - 1e-8, half_pi - 1e-4, 0.0, 1e-16] {
            qs.push(EulerAngles::new(EulerSequence::S321, [0.3, b, -1.2]).quaternion());
        }
        for seq in [EulerSequence::S321, EulerSequence::S313.extrinsic()] {
            let batch = EulerAngles::from_quaternions(&qs, seq).unwrap();
            let (mut angles, mut locks) = (vec![[0.0; 3]; qs.len()], Vec::new());
            euler_all::<FUSED_LOOPS>(&qs, seq, &mut angles, &mut locks).unwrap();
            for (d, p) in batch.angles().iter().zip(&angles) {
                assert_eq!(d.map(f64::to_bits), p.map(f64::to_bits), "{seq:?}");
            }
            assert_eq!(batch.gimbal_locks(), &locks[..]);
        }
    }
}
