//! Dense output: the continuous extension of an accepted step.

use crate::state::State;

/// The interpolant of one accepted step [t, t + h]: Hairer's form
/// y(t + θh) = c₀ + θ(c₁ + (1−θ)(c₂ + θ(c₃ + (1−θ) q(θ)))), with q ≡ c₄ for DOPRI5 (order 4)
/// and q(θ) = c₄ + θ(c₅ + (1−θ)(c₆ + θc₇)) for DOP853 (order 7); for Radau IIA 5 the
/// collocation polynomial y(t + θh) = c₀ + s(c₁ + (s − c₂ + 1)(c₂' + (s − c₁ + 1)c₃)) with
/// s = θ − 1 through the step's end and its three stages (order 3 uniformly, exact at the
/// collocation points); for BDF the polynomial through the last k + 1 points in backward
/// differences (Shampine & Reichelt 1997); for a Taylor step its series Σ cₖθᵏ.
///
/// Book: §4.11; HNW §II.6 (dense output), `contd5`/`contd8` of `dopri5.f`/`dop853.f`; HW
/// §IV.8 and `contr5` of `radau5.f` (Radau IIA collocation polynomial).
#[derive(Debug, Clone)]
pub struct DenseStep<S> {
    /// Start of the step.
    pub t: f64,
    /// Step size.
    pub h: f64,
    pub(crate) c: Vec<S>,
    pub(crate) form: Form,
}

/// Which polynomial the coefficients of a [`DenseStep`] describe.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Form {
    /// Hairer's Dormand–Prince form (5 coefficients for DOPRI5, 8 for DOP853).
    DormandPrince,
    /// RADAU5's collocation polynomial about the step's end (4 coefficients).
    Radau,
    /// BDF's interpolating polynomial in backward differences D₀ … Dₖ on the grid of the
    /// given step about the step's end.
    Bdf(f64),
    /// A Taylor step's series in θ: y(t + θh) = Σₖ cₖ θᵏ (cₖ = xₖhᵏ).
    Taylor,
}

impl<S: State> DenseStep<S> {
    /// The interpolated state at `t` (θ = (t − t₀)/h, meant for θ ∈ [0, 1]).
    pub fn eval(&self, t: f64) -> S {
        let s = (t - self.t) / self.h;
        let mut out = self.c[0].clone();
        let o = out.as_mut_slice();
        let c: Vec<&[f64]> = self.c.iter().map(State::as_slice).collect();
        if let Form::Bdf(hp) = self.form {
            // y(t) = D₀ + Σⱼ Dⱼ Πₘ₌₀ʲ⁻¹ (t − (tₙ − m·hp))/((m + 1)·hp), tₙ the step's end
            let t_n = self.t + self.h;
            let mut prod = 1.0;
            for (m, cj) in c.iter().enumerate().skip(1) {
                prod *= (t - (t_n - (m - 1) as f64 * hp)) / (m as f64 * hp);
                for (oi, x) in o.iter_mut().zip(cj.iter()) {
                    *oi += prod * x;
                }
            }
            return out;
        }
        if self.form == Form::Taylor {
            // Horner's rule in θ
            for (i, oi) in o.iter_mut().enumerate() {
                *oi = c.iter().rev().fold(0.0, |acc, ck| acc * s + ck[i]);
            }
            return out;
        }
        if self.form == Form::Radau {
            let (c1m1, c2m1) = crate::implicit::radau_nodes_minus_one();
            let s = s - 1.0;
            for (i, oi) in o.iter_mut().enumerate() {
                *oi += s * (c[1][i] + (s - c2m1) * (c[2][i] + (s - c1m1) * c[3][i]));
            }
            return out;
        }
        let s1 = 1.0 - s;
        for (i, oi) in o.iter_mut().enumerate() {
            let q =
                if c.len() == 8 { c[4][i] + s * (c[5][i] + s1 * (c[6][i] + s * c[7][i])) } else { c[4][i] };
            *oi += s * (c[1][i] + s1 * (c[2][i] + s * (c[3][i] + s1 * q)));
        }
        out
    }
}

/// The four leading coefficients shared by DOPRI5 and DOP853:
/// c₀ = y₀, c₁ = y₁ − y₀, c₂ = h f₀ − c₁, c₃ = c₁ − h f₁ − c₂ (cubic Hermite part).
pub(crate) fn hermite_part<S: State>(y0: &S, y1: &S, f0: &S, f1: &S, h: f64) -> [S; 4] {
    let mut c1 = y1.clone();
    let mut c2 = y1.clone();
    let mut c3 = y1.clone();
    for i in 0..y0.dim() {
        let ydiff = y1.as_slice()[i] - y0.as_slice()[i];
        let bspl = h * f0.as_slice()[i] - ydiff;
        c1.as_mut_slice()[i] = ydiff;
        c2.as_mut_slice()[i] = bspl;
        c3.as_mut_slice()[i] = ydiff - h * f1.as_slice()[i] - bspl;
    }
    [y0.clone(), c1, c2, c3]
}

/// h Σⱼ dⱼ kⱼ (zero coefficients skipped).
pub(crate) fn weighted<S: State>(template: &S, h: f64, d: &[f64], k: &[S]) -> S {
    let mut out = template.clone();
    out.as_mut_slice().fill(0.0);
    for (dj, kj) in d.iter().zip(k) {
        if *dj != 0.0 {
            for (o, x) in out.as_mut_slice().iter_mut().zip(kj.as_slice()) {
                *o += h * dj * x;
            }
        }
    }
    out
}
