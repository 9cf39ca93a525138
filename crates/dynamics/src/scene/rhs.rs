//! The right-hand side y′ = f(t, y) of a scene, y = (q, v): forward dynamics by ABA with the
//! declared loads, then (only when declared) inerters in the mass matrix and rolling
//! constraints by Gauss's principle.
//!
//! Book: §7.11 (ABA, CRBA), §6.8 (inerters), rolling without slip (§4.x, §7.x);
//! constrained accelerations v̇ = a − M⁻¹Gᵀ(GM⁻¹Gᵀ)⁻¹(Ga + Ġv).

use nalgebra::{DMatrix, DVector, Vector3};

use super::build::Effect;
use super::forces::{Loads, apply};
use super::kin::{Kin, kinematics_into, qdot, twists};
use super::{Scene, SceneError};
use crate::multibody::{AbaScratch, JointWrench, Pose};

/// Finite-difference step for the rates Ġv and ġᵀv of constraint and inerter rows.
const FD_STEP: f64 = 1e-7;

/// Work space of the right-hand side: everything an evaluation needs, allocated once per run.
pub(crate) struct RhsScratch {
    aba: AbaScratch,
    tau: Vec<f64>,
    wrenches: Vec<JointWrench>,
    kin: Kin,
    world: Vec<Pose>,
}

impl RhsScratch {
    pub fn new(scene: &Scene) -> Self {
        let m = &scene.built.model;
        Self {
            aba: m.aba_scratch(),
            tau: vec![0.0; m.nv()],
            wrenches: vec![JointWrench::default(); scene.built.bodies.len()],
            kin: Kin::empty(),
            world: Vec::new(),
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
    /// [`SceneError::Run`] for wrong lengths, or when the dynamics fail (a singular mass
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
        self.scene.deriv_into(t, y, out, &mut self.scratch).map_err(|message| SceneError::Run { t, message })
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
        let b = &self.built;
        let nq = b.model.nq();
        let (q, v) = y.split_at(nq);
        let (qd, vd) = out.split_at_mut(nq);
        qdot(&b.bodies, q, v, qd);
        let ext = if self.needs.loads {
            kinematics_into(&b.model, &b.bodies, &self.order, q, v, &mut w.kin, &mut w.world);
            w.tau.fill(0.0);
            w.wrenches.fill(JointWrench::default());
            let q_angle = |dof: usize| self.angle_of_dof(q, dof);
            let mut loads = Loads { kin: &w.kin, wrenches: &mut w.wrenches, tau: &mut w.tau };
            apply(&b.effects, &b.bodies, &self.ground, t, v, &q_angle, &mut loads)?;
            Some(w.wrenches.as_slice())
        } else {
            None
        };
        b.model.aba_into(q, v, &w.tau, ext, vd, &mut w.aba).map_err(|e| e.to_string())?;
        if self.needs.inerters || self.needs.rolling {
            let a = self.constrained(q, v, vd.to_vec())?;
            vd.copy_from_slice(&a);
        }
        Ok(())
    }

    /// Inerters in the mass matrix and rolling constraints (only when declared).
    fn constrained(&self, q: &[f64], v: &[f64], a: Vec<f64>) -> Result<Vec<f64>, String> {
        let b = &self.built;
        let n = b.model.nv();
        let m = b.model.crba(q).map_err(|e| e.to_string())?;
        let a = DVector::from_vec(a);
        let vv = DVector::from_column_slice(v);
        let q1 = b.model.integrate(q, v, FD_STEP).map_err(|e| e.to_string())?;
        let mut m_tot = m.clone();
        let mut rhs = &m * &a;
        for e in &b.effects {
            match e {
                Effect::Inerter { a: pa, b: pb, b_in } => {
                    let g0 = self.rate_row(q, &[*pa, *pb])?;
                    let g1 = self.rate_row(&q1, &[*pa, *pb])?;
                    let g = g0.row(0).transpose();
                    let gdot_v = ((g1.row(0) - g0.row(0)) * &vv)[0] / FD_STEP;
                    m_tot += &g * g.transpose() * *b_in;
                    rhs -= &g * (b_in * gdot_v);
                }
                Effect::RotInerter { dof, beta } => m_tot[(*dof, *dof)] += beta,
                _ => {}
            }
        }
        let lu = m_tot.clone().lu();
        let mut acc = lu.solve(&rhs).ok_or("singular mass matrix with inerters")?;
        let rows: Vec<DMatrix<f64>> = b
            .effects
            .iter()
            .filter(|e| matches!(e, Effect::Rolling { .. }))
            .map(|e| -> Result<DMatrix<f64>, String> {
                let g0 = self.rolling_rows(q, e)?;
                let g1 = self.rolling_rows(&q1, e)?;
                Ok(DMatrix::from_fn(3, n + 1, |r, c| {
                    if c < n { g0[(r, c)] } else { ((&g1 - &g0) * &vv)[r] / FD_STEP }
                }))
            })
            .collect::<Result<_, _>>()?;
        if !rows.is_empty() {
            let k = rows.len() * 3;
            let g = DMatrix::from_fn(k, n, |r, c| rows[r / 3][(r % 3, c)]);
            let gdot_v = DVector::from_fn(k, |r, _| rows[r / 3][(r % 3, n)]);
            let minv_gt = lu.solve(&g.transpose()).ok_or("singular mass matrix")?;
            let s = &g * &minv_gt;
            let lam = s.lu().solve(&(&g * &acc + gdot_v)).ok_or("rolling constraints are dependent")?;
            acc -= minv_gt * lam;
        }
        Ok(acc.as_slice().to_vec())
    }

    /// M + Σ b g gᵀ: the mass matrix with the translational inerters (g: the row of ℓ̇ = g·v).
    pub(crate) fn mass_with_inerters(&self, q: &[f64], mut m: DMatrix<f64>) -> Result<DMatrix<f64>, String> {
        for e in &self.built.effects {
            if let Effect::Inerter { a: pa, b: pb, b_in } = e {
                let g = self.rate_row(q, &[*pa, *pb])?.row(0).transpose();
                m += &g * g.transpose() * *b_in;
            }
        }
        Ok(m)
    }

    /// Row of ℓ̇ = r̂·(v_b − v_a) as a linear function of v (one row), for an inerter.
    fn rate_row(&self, q: &[f64], ends: &[super::build::At; 2]) -> Result<DMatrix<f64>, String> {
        let b = &self.built;
        let n = b.model.nv();
        let poses = b.model.poses(q).map_err(|e| e.to_string())?;
        let mut row = DMatrix::zeros(1, n);
        let mut e = vec![0.0; n];
        for k in 0..n {
            e.iter_mut().for_each(|x| *x = 0.0);
            e[k] = 1.0;
            let (omega, vel) = twists(&b.bodies, &self.order, &poses, &e);
            let kin = Kin { poses: poses.clone(), omega, vel };
            let (pa, va) = kin.point(&ends[0]);
            let (pb, vb) = kin.point(&ends[1]);
            let rhat = (pb - pa).try_normalize(1e-300).ok_or("inerter ends coincide")?;
            row[(0, k)] = rhat.dot(&(vb - va));
        }
        Ok(row)
    }

    /// G(q): velocity of the contact point of a rolling body as a linear function of v.
    fn rolling_rows(&self, q: &[f64], e: &Effect) -> Result<DMatrix<f64>, String> {
        let Effect::Rolling { body, disk, r, n: nrm, .. } = e else {
            return Ok(DMatrix::zeros(3, 0));
        };
        let b = &self.built;
        let nv = b.model.nv();
        let poses = b.model.poses(q).map_err(|e| e.to_string())?;
        let (el, rl) = poses[*body];
        let c = rl + el.transpose() * b.bodies[*body].com;
        let down = if *disk {
            let k = el.transpose() * Vector3::z();
            let u = k * k.dot(nrm) - nrm;
            u.try_normalize(1e-12).ok_or("disk lies flat on the plane: rolling contact undefined")?
        } else {
            -nrm
        };
        let p_link = el * (c + down * *r - rl);
        let mut g = DMatrix::zeros(3, nv);
        let mut ev = vec![0.0; nv];
        for k in 0..nv {
            ev.iter_mut().for_each(|x| *x = 0.0);
            ev[k] = 1.0;
            let (omega, vel) = twists(&b.bodies, &self.order, &poses, &ev);
            let kin = Kin { poses: poses.clone(), omega, vel };
            let (_, vp) = kin.point(&(Some(*body), p_link));
            g.set_column(k, &vp);
        }
        Ok(g)
    }

    /// y′ = (q̇, v̇), allocating its own work space (for one-off evaluations).
    pub(crate) fn deriv(&self, t: f64, y: &[f64]) -> Result<Vec<f64>, String> {
        let mut out = vec![0.0; y.len()];
        self.deriv_into(t, y, &mut out, &mut RhsScratch::new(self))?;
        Ok(out)
    }

    /// The joint angle whose velocity coordinate is `dof` (pin, collar, slot: q and v align).
    pub(crate) fn angle_of_dof(&self, q: &[f64], dof: usize) -> f64 {
        self.built
            .bodies
            .iter()
            .find(|b| dof >= b.vi && dof < b.vi + super::build::dims(&b.joint).1)
            .map_or(0.0, |b| q[b.qi + (dof - b.vi)])
    }
}
