//! Kinematic trees of rigid bodies connected by the book's joints (book §1.5, Table 1.3,
//! §7.11), in reduced coordinates, generic over the scalar (f64 by default; dual numbers give
//! exact derivatives of everything computed from a model): the model and its queries here,
//! its construction and validation in `build`, link placements in `poses`.
#![allow(non_snake_case)]

use nalgebra::{Matrix3, Vector3};
use vectrix_tensor::Scalar;

use super::planar::Planar;
use super::segment::Segment;

mod build;
mod poses;

pub use poses::PosesScratch;
pub(crate) use poses::Trig;

/// A validated kinematic tree in reduced coordinates, ready for RNEA, ABA and CRBA, generic
/// over the scalar: `Model` is `Model<f64>`; [`Model::cast`] gives the same tree over dual
/// numbers (`Model<Dual64>`, `Model<HyperDual64>`, `Model<DualSVec64<N>>`), whose
/// algorithms then return exact derivatives of their results with respect to whatever the
/// caller seeded (states, or the model's own numbers).
///
/// Book: §7.11; DESIGN §1.4 (generic scalar).
#[derive(Debug, Clone, PartialEq)]
pub struct Model<T: Scalar = f64> {
    pub(crate) segs: Vec<Segment<T>>,
    /// For each user link, the index of its (last) segment.
    pub(crate) link_seg: Vec<usize>,
    pub(crate) nq: usize,
    pub(crate) nv: usize,
    /// Gravitational acceleration g resolved in the ground frame.
    pub gravity: Vector3<T>,
    pub(crate) q_neutral: Vec<T>,
    /// For each velocity coordinate, the nearest coordinate above it in the tree (the previous
    /// column of the same joint, else the last column of the nearest ancestor that has one).
    pub(crate) parent_col: Vec<Option<usize>>,
    /// For each velocity coordinate, its segment.
    pub(crate) col_seg: Vec<usize>,
    /// First segments of the free joints at the root whose link has no children (a floating
    /// body on its own): ABA solves these in closed form ([`Model::aba_into`]).
    pub(crate) free_leaves: Vec<usize>,
    /// For each entry of `free_leaves`, its user link (whose external wrench it takes).
    pub(crate) free_links: Vec<usize>,
    /// For each entry of `free_leaves`, J_c⁻¹ of its body (from the Cholesky factor found
    /// definite when the model was built): Euler's equations solved by one product.
    pub(crate) free_jc_inv: Vec<Matrix3<T>>,
    /// For each segment, whether it belongs to a free leaf.
    pub(crate) free_seg: Vec<bool>,
    /// Ball joints at the root whose link has no children (a body turning about a fixed
    /// point on its own): ABA solves these in closed form too ([`Model::aba_into`]).
    pub(crate) ball_leaves: Vec<usize>,
    /// For each entry of `ball_leaves`, its user link (whose external wrench it takes).
    pub(crate) ball_links: Vec<usize>,
    /// For each entry of `ball_leaves`, J_o⁻¹: the inverse of the body's inertia about the
    /// joint point (definite: checked when the model was built).
    pub(crate) ball_jo_inv: Vec<Matrix3<T>>,
    /// For each segment, whether ABA solves it in closed form (a free or ball leaf): the
    /// three passes skip it.
    pub(crate) aba_skip: Vec<bool>,
    /// First segments of the free joints at the root whose body has children (a floating
    /// base): ABA eliminates each in one 6×6 solve after its subtree.
    pub(crate) free_roots: Vec<usize>,
    /// For each segment, the entry of `free_roots` it belongs to.
    pub(crate) free_root_seg: Vec<Option<usize>>,
    /// `aba_skip` or part of a free root: the segments ABA's inward loop leaves alone.
    pub(crate) inward_skip: Vec<bool>,
    /// The planar reduction, when every pin turns about one axis of the ground and every
    /// slider moves across it: ABA then runs on 3-vectors ([`Model::aba_into`]).
    pub(crate) planar: Option<Planar<T>>,
}

/// Longest chain [`Model::revolute_chain`] builds (its benchmark chains have tens of links; a
/// million keeps a hostile `n` from allocating without bound).
pub const MAX_CHAIN_LINKS: usize = 1_000_000;

impl<T: Scalar> Model<T> {
    /// Number of configuration coordinates (quaternions count 4).
    pub fn nq(&self) -> usize {
        self.nq
    }

    /// Number of velocity coordinates (degrees of freedom).
    pub fn nv(&self) -> usize {
        self.nv
    }

    /// Number of links.
    pub fn links(&self) -> usize {
        self.link_seg.len()
    }

    /// The axis â (ground components) when the tree is planar: every pin turns about ±â, every
    /// slider moves ⊥ â, and no placement rotates the joint frame (so every link frame differs
    /// from the ground by a turn about â). Such a mechanism moves in planes ⊥ â from any state,
    /// and [`Model::aba`] then works on planar spatial vectors (3 numbers instead of 6: the
    /// in-plane parts of positions, centres, gravity and forces, the moment along â, and
    /// âᵀĪâ of each body), with the same v̇ to rounding. The tests are exact: an axis off ±â
    /// by rounding keeps the spatial algorithm. `None` for spatial trees.
    ///
    /// Book: §7.11 (chains); §6.3 (moment of inertia about an axis); RBDA §2.16.
    pub fn planar_axis(&self) -> Option<Vector3<T>> {
        self.planar.as_ref().map(|p| p.axis)
    }

    /// Turns the planar reduction of [`Model::planar_axis`] off, so that [`Model::aba`] runs the
    /// spatial passes on a planar tree too: for measuring what the reduction saves and for
    /// checking it (the answers agree to rounding). [`Model::planar_axis`] returns `None`
    /// afterwards: it reports what the model uses.
    pub fn disable_planar_reduction(&mut self) {
        self.planar = None;
    }

    /// Segment i is the first slider of a free joint at the root (`free_leaves`, `free_roots`):
    /// three massless sliders along x̂, ŷ, ẑ of the joint frame, then the ball carrying the
    /// body; RNEA and CRBA take the four segments in one step.
    #[inline(always)]
    pub(crate) fn free_at_root(&self, i: usize) -> bool {
        self.segs[i].parent.is_none() && (self.free_seg[i] || self.free_root_seg[i].is_some())
    }

    /// The neutral configuration: zero for every coordinate, identity quaternions.
    pub fn neutral(&self) -> Vec<T> {
        self.q_neutral.clone()
    }
}
