//! Constraints of a scene beyond its tree: loop-closing joints (holonomic, §9.11), rolling
//! without slip (nonholonomic, §9.12) and inerters (mass-matrix terms, §6.8). Each gives rows
//! of a velocity Jacobian G (by unit velocities: G v is linear in v) and its bias Ġv (from the
//! links' bias accelerations, exactly: no finite differences). The accelerations solve
//! [[M + Σ b g gᵀ, Gᵀ], [G, 0]] [v̇; λ] = [M a − Σ b g ġv; −Ġv] with a at v̇ from ABA, by the
//! rank-revealing factorization of `vectrix_dynamics::constraints` (redundant loop rows, as in a planar
//! mechanism closed by a 3-D pin, are dropped: their reactions are indeterminate).
//!
//! Book: §9.11 (multipliers), §9.12 (nonholonomic), §4.18 (rolling), §6.8 (inerters), §6.10
//! (reactions).

use nalgebra::{DMatrix, DVector, Vector3};

use super::Scene;
use super::kin::Kin;
use super::parts::{At, Effect};
use vectrix_dynamics::DynamicsError;
use vectrix_dynamics::constraints::{DEPENDENT_ROW_REL_TOL, KktFactor};

/// A loop-closing joint with names resolved: points of body `a` and `b` (or the ground).
#[derive(Debug, Clone)]
pub(crate) struct Loop {
    pub name: String,
    pub kind: LoopKind,
    pub a: At,
    pub b: At,
}

/// The geometry of a loop joint (unit vectors in the frames named).
#[derive(Debug, Clone)]
pub(crate) enum LoopKind {
    Ball,
    /// e1, e2 ⊥ the axis in `a`'s link frame; the axis in `b`'s link frame (fixed at q₀).
    Pin {
        e1_a: Vector3<f64>,
        e2_a: Vector3<f64>,
        axis_b: Vector3<f64>,
    },
    /// Two normals of the line, `b`'s link frame.
    Line {
        n1_b: Vector3<f64>,
        n2_b: Vector3<f64>,
    },
    /// The plane's normal, `b`'s link frame.
    Plane {
        n_b: Vector3<f64>,
    },
    /// A weld: the points coincide and three pairs (u, w), u fixed in `b` (link frame) and
    /// w fixed in `a` (link frame), stay perpendicular (u·w = 0), u being at q₀ the image in
    /// `b` of the `a`-axis after w (y→z, z→x, x→y); with the points, 6 rows.
    Weld {
        pairs: [(Vector3<f64>, Vector3<f64>); 3],
    },
    /// q[qa] = ratio · q[qb] + offset (speeds va, vb): a linear joint-coordinate coupling.
    Coupler {
        qa: usize,
        va: usize,
        lead: Option<(usize, usize)>,
        ratio: f64,
        offset: f64,
    },
}

impl Loop {
    /// Number of scalar constraints.
    pub fn rows(&self) -> usize {
        match self.kind {
            LoopKind::Ball => 3,
            LoopKind::Pin { .. } => 5,
            LoopKind::Line { .. } => 2,
            LoopKind::Plane { .. } => 1,
            LoopKind::Weld { .. } => 6,
            LoopKind::Coupler { .. } => 1,
        }
    }
}

/// Two unit vectors that complete `n` (unit) to an orthonormal triad.
pub(crate) fn normals(n: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let pick = if n.x.abs() < 0.6 { Vector3::x() } else { Vector3::y() };
    let e1 = n.cross(&pick).normalize();
    (e1, n.cross(&e1))
}

/// 𝓞_{link/ground} of a body, the identity for the ground.
pub(crate) fn orient<T: vectrix_tensor::Scalar>(kin: &Kin<T>, body: Option<usize>) -> nalgebra::Matrix3<T> {
    body.map_or_else(nalgebra::Matrix3::identity, |i| kin.poses[i].0)
}

fn omega(kin: &Kin, body: Option<usize>) -> Vector3<f64> {
    body.map_or_else(Vector3::zeros, |i| kin.omega[i])
}

/// d/dt[(ω_b − ω_a)·(k × e)] at v̇ = 0, k fixed in `b` and e in `a` (ground components), with
/// k̇ = ω_b × k, ė = ω_a × e and the bias angular accelerations α: the bias of a pin's or a
/// weld's turning rows.
fn turn_bias(
    k: &Vector3<f64>,
    e: &Vector3<f64>,
    (wa, wb): (&Vector3<f64>, &Vector3<f64>),
    (aa, ab): (&Vector3<f64>, &Vector3<f64>),
) -> f64 {
    let kxe_dot = wb.cross(k).cross(e) + k.cross(&wa.cross(e));
    (ab - aa).dot(&k.cross(e)) + (wb - wa).dot(&kxe_dot)
}

/// The scene's constraint rows at one state: G (m × nv), the bias Ġv, and the inerters'
/// rank-one mass terms (g, ġv, b).
pub(crate) struct Rows {
    pub g: DMatrix<f64>,
    pub bias: DVector<f64>,
    pub inerters: Vec<(DVector<f64>, f64, f64)>,
}

impl Scene {
    /// φ(q) of every loop (the position constraints), in loop order; `kin` is at q.
    pub(crate) fn loop_phi(&self, kin: &Kin, q: &[f64], out: &mut Vec<f64>) {
        for l in &self.built.loops {
            let (pa, _) = kin.point(&l.a);
            let (pb, _) = kin.point(&l.b);
            let d = pa - pb;
            let (ea, eb) = (orient(kin, l.a.0), orient(kin, l.b.0));
            match &l.kind {
                LoopKind::Ball => out.extend(d.iter()),
                LoopKind::Pin { e1_a, e2_a, axis_b } => {
                    out.extend(d.iter());
                    let k = eb.tr_mul(axis_b);
                    out.push(k.dot(&ea.tr_mul(e1_a)));
                    out.push(k.dot(&ea.tr_mul(e2_a)));
                }
                LoopKind::Line { n1_b, n2_b } => {
                    out.push(d.dot(&eb.tr_mul(n1_b)));
                    out.push(d.dot(&eb.tr_mul(n2_b)));
                }
                LoopKind::Plane { n_b } => out.push(d.dot(&eb.tr_mul(n_b))),
                LoopKind::Weld { pairs } => {
                    out.extend(d.iter());
                    // u_b · w_a for each pair, 0 at the welded pose
                    out.extend(pairs.iter().map(|(u, w)| eb.tr_mul(u).dot(&ea.tr_mul(w))));
                }
                // q_a − m q_b − offset
                LoopKind::Coupler { qa, lead, ratio, offset, .. } => {
                    out.push(q[*qa] - lead.map_or(0.0, |(qb, _)| ratio * q[qb]) - offset);
                }
            }
        }
    }

    /// φ̇ = G v of every loop for the twists in `kin` (linear in them), `kin` holding the
    /// unit velocity v = e_k.
    fn loop_rates(&self, kin: &Kin, k: usize, out: &mut Vec<f64>) {
        for l in &self.built.loops {
            let (pa, va) = kin.point(&l.a);
            let (pb, vb) = kin.point(&l.b);
            let (d, dv) = (pa - pb, va - vb);
            let (ea, eb) = (orient(kin, l.a.0), orient(kin, l.b.0));
            let (wa, wb) = (omega(kin, l.a.0), omega(kin, l.b.0));
            match &l.kind {
                LoopKind::Ball => out.extend(dv.iter()),
                LoopKind::Pin { e1_a, e2_a, axis_b } => {
                    out.extend(dv.iter());
                    // d/dt(k_b·e_a) = (ω_b − ω_a)·(k_b × e_a)
                    let k = eb.tr_mul(axis_b);
                    for e in [e1_a, e2_a] {
                        out.push((wb - wa).dot(&k.cross(&ea.tr_mul(e))));
                    }
                }
                LoopKind::Line { n1_b, n2_b } => {
                    for n in [n1_b, n2_b] {
                        let n = eb.tr_mul(n);
                        // d/dt(d·n) = ḋ·n + d·(ω_b × n)
                        out.push(dv.dot(&n) + d.dot(&wb.cross(&n)));
                    }
                }
                LoopKind::Plane { n_b } => {
                    let n = eb.tr_mul(n_b);
                    out.push(dv.dot(&n) + d.dot(&wb.cross(&n)));
                }
                LoopKind::Weld { pairs } => {
                    out.extend(dv.iter());
                    // d/dt(u_b·w_a) = (ω_b − ω_a)·(u_b × w_a)
                    for (u, w) in pairs {
                        out.push((wb - wa).dot(&eb.tr_mul(u).cross(&ea.tr_mul(w))));
                    }
                }
                // d/dt(q_a − m q_b) at v = e_k: δ(k, a) − m δ(k, b)
                LoopKind::Coupler { va, lead, ratio, .. } => {
                    let e = |i: usize| if i == k { 1.0 } else { 0.0 };
                    out.push(e(*va) - lead.map_or(0.0, |(_, vb)| ratio * e(vb)));
                }
            }
        }
    }

    /// Ġv of every loop: d/dt of `loop_rates` at v̇ = 0, from the bias accelerations.
    fn loop_bias(&self, kin: &Kin, alpha: &[Vector3<f64>], acc: &[Vector3<f64>], out: &mut Vec<f64>) {
        for l in &self.built.loops {
            let (pa, va) = kin.point(&l.a);
            let (pb, vb) = kin.point(&l.b);
            let (d, dv) = (pa - pb, va - vb);
            let da = kin.point_bias(&l.a, alpha, acc) - kin.point_bias(&l.b, alpha, acc);
            let (ea, eb) = (orient(kin, l.a.0), orient(kin, l.b.0));
            let (wa, wb) = (omega(kin, l.a.0), omega(kin, l.b.0));
            let al = |b: Option<usize>| b.map_or_else(Vector3::zeros, |i| alpha[i]);
            let (aa, ab) = (al(l.a.0), al(l.b.0));
            match &l.kind {
                LoopKind::Ball => out.extend(da.iter()),
                LoopKind::Pin { e1_a, e2_a, axis_b } => {
                    out.extend(da.iter());
                    let k = eb.tr_mul(axis_b);
                    for e in [e1_a, e2_a] {
                        out.push(turn_bias(&k, &ea.tr_mul(e), (&wa, &wb), (&aa, &ab)));
                    }
                }
                LoopKind::Weld { pairs } => {
                    out.extend(da.iter());
                    for (u, w) in pairs {
                        out.push(turn_bias(&eb.tr_mul(u), &ea.tr_mul(w), (&wa, &wb), (&aa, &ab)));
                    }
                }
                // q̈_a − m q̈_b = v̇_a − m v̇_b: no bias
                LoopKind::Coupler { .. } => out.push(0.0),
                LoopKind::Line { n1_b, n2_b } => {
                    for n in [n1_b, n2_b] {
                        let n = eb.tr_mul(n);
                        out.push(
                            da.dot(&n)
                                + 2.0 * dv.dot(&wb.cross(&n))
                                + d.dot(&(ab.cross(&n) + wb.cross(&wb.cross(&n)))),
                        );
                    }
                }
                LoopKind::Plane { n_b } => {
                    let n = eb.tr_mul(n_b);
                    out.push(
                        da.dot(&n)
                            + 2.0 * dv.dot(&wb.cross(&n))
                            + d.dot(&(ab.cross(&n) + wb.cross(&wb.cross(&n)))),
                    );
                }
            }
        }
    }

    /// The contact point of a rolling body relative to its centre, and its rate (P − c and
    /// d/dt(P − c)): −r n for a sphere; r u for a disk, u the unit vector in the disk's plane
    /// toward the plane, u ∝ k (k·n) − n with k the disk's normal (k̇ = ω × k).
    fn contact_offset(
        &self,
        kin: &Kin,
        body: usize,
        disk: bool,
        r: f64,
        n: &Vector3<f64>,
    ) -> Result<(Vector3<f64>, Vector3<f64>), String> {
        if !disk {
            return Ok((-n * r, Vector3::zeros()));
        }
        let k = kin.poses[body].0.tr_mul(&Vector3::z());
        let w = k * k.dot(n) - n;
        let len = w.norm();
        if len <= 1e-12 {
            return Err("disk lies flat on the plane: rolling contact undefined".into());
        }
        let u = w / len;
        let kd = kin.omega[body].cross(&k);
        let wd = kd * k.dot(n) + k * kd.dot(n);
        let ud = (wd - u * u.dot(&wd)) / len;
        Ok((u * r, ud * r))
    }

    /// The twists of the unit velocities at the poses of `kin`: entry k is the motion of
    /// every link for v = e_k, so that a velocity constraint's row is read column by column.
    fn unit_twists(&self, kin: &Kin) -> Vec<Kin> {
        let b = &self.built;
        let nv = b.model.nv();
        (0..nv)
            .map(|k| {
                let mut e = vec![0.0; nv];
                e[k] = 1.0;
                kin.with_velocities(&b.model, &e)
            })
            .collect()
    }

    /// G (m × nv) at the poses of `kin`: the loop rows in loop order, then (with `rolling`) three
    /// rows per rolling contact (the velocity of the material contact point).
    fn jacobian_from(&self, kin: &Kin, unit: &[Kin], rolling: bool) -> Result<DMatrix<f64>, String> {
        let b = &self.built;
        let nv = b.model.nv();
        let mut cols: Vec<Vec<f64>> = vec![Vec::new(); nv];
        for (k, u) in unit.iter().enumerate() {
            self.loop_rates(u, k, &mut cols[k]);
        }
        if rolling {
            for e in &b.effects {
                if let Effect::Rolling { body, disk, r, n, .. } = e {
                    let (pc, _) = self.contact_offset(kin, *body, *disk, *r, n)?;
                    let el = kin.poses[*body].0;
                    // the material point at the contact, in link components
                    let p_link = el * (el.tr_mul(&b.bodies[*body].com) + pc);
                    for (k, u) in unit.iter().enumerate() {
                        cols[k].extend(u.point(&(Some(*body), p_link)).1.iter());
                    }
                }
            }
        }
        let m = cols.first().map_or(0, Vec::len);
        Ok(DMatrix::from_fn(m, nv, |r, c| cols[c][r]))
    }

    /// G of the loops and rolling contacts at the poses of `kin` (v does not enter).
    pub(crate) fn velocity_jacobian(&self, kin: &Kin, rolling: bool) -> Result<DMatrix<f64>, String> {
        self.jacobian_from(kin, &self.unit_twists(kin), rolling)
    }

    /// All constraint rows at (q, v): loops, rolling contacts, inerters.
    pub(crate) fn constraint_rows(&self, kin: &Kin) -> Result<Rows, String> {
        let b = &self.built;
        let nv = b.model.nv();
        let unit = self.unit_twists(kin);
        let g = self.jacobian_from(kin, &unit, true)?;
        let (alpha, acc) = kin.bias_accelerations(&b.model);
        let mut bias = Vec::with_capacity(g.nrows());
        self.loop_bias(kin, &alpha, &acc, &mut bias);
        let mut inerters = Vec::new();
        for e in &b.effects {
            match e {
                Effect::Rolling { body, disk, r, n, .. } => {
                    let (pc, pc_dot) = self.contact_offset(kin, *body, *disk, *r, n)?;
                    // d/dt v_P = a_c + α × (P − c) + ω × d/dt(P − c) at v̇ = 0
                    let ac = kin.point_bias(&(Some(*body), b.bodies[*body].com), &alpha, &acc);
                    let g = ac + alpha[*body].cross(&pc) + kin.omega[*body].cross(&pc_dot);
                    bias.extend(g.iter());
                }
                Effect::Inerter { a: pa, b: pb, b_in } => {
                    let (xa, va) = kin.point(pa);
                    let (xb, vb) = kin.point(pb);
                    let r = xb - xa;
                    let len = r.norm();
                    let rhat =
                        r.try_normalize(0.0).filter(|_| len > 1e-300).ok_or("inerter ends coincide")?;
                    let g = DVector::from_iterator(
                        nv,
                        unit.iter().map(|u| rhat.dot(&(u.point(pb).1 - u.point(pa).1))),
                    );
                    // ℓ̈ at v̇ = 0: r̂·r̈ + (|ṙ|² − (r̂·ṙ)²)/|r|
                    let rd = vb - va;
                    let rdd = kin.point_bias(pb, &alpha, &acc) - kin.point_bias(pa, &alpha, &acc);
                    let gdot_v = rhat.dot(&rdd) + (rd.norm_squared() - rhat.dot(&rd).powi(2)) / len;
                    inerters.push((g, gdot_v, *b_in));
                }
                _ => {}
            }
        }
        Ok(Rows { g, bias: DVector::from_vec(bias), inerters })
    }

    /// v̇ and λ with the inerters, rolling contacts and loops: [[M̃, Gᵀ], [G, 0]] [v̇; λ] =
    /// [M a − Σ b g ġv; −Ġv], M̃ = M + Σ b g gᵀ + rotational inerters. Rows that depend on
    /// others (a planar loop's out-of-plane rows) are dropped (λ = 0 there); `keep` caches the
    /// independent set between evaluations.
    pub(crate) fn constrained_solve(
        &self,
        kin: &Kin,
        q: &[f64],
        a_free: &[f64],
        keep: &mut Option<Vec<usize>>,
    ) -> Result<(DVector<f64>, DVector<f64>), String> {
        let b = &self.built;
        let m = b.model.crba(q).map_err(|e| e.to_string())?;
        let mut forcing = &m * DVector::from_column_slice(a_free);
        let mut m_tot = m;
        for e in &b.effects {
            if let Effect::RotInerter { dof, beta } = e {
                m_tot[(*dof, *dof)] += beta;
            }
        }
        let rows = self.constraint_rows(kin)?;
        for (g, gdot_v, b_in) in &rows.inerters {
            m_tot += g * g.transpose() * *b_in;
            forcing -= g * (b_in * gdot_v);
        }
        let gamma = -&rows.bias;
        let (x, lam) = solve_dropping(&m_tot, &rows.g, &forcing, &gamma, keep).map_err(|e| e.to_string())?;
        Ok((x, lam))
    }
}

/// The rows `rows` of G.
pub(crate) fn select(g: &DMatrix<f64>, rows: &[usize]) -> DMatrix<f64> {
    DMatrix::from_fn(rows.len(), g.ncols(), |r, c| g[(rows[r], c)])
}

/// The entries `rows` of x.
pub(crate) fn select_v(x: &DVector<f64>, rows: &[usize]) -> DVector<f64> {
    DVector::from_fn(rows.len(), |r, _| x[rows[r]])
}

/// `keep`, or the independent rows of `g` (see [`independent_rows`]) when `keep` is empty or
/// no longer independent; `keep` is updated.
pub(crate) fn rows_of(
    m: &DMatrix<f64>,
    g: &DMatrix<f64>,
    keep: &mut Option<Vec<usize>>,
) -> Result<Vec<usize>, DynamicsError> {
    if let Some(rows) = keep.as_ref()
        && rows.iter().all(|&r| r < g.nrows())
        && KktFactor::new(m, &select(g, rows), DEPENDENT_ROW_REL_TOL).is_ok()
    {
        return Ok(rows.clone());
    }
    let rows = independent_rows(m, g)?;
    *keep = Some(rows.clone());
    Ok(rows)
}

/// Solves the KKT system with the independent rows of G (cached in `keep`, see [`rows_of`]):
/// a row that depends on those kept is dropped. Returns v̇ and λ for every row (0 for dropped
/// ones).
pub(crate) fn solve_dropping(
    m: &DMatrix<f64>,
    g: &DMatrix<f64>,
    f: &DVector<f64>,
    gamma: &DVector<f64>,
    keep: &mut Option<Vec<usize>>,
) -> Result<(DVector<f64>, DVector<f64>), DynamicsError> {
    let rows = rows_of(m, g, keep)?;
    let s = KktFactor::new(m, &select(g, &rows), DEPENDENT_ROW_REL_TOL)?.solve(f, &select_v(gamma, &rows))?;
    let mut lam = DVector::zeros(g.nrows());
    for (k, &r) in rows.iter().enumerate() {
        lam[r] = s.lambda[k];
    }
    Ok((s.x, lam))
}

/// The rows of G kept, in order, when each row that depends on those before it (in the metric
/// of `m`) is dropped.
pub(crate) fn independent_rows(m: &DMatrix<f64>, g: &DMatrix<f64>) -> Result<Vec<usize>, DynamicsError> {
    let mut rows: Vec<usize> = Vec::new();
    for r in 0..g.nrows() {
        rows.push(r);
        match KktFactor::new(m, &select(g, &rows), DEPENDENT_ROW_REL_TOL) {
            Ok(_) => {}
            Err(DynamicsError::DependentConstraint { .. })
            | Err(DynamicsError::SingularConstraint { .. }) => {
                rows.pop();
            }
            Err(e) => return Err(e),
        }
    }
    Ok(rows)
}
