//! Eigenvalues of small real matrices without a general-purpose library: Householder reduction
//! to upper Hessenberg form, then the Francis double-shift QR iteration on the Hessenberg
//! matrix (EISPACK `orthes` + `hqr`, as in Press et al., *Numerical Recipes*, §11.5–11.6).
//! Both are backward stable. A companion matrix is already Hessenberg, so polynomial roots skip
//! the reduction. For the sizes of control problems (n ≤ 64) this is several times faster than
//! a blocked library eigensolver, whose set-up cost dominates there.
//!
//! Book: §15.3 (eigenvalues), §15.7 (companion matrix, (15.7.3)).

use num_complex::Complex64;
use std::ops::{Index, IndexMut};

/// Row-major n×n working matrix.
pub(crate) struct Work {
    n: usize,
    a: Vec<f64>,
}

impl Work {
    /// From a closure of (row, column).
    pub(crate) fn from_fn(n: usize, f: impl Fn(usize, usize) -> f64) -> Self {
        let mut a = vec![0.0; n * n];
        for i in 0..n {
            for j in 0..n {
                a[i * n + j] = f(i, j);
            }
        }
        Self { n, a }
    }

    #[inline(always)]
    fn at(&self, i: usize, j: usize) -> f64 {
        self.a[i * self.n + j]
    }

    #[inline(always)]
    fn set(&mut self, i: usize, j: usize, v: f64) {
        self.a[i * self.n + j] = v;
    }

    /// Householder reduction to upper Hessenberg form (similarity, eigenvalues unchanged).
    #[allow(clippy::needless_range_loop)] // v and the matrix share the index, as in the algorithm
    pub(crate) fn hessenberg(&mut self) {
        let n = self.n;
        let mut v = vec![0.0; n];
        for k in 0..n.saturating_sub(2) {
            // reflector H = I − 2vvᵀ/vᵀv zeroing a[k+2.., k]
            let scale: f64 = (k + 1..n).map(|i| self.at(i, k).abs()).sum();
            if scale == 0.0 {
                continue;
            }
            let mut h = 0.0;
            for i in k + 1..n {
                v[i] = self.at(i, k) / scale;
                h += v[i] * v[i];
            }
            let g = if v[k + 1] > 0.0 { -h.sqrt() } else { h.sqrt() };
            h -= v[k + 1] * g;
            v[k + 1] -= g;
            // A ← HA on rows k+1.., then A ← AH on columns k+1..
            for j in k..n {
                let f: f64 = (k + 1..n).map(|i| v[i] * self.at(i, j)).sum::<f64>() / h;
                for i in k + 1..n {
                    let x = self.at(i, j) - f * v[i];
                    self.set(i, j, x);
                }
            }
            for i in 0..n {
                let f: f64 = (k + 1..n).map(|j| v[j] * self.at(i, j)).sum::<f64>() / h;
                for j in k + 1..n {
                    let x = self.at(i, j) - f * v[j];
                    self.set(i, j, x);
                }
            }
            self.set(k + 1, k, scale * g);
            for i in k + 2..n {
                self.set(i, k, 0.0);
            }
        }
    }

    /// Eigenvalues of the (upper Hessenberg) matrix by the Francis double-shift QR iteration;
    /// `None` if some eigenvalue needs more than 30 iterations.
    ///
    /// Each pass over the active block rows l..nn: the deflation search ([`Hess::split_point`])
    /// splits off a 1×1 or 2×2 block when a subdiagonal element is negligible; otherwise the
    /// shift (the trailing 2×2 block's, or an exceptional one at iterations 10 and 20) starts a
    /// double-shift sweep ([`Hess::sweep_start`]) that [`Hess::qr_sweep`] chases down the
    /// block. The arithmetic is EISPACK's, operation for operation.
    pub(crate) fn hqr(self) -> Option<Vec<Complex64>> {
        let n = self.n;
        let mut out = vec![Complex64::new(0.0, 0.0); n];
        if n == 0 {
            return Some(out);
        }
        let mut a = Hess::new(&self);
        let anorm = a.band_norm(n as isize);
        let mut nn = n as isize;
        // the accumulated exceptional shifts
        let mut t = 0.0;
        while nn >= 1 {
            let mut its = 0;
            loop {
                let l = a.split_point(nn, anorm);
                let x = a[(nn, nn)];
                if l == nn {
                    // a 1×1 block: one real root
                    out[nn as usize - 1] = Complex64::new(x + t, 0.0);
                    nn -= 1;
                    break;
                }
                let y = a[(nn - 1, nn - 1)];
                let w = a[(nn, nn - 1)] * a[(nn - 1, nn)];
                if l == nn - 1 {
                    (out[nn as usize - 2], out[nn as usize - 1]) = block_2x2(x, y, w, t);
                    nn -= 2;
                    break;
                }
                if its == 30 {
                    return None;
                }
                let shift =
                    if its == 10 || its == 20 { a.exceptional_shift(nn, x, &mut t) } else { (x, y, w) };
                its += 1;
                let (m, v) = a.sweep_start(l, nn, shift);
                a.qr_sweep(l, m, nn, v);
            }
        }
        Some(out)
    }
}

/// The two eigenvalues of a trailing 2×2 block with diagonal (y, x) and off-diagonal product w,
/// shifted back by the accumulated exceptional shift t: two real roots or a conjugate pair.
fn block_2x2(x: f64, y: f64, w: f64, t: f64) -> (Complex64, Complex64) {
    let p = 0.5 * (y - x);
    let q = p * p + w;
    let z = q.abs().sqrt();
    let x = x + t;
    if q >= 0.0 {
        // real pair: the larger root from p + sign(p)·z (no cancellation), the other as w/z
        let z = p + z.copysign(p);
        (Complex64::new(x + z, 0.0), Complex64::new(if z != 0.0 { x - w / z } else { x + z }, 0.0))
    } else {
        (Complex64::new(x + p, -z), Complex64::new(x + p, z))
    }
}

/// The Hessenberg matrix as the published algorithm indexes it: 1-based, A(i, j) =
/// h[i·(n + 1) + j] (row and column 0 unused).
struct Hess {
    n1: usize,
    h: Vec<f64>,
}

impl Index<(isize, isize)> for Hess {
    type Output = f64;
    #[inline(always)]
    fn index(&self, (i, j): (isize, isize)) -> &f64 {
        &self.h[i as usize * self.n1 + j as usize]
    }
}

impl IndexMut<(isize, isize)> for Hess {
    #[inline(always)]
    fn index_mut(&mut self, (i, j): (isize, isize)) -> &mut f64 {
        &mut self.h[i as usize * self.n1 + j as usize]
    }
}

impl Hess {
    /// The 1-based copy of a row-major working matrix.
    fn new(w: &Work) -> Self {
        let (n, n1) = (w.n, w.n + 1);
        let mut h = vec![0.0; n1 * n1];
        for i in 0..n {
            h[(i + 1) * n1 + 1..(i + 1) * n1 + 1 + n].copy_from_slice(&w.a[i * n..(i + 1) * n]);
        }
        Self { n1, h }
    }

    /// Σ|A(i, j)| over the Hessenberg band: what "negligible" is measured against when both
    /// neighbouring diagonal entries are 0.
    fn band_norm(&self, n: isize) -> f64 {
        let mut anorm = 0.0;
        for i in 1..=n {
            for j in (i - 1).max(1)..=n {
                anorm += self[(i, j)].abs();
            }
        }
        anorm
    }

    /// Deflation search: the largest l ≤ nn whose subdiagonal A(l, l−1) is negligible beside
    /// its diagonal neighbours (it is set to 0, splitting the matrix), or 1 when none is; rows
    /// l..nn are then the active unreduced block.
    fn split_point(&mut self, nn: isize, anorm: f64) -> isize {
        let mut l = nn;
        while l >= 2 {
            let mut s = self[(l - 1, l - 1)].abs() + self[(l, l)].abs();
            if s == 0.0 {
                s = anorm;
            }
            if self[(l, l - 1)].abs() + s == s {
                self[(l, l - 1)] = 0.0;
                break;
            }
            l -= 1;
        }
        l
    }

    /// The exceptional shift of iterations 10 and 20 (a stalled iteration, e.g. a cyclic
    /// permutation matrix): A ← A − xI on rows 1..nn, t += x, and the ad hoc shift
    /// (x, y, w) = (¾s, ¾s, −0.4375s²) with s = |A(nn, nn−1)| + |A(nn−1, nn−2)|.
    fn exceptional_shift(&mut self, nn: isize, x: f64, t: &mut f64) -> (f64, f64, f64) {
        *t += x;
        for i in 1..=nn {
            let v = self[(i, i)] - x;
            self[(i, i)] = v;
        }
        let s = self[(nn, nn - 1)].abs() + self[(nn - 1, nn - 2)].abs();
        let x = 0.75 * s;
        (x, x, -0.4375 * s * s)
    }

    /// Shift search: from the bottom of the active block l..nn, the row m where two
    /// consecutive subdiagonal elements are small enough to start the double-shift sweep, with
    /// the first column (p, q, r) of (A − σ₁I)(A − σ₂I) there, scaled to unit 1-norm. The
    /// entries below the second subdiagonal that the sweep will fill are cleared.
    fn sweep_start(&mut self, l: isize, nn: isize, (x, y, w): (f64, f64, f64)) -> (isize, [f64; 3]) {
        let mut m = nn - 2;
        let (mut p, mut q, mut r): (f64, f64, f64);
        loop {
            let z = self[(m, m)];
            let r0 = x - z;
            let s0 = y - z;
            p = (r0 * s0 - w) / self[(m + 1, m)] + self[(m, m + 1)];
            q = self[(m + 1, m + 1)] - z - r0 - s0;
            r = self[(m + 2, m + 1)];
            let s = p.abs() + q.abs() + r.abs();
            p /= s;
            q /= s;
            r /= s;
            if m == l {
                break;
            }
            let u = self[(m, m - 1)].abs() * (q.abs() + r.abs());
            let v = p.abs() * (self[(m - 1, m - 1)].abs() + z.abs() + self[(m + 1, m + 1)].abs());
            if u + v == v {
                break;
            }
            m -= 1;
        }
        for i in m + 2..=nn {
            self[(i, i - 2)] = 0.0;
            if i != m + 2 {
                self[(i, i - 3)] = 0.0;
            }
        }
        (m, [p, q, r])
    }

    /// One Francis double-shift QR sweep on rows l..nn and columns m..nn: a 3×3 Householder
    /// reflector per k = m..nn−1 (2×2 at the last), each chasing the bulge one row down.
    fn qr_sweep(&mut self, l: isize, m: isize, nn: isize, [mut p, mut q, mut r]: [f64; 3]) {
        // |p| + |q| + |r| of the column below the bulge (k > m)
        let mut x = 0.0f64;
        let mut k = m;
        while k < nn {
            if k != m {
                p = self[(k, k - 1)];
                q = self[(k + 1, k - 1)];
                r = if k != nn - 1 { self[(k + 2, k - 1)] } else { 0.0 };
                x = p.abs() + q.abs() + r.abs();
                if x != 0.0 {
                    p /= x;
                    q /= x;
                    r /= x;
                }
            }
            let s = (p * p + q * q + r * r).sqrt().copysign(p);
            if s != 0.0 {
                if k == m {
                    if l != m {
                        let v = -self[(k, k - 1)];
                        self[(k, k - 1)] = v;
                    }
                } else {
                    self[(k, k - 1)] = -s * x;
                }
                p += s;
                // the reflector's vector (p, q, r)/s after p ← p + s (EISPACK's scaling)
                let (x, y, z) = (p / s, q / s, r / s);
                q /= p;
                r /= p;
                // rows k..k+2 from the left
                for j in k..=nn {
                    let mut pp = self[(k, j)] + q * self[(k + 1, j)];
                    if k != nn - 1 {
                        pp += r * self[(k + 2, j)];
                        let v = self[(k + 2, j)] - pp * z;
                        self[(k + 2, j)] = v;
                    }
                    let v = self[(k + 1, j)] - pp * y;
                    self[(k + 1, j)] = v;
                    let v = self[(k, j)] - pp * x;
                    self[(k, j)] = v;
                }
                // columns k..k+2 from the right, down to row min(nn, k + 3)
                let mmin = if nn < k + 3 { nn } else { k + 3 };
                for i in l..=mmin {
                    let mut pp = x * self[(i, k)] + y * self[(i, k + 1)];
                    if k != nn - 1 {
                        pp += z * self[(i, k + 2)];
                        let v = self[(i, k + 2)] - pp * r;
                        self[(i, k + 2)] = v;
                    }
                    let v = self[(i, k + 1)] - pp * q;
                    self[(i, k + 1)] = v;
                    let v = self[(i, k)] - pp;
                    self[(i, k)] = v;
                }
            }
            k += 1;
        }
    }
}
