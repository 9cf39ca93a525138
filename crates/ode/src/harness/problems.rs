//! Reference problems with exact solutions.

use core::f64::consts::PI;

use nalgebra::{SVector, Vector2, Vector4};

use super::elliptic::{elliptic_k, sncndn};
use crate::taylor::Var;

/// A reference problem y′ = f(t, y), y(0) = y₀ on [0, t_end] with a known exact solution.
///
/// Book: §4.11; HNW §II.10 (test problems).
pub trait Reference<const N: usize> {
    /// Name for tables and plots.
    fn name(&self) -> String;
    /// Initial state y(0).
    fn y0(&self) -> SVector<f64, N>;
    /// End of the interval.
    fn t_end(&self) -> f64;
    /// The right-hand side f(t, y).
    fn rhs(&self, t: f64, y: &SVector<f64, N>) -> SVector<f64, N>;
    /// The exact solution at t (components the error is measured on; see [`Reference::error`]).
    fn exact(&self, t: f64) -> SVector<f64, N>;
    /// The error of a computed y(t_end): max-norm distance to the exact solution.
    fn error(&self, y: &SVector<f64, N>) -> f64 {
        // (amax skips NaN, so test the state itself)
        let e = (y - self.exact(self.t_end())).amax();
        if e.is_finite() && y.iter().all(|c| c.is_finite()) { e } else { f64::INFINITY }
    }
    /// Relative drifts of the geometric invariants (off the group, of T, of |H|) of a final
    /// state, where the problem has them.
    fn drift(&self, _y: &SVector<f64, N>) -> Option<[f64; 3]> {
        None
    }
}

/// A separable second-order problem q̈ = a(q), state y = (q, v), for Störmer–Verlet.
///
/// Book: §4.11; HLW §I.1.
pub trait Separable<const M: usize> {
    /// The acceleration a(q).
    fn accel(&self, q: &SVector<f64, M>) -> SVector<f64, M>;
}

/// Harmonic oscillator ẍ = −x, x(0) = 1, ẋ(0) = 0 on [0, 10]: x = cos t.
///
/// Book: §4.11 (reference motion); HNW §II.10.
#[derive(Debug, Clone, Copy, Default)]
pub struct Oscillator;

impl Reference<2> for Oscillator {
    fn name(&self) -> String {
        "oscillator".into()
    }
    fn y0(&self) -> Vector2<f64> {
        Vector2::new(1.0, 0.0)
    }
    fn t_end(&self) -> f64 {
        10.0
    }
    #[inline]
    fn rhs(&self, _: f64, y: &Vector2<f64>) -> Vector2<f64> {
        Vector2::new(y[1], -y[0])
    }
    fn exact(&self, t: f64) -> Vector2<f64> {
        Vector2::new(t.cos(), -t.sin())
    }
}

impl Separable<1> for Oscillator {
    fn accel(&self, q: &SVector<f64, 1>) -> SVector<f64, 1> {
        -q
    }
}

/// Simple pendulum θ̈ = −sin θ released from rest at amplitude θ₀ (ω₀ = 1) on [0, 10].
/// Exact: sin(θ/2) = k sn(K − t | k²), θ̇ = −2k cn(K − t | k²), k = sin(θ₀/2).
///
/// Book: §4.11; A&S §16 (Jacobi elliptic functions).
#[derive(Debug, Clone, Copy)]
pub struct Pendulum {
    /// Amplitude θ₀ in radians, in (0, π).
    pub theta0: f64,
}

impl Reference<2> for Pendulum {
    fn name(&self) -> String {
        format!("pendulum θ0={:.1}", self.theta0)
    }
    fn y0(&self) -> Vector2<f64> {
        Vector2::new(self.theta0, 0.0)
    }
    fn t_end(&self) -> f64 {
        10.0
    }
    #[inline]
    fn rhs(&self, _: f64, y: &Vector2<f64>) -> Vector2<f64> {
        Vector2::new(y[1], -y[0].sin())
    }
    fn exact(&self, t: f64) -> Vector2<f64> {
        let k = (0.5 * self.theta0).sin();
        let m = k * k;
        let kk = elliptic_k(m).unwrap_or(f64::NAN);
        let (sn, cn, _) = sncndn(kk - t, m).unwrap_or((f64::NAN, f64::NAN, f64::NAN));
        Vector2::new(2.0 * (k * sn).asin(), -2.0 * k * cn)
    }
}

/// θ̈ = −sin θ as series (the Taylor integrator).
impl crate::taylor::TaylorRhs<2> for Pendulum {
    fn eval<'a>(&self, _: Var<'a>, y: &[Var<'a>; 2]) -> [Var<'a>; 2] {
        [y[1], -y[0].sin()]
    }
}

impl Separable<1> for Pendulum {
    fn accel(&self, q: &SVector<f64, 1>) -> SVector<f64, 1> {
        q.map(|x| -x.sin())
    }
}

/// Kepler problem r̈ = −r/|r|³ (μ = 1, a = 1) from periapsis with eccentricity e, on
/// [0, 20] (about 3.2 periods). Exact by Kepler's equation M = E − e sin E (Newton).
///
/// Book: §4.11; HLW §I.2.3.
#[derive(Debug, Clone, Copy)]
pub struct Kepler {
    /// Eccentricity e ∈ [0, 1).
    pub e: f64,
}

impl Kepler {
    /// Eccentric anomaly E with E − e sin E = M, by Newton from E = M + e sin M (or π for
    /// high e), to round-off.
    pub fn eccentric_anomaly(&self, mean: f64) -> f64 {
        let e = self.e;
        let m = mean.rem_euclid(2.0 * PI);
        let mut ea = if e > 0.8 { PI } else { m + e * m.sin() };
        for _ in 0..50 {
            let d = (ea - e * ea.sin() - m) / (1.0 - e * ea.cos());
            ea -= d;
            if d.abs() <= 4.0 * f64::EPSILON {
                break;
            }
        }
        ea
    }
}

impl Reference<4> for Kepler {
    fn name(&self) -> String {
        format!("Kepler e={}", self.e)
    }
    fn y0(&self) -> Vector4<f64> {
        self.exact(0.0)
    }
    fn t_end(&self) -> f64 {
        20.0
    }
    #[inline]
    fn rhs(&self, _: f64, y: &Vector4<f64>) -> Vector4<f64> {
        let r2 = y[0] * y[0] + y[1] * y[1];
        let r3 = r2 * r2.sqrt();
        Vector4::new(y[2], y[3], -y[0] / r3, -y[1] / r3)
    }
    fn exact(&self, t: f64) -> Vector4<f64> {
        // x = cos E − e, y = √(1−e²) sin E, Ė = 1/(1 − e cos E)
        let e = self.e;
        let ea = self.eccentric_anomaly(t);
        let b = (1.0 - e * e).sqrt();
        let de = 1.0 / (1.0 - e * ea.cos());
        Vector4::new(ea.cos() - e, b * ea.sin(), -ea.sin() * de, b * ea.cos() * de)
    }
}

/// r̈ = −r u with u = (x² + y²)^(−3/2), as series (the Taylor integrator).
impl crate::taylor::TaylorRhs<4> for Kepler {
    fn eval<'a>(&self, _: Var<'a>, y: &[Var<'a>; 4]) -> [Var<'a>; 4] {
        let u = (y[0].square() + y[1].square()).powf(-1.5);
        [y[2], y[3], -(y[0] * u), -(y[1] * u)]
    }
}

impl Separable<2> for Kepler {
    fn accel(&self, q: &SVector<f64, 2>) -> SVector<f64, 2> {
        let r2 = q.norm_squared();
        -q / (r2 * r2.sqrt())
    }
}

/// Stiff chain of `5` unit masses between two walls, unit springs K = tridiag(−1, 2, −1)
/// and proportional dashpots C = αK (the harness uses α = 1000: modal roots from −0.001 to
/// −3732, stiffness ratio ≈ 4·10⁶). State y = (x, v); x₀ = (1, 0, 0, 0, 0), v₀ = 0, on
/// [0, 10]. Exact by the modes: K vⱼ = λⱼ vⱼ, λⱼ = 2 − 2cos(jπ/6), vⱼ,ᵢ = sin(ijπ/6).
///
/// Book: §4.11; HNW II §IV.1 (stiff problems).
#[derive(Debug, Clone, Copy)]
pub struct SpringChain {
    /// Damping ratio α of C = αK.
    pub alpha: f64,
}

/// Number of masses of [`SpringChain`].
pub const CHAIN_MASSES: usize = 5;

impl SpringChain {
    /// Mode j (1-based) shape vⱼ,ᵢ = sin(ijπ/(n+1)) normalised, and eigenvalue λⱼ.
    fn mode(j: usize) -> ([f64; CHAIN_MASSES], f64) {
        let n1 = (CHAIN_MASSES + 1) as f64;
        let norm = (n1 / 2.0).sqrt();
        let v = core::array::from_fn(|i| ((i + 1) as f64 * j as f64 * PI / n1).sin() / norm);
        (v, 2.0 - 2.0 * (j as f64 * PI / n1).cos())
    }
}

impl Reference<10> for SpringChain {
    fn name(&self) -> String {
        format!("stiff chain α={}", self.alpha)
    }
    fn y0(&self) -> SVector<f64, 10> {
        let mut y = SVector::<f64, 10>::zeros();
        y[0] = 1.0;
        y
    }
    fn t_end(&self) -> f64 {
        10.0
    }
    #[inline]
    fn rhs(&self, _: f64, y: &SVector<f64, 10>) -> SVector<f64, 10> {
        let n = CHAIN_MASSES;
        let mut d = SVector::<f64, 10>::zeros();
        for i in 0..n {
            // (K u)ᵢ = 2uᵢ − uᵢ₋₁ − uᵢ₊₁ with walls u₀ = u_{n+1} = 0
            let k = |u: &dyn Fn(usize) -> f64| {
                2.0 * u(i) - if i > 0 { u(i - 1) } else { 0.0 } - if i + 1 < n { u(i + 1) } else { 0.0 }
            };
            let kx = k(&|j| y[j]);
            let kv = k(&|j| y[n + j]);
            d[i] = y[n + i];
            // ẍ = −Kx − αKv
            d[n + i] = -kx - self.alpha * kv;
        }
        d
    }
    fn exact(&self, t: f64) -> SVector<f64, 10> {
        let n = CHAIN_MASSES;
        let y0 = self.y0();
        let mut y = SVector::<f64, 10>::zeros();
        for j in 1..=n {
            let (v, lam) = Self::mode(j);
            let q0: f64 = (0..n).map(|i| v[i] * y0[i]).sum();
            let p0: f64 = (0..n).map(|i| v[i] * y0[n + i]).sum();
            // q̈ + αλq̇ + λq = 0: roots of r² + αλ r + λ = 0
            let b = self.alpha * lam;
            let disc = b * b - 4.0 * lam;
            let (q, p) = if disc > 0.0 {
                // real roots, the small one from the product r₁r₂ = λ (no cancellation)
                let r1 = -0.5 * (b + disc.sqrt());
                let r2 = lam / r1;
                let a1 = (p0 - r2 * q0) / (r1 - r2);
                let a2 = q0 - a1;
                let (e1, e2) = ((r1 * t).exp(), (r2 * t).exp());
                (a1 * e1 + a2 * e2, a1 * r1 * e1 + a2 * r2 * e2)
            } else {
                let (s, w) = (-0.5 * b, 0.5 * (-disc).sqrt());
                let c2 = (p0 - s * q0) / w;
                let (ex, c, sn) = ((s * t).exp(), (w * t).cos(), (w * t).sin());
                (ex * (q0 * c + c2 * sn), ex * (s * (q0 * c + c2 * sn) + w * (-q0 * sn + c2 * c)))
            };
            for i in 0..n {
                y[i] += v[i] * q;
                y[n + i] += v[i] * p;
            }
        }
        y
    }
}
