//! Truncated Taylor series of the quantities of a right-hand side, computed one order at a
//! time: automatic differentiation in Taylor mode (Moore's recurrences).
//!
//! A [`Var`] is one quantity of a right-hand side (a state component, the time, or a result of
//! an operation on them) seen as a power series in the time step, x(t₀ + s) = Σ xₖ sᵏ. The
//! integrator evaluates the right-hand side once per order k = 0, 1, …, p − 1: on the pass of
//! order k every operation computes the k-th coefficient of its result from the coefficients
//! 0..=k of its operands (the lower ones kept from the earlier passes), and the state's
//! coefficient k + 1 follows from ẋ = f as xₖ₊₁ = fₖ/(k + 1). A pass costs O(k) per product,
//! so a step of order p costs O(p²) per operation, with no symbolic algebra and no tape to
//! interpret: the right-hand side is ordinary compiled Rust, generic in nothing.
//!
//! Reference: Moore, *Interval Analysis* (1966) §11; Griewank & Walther, *Evaluating
//! Derivatives* (2008) §13.2 (Table 13.1: the recurrences used here); Jorba & Zou, *Experimental
//! Mathematics* 14 (2005) 99–117 §3.

use core::cell::Cell;
use core::ops::{Add, Div, Mul, Neg, Sub};

/// The series of every quantity of one right-hand side at one step: slot-major coefficient
/// storage (each quantity p + 1 numbers), filled one order per pass. The store has a fixed
/// capacity (cells, so that operations write through shared references without a borrow
/// flag); a pass that needs more slots writes into a spare one, flags `overflow`, and is run
/// again after [`Jets::grow`].
///
/// Book: §4.11 (integration of the equations of motion); Griewank & Walther §13.2.
#[derive(Debug)]
pub(crate) struct Jets {
    /// Numbers per quantity: the highest order p plus one.
    stride: usize,
    /// Quantities given before the operations (the state's components and t).
    inputs: usize,
    /// The order computed by the current pass.
    k: usize,
    /// `limit` usable cells, then one spare slot.
    c: Vec<Cell<f64>>,
    limit: usize,
    /// Start of the next quantity's slot in `c`.
    next: Cell<usize>,
    /// A pass needed more than `limit` cells.
    overflow: Cell<bool>,
    /// Slot starts in use after the first pass (inputs plus every operation's result).
    recorded: usize,
    /// The first pass of a step: its count of operations is recorded.
    recording: bool,
}

/// One quantity of a right-hand side written for the Taylor integrator ([`crate::Taylor`]):
/// a state component, the time, a constant, or the result of `+ − × ÷`, `sqrt`, `powf`,
/// `exp`, `ln`, `sin`, `cos` on them (with other `Var`s or with `f64`s). It has no value a
/// right-hand side could branch on: the same operations run on every pass of a step.
///
/// Book: §4.11; Griewank & Walther §13.2 (Taylor arithmetic).
#[derive(Debug, Clone, Copy)]
pub struct Var<'a> {
    cx: &'a Jets,
    /// Start of this quantity's coefficients in the store.
    at: usize,
}

impl Jets {
    /// Storage for series up to order `p` whose first `inputs` quantities are given, with room
    /// for `ops` operations (grown on demand).
    pub(crate) fn new(p: usize, inputs: usize, ops: usize) -> Self {
        let stride = p + 1;
        let limit = (inputs + ops) * stride;
        Self {
            stride,
            inputs,
            k: 0,
            c: (0..limit + stride).map(|_| Cell::new(0.0)).collect(),
            limit,
            next: Cell::new(inputs * stride),
            overflow: Cell::new(false),
            recorded: inputs * stride,
            recording: true,
        }
    }

    /// Room for twice as many operations (the inputs' coefficients kept).
    pub(crate) fn grow(&mut self) {
        self.limit = 2 * self.limit.max(self.stride);
        self.c.resize_with(self.limit + self.stride, || Cell::new(0.0));
    }

    /// Starts the pass of order `k` (the first pass, k = 0, records the count of operations;
    /// later passes reuse the slots in the same order).
    pub(crate) fn begin(&mut self, k: usize) {
        self.recording = k == 0;
        self.k = k;
        self.overflow.set(false);
        self.next.set(self.inputs * self.stride);
    }

    /// Operations (quantities made) on the first pass of the step.
    pub(crate) fn recorded_operations(&self) -> usize {
        self.recorded / self.stride - self.inputs
    }

    /// Operations made so far on this pass.
    pub(crate) fn operations_this_pass(&self) -> usize {
        self.next.get() / self.stride - self.inputs
    }

    /// The pass ran out of room (grow and run it again).
    pub(crate) fn overflowed(&self) -> bool {
        self.overflow.get()
    }

    /// Ends a pass: `false` when it made another number of quantities than the first pass
    /// of the step (a right-hand side whose operations changed between passes).
    pub(crate) fn end(&mut self) -> bool {
        let n = self.next.get();
        if self.recording {
            self.recording = false;
            self.recorded = n;
            true
        } else {
            n == self.recorded
        }
    }

    /// The quantity whose coefficients start at `at`.
    pub(crate) fn var(&self, at: usize) -> Var<'_> {
        Var { cx: self, at }
    }

    /// Coefficient `j` of input `i`.
    pub(crate) fn get(&self, i: usize, j: usize) -> f64 {
        self.c[i * self.stride + j].get()
    }

    /// Sets coefficient `j` of input `i`.
    pub(crate) fn set(&self, i: usize, j: usize, v: f64) {
        self.c[i * self.stride + j].set(v);
    }

    /// Coefficient `j` of the quantity at `at`.
    pub(crate) fn coef(&self, at: usize, j: usize) -> f64 {
        self.c[at + j].get()
    }

    /// A new quantity's slot (past the room: the spare slot, and the pass is flagged).
    #[inline(always)]
    fn slot(&self) -> usize {
        let at = self.next.get();
        self.next.set(at + self.stride);
        if at + self.stride > self.limit {
            self.overflow.set(true);
            return self.limit;
        }
        at
    }

    /// The coefficients 0..=k of the quantity at `at`.
    #[inline(always)]
    fn upto(&self, at: usize) -> &[Cell<f64>] {
        &self.c[at..=at + self.k]
    }

    /// A new quantity from a unary recurrence: `f(k, a, out)` with the operand's coefficients
    /// `a` and the result's `out` (0..=k each) writes out[k].
    #[inline(always)]
    fn unary(&self, a: usize, f: impl FnOnce(usize, &[Cell<f64>], &[Cell<f64>])) -> Var<'_> {
        let at = self.slot();
        f(self.k, self.upto(a), self.upto(at));
        Var { cx: self, at }
    }

    /// As [`Jets::unary`] with two operands.
    #[inline(always)]
    fn binary(
        &self,
        a: usize,
        b: usize,
        f: impl FnOnce(usize, &[Cell<f64>], &[Cell<f64>], &[Cell<f64>]),
    ) -> Var<'_> {
        let at = self.slot();
        f(self.k, self.upto(a), self.upto(b), self.upto(at));
        Var { cx: self, at }
    }

    /// A pair of quantities from one recurrence (sin and cos together): `f(k, a, s, c)`.
    #[inline(always)]
    fn pair(
        &self,
        a: usize,
        f: impl FnOnce(usize, &[Cell<f64>], &[Cell<f64>], &[Cell<f64>]),
    ) -> (Var<'_>, Var<'_>) {
        let s_at = self.slot();
        let c_at = self.slot();
        f(self.k, self.upto(a), self.upto(s_at), self.upto(c_at));
        (Var { cx: self, at: s_at }, Var { cx: self, at: c_at })
    }
}

/// Σⱼ₌ₗₒ..=ₕᵢ aⱼ bₖ₋ⱼ (terms `lo` to `hi` of the Cauchy product, in increasing j), with
/// k = the order of `b` (its length − 1).
#[inline(always)]
fn conv(a: &[Cell<f64>], b: &[Cell<f64>], lo: usize, hi: usize) -> f64 {
    let k = b.len() - 1;
    a[lo..=hi].iter().zip(b[k - hi..=k - lo].iter().rev()).fold(0.0, |s, (x, y)| s + x.get() * y.get())
}

/// Σⱼ₌₁..=ₖ j aⱼ bₖ₋ⱼ (the chain rule's weighted product), k = the order of `b`.
#[inline(always)]
fn wconv(a: &[Cell<f64>], b: &[Cell<f64>]) -> f64 {
    let k = b.len() - 1;
    let (mut s, mut j) = (0.0, 0.0);
    for (x, y) in a[1..=k].iter().zip(b[..k].iter().rev()) {
        j += 1.0;
        s += j * x.get() * y.get();
    }
    s
}

/// k as a float (orders are small: through u32, one instruction).
#[inline(always)]
fn real(k: usize) -> f64 {
    f64::from(k as u32)
}

impl<'a> Var<'a> {
    /// Start of this quantity's coefficients in the store.
    pub(crate) fn at(&self) -> usize {
        self.at
    }

    /// The constant `v` as a quantity (its series is v, 0, 0, …).
    #[inline]
    pub fn constant(self, v: f64) -> Var<'a> {
        self.cx.unary(self.at, |k, _, o| o[k].set(if k == 0 { v } else { 0.0 }))
    }

    /// √x: c₀ = √a₀, cₖ = (aₖ − Σⱼ₌₁..ₖ₋₁ cⱼcₖ₋ⱼ)/(2c₀) (Griewank & Walther Table 13.1).
    /// x(t) must stay positive over the step (else the result is not finite and the
    /// integrator reports [`crate::OdeError::RhsNotFinite`]).
    #[inline]
    pub fn sqrt(self) -> Var<'a> {
        self.cx.unary(self.at, |k, a, o| {
            o[k].set(if k == 0 {
                a[0].get().sqrt()
            } else {
                (a[k].get() - conv(o, o, 1, k - 1)) / (2.0 * o[0].get())
            });
        })
    }

    /// x^α for a real α: c₀ = a₀^α, cₖ = Σⱼ₌₀..ₖ₋₁ (α(k − j) − j) aₖ₋ⱼ cⱼ / (k a₀)
    /// (x ċ = α c ẋ). x(t) must not vanish (use products for integer powers of a quantity
    /// that can be zero).
    #[inline]
    pub fn powf(self, alpha: f64) -> Var<'a> {
        self.cx.unary(self.at, |k, a, o| {
            let v = if k == 0 {
                a[0].get().powf(alpha)
            } else {
                // weight α(k − j) − j from j = 0, less α + 1 a term
                let kf = real(k);
                let (mut s, mut w) = (0.0, alpha * kf);
                for (oj, akj) in o[..k].iter().zip(a[1..].iter().rev()) {
                    s += w * akj.get() * oj.get();
                    w -= alpha + 1.0;
                }
                s / (kf * a[0].get())
            };
            o[k].set(v);
        })
    }

    /// eˣ: c₀ = e^{a₀}, cₖ = Σⱼ₌₁..ₖ j aⱼ cₖ₋ⱼ / k (ċ = c ẋ).
    #[inline]
    pub fn exp(self) -> Var<'a> {
        self.cx.unary(self.at, |k, a, o| {
            o[k].set(if k == 0 { a[0].get().exp() } else { wconv(a, o) / real(k) });
        })
    }

    /// ln x: c₀ = ln a₀, cₖ = (aₖ − Σⱼ₌₁..ₖ₋₁ j cⱼ aₖ₋ⱼ / k)/a₀ (x ċ = ẋ); x(t) > 0.
    #[inline]
    pub fn ln(self) -> Var<'a> {
        self.cx.unary(self.at, |k, a, o| {
            let v = if k == 0 {
                a[0].get().ln()
            } else {
                // Σⱼ₌₁..ₖ j cⱼ aₖ₋ⱼ without its last term (j = k: cₖ, not yet known)
                let (mut s, mut jf) = (0.0, 0.0);
                for (oj, akj) in o[1..k].iter().zip(a[1..k].iter().rev()) {
                    jf += 1.0;
                    s += jf * oj.get() * akj.get();
                }
                (a[k].get() - s / real(k)) / a[0].get()
            };
            o[k].set(v);
        })
    }

    /// (sin x, cos x) together (each one's recurrence needs the other's series):
    /// sₖ = Σ j aⱼ cₖ₋ⱼ / k, cₖ = −Σ j aⱼ sₖ₋ⱼ / k.
    #[inline]
    pub fn sin_cos(self) -> (Var<'a>, Var<'a>) {
        self.cx.pair(self.at, |k, a, s, c| {
            if k == 0 {
                let (sv, cv) = a[0].get().sin_cos();
                s[0].set(sv);
                c[0].set(cv);
            } else {
                // one loop for both sums: j aⱼ once per term
                let (mut ss, mut cs, mut j) = (0.0, 0.0, 0.0);
                for ((aj, cj), sj) in a[1..=k].iter().zip(c[..k].iter().rev()).zip(s[..k].iter().rev()) {
                    j += 1.0;
                    let ja = j * aj.get();
                    ss += ja * cj.get();
                    cs += ja * sj.get();
                }
                let kf = real(k);
                s[k].set(ss / kf);
                c[k].set(-cs / kf);
            }
        })
    }

    /// sin x (computes cos x beside it: [`Var::sin_cos`]).
    #[inline]
    pub fn sin(self) -> Var<'a> {
        self.sin_cos().0
    }

    /// cos x (computes sin x beside it: [`Var::sin_cos`]).
    #[inline]
    pub fn cos(self) -> Var<'a> {
        self.sin_cos().1
    }

    /// x²: 2 Σⱼ<ₖ₋ⱼ aⱼaₖ₋ⱼ (+ a²ₖ/₂ for even k), half the products of x·x.
    #[inline]
    pub fn square(self) -> Var<'a> {
        self.cx.unary(self.at, |k, a, o| {
            let half = k.div_ceil(2);
            let mut v = if half > 0 { 2.0 * conv(a, a, 0, half - 1) } else { 0.0 };
            if k % 2 == 0 {
                v += a[k / 2].get() * a[k / 2].get();
            }
            o[k].set(v);
        })
    }
}

impl<'a> Add for Var<'a> {
    type Output = Var<'a>;
    #[inline]
    fn add(self, b: Var<'a>) -> Var<'a> {
        self.cx.binary(self.at, b.at, |k, a, b, o| o[k].set(a[k].get() + b[k].get()))
    }
}

impl<'a> Sub for Var<'a> {
    type Output = Var<'a>;
    #[inline]
    fn sub(self, b: Var<'a>) -> Var<'a> {
        self.cx.binary(self.at, b.at, |k, a, b, o| o[k].set(a[k].get() - b[k].get()))
    }
}

impl<'a> Mul for Var<'a> {
    type Output = Var<'a>;
    /// The Cauchy product cₖ = Σⱼ₌₀..ₖ aⱼ bₖ₋ⱼ.
    #[inline]
    fn mul(self, b: Var<'a>) -> Var<'a> {
        self.cx.binary(self.at, b.at, |k, a, b, o| o[k].set(conv(a, b, 0, k)))
    }
}

impl<'a> Div for Var<'a> {
    type Output = Var<'a>;
    /// cₖ = (aₖ − Σⱼ₌₁..ₖ bⱼ cₖ₋ⱼ)/b₀ (c b = a); the divisor must not vanish.
    #[inline]
    fn div(self, b: Var<'a>) -> Var<'a> {
        self.cx.binary(self.at, b.at, |k, a, b, o| {
            let v =
                if k == 0 { a[0].get() / b[0].get() } else { (a[k].get() - conv(b, o, 1, k)) / b[0].get() };
            o[k].set(v);
        })
    }
}

impl<'a> Neg for Var<'a> {
    type Output = Var<'a>;
    #[inline]
    fn neg(self) -> Var<'a> {
        self.cx.unary(self.at, |k, a, o| o[k].set(-a[k].get()))
    }
}

impl<'a> Add<f64> for Var<'a> {
    type Output = Var<'a>;
    #[inline]
    fn add(self, v: f64) -> Var<'a> {
        self.cx.unary(self.at, |k, a, o| o[k].set(if k == 0 { a[0].get() + v } else { a[k].get() }))
    }
}

impl<'a> Sub<f64> for Var<'a> {
    type Output = Var<'a>;
    #[inline]
    fn sub(self, v: f64) -> Var<'a> {
        self + (-v)
    }
}

impl<'a> Mul<f64> for Var<'a> {
    type Output = Var<'a>;
    #[inline]
    fn mul(self, v: f64) -> Var<'a> {
        self.cx.unary(self.at, |k, a, o| o[k].set(a[k].get() * v))
    }
}

impl<'a> Div<f64> for Var<'a> {
    type Output = Var<'a>;
    #[inline]
    fn div(self, v: f64) -> Var<'a> {
        self.cx.unary(self.at, |k, a, o| o[k].set(a[k].get() / v))
    }
}

impl<'a> Add<Var<'a>> for f64 {
    type Output = Var<'a>;
    #[inline]
    fn add(self, x: Var<'a>) -> Var<'a> {
        x + self
    }
}

impl<'a> Sub<Var<'a>> for f64 {
    type Output = Var<'a>;
    #[inline]
    fn sub(self, x: Var<'a>) -> Var<'a> {
        x.cx.unary(x.at, |k, a, o| o[k].set(if k == 0 { self - a[0].get() } else { -a[k].get() }))
    }
}

impl<'a> Mul<Var<'a>> for f64 {
    type Output = Var<'a>;
    #[inline]
    fn mul(self, x: Var<'a>) -> Var<'a> {
        x * self
    }
}

impl<'a> Div<Var<'a>> for f64 {
    type Output = Var<'a>;
    /// v/x: c₀ = v/b₀, cₖ = −Σⱼ₌₁..ₖ bⱼ cₖ₋ⱼ / b₀ (k ≥ 1).
    #[inline]
    fn div(self, x: Var<'a>) -> Var<'a> {
        x.cx.unary(x.at, |k, b, o| {
            o[k].set(if k == 0 { self / b[0].get() } else { -conv(b, o, 1, k) / b[0].get() });
        })
    }
}
