//! Truncated Taylor series of the quantities of a right-hand side, computed one order at a
//! time: automatic differentiation in Taylor mode (Moore's recurrences).
//!
//! A [`Var`] is one quantity of a right-hand side (a state component, the time, or a result of
//! an operation on them) seen as a power series in the time step, x(t₀ + s) = Σ xₖ sᵏ. The
//! right-hand side runs once, on [`Var`]s, to record its operations on a [`Tape`]; each step
//! then runs the tape once per order k = 0, 1, …, p − 1: every operation computes the k-th
//! coefficient of its result from the coefficients 0..=k of its operands (the lower ones kept
//! from the earlier passes), and the state's coefficient k + 1 follows from ẋ = f as
//! xₖ₊₁ = fₖ/(k + 1). A pass costs O(k) per product, so a step of order p costs O(p²) per
//! operation, with no symbolic algebra.
//!
//! Reference: Moore, *Interval Analysis* (1966) §11; Griewank & Walther, *Evaluating
//! Derivatives* (2008) §13.2 (Table 13.1: the recurrences used here); Jorba & Zou, *Experimental
//! Mathematics* 14 (2005) 99–117 §3.

use core::cell::RefCell;
use core::ops::{Add, Div, Mul, Neg, Sub};

/// One recorded operation: its kind and operands (coefficient offsets in the store).
#[derive(Debug, Clone, Copy)]
enum Op {
    Const(f64),
    Add(usize, usize),
    Sub(usize, usize),
    Mul(usize, usize),
    Div(usize, usize),
    Neg(usize),
    Square(usize),
    AddC(usize, f64),
    MulC(usize, f64),
    DivC(usize, f64),
    /// c − x.
    CSub(f64, usize),
    /// c / x.
    CDiv(f64, usize),
    Sqrt(usize),
    Powf(usize, f64),
    Exp(usize),
    Ln(usize),
    /// sin x into the output, cos x into the next quantity.
    SinCos(usize),
}

/// The operations of a right-hand side, recorded once from a run on [`Var`]s, and run once
/// per order on a coefficient store (each quantity p + 1 numbers, the inputs first).
///
/// Book: §4.11 (integration of the equations of motion); Griewank & Walther §13.2.
#[derive(Debug)]
pub(crate) struct Tape {
    /// Numbers per quantity: the highest order p plus one.
    stride: usize,
    /// (operation, offset of its result).
    ops: RefCell<Vec<(Op, usize)>>,
    /// Quantities so far (inputs and results).
    quantities: RefCell<usize>,
}

/// One quantity of a right-hand side written for the Taylor integrator ([`crate::Taylor`]):
/// a state component, the time, a constant, or the result of `+ − × ÷`, `sqrt`, `powf`,
/// `exp`, `ln`, `sin`, `cos` on them (with other `Var`s or with `f64`s). It has no value: the
/// right-hand side runs once to record its operations, which every step then repeats.
///
/// Book: §4.11; Griewank & Walther §13.2 (Taylor arithmetic).
#[derive(Debug, Clone, Copy)]
pub struct Var<'a> {
    tape: &'a Tape,
    /// Start of this quantity's coefficients in the store.
    at: usize,
}

impl Tape {
    /// An empty tape for series up to order `p` whose first `inputs` quantities are given.
    pub(crate) fn new(p: usize, inputs: usize) -> Self {
        Self { stride: p + 1, ops: RefCell::new(Vec::new()), quantities: RefCell::new(inputs) }
    }

    /// Input `i` as a quantity.
    pub(crate) fn input(&self, i: usize) -> Var<'_> {
        Var { tape: self, at: i * self.stride }
    }

    /// Numbers a store needs: every quantity's p + 1 coefficients.
    pub(crate) fn store_len(&self) -> usize {
        *self.quantities.borrow() * self.stride
    }

    /// Records `op` with a result of `n` quantities (2 for sin and cos); the first's offset.
    fn record(&self, op: Op, n: usize) -> Var<'_> {
        let mut q = self.quantities.borrow_mut();
        let at = *q * self.stride;
        *q += n;
        self.ops.borrow_mut().push((op, at));
        Var { tape: self, at }
    }

    /// The pass of order k: coefficient k of every operation's result, in recorded order, into
    /// `c` (the inputs' coefficients 0..=k and every result's 0..k already there).
    pub(crate) fn pass(&self, k: usize, c: &mut [f64]) {
        let kf = f64::from(k as u32);
        for &(op, o) in self.ops.borrow().iter() {
            let v = match op {
                Op::Sqrt(_) | Op::Powf(..) | Op::Exp(_) | Op::Ln(_) => elementary(op, o, k, kf, c),
                Op::SinCos(a) => {
                    let oc = o + self.stride;
                    let (sv, cv) = if k == 0 {
                        c[a].sin_cos()
                    } else {
                        // one loop for both sums: j aⱼ once per term
                        let (mut ss, mut cs, mut j) = (0.0, 0.0, 0.0);
                        let terms = c[a + 1..=a + k]
                            .iter()
                            .zip(c[oc..oc + k].iter().rev())
                            .zip(c[o..o + k].iter().rev());
                        for ((aj, cj), sj) in terms {
                            j += 1.0;
                            let ja = j * aj;
                            ss += ja * cj;
                            cs += ja * sj;
                        }
                        (ss / kf, -cs / kf)
                    };
                    c[oc + k] = cv;
                    sv
                }
                _ => arithmetic(op, o, k, c),
            };
            c[o + k] = v;
        }
    }
}

/// Coefficient k of the result (at `o`) of +, −, ×, ÷, negation, square or a constant.
#[inline(always)]
fn arithmetic(op: Op, o: usize, k: usize, c: &[f64]) -> f64 {
    match op {
        Op::Const(v) => {
            if k == 0 {
                v
            } else {
                0.0
            }
        }
        Op::Add(a, b) => c[a + k] + c[b + k],
        Op::Sub(a, b) => c[a + k] - c[b + k],
        Op::Mul(a, b) => conv(&c[a..=a + k], &c[b..=b + k], 0, k),
        Op::Div(a, b) => {
            if k == 0 {
                c[a] / c[b]
            } else {
                (c[a + k] - conv(&c[b..=b + k], &c[o..=o + k], 1, k)) / c[b]
            }
        }
        Op::Neg(a) => -c[a + k],
        Op::Square(a) => {
            let x = &c[a..=a + k];
            let half = k.div_ceil(2);
            let mut v = if half > 0 { 2.0 * conv(x, x, 0, half - 1) } else { 0.0 };
            if k.is_multiple_of(2) {
                v += x[k / 2] * x[k / 2];
            }
            v
        }
        Op::AddC(a, v) => {
            if k == 0 {
                c[a] + v
            } else {
                c[a + k]
            }
        }
        Op::MulC(a, v) => c[a + k] * v,
        Op::DivC(a, v) => c[a + k] / v,
        Op::CSub(v, a) => {
            if k == 0 {
                v - c[a]
            } else {
                -c[a + k]
            }
        }
        Op::CDiv(v, b) => {
            if k == 0 {
                v / c[b]
            } else {
                -conv(&c[b..=b + k], &c[o..=o + k], 1, k) / c[b]
            }
        }
        _ => unreachable!("an elementary function or sin/cos, handled by the caller"),
    }
}

/// Coefficient k of the result (at `o`) of √, x^α, eˣ or ln.
#[inline(always)]
fn elementary(op: Op, o: usize, k: usize, kf: f64, c: &[f64]) -> f64 {
    match op {
        Op::Sqrt(a) => {
            if k == 0 {
                c[a].sqrt()
            } else {
                let s = &c[o..=o + k];
                (c[a + k] - conv(s, s, 1, k - 1)) / (2.0 * c[o])
            }
        }
        Op::Powf(a, alpha) => {
            if k == 0 {
                c[a].powf(alpha)
            } else {
                // Σⱼ₌₀..ₖ₋₁ (α(k − j) − j) aₖ₋ⱼ cⱼ / (k a₀); the weight from αk, less α + 1 a term
                let (mut s, mut w) = (0.0, alpha * kf);
                for (cj, akj) in c[o..o + k].iter().zip(c[a + 1..=a + k].iter().rev()) {
                    s += w * akj * cj;
                    w -= alpha + 1.0;
                }
                s / (kf * c[a])
            }
        }
        Op::Exp(a) => {
            if k == 0 {
                c[a].exp()
            } else {
                wconv(&c[a..=a + k], &c[o..=o + k]) / kf
            }
        }
        Op::Ln(a) => {
            if k == 0 {
                c[a].ln()
            } else {
                // Σⱼ₌₁..ₖ₋₁ j cⱼ aₖ₋ⱼ (the term j = k is cₖ itself)
                let (mut s, mut j) = (0.0, 0.0);
                for (cj, akj) in c[o + 1..o + k].iter().zip(c[a + 1..a + k].iter().rev()) {
                    j += 1.0;
                    s += j * cj * akj;
                }
                (c[a + k] - s / kf) / c[a]
            }
        }
        _ => unreachable!("an arithmetic operation, handled by the caller"),
    }
}

/// Σⱼ₌ₗₒ..=ₕᵢ aⱼ bₖ₋ⱼ (terms `lo` to `hi` of the Cauchy product, in increasing j), with
/// k = the order of `b` (its length − 1).
#[inline(always)]
fn conv(a: &[f64], b: &[f64], lo: usize, hi: usize) -> f64 {
    let k = b.len() - 1;
    a[lo..=hi].iter().zip(b[k - hi..=k - lo].iter().rev()).fold(0.0, |s, (x, y)| s + x * y)
}

/// Σⱼ₌₁..=ₖ j aⱼ bₖ₋ⱼ (the chain rule's weighted product), k = the order of `b`.
#[inline(always)]
fn wconv(a: &[f64], b: &[f64]) -> f64 {
    let k = b.len() - 1;
    let (mut s, mut j) = (0.0, 0.0);
    for (x, y) in a[1..=k].iter().zip(b[..k].iter().rev()) {
        j += 1.0;
        s += j * x * y;
    }
    s
}

impl<'a> Var<'a> {
    /// Start of this quantity's coefficients in the store.
    pub(crate) fn at(&self) -> usize {
        self.at
    }

    fn op(self, op: Op) -> Var<'a> {
        self.tape.record(op, 1)
    }

    /// The constant `v` as a quantity (its series is v, 0, 0, …).
    pub fn constant(self, v: f64) -> Var<'a> {
        self.op(Op::Const(v))
    }

    /// √x: c₀ = √a₀, cₖ = (aₖ − Σⱼ₌₁..ₖ₋₁ cⱼcₖ₋ⱼ)/(2c₀) (Griewank & Walther Table 13.1).
    /// x(t) must stay positive over the step (else the result is not finite and the
    /// integrator reports [`crate::OdeError::RhsNotFinite`]).
    pub fn sqrt(self) -> Var<'a> {
        self.op(Op::Sqrt(self.at))
    }

    /// x^α for a real α: c₀ = a₀^α, cₖ = Σⱼ₌₀..ₖ₋₁ (α(k − j) − j) aₖ₋ⱼ cⱼ / (k a₀)
    /// (x ċ = α c ẋ). x(t) must not vanish (use products for integer powers of a quantity
    /// that can be zero).
    pub fn powf(self, alpha: f64) -> Var<'a> {
        self.op(Op::Powf(self.at, alpha))
    }

    /// eˣ: c₀ = e^{a₀}, cₖ = Σⱼ₌₁..ₖ j aⱼ cₖ₋ⱼ / k (ċ = c ẋ).
    pub fn exp(self) -> Var<'a> {
        self.op(Op::Exp(self.at))
    }

    /// ln x: c₀ = ln a₀, cₖ = (aₖ − Σⱼ₌₁..ₖ₋₁ j cⱼ aₖ₋ⱼ / k)/a₀ (x ċ = ẋ); x(t) > 0.
    pub fn ln(self) -> Var<'a> {
        self.op(Op::Ln(self.at))
    }

    /// (sin x, cos x) together (each one's recurrence needs the other's series):
    /// sₖ = Σ j aⱼ cₖ₋ⱼ / k, cₖ = −Σ j aⱼ sₖ₋ⱼ / k.
    pub fn sin_cos(self) -> (Var<'a>, Var<'a>) {
        let s = self.tape.record(Op::SinCos(self.at), 2);
        (s, Var { tape: self.tape, at: s.at + self.tape.stride })
    }

    /// sin x (computes cos x beside it: [`Var::sin_cos`]).
    pub fn sin(self) -> Var<'a> {
        self.sin_cos().0
    }

    /// cos x (computes sin x beside it: [`Var::sin_cos`]).
    pub fn cos(self) -> Var<'a> {
        self.sin_cos().1
    }

    /// x²: 2 Σⱼ<ₖ₋ⱼ aⱼaₖ₋ⱼ (+ a²ₖ/₂ for even k), half the products of x·x.
    pub fn square(self) -> Var<'a> {
        self.op(Op::Square(self.at))
    }
}

/// The operators between two quantities, each one recorded operation.
macro_rules! binary {
    ($($tr:ident $f:ident $op:ident $doc:literal;)*) => {$(
        impl<'a> $tr for Var<'a> {
            type Output = Var<'a>;
            #[doc = $doc]
            fn $f(self, b: Var<'a>) -> Var<'a> {
                self.op(Op::$op(self.at, b.at))
            }
        }
    )*};
}

binary! {
    Add add Add "cₖ = aₖ + bₖ.";
    Sub sub Sub "cₖ = aₖ − bₖ.";
    Mul mul Mul "The Cauchy product cₖ = Σⱼ₌₀..ₖ aⱼ bₖ₋ⱼ.";
    Div div Div "cₖ = (aₖ − Σⱼ₌₁..ₖ bⱼ cₖ₋ⱼ)/b₀ (c b = a); the divisor must not vanish.";
}

impl<'a> Neg for Var<'a> {
    type Output = Var<'a>;
    fn neg(self) -> Var<'a> {
        self.op(Op::Neg(self.at))
    }
}

/// The operators with a constant on the right, each one recorded operation (x − v is x + (−v)).
macro_rules! with_constant {
    ($($tr:ident $f:ident $op:ident $doc:literal;)*) => {$(
        impl<'a> $tr<f64> for Var<'a> {
            type Output = Var<'a>;
            #[doc = $doc]
            fn $f(self, v: f64) -> Var<'a> {
                self.op(Op::$op(self.at, v))
            }
        }
    )*};
}

with_constant! {
    Add add AddC "c₀ = a₀ + v, cₖ = aₖ.";
    Mul mul MulC "cₖ = aₖ v.";
    Div div DivC "cₖ = aₖ / v, coefficient by coefficient (not x·(1/v), which would round twice).";
}

impl<'a> Sub<f64> for Var<'a> {
    type Output = Var<'a>;
    fn sub(self, v: f64) -> Var<'a> {
        self + (-v)
    }
}

impl<'a> Add<Var<'a>> for f64 {
    type Output = Var<'a>;
    fn add(self, x: Var<'a>) -> Var<'a> {
        x + self
    }
}

impl<'a> Sub<Var<'a>> for f64 {
    type Output = Var<'a>;
    fn sub(self, x: Var<'a>) -> Var<'a> {
        x.op(Op::CSub(self, x.at))
    }
}

impl<'a> Mul<Var<'a>> for f64 {
    type Output = Var<'a>;
    fn mul(self, x: Var<'a>) -> Var<'a> {
        x * self
    }
}

impl<'a> Div<Var<'a>> for f64 {
    type Output = Var<'a>;
    /// v/x: c₀ = v/b₀, cₖ = −Σⱼ₌₁..ₖ bⱼ cₖ₋ⱼ / b₀ (k ≥ 1).
    fn div(self, x: Var<'a>) -> Var<'a> {
        x.op(Op::CDiv(self, x.at))
    }
}
