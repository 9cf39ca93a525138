//! Frame identity: a label that travels with every frame derivative.

use core::fmt;

use vectrix_frames::Frame;
use vectrix_tensor::Scalar;

/// The identity of a frame, F_A ↦ `FrameLabel::new("A")`.
///
/// A vectrix [`Frame`] is only its three axes at an instant (book §2.4); two different frames
/// can coincide at one instant while moving differently. A frame derivative x⃗^{A•} therefore
/// carries the *label* of its frame, and every operation checks it at run time: using a
/// derivative with respect to F_A where F_B is needed is [`KinematicsError::FrameMismatch`],
/// never a silent mix.
///
/// Book: §4.1, (4.1.3).
///
/// [`KinematicsError::FrameMismatch`]: crate::KinematicsError::FrameMismatch
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct FrameLabel {
    name: &'static str,
    index: Option<u32>,
}

impl FrameLabel {
    /// A frame named like the book: `FrameLabel::new("A")`.
    ///
    /// Book: §2.4, §4.1.
    pub const fn new(name: &'static str) -> Self {
        Self { name, index: None }
    }

    /// The k-th frame of a family, e.g. the links of a chain: `FrameLabel::indexed("link", 3)`.
    ///
    /// Book: §4.13 (chains of frames).
    pub const fn indexed(name: &'static str, index: u32) -> Self {
        Self { name, index: Some(index) }
    }

    /// The name part.
    ///
    /// Book: §2.4.
    pub const fn name(&self) -> &'static str {
        self.name
    }
}

impl fmt::Display for FrameLabel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.index {
            None => write!(f, "F_{}", self.name),
            Some(k) => write!(f, "F_{}[{k}]", self.name),
        }
    }
}

/// A frame with its label: the axes of F_A at an instant together with the identity "A".
///
/// Book: §2.4, §4.1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LabeledFrame<T: Scalar = f64> {
    /// The frame's identity.
    pub label: FrameLabel,
    /// Its axes at this instant.
    pub frame: Frame<T>,
}

impl<T: Scalar> LabeledFrame<T> {
    /// Labels a frame: `LabeledFrame::new("A", a)`.
    ///
    /// Book: §2.4, §4.1.
    pub fn new(name: &'static str, frame: Frame<T>) -> Self {
        Self { label: FrameLabel::new(name), frame }
    }

    /// Labels a frame with a prepared label.
    ///
    /// Book: §2.4.
    pub fn with_label(label: FrameLabel, frame: Frame<T>) -> Self {
        Self { label, frame }
    }
}

/// `Ok(())` when `found` is `expected`, else [`KinematicsError::FrameMismatch`].
pub(crate) fn check_label(
    context: &'static str,
    expected: FrameLabel,
    found: FrameLabel,
) -> Result<(), crate::KinematicsError> {
    if expected == found {
        Ok(())
    } else {
        Err(crate::KinematicsError::FrameMismatch { context, expected, found })
    }
}
