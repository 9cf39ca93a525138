//! Forward dynamics in O(n) by the articulated-body algorithm.
#![allow(non_snake_case)]

use nalgebra::{Matrix3, Matrix6, Matrix6x3, Vector3, Vector6};

use super::model::{Elem, Model};
use super::rnea::{LinkWrenches, joint_motion};
use super::spatial::{Xform, cross_force, cross_motion, join, split};
use crate::DynamicsError;

/// Work space of the articulated-body algorithm.
#[derive(Debug, Clone)]
pub struct AbaScratch {
    x: Vec<Xform>,
    IA: Vec<Matrix6<f64>>,
    pA: Vec<Vector6<f64>>,
    c: Vec<Vector6<f64>>,
    U: Vec<Matrix6x3<f64>>,
    Dinv: Vec<Matrix3<f64>>,
    u: Vec<Vector3<f64>>,
    a: Vec<Vector6<f64>>,
    w: Vec<Vector3<f64>>,
    v: Vec<Vector3<f64>>,
}

impl Model {
    /// A work space for [`Model::aba_unchecked`].
    pub fn aba_scratch(&self) -> AbaScratch {
        let n = self.segs.len();
        AbaScratch {
            x: vec![Xform::identity(); n],
            IA: vec![Matrix6::zeros(); n],
            pA: vec![Vector6::zeros(); n],
            c: vec![Vector6::zeros(); n],
            U: vec![Matrix6x3::zeros(); n],
            Dinv: vec![Matrix3::zeros(); n],
            u: vec![Vector3::zeros(); n],
            a: vec![Vector6::zeros(); n],
            w: vec![Vector3::zeros(); n],
            v: vec![Vector3::zeros(); n],
        }
    }

    /// Forward dynamics v̇ = FD(q, v, τ) in O(n) by the articulated-body algorithm
    /// (Featherstone): three passes over the tree; the book's per-body equations (7.11.13)
    /// with the joint reactions eliminated tip to base. `f_ext` as in [`Model::rnea`].
    ///
    /// Book: §7.11; RBDA Table 7.1.
    ///
    /// # Errors
    /// [`DynamicsError::DimensionMismatch`], [`DynamicsError::NonFinite`];
    /// [`DynamicsError::SingularMassMatrix`] when a joint's articulated inertia SᵀIᴬS is not
    /// positive definite (a massless leaf link, or a massless chain end).
    pub fn aba(
        &self,
        q: &[f64],
        v: &[f64],
        tau: &[f64],
        f_ext: Option<&LinkWrenches>,
    ) -> Result<Vec<f64>, DynamicsError> {
        self.check_q(q)?;
        self.check_v(v, "v")?;
        self.check_v(tau, "τ")?;
        if let Some(f) = f_ext {
            crate::error::check_len(f.len(), self.links(), "external wrenches")?;
        }
        let mut out = vec![0.0; self.nv];
        let mut s = self.aba_scratch();
        self.aba_into(q, v, tau, f_ext, &mut out, &mut s)?;
        Ok(out)
    }

    /// [`Model::aba`] without input checks and with caller-provided scratch: the hot path.
    ///
    /// # Errors
    /// [`DynamicsError::SingularMassMatrix`] as [`Model::aba`].
    pub fn aba_unchecked(
        &self,
        q: &[f64],
        v: &[f64],
        tau: &[f64],
        vdot: &mut [f64],
        s: &mut AbaScratch,
    ) -> Result<(), DynamicsError> {
        self.aba_into(q, v, tau, None, vdot, s)
    }

    /// [`Model::aba`] with external wrenches, without input checks and with caller-provided
    /// scratch: the hot path of a scene's right-hand side.
    ///
    /// # Errors
    /// [`DynamicsError::SingularMassMatrix`] as [`Model::aba`].
    pub fn aba_into(
        &self,
        q: &[f64],
        v: &[f64],
        tau: &[f64],
        f_ext: Option<&LinkWrenches>,
        vdot: &mut [f64],
        s: &mut AbaScratch,
    ) -> Result<(), DynamicsError> {
        let n = self.segs.len();
        // pass 1 (outward): twists, bias accelerations c = 𝒱 ×m S q̇, bias forces 𝒱 ×f 𝒥𝒱
        for (i, seg) in self.segs.iter().enumerate() {
            let x = seg.placement.then(&seg.elem.xform(&q[seg.qi..]));
            let (wp, vp) = match seg.parent {
                Some(p) => (s.w[p], s.v[p]),
                None => (Vector3::zeros(), Vector3::zeros()),
            };
            let (mut wi, mut vi) = x.motion(&wp, &vp);
            let (sw, sv) = joint_motion(&seg.elem, &v[seg.vi..]);
            wi += sw;
            vi += sv;
            let (cw, cv) = cross_motion(&wi, &vi, &sw, &sv);
            let (hn, hf) = seg.inertia.apply(&wi, &vi);
            let (bn, bf) = cross_force(&wi, &vi, &hn, &hf);
            s.x[i] = x;
            s.c[i] = join(&cw, &cv);
            s.IA[i] = seg.inertia.matrix();
            s.pA[i] = join(&bn, &bf);
            (s.w[i], s.v[i]) = (wi, vi);
        }
        if let Some(fe) = f_ext {
            for (l, &k) in self.link_seg.iter().enumerate() {
                s.pA[k] -= join(&fe[l].moment, &fe[l].force);
            }
        }
        // pass 2 (inward): U = IᴬS, D = SᵀU, u = τ − SᵀpA; Iᵃ = Iᴬ − U D⁻¹Uᵀ,
        // pᵃ = pᴬ + Iᵃc + U D⁻¹u, accumulated into the parent through Xᵀ
        for i in (0..n).rev() {
            let seg = &self.segs[i];
            let IA = s.IA[i];
            let pA = s.pA[i];
            let (Ia, pa) = match seg.elem {
                Elem::Revolute(a) | Elem::Prismatic(a) => {
                    let sv = match seg.elem {
                        Elem::Revolute(_) => join(&a, &Vector3::zeros()),
                        _ => join(&Vector3::zeros(), &a),
                    };
                    let U = IA * sv;
                    let D = sv.dot(&U);
                    if D.is_nan() || D <= f64::EPSILON * IA.norm().max(f64::MIN_POSITIVE) {
                        return Err(DynamicsError::SingularMassMatrix {
                            detail: format!(
                                "articulated inertia SᵀIᴬS = {D:e} at velocity coordinate {}",
                                seg.vi
                            ),
                        });
                    }
                    let u = tau[seg.vi] - sv.dot(&pA);
                    s.U[i].set_column(0, &U);
                    s.Dinv[i][(0, 0)] = 1.0 / D;
                    s.u[i][0] = u;
                    let Ia = IA - U * (U.transpose() / D);
                    let pa = pA + Ia * s.c[i] + U * (u / D);
                    (Ia, pa)
                }
                Elem::Spherical => {
                    let U: Matrix6x3<f64> = IA.fixed_columns::<3>(0).into_owned();
                    let D: Matrix3<f64> = U.fixed_rows::<3>(0).into_owned();
                    let Dinv = D.cholesky().map(|c| c.inverse()).ok_or_else(|| {
                        DynamicsError::SingularMassMatrix {
                            detail: format!(
                                "ball-joint articulated inertia not positive definite at {}",
                                seg.vi
                            ),
                        }
                    })?;
                    let u =
                        Vector3::new(tau[seg.vi], tau[seg.vi + 1], tau[seg.vi + 2]) - pA.fixed_rows::<3>(0);
                    s.U[i] = U;
                    s.Dinv[i] = Dinv;
                    s.u[i] = u;
                    let Ia = IA - U * Dinv * U.transpose();
                    (Ia, pA + Ia * s.c[i] + U * (Dinv * u))
                }
                Elem::Fixed => (IA, pA + IA * s.c[i]),
            };
            if let Some(p) = seg.parent {
                let add = s.x[i].inertia_to_parent(&Ia);
                s.IA[p] += add;
                s.pA[p] += s.x[i].force6_to_parent(&pa);
            }
        }
        // pass 3 (outward): 𝒜' = X𝒜_p + c, q̈ = D⁻¹(u − Uᵀ𝒜'), 𝒜 = 𝒜' + S q̈
        let a0 = join(&Vector3::zeros(), &(-self.gravity));
        for i in 0..n {
            let seg = &self.segs[i];
            let ap = match seg.parent {
                Some(p) => s.a[p],
                None => a0,
            };
            let (aw, av) = split(&ap);
            let (xw, xv) = s.x[i].motion(&aw, &av);
            let a_prime = join(&xw, &xv) + s.c[i];
            let a = match seg.elem {
                Elem::Revolute(ax) | Elem::Prismatic(ax) => {
                    let qdd = s.Dinv[i][(0, 0)] * (s.u[i][0] - s.U[i].column(0).dot(&a_prime));
                    vdot[seg.vi] = qdd;
                    match seg.elem {
                        Elem::Revolute(_) => a_prime + join(&(ax * qdd), &Vector3::zeros()),
                        _ => a_prime + join(&Vector3::zeros(), &(ax * qdd)),
                    }
                }
                Elem::Spherical => {
                    let qdd = s.Dinv[i] * (s.u[i] - s.U[i].transpose() * a_prime);
                    vdot[seg.vi..seg.vi + 3].copy_from_slice(qdd.as_slice());
                    a_prime + join(&qdd, &Vector3::zeros())
                }
                Elem::Fixed => a_prime,
            };
            s.a[i] = a;
        }
        Ok(())
    }
}
