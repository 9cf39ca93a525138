//! Gragg's midpoint rule for the rows of the extrapolation table ([`super::extrapolation`]),
//! one row at a time or, for a right-hand side that evaluates two states at once
//! ([`Rhs::pairs`]), rows 1 … k of a step side by side in two lanes: the rows are independent
//! of one another (each starts from y₀ with its own nⱼ), so lane A and lane B each take a
//! share of them, balanced by their evaluations, and every evaluation of the two is one
//! [`Rhs::call_pair_into`]. Each row's operations are those of the single lane, in the same
//! order: the same raw entries, so the same table, steps and bits. A row that the controller
//! then does not read (it accepted or rejected in row k − 1, or a row before diverged) has
//! cost its evaluations for nothing; they are counted.
//!
//! Book: §4.11; HNW §II.9 (the rows of the table are independent: parallel extrapolation).

use crate::state::{State, check_rhs};
use crate::{OdeError, Rhs};

/// Largest number of extrapolation columns allowed (HNW's KM; the table then reaches order
/// 2·KM: 2·12 = 24 is far beyond what f64 can use).
pub const GBS_MAX_COLUMNS: usize = 12;

/// One lane: Gragg's increments δ_{i−1}, δᵢ of its current row, f's argument y₀ + δᵢ and
/// f's value, and where it is: row j (1-based), evaluation m of n, step H/n.
pub(super) struct Lane<S> {
    yh1: S,
    yh2: S,
    pub(super) arg: S,
    dy: S,
    j: usize,
    m: usize,
    n: usize,
    hj: f64,
}

/// out ← y + δ, element by element.
#[inline(always)]
pub(super) fn offset<S: State>(out: &mut S, y: &S, d: &S) {
    for ((o, a), b) in out.as_mut_slice().iter_mut().zip(y.as_slice()).zip(d.as_slice()) {
        *o = a + b;
    }
}

impl<S: State> Lane<S> {
    pub(super) fn new(y0: &S) -> Self {
        Self { yh1: y0.clone(), yh2: y0.clone(), arg: y0.clone(), dy: y0.clone(), j: 0, m: 0, n: 0, hj: 0.0 }
    }

    /// Starts row j of n steps over H = `h`: δ₀ = 0, δ₁ = (H/n) f(t, y₀).
    #[inline(always)]
    fn start(&mut self, j: usize, n: usize, h: f64, dz: &S) {
        (self.j, self.n, self.m, self.hj) = (j, n, 1, h / n as f64);
        self.yh1.as_mut_slice().fill(0.0);
        self.yh2.as_mut_slice().fill(0.0);
        self.yh2.add_scaled(self.hj, dz);
    }

    /// f's next argument y₀ + δ_m (in `arg`) and its time: tₘ = t + m H/n, the last one t + H.
    #[inline(always)]
    fn prepare(&mut self, t: f64, h: f64, y: &S) -> f64 {
        offset(&mut self.arg, y, &self.yh2);
        if self.m < self.n { t + self.hj * self.m as f64 } else { t + h }
    }

    /// Takes f's value (in `dy`): δ_{m+1} = δ_{m−1} + 2(H/n) f, or after the last evaluation
    /// the smoothed row T = (δ_{n−1} + δ_n + (H/n) f(t + H, y₀ + δ_n)) / 2 into `out`; `true`
    /// when the row is done.
    #[inline(always)]
    fn advance(&mut self, table: &mut [S]) -> bool {
        if self.m < self.n {
            self.yh1.add_scaled(2.0 * self.hj, &self.dy);
            core::mem::swap(&mut self.yh1, &mut self.yh2);
            self.m += 1;
            return false;
        }
        let hj = self.hj;
        for ((o, a), (b, d)) in table[self.j - 1]
            .as_mut_slice()
            .iter_mut()
            .zip(self.yh1.as_slice())
            .zip(self.yh2.as_slice().iter().zip(self.dy.as_slice()))
        {
            *o = 0.5 * (a + b + hj * d);
        }
        true
    }
}

/// The lanes and what they left for the controller this attempt.
pub(super) struct Lanes<S> {
    pub(super) a: Lane<S>,
    b: Lane<S>,
    /// Bit j: row j's raw entry is in the table.
    ready: u32,
}

/// The step, its start and f there: (t, H, y₀, f(t, y₀)).
pub(super) type At<'a, S> = (f64, f64, &'a S, &'a S);

impl<S: State> Lanes<S> {
    pub(super) fn new(y0: &S) -> Self {
        Self { a: Lane::new(y0), b: Lane::new(y0), ready: 0 }
    }

    /// Row j's raw entry into `table[j − 1]` with lane A alone (unless a paired pass left it
    /// there); the evaluations counted in `fevals`.
    pub(super) fn row<F: Rhs<S>>(
        &mut self,
        f: &mut F,
        (j, n): (usize, usize),
        at: At<'_, S>,
        table: &mut [S],
        fevals: &mut usize,
    ) -> Result<(), OdeError> {
        if self.ready & (1 << j) != 0 {
            return Ok(());
        }
        let (t, h, y, dz) = at;
        let lane = &mut self.a;
        lane.start(j, n, h, dz);
        loop {
            let tm = lane.prepare(t, h, y);
            *fevals += 1;
            f.call_into(tm, &lane.arg, &mut lane.dy);
            check_rhs(&lane.dy, &lane.arg, tm, (t, 1 + lane.m))?;
            if lane.advance(table) {
                return Ok(());
            }
        }
    }

    /// Forgets the last attempt's rows.
    pub(super) fn clear(&mut self) {
        self.ready = 0;
    }

    /// Rows 1 … k (step numbers `nj`, index j − 1) in two lanes, each row to the lane with
    /// fewer evaluations so far, longest first; raw entries into the table and `ready`.
    pub(super) fn rows<F: Rhs<S>>(
        &mut self,
        f: &mut F,
        k: usize,
        nj: &[usize],
        at: At<'_, S>,
        table: &mut [S],
        fevals: &mut usize,
    ) {
        let (t, h, y, dz) = at;
        // the lanes' queues, each in the order the rows were dealt (longest first)
        let (mut qa, mut qb) = ([0usize; GBS_MAX_COLUMNS + 1], [0usize; GBS_MAX_COLUMNS + 1]);
        let (mut na, mut nb, mut wa, mut wb) = (0, 0, 0, 0);
        for j in (1..=k).rev() {
            if wa <= wb {
                (qa[na], na, wa) = (j, na + 1, wa + nj[j - 1]);
            } else {
                (qb[nb], nb, wb) = (j, nb + 1, wb + nj[j - 1]);
            }
        }
        let (mut ia, mut ib) = (0, 0);
        let next = |lane: &mut Lane<S>, q: &[usize], i: &mut usize, len: usize| -> bool {
            if *i == len {
                return false;
            }
            let j = q[*i];
            *i += 1;
            lane.start(j, nj[j - 1], h, dz);
            true
        };
        let mut on_a = next(&mut self.a, &qa, &mut ia, na);
        let mut on_b = next(&mut self.b, &qb, &mut ib, nb);
        while on_a || on_b {
            let ta = if on_a { self.a.prepare(t, h, y) } else { t };
            let tb = if on_b { self.b.prepare(t, h, y) } else { t };
            let (la, lb) = (&mut self.a, &mut self.b);
            match (on_a, on_b) {
                (true, true) => {
                    *fevals += 2;
                    f.call_pair_into((ta, &la.arg, &mut la.dy), (tb, &lb.arg, &mut lb.dy));
                }
                (true, false) => {
                    *fevals += 1;
                    f.call_into(ta, &la.arg, &mut la.dy);
                }
                _ => {
                    *fevals += 1;
                    f.call_into(tb, &lb.arg, &mut lb.dy);
                }
            }
            for (on, lane, q, i, len) in
                [(&mut on_a, la, &qa, &mut ia, na), (&mut on_b, lb, &qb, &mut ib, nb)]
            {
                if !*on {
                    continue;
                }
                if check_rhs(&lane.dy, &lane.arg, t, (t, lane.m)).is_err() {
                    // the lane stops; its rows are built alone if they are read, where a
                    // failing evaluation raises its error
                    *on = false;
                } else if lane.advance(table) {
                    self.ready |= 1 << lane.j;
                    *on = next(lane, q, i, len);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use std::cell::Cell;

    use nalgebra::{SVector, Vector4};

    use crate::{Extrapolation, Rhs};

    /// A right-hand side that says it pairs; `sabotage` writes NaN into the second lane of
    /// every pair (a broken `call_pair_into`: its rows must be rebuilt alone).
    struct Counting<'a, F> {
        f: F,
        pairs: &'a Cell<usize>,
        sabotage: bool,
    }

    impl<const N: usize, F: FnMut(f64, &SVector<f64, N>) -> SVector<f64, N>> Rhs<SVector<f64, N>>
        for Counting<'_, F>
    {
        const IN_PLACE: bool = false;
        fn call(&mut self, t: f64, y: &SVector<f64, N>) -> SVector<f64, N> {
            (self.f)(t, y)
        }
        fn call_into(&mut self, t: f64, y: &SVector<f64, N>, out: &mut SVector<f64, N>) {
            *out = (self.f)(t, y);
        }
        fn pairs(&self) -> bool {
            true
        }
        fn call_pair_into(
            &mut self,
            a: (f64, &SVector<f64, N>, &mut SVector<f64, N>),
            b: (f64, &SVector<f64, N>, &mut SVector<f64, N>),
        ) {
            self.pairs.set(self.pairs.get() + 1);
            *a.2 = (self.f)(a.0, a.1);
            *b.2 = if self.sabotage { SVector::repeat(f64::NAN) } else { (self.f)(b.0, b.1) };
        }
    }

    /// Kepler's problem at e = 0.6 (period 2π) and Van der Pol at μ = 5.
    fn kepler(_: f64, y: &Vector4<f64>) -> Vector4<f64> {
        let r3 = (y[0] * y[0] + y[1] * y[1]).powf(1.5);
        Vector4::new(y[2], y[3], -y[0] / r3, -y[1] / r3)
    }
    fn van_der_pol(_: f64, y: &SVector<f64, 2>) -> SVector<f64, 2> {
        SVector::<f64, 2>::new(y[1], 5.0 * (1.0 - y[0] * y[0]) * y[1] - y[0])
    }

    fn bits<const N: usize>(s: &crate::explicit::Solution<SVector<f64, N>>) -> Vec<u64> {
        s.t.iter().chain(s.y.iter().flat_map(|y| y.iter())).map(|x| x.to_bits()).collect()
    }

    /// Rows built two at a time give the steps and bits of rows built one at a time, at loose
    /// and tight tolerances, also when every second lane fails (its rows rebuilt alone); the
    /// extra evaluations are the rows built but not read, at most 12 %.
    #[test]
    fn paired_rows_give_the_steps_and_bits_of_single_rows() {
        let e: f64 = 0.6;
        let y0 = Vector4::new(1.0 - e, 0.0, 0.0, ((1.0 + e) / (1.0 - e)).sqrt());
        let v0 = SVector::<f64, 2>::new(2.0, 0.0);
        for tol in [1e-5, 1e-9, 1e-13] {
            let g = Extrapolation::gbs().rtol(tol).atol(tol);
            let plain = g.solve(kepler, 0.0, &y0, 20.0).expect("smooth");
            for sabotage in [false, true] {
                let pairs = Cell::new(0);
                let r = Counting { f: kepler, pairs: &pairs, sabotage };
                let paired = g.solve_rhs(r, 0.0, &y0, 20.0).expect("smooth");
                assert_eq!(bits(&paired), bits(&plain), "Kepler, tol {tol:e}, sabotage {sabotage}");
                assert!(pairs.get() > 0);
                let (p, q) = (paired.work.fevals as f64, plain.work.fevals as f64);
                // (Kepler's step sizes vary over the orbit, so the controller stops in row k − 1
                // now and then: 7–9 % more evaluations, measured; a chain of pins, 2–3 %)
                assert!(p >= q && (sabotage || p <= 1.12 * q), "{p} against {q} evaluations");
            }
            let plain = g.solve(van_der_pol, 0.0, &v0, 10.0).expect("smooth");
            let r = Counting { f: van_der_pol, pairs: &Cell::new(0), sabotage: false };
            let paired = g.solve_rhs(r, 0.0, &v0, 10.0).expect("smooth");
            assert_eq!(bits(&paired), bits(&plain), "Van der Pol, tol {tol:e}");
        }
    }

    /// A right-hand side that is NaN from t = 0.5 on: the same typed error, paired or not.
    #[test]
    fn paired_rows_raise_the_error_of_single_rows() {
        let late = |t: f64, y: &SVector<f64, 2>| if t > 0.5 { SVector::repeat(f64::NAN) } else { -*y };
        let (g, y0) = (Extrapolation::gbs().rtol(1e-10).atol(1e-10), SVector::<f64, 2>::new(1.0, 2.0));
        let plain = g.solve(late, 0.0, &y0, 1.0).expect_err("NaN after 0.5");
        let paired = g.solve_rhs(Counting { f: late, pairs: &Cell::new(0), sabotage: false }, 0.0, &y0, 1.0);
        assert_eq!(paired.expect_err("NaN after 0.5").to_string(), plain.to_string());
    }
}
