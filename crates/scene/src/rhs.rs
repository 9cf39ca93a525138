//! The right-hand side y′ = f(t, y) of a scene, y = (q, v): forward dynamics by ABA with the
//! declared loads, then (only when declared) inerters, rolling contacts and loop-closing
//! joints by the multiplier system of [`super::loops`] (exact bias terms, no finite
//! differences).
//!
//! Book: §7.11 (ABA, CRBA), §6.8 (inerters), §4.18 and §9.12 (rolling), §9.11 (loops).

use std::cell::{Cell, RefCell};

use nalgebra::{DMatrix, DVector};
use vectrix_tensor::Scalar;

use super::aero::AeroScratch;
use super::contacts::Contacts;
use super::forces::{Ground, Loads, apply};
use super::kin::{Kin, kinematics_into, poses_into};
use super::needs::Route;
use super::{Scene, SceneError};
use vectrix_dynamics::Model;
use vectrix_dynamics::multibody::{AbaScratch, JointWrench};

/// Work space of the right-hand side: everything an evaluation needs, allocated once per run,
/// in the scalar of the evaluation (f64, or dual numbers for exact derivatives).
pub(crate) struct RhsScratch<T: Scalar = f64> {
    aba: AbaScratch<T>,
    tau: Vec<T>,
    wrenches: Vec<JointWrench<T>>,
    kin: Kin<T>,
    ground: Ground<T>,
    /// The independent constraint rows found last (see `loops::solve_dropping`).
    keep: Option<Vec<usize>>,
    /// The α̇/β̇ solve of aero effects.
    aero: AeroScratch<T>,
    /// In a run, the piece [lo, hi] between two corners of the load profiles that the
    /// integrator is on: their jumps are taken from its side (`Profile::eval_on`).
    pub(crate) piece: Option<(f64, f64)>,
}

impl RhsScratch {
    pub fn new(scene: &Scene) -> Self {
        Self::for_model(scene, &scene.built.model)
    }
}

impl<T: Scalar> RhsScratch<T> {
    /// Work space for evaluations on `model` (the scene's, or its cast to another scalar).
    pub fn for_model(scene: &Scene, m: &Model<T>) -> Self {
        Self {
            aba: m.aba_scratch(),
            tau: vec![T::zero(); m.nv()],
            wrenches: vec![JointWrench::default(); scene.built.bodies.len()],
            kin: Kin::empty(),
            ground: Ground::new(),
            keep: None,
            aero: AeroScratch::new(scene.built.bodies.len(), m.nv(), scene.rate_aircraft().count()),
            piece: None,
        }
    }
}

/// A reusable evaluator of a scene's right-hand side y′ = f(t, y), y = (q, v): its work space
/// is allocated once, so an evaluation allocates nothing (the scene's own loads, ABA and
/// joint kinematics; inerters and rolling still build small matrices). For your own
/// integrators, sensitivity studies and benches.
///
/// Book: §7.11 (ABA), ch. 6 (the declared loads).
pub struct SceneRhs<'a> {
    scene: &'a Scene,
    scratch: RhsScratch,
}

impl std::fmt::Debug for SceneRhs<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SceneRhs").field("scene", &self.scene.spec().name).finish_non_exhaustive()
    }
}

impl SceneRhs<'_> {
    /// y′ = f(t, y) into `out` (both of length nq + nv).
    ///
    /// # Errors
    /// [`SceneError::Run`] for wrong lengths, a non-finite t or y, a non-finite y′ (finite
    /// input whose derivative overflows), or when the dynamics fail (a singular mass
    /// matrix, coincident points).
    pub fn eval(&mut self, t: f64, y: &[f64], out: &mut [f64]) -> Result<(), SceneError> {
        let n = self.scene.built.model.nq() + self.scene.built.model.nv();
        if y.len() != n || out.len() != n {
            return Err(SceneError::Run {
                t,
                message: format!(
                    "state of length {} and output of length {}; valid: {n} each",
                    y.len(),
                    out.len()
                ),
            });
        }
        // the checks' fast path inline; the search for the offending entry only on failure
        if !(t.is_finite() && all_finite(y)) {
            finite_state(t, y).map_err(|message| SceneError::Run { t, message })?;
        }
        let scene = self.scene;
        // the shortest path the scene allows: ABA alone, the tree with its loads, or everything
        let done = match scene.needs.route {
            Route::Plain => scene.deriv_plain(y, out, &mut self.scratch),
            Route::Tree => scene.deriv_tree(&scene.built.model, t, y, None, out, &mut self.scratch),
            Route::Full => scene.deriv_into(t, y, out, &mut self.scratch),
        };
        done.map_err(|message| SceneError::Run { t, message })?;
        if all_finite(out) {
            return Ok(());
        }
        finite_derivative(out).map_err(|message| SceneError::Run { t, message })
    }
}

/// Whether every entry is finite, without a branch per entry: the exponent field of x plus one
/// exponent step carries into the sign bit exactly when the field is all ones (±∞ and NaN), so
/// the OR of those sums has its top bit clear exactly when all are finite. Integer and, add and
/// or are associative, so the loop vectorizes whole (the hot path of every public evaluation;
/// the search for the offending entry runs only on failure).
#[inline(always)]
fn all_finite(y: &[f64]) -> bool {
    const EXPONENT: u64 = 0x7ff0_0000_0000_0000;
    const STEP: u64 = 0x0010_0000_0000_0000;
    y.iter().fold(0u64, |acc, x| acc | ((x.to_bits() & EXPONENT) + STEP)) >> 63 == 0
}

/// The public evaluators take user states: a non-finite t or y is refused before the
/// unchecked hot path (which would propagate it as NaN).
pub(crate) fn finite_state(t: f64, y: &[f64]) -> Result<(), String> {
    if !t.is_finite() {
        return Err(format!("t = {t}; valid: a finite time"));
    }
    if all_finite(y) {
        return Ok(());
    }
    match y.iter().position(|x| !x.is_finite()) {
        Some(k) => Err(format!("state entry {k} is {}; valid: finite numbers", y[k])),
        None => Ok(()),
    }
}

/// A finite state whose derivative is not finite (an angle of 1e300 rad, speeds that square
/// past f64::MAX) is an error, never NaN or ∞ inside `Ok`.
pub(crate) fn finite_derivative(d: &[f64]) -> Result<(), String> {
    if all_finite(d) {
        return Ok(());
    }
    match d.iter().position(|x| !x.is_finite()) {
        Some(k) => Err(format!(
            "the right-hand side is not finite (component {k}: {}); valid: a state where the dynamics are finite",
            d[k]
        )),
        None => Ok(()),
    }
}

impl Scene {
    /// A reusable, allocation-free evaluator of the right-hand side (see [`SceneRhs`]).
    pub fn rhs(&self) -> SceneRhs<'_> {
        SceneRhs { scene: self, scratch: RhsScratch::new(self) }
    }

    /// y′ = (q̇, v̇) at (t, y) into `out`: q̇ from the joint kinematics, v̇ by ABA with the
    /// declared loads (only when some are declared), then inerters and rolling.
    pub(crate) fn deriv_into(
        &self,
        t: f64,
        y: &[f64],
        out: &mut [f64],
        w: &mut RhsScratch,
    ) -> Result<(), String> {
        self.deriv_lambda(t, y, out, w, &[]).map(|_| ())
    }

    /// [`Scene::deriv_into`] with the resting contacts (`resting[c]`: contact c rests on its
    /// plane and pushes with its normal force, see `resting`).
    pub(crate) fn deriv_resting(
        &self,
        t: f64,
        y: &[f64],
        out: &mut [f64],
        w: &mut RhsScratch,
        resting: &[bool],
    ) -> Result<(), String> {
        self.deriv_lambda(t, y, out, w, resting).map(|_| ())
    }

    /// The multipliers λ of the constraint rows (loops in loop order, then rolling contacts)
    /// at (t, y): −Gᵀλ is the generalized constraint force (§9.11).
    pub(crate) fn multipliers(&self, t: f64, y: &[f64]) -> Result<DVector<f64>, String> {
        let mut out = vec![0.0; y.len()];
        Ok(self
            .deriv_lambda(t, y, &mut out, &mut RhsScratch::new(self), &[])?
            .unwrap_or_else(|| DVector::zeros(0)))
    }

    /// [`Scene::deriv_into`], returning the multipliers when the scene has constraint rows.
    fn deriv_lambda(
        &self,
        t: f64,
        y: &[f64],
        out: &mut [f64],
        w: &mut RhsScratch,
        resting: &[bool],
    ) -> Result<Option<DVector<f64>>, String> {
        let b = &self.built;
        let nq = b.model.nq();
        if self.needs.route == Route::Plain {
            self.deriv_plain(y, out, w)?;
        } else {
            self.deriv_tree(&b.model, t, y, None, out, w)?;
        }
        let (q, v) = y.split_at(nq);
        let vd = &mut out[nq..];
        if self.needs.constrained() {
            if !self.needs.twists {
                kinematics_into(&b.model, q, v, &mut w.kin);
            }
            let (a, lambda) = self.constrained_solve(&w.kin, q, vd, &mut w.keep)?;
            vd.copy_from_slice(a.as_slice());
            return Ok(Some(lambda));
        }
        if resting.contains(&true) {
            if !self.needs.twists {
                kinematics_into(&b.model, q, v, &mut w.kin);
            }
            self.rest_forces(&w.kin, resting, vd);
            self.stop_rest_forces(q, resting, vd)?;
        }
        Ok(None)
    }

    /// y′ = (q̇, v̇) of the tree with the declared loads (ABA), in any scalar: the whole
    /// right-hand side of a scene without loops, rolling, inerters or resting contacts, and the
    /// first part of every other. `model` is the scene's model in the scalar T; `u` adds to the
    /// magnitudes of the `force` and `torque` effects (a linearization's inputs).
    pub(crate) fn deriv_tree<T: Scalar>(
        &self,
        model: &Model<T>,
        t: f64,
        y: &[T],
        u: Option<&[T]>,
        out: &mut [T],
        w: &mut RhsScratch<T>,
    ) -> Result<(), String> {
        let b = &self.built;
        let nq = model.nq();
        let (q, v) = y.split_at(nq);
        let (qd, vd) = out.split_at_mut(nq);
        self.qdot_into(q, v, qd);
        let ext = if self.needs.loads {
            // the kinematics the declared loads read: twists (dashpots, aero), poses (the
            // others but rotational springs and dashpots, which read q and v), or none
            if self.needs.twists {
                kinematics_into(model, q, v, &mut w.kin);
            } else if self.needs.poses {
                poses_into(model, q, &mut w.kin);
            }
            // τ stays zero (as allocated) unless a load writes it
            if self.needs.joint_torques {
                w.tau.fill(T::zero());
            }
            w.wrenches.fill(JointWrench::default());
            let q_angle = |dof: usize| self.angle_of_dof(q, dof);
            let mut loads = Loads { kin: &w.kin, wrenches: &mut w.wrenches, tau: &mut w.tau };
            apply(&b.effects, &b.bodies, &w.ground, (t, w.piece), v, &q_angle, u, &mut loads)?;
            Some(w.wrenches.as_slice())
        } else {
            None
        };
        model.aba_into(q, v, &w.tau, ext, vd, &mut w.aba).map_err(|e| e.to_string())?;
        if self.needs.aero_rates {
            self.aero_rates(model, q, v, &w.tau, &w.kin, &w.wrenches, vd, &mut w.aba, &mut w.aero)?;
        }
        Ok(())
    }

    /// y′ of a scene with no loads, constraints or contacts to apply (a free body, a chain under
    /// uniform gravity): q̇ from the joints and v̇ by ABA alone, as [`Scene::deriv_tree`] gives it
    /// then, without its branches.
    #[inline]
    pub(crate) fn deriv_plain(&self, y: &[f64], out: &mut [f64], w: &mut RhsScratch) -> Result<(), String> {
        let model = &self.built.model;
        let nq = model.nq();
        let (q, v) = y.split_at(nq);
        let (qd, vd) = out.split_at_mut(nq);
        self.qdot_into(q, v, qd);
        model.aba_into(q, v, &w.tau, None, vd, &mut w.aba).map_err(|e| e.to_string())
    }

    /// [`Scene::deriv_plain`] at two states at once, each the same bits (a chain of pins:
    /// `Model::aba_pair_unchecked` runs both in one pass).
    pub(crate) fn deriv_plain_pair(
        &self,
        (ya, oa): (&[f64], &mut [f64]),
        (yb, ob): (&[f64], &mut [f64]),
        w: &mut RhsScratch,
    ) -> Result<(), String> {
        let model = &self.built.model;
        let nq = model.nq();
        let ((qa, va), (qb, vb)) = (ya.split_at(nq), yb.split_at(nq));
        let ((qda, vda), (qdb, vdb)) = (oa.split_at_mut(nq), ob.split_at_mut(nq));
        self.qdot_into(qa, va, qda);
        self.qdot_into(qb, vb, qdb);
        model
            .aba_pair_unchecked((qa, va), (qb, vb), &w.tau, (vda, vdb), &mut w.aba)
            .map_err(|e| e.to_string())
    }

    /// Whether a run's evaluations may go two at a time ([`Scene::deriv_plain_pair`]): the
    /// plain route (no loads, constraints or contacts) on a model whose ABA pairs.
    pub(crate) fn pairs(&self) -> bool {
        self.needs.route == Route::Plain
            && !self.needs.constrained()
            && self.contacts.is_empty()
            && self.built.model.aba_pairs()
    }

    /// q̇ from (q, v): a copy when every coordinate is its own speed, else the joints' map.
    #[inline(always)]
    fn qdot_into<T: Scalar>(&self, q: &[T], v: &[T], qd: &mut [T]) {
        if self.needs.qdot_is_v {
            qd.copy_from_slice(v);
        } else {
            self.qdot.apply(q, v, qd);
        }
    }

    /// M + Σ b g gᵀ (+ rotational inerters): the mass matrix with the inerters, for
    /// [`Scene::query`].
    pub(crate) fn mass_with_inerters(&self, kin: &Kin, mut m: DMatrix<f64>) -> Result<DMatrix<f64>, String> {
        for (g, _, b_in) in &self.constraint_rows(kin)?.inerters {
            m += g * g.transpose() * *b_in;
        }
        Ok(m)
    }

    /// y′ = (q̇, v̇), allocating its own work space (for one-off evaluations).
    pub(crate) fn deriv(&self, t: f64, y: &[f64]) -> Result<Vec<f64>, String> {
        let mut out = vec![0.0; y.len()];
        self.deriv_into(t, y, &mut out, &mut RhsScratch::new(self))?;
        Ok(out)
    }

    /// The joint angle whose velocity coordinate is `dof` (pin, collar, slot: q and v align).
    pub(crate) fn angle_of_dof<T: Scalar>(&self, q: &[T], dof: usize) -> T {
        self.built
            .bodies
            .iter()
            .find(|b| dof >= b.vi && dof < b.vi + b.joint.nv())
            .map_or(T::zero(), |b| q[b.qi + (dof - b.vi)])
    }
}

/// A run's right-hand side, written in place (the stepper keeps one state per stage: no
/// allocation per evaluation): [`Scene::deriv_resting`] with the contacts at rest, on the
/// piece of the load profiles the stepper is on; a failure is kept (the first) and shows
/// the stepper a NaN. Two states at once where the scene allows ([`Scene::pairs`]).
pub(crate) struct RunRhs<'a> {
    pub scene: &'a Scene,
    pub scratch: RhsScratch,
    pub piece: &'a Cell<(f64, f64)>,
    pub contacts: &'a RefCell<Contacts>,
    pub failure: &'a RefCell<Option<String>>,
}

impl vectrix_ode::Rhs<Vec<f64>> for RunRhs<'_> {
    const IN_PLACE: bool = true;
    fn call(&mut self, t: f64, y: &Vec<f64>) -> Vec<f64> {
        let mut out = y.clone();
        self.call_into(t, y, &mut out);
        out
    }
    fn call_into(&mut self, t: f64, y: &Vec<f64>, out: &mut Vec<f64>) {
        self.scratch.piece = Some(self.piece.get());
        let resting = &self.contacts.borrow().resting;
        if let Err(e) = self.scene.deriv_resting(t, y, out, &mut self.scratch, resting) {
            self.failure.borrow_mut().get_or_insert(e);
            out.fill(f64::NAN);
        }
    }
    fn pairs(&self) -> bool {
        self.scene.pairs()
    }
    fn call_pair_into(&mut self, a: (f64, &Vec<f64>, &mut Vec<f64>), b: (f64, &Vec<f64>, &mut Vec<f64>)) {
        if !self.scene.pairs() {
            self.call_into(a.0, a.1, a.2);
            self.call_into(b.0, b.1, b.2);
        } else if let Err(e) = self.scene.deriv_plain_pair((a.1, a.2), (b.1, b.2), &mut self.scratch) {
            self.failure.borrow_mut().get_or_insert(e);
            a.2.fill(f64::NAN);
            b.2.fill(f64::NAN);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn all_finite_sees_every_non_finite_entry_at_every_position() {
        for n in 0..11 {
            let y: Vec<f64> = (0..n).map(|k| [f64::MAX, -0.0, 5e-324, -1e300, 1.0][k % 5]).collect();
            assert!(all_finite(&y), "{y:?}");
            for k in 0..n {
                for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                    let mut z = y.clone();
                    z[k] = bad;
                    assert!(!all_finite(&z), "{z:?}");
                    assert!(finite_state(0.0, &z).is_err_and(|m| m.contains(&format!("entry {k}"))));
                    assert!(finite_derivative(&z).is_err_and(|m| m.contains(&format!("component {k}"))));
                }
            }
        }
    }

    /// A chain of pins under uniform gravity: a run's right-hand side pairs, and each state
    /// of a pair gets the bits of one evaluation; with a spring (a load), or a ball on a free
    /// joint with a contact beside it, it does not pair.
    #[test]
    fn run_rhs_pairs_a_pin_chain_with_the_bits_of_single_calls() {
        use vectrix_ode::Rhs as _;
        let body = |i: usize| {
            let parent = if i == 0 {
                String::new()
            } else {
                format!("parent = \"l{}\"\noffset = [0.0, 0.0, -0.3]\n", i - 1)
            };
            format!(
                "\n[[bodies]]\nname = \"l{i}\"\n{parent}joint = {{ type = \"pin\", axis = [0.0, 1.0, 0.0] }}\n\
                 mass = {{ shape = \"value\", mass = 1.0, principal = [0.01, 0.01, 0.001] }}\ncom = [0.0, 0.0, -0.15]\n"
            )
        };
        let mut text = String::from(
            "name = \"chain\"\nduration = 1.0\nmethod = { name = \"gbs\", rtol = 1e-10 }\n\
             [[effects]]\ntype = \"uniform_gravity\"\ng = [0.0, 0.0, -9.81]\n",
        );
        for i in 0..5 {
            text += &body(i);
        }
        let scene = Scene::from_toml(&text, "test").expect("valid chain");
        assert!(scene.pairs());
        let (piece, failure) = (Cell::new((0.0, 1.0)), RefCell::new(None));
        let contacts = RefCell::new(Contacts { resting: Vec::new(), events: Vec::new() });
        let mut f = RunRhs {
            scene: &scene,
            scratch: RhsScratch::new(&scene),
            piece: &piece,
            contacts: &contacts,
            failure: &failure,
        };
        assert!(f.pairs());
        let y0 = scene.initial_state();
        let ya: Vec<f64> = (0..10).map(|k| 0.3 * k as f64 - 1.0).collect();
        let yb: Vec<f64> = (0..10).map(|k| (k as f64).sin() * 2.0).collect();
        let (mut oa, mut ob) = (y0.clone(), y0.clone());
        f.call_pair_into((0.1, &ya, &mut oa), (0.2, &yb, &mut ob));
        let (ea, eb) = (f.call(0.1, &ya), f.call(0.2, &yb));
        let bits = |x: &[f64]| x.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
        assert_eq!((bits(&oa), bits(&ob)), (bits(&ea), bits(&eb)));
        assert!(failure.borrow().is_none());
        let spring =
            text.clone() + "\n[[effects]]\ntype = \"rotational_spring\"\nbody = \"l1\"\nkappa = 2.0\n";
        let contact = text.clone()
            + "\n[[bodies]]\nname = \"ball\"\njoint = { type = \"free\" }\n\
               mass = { shape = \"value\", mass = 1.0, principal = [0.01, 0.01, 0.01] }\n\
               \n[[effects]]\ntype = \"contact_plane\"\nbody = \"ball\"\nradius = 0.05\n\
               point = [0.0, 0.0, -5.0]\nnormal = [0.0, 0.0, 1.0]\nrestitution = 0.5\nfriction = 0.0\n";
        for other in [spring, contact.replace("\"gbs\"", "\"dop853\"")] {
            let scene = Scene::from_toml(&other, "test").expect("valid scene");
            assert!(!scene.pairs(), "{other}");
        }
    }
}
