//! Frame derivatives as tagged data (book §4.1): a vector with its first and second
//! derivatives with respect to a *named* frame.

use vectrix_tensor::{Dyadic, Scalar, Vector};

use crate::label::check_label;
use crate::motion::finite_vector;
use crate::transport::{double_transport, transport, transport_dyadic};
use crate::{FrameLabel, FrameMotion, KinematicsError};

/// (x⃗, x⃗^{A•}, x⃗^{A••}) at one instant, tagged with the frame F_A of the derivatives.
///
/// A frame derivative is not a property of a vector's value but of (value, rate, frame): the
/// same x⃗ has different derivatives with respect to different frames (4.4.1). Every method
/// that needs a particular frame checks the tag and returns
/// [`KinematicsError::FrameMismatch`] otherwise. For a position r⃗_{y/x}, `rate()` is the
/// velocity v⃗_{y/x/A} and `second_rate()` the acceleration a⃗_{y/x/A} (4.1.6–7).
///
/// Book: §4.1, (4.1.3), (4.1.6–7).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VectorJet<T: Scalar = f64> {
    wrt: FrameLabel,
    x: Vector<T>,
    d1: Vector<T>,
    d2: Vector<T>,
}

impl<T: Scalar> VectorJet<T> {
    /// x⃗ with x⃗^{A•} = `d1` and x⃗^{A••} = `d2`, derivatives with respect to `wrt` = F_A.
    ///
    /// # Errors
    /// [`KinematicsError::NonFinite`].
    ///
    /// Book: §4.1, (4.1.3).
    pub fn new(wrt: FrameLabel, x: Vector<T>, d1: Vector<T>, d2: Vector<T>) -> Result<Self, KinematicsError> {
        finite_vector(&x, "jet value")?;
        finite_vector(&d1, "jet first derivative")?;
        finite_vector(&d2, "jet second derivative")?;
        Ok(Self { wrt, x, d1, d2 })
    }

    /// A vector fixed in F_A: both derivatives with respect to F_A vanish.
    ///
    /// Book: §4.1 ("constant with respect to F_A").
    pub fn fixed_in(wrt: FrameLabel, x: Vector<T>) -> Self {
        Self { wrt, x, d1: Vector::zero(), d2: Vector::zero() }
    }

    /// The frame of the derivatives.
    ///
    /// Book: §4.1, (4.1.3).
    pub fn wrt(&self) -> FrameLabel {
        self.wrt
    }

    /// x⃗.
    ///
    /// Book: §4.1.
    pub fn value(&self) -> Vector<T> {
        self.x
    }

    /// x⃗^{A•} for the tagged frame (for a position: the velocity v⃗_{y/x/A}).
    ///
    /// Book: (4.1.3), (4.1.6).
    pub fn rate(&self) -> Vector<T> {
        self.d1
    }

    /// x⃗^{A••} (for a position: the acceleration a⃗_{y/x/A}).
    ///
    /// Book: (4.1.7).
    pub fn second_rate(&self) -> Vector<T> {
        self.d2
    }

    /// x⃗^{F•} after checking that the jet's frame is `frame`.
    ///
    /// # Errors
    /// [`KinematicsError::FrameMismatch`] when the jet holds derivatives with respect to
    /// another frame.
    ///
    /// Book: (4.1.3); Fact 4.3.2 (why frames are checked).
    pub fn rate_wrt(&self, frame: FrameLabel) -> Result<Vector<T>, KinematicsError> {
        check_label("VectorJet::rate_wrt", frame, self.wrt)?;
        Ok(self.d1)
    }

    /// x⃗^{F••} after checking the frame, as [`VectorJet::rate_wrt`].
    ///
    /// # Errors
    /// [`KinematicsError::FrameMismatch`].
    ///
    /// Book: (4.1.7).
    pub fn second_rate_wrt(&self, frame: FrameLabel) -> Result<Vector<T>, KinematicsError> {
        check_label("VectorJet::second_rate_wrt", frame, self.wrt)?;
        Ok(self.d2)
    }

    /// The same vector with derivatives re-taken with respect to the other frame of `motion`:
    /// from F_B to F_A by the transport theorems (4.4.1), (4.5.1), or from F_A to F_B by the
    /// same theorems with the inverse motion (ω⃗_{A/B} = −ω⃗_{B/A}).
    ///
    /// Book: Fact 4.4.1, (4.4.1), (4.5.1).
    ///
    /// # Errors
    /// [`KinematicsError::FrameMismatch`] when the jet's frame is neither frame of `motion`.
    pub fn transported(&self, motion: &FrameMotion<T>) -> Result<Self, KinematicsError> {
        let m = if self.wrt == motion.body().label {
            *motion
        } else {
            check_label("VectorJet::transported", motion.reference().label, self.wrt)?;
            motion.inverse()
        };
        // here m is the motion of the jet's frame (B) relative to the target frame (A)
        let (w, al) = (m.omega(), m.alpha());
        Ok(Self {
            wrt: m.reference().label,
            x: self.x,
            // (4.4.1): x^{A•} = x^{B•} + ω_{B/A} × x
            d1: transport(&self.d1, &w, &self.x),
            // (4.5.1): x^{A••} = x^{B••} + 2ω×x^{B•} + α×x + ω×(ω×x)
            d2: double_transport(&self.x, &self.d1, &self.d2, &w, &al),
        })
    }

    /// The mixed acceleration a⃗_{y/x/A/B} = (v⃗_{y/x/A})^{B•} = a⃗_{y/x/A} − ω⃗_{B/A} × v⃗_{y/x/A}
    /// for this position jet r⃗_{y/x} with respect to F_A and `b_a` the motion of F_B relative
    /// to F_A.
    ///
    /// Book: (4.1.16–18).
    ///
    /// # Errors
    /// [`KinematicsError::FrameMismatch`] unless the jet is with respect to F_A of `b_a`.
    pub fn mixed_acceleration(&self, b_a: &FrameMotion<T>) -> Result<Vector<T>, KinematicsError> {
        check_label("VectorJet::mixed_acceleration", b_a.reference().label, self.wrt)?;
        // (4.1.16) with (4.4.1) applied to v_{y/x/A}
        Ok(self.d2 - b_a.omega().cross(&self.d1))
    }

    /// r⃗_{x/O_A} with respect to F_A for a point x moving in a moving frame (4.4.11), (4.5.3):
    /// `self` = r⃗_{O_B/O_A} w.r.t. F_A, `b_a` = motion of F_B relative to F_A,
    /// `rel` = r⃗_{x/O_B} w.r.t. F_B. Then
    /// v⃗_{x/O_A/A} = v⃗_{x/O_B/B} + ω⃗_{B/A} × r⃗_{x/O_B} + v⃗_{O_B/O_A/A} and
    /// a⃗_{x/O_A/A} = a⃗_{x/O_B/B} + 2ω⃗×v⃗_{x/O_B/B} + α⃗×r⃗ + ω⃗×(ω⃗×r⃗) + a⃗_{O_B/O_A/A}.
    ///
    /// Book: Fact 4.4.4, (4.4.11), (4.5.3).
    ///
    /// # Errors
    /// [`KinematicsError::FrameMismatch`] unless `self` is w.r.t. F_A and `rel` w.r.t. F_B.
    pub fn moving_point(&self, b_a: &FrameMotion<T>, rel: &VectorJet<T>) -> Result<Self, KinematicsError> {
        check_label("VectorJet::moving_point (origin)", b_a.reference().label, self.wrt)?;
        check_label("VectorJet::moving_point (relative)", b_a.body().label, rel.wrt)?;
        let rel_a = rel.transported(b_a)?;
        Ok(Self { wrt: self.wrt, x: self.x + rel_a.x, d1: self.d1 + rel_a.d1, d2: self.d2 + rel_a.d2 })
    }

    /// A point z of a rigid body B: `self` = r⃗_{y/x} w.r.t. F_A for a point y fixed in B,
    /// `r_z_y` = r⃗_{z/y} (fixed in B). Then v⃗_{z/x/A} = ω⃗_{B/A} × r⃗_{z/y} + v⃗_{y/x/A} (4.4.9)
    /// and a⃗_{z/x/A} = a⃗_{y/x/A} + α⃗_{B/A} × r⃗_{z/y} + ω⃗_{B/A} × (ω⃗_{B/A} × r⃗_{z/y}) (4.5.3).
    ///
    /// Book: (4.4.9), (4.5.3).
    ///
    /// # Errors
    /// [`KinematicsError::FrameMismatch`] unless `self` is w.r.t. F_A of `b_a`;
    /// [`KinematicsError::NonFinite`].
    pub fn rigid_point(&self, b_a: &FrameMotion<T>, r_z_y: Vector<T>) -> Result<Self, KinematicsError> {
        self.moving_point(b_a, &VectorJet::new(b_a.body().label, r_z_y, Vector::zero(), Vector::zero())?)
    }

    /// Sum of two jets with respect to the same frame: r⃗_{z/x} = r⃗_{z/y} + r⃗_{y/x}, and the
    /// additivity v⃗_{z/x/A} = v⃗_{z/y/A} + v⃗_{y/x/A} (Fact 4.1.1).
    ///
    /// # Errors
    /// [`KinematicsError::FrameMismatch`] when the frames differ.
    ///
    /// Book: Fact 4.1.1.
    pub fn plus(&self, other: &VectorJet<T>) -> Result<Self, KinematicsError> {
        check_label("VectorJet::plus", self.wrt, other.wrt)?;
        Ok(Self { wrt: self.wrt, x: self.x + other.x, d1: self.d1 + other.d1, d2: self.d2 + other.d2 })
    }
}

/// (M⃗, M⃗^{A•}) at one instant, tagged with the frame F_A of the derivative.
///
/// Book: (4.1.27–30), (4.4.12).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DyadicJet<T: Scalar = f64> {
    wrt: FrameLabel,
    m: Dyadic<T>,
    d1: Dyadic<T>,
}

impl<T: Scalar> DyadicJet<T> {
    /// M⃗ with M⃗^{A•} = `d1` with respect to `wrt`.
    ///
    /// # Errors
    /// [`KinematicsError::NonFinite`].
    ///
    /// Book: §4.1, (4.1.3).
    pub fn new(wrt: FrameLabel, m: Dyadic<T>, d1: Dyadic<T>) -> Result<Self, KinematicsError> {
        if !m.is_finite() || !d1.is_finite() {
            return Err(KinematicsError::NonFinite { what: "dyadic jet" });
        }
        Ok(Self { wrt, m, d1 })
    }

    /// The frame of the derivative.
    ///
    /// Book: §4.1, (4.1.3).
    pub fn wrt(&self) -> FrameLabel {
        self.wrt
    }

    /// M⃗.
    ///
    /// Book: §4.1.
    pub fn value(&self) -> Dyadic<T> {
        self.m
    }

    /// M⃗^{A•} after checking the frame.
    ///
    /// # Errors
    /// [`KinematicsError::FrameMismatch`].
    ///
    /// Book: (4.1.3); Fact 4.3.2 (why frames are checked).
    pub fn rate_wrt(&self, frame: FrameLabel) -> Result<Dyadic<T>, KinematicsError> {
        check_label("DyadicJet::rate_wrt", frame, self.wrt)?;
        Ok(self.d1)
    }

    /// The derivative re-taken with respect to the other frame of `motion` by
    /// M⃗^{A•} = M⃗^{B•} + Ω⃗_{B/A}M⃗ − M⃗Ω⃗_{B/A}.
    ///
    /// Book: (4.4.12).
    ///
    /// # Errors
    /// [`KinematicsError::FrameMismatch`] when the jet's frame is neither frame of `motion`.
    pub fn transported(&self, motion: &FrameMotion<T>) -> Result<Self, KinematicsError> {
        let m = if self.wrt == motion.body().label {
            *motion
        } else {
            check_label("DyadicJet::transported", motion.reference().label, self.wrt)?;
            motion.inverse()
        };
        Ok(Self { wrt: m.reference().label, m: self.m, d1: transport_dyadic(&self.d1, &m.omega(), &self.m) })
    }
}
