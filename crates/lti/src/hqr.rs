//! Eigenvalues of small real matrices without a general-purpose library: Householder reduction
//! to upper Hessenberg form, then the Francis double-shift QR iteration on the Hessenberg
//! matrix (EISPACK `orthes` + `hqr`, as in Press et al., *Numerical Recipes*, §11.5–11.6).
//! Both are backward stable. A companion matrix is already Hessenberg, so polynomial roots skip
//! the reduction. For the sizes of control problems (n ≤ 64) this is several times faster than
//! a blocked library eigensolver, whose set-up cost dominates there.
//!
//! Book: §15.3 (eigenvalues), §15.7 (companion matrix, (15.7.3)).

use num_complex::Complex64;

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
    pub(crate) fn hqr(self) -> Option<Vec<Complex64>> {
        let n = self.n;
        let mut out = vec![Complex64::new(0.0, 0.0); n];
        if n == 0 {
            return Some(out);
        }
        // 1-based indices below, as in the published algorithm: A(i, j) = h[i·(n + 1) + j]
        let n1 = n + 1;
        let mut h = vec![0.0; n1 * n1];
        for i in 0..n {
            h[(i + 1) * n1 + 1..(i + 1) * n1 + 1 + n].copy_from_slice(&self.a[i * n..(i + 1) * n]);
        }
        macro_rules! a {
            ($i:expr, $j:expr) => {
                h[($i) as usize * n1 + ($j) as usize]
            };
        }
        let mut anorm = 0.0;
        for i in 1..=n as isize {
            for j in (i - 1).max(1)..=n as isize {
                anorm += a!(i, j).abs();
            }
        }
        let mut nn = n as isize;
        let mut t = 0.0;
        // p, q, r carry the first Householder vector from the shift search into the sweep
        let (mut p, mut q, mut r): (f64, f64, f64);
        while nn >= 1 {
            let mut its = 0;
            loop {
                // a single small subdiagonal element splits the matrix
                let mut l = nn;
                while l >= 2 {
                    let mut s = a!(l - 1, l - 1).abs() + a!(l, l).abs();
                    if s == 0.0 {
                        s = anorm;
                    }
                    if a!(l, l - 1).abs() + s == s {
                        a!(l, l - 1) = 0.0;
                        break;
                    }
                    l -= 1;
                }
                let mut x = a!(nn, nn);
                if l == nn {
                    out[nn as usize - 1] = Complex64::new(x + t, 0.0);
                    nn -= 1;
                    break;
                }
                let mut y = a!(nn - 1, nn - 1);
                let mut w = a!(nn, nn - 1) * a!(nn - 1, nn);
                if l == nn - 1 {
                    // a 2×2 block: two real roots or a conjugate pair
                    p = 0.5 * (y - x);
                    q = p * p + w;
                    let z = q.abs().sqrt();
                    x += t;
                    let (i0, i1) = (nn as usize - 2, nn as usize - 1);
                    if q >= 0.0 {
                        let z = p + z.copysign(p);
                        out[i0] = Complex64::new(x + z, 0.0);
                        out[i1] = Complex64::new(if z != 0.0 { x - w / z } else { x + z }, 0.0);
                    } else {
                        out[i0] = Complex64::new(x + p, -z);
                        out[i1] = Complex64::new(x + p, z);
                    }
                    nn -= 2;
                    break;
                }
                if its == 30 {
                    return None;
                }
                if its == 10 || its == 20 {
                    // exceptional shift
                    t += x;
                    for i in 1..=nn {
                        let v = a!(i, i) - x;
                        a!(i, i) = v;
                    }
                    let s = a!(nn, nn - 1).abs() + a!(nn - 1, nn - 2).abs();
                    x = 0.75 * s;
                    y = x;
                    w = -0.4375 * s * s;
                }
                its += 1;
                // two consecutive small subdiagonal elements: start of the double-shift sweep
                let mut m = nn - 2;
                let mut z;
                loop {
                    z = a!(m, m);
                    let r0 = x - z;
                    let s0 = y - z;
                    p = (r0 * s0 - w) / a!(m + 1, m) + a!(m, m + 1);
                    q = a!(m + 1, m + 1) - z - r0 - s0;
                    r = a!(m + 2, m + 1);
                    let s = p.abs() + q.abs() + r.abs();
                    p /= s;
                    q /= s;
                    r /= s;
                    if m == l {
                        break;
                    }
                    let u = a!(m, m - 1).abs() * (q.abs() + r.abs());
                    let v = p.abs() * (a!(m - 1, m - 1).abs() + z.abs() + a!(m + 1, m + 1).abs());
                    if u + v == v {
                        break;
                    }
                    m -= 1;
                }
                for i in m + 2..=nn {
                    a!(i, i - 2) = 0.0;
                    if i != m + 2 {
                        a!(i, i - 3) = 0.0;
                    }
                }
                // double QR step on rows l..nn and columns m..nn
                let mut k = m;
                while k < nn {
                    if k != m {
                        p = a!(k, k - 1);
                        q = a!(k + 1, k - 1);
                        r = if k != nn - 1 { a!(k + 2, k - 1) } else { 0.0 };
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
                                let v = -a!(k, k - 1);
                                a!(k, k - 1) = v;
                            }
                        } else {
                            a!(k, k - 1) = -s * x;
                        }
                        p += s;
                        x = p / s;
                        y = q / s;
                        z = r / s;
                        q /= p;
                        r /= p;
                        for j in k..=nn {
                            let mut pp = a!(k, j) + q * a!(k + 1, j);
                            if k != nn - 1 {
                                pp += r * a!(k + 2, j);
                                let v = a!(k + 2, j) - pp * z;
                                a!(k + 2, j) = v;
                            }
                            let v = a!(k + 1, j) - pp * y;
                            a!(k + 1, j) = v;
                            let v = a!(k, j) - pp * x;
                            a!(k, j) = v;
                        }
                        let mmin = if nn < k + 3 { nn } else { k + 3 };
                        for i in l..=mmin {
                            let mut pp = x * a!(i, k) + y * a!(i, k + 1);
                            if k != nn - 1 {
                                pp += z * a!(i, k + 2);
                                let v = a!(i, k + 2) - pp * r;
                                a!(i, k + 2) = v;
                            }
                            let v = a!(i, k + 1) - pp * q;
                            a!(i, k + 1) = v;
                            let v = a!(i, k) - pp;
                            a!(i, k) = v;
                        }
                    }
                    k += 1;
                }
            }
        }
        Some(out)
    }
}
