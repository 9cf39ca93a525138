//! The motion of a scene's bodies at one state, read from the multibody model's joints (its
//! poses, twists, bias accelerations: `vectrix_dynamics::multibody`, the one definition of
//! joint motion): link poses and twists in the ground frame, and the positions, velocities and
//! bias accelerations of points fixed in bodies.
//!
//! Book: §4.5 (angular velocity adds along a chain), §5 (transport theorem
//! v_y = v_x + ω × r_{y/x}, a = a₀ + α × r + ω × (ω × r)).

use nalgebra::{Matrix3, Vector3};
use vectrix_dynamics::multibody::{LinkAcceleration, LinkTwist, Model, MotionScratch, Pose, PosesScratch};
use vectrix_tensor::Scalar;

/// A point of a body (or of the ground, `None`), link components.
pub(crate) type At = (Option<usize>, Vector3<f64>);

/// Poses and twists at one state: for each link 𝓞_{link/ground}, r_{origin}, ω and v_{origin}
/// (ground components), in the scalar of the evaluation (f64, or dual numbers for exact
/// derivatives); with the model's transforms at q, so that other velocities and the bias
/// accelerations reuse them.
#[derive(Debug, Clone)]
pub(crate) struct Kin<T: Scalar = f64> {
    pub poses: Vec<Pose<T>>,
    pub omega: Vec<Vector3<T>>,
    pub vel: Vec<Vector3<T>>,
    /// The velocities of the twists.
    v: Vec<T>,
    world: PosesScratch<T>,
    motion: MotionScratch<T>,
    twists: Vec<LinkTwist<T>>,
}

/// A scene constant (f64) in the scalar T of an evaluation.
#[inline(always)]
pub(crate) fn lift<T: Scalar>(x: &Vector3<f64>) -> Vector3<T> {
    x.map(T::lit)
}

/// A scene matrix constant (f64) in the scalar T of an evaluation.
#[inline(always)]
pub(crate) fn lift33<T: Scalar>(x: &Matrix3<f64>) -> Matrix3<T> {
    x.map(T::lit)
}

/// Poses and twists at (q, v); q is checked (lengths, finite numbers, quaternion norms).
pub(crate) fn kinematics(model: &Model, q: &[f64], v: &[f64]) -> Result<Kin, String> {
    model.check_configuration(q).map_err(|e| e.to_string())?;
    let mut kin = Kin::empty();
    kinematics_into(model, q, v, &mut kin);
    Ok(kin)
}

/// [`kinematics`] into a reused [`Kin`], unchecked: no allocation once grown; in any scalar.
pub(crate) fn kinematics_into<T: Scalar>(model: &Model<T>, q: &[T], v: &[T], kin: &mut Kin<T>) {
    model.poses_into(q, &mut kin.world, &mut kin.poses);
    kin.set_velocities(model, v);
}

/// The poses alone at q into a reused [`Kin`] (no twists: its velocities are left empty), for
/// loads that read positions only (gravitation, springs, applied forces); unchecked, in any
/// scalar.
pub(crate) fn poses_into<T: Scalar>(model: &Model<T>, q: &[T], kin: &mut Kin<T>) {
    model.poses_into(q, &mut kin.world, &mut kin.poses);
    kin.omega.clear();
    kin.vel.clear();
    kin.v.clear();
}

impl<T: Scalar> Kin<T> {
    /// An empty buffer for [`kinematics_into`].
    pub fn empty() -> Self {
        Self {
            poses: Vec::new(),
            omega: Vec::new(),
            vel: Vec::new(),
            v: Vec::new(),
            world: PosesScratch::default(),
            motion: MotionScratch::default(),
            twists: Vec::new(),
        }
    }

    /// The twists of the velocities `v` at this configuration.
    fn set_velocities(&mut self, model: &Model<T>, v: &[T]) {
        model.twists_into(&self.world, v, &mut self.motion, &mut self.twists);
        self.omega.clear();
        self.omega.extend(self.twists.iter().map(|t| t.omega));
        self.vel.clear();
        self.vel.extend(self.twists.iter().map(|t| t.velocity));
        self.v.clear();
        self.v.extend_from_slice(&v[..model.nv()]);
    }

    /// Ground position of a point fixed in a body (or in the ground); needs the poses only. A
    /// point at the link origin is the origin's position, read without arithmetic.
    #[inline]
    pub fn position(&self, at: &At) -> Vector3<T> {
        match at.0 {
            None => lift(&at.1),
            Some(i) if at.1 == Vector3::zeros() => self.poses[i].1,
            Some(i) => {
                let (e, r) = self.poses[i];
                r + e.tr_mul(&lift::<T>(&at.1))
            }
        }
    }

    /// Ground position and velocity of a point fixed in a body (or in the ground).
    pub fn point(&self, at: &At) -> (Vector3<T>, Vector3<T>) {
        match at.0 {
            None => (lift(&at.1), Vector3::zeros()),
            Some(i) => {
                let (e, r) = self.poses[i];
                let d = e.transpose() * lift::<T>(&at.1);
                (r + d, self.vel[i] + self.omega[i].cross(&d))
            }
        }
    }
}

impl Kin {
    /// The same configuration moving with the velocities `v` (a column of a velocity
    /// Jacobian for a unit v).
    pub fn with_velocities(&self, model: &Model, v: &[f64]) -> Kin {
        let mut k = self.clone();
        k.set_velocities(model, v);
        k
    }

    /// The links' bias accelerations (α and the origin's acceleration at v̇ = 0, ground
    /// components) at this state, from [`Model::bias_accelerations_into`].
    pub fn bias_accelerations(&self, model: &Model) -> (Vec<Vector3<f64>>, Vec<Vector3<f64>>) {
        let mut acc: Vec<LinkAcceleration> = Vec::new();
        model.bias_accelerations_into(&self.world, &self.v, &mut MotionScratch::default(), &mut acc);
        acc.iter().map(|a| (a.alpha, a.acceleration)).unzip()
    }

    /// The bias acceleration (v̇ = 0) of a point fixed in a body (or in the ground), given the
    /// links' bias accelerations: a = a_o + α × d + ω × (ω × d).
    pub fn point_bias(&self, at: &At, alpha: &[Vector3<f64>], acc: &[Vector3<f64>]) -> Vector3<f64> {
        match at.0 {
            None => Vector3::zeros(),
            Some(i) => {
                let d = self.poses[i].0.transpose() * at.1;
                acc[i] + alpha[i].cross(&d) + self.omega[i].cross(&self.omega[i].cross(&d))
            }
        }
    }
}
