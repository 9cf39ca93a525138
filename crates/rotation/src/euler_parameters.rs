//! Quaternions as Euler parameters of a rotation (book §2.14–2.17): conversions with
//! 𝓡, eigenaxis and angle, angle vector, Gibbs vector and modified Rodrigues parameters.
//!
//! Every conversion here works on components resolved in one frame: q_{B/A} describes
//! 𝓡_{B/A} = R⃗_{B/A}|_A (= R⃗_{B/A}|_B, Fact 2.10.1), the active rotation
//! 𝓡(q)x = 𝐪𝐱𝐪̄ (Prob 2.26.23).

use core::any::Any;

use nalgebra::{Matrix3, Vector3};
use vectrix_tensor::Scalar;

use crate::series::{angle_0_pi, atan2, canonical_sign, cos_sinc_of_square, norm3, sin_cos, sinc};
use crate::vmath::{FMA_BUILTIN, SIN_COS_MAX, madd};
use crate::{AxisAngle, Quaternion, RotationError, check_rotation_matrix};

impl<T: Scalar> Quaternion<T> {
    /// Euler parameters of the rotation matrix 𝓡 (checked): Shepperd's method in Markley's
    /// form, then η ≥ 0.
    ///
    /// Book: §2.15, (2.15.2), (2.15.8–10) replaced by the largest-pivot method (notes ch2b
    /// §3.2: the printed η = ½√(1 + tr 𝓡) loses 1e-4 at θ = π − 1e-6).
    ///
    /// # Errors
    /// As [`check_rotation_matrix`]: non-finite, not orthonormal within `tol`, or det < 0.
    /// Noisy matrices must be projected explicitly with [`crate::nearest_rotation`].
    #[doc(alias = "from_dcm")]
    #[doc(alias = "from_matrix")]
    pub fn from_rotation_matrix(r: &Matrix3<T>, tol: f64) -> Result<Self, RotationError> {
        vectrix_tensor::check_tolerance(tol, "tol")?;
        check_rotation_matrix(r, tol)?;
        Ok(Self::from_rotation_matrix_unchecked(r))
    }

    /// Shepperd/Markley without the orthonormality check, for hot paths whose input is a
    /// rotation by construction. The result is normalised and canonical (η ≥ 0).
    ///
    /// For `f64` (chosen at compile time by type) the same pivot and the same roundings (for a
    /// rotation, bit for bit), with |4p·q| by a plain square root (for a rotation |4p·q|² = 4p² ≥ 1: the four
    /// pivots 4η², 4εᵢ² sum to 4) and the canonical sign folded into the scale factor; inlined
    /// always, so that it sits in the caller's loop.
    ///
    /// Book: §2.15 (2.15.8–10), largest pivot among {tr 𝓡, 𝓡₁₁, 𝓡₂₂, 𝓡₃₃}.
    #[inline(always)]
    pub fn from_rotation_matrix_unchecked(r: &Matrix3<T>) -> Self {
        // The type test is resolved at compile time (every `Scalar` is `'static`).
        if let Some(m) = (r as &dyn Any).downcast_ref::<Matrix3<f64>>() {
            let q = shepperd_f64(m);
            return Self::new(T::lit(q.a), T::lit(q.b), T::lit(q.c), T::lit(q.d));
        }
        let q = Self::shepperd_unnormalized(r);
        (q * (T::one() / q.norm())).canonical()
    }

    /// The angle vector (log map) of a rotation matrix 𝓡. The angle θ from sin θ = ½|vee(𝓡 − 𝓡ᵀ)|
    /// or cos θ = ½(tr 𝓡 − 1), whichever is well conditioned (asin of the sine below 45.6° and
    /// above 134.4°, of the cosine between); the axis for tr 𝓡 > −0.9 (θ < 162°) from
    /// vee(𝓡 − 𝓡ᵀ) itself, nearer the half turn from the largest pivot of the unnormalised
    /// Shepperd quaternion (whose vector part keeps its digits there). Unchecked (the matrix
    /// must be a rotation).
    ///
    /// For `f64` (chosen at compile time by type) the same choices, switching at 45° and 135°,
    /// are made without a `libm` call: with φ/sin φ = G(cos φ), a polynomial in 1 − cos φ on
    /// cos φ ≥ 1/√2 (every coefficient positive, within 0.2 ε), θ/(2 sin θ) is ½G(cos θ) below
    /// 45°, π/|v| − ½G(−cos θ) above 135°, and (π/2 − cos θ·G(sin θ))/|v| between (asin of the
    /// cosine), v = vee(𝓡 − 𝓡ᵀ): no square root below 45° (exact at θ = 0 and for tiny angles,
    /// whose |v|² underflows), one square root and one division otherwise. The polynomial uses
    /// fused multiply–add where the CPU has it (detected when the program runs), so the last bit
    /// may differ between machines.
    ///
    /// Book: §2.14 (log map), §2.15; notes ch2b §3.5.
    #[doc(alias = "as_rotvec")]
    #[inline(always)]
    pub fn angle_vector_of_rotation_matrix(r: &Matrix3<T>) -> Vector3<T> {
        // The type test is resolved at compile time (every `Scalar` is `'static`); inlined
        // always, so that the `f64` kernel sits in the caller's loop.
        if let Some(m) = (r as &dyn Any).downcast_ref::<Matrix3<f64>>() {
            let w = matrix_log_f64(m);
            return Vector3::new(T::lit(w.x), T::lit(w.y), T::lit(w.z));
        }
        Self::angle_vector_of_rotation_matrix_generic(r)
    }

    /// [`Self::angle_vector_of_rotation_matrix`] for every other scalar (dual numbers, `f32`):
    /// asin of the better conditioned of sin θ and cos θ (`angle_0_pi`), the axis from
    /// vee(𝓡 − 𝓡ᵀ) below 162° and from the largest Shepperd pivot beyond.
    ///
    /// Book: §2.14 (log map), §2.15; notes ch2b §3.5.
    #[inline]
    fn angle_vector_of_rotation_matrix_generic(r: &Matrix3<T>) -> Vector3<T> {
        // From Rodrigues (2.11.1): vee(𝓡 − 𝓡ᵀ) = 2 sin θ n̂ and tr 𝓡 − 1 = 2 cos θ, so θ follows
        // from sin θ or cos θ, whichever is well conditioned (`angle_0_pi`).
        let tr = r[(0, 0)] + r[(1, 1)] + r[(2, 2)];
        let v = Vector3::new(r[(2, 1)] - r[(1, 2)], r[(0, 2)] - r[(2, 0)], r[(1, 0)] - r[(0, 1)]);
        let s = norm3(&v);
        let c = (tr - T::one()) * T::lit(0.5);
        let theta = angle_0_pi(s * T::lit(0.5), c);
        if tr.re() > -0.9 {
            // cos θ > −0.95 (θ < 162°), away from the half turn: |v| = 2 sin θ > 0.62 keeps the
            // axis to a few ulps, and Θ = (θ / 2 sin θ) v.
            // θ / (2 sin θ) = ½(1 + θ²/6 + 7θ⁴/360 + …); the θ⁴ term is below ε for θ < 1e-4.
            let k = if theta.re() < 1e-4 {
                T::lit(0.5) * (T::one() + theta * theta / T::lit(6.0))
            } else {
                theta / s
            };
            return v * k;
        }
        // Near the half turn the antisymmetric part vanishes: the axis from the largest Shepperd
        // pivot, 4p·q (p the pivot component), whose ε is ∥ n̂ with the sign of η·p; θ (from
        // sin θ = |v|/2 above, π − asin) is exact to an ulp there, as 2 atan2(|ε|, η) would be.
        let q = Self::shepperd_unnormalized(r);
        let e = q.epsilon();
        let n = norm3(&e);
        let axis = if q.a > T::zero() {
            e / n
        } else if q.a < T::zero() {
            -e / n
        } else {
            // θ = π exactly: ±n̂ describe the same half-turn; the canonical sign (DESIGN §4)
            canonical_sign(e / n)
        };
        axis * theta
    }

    /// 4·(pivot component)·q for the largest pivot (Markley's columns).
    #[inline]
    fn shepperd_unnormalized(r: &Matrix3<T>) -> Self {
        let (r11, r22, r33) = (r[(0, 0)], r[(1, 1)], r[(2, 2)]);
        let tr = r11 + r22 + r33;
        let one = T::one();
        // Each candidate is 4·(pivot component)·q; the largest pivot has no cancellation.
        if tr >= r11 && tr >= r22 && tr >= r33 {
            // (2.15.8–10): 4η·[η; ε], η = ½√(1 + tr 𝓡)
            Self::new(one + tr, r[(2, 1)] - r[(1, 2)], r[(0, 2)] - r[(2, 0)], r[(1, 0)] - r[(0, 1)])
        } else if r11 >= r22 && r11 >= r33 {
            Self::new(
                r[(2, 1)] - r[(1, 2)],
                one + r11 - r22 - r33,
                r[(0, 1)] + r[(1, 0)],
                r[(0, 2)] + r[(2, 0)],
            )
        } else if r22 >= r33 {
            Self::new(
                r[(0, 2)] - r[(2, 0)],
                r[(0, 1)] + r[(1, 0)],
                one + r22 - r11 - r33,
                r[(1, 2)] + r[(2, 1)],
            )
        } else {
            Self::new(
                r[(1, 0)] - r[(0, 1)],
                r[(0, 2)] + r[(2, 0)],
                r[(1, 2)] + r[(2, 1)],
                one + r33 - r11 - r22,
            )
        }
    }

    /// The canonical sign: η ≥ 0, and at η = 0 (θ = π) the first nonzero component of ε
    /// positive (DESIGN §4).
    ///
    /// Book: (2.15.20), η = cos(θ/2) ≥ 0 since θ ∈ [0, π]; Fact 2.11.5 (the ± at π).
    #[inline]
    pub fn canonical(&self) -> Self {
        if self.a > T::zero() {
            *self
        } else if self.a < T::zero() {
            -*self
        } else {
            // θ = π: ±ε describe the same half-turn; pick the canonical one.
            Self::from_parts(self.a, canonical_sign(self.epsilon()))
        }
    }

    /// `Ok` when every component is finite and |‖𝐪‖ − 1| ≤ `tol`: the check of every checked
    /// constructor that takes Euler parameters.
    ///
    /// Book: (2.15.20) (‖q‖ = 1).
    pub(crate) fn check_unit(&self, tol: f64) -> Result<(), RotationError> {
        if !crate::series::all_finite([self.a, self.b, self.c, self.d]) {
            return Err(RotationError::NonFinite { what: "quaternion" });
        }
        let defect = (self.norm().re() - 1.0).abs();
        if defect > tol {
            return Err(RotationError::NotUnit { defect, tol });
        }
        Ok(())
    }

    /// `true` when |‖𝐪‖ − 1| ≤ `tol`.
    #[inline]
    pub fn is_unit(&self, tol: f64) -> bool {
        (self.norm().re() - 1.0).abs() <= tol
    }

    /// 𝓡(q) (2.15.14), the active rotation matrix 𝓡_{B/A} of q_{B/A}; assumes |q| = 1.
    ///
    /// Book: Fact 2.15.3, (2.15.14); (2.15.13) prints the (1,1) entry as 2d² + 2b² − 1, an
    /// erratum for 2a² + 2b² − 1.
    #[inline]
    #[doc(alias = "to_rotation_matrix")]
    pub fn rotation_matrix(&self) -> Matrix3<T> {
        let (a, b, c, d) = (self.a, self.b, self.c, self.d);
        // The products with 2b, 2c, 2d: doubling is exact, so 2(bc − ad) = (2b)c − a(2d) to the
        // bit (barring underflow), and the 9 doublings of the entries become 3 (24 flops, not 30).
        let (b2, c2, d2) = (b + b, c + c, d + d);
        let (bb, cc, dd) = (b * b2, c * c2, d * d2);
        let (ab, ac, ad) = (a * b2, a * c2, a * d2);
        let (bc, bd, cd) = (b * c2, b * d2, c * d2);
        let one = T::one();
        Matrix3::new(
            one - (cc + dd),
            bc - ad,
            ac + bd,
            ad + bc,
            one - (bb + dd),
            cd - ab,
            bd - ac,
            ab + cd,
            one - (bb + cc),
        )
    }

    /// 𝓞(q) = 𝓡(q)ᵀ = 𝓡(q̄) (Fact 2.15.6), the passive orientation matrix 𝓞_{B/A}.
    ///
    /// Book: (2.15.31).
    #[inline]
    #[doc(alias = "dcm")]
    pub fn orientation_matrix(&self) -> Matrix3<T> {
        self.conjugate().rotation_matrix()
    }

    /// 𝓡(q)x = 𝐪𝐱𝐪̄ (Prob 2.26.23), evaluated as x + 2η(ε×x) + 2ε×(ε×x).
    #[inline]
    pub fn rotate(&self, x: &Vector3<T>) -> Vector3<T> {
        let e = self.epsilon();
        let t = e.cross(x) * T::lit(2.0);
        x + t * self.a + e.cross(&t)
    }

    /// q = (cos θ/2, sin θ/2 n̂) (2.15.20) for any θ and nonzero axis (normalised here),
    /// returned canonical (η ≥ 0).
    ///
    /// For `f64` (chosen at compile time by type) with a unit axis (|n̂|² within 4ε of 1) and
    /// |θ/2| ≤ 2·10⁵, inlined always into the caller: vmath's branch-free fdlibm sine and cosine
    /// of θ/2 (each within 1 ulp), with fused multiply–add where the CPU has it (detected when
    /// the program runs), so the last bit may differ between machines.
    ///
    /// # Errors
    /// [`RotationError::Zero`] for a zero axis, [`RotationError::NonFinite`].
    #[inline(always)]
    pub fn from_axis_angle(axis: &Vector3<T>, theta: T) -> Result<Self, RotationError> {
        // The type tests are resolved at compile time (every `Scalar` is `'static`).
        if let (Some(n), Some(&t)) =
            ((axis as &dyn Any).downcast_ref::<Vector3<f64>>(), (&theta as &dyn Any).downcast_ref::<f64>())
        {
            // A unit axis, as below; the comparisons are false for NaN (the checks below).
            let h = t * 0.5;
            if (n.norm_squared() - 1.0).abs() <= 4.0 * f64::EPSILON && h.abs() <= SIN_COS_MAX {
                let q = axis_angle_f64(n, h);
                return Ok(Self::new(T::lit(q.a), T::lit(q.b), T::lit(q.c), T::lit(q.d)));
            }
        }
        Self::from_axis_angle_general(axis, theta)
    }

    /// [`Self::from_axis_angle`] for every other scalar, and for `f64` with an axis that is not
    /// unit or a huge or non-finite angle: out of line, so that the `f64` fast path stays small.
    ///
    /// Book: (2.15.20).
    #[inline(never)]
    fn from_axis_angle_general(axis: &Vector3<T>, theta: T) -> Result<Self, RotationError> {
        // A unit axis (|n̂|² within 4ε of 1, so |n̂| within 2ε) needs no normalisation: the
        // quaternion's norm is then 1 to rounding either way.
        let n2 = axis.norm_squared();
        if (n2.re() - 1.0).abs() <= 4.0 * f64::EPSILON && theta.re().is_finite() {
            let (s, c) = sin_cos(theta * T::lit(0.5));
            let q = Self::from_parts(c, axis * s);
            return Ok(if c <= T::zero() { q.canonical() } else { q });
        }
        if !(axis.iter().all(|x| x.re().is_finite()) && theta.re().is_finite()) {
            return Err(RotationError::NonFinite { what: "axis or angle" });
        }
        let m = axis.x.abs().max(axis.y.abs()).max(axis.z.abs());
        if m == T::zero() {
            return Err(RotationError::Zero { what: "rotation axis" });
        }
        let (s, c) = sin_cos(theta * T::lit(0.5));
        // n̂ sin(θ/2) with n̂ = u/|u|, u = axis/max|axisᵢ|: exact for subnormal or huge axes
        // (|n| of a subnormal axis carries too few bits to divide by, |n| of 1e308 overflows)
        let u = axis / m;
        let q = Self::from_parts(c, (u / u.norm()) * s);
        // η = cos(θ/2) < 0 only for |θ| > π.
        Ok(if c <= T::zero() { q.canonical() } else { q })
    }

    /// Eigenaxis and eigenangle θ = 2 atan2(|ε|, η) ∈ [0, π] (never acos), resolved in the
    /// quaternion's frame. Exact comparisons decide the variant: `Identity` only for ε = 0,
    /// `HalfTurn` only for η = 0 (canonical axis sign there).
    ///
    /// Book: §2.11, Facts 2.11.4–5, (2.11.49); notes ch2b §3.1.
    #[inline]
    pub fn axis_angle(&self) -> AxisAngle<T, Vector3<T>> {
        let q = self.canonical();
        let e = q.epsilon();
        let s = norm3(&e);
        if s == T::zero() {
            // Fact 2.11.4: θ = 0, any axis.
            return AxisAngle::Identity;
        }
        let n = e / s;
        if q.a == T::zero() {
            // Fact 2.11.5: θ = π, axis ±n̂, canonical sign already chosen by `canonical`.
            return AxisAngle::HalfTurn(n);
        }
        AxisAngle::General { axis: n, angle: T::lit(2.0) * atan2(s, q.a) }
    }

    /// exp: the Euler parameters of the angle vector Θ = θn̂ (2.14.5), q = (cos θ/2,
    /// ½ sinc(θ/2) Θ), i.e. 𝐪 = e^{Θ/2} (Prob 2.26.22), series near θ = 0, canonical η ≥ 0.
    ///
    /// Book: §2.14, Prob 2.26.22.
    #[doc(alias = "from_rotvec")]
    #[doc(alias = "from_scaled_axis")]
    #[inline]
    pub fn from_angle_vector(theta: &Vector3<T>) -> Self {
        // |Θ| = √(Θ·Θ) unless that overflows; an underflow (|Θ| < 1e-154) leaves h = 0 and
        // the series below gives the exact limit q = (1, Θ/2) anyway. Beyond 1e145 the scaled
        // norm of Θ/2 (components near f64::MAX: |Θ| overflows, |Θ/2| need not).
        let n2 = theta.norm_squared();
        // |Θ| ≤ π in f64 (the usual case): the series of cos h and sin h / h in h² = |Θ|²/4,
        // with no square root and no division; η = cos h ≥ 0 is canonical.
        if let Some((c, sinc_h)) = cos_sinc_of_square(n2 * T::lit(0.25)) {
            return Self::from_parts(c, theta * (T::lit(0.5) * sinc_h));
        }
        let h = if n2.re() < 1e290 { n2.sqrt() * T::lit(0.5) } else { norm3(&(theta * T::lit(0.5))) };
        let (s, c) = sin_cos(h);
        // ½ sin(h)/h, by series near h = 0 (sinc). The `0·s` keeps sin(h) on both paths: LLVM
        // otherwise sinks the sine into the branch that uses it, and sin and cos stay two libm
        // calls instead of one sincos (a quarter of the cost of the whole conversion).
        let k = if h.re() < 1e-3 { T::lit(0.5) * sinc(h) + T::zero() * s } else { T::lit(0.5) * s / h };
        let q = Self::from_parts(c, theta * k);
        // |Θ| ≤ π (the usual case) gives η = cos(h) > 0: already canonical
        if c > T::zero() { q } else { q.canonical() }
    }

    /// log: the angle vector Θ = θn̂ with θ ∈ [0, π], from θ = 2 atan2(|ε|, η); the series
    /// 2/η·(1 − |ε|²/(3η²)) near θ = 0; at θ = π the canonical sign (first nonzero component
    /// positive).
    ///
    /// Book: §2.14 (log map, L2477), (2.14.17) replaced by the quaternion route (notes ch2b
    /// §3.5: θ/(2 sin θ) is singular at both ends).
    #[doc(alias = "as_rotvec")]
    #[doc(alias = "scaled_axis")]
    #[inline]
    pub fn angle_vector(&self) -> Vector3<T> {
        let q = self.canonical();
        let (eta, e) = (q.a, q.epsilon());
        let s2 = e.norm_squared();
        // 2 atan(t)/s = (2/η)(1 − t²/3 + t⁴/5 − …), t = |ε|/η; t⁴/5 < 2·10⁻²¹ below t² = 1e-10.
        let ratio = if s2.re() < 1e-10 * (eta * eta).re() {
            T::lit(2.0) / eta * (T::one() - s2 / (T::lit(3.0) * eta * eta))
        } else {
            let s = norm3(&e);
            T::lit(2.0) * atan2(s, eta) / s
        };
        e * ratio
    }

    /// Gibbs vector g = ε/η = tan(θ/2) n̂ (2.17.1, F2.17.2); `None` at θ = π (η = 0), where the
    /// book leaves it undefined (§2.18). Near π it is finite but huge.
    ///
    /// Book: §2.17, (2.17.1), (2.17.10).
    #[doc(alias = "classical_rodrigues_parameters")]
    #[inline]
    pub fn gibbs(&self) -> Option<Vector3<T>> {
        let q = self.canonical();
        (q.a != T::zero()).then(|| q.epsilon() / q.a)
    }

    /// The Gibbs vector, with [`RotationError::GibbsAtHalfTurn`] at θ = π.
    ///
    /// Book: §2.17–2.18.
    ///
    /// # Errors
    /// [`RotationError::GibbsAtHalfTurn`] when η = 0.
    pub fn try_gibbs(&self) -> Result<Vector3<T>, RotationError> {
        self.gibbs().ok_or(RotationError::GibbsAtHalfTurn { eta: self.a.re() })
    }

    /// Euler parameters of the Gibbs vector: q = (1, g)/√(1 + g·g), scaled for huge |g|.
    ///
    /// Book: (2.17.1), inverse of F2.17.2.
    #[inline]
    pub fn from_gibbs(g: &Vector3<T>) -> Self {
        let n = norm3(g);
        let one = T::one();
        if g.iter().any(|x| x.re().is_infinite()) {
            // θ = π, the limit |g| → ∞: the axis is the direction of the infinite components
            // ((∞, 1, 0) is the half turn about î). NaN input stays NaN.
            let d = g.map(|x| if x.re().is_infinite() { x.signum() } else { x * T::zero() });
            return Self::from_parts(T::zero(), d / norm3(&d)).canonical();
        }
        if n > one {
            // (1/n, ĝ)/√(1 + 1/n²): no overflow of g·g near θ = π; ĝ from g/max|gᵢ|, so that
            // |g| beyond f64::MAX (n = ∞, r = 0) still gives the half turn about ĝ.
            let r = one / n;
            let u = g / g.x.abs().max(g.y.abs()).max(g.z.abs());
            Self::from_parts(r, u / u.norm()) * (one / (one + r * r).sqrt())
        } else {
            Self::from_parts(one, *g) * (one / (one + n * n).sqrt())
        }
    }

    /// Modified Rodrigues parameters p = ε/(1 + η) = tan(θ/4) n̂, |p| ≤ 1 (η ≥ 0). Not in the
    /// book; users of spacecraft attitude expect them.
    ///
    /// Book: extends §2.17 (Gibbs, tan(θ/2)) to tan(θ/4).
    #[doc(alias = "modified_rodrigues_parameters")]
    #[inline]
    pub fn mrp(&self) -> Vector3<T> {
        let q = self.canonical();
        q.epsilon() / (T::one() + q.a)
    }

    /// Euler parameters of MRPs p (or their shadow): q = (1 − p·p, 2p)/(1 + p·p), canonical.
    ///
    /// Book: extends §2.17.
    #[inline]
    pub fn from_mrp(p: &Vector3<T>) -> Self {
        let one = T::one();
        let n = norm3(p);
        if n.re() > 1.0 && n.re().is_finite() {
            // |p| > 1, in terms of r = 1/|p| and p̂ so that |p|² never overflows:
            // q₀ = (1 − |p|²)/(1 + |p|²) = (r² − 1)/(r² + 1), q⃗ = 2p/(1 + |p|²) = 2r p̂/(r² + 1)
            let r = one / n;
            let k = one / (r * r + one);
            return Self::from_parts((r * r - one) * k, (p / n) * (T::lit(2.0) * r * k)).canonical();
        }
        if n.re().is_infinite() {
            // |p| → ∞: the shadow −p/|p|² → 0, the identity.
            return Self::identity();
        }
        // (2.17.x, MRP): q = ((1 − |p|²), 2p)/(1 + |p|²); |p|² ≤ 1 cannot overflow, and its
        // underflow for tiny p is harmless (q₀ = 1, q⃗ = 2p).
        let p2 = p.norm_squared();
        let k = one / (one + p2);
        Self::from_parts((one - p2) * k, p * (T::lit(2.0) * k)).canonical()
    }

    /// Spherical linear interpolation from `self` (t = 0) to `q` (t = 1) along the shorter arc,
    /// with the angle by atan2 and sinc series (no division by sin Ω near Ω = 0).
    ///
    /// Book: §2.14 (geodesic exp(tΘ)); not printed in the book.
    pub fn slerp(&self, q: &Quaternion<T>, t: T) -> Self {
        let mut q1 = *q;
        if self.dot(&q1) < T::zero() {
            q1 = -q1;
        }
        // self ⊗ exp(t log(self⁻¹ ⊗ q))
        let d = self.conjugate() * q1;
        let theta = Self::angle_vector(&d) * t;
        (*self * Self::from_angle_vector(&theta)).canonical()
    }
}

/// The canonical axis of a half-turn in one frame: first nonzero component positive.
///
/// Book: Fact 2.11.5; DESIGN §4.
#[inline]
pub fn canonical_half_turn_axis<T: Scalar>(n: &Vector3<T>) -> Vector3<T> {
    canonical_sign(*n)
}

/// (G(1 − t) − 1)/t for t = 1 − cos φ ∈ [0, 0.3], where G(cos φ) = φ / sin φ = acos(x)/√(1 − x²):
/// degree 10, ascending, the Chebyshev interpolant of mpmath at 50 digits
/// (`mp.chebyfit(H, [0, 0.3], 11)`), G within 0.2 ε with these rounded coefficients. G is
/// analytic but for x ≤ −1, so the series in 1 − x converges fast on x ≥ 1/√2, and every
/// coefficient is positive (no cancellation).
const PHI_OVER_SIN: [f64; 11] = [
    0.3333333333333334,
    0.13333333333323752,
    0.05714285715559279,
    0.025396824738313475,
    0.011544028950451169,
    0.005327738017410276,
    0.002488947053473886,
    0.0011546510294283179,
    0.0006133984328641961,
    0.00012706634161320588,
    0.0002923482308981945,
];

/// φ / sin φ from t = 1 − cos φ, for cos φ ≥ 1/√2 (0 ≤ φ ≤ 45°), by Estrin's scheme (the
/// powers and the pairs independent, a short chain); 1 at t = 0 exactly. `F`: fused
/// multiply–add ([`madd`]).
///
/// Book: (2.14.12–15) (the removable singularity of θ / sin θ at 0).
#[inline(always)]
fn phi_over_sin<const F: bool>(t: f64) -> f64 {
    let h = &PHI_OVER_SIN;
    let t2 = t * t;
    let t4 = t2 * t2;
    let t8 = t4 * t4;
    let p = |i: usize| madd::<F>(h[i + 1], t, h[i]);
    let q0 = madd::<F>(p(2), t2, p(0));
    let q1 = madd::<F>(p(6), t2, p(4));
    let q2 = madd::<F>(h[10], t2, p(8));
    let g = madd::<F>(q2, t8, madd::<F>(q1, t4, q0));
    madd::<F>(t, g, 1.0)
}

/// [`matrix_log_kernel`] with fused multiply–add where the CPU has it (detected when the program
/// runs, as the batched conversions do): the polynomial's chain is half as long. The two builds
/// may differ in the last bit; both are within the same bounds.
///
/// Book: §2.14 (log map).
#[inline(always)]
fn matrix_log_f64(r: &Matrix3<f64>) -> Vector3<f64> {
    #[cfg(target_arch = "x86_64")]
    {
        #[target_feature(enable = "fma")]
        fn with_fma(r: &Matrix3<f64>) -> Vector3<f64> {
            matrix_log_kernel::<true>(r)
        }
        if !FMA_BUILTIN && std::is_x86_feature_detected!("fma") {
            // SAFETY: FMA was detected on this CPU just above.
            return unsafe { with_fma(r) };
        }
    }
    matrix_log_kernel::<FMA_BUILTIN>(r)
}

/// The log map of an `f64` rotation matrix ([`Quaternion::angle_vector_of_rotation_matrix`]):
/// Θ = (θ / 2 sin θ) v, v = vee(𝓡 − 𝓡ᵀ) = 2 sin θ n̂, with θ / sin θ from [`phi_over_sin`] of
/// whichever of cos θ, sin θ is well conditioned; nearer the half turn than tr 𝓡 = −0.9 the
/// axis from the largest Shepperd pivot, as in the generic code.
///
/// Book: §2.14 (log map), (2.11.1) (vee(𝓡 − 𝓡ᵀ) = 2 sin θ n̂, tr 𝓡 = 1 + 2 cos θ); notes ch2b
/// §3.5.
#[inline(always)]
fn matrix_log_kernel<const F: bool>(r: &Matrix3<f64>) -> Vector3<f64> {
    use core::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, PI};
    let tr = r[(0, 0)] + r[(1, 1)] + r[(2, 2)];
    let v = Vector3::new(r[(2, 1)] - r[(1, 2)], r[(0, 2)] - r[(2, 0)], r[(1, 0)] - r[(0, 1)]);
    let c = (tr - 1.0) * 0.5;
    if c > FRAC_1_SQRT_2 {
        // θ < 45°: θ / (2 sin θ) = ½G(cos θ). 1 − c is exact (Sterbenz) and G is flat at 1
        // (G' = 1/3), so the rounding of c barely moves k; no |v|, so nothing underflows.
        return v * (0.5 * phi_over_sin::<F>(1.0 - c));
    }
    let n2 = v.x * v.x + v.y * v.y + v.z * v.z;
    // |v| = 2 sin θ ≥ 0.62 up to 162° (|v|² neither underflows nor overflows); beyond, |v| only
    // scales the correction π − θ, and an underflow there is far below an ulp of π.
    let rv = n2.sqrt();
    if c >= -FRAC_1_SQRT_2 {
        // 45° ≤ θ ≤ 135°: θ = π/2 − asin(cos θ), asin(cos θ) = cos θ·G(sin θ) (φ = π/2 − θ).
        let k = madd::<F>(-c, phi_over_sin::<F>(madd::<F>(-0.5, rv, 1.0)), FRAC_PI_2) / rv;
        return v * k;
    }
    // θ > 135°: θ = π − φ with sin φ = |v|/2, cos φ = −c, so θ / (2 sin θ) = π/|v| − ½G(−c).
    let g = phi_over_sin::<F>(1.0 + c);
    if tr > -0.9 {
        return v * madd::<F>(-0.5, g, PI / rv);
    }
    near_half_turn_f64(r, PI - 0.5 * rv * g)
}

/// The end of [`matrix_log_kernel`] beyond 162° (tr 𝓡 ≤ −0.9), kept out of line: θ (from
/// θ = π − ½|v|·G(−cos θ), π exactly at θ = π) times the axis from the largest diagonal pivot
/// (the trace is never the largest there), 4p·q with p the pivot component, whose ε is ∥ n̂
/// with the sign of η·p, the same as [`Quaternion::shepperd_unnormalized`] and the generic code.
/// |4p·ε| ≥ 2.2 for a rotation, so |ε|² neither underflows nor overflows.
///
/// Book: §2.15 (2.15.8–10) (the largest pivot); Fact 2.11.5 (the ± at π).
#[cold]
#[inline(never)]
fn near_half_turn_f64(r: &Matrix3<f64>, theta: f64) -> Vector3<f64> {
    let (r11, r22, r33) = (r[(0, 0)], r[(1, 1)], r[(2, 2)]);
    // (4p·η, 4p·ε) for the pivot p = ε₁, ε₂ or ε₃
    let (eta, e) = if r11 >= r22 && r11 >= r33 {
        (
            r[(2, 1)] - r[(1, 2)],
            Vector3::new(1.0 + r11 - r22 - r33, r[(0, 1)] + r[(1, 0)], r[(0, 2)] + r[(2, 0)]),
        )
    } else if r22 >= r33 {
        (
            r[(0, 2)] - r[(2, 0)],
            Vector3::new(r[(0, 1)] + r[(1, 0)], 1.0 + r22 - r11 - r33, r[(1, 2)] + r[(2, 1)]),
        )
    } else {
        (
            r[(1, 0)] - r[(0, 1)],
            Vector3::new(r[(0, 2)] + r[(2, 0)], r[(1, 2)] + r[(2, 1)], 1.0 + r33 - r11 - r22),
        )
    };
    let k = theta / (e.x * e.x + e.y * e.y + e.z * e.z).sqrt();
    if eta > 0.0 {
        e * k
    } else if eta < 0.0 {
        e * -k
    } else {
        // θ = π exactly: ±n̂ describe the same half-turn; the canonical sign (DESIGN §4)
        canonical_sign(e) * k
    }
}

/// [`Quaternion::from_rotation_matrix_unchecked`] for `f64`: the largest pivot's 4p·q
/// ([`Quaternion::shepperd_unnormalized`]), divided by its norm √(4p·q · 4p·q) with the sign of
/// its η, the same roundings as the generic code. The trace pivot's η = 1 + tr 𝓡 ≥ 1 > 0
/// (tr 𝓡 ≥ 𝓡ᵢᵢ for every i gives tr 𝓡 ≥ 0); the others' η = 4εᵢη may have either sign.
///
/// Book: §2.15 (2.15.8–10); (2.15.20) (η ≥ 0).
#[inline(always)]
fn shepperd_f64(r: &Matrix3<f64>) -> Quaternion<f64> {
    let q = Quaternion::shepperd_unnormalized(r);
    // |4p·q|² = 4p² ∈ [1, 16] for a rotation: no overflow, no underflow (`Quaternion::norm`'s
    // scaled branch never runs there).
    let k = 1.0 / q.norm_squared().sqrt();
    if q.a > 0.0 {
        q * k
    } else if q.a < 0.0 {
        q * -k
    } else {
        // η = 0 (θ = π), or NaN input
        half_turn_f64(q, k)
    }
}

/// The end of [`shepperd_f64`] at η = 0 (a half-turn, or a NaN matrix), out of line: the
/// canonical sign of ε (DESIGN §4), as [`Quaternion::canonical`].
///
/// Book: Fact 2.11.5 (the ± at π).
#[cold]
#[inline(never)]
fn half_turn_f64(q: Quaternion<f64>, k: f64) -> Quaternion<f64> {
    (q * k).canonical()
}

/// q = (cos h, sin h n̂) for a unit `f64` axis n̂ and h = θ/2 with |h| ≤ [`SIN_COS_MAX`]
/// ([`Quaternion::from_axis_angle`]), the sine and cosine with fused multiply–add where the CPU
/// has it (detected when the program runs, as [`matrix_log_f64`]; the fused build is called,
/// and returns the pair in registers). The two builds may differ in the last bit; both are
/// within 1 ulp of sin h and cos h.
///
/// Book: (2.15.20).
#[inline(always)]
fn axis_angle_f64(n: &Vector3<f64>, h: f64) -> Quaternion<f64> {
    #[cfg(target_arch = "x86_64")]
    {
        #[target_feature(enable = "fma")]
        fn with_fma(h: f64) -> (f64, f64) {
            crate::vmath::sin_cos::<true>(h)
        }
        if !FMA_BUILTIN && std::is_x86_feature_detected!("fma") {
            // SAFETY: FMA was detected on this CPU just above.
            return axis_angle_of(n, unsafe { with_fma(h) });
        }
    }
    axis_angle_of(n, crate::vmath::sin_cos::<FMA_BUILTIN>(h))
}

/// (cos h, sin h n̂) from (sin h, cos h), made canonical when cos h ≤ 0 (|θ| ≥ π).
///
/// Book: (2.15.20) (η = cos(θ/2) ≥ 0 for θ ∈ [0, π]).
#[inline(always)]
fn axis_angle_of(n: &Vector3<f64>, (s, c): (f64, f64)) -> Quaternion<f64> {
    let q = Quaternion::from_parts(c, n * s);
    // η = cos(θ/2) < 0 only for |θ| > π.
    if c <= 0.0 { q.canonical() } else { q }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Both builds of the `f64` matrix log (with and without fused multiply–add; this CPU runs
    /// only one of them through the public function) agree with the generic asin code to a few
    /// ulps of max(θ, 1), relatively at tiny angles, on every side of the switches at 45°,
    /// 135° and 162° and at the hard angles.
    #[test]
    fn f64_matrix_log_kernels_match_the_generic_code() {
        let pi = core::f64::consts::PI;
        let axes = [
            Vector3::new(1.0, 0.0, 0.0),
            Vector3::new(1.0, 2.0, 2.0) / 3.0,
            Vector3::new(-0.3, 0.1, 0.95).normalize(),
            Vector3::new(0.0, -1.0, 1e-9).normalize(),
        ];
        let mut angles = vec![0.0, 1e-300, 1e-16, 1e-8, 1e-4, 0.5, 1.5, 2.0, 2.5, 3.0, 3.1];
        for edge in [pi / 4.0, 3.0 * pi / 4.0, 2.8274, pi] {
            angles.extend([edge - 1e-9, edge, edge + 1e-9].into_iter().filter(|t| *t <= pi));
        }
        angles.extend([pi - 1e-4, pi - 1e-8, pi - 1e-12]);
        for n in axes {
            for &th in &angles {
                let r = Quaternion::from_axis_angle(&n, th).unwrap().rotation_matrix();
                let want = Quaternion::angle_vector_of_rotation_matrix_generic(&r);
                for got in [matrix_log_kernel::<false>(&r), matrix_log_kernel::<true>(&r)] {
                    // at θ = π both ±πn̂ are right
                    let (d, e) = ((got - want).amax(), (got + want).amax());
                    let err = if th == pi { d.min(e) } else { d };
                    let scale = if th < 1e-3 { th } else { th.max(1.0) };
                    assert!(err <= 4.0 * f64::EPSILON * scale, "θ = {th:e}, n = {n:?}: {got:?} vs {want:?}");
                }
            }
        }
    }

    /// Hard rotations for the `f64` paths below: tiny and half-turn angles about the hard
    /// axes, and random unit quaternions with every component the largest.
    fn hard_quaternions() -> Vec<Quaternion<f64>> {
        let pi = core::f64::consts::PI;
        let mut qs = Vec::new();
        for n in [
            Vector3::new(1.0, 0.0, 0.0),
            Vector3::new(0.0, -1.0, 0.0),
            Vector3::new(0.0, 0.0, 1.0),
            Vector3::new(1.0, 2.0, 2.0) / 3.0,
            Vector3::new(-0.3, 0.1, 0.95).normalize(),
            Vector3::new(0.0, -1.0, 1e-9).normalize(),
        ] {
            for th in [0.0, 1e-300, 1e-16, 1e-8, 1e-4, 0.5, 1.5, 2.0, 3.0, pi - 1e-8, pi] {
                qs.push(Quaternion::from_axis_angle_general(&n, th).unwrap());
            }
        }
        let mut s = 0x9E37_79B9_7F4A_7C15u64;
        let mut rng = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for _ in 0..2000 {
            let q = Quaternion::new(rng(), rng(), rng(), rng());
            qs.push(q * (1.0 / q.norm()));
        }
        qs
    }

    /// The `f64` Shepperd path returns the generic code's bits: the same pivot, the same norm
    /// (no scaling is needed for a rotation), the same canonical sign, also at η = 0.
    #[test]
    fn f64_shepperd_matches_the_generic_code_bitwise() {
        let mut mats: Vec<Matrix3<f64>> = hard_quaternions().iter().map(|q| q.rotation_matrix()).collect();
        // exact half-turns: η = 0 in every pivot, the canonical sign decides
        mats.extend([
            Matrix3::new(1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, -1.0),
            Matrix3::new(-1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, -1.0),
            Matrix3::new(-1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0),
            Matrix3::new(
                -1.0 / 9.0,
                4.0 / 9.0,
                -8.0 / 9.0,
                4.0 / 9.0,
                -7.0 / 9.0,
                -4.0 / 9.0,
                -8.0 / 9.0,
                -4.0 / 9.0,
                -1.0 / 9.0,
            ),
        ]);
        for r in &mats {
            let q = Quaternion::shepperd_unnormalized(r);
            let want = (q * (1.0 / q.norm())).canonical();
            let got = shepperd_f64(r);
            let bits = |q: Quaternion<f64>| [q.a, q.b, q.c, q.d].map(f64::to_bits);
            assert_eq!(bits(got), bits(want), "{r:?}");
            assert!(got.a >= 0.0);
        }
        let nan = shepperd_f64(&Matrix3::from_element(f64::NAN));
        assert!(nan.a.is_nan());
    }

    /// 𝓡(q) with the doubled factors returns the bits of the textbook 1 − 2(c² + d²), 2(bc − ad), …
    #[test]
    fn rotation_matrix_matches_the_doubled_entries_bitwise() {
        for q in hard_quaternions() {
            let (a, b, c, d) = (q.a, q.b, q.c, q.d);
            let want = Matrix3::new(
                1.0 - 2.0 * (c * c + d * d),
                2.0 * (b * c - a * d),
                2.0 * (a * c + b * d),
                2.0 * (a * d + b * c),
                1.0 - 2.0 * (b * b + d * d),
                2.0 * (c * d - a * b),
                2.0 * (b * d - a * c),
                2.0 * (a * b + c * d),
                1.0 - 2.0 * (b * b + c * c),
            );
            let got = q.rotation_matrix();
            for (g, w) in got.iter().zip(want.iter()) {
                assert_eq!(g.to_bits(), w.to_bits(), "{q:?}");
            }
        }
    }

    /// Both builds of the `f64` axis-angle kernel: without fused multiply–add the generic code's
    /// bits; with it within 1 ulp of sin h, cos h (libm) per component, every θ in [−4π, 4π]
    /// on a grid and at the hard angles, canonical (η ≥ 0); the public function takes the fast
    /// path for a unit axis and still reports a zero or non-finite axis.
    #[test]
    fn f64_axis_angle_kernels_match_the_generic_code() {
        let pi = core::f64::consts::PI;
        let n = Vector3::new(1.0, 2.0, 2.0) / 3.0;
        let mut angles: Vec<f64> = (-400..=400).map(|k| k as f64 * pi / 100.0 + 1e-3).collect();
        angles.extend([0.0, -0.0, 1e-300, 1e-16, 1e-8, pi, -pi, pi - 1e-12, 2.0 * pi, 4e5, -4e5]);
        for &th in &angles {
            let want = Quaternion::from_axis_angle_general(&n, th).unwrap();
            let plain = axis_angle_of(&n, crate::vmath::sin_cos::<false>(th * 0.5));
            let bits = |q: Quaternion<f64>| [q.a, q.b, q.c, q.d].map(f64::to_bits);
            assert_eq!(bits(plain), bits(want), "θ = {th:e}");
            let fused = axis_angle_of(&n, crate::vmath::sin_cos::<true>(th * 0.5));
            let (s, c) = (th * 0.5).sin_cos();
            let sign = if c < 0.0 || (c == 0.0 && s < 0.0) { -1.0 } else { 1.0 };
            for (g, w) in [fused.a, fused.b, fused.c, fused.d].iter().zip([c, n.x * s, n.y * s, n.z * s]) {
                assert!((g - sign * w).abs() <= 2.0 * f64::EPSILON, "θ = {th:e}: {fused:?}");
            }
            assert!(fused.a >= 0.0 && plain.a >= 0.0);
            assert_eq!(Quaternion::from_axis_angle(&n, th).unwrap(), if fma() { fused } else { plain });
        }
        assert!(Quaternion::from_axis_angle(&Vector3::zeros(), 1.0).is_err());
        assert!(Quaternion::from_axis_angle(&n, f64::NAN).is_err());
        assert!(Quaternion::from_axis_angle(&Vector3::new(f64::NAN, 0.0, 0.0), 1.0).is_err());
    }

    /// Whether this machine runs the fused build of the dispatched `f64` kernels.
    fn fma() -> bool {
        #[cfg(target_arch = "x86_64")]
        {
            FMA_BUILTIN || std::is_x86_feature_detected!("fma")
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            FMA_BUILTIN
        }
    }
}
