//! Exact first derivatives of a scene's right-hand side and outputs, for linearization, trim
//! and implicit integrators: the generic right-hand side evaluated once per state and input on
//! dual numbers (forward mode, num-dual's `Dual64`), so the Jacobians carry no truncation
//! error. Also the inputs of a scene (the profiles of its effects) and their names.
//!
//! Book: §12.6 (linearization), §9.x (dual numbers for exact derivatives).

use nalgebra::DMatrix;
use num_dual::Dual64;
use vectrix_dynamics::Model;
use vectrix_tensor::Scalar;

use super::kin::{Kin, kinematics_into};
use super::rhs::RhsScratch;
use super::{Scene, SceneError};
use vectrix_dynamics::multibody::Joint;

/// g's value, ∂g/∂x and ∂g/∂u.
type DualColumns = (Vec<f64>, DMatrix<f64>, DMatrix<f64>);

/// Forward-mode derivatives of g(x, u): one Dual64 evaluation per variable, the j-th seeded
/// (ε = 1), so the ε parts of the result are the j-th column. Returns g's value, ∂g/∂x and
/// ∂g/∂u; a value or derivative that is not finite is an error.
fn dual_columns(
    x: &[f64],
    u: &[f64],
    mut g: impl FnMut(&[Dual64], &[Dual64]) -> Result<Vec<Dual64>, String>,
) -> Result<DualColumns, String> {
    let (n, m) = (x.len(), u.len());
    let (mut value, mut gx, mut gu) = (Vec::new(), DMatrix::zeros(0, n), DMatrix::zeros(0, m));
    for j in 0..n + m {
        let seed = |k: usize, v: f64| Dual64::new(v, if k == j { 1.0 } else { 0.0 });
        let xd: Vec<Dual64> = x.iter().enumerate().map(|(k, v)| seed(k, *v)).collect();
        let ud: Vec<Dual64> = u.iter().enumerate().map(|(k, v)| seed(n + k, *v)).collect();
        let r = g(&xd, &ud)?;
        if let Some(bad) = r.iter().find(|d| !(d.re.is_finite() && d.eps.is_finite())) {
            return Err(format!(
                "a derivative is not finite ({bad}); valid: a state where the dynamics are smooth"
            ));
        }
        if j == 0 {
            (gx, gu) = (DMatrix::zeros(r.len(), n), DMatrix::zeros(r.len(), m));
        }
        value = r.iter().map(|d| d.re).collect();
        for (i, d) in r.iter().enumerate() {
            if j < n { gx[(i, j)] = d.eps } else { gu[(i, j - n)] = d.eps }
        }
    }
    Ok((value, gx, gu))
}

/// Exact first derivatives at a state of the linearization (x = (δ, v) about q₀).
pub(crate) struct Jacobians {
    /// v̇ at the state.
    pub vdot: Vec<f64>,
    /// ∂v̇/∂x (nv × 2nv).
    pub vdot_x: DMatrix<f64>,
    /// ∂v̇/∂u (nv × inputs).
    pub vdot_u: DMatrix<f64>,
    /// ∂(output columns)/∂x.
    pub row_x: DMatrix<f64>,
}

impl Scene {
    /// The inputs of a linearization, in the order the right-hand side reads them: every
    /// profile of the `force`, `torque`, `thrust` and `aero` effects, as (effect index, key);
    /// named `effects[k]` for a one-profile effect and `effects[k].elevator` (`aileron`,
    /// `rudder`) for an aircraft's controls.
    pub(crate) fn inputs(&self) -> Vec<(usize, &'static str)> {
        let effects = self.spec().effects.iter().enumerate();
        effects.flat_map(|(k, e)| e.profiles().into_iter().map(move |(key, _)| (k, key))).collect()
    }

    /// The names of [`Scene::inputs`].
    pub(crate) fn input_names(&self) -> Vec<String> {
        let name = |(k, key): (usize, &str)| match key {
            "profile" => format!("effects[{k}]"),
            _ => format!("effects[{k}].{key}"),
        };
        self.inputs().into_iter().map(name).collect()
    }

    /// Scenes whose right-hand side is the tree's alone (no loops, rolling or inerters): the
    /// generic right-hand side covers them.
    pub(crate) fn tree_only(&self) -> bool {
        !self.needs.constrained()
    }

    /// v̇ and the output columns at x = (δ, v) (q = q₀ ⊕ δ) with the inputs u, in any scalar;
    /// with `body_axes`, a free joint's translational v̇ is taken in its body's axes (see
    /// [`Scene::body_axis_rates`]).
    fn vdot_and_row<T: Scalar>(
        &self,
        model: &Model<T>,
        (q0, x, u): (&[f64], &[T], &[T]),
        body_axes: bool,
        w: &mut RhsScratch<T>,
    ) -> Result<(Vec<T>, Vec<T>), String> {
        let (nq, nv) = (model.nq(), model.nv());
        let q0: Vec<T> = q0.iter().map(|x| T::lit(*x)).collect();
        let mut q = model.integrate(&q0, &x[..nv], T::one()).map_err(|e| e.to_string())?;
        model.normalize_quaternions(&mut q);
        let y = [q.as_slice(), &x[nv..]].concat();
        let mut out = vec![T::zero(); nq + nv];
        self.deriv_tree(model, 0.0, &y, Some(u), &mut out, w)?;
        let (q, v) = y.split_at(nq);
        let mut kin = Kin::empty();
        kinematics_into(model, q, v, &mut kin);
        let mut row = Vec::new();
        self.row(&kin, q, v, None, &mut row);
        let mut vd = out[nq..].to_vec();
        if body_axes {
            self.body_axis_rates(&kin, &mut vd);
        }
        Ok((vd, row))
    }

    /// A free joint's (on the ground) translational acceleration (joint-frame components of the
    /// origin's acceleration) replaced by the rate of its velocity in the body's own axes,
    /// d/dt(𝓞 v_o) = 𝓞 a_o − ω × 𝓞 v_o (transport theorem): zero in a steady turn, where the
    /// ground velocity turns with the body. The other joints' v̇ are left as they are.
    ///
    /// Book: §5.x (transport theorem), §12.5 (steady turning flight).
    pub(crate) fn body_axis_rates<T: Scalar>(&self, kin: &Kin<T>, vd: &mut [T]) {
        for (i, b) in self.built.bodies.iter().enumerate() {
            if !matches!(b.joint, Joint::Free) || b.parent.is_some() {
                continue;
            }
            let e = kin.poses[i].0;
            let w = e * kin.omega[i];
            // the ground joint frame's components of a_o → ground → body
            let a_o = super::kin::lift33::<T>(&b.orient).tr_mul(&nalgebra::Vector3::new(
                vd[b.vi],
                vd[b.vi + 1],
                vd[b.vi + 2],
            ));
            let r = e * a_o - w.cross(&(e * kin.vel[i]));
            vd[b.vi..b.vi + 3].copy_from_slice(r.as_slice());
        }
    }

    /// Exact ∂v̇/∂x, ∂v̇/∂u and ∂(outputs)/∂x at x about the initial configuration, with no
    /// inputs added.
    pub(crate) fn jacobians(&self, x: &[f64]) -> Result<Jacobians, String> {
        let q0 = self.initial_state()[..self.built.model.nq()].to_vec();
        self.jacobians_at(&q0, &vec![0.0; self.inputs().len()], x, None)
    }

    /// Exact ∂v̇/∂x, ∂v̇/∂u and ∂(outputs)/∂x at x = (δ, v) about the configuration q0 with the
    /// inputs u0, by one dual-number evaluation per state and input. With `hold` (a trim's), the
    /// residual is v̇ with free joints in body axes followed by output column − target for each
    /// (column, target) held.
    pub(crate) fn jacobians_at(
        &self,
        q0: &[f64],
        u0: &[f64],
        x: &[f64],
        hold: Option<&[(usize, f64)]>,
    ) -> Result<Jacobians, String> {
        let model = self.built.model.cast::<Dual64>();
        let mut w = RhsScratch::for_model(self, &model);
        let nr = x.len() / 2 + hold.map_or(0, |h| h.len());
        let (value, fx, fu) = dual_columns(x, u0, |xd, ud| {
            let (mut a, row) = self.vdot_and_row(&model, (q0, xd, ud), hold.is_some(), &mut w)?;
            for (c, target) in hold.unwrap_or_default() {
                a.push(row[*c] - Dual64::from(*target));
            }
            Ok([a, row].concat())
        })?;
        let rows = fx.nrows();
        Ok(Jacobians {
            vdot: value[..nr].to_vec(),
            vdot_x: fx.rows(0, nr).into_owned(),
            vdot_u: fu.rows(0, nr).into_owned(),
            row_x: fx.rows(nr, rows - nr).into_owned(),
        })
    }

    /// The Jacobians of the right-hand side y′ = f(t, y, u) at (t, y) with the inputs u = 0:
    /// (∂f/∂y, ∂f/∂u), exact (dual numbers through the same code as the f64 evaluation), y =
    /// (q, v) as [`Scene::derivative`] takes it (a quaternion's four components each), u the
    /// magnitudes added to the `force` and `torque` effects in their order. For implicit
    /// integrators and sensitivity studies.
    ///
    /// Book: §12.6 (linearization), §9.x (dual numbers for exact derivatives).
    ///
    /// # Errors
    /// [`SceneError::Run`] for a state of the wrong length or not finite, a derivative that is
    /// not finite; [`SceneError::Invalid`] for scenes with loops, rolling or inerters (their
    /// right-hand side solves for multipliers in f64 only, so far).
    pub fn jacobian(&self, t: f64, y: &[f64]) -> Result<(DMatrix<f64>, DMatrix<f64>), SceneError> {
        let fail = |message: String| SceneError::Run { t, message };
        let n = self.built.model.nq() + self.built.model.nv();
        if y.len() != n {
            return Err(fail(format!("state of length {}; valid: {n}", y.len())));
        }
        super::rhs::finite_state(t, y).map_err(fail)?;
        if !self.tree_only() {
            return Err(self.invalid(
                "effects",
                "exact Jacobians of scenes with loops, rolling or inerters are not available yet; valid: a tree \
                 with force elements",
            ));
        }
        let model = self.built.model.cast::<Dual64>();
        let mut w = RhsScratch::for_model(self, &model);
        let mut out = vec![Dual64::from(0.0); n];
        let (_, fy, fu) = dual_columns(y, &vec![0.0; self.inputs().len()], |yd, ud| {
            self.deriv_tree(&model, t, yd, Some(ud), &mut out, &mut w)?;
            Ok(out.clone())
        })
        .map_err(fail)?;
        Ok((fy, fu))
    }
}
