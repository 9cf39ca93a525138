//! The torque-free asymmetric rigid body: Euler's equations with quaternion kinematics,
//! exact ω by Jacobi elliptic functions.

use nalgebra::{SVector, Vector3, Vector4};
use vectrix_frames::{Frame, Resolve};
use vectrix_tensor::{Dyadic, Rotor, Vector};

use super::elliptic::sncndn;
use super::problems::Reference;

/// Torque-free rigid body with principal inertias I₁ < I₂ < I₃, state
/// y = (ω_B, q) ∈ ℝ⁷: body angular velocity and Euler parameters q = (η, ε) (scalar first):
/// I ω̇ = Iω × ω (Euler), q̇ = ½ q ⊗ (0, ω_B) (4.11.13). Starts at ω_B(0) = (ω₁, 0, ω₃),
/// q = 1, runs on [0, 20]. The error is measured on ω only (the exact attitude needs theta
/// functions); the attitude is judged by the drift of |q| off 1, of T and of |H|.
///
/// Exact ω (Landau & Lifshitz §37), with H² = Σ(Iᵢωᵢ)², 2T = ΣIᵢωᵢ²:
/// for H² < 2TI₂: ω₁ = a₁ dn τ, ω₂ = a₂ sn τ, ω₃ = a₃ cn τ,
/// τ = t√((I₂−I₁)(2TI₃−H²)/(I₁I₂I₃)), m = (I₃−I₂)(H²−2TI₁)/((I₂−I₁)(2TI₃−H²));
/// for H² > 2TI₂: cn and dn exchange roles and the indices 1 ↔ 3 of the rate and parameter.
///
/// Book: §4.11, (4.11.13); ch. 9 (Euler's equations); Landau & Lifshitz, *Mechanics*, §37.
#[derive(Debug, Clone, Copy)]
pub struct RigidBody {
    /// Principal inertias, strictly increasing.
    pub inertia: [f64; 3],
    /// ω₁ and ω₃ of the initial body angular velocity (ω₂(0) = 0).
    pub omega13: [f64; 2],
    /// End time.
    pub t_end: f64,
}

impl Default for RigidBody {
    fn default() -> Self {
        Self { inertia: [1.0, 2.0, 3.0], omega13: [1.0, 0.5], t_end: 20.0 }
    }
}

/// Euler's equations ω̇ = I⁻¹(Iω × ω) in principal axes.
#[inline]
pub fn euler_equations(i: &[f64; 3], w: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(
        (i[1] - i[2]) * w[1] * w[2] / i[0],
        (i[2] - i[0]) * w[2] * w[0] / i[1],
        (i[0] - i[1]) * w[0] * w[1] / i[2],
    )
}

/// q̇ = ½ q ⊗ (0, ω_B) for q = (η, ε) scalar first (4.11.13).
#[inline]
pub fn quaternion_rate(q: &Vector4<f64>, w: &Vector3<f64>) -> Vector4<f64> {
    let (eta, e) = (q[0], Vector3::new(q[1], q[2], q[3]));
    let de = (w * eta + e.cross(w)) * 0.5;
    Vector4::new(-0.5 * e.dot(w), de[0], de[1], de[2])
}

/// Euler's equations and q̇ = ½ q ⊗ (0, ω) as series (the Taylor integrator), the same
/// formulas as [`euler_equations`] and [`quaternion_rate`].
impl crate::taylor::TaylorRhs<7> for RigidBody {
    fn eval<'a>(
        &self,
        _: crate::taylor::Var<'a>,
        y: &[crate::taylor::Var<'a>; 7],
    ) -> [crate::taylor::Var<'a>; 7] {
        let i = self.inertia;
        let (w, eta, e) = ([y[0], y[1], y[2]], y[3], [y[4], y[5], y[6]]);
        // ½ (η ω + ε × ω)
        let de = |a: usize, b: usize, c: usize| (eta * w[a] + (e[b] * w[c] - e[c] * w[b])) * 0.5;
        [
            w[1] * w[2] * ((i[1] - i[2]) / i[0]),
            w[2] * w[0] * ((i[2] - i[0]) / i[1]),
            w[0] * w[1] * ((i[0] - i[1]) / i[2]),
            (e[0] * w[0] + e[1] * w[1] + e[2] * w[2]) * -0.5,
            de(0, 1, 2),
            de(1, 2, 0),
            de(2, 0, 1),
        ]
    }
}

impl RigidBody {
    /// Exact body angular velocity at t.
    pub fn exact_omega(&self, t: f64) -> Vector3<f64> {
        let [i1, i2, i3] = self.inertia;
        let w0 = Vector3::new(self.omega13[0], 0.0, self.omega13[1]);
        let h2: f64 = (0..3).map(|k| (self.inertia[k] * w0[k]).powi(2)).sum();
        let t2: f64 = (0..3).map(|k| self.inertia[k] * w0[k] * w0[k]).sum();
        let (s1, s3) = (self.omega13[0].signum(), self.omega13[1].signum());
        let a1 = ((t2 * i3 - h2) / (i1 * (i3 - i1))).sqrt();
        let a3 = ((h2 - t2 * i1) / (i3 * (i3 - i1))).sqrt();
        if h2 < t2 * i2 {
            // rotation about the minor axis side: ω₁ ~ dn, ω₃ ~ cn
            let a2 = ((h2 - t2 * i1) / (i2 * (i2 - i1))).sqrt();
            let rate = ((i2 - i1) * (t2 * i3 - h2) / (i1 * i2 * i3)).sqrt();
            let m = (i3 - i2) * (h2 - t2 * i1) / ((i2 - i1) * (t2 * i3 - h2));
            let (sn, cn, dn) = sncndn(rate * t, m).unwrap_or((f64::NAN, f64::NAN, f64::NAN));
            Vector3::new(s1 * a1 * dn, s1 * s3 * a2 * sn, s3 * a3 * cn)
        } else {
            // rotation about the major axis side: ω₁ ~ cn, ω₃ ~ dn
            let a2 = ((t2 * i3 - h2) / (i2 * (i3 - i2))).sqrt();
            let rate = ((i3 - i2) * (h2 - t2 * i1) / (i1 * i2 * i3)).sqrt();
            let m = (i2 - i1) * (t2 * i3 - h2) / ((i3 - i2) * (h2 - t2 * i1));
            let (sn, cn, dn) = sncndn(rate * t, m).unwrap_or((f64::NAN, f64::NAN, f64::NAN));
            Vector3::new(s1 * a1 * cn, s1 * s3 * a2 * sn, s3 * a3 * dn)
        }
    }

    /// Kinetic energy T = ½ Σ Iᵢωᵢ².
    pub fn energy(&self, w: &Vector3<f64>) -> f64 {
        0.5 * (0..3).map(|k| self.inertia[k] * w[k] * w[k]).sum::<f64>()
    }

    /// |H| = |Iω| (invariant in the body too: the body only rotates H).
    pub fn momentum(&self, w: &Vector3<f64>) -> f64 {
        Vector3::new(self.inertia[0] * w[0], self.inertia[1] * w[1], self.inertia[2] * w[2]).norm()
    }

    /// Relative drifts (|q| − 1 or |R R̄ − 1|, ΔT/T, Δ|H|/|H|) of a final state.
    pub fn drift(&self, w: &Vector3<f64>, attitude_norm: f64) -> [f64; 3] {
        let w0 = self.exact_omega(0.0);
        let (t0, h0) = (self.energy(&w0), self.momentum(&w0));
        [
            (attitude_norm - 1.0).abs(),
            ((self.energy(w) - t0) / t0).abs(),
            ((self.momentum(w) - h0) / h0).abs(),
        ]
    }

    /// The Lie-group form on Rotor × ℝ³ (frame-free): ξ(R, ω_b) = (ω_b, J⁻¹(Jω_b × ω_b)),
    /// with J = Σ Iₖ âₖâₖ the inertia dyad pulled back to the reference frame `a`.
    pub fn lie_rhs(&self, a: &Frame) -> impl Fn(f64, &(Rotor, Vector)) -> (Vector, Vector) + use<> {
        let axes = [a.i(), a.j(), a.k()];
        let dyad = |s: &dyn Fn(f64) -> f64| {
            (0..3).fold(Dyadic::zero(), |acc, k| acc + axes[k].outer(&axes[k]) * s(self.inertia[k]))
        };
        let j = dyad(&|x| x);
        let j_inv = dyad(&|x| 1.0 / x);
        move |_, (_, w): &(Rotor, Vector)| (*w, j_inv * (j * *w).cross(w))
    }

    /// Initial state on Rotor × ℝ³: R = 1, ω_b resolved in `a` equal to ω_B(0).
    pub fn lie_y0(&self, a: &Frame) -> (Rotor, Vector) {
        let w = self.exact_omega(0.0);
        (Rotor::identity(), a.vector([w[0], w[1], w[2]]))
    }

    /// Error, |R R̄ − 1| and drift of a final Lie state.
    pub fn lie_error(&self, a: &Frame, y: &(Rotor, Vector)) -> (f64, [f64; 3]) {
        let w = y.1.resolve(a);
        let e = (w - self.exact_omega(self.t_end)).amax();
        let r = &y.0;
        let norm2 = r.scalar() * r.scalar() + r.bivector().norm().powi(2);
        (if e.is_finite() { e } else { f64::INFINITY }, self.drift(&w, norm2.sqrt()))
    }
}

impl Reference<7> for RigidBody {
    fn name(&self) -> String {
        "rigid body".into()
    }
    fn y0(&self) -> SVector<f64, 7> {
        let w = self.exact_omega(0.0);
        SVector::<f64, 7>::from_column_slice(&[w[0], w[1], w[2], 1.0, 0.0, 0.0, 0.0])
    }
    fn t_end(&self) -> f64 {
        self.t_end
    }
    #[inline]
    fn rhs(&self, _: f64, y: &SVector<f64, 7>) -> SVector<f64, 7> {
        let w = Vector3::new(y[0], y[1], y[2]);
        let q = Vector4::new(y[3], y[4], y[5], y[6]);
        let dw = euler_equations(&self.inertia, &w);
        let dq = quaternion_rate(&q, &w);
        SVector::<f64, 7>::from_column_slice(&[dw[0], dw[1], dw[2], dq[0], dq[1], dq[2], dq[3]])
    }
    /// ω exact; the quaternion part is not known in closed form and is returned as q(0).
    fn exact(&self, t: f64) -> SVector<f64, 7> {
        let w = self.exact_omega(t);
        SVector::<f64, 7>::from_column_slice(&[w[0], w[1], w[2], 1.0, 0.0, 0.0, 0.0])
    }
    fn error(&self, y: &SVector<f64, 7>) -> f64 {
        let e = (Vector3::new(y[0], y[1], y[2]) - self.exact_omega(self.t_end)).amax();
        if e.is_finite() { e } else { f64::INFINITY }
    }
    fn drift(&self, y: &SVector<f64, 7>) -> Option<[f64; 3]> {
        let q = Vector4::new(y[3], y[4], y[5], y[6]);
        Some(RigidBody::drift(self, &Vector3::new(y[0], y[1], y[2]), q.norm()))
    }
}
