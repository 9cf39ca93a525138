//! Quaternions as Euler parameters of a rotation (book §2.14–2.17): conversions with
//! 𝓡, eigenaxis and angle, angle vector, Gibbs vector and modified Rodrigues parameters.
//!
//! Every conversion here works on components resolved in one frame: q_{B/A} describes
//! 𝓡_{B/A} = R⃗_{B/A}|_A (= R⃗_{B/A}|_B, Fact 2.10.1), the active rotation
//! 𝓡(q)x = 𝐪𝐱𝐪̄ (Prob 2.26.23).

use nalgebra::{Matrix3, Vector3};
use vectrix_tensor::{FastPath, Scalar};

use crate::series::{angle_0_pi, atan2, canonical_sign, norm3, sin_cos, sinc};
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
    /// rotation by construction. The result is normalised and canonical (η ≥ 0): the largest
    /// pivot's 4p·q divided by |4p·q| = √(4p·q · 4p·q), a plain square root (for a rotation
    /// |4p·q|² = 4p² ∈ [1, 16]: the four pivots 4η², 4εᵢ² sum to 4), with the canonical sign
    /// folded into the scale factor; inlined always, so that it sits in the caller's loop.
    ///
    /// Book: §2.15 (2.15.8–10), largest pivot among {tr 𝓡, 𝓡₁₁, 𝓡₂₂, 𝓡₃₃}; (2.15.20) (η ≥ 0).
    #[inline(always)]
    pub fn from_rotation_matrix_unchecked(r: &Matrix3<T>) -> Self {
        let q = Self::shepperd_unnormalized(r);
        let k = T::one() / q.norm_squared().sqrt();
        // The trace pivot's η = 1 + tr 𝓡 ≥ 1 (tr 𝓡 ≥ 𝓡ᵢᵢ for every i gives tr 𝓡 ≥ 0); the
        // others' η = 4εᵢη may have either sign.
        if q.a > T::zero() {
            q * k
        } else if q.a < T::zero() {
            q * -k
        } else {
            // η = 0 (θ = π), or NaN input
            half_turn(q, k)
        }
    }

    /// The angle vector (log map) of a rotation matrix 𝓡. The angle θ from sin θ = ½|vee(𝓡 − 𝓡ᵀ)|
    /// or cos θ = ½(tr 𝓡 − 1), whichever is well conditioned (asin of the sine below 45.6° and
    /// above 134.4°, of the cosine between); the axis for tr 𝓡 > −0.9 (θ < 162°) from
    /// vee(𝓡 − 𝓡ᵀ) itself, nearer the half turn from the largest pivot of the unnormalised
    /// Shepperd quaternion (whose vector part keeps its digits there). Unchecked (the matrix
    /// must be a rotation).
    ///
    /// For `f64` (chosen at compile time by type, [`Scalar`]'s fast path) the same choices,
    /// switching at 45° and 135°, are made without a `libm` call: with φ/sin φ = G(cos φ), a
    /// polynomial in 1 − cos φ on cos φ ≥ 1/√2 (every coefficient positive, within 0.2 ε),
    /// θ/(2 sin θ) is ½G(cos θ) below 45°, π/|v| − ½G(−cos θ) above 135°, and
    /// (π/2 − cos θ·G(sin θ))/|v| between (asin of the cosine), v = vee(𝓡 − 𝓡ᵀ): no square root
    /// below 45° (exact at θ = 0 and for tiny angles, whose |v|² underflows), one square root
    /// and one division otherwise; within 4 ε of the generic code.
    ///
    /// Book: §2.14 (log map), §2.15; notes ch2b §3.5.
    #[doc(alias = "as_rotvec")]
    #[inline(always)]
    pub fn angle_vector_of_rotation_matrix(r: &Matrix3<T>) -> Vector3<T> {
        // inlined always, so that the `f64` kernel sits in the caller's loop
        T::fast_path::<MatrixLog>(*r)
    }

    /// [`Self::angle_vector_of_rotation_matrix`] for every other scalar (dual numbers, `f32`):
    /// asin of the better conditioned of sin θ and cos θ (`angle_0_pi`), the axis from
    /// vee(𝓡 − 𝓡ᵀ) below 162° and from the largest Shepperd pivot beyond.
    ///
    /// Book: §2.14 (log map), §2.15; notes ch2b §3.5.
    #[inline]
    pub(crate) fn angle_vector_of_rotation_matrix_generic(r: &Matrix3<T>) -> Vector3<T> {
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
    pub(crate) fn shepperd_unnormalized(r: &Matrix3<T>) -> Self {
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
    /// A unit axis (|n̂|² within 4ε of 1) with a finite angle takes the short path, inlined
    /// always into the caller: [`Scalar::fast_sin_cos`] of θ/2 (for `f64` fdlibm's branch-free
    /// kernels, each within 1 ulp); the rest (normalisation, typed errors) is out of line.
    ///
    /// # Errors
    /// [`RotationError::Zero`] for a zero axis, [`RotationError::NonFinite`].
    #[inline(always)]
    pub fn from_axis_angle(axis: &Vector3<T>, theta: T) -> Result<Self, RotationError> {
        // A unit axis (|n̂|² within 4ε of 1, so |n̂| within 2ε) needs no normalisation: the
        // quaternion's norm is then 1 to rounding either way. The comparisons are false for
        // NaN (the checks out of line).
        if (axis.norm_squared().re() - 1.0).abs() <= 4.0 * f64::EPSILON && theta.re().is_finite() {
            let (s, c) = sin_cos(theta * T::lit(0.5));
            let q = Self::from_parts(c, axis * s);
            // η = cos(θ/2) < 0 only for |θ| > π.
            return Ok(if c <= T::zero() { q.canonical() } else { q });
        }
        Self::from_axis_angle_general(axis, theta)
    }

    /// [`Self::from_axis_angle`] for an axis that is not unit or an angle that is not finite:
    /// out of line, so that the short path stays small.
    ///
    /// Book: (2.15.20).
    #[inline(never)]
    fn from_axis_angle_general(axis: &Vector3<T>, theta: T) -> Result<Self, RotationError> {
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
        if let Some((c, sinc_h)) = (n2 * T::lit(0.25)).fast_cos_sinc_of_square() {
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

/// The end of [`Quaternion::from_rotation_matrix_unchecked`] at η = 0 (a half-turn, or a NaN
/// matrix), out of line: the canonical sign of ε (DESIGN §4), as [`Quaternion::canonical`].
///
/// Book: Fact 2.11.5 (the ± at π).
#[cold]
#[inline(never)]
fn half_turn<T: Scalar>(q: Quaternion<T>, k: T) -> Quaternion<T> {
    (q * k).canonical()
}

/// [`Quaternion::angle_vector_of_rotation_matrix`]: the generic asin code, or the `f64` kernel of
/// [`crate::f64::log`].
struct MatrixLog;

impl FastPath for MatrixLog {
    type Input<T: Scalar> = Matrix3<T>;
    type Output<T: Scalar> = Vector3<T>;

    #[inline(always)]
    fn generic<T: Scalar>(r: Matrix3<T>) -> Vector3<T> {
        Quaternion::angle_vector_of_rotation_matrix_generic(&r)
    }

    #[inline(always)]
    fn f64(r: Matrix3<f64>) -> Vector3<f64> {
        crate::f64::log::matrix_log::<{ vectrix_simd::FUSED }>(&r)
    }
}
