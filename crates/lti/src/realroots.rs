//! The positive real roots of a real polynomial without computing the complex ones: Descartes'
//! rule of signs with the continued-fraction (Vincent–Akritas–Strzeboński) subdivision, each
//! sign certified against a running bound on the rounding of the Taylor shifts, then a few steps
//! of the Illinois method inside each isolating interval. Far cheaper than the eigenvalues of
//! the companion matrix when, as for the crossover polynomials of the margins, most roots are
//! complex or negative.
//!
//! Book: §16.3 (the crossover equations of the margins); notes §3.6.

/// A node of the subdivision: q(y) (ascending powers) with absolute bounds on the rounding of
/// its coefficients, whose positive roots y are the roots x = (a·y + b)/(c·y + d) of p.
struct Node {
    q: Vec<f64>,
    err: Vec<f64>,
    m: [f64; 4],
}

impl Node {
    /// Whether q[k] could be zero or of either sign within its rounding.
    #[inline]
    fn uncertain(&self, k: usize) -> bool {
        self.q[k].abs() <= self.err[k]
    }
}

/// Half a unit in the last place.
const U: f64 = f64::EPSILON / 2.0;

/// Degrees below this use stack scratch in [`shift`].
const SMALL: usize = 64;

/// Binomial coefficients C(k, j) stored by j (row j holds C(j, j), C(j+1, j), …, C(n, j) at
/// offsets j…n, so the sums of [`shift`] run over contiguous memory), for degrees up to `n`
/// (exact in f64 to n = 56; beyond that the rounding is covered by the error bound's γ).
fn binomials(n: usize) -> Vec<f64> {
    let w = n + 1;
    let mut c = vec![0.0; w * w];
    // Pascal's rule C(k, j) = C(k−1, j−1) + C(k−1, j), row j at c[j·w + k]
    for k in 0..=n {
        c[k] = 1.0; // C(k, 0)
        for j in 1..=k {
            c[j * w + k] = c[(j - 1) * w + k - 1] + if j < k { c[j * w + k - 1] } else { 0.0 };
        }
    }
    c
}

/// q(y) ← q(y + s) for s ≥ 0 as q'ⱼ = Σₖ C(k, j) s^{k−j} qₖ (independent sums of products:
/// no chain of dependent multiply-adds as in repeated synthetic division). The error bounds
/// follow: the old bounds transform exactly like the coefficients (nonnegative weights), and the
/// new rounding is at most γ_{2n+4} times the transform of |q|; both ride in one sum,
/// Σ f·(errₖ(1 + γ) + γ|qₖ|).
fn shift(node: &mut Node, s: f64, binom: &[f64], w: usize) {
    let n = node.q.len() - 1;
    let gamma = 2.0 * U * (2 * n + 4) as f64;
    let mut buf = [0.0f64; 2 * SMALL];
    let mut heap = Vec::new();
    let (t, pw) = if n < SMALL {
        let (t, pw) = buf.split_at_mut(SMALL);
        (&mut t[..=n], &mut pw[..=n])
    } else {
        heap.resize(2 * (n + 1), 0.0);
        let (t, pw) = heap.split_at_mut(n + 1);
        (t, pw)
    };
    for ((tk, q), e) in t.iter_mut().zip(&node.q).zip(&node.err) {
        *tk = e * (1.0 + gamma) + gamma * q.abs();
    }
    if s == 1.0 {
        for j in 0..=n {
            let row = &binom[j * w + j..j * w + n + 1];
            let (mut aq, mut ae) = (0.0, 0.0);
            for ((b, q), t) in row.iter().zip(&node.q[j..]).zip(&t[j..]) {
                aq += b * q;
                ae += b * t;
            }
            node.q[j] = aq;
            node.err[j] = ae;
        }
        return;
    }
    pw[0] = 1.0;
    for k in 1..=n {
        pw[k] = pw[k - 1] * s;
    }
    for j in 0..=n {
        let row = &binom[j * w + j..j * w + n + 1];
        let (mut aq, mut ae) = (0.0, 0.0);
        for (((b, p), q), t) in row.iter().zip(pw.iter()).zip(&node.q[j..]).zip(&t[j..]) {
            let f = b * p;
            aq += f * q;
            ae += f * t;
        }
        node.q[j] = aq;
        node.err[j] = ae;
    }
}

/// The fewest and most sign variations of q over every sign its uncertain coefficients (|qₖ| ≤
/// errₖ) could have, zero included.
fn variations(q: &[f64], err: impl Iterator<Item = f64>) -> (usize, usize) {
    // states: the last nonzero sign (0: +, 1: −) with the (min, max) variations reaching it, and
    // "no nonzero coefficient yet"
    let mut reach = [false, false];
    let mut lo = [0usize; 2];
    let mut hi = [0usize; 2];
    let mut empty = true;
    for (x, e) in q.iter().zip(err) {
        let can_zero = x.abs() <= e;
        let can = [*x > 0.0 || can_zero, *x < 0.0 || can_zero];
        let (mut nreach, mut nlo, mut nhi, mut nempty) = ([false; 2], [usize::MAX; 2], [0usize; 2], false);
        if can_zero {
            // a zero coefficient is skipped: every state carries over
            nreach = reach;
            nlo = [if reach[0] { lo[0] } else { usize::MAX }, if reach[1] { lo[1] } else { usize::MAX }];
            nhi = hi;
            nempty = empty;
        }
        for t in 0..2 {
            if !can[t] {
                continue;
            }
            let mut take = |count: usize| {
                nreach[t] = true;
                nlo[t] = nlo[t].min(count);
                nhi[t] = nhi[t].max(count);
            };
            if empty {
                take(0);
            }
            for s in 0..2 {
                if reach[s] {
                    take(lo[s] + (s != t) as usize);
                    take(hi[s] + (s != t) as usize);
                }
            }
        }
        reach = nreach;
        lo = nlo;
        hi = nhi;
        empty = nempty;
    }
    let mut vmin = if empty { 0 } else { usize::MAX };
    let mut vmax = 0;
    for s in 0..2 {
        if reach[s] {
            vmin = vmin.min(lo[s]);
            vmax = vmax.max(hi[s]);
        }
    }
    (vmin, vmax)
}

/// The two halves of a node at y = y₀: (y₀, ∞) as q(y + y₀), and (0, y₀) as
/// (u + 1)ⁿ q(y₀/(u + 1)) for u ∈ (0, ∞).
fn split(node: &Node, y0: f64, binom: &[f64], w: usize) -> (Node, Node) {
    let [a, b, c, d] = node.m;
    let mut right = Node { q: node.q.clone(), err: node.err.clone(), m: [a, a * y0 + b, c, c * y0 + d] };
    shift(&mut right, y0, binom, w);
    // y = y₀·v: coefficient k times y₀ᵏ (exact for y₀ = 1; a few roundings per power otherwise)
    let (mut qs, mut es) = (node.q.clone(), node.err.clone());
    if y0 != 1.0 {
        let mut pk = 1.0;
        for (k, (q, e)) in qs.iter_mut().zip(es.iter_mut()).enumerate() {
            *q *= pk;
            *e = *e * pk + (k as f64 + 2.0) * 2.0 * U * q.abs();
            pk *= y0;
        }
    }
    // v ∈ (0, 1) ↦ u ∈ (0, ∞) with v = 1/(u + 1): reverse, then shift by 1
    qs.reverse();
    es.reverse();
    let mut left = Node { q: qs, err: es, m: [b, a * y0 + b, d, c * y0 + d] };
    shift(&mut left, 1.0, binom, w);
    (left, right)
}

/// An upper bound on the positive roots of q (ascending, leading coefficient nonzero):
/// Kioustelidis' 2·max (−qₖ/qₙ)^{1/(n−k)} over the coefficients of the other sign, with the
/// logarithms bounded from the floating-point representation (one `exp2` per call, no `powf`);
/// 0 when there is none.
fn positive_root_bound(q: &[f64]) -> f64 {
    let n = q.len() - 1;
    kioustelidis(q[n], q[..n].iter().enumerate().map(|(k, &c)| (c, n - k)))
}

/// [`positive_root_bound`] of the reversed polynomial yⁿq(1/y), without forming it: its
/// coefficient of yᵏ is q_{n−k}, its leading coefficient q₀.
fn positive_root_bound_reversed(q: &[f64]) -> f64 {
    kioustelidis(q[0], q.iter().enumerate().skip(1).map(|(i, &c)| (c, i)))
}

/// 2·max (−c/lead)^{1/d} over the (coefficient, distance to the top) pairs of the other sign.
fn kioustelidis(lead: f64, terms: impl Iterator<Item = (f64, usize)>) -> f64 {
    // log₂ x = e + log₂ m with m ∈ [1, 2), and m − 1 ≤ log₂ m ≤ m − 1 + 0.0861
    let lg = |x: f64| -> f64 {
        let bits = x.abs().to_bits();
        let e = ((bits >> 52) & 0x7ff) as i64 - 1023;
        let m = f64::from_bits((bits & ((1 << 52) - 1)) | (1023u64 << 52));
        e as f64 + m - 1.0
    };
    if !lead.is_normal() {
        return f64::INFINITY;
    }
    let lead_lo = lg(lead);
    let mut best = f64::NEG_INFINITY;
    for (c, d) in terms {
        if c != 0.0 && (c > 0.0) != (lead > 0.0) {
            // a subnormal c is below 2^−1022: bounded by the normal 2^−1022
            let c_hi = if c.is_normal() { lg(c) + 0.0861 } else { -1022.0 };
            best = best.max((c_hi - lead_lo) / d as f64);
        }
    }
    if best == f64::NEG_INFINITY { 0.0 } else { 2.0 * best.exp2() }
}

/// Positive roots of p (descending powers), each to about 1e-9 relative after the Illinois
/// refinement (callers polish on their own function). `None` when
/// the signs could not be certified within the subdivision budget (a root at an exact split
/// point, a double root, heavy cancellation): the caller falls back to the eigenvalues.
pub(crate) fn positive_roots(p: &[f64]) -> Option<Vec<f64>> {
    // ascending, exact leading zeros dropped, roots at 0 dropped (not positive)
    let mut q: Vec<f64> = p.iter().rev().copied().collect();
    while q.last() == Some(&0.0) {
        q.pop();
    }
    let zeros = q.iter().take_while(|&&c| c == 0.0).count();
    q.drain(..zeros);
    if q.len() <= 1 {
        return Some(Vec::new());
    }
    let cap = positive_root_bound(&q).max(f64::MIN_POSITIVE);
    // the polynomial without its roots at 0, for the refinement (p itself vanishes at x = 0,
    // the left end of the first interval)
    let stripped = crate::poly::Polynomial::from_vec(q.iter().rev().copied().collect());
    let mut out = Vec::new();
    let w = q.len();
    let binom = binomials(q.len() - 1);
    // x = 2ᵏy with 2ᵏ ≈ |q₀/qₙ|^{1/n} (exact): the roots move near 1, where the subdivision
    // starts, instead of being reached by many shifts
    let n = q.len() - 1;
    let k = ((q[0].abs().log2() - q[n].abs().log2()) / n as f64).round() as i32;
    let scaled: Vec<f64> =
        q.iter().enumerate().map(|(i, &c)| crate::axis::mul_pow2(c, k * i as i32)).collect();
    let (q, m0) = if k != 0 && scaled.iter().zip(&q).all(|(s, c)| s.is_finite() && (*s != 0.0) == (*c != 0.0))
    {
        (scaled, [crate::axis::pow2(k.clamp(-1074, 1023)), 0.0, 0.0, 1.0])
    } else {
        (q, [1.0, 0.0, 0.0, 1.0])
    };
    let mut stack = vec![Node { err: vec![0.0; q.len()], q, m: m0 }];
    let mut budget = 400;
    while let Some(mut node) = stack.pop() {
        budget -= 1;
        if budget == 0 {
            return None;
        }
        let (vmin, vmax) = variations(&node.q, node.err.iter().copied());
        if vmax == 0 {
            continue;
        }
        let [a, b, c, d] = node.m;
        if vmin == 1 && vmax == 1 {
            // exactly one simple root for y ∈ (0, ∞): x between b/d and a/c
            let lo_x = b / d;
            let hi_x = if c == 0.0 { f64::INFINITY } else { a / c };
            let (lo_x, hi_x) = if lo_x <= hi_x { (lo_x, hi_x) } else { (hi_x, lo_x) };
            out.push((lo_x, hi_x));
            continue;
        }
        if node.uncertain(0) {
            // a possible root at the left end of the interval: not decidable here
            return None;
        }
        // a lower bound on the positive roots: 1/(upper bound of the reversed polynomial)
        let ub_rev = positive_root_bound_reversed(&node.q);
        let lb = if ub_rev > 0.0 { 1.0 / ub_rev } else { 0.0 };
        if lb >= 1.0 {
            // y ← y + s with s = 15/16 of the lower bound, and again at the same node: the new
            // left end stays clear of the roots, so q(0) keeps a certain sign
            let s = 0.9375 * lb;
            shift(&mut node, s, &binom, w);
            node.m = [a, a * s + b, c, c * s + d];
            stack.push(node);
            continue;
        }
        // split at y₀ (1, or a nearby dyadic when q(1) cannot be told from 0: a root there)
        let mut children = None;
        for y0 in [1.0, 1.0625, 0.9375, 1.125] {
            let (left, right) = split(&node, y0, &binom, w);
            if !right.uncertain(0) {
                children = Some((left, right));
                break;
            }
        }
        let (left, right) = children?;
        stack.push(right);
        stack.push(left);
    }
    // refine each isolating interval on p itself
    let eval = |x: f64| stripped.eval(x);
    let mut roots = Vec::with_capacity(out.len());
    for (lo, hi) in out {
        let hi = if hi.is_finite() { hi.min(cap) } else { cap };
        roots.push(illinois(&eval, lo.max(0.0), hi));
    }
    roots.sort_by(f64::total_cmp);
    Some(roots)
}

/// The Illinois variant of regula falsi on [a, b] where f changes sign (else the midpoint),
/// at most 60 steps, to 1e-9 relative width (the callers polish with Newton's method on their
/// own, better conditioned, function).
fn illinois(f: &impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let (mut fa, mut fb) = (f(a), f(b));
    if fa == 0.0 {
        return a;
    }
    if fb == 0.0 {
        return b;
    }
    if fa.signum() == fb.signum() || !(fa.is_finite() && fb.is_finite()) {
        return 0.5 * (a + b);
    }
    // wide brackets first by bisection in the logarithm (regula falsi creeps on x⁴-like growth)
    for _ in 0..64 {
        if !(a > 0.0 && b > 2.0 * a) {
            break;
        }
        let m = (a * b).sqrt();
        let fm = f(m);
        if fm == 0.0 {
            return m;
        }
        if fm.signum() == fa.signum() {
            (a, fa) = (m, fm);
        } else {
            (b, fb) = (m, fm);
        }
    }
    let mut side = 0i32;
    for _ in 0..60 {
        let x = (a * fb - b * fa) / (fb - fa);
        let x = if x > a.min(b) && x < a.max(b) { x } else { 0.5 * (a + b) };
        let fx = f(x);
        if fx == 0.0 || (b - a).abs() <= 1e-9 * x.abs() {
            return x;
        }
        if fx.signum() == fb.signum() {
            b = x;
            fb = fx;
            if side == -1 {
                fa *= 0.5;
            }
            side = -1;
        } else {
            a = x;
            fa = fx;
            if side == 1 {
                fb *= 0.5;
            }
            side = 1;
        }
    }
    0.5 * (a + b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::poly::Polynomial;
    use num_complex::Complex64;

    fn from_roots(r: &[Complex64]) -> Vec<f64> {
        Polynomial::from_roots(r).unwrap().coeffs().to_vec()
    }

    #[test]
    fn isolates_positive_roots_among_complex_and_negative_ones() {
        let c = |re: f64, im: f64| Complex64::new(re, im);
        let cases: [(Vec<Complex64>, Vec<f64>); 4] = [
            (vec![c(1.0, 0.0), c(2.0, 0.0), c(-3.0, 0.0), c(0.0, 1.0), c(0.0, -1.0)], vec![1.0, 2.0]),
            (vec![c(1e-4, 0.0), c(1e4, 0.0), c(7.0, 0.0), c(-5.0, 0.0)], vec![1e-4, 7.0, 1e4]),
            (vec![c(0.5, 3.0), c(0.5, -3.0), c(-1.0, 0.0)], vec![]),
            (vec![c(3.0, 0.0), c(3.003, 0.0), c(0.1, 0.05), c(0.1, -0.05)], vec![3.0, 3.003]),
        ];
        for (roots, want) in cases {
            let got = positive_roots(&from_roots(&roots)).expect("decided");
            assert_eq!(got.len(), want.len(), "{roots:?}: {got:?}");
            for (g, w) in got.iter().zip(&want) {
                assert!((g - w).abs() <= 1e-9 * w, "{g} vs {w}");
            }
        }
    }

    #[test]
    fn a_nearly_double_root_is_isolated_or_left_to_the_caller() {
        // 3 and 3 + 10⁻⁶: the signs near the pair are at the rounding level, so the subdivision
        // either separates them or declines (the caller then uses the eigenvalues)
        let c = |re: f64| Complex64::new(re, 0.0);
        let p = from_roots(&[c(3.0), c(3.0 + 1e-6), Complex64::new(0.1, 0.05), Complex64::new(0.1, -0.05)]);
        if let Some(r) = positive_roots(&p) {
            assert_eq!(r.len(), 2);
            assert!((r[0] - 3.0).abs() < 1e-6 && (r[1] - 3.0 - 1e-6).abs() < 1e-6, "{r:?}");
        }
    }

    #[test]
    fn a_double_root_is_undecided() {
        let c = Complex64::new(2.0, 0.0);
        assert_eq!(positive_roots(&from_roots(&[c, c, Complex64::new(-1.0, 0.0)])), None);
    }

    #[test]
    fn variations_with_uncertain_signs() {
        let v = |q: &[f64], e: &[f64]| variations(q, e.iter().copied());
        assert_eq!(v(&[1.0, -1.0, 1.0], &[0.0; 3]), (2, 2));
        assert_eq!(v(&[1.0, 1e-20, 1.0], &[0.0, 1e-10, 0.0]), (0, 2));
        assert_eq!(v(&[1.0, 0.0, -1.0], &[0.0; 3]), (1, 1));
        assert_eq!(v(&[1e-20, 1.0], &[1e-10, 0.0]), (0, 1));
    }
}
