//! Problems of chapter 9: the theoretical problem of §9.15 and the applied problems of §9.16.
//!
//! Each system is written as the book describes it — kinetic energy from the positions and
//! velocities of its parts, potential energy of its springs and gravity, Rayleigh function of
//! its dashpots, generalized forces by (9.4.3) — and vectrix differentiates it with dual
//! numbers (`vectrix::dynamics::lagrange`). The references are the solutions printed in §9.17
//! (P9.16.1–8; corrected where they are wrong, with the reason), and for P9.16.9–12, which
//! print no solution, Newton–Euler equations written from free-body diagrams or closed forms
//! derived by hand. The figures are missing from the text; each problem states the geometry
//! it reads from the text and the printed solution, and `tests/textbook/missing.md` lists what
//! the figures leave open.

use std::f64::consts::{FRAC_PI_2, PI};

use proptest::prelude::*;
use vectrix::dynamics::lagrange::{accelerations, lagrange_terms, mass_matrix};
use vectrix::kinematics::{FrameLabel, FrameMotion, LabeledFrame, VectorJet};
use vectrix::nalgebra::{DMatrix, DVector, Matrix5, Vector5};
use vectrix::num_dual::Dual64;
use vectrix::prelude::*;
use vectrix::rotation::{Axis, orientation_about};

use super::systems::CART;
use crate::support::{EPS, NanAmax, nan_max};

/// Compares vectrix's Lagrange equations M q̈ = rhs (9.9.7) with printed equations e_i(q̈) = 0
/// that are Lagrange's equation i divided by `d[i]`. Each e_i is affine in q̈, so
/// d_i ∂e_i/∂q̈_j must equal M_ij and −d_i e_i(0) must equal rhs_i.
///
/// Tolerance: 64 ε times the size of the terms of equation i — Σ_j |M_ij|(1 + max|q̇|²) (the
/// velocity terms are sums of products ∂M/∂q q̇q̇ that cancel, of that order for these
/// trigonometric and polynomial systems) plus the magnitudes of ∂T/∂q, ∂U/∂q, ∂R/∂q̇ and Q:
/// each side rounds a few times per term.
fn agrees_with_printed<L: Lagrangian>(
    sys: &L,
    q: &[f64],
    qd: &[f64],
    t: f64,
    d: &[f64],
    printed: impl Fn(&[f64]) -> Vec<f64>,
) -> Result<(), String> {
    let terms = lagrange_terms(sys, q, qd, t).map_err(|e| e.to_string())?;
    let r = q.len();
    let rhs = terms.rhs();
    let zero = vec![0.0; r];
    let e0 = printed(&zero);
    let vmax = qd.iter().fold(0.0f64, |m, v| nan_max(m, v.abs()));
    for i in 0..r {
        let row = (0..r).map(|j| terms.mass[(i, j)].abs()).sum::<f64>();
        let scale = row * (1.0 + vmax * vmax)
            + terms.force[i].abs()
            + terms.dr_dqd[i].abs()
            + terms.du_dq[i].abs()
            + terms.dt_dq[i].abs()
            + terms.velocity_terms[i].abs();
        let tol = 64.0 * EPS * scale;
        let got = -d[i] * e0[i];
        if (got - rhs[i]).abs() > tol {
            return Err(format!("equation {i}: printed rhs {got:e} vs Lagrange {:e} (tol {tol:e})", rhs[i]));
        }
        for j in 0..r {
            let mut ej = zero.clone();
            ej[j] = 1.0;
            let mij = d[i] * (printed(&ej)[i] - e0[i]);
            if (mij - terms.mass[(i, j)]).abs() > tol {
                return Err(format!(
                    "equation {i}: printed coefficient of q̈{j} {mij:e} vs M = {:e} (tol {tol:e})",
                    terms.mass[(i, j)]
                ));
            }
        }
    }
    Ok(())
}

/// |got − want| ≤ tol (absolute).
#[track_caller]
pub fn assert_abs(got: f64, want: f64, tol: f64) {
    assert!(
        (got - want).abs() <= tol,
        "got {got:e}, want {want:e}, |err| = {:e} > {tol:e}",
        (got - want).abs()
    );
}

/// An angle biased toward the hard set of a coordinate: 0, tiny, and the ends of `range`.
fn angle_in(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => lo..hi,
        1 => prop::sample::select(vec![lo, hi, 0.5 * (lo + hi), lo + 1e-9, hi - 1e-9]),
    ]
}

/// A distance along a track, with the hard value 1e-7 (the particles nearly at a).
fn near_zero_distance() -> impl Strategy<Value = f64> {
    prop_oneof![4 => 0.01..3.0f64, 1 => Just(1e-7)]
}

/// A rate biased toward zero and large values.
fn rate() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -3.0..3.0f64,
        1 => prop::sample::select(vec![0.0, 1e-9, -1e-9, 40.0, -40.0]),
    ]
}

// ---------------------------------------------------------------------------------------------
// P9.15.1: the inerter.

/// A base system (the cart with eccentric pendulum of Ex 9.10.3) plus inerters with
/// generalized force Q_inert = −Bq̈, written as the problem's claim: T = ½q̇ᵀ(M + B)q̇.
struct WithInerter {
    b: [[f64; 2]; 2],
}

impl Lagrangian for WithInerter {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], t: T) -> T {
        let mut inert = T::zero();
        for i in 0..2 {
            for j in 0..2 {
                inert += T::lit(0.5 * self.b[i][j]) * qd[i] * qd[j];
            }
        }
        Lagrangian::kinetic(&CART, q, qd, t) + inert
    }
    fn potential<T: Scalar>(&self, q: &[T], t: T) -> T {
        Lagrangian::potential(&CART, q, t)
    }
}

/// P9.15.1: "for inerters with generalized force Q_inert = −Bq̈ (B ⪰ 0) and inertance function
/// I(q̈) = ½q̈ᵀBq̈, the kinetic energy of the body with the inerter is ½q̇ᵀ[M(q) + B]q̇."
/// Lagrange's equations of T + ½q̇ᵀBq̇ are those of T with the force −Bq̈ = −∂I/∂q̈ added.
#[test]
fn problem_9_15_1_inerter_adds_b_to_the_mass_matrix() {
    let b = [[0.7, -0.2], [-0.2, 0.3]];
    let (q, qd) = ([0.1, 0.7], [0.3, -0.4]);
    let with = WithInerter { b };
    let m = mass_matrix(&CART, &q, &qd, 0.0).unwrap();
    let m_b = mass_matrix(&with, &q, &qd, 0.0).unwrap();
    for i in 0..2 {
        for j in 0..2 {
            // M is computed to a few ulps of its entries (≈ 1)
            assert_abs(m_b[(i, j)], m[(i, j)] + b[i][j], 8.0 * EPS);
        }
    }
    // q̈ of the inerter system solves the base equations with Q = −Bq̈: M q̈ = rhs − Bq̈
    let qdd = accelerations(&with, &q, &qd, 0.0).unwrap();
    let base = lagrange_terms(&CART, &q, &qd, 0.0).unwrap();
    let bq = DMatrix::from_fn(2, 2, |i, j| b[i][j]) * &qdd;
    let resid = &base.mass * &qdd - (base.rhs() - &bq);
    // residual of a 2×2 Cholesky solve with κ(M + B) < 10, |q̈| ≈ 10
    assert!(resid.nan_amax() <= 64.0 * EPS * 10.0, "residual {resid}");
    // Q_inert = −∂I/∂q̈ (dual numbers on q̈)
    let qdd_v = [qdd[0], qdd[1]];
    for k in 0..2 {
        let x: Vec<Dual64> = (0..2).map(|i| Dual64::new(qdd_v[i], f64::from(i == k))).collect();
        let mut inert = Dual64::from(0.0);
        for i in 0..2 {
            for j in 0..2 {
                inert += x[i] * x[j] * (0.5 * b[i][j]);
            }
        }
        assert_abs(-inert.eps, -bq[k], 8.0 * EPS * 10.0);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// P9.15.1 at random B = LLᵀ ⪰ 0 (rank 0, 1 or 2) and states.
    #[test]
    fn problem_9_15_1_inerter_random(
        l in [-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64],
        rank in 0usize..3,
        q in [-1.0..1.0f64, -3.0..3.0f64],
        qd in [-2.0..2.0f64, -2.0..2.0f64],
    ) {
        let (l11, l21, l22) = (l[0], l[1], if rank == 2 { l[2] } else { 0.0 });
        let (l11, l21) = if rank == 0 { (0.0, 0.0) } else { (l11, l21) };
        let b = [[l11 * l11, l11 * l21], [l11 * l21, l21 * l21 + l22 * l22]];
        let with = WithInerter { b };
        let m = mass_matrix(&CART, &q, &qd, 0.0).unwrap();
        let m_b = mass_matrix(&with, &q, &qd, 0.0).unwrap();
        for i in 0..2 {
            for j in 0..2 {
                prop_assert!((m_b[(i, j)] - m[(i, j)] - b[i][j]).abs() <= 16.0 * EPS * (1.0 + m[(i, j)].abs() + b[i][j].abs()));
            }
        }
        let rhs = lagrange_terms(&with, &q, &qd, 0.0).unwrap().rhs();
        let base = lagrange_terms(&CART, &q, &qd, 0.0).unwrap().rhs();
        // the inerter adds no velocity terms (B is constant)
        for i in 0..2 {
            prop_assert!((rhs[i] - base[i]).abs() <= 16.0 * EPS * (1.0 + base[i].abs()));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// P9.16.1: two particles on orthogonal tracks.

/// P9.16.1: m1 on track î at distance q1 from a, m2 on track ĵ at distance q2; springs k1, k2
/// from a (relaxed r1, r2); spring k (relaxed r) and dashpot c between the particles.
#[derive(Clone, Copy, Debug)]
struct TwoTracks {
    m1: f64,
    m2: f64,
    k1: f64,
    k2: f64,
    k: f64,
    c: f64,
    r1: f64,
    r2: f64,
    r: f64,
}

impl Lagrangian for TwoTracks {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, _q: &[T], qd: &[T], _t: T) -> T {
        T::lit(0.5 * self.m1) * qd[0] * qd[0] + T::lit(0.5 * self.m2) * qd[1] * qd[1]
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        let l = (q[0] * q[0] + q[1] * q[1]).sqrt();
        let s1 = q[0] - T::lit(self.r1);
        let s2 = q[1] - T::lit(self.r2);
        let s = l - T::lit(self.r);
        T::lit(0.5) * (T::lit(self.k1) * s1 * s1 + T::lit(self.k2) * s2 * s2 + T::lit(self.k) * s * s)
    }
    fn rayleigh<T: Scalar>(&self, q: &[T], qd: &[T]) -> T {
        // R = ½c(d|r|/dt)² (9.9.6)
        let l = (q[0] * q[0] + q[1] * q[1]).sqrt();
        let l_dot = (q[0] * qd[0] + q[1] * qd[1]) / l;
        T::lit(0.5 * self.c) * l_dot * l_dot
    }
}

/// The printed solution of P9.16.1 (§9.17): residuals of
/// m1q̈1 + (c/l²)(q1²q̇1 + q1q2q̇2) + k1(q1 − r1) + (k/l)(l − r)q1 = 0 and the same with 1 ↔ 2.
fn p9_16_1_printed(s: &TwoTracks, q: &[f64], qd: &[f64], qdd: &[f64]) -> Vec<f64> {
    let l = q[0].hypot(q[1]);
    vec![
        s.m1 * qdd[0]
            + s.c / (l * l) * (q[0] * q[0] * qd[0] + q[0] * q[1] * qd[1])
            + s.k1 * (q[0] - s.r1)
            + s.k / l * (l - s.r) * q[0],
        s.m2 * qdd[1]
            + s.c / (l * l) * (q[1] * q[1] * qd[1] + q[0] * q[1] * qd[0])
            + s.k2 * (q[1] - s.r2)
            + s.k / l * (l - s.r) * q[1],
    ]
}

/// Newton's second law along each track with frame-free forces: the spring and dashpot between
/// the particles act along their line n̂, f = −(k(l − r) + c l̇)n̂ on m1 (and −f on m2).
fn p9_16_1_newton(s: &TwoTracks, q: &[f64], qd: &[f64]) -> [f64; 2] {
    let a = Frame::new();
    let (r1, r2) = (a.vector([q[0], 0.0, 0.0]), a.vector([0.0, q[1], 0.0]));
    let (v1, v2) = (a.vector([qd[0], 0.0, 0.0]), a.vector([0.0, qd[1], 0.0]));
    let d = r1 - r2;
    let l = d.norm();
    let n = d.unit().expect("distinct particles");
    let l_dot = n.dot(&(v1 - v2));
    let f = n * (-(s.k * (l - s.r) + s.c * l_dot));
    let f1 = f + a.i() * (-s.k1 * (q[0] - s.r1));
    let f2 = -f + a.j() * (-s.k2 * (q[1] - s.r2));
    [f1.dot(&a.i()) / s.m1, f2.dot(&a.j()) / s.m2]
}

const TRACKS: TwoTracks =
    TwoTracks { m1: 1.5, m2: 0.8, k1: 20.0, k2: 12.0, k: 30.0, c: 0.6, r1: 1.0, r2: 0.7, r: 1.1 };

/// P9.16.1: "derive the equations of motion, and then specialize these equations to the case
/// where m2 is fixed at a." Printed: m1q̈1 + (c/l²)(q1²q̇1 + q1q2q̇2) + k1(q1 − r1) +
/// (k/l)(l − r)q1 = 0 and the same with 1 ↔ 2, l = √(q1² + q2²). With m2 fixed at a
/// (q2 = q̇2 = 0, q1 > 0): m1q̈1 + cq̇1 + k1(q1 − r1) + k(q1 − r) = 0.
#[test]
fn problem_9_16_1_two_particles_on_orthogonal_tracks() {
    let s = TRACKS;
    let (q, qd) = ([0.9, 0.6], [0.4, -1.2]);
    agrees_with_printed(&s, &q, &qd, 0.0, &[1.0, 1.0], |qdd| p9_16_1_printed(&s, &q, &qd, qdd)).unwrap();
    let qdd = accelerations(&s, &q, &qd, 0.0).unwrap();
    let newton = p9_16_1_newton(&s, &q, &qd);
    for i in 0..2 {
        // accelerations of size ≈ 10, diagonal M: a few roundings
        assert_abs(qdd[i], newton[i], 64.0 * EPS * 10.0);
    }
    // m2 fixed at a: the first equation alone, with l = q1
    let (q1, q1d) = (0.9, 0.4);
    let qdd = accelerations(&s, &[q1, 0.0], &[q1d, 0.0], 0.0).unwrap();
    let want = -(s.c * q1d + s.k1 * (q1 - s.r1) + s.k * (q1 - s.r)) / s.m1;
    assert_abs(qdd[0], want, 64.0 * EPS * 10.0);
}

/// P9.16.1 when the particles meet at a (l = 0): the direction of the spring between them is
/// undefined, and vectrix reports a non-finite derivative instead of returning NaN.
#[test]
fn problem_9_16_1_coincident_particles_are_a_typed_error() {
    let err = accelerations(&TRACKS, &[0.0, 0.0], &[0.3, 0.2], 0.0).unwrap_err();
    assert!(matches!(err, DynamicsError::NonFinite { .. }), "{err}");
}

// ---------------------------------------------------------------------------------------------
// P9.16.2: rectangular body and thin bar.

/// P9.16.2: the block M at horizontal position x (dashpot c, force f along x); the bar (m, l)
/// hinged by a pin sliding in the block's vertical track, its foot on the floor, at angle θ to
/// the floor, its centre at (x + ½l cos θ, ½l sin θ); a spring k (relaxed r) along the track
/// from the floor to the pin, of length l sin θ. (The figure is missing; these placements are
/// the ones the printed solution implies.)
#[derive(Clone, Copy, Debug)]
struct BlockBar {
    big_m: f64,
    m: f64,
    l: f64,
    k: f64,
    r: f64,
    c: f64,
    g: f64,
    f: f64,
}

impl Lagrangian for BlockBar {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        // block ½Mẋ², bar ½m|v_c|² + ½(ml²/12)θ̇² (thin bar about its centre)
        let (xd, th, thd) = (qd[0], q[1], qd[1]);
        let h = T::lit(0.5 * self.l);
        let (vx, vy) = (xd - h * th.sin() * thd, h * th.cos() * thd);
        T::lit(0.5 * self.big_m) * xd * xd
            + T::lit(0.5 * self.m) * (vx * vx + vy * vy)
            + T::lit(0.5 * self.m * self.l * self.l / 12.0) * thd * thd
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        let s = T::lit(self.l) * q[1].sin() - T::lit(self.r);
        T::lit(self.m * self.g * 0.5 * self.l) * q[1].sin() + T::lit(0.5 * self.k) * s * s
    }
    fn rayleigh<T: Scalar>(&self, _q: &[T], qd: &[T]) -> T {
        T::lit(0.5 * self.c) * qd[0] * qd[0]
    }
    fn generalized_force(&self, _q: &[f64], _qd: &[f64], _t: f64, out: &mut [f64]) {
        out[0] += self.f;
    }
}

/// The solution of P9.16.2 in §9.17 with the coefficient of θ̈ corrected from ½ml to ⅓ml:
/// (m + M)ẍ + cẋ − ½ml(cos θ θ̇² + sin θ θ̈) = f,
/// κ ml θ̈ − ½m sin θ ẍ + ½mg cos θ + k cos θ (l sin θ − r) = 0 (the θ equation divided by l).
fn p9_16_2_printed(s: &BlockBar, kappa: f64, q: &[f64], qd: &[f64], qdd: &[f64]) -> Vec<f64> {
    let (th, thd) = (q[1], qd[1]);
    vec![
        (s.m + s.big_m) * qdd[0] + s.c * qd[0]
            - 0.5 * s.m * s.l * (th.cos() * thd * thd + th.sin() * qdd[1])
            - s.f,
        kappa * s.m * s.l * qdd[1] - 0.5 * s.m * th.sin() * qdd[0]
            + 0.5 * s.m * s.g * th.cos()
            + s.k * th.cos() * (s.l * th.sin() - s.r),
    ]
}

const BLOCK_BAR: BlockBar = BlockBar { big_m: 4.0, m: 1.2, l: 0.9, k: 25.0, r: 0.5, c: 0.7, g: 9.8, f: 2.5 };

/// P9.16.2. Printed (§9.17): (m + M)ẍ + cẋ − ½ml[cos θ θ̇² + sin θ θ̈] = f and
/// ½mlθ̈ − ½m sin θ ẍ + ½mg cos θ + k cos θ (l sin θ − r) = 0. Erratum: the θ̈ coefficient must
/// be ⅓ml — the bar's kinetic energy ½m|v_c|² + ½(ml²/12)θ̇² contributes (¼ + 1/12)ml² = ⅓ml²
/// to M_θθ (divided by l in the printed equation); no reading of the bar gives ½. Every other
/// term of the printed solution is right. (Correction derived here; not in the notes.)
#[test]
fn problem_9_16_2_block_and_bar_corrected() {
    let s = BLOCK_BAR;
    let (q, qd) = ([0.3, 0.8], [-0.5, 1.3]);
    agrees_with_printed(&s, &q, &qd, 0.0, &[1.0, s.l], |qdd| p9_16_2_printed(&s, 1.0 / 3.0, &q, &qd, qdd))
        .unwrap();
    // the printed ½ml disagrees by (½ − ⅓)ml² in M_θθ
    let err =
        agrees_with_printed(&s, &q, &qd, 0.0, &[1.0, s.l], |qdd| p9_16_2_printed(&s, 0.5, &q, &qd, qdd))
            .unwrap_err();
    assert!(err.contains("q̈1"), "{err}");
    let m = mass_matrix(&s, &q, &qd, 0.0).unwrap();
    assert_abs(m[(1, 1)], s.m * s.l * s.l / 3.0, 8.0 * EPS);
}

// ---------------------------------------------------------------------------------------------
// P9.16.3: triangular cart with a particle on its slope.

/// P9.16.3: cart m1 at q1 (spring k1 to the wall); particle m2 at distance q2 down the slope
/// (angle θ) from the cart's vertical edge, at (q1 + q2 cos θ, −q2 sin θ); spring k2 along the
/// slope; both springs relaxed at zero length; gravity −ĵ.
#[derive(Clone, Copy, Debug)]
struct WedgeCart {
    m1: f64,
    m2: f64,
    k1: f64,
    k2: f64,
    theta: f64,
    g: f64,
}

impl Lagrangian for WedgeCart {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, _q: &[T], qd: &[T], _t: T) -> T {
        let (s, c) = self.theta.sin_cos();
        let (vx, vy) = (qd[0] + qd[1] * T::lit(c), -qd[1] * T::lit(s));
        T::lit(0.5 * self.m1) * qd[0] * qd[0] + T::lit(0.5 * self.m2) * (vx * vx + vy * vy)
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        let height = -q[1] * T::lit(self.theta.sin());
        T::lit(0.5 * self.k1) * q[0] * q[0]
            + T::lit(0.5 * self.k2) * q[1] * q[1]
            + T::lit(self.m2 * self.g) * height
    }
}

/// P9.16.3: "(m1 + m2)q̈1 + m2 cos θ q̈2 + k1q1 = 0, m2[q̈2 + cos θ q̈1] + k2q2 = m2 g sin θ."
#[test]
fn problem_9_16_3_wedge_cart_and_particle() {
    let s = WedgeCart { m1: 3.0, m2: 0.7, k1: 15.0, k2: 9.0, theta: 0.6, g: 9.8 };
    let printed = |q: &[f64], qdd: &[f64]| {
        let (sn, cs) = s.theta.sin_cos();
        vec![
            (s.m1 + s.m2) * qdd[0] + s.m2 * cs * qdd[1] + s.k1 * q[0],
            s.m2 * (qdd[1] + cs * qdd[0]) + s.k2 * q[1] - s.m2 * s.g * sn,
        ]
    };
    for (q, qd) in [([0.2, 0.5], [0.1, -0.3]), ([-0.4, 1.5], [2.0, 0.0]), ([0.0, 0.0], [0.0, 0.0])] {
        agrees_with_printed(&s, &q, &qd, 0.0, &[1.0, 1.0], |qdd| printed(&q, qdd)).unwrap();
    }
}

// ---------------------------------------------------------------------------------------------
// P9.16.4: two particles on a bar turned by a prescribed angle θ(t).

/// P9.16.4: particles m at distances q1 and q1 + q2 from the pin along a bar whose angle θ(t)
/// from the downward vertical is prescribed; spring k (relaxed l) from the pin to the first
/// particle and another between the particles; gravity downward.
#[derive(Clone, Copy, Debug)]
struct TurnedBar {
    m: f64,
    k: f64,
    l: f64,
    g: f64,
    // θ(t) = θ0 + θ1 sin(νt)
    th0: f64,
    th1: f64,
    nu: f64,
}

impl TurnedBar {
    fn theta<T: Scalar>(&self, t: T) -> T {
        T::lit(self.th0) + T::lit(self.th1) * (T::lit(self.nu) * t).sin()
    }
    fn theta_dot<T: Scalar>(&self, t: T) -> T {
        T::lit(self.th1 * self.nu) * (T::lit(self.nu) * t).cos()
    }
}

impl Lagrangian for TurnedBar {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], t: T) -> T {
        // a particle at distance s on a line turning at θ̇: |v|² = ṡ² + s²θ̇²
        let w = self.theta_dot(t);
        let (s1, s2) = (q[0], q[0] + q[1]);
        let (v1, v2) = (qd[0], qd[0] + qd[1]);
        T::lit(0.5 * self.m) * (v1 * v1 + s1 * s1 * w * w + v2 * v2 + s2 * s2 * w * w)
    }
    fn potential<T: Scalar>(&self, q: &[T], t: T) -> T {
        let th = self.theta(t);
        let (e1, e2) = (q[0] - T::lit(self.l), q[1] - T::lit(self.l));
        // heights −s cos θ below the pin
        T::lit(0.5 * self.k) * (e1 * e1 + e2 * e2) - T::lit(self.m * self.g) * th.cos() * (q[0] + q[0] + q[1])
    }
}

fn p9_16_4_printed(s: &TurnedBar, q: &[f64], t: f64, qdd: &[f64]) -> Vec<f64> {
    let (th, w) = (s.theta(t), s.theta_dot(t));
    let km = s.k / s.m;
    vec![
        2.0 * qdd[0] + qdd[1] - (2.0 * q[0] + q[1]) * w * w + km * (q[0] - s.l) - 2.0 * s.g * th.cos(),
        qdd[0] + qdd[1] - (q[0] + q[1]) * w * w + km * (q[1] - s.l) - s.g * th.cos(),
    ]
}

/// P9.16.4: "2q̈1 + q̈2 − (2q1 + q2)θ̇² + (k/m)(q1 − l) = 2g cos θ,
/// q̈1 + q̈2 − (q1 + q2)θ̇² + (k/m)(q2 − l) = g cos θ" (both divided by m), with θ(t)
/// prescribed: T and U depend on t explicitly.
#[test]
fn problem_9_16_4_particles_on_a_turned_bar() {
    let s = TurnedBar { m: 0.9, k: 14.0, l: 0.4, g: 9.8, th0: 0.3, th1: 1.1, nu: 1.7 };
    for (q, qd, t) in
        [([0.5, 0.45], [0.2, -0.1], 0.0), ([0.3, 0.9], [-1.0, 0.6], 2.3), ([0.4, 0.4], [0.0, 0.0], 0.9)]
    {
        agrees_with_printed(&s, &q, &qd, t, &[s.m, s.m], |qdd| p9_16_4_printed(&s, &q, t, qdd)).unwrap();
    }
}

// ---------------------------------------------------------------------------------------------
// P9.16.5: spherical pendulum with a rope of prescribed length l(t).

/// P9.16.5: the particle at l(t)(sin φ cos θ, sin φ sin θ, −cos φ) from the top of the bar
/// (φ from the downward bar, θ around it), q = (φ, θ) in the order of the printed equations.
#[derive(Clone, Copy, Debug)]
struct ReelPendulum {
    m: f64,
    g: f64,
    // l(t) = l0 + l1 sin(νt)
    l0: f64,
    l1: f64,
    nu: f64,
}

impl ReelPendulum {
    fn l<T: Scalar>(&self, t: T) -> T {
        T::lit(self.l0) + T::lit(self.l1) * (T::lit(self.nu) * t).sin()
    }
    fn l_dot<T: Scalar>(&self, t: T) -> T {
        T::lit(self.l1 * self.nu) * (T::lit(self.nu) * t).cos()
    }
}

impl Lagrangian for ReelPendulum {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], t: T) -> T {
        let (l, ld) = (self.l(t), self.l_dot(t));
        let s = q[0].sin();
        T::lit(0.5 * self.m) * (ld * ld + l * l * qd[0] * qd[0] + l * l * s * s * qd[1] * qd[1])
    }
    fn potential<T: Scalar>(&self, q: &[T], t: T) -> T {
        -T::lit(self.m * self.g) * self.l(t) * q[0].cos()
    }
}

/// The printed solution of P9.16.5, reading the OCR's "2ll φ̇" as 2l l̇ φ̇ (notes) and
/// "2l sin φ" in the θ equation as 2l̇ sin φ (the dot was lost the same way):
/// l²φ̈ + 2l l̇ φ̇ − l²θ̇² sin φ cos φ + gl sin φ = 0 (divided by m),
/// l sin φ θ̈ + [2l̇ sin φ + 2l cos φ φ̇]θ̇ = 0 (divided by m l sin φ).
fn p9_16_5_printed(s: &ReelPendulum, q: &[f64], qd: &[f64], t: f64, qdd: &[f64]) -> Vec<f64> {
    let (l, ld) = (s.l(t), s.l_dot(t));
    let (sp, cp) = q[0].sin_cos();
    vec![
        l * l * qdd[0] + 2.0 * l * ld * qd[0] - l * l * qd[1] * qd[1] * sp * cp + s.g * l * sp,
        l * sp * qdd[1] + (2.0 * ld * sp + 2.0 * l * cp * qd[0]) * qd[1],
    ]
}

#[test]
fn problem_9_16_5_spherical_pendulum_with_reeled_rope() {
    let s = ReelPendulum { m: 0.6, g: 9.8, l0: 1.2, l1: 0.5, nu: 0.8 };
    for (q, qd, t) in
        [([0.7f64, 0.2], [0.3, 1.1], 0.4f64), ([2.5, -1.0], [-0.8, 0.2], 3.0), ([0.1, 3.0], [0.0, 2.0], 1.0)]
    {
        let d = [s.m, s.m * s.l::<f64>(t) * q[0].sin()];
        agrees_with_printed(&s, &q, &qd, t, &d, |qdd| p9_16_5_printed(&s, &q, &qd, t, qdd)).unwrap();
    }
}

/// P9.16.5 hanging straight down (φ = 0): θ is then no coordinate at all (M_θθ = ml² sin²φ = 0)
/// and vectrix refuses with a typed error rather than dividing by zero.
#[test]
fn problem_9_16_5_hanging_straight_down_is_singular() {
    let s = ReelPendulum { m: 0.6, g: 9.8, l0: 1.2, l1: 0.5, nu: 0.8 };
    let err = accelerations(&s, &[0.0, 0.3], &[0.2, 0.5], 0.0).unwrap_err();
    assert!(matches!(err, DynamicsError::SingularMassMatrix { .. }), "{err}");
}

// ---------------------------------------------------------------------------------------------
// P9.16.6: two-link pendulum with a follower force at the tip.

/// P9.16.6: link 1 (m1, l1, inertia J1 about the pin a) at angle θ1 from the downward vertical,
/// link 2 (m2, l2, inertia J2 about the pin b) at θ2 relative to link 1, centres of mass at
/// the links' midpoints; a force of magnitude f at the tip c perpendicular to link 2.
#[derive(Clone, Copy, Debug)]
struct TwoLink {
    m1: f64,
    m2: f64,
    l1: f64,
    l2: f64,
    j1: f64,
    j2: f64,
    g: f64,
    f: f64,
}

/// e(φ) = (sin φ, −cos φ): the unit vector at angle φ from the downward vertical.
fn down_at<T: Scalar>(a: &Frame<T>, phi: T) -> Vector<T> {
    a.vector([phi.sin(), -phi.cos(), T::zero()])
}

impl Lagrangian for TwoLink {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        // link 1 turns about the fixed pin a: ½J1θ̇1²; link 2: ½m2|v_c2|² + ½J_c2 ω2² with
        // J_c2 = J2 − m2(l2/2)² (parallel axes) and ω2 = θ̇1 + θ̇2
        let a = Frame::<T>::identity();
        let (t1, t12) = (q[0], q[0] + q[1]);
        let (w1, w12) = (qd[0], qd[0] + qd[1]);
        // v_c2 = l1 θ̇1 e′(θ1) + ½l2 (θ̇1 + θ̇2) e′(θ1 + θ2), e′(φ) = (cos φ, sin φ)
        let v = a.vector([t1.cos(), t1.sin(), T::zero()]) * (T::lit(self.l1) * w1)
            + a.vector([t12.cos(), t12.sin(), T::zero()]) * (T::lit(0.5 * self.l2) * w12);
        let jc2 = self.j2 - self.m2 * 0.25 * self.l2 * self.l2;
        T::lit(0.5 * self.j1) * w1 * w1
            + T::lit(0.5 * self.m2) * v.norm_squared()
            + T::lit(0.5 * jc2) * w12 * w12
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        let a = Frame::<T>::identity();
        let up = a.j();
        let c1 = down_at(&a, q[0]) * T::lit(0.5 * self.l1);
        let c2 = down_at(&a, q[0]) * T::lit(self.l1) + down_at(&a, q[0] + q[1]) * T::lit(0.5 * self.l2);
        T::lit(self.g) * (T::lit(self.m1) * c1.dot(&up) + T::lit(self.m2) * c2.dot(&up))
    }
    fn generalized_force(&self, q: &[f64], _qd: &[f64], _t: f64, out: &mut [f64]) {
        // (9.4.3): Q_j = f⃗ · ∂r⃗_c/∂q_j, the tip r_c = l1 e(θ1) + l2 e(θ1 + θ2), dual numbers
        let a = Frame::<f64>::identity();
        let t12 = q[0] + q[1];
        let force = a.vector([t12.cos(), t12.sin(), 0.0]) * self.f;
        for (j, o) in out.iter_mut().enumerate() {
            let qj: Vec<Dual64> = (0..2).map(|k| Dual64::new(q[k], f64::from(k == j))).collect();
            let ad = Frame::<Dual64>::identity();
            let tip = down_at(&ad, qj[0]) * Dual64::from(self.l1)
                + down_at(&ad, qj[0] + qj[1]) * Dual64::from(self.l2);
            let d = tip.resolve(&ad).map(|x| x.eps);
            *o += force.dot(&a.vector([d[0], d[1], d[2]]));
        }
    }
}

/// P9.16.6 printed: βθ̈1 + αθ̈2 − ½m2l1l2 sin θ2 θ̇2(2θ̇1 + θ̇2) + (½m1 + m2)gl1 sin θ1 + γ =
/// f(l1 cos θ2 + l2), αθ̈1 + J2θ̈2 + ½m2l1l2 sin θ2 θ̇1² + γ = fl2, with α = J2 + ½m2l1l2 cos θ2,
/// β = J1 + J2 + m2l1² + m2l1l2 cos θ2, γ = ½m2gl2 sin(θ1 + θ2).
fn p9_16_6_printed(s: &TwoLink, q: &[f64], qd: &[f64], qdd: &[f64]) -> Vec<f64> {
    let (t1, t2) = (q[0], q[1]);
    let h = 0.5 * s.m2 * s.l1 * s.l2;
    let alpha = s.j2 + h * t2.cos();
    let beta = s.j1 + s.j2 + s.m2 * s.l1 * s.l1 + s.m2 * s.l1 * s.l2 * t2.cos();
    let gamma = 0.5 * s.m2 * s.g * s.l2 * (t1 + t2).sin();
    vec![
        beta * qdd[0] + alpha * qdd[1] - h * t2.sin() * qd[1] * (2.0 * qd[0] + qd[1])
            + (0.5 * s.m1 + s.m2) * s.g * s.l1 * t1.sin()
            + gamma
            - s.f * (t2.cos() * s.l1 + s.l2),
        alpha * qdd[0] + s.j2 * qdd[1] + h * t2.sin() * qd[0] * qd[0] + gamma - s.f * s.l2,
    ]
}

#[test]
fn problem_9_16_6_two_link_pendulum_with_tip_force() {
    // uniform links: J about an end is ml²/3
    let s = TwoLink {
        m1: 1.0,
        m2: 0.6,
        l1: 0.8,
        l2: 0.5,
        j1: 0.8 * 0.64 / 3.0,
        j2: 0.6 * 0.25 / 3.0,
        g: 9.8,
        f: 1.3,
    };
    for (q, qd) in [([0.4, -0.9], [1.0, 0.5]), ([PI, 0.0], [0.0, 0.0]), ([-2.0, 2.9], [-3.0, 4.0])] {
        agrees_with_printed(&s, &q, &qd, 0.0, &[1.0, 1.0], |qdd| p9_16_6_printed(&s, &q, &qd, qdd)).unwrap();
    }
}

// ---------------------------------------------------------------------------------------------
// P9.16.7: rotating disk with a particle in a slot.

/// P9.16.7: disk (J_D about a) at angle θ; the particle at r⃗ = h ê_r(θ) − x ê_θ(θ), x measured
/// from b along the slot against the sense of θ (the sign the printed −mhẍ implies); two
/// springs k, relaxed at b; moment τ on the disk.
#[derive(Clone, Copy, Debug)]
struct SlotDisk {
    jd: f64,
    m: f64,
    h: f64,
    k: f64,
    tau: f64,
}

impl Lagrangian for SlotDisk {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        // r⃗ = (h cos θ + x sin θ, h sin θ − x cos θ): differentiate by hand along (θ̇, ẋ)
        let (th, x, thd, xd) = (q[0], q[1], qd[0], qd[1]);
        let h = T::lit(self.h);
        let vx = -h * th.sin() * thd + xd * th.sin() + x * th.cos() * thd;
        let vy = h * th.cos() * thd - xd * th.cos() + x * th.sin() * thd;
        T::lit(0.5 * self.jd) * thd * thd + T::lit(0.5 * self.m) * (vx * vx + vy * vy)
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        // two springs k, both relaxed at b: U = 2·½kx²
        T::lit(self.k) * q[1] * q[1]
    }
    fn generalized_force(&self, _q: &[f64], _qd: &[f64], _t: f64, out: &mut [f64]) {
        out[0] += self.tau;
    }
}

/// P9.16.7: "(J_D + mh² + mx²)θ̈ + 2mxẋθ̇ − mhẍ = τ, ẍ − hθ̈ − xθ̇² + (2k/m)x = 0."
#[test]
fn problem_9_16_7_rotating_disk_with_slot() {
    let s = SlotDisk { jd: 2.0, m: 0.4, h: 0.6, k: 7.0, tau: 0.9 };
    let printed = |q: &[f64], qd: &[f64], qdd: &[f64]| {
        let (x, thd, xd) = (q[1], qd[0], qd[1]);
        vec![
            (s.jd + s.m * s.h * s.h + s.m * x * x) * qdd[0] + 2.0 * s.m * x * xd * thd
                - s.m * s.h * qdd[1]
                - s.tau,
            qdd[1] - s.h * qdd[0] - x * thd * thd + 2.0 * s.k / s.m * x,
        ]
    };
    for (q, qd) in [([0.3, 0.2], [1.5, -0.4]), ([-2.0, -0.5], [0.0, 3.0]), ([1.0, 0.0], [0.0, 0.0])] {
        agrees_with_printed(&s, &q, &qd, 0.0, &[1.0, s.m], |qdd| printed(&q, &qd, qdd)).unwrap();
    }
}

// ---------------------------------------------------------------------------------------------
// P9.16.8: two-bar linkage with a slider.

/// P9.16.8: bars a–b and b–c of length l at ±θ to the line ac (a at the origin, ac along î,
/// b above it), gravity −ĵ ⟂ ac; centres d and e at the midpoints, spring k (relaxed l/2)
/// between d and e; particle m3 at c on a horizontal slider; force f at e along gravity;
/// moment M on bar 1 at a (counter-clockwise, the sense of θ).
#[derive(Clone, Copy, Debug)]
struct Linkage {
    m1: f64,
    m2: f64,
    m3: f64,
    l: f64,
    k: f64,
    g: f64,
    f: f64,
    moment: f64,
}

impl Linkage {
    /// d, e, c as vectors (generic, for dual numbers).
    fn points<T: Scalar>(&self, th: T) -> [Vector<T>; 3] {
        let a = Frame::<T>::identity();
        let l = T::lit(self.l);
        let (s, c) = (th.sin(), th.cos());
        let half = T::lit(0.5);
        [
            a.vector([half * l * c, half * l * s, T::zero()]),
            a.vector([T::lit(1.5) * l * c, half * l * s, T::zero()]),
            a.vector([T::lit(2.0) * l * c, T::zero(), T::zero()]),
        ]
    }
}

impl Lagrangian for Linkage {
    fn dof(&self) -> usize {
        1
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        // velocities of e and c by a dual number in θ; bar 1 turns about a (J = ml²/3), bar 2
        // turns at −θ̇ about its centre (J = ml²/12)
        let th = q[0];
        let (s, c) = (th.sin(), th.cos());
        let l = T::lit(self.l);
        let w = qd[0];
        let (vex, vey) = (-T::lit(1.5) * l * s * w, T::lit(0.5) * l * c * w);
        let vcx = -T::lit(2.0) * l * s * w;
        let ll = self.l * self.l;
        T::lit(0.5 * self.m1 * ll / 3.0) * w * w
            + T::lit(0.5 * self.m2) * (vex * vex + vey * vey)
            + T::lit(0.5 * self.m2 * ll / 12.0) * w * w
            + T::lit(0.5 * self.m3) * vcx * vcx
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        let [d, e, _] = self.points(q[0]);
        let up = Frame::<T>::identity().j();
        let stretch = (e - d).norm() - T::lit(0.5 * self.l);
        T::lit(self.g) * (T::lit(self.m1) * d.dot(&up) + T::lit(self.m2) * e.dot(&up))
            + T::lit(0.5 * self.k) * stretch * stretch
    }
    fn generalized_force(&self, q: &[f64], _qd: &[f64], _t: f64, out: &mut [f64]) {
        // (9.5.2) for M on bar 1 (ω1 = θ̇k̂) and (9.4.3) for f⃗ = −f ĵ at e
        let [_, e, _] = self.points(Dual64::new(q[0], 1.0));
        let a = Frame::<Dual64>::identity();
        let de = e.resolve(&a).map(|x| x.eps);
        out[0] += self.moment + (-self.f) * de[1];
    }
}

/// P9.16.8 printed: ⅓(m1 + m2)l²θ̈ + (2m2 + 4m3)l² sin θ(sin θ θ̈ + cos θ θ̇²)
/// + kl² sin θ(½ − cos θ) + ½(m1 + m2)gl cos θ = M − ½fl cos θ.
fn p9_16_8_printed(s: &Linkage, q: &[f64], qd: &[f64], qdd: &[f64]) -> Vec<f64> {
    let (sn, cs) = q[0].sin_cos();
    let ll = s.l * s.l;
    vec![
        (s.m1 + s.m2) * ll / 3.0 * qdd[0]
            + (2.0 * s.m2 + 4.0 * s.m3) * ll * sn * (sn * qdd[0] + cs * qd[0] * qd[0])
            + s.k * ll * sn * (0.5 - cs)
            + 0.5 * (s.m1 + s.m2) * s.g * s.l * cs
            - s.moment
            + 0.5 * s.f * s.l * cs,
    ]
}

/// P9.16.8 at bars nearly flat (θ = 1e-6) and nearly upright (d and e nearly meet).
#[test]
fn problem_9_16_8_two_bar_linkage_with_slider() {
    let s = Linkage { m1: 1.1, m2: 0.9, m3: 0.5, l: 0.7, k: 40.0, g: 9.8, f: 2.0, moment: 1.5 };
    for (q, qd) in [([0.6], [1.2]), ([1e-6], [0.0]), ([1.5], [-2.0]), ([FRAC_PI_2 - 1e-4], [0.3])] {
        agrees_with_printed(&s, &q, &qd, 0.0, &[1.0], |qdd| p9_16_8_printed(&s, &q, &qd, qdd)).unwrap();
    }
}

// ---------------------------------------------------------------------------------------------
// P9.16.9: wheel with a pivoted bar (Problem 7.17.7); no printed solution.

/// P9.16.9: a uniform disk (m1, r) rolling on the ground, its centre at (rφ, r) (φ > 0 rolls it
/// toward +x, clockwise); a thin bar (m2, l) pinned at the centre at angle θ above the
/// horizontal, its centre at the pin + ½l(cos θ, sin θ); gravity −ĵ. q = (φ, θ).
#[derive(Clone, Copy, Debug)]
struct WheelBar {
    m1: f64,
    r: f64,
    m2: f64,
    l: f64,
    g: f64,
}

impl Lagrangian for WheelBar {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        let (phid, th, thd) = (qd[0], q[1], qd[1]);
        let r = T::lit(self.r);
        let h = T::lit(0.5 * self.l);
        // rolling: the centre moves at rφ̇ and the disk spins at φ̇ (J = ½m1r²)
        let xd = r * phid;
        let (vx, vy) = (xd - h * th.sin() * thd, h * th.cos() * thd);
        T::lit(0.5 * self.m1) * xd * xd
            + T::lit(0.25 * self.m1 * self.r * self.r) * phid * phid
            + T::lit(0.5 * self.m2) * (vx * vx + vy * vy)
            + T::lit(0.5 * self.m2 * self.l * self.l / 12.0) * thd * thd
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        T::lit(self.m2 * self.g * 0.5 * self.l) * q[1].sin()
    }
}

/// Newton–Euler for the wheel and the bar separately, written from their free-body diagrams;
/// unknowns (φ̈, θ̈, P_x, P_y, F) with P⃗ the pin force on the bar and F the friction on the
/// wheel (along +î at the contact point):
///   wheel, î:      m1 r φ̈ = −P_x + F
///   wheel, spin:   ½m1r² φ̈ = −r F          (ω_z = −φ̇, friction torque r F about the centre)
///   bar, î:        m2 (rφ̈ − ½l(sin θ θ̈ + cos θ θ̇²)) = P_x
///   bar, ĵ:        m2 ½l(cos θ θ̈ − sin θ θ̇²) = P_y − m2 g
///   bar, spin:     (m2l²/12) θ̈ = ½l(sin θ P_x − cos θ P_y)
fn p9_16_9_newton_euler(s: &WheelBar, th: f64, thd: f64) -> Vector5<f64> {
    let (sn, cs) = th.sin_cos();
    let h = 0.5 * s.l;
    #[rustfmt::skip]
    let a = Matrix5::new(
        s.m1 * s.r, 0.0, 1.0, 0.0, -1.0,
        0.5 * s.m1 * s.r * s.r, 0.0, 0.0, 0.0, s.r,
        s.m2 * s.r, -s.m2 * h * sn, -1.0, 0.0, 0.0,
        0.0, s.m2 * h * cs, 0.0, -1.0, 0.0,
        0.0, s.m2 * s.l * s.l / 12.0, -h * sn, h * cs, 0.0,
    );
    let b = Vector5::new(0.0, 0.0, s.m2 * h * cs * thd * thd, s.m2 * h * sn * thd * thd - s.m2 * s.g, 0.0);
    a.lu().solve(&b).expect("nonsingular free-body system")
}

/// P9.16.9 (P7.17.7): Lagrange's φ̈, θ̈ equal the Newton–Euler ones, and the pin reaction
/// P⃗ = m2(a⃗_c − g⃗) from Lagrange's accelerations equals the Newton–Euler unknowns.
#[test]
fn problem_9_16_9_wheel_with_pivoted_bar() {
    let s = WheelBar { m1: 2.0, r: 0.3, m2: 0.8, l: 1.1, g: 9.8 };
    for (q, qd) in [([0.0, 0.5], [2.0, 1.0]), ([3.0, -0.4], [-1.0, 0.3]), ([0.0, FRAC_PI_2], [0.5, 0.0])] {
        let qdd = accelerations(&s, &q, &qd, 0.0).unwrap();
        let ne = p9_16_9_newton_euler(&s, q[1], qd[1]);
        // both routes solve well-conditioned systems of accelerations ≈ 10
        assert_abs(qdd[0], ne[0], 256.0 * EPS * 10.0);
        assert_abs(qdd[1], ne[1], 256.0 * EPS * 10.0);
        let (sn, cs) = q[1].sin_cos();
        let h = 0.5 * s.l;
        let (ax, ay) =
            (s.r * qdd[0] - h * (sn * qdd[1] + cs * qd[1] * qd[1]), h * (cs * qdd[1] - sn * qd[1] * qd[1]));
        assert_abs(s.m2 * ax, ne[2], 256.0 * EPS * 10.0);
        assert_abs(s.m2 * (ay + s.g), ne[3], 256.0 * EPS * 10.0);
    }
}

// ---------------------------------------------------------------------------------------------
// P9.16.10: physical pendulum (Example 7.15.2).

/// P9.16.10: the physical pendulum of Ex 7.15.2: F_B = F_A turned by θ about î_A, r⃗_{c/w} = ℓk̂_B,
/// g⃗ = g k̂_A (k̂_A down), T = ½m|v_c|² + ½J0θ̇², U = −m g⃗·r⃗_c.
#[derive(Clone, Copy, Debug)]
struct Physical {
    m: f64,
    ell: f64,
    j0: f64,
    g: f64,
}

impl Lagrangian for Physical {
    fn dof(&self) -> usize {
        1
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        // r_c|_A = ℓ(0, −sin θ, cos θ): v_c = ℓθ̇(0, −cos θ, −sin θ)
        let v =
            Frame::<T>::identity().vector([T::zero(), -q[0].cos(), -q[0].sin()]) * (T::lit(self.ell) * qd[0]);
        T::lit(0.5 * self.m) * v.norm_squared() + T::lit(0.5 * self.j0) * qd[0] * qd[0]
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        -T::lit(self.m * self.g * self.ell) * q[0].cos()
    }
}

/// The reaction f⃗_R = m a⃗_c − m g⃗ at w resolved in F_B, with a⃗_c by the double transport
/// theorem (4.5.1) applied to r⃗_{c/w} = ℓk̂_B fixed in F_B.
fn pin_reaction(s: &Physical, th: f64, thd: f64, thdd: f64) -> (f64, f64) {
    let fa = LabeledFrame::new("A", Frame::new());
    let o_ba = orientation_about(Axis::X, th);
    let motion =
        FrameMotion::from_body_rates(FrameLabel::new("B"), &fa, &o_ba, [thd, 0.0, 0.0], [thdd, 0.0, 0.0])
            .unwrap();
    let b = motion.body().frame;
    let jet = VectorJet::fixed_in(motion.body().label, b.k() * s.ell).transported(&motion).unwrap();
    let f = jet.second_rate() * s.m - fa.frame.k() * (s.m * s.g);
    (f.dot(&b.j()), f.dot(&b.k()))
}

/// P9.16.10: "derive the equations of motion for the physical pendulum of Example 7.15.2 and
/// determine the reaction forces at the pin." θ̈ + ℓmg sin θ/(J0 + mℓ²) = 0 and
/// f1 = −mgJ0 sin θ/(J0 + mℓ²), f2 = −m(ℓθ̇² + g cos θ). Ex 7.15.2 prints f1 with the opposite
/// sign (erratum, l.9782); the thin bar (ℓ0 = 2ℓ, J0 = mℓ0²/12) gives f1 = −¼mg sin θ and
/// f2 = −m(½ℓ0θ̇² + g cos θ) (printed −mg(½ℓθ̇² + g cos θ), erratum); the simple pendulum
/// (J0 = 0) gives f1 = 0.
#[test]
fn problem_9_16_10_physical_pendulum_reactions() {
    let (m, g) = (1.4, 9.8);
    let ell0 = 0.9;
    let cases = [
        Physical { m, ell: 0.35, j0: 0.12, g },
        Physical { m, ell: 0.5 * ell0, j0: m * ell0 * ell0 / 12.0, g },
        Physical { m, ell: 0.8, j0: 0.0, g },
    ];
    for (k, s) in cases.iter().enumerate() {
        for (th, thd) in [(0.7, 1.3), (-2.5, 0.0), (PI, 4.0)] {
            let qdd = accelerations(s, &[th], &[thd], 0.0).unwrap()[0];
            let jw = s.j0 + s.m * s.ell * s.ell;
            // (θ̈ ≈ 10): a Cholesky solve of a 1×1 system
            assert_abs(qdd, -s.ell * s.m * s.g * th.sin() / jw, 8.0 * EPS * 10.0);
            let (f1, f2) = pin_reaction(s, th, thd, qdd);
            let tol = 64.0 * EPS * s.m * (s.g + s.ell * thd * thd + s.ell * qdd.abs());
            assert_abs(f1, -s.m * s.g * s.j0 * th.sin() / jw, tol);
            assert_abs(f2, -s.m * (s.ell * thd * thd + s.g * th.cos()), tol);
            match k {
                1 => {
                    assert_abs(f1, -0.25 * s.m * s.g * th.sin(), tol);
                    assert_abs(f2, -s.m * (0.5 * ell0 * thd * thd + s.g * th.cos()), tol);
                }
                2 => assert_abs(f1, 0.0, tol),
                _ => {}
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// P9.16.11: ball rolling on the slope of a free cart (Problem 7.17.1).

/// P9.16.11: cart M at Y on frictionless wheels; ball (m, r, J = ⅖mr²) at distance x down the
/// slope (angle θ), its centre moving along (cos θ, −sin θ) relative to the cart and rolling
/// without slip (spin ẋ/r); gravity −ĵ. q = (x, Y).
#[derive(Clone, Copy, Debug)]
struct BallCart {
    m: f64,
    big_m: f64,
    r: f64,
    theta: f64,
    g: f64,
}

impl Lagrangian for BallCart {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, _q: &[T], qd: &[T], _t: T) -> T {
        let (s, c) = self.theta.sin_cos();
        let (xd, yd) = (qd[0], qd[1]);
        let (vx, vy) = (yd + xd * T::lit(c), -xd * T::lit(s));
        let spin = xd / T::lit(self.r);
        T::lit(0.5 * self.big_m) * yd * yd
            + T::lit(0.5 * self.m) * (vx * vx + vy * vy)
            + T::lit(0.5 * 0.4 * self.m * self.r * self.r) * spin * spin
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        -T::lit(self.m * self.g * self.theta.sin()) * q[0]
    }
}

/// P9.16.11 against the solution of P7.17.1 (§7.18): ẍ = 5(m + M)g sin θ/D,
/// D = 7M + (2 + 5 sin²θ)m; ÿ = g tan θ − (7/(5 cos θ))ẍ (printed with ẋ, an OCR slip: the
/// identity needs ẍ); friction f_T = −2(m + M)mg sin θ/D and normal force
/// f_N = (mg/cos θ)(1 − 7(m + M) sin²θ/D). The reactions here come from Newton's law for the
/// ball with Lagrange's accelerations: m a⃗ = f_N n̂ + f_T t̂ + m g⃗. The ground's vertical
/// reaction on the cart is Mg + f_N cos θ − f_T sin θ = (M + m)g − mẍ sin θ.
#[test]
fn problem_9_16_11_ball_rolling_on_a_free_cart() {
    for s in [
        BallCart { m: 0.5, big_m: 3.0, r: 0.1, theta: 0.5, g: 9.8 },
        BallCart { m: 4.0, big_m: 0.2, r: 0.3, theta: 1.2, g: 9.8 },
        BallCart { m: 1.0, big_m: 1.0, r: 0.05, theta: 1e-6, g: 9.8 },
    ] {
        let qdd = accelerations(&s, &[0.3, 0.0], &[0.7, -0.1], 0.0).unwrap();
        let (sn, cs) = s.theta.sin_cos();
        let d = 7.0 * s.big_m + (2.0 + 5.0 * sn * sn) * s.m;
        let x_dd = 5.0 * (s.m + s.big_m) * s.g * sn / d;
        let tol = 64.0 * EPS * s.g;
        assert_abs(qdd[0], x_dd, tol);
        // the printed y is measured the same way as Y here (both equal −m cos θ ẍ/(m + M))
        assert_abs(qdd[1], s.g * sn / cs - 7.0 / (5.0 * cs) * x_dd, tol);
        assert_abs(qdd[1], -s.m * cs * x_dd / (s.m + s.big_m), tol);
        // Newton for the ball along t̂ = (cos θ, −sin θ) and n̂ = (sin θ, cos θ)
        let (ax, ay) = (qdd[1] + qdd[0] * cs, -qdd[0] * sn);
        let f_t = s.m * (ax * cs - ay * sn) - s.m * s.g * sn;
        let f_n = s.m * (ax * sn + ay * cs) + s.m * s.g * cs;
        let ftol = 64.0 * EPS * s.m * s.g;
        assert_abs(f_t, -2.0 * (s.m + s.big_m) * s.m * s.g * sn / d, ftol);
        assert_abs(f_n, s.m * s.g / cs * (1.0 - 7.0 * (s.m + s.big_m) * sn * sn / d), ftol);
        let ground = s.big_m * s.g + f_n * cs - f_t * sn;
        assert_abs(ground, (s.big_m + s.m) * s.g - s.m * qdd[0] * sn, 64.0 * EPS * (s.m + s.big_m) * s.g);
    }
}

// ---------------------------------------------------------------------------------------------
// P9.16.12: offset rotating pendulum.

/// P9.16.12: shaft spinning at ω(t) about k̂_A (k̂_A down, g⃗ = g k̂_A); arm of length R along ê1
/// of the arm frame F_B (ê2 = k̂_A × ê1, so ê1^{A•} = ωê2); hinge at a along ê1; link of length
/// ℓ along ê_link = cos θ k̂_A − sin θ ê2, θ > 0 clockwise seen from b to a (a positive turn
/// about ê1). ω(t) = ω0 + ω1 sin(νt).
#[derive(Clone, Copy, Debug)]
struct OffsetPendulum {
    m: f64,
    big_r: f64,
    ell: f64,
    g: f64,
    w0: f64,
    w1: f64,
    nu: f64,
}

impl OffsetPendulum {
    fn omega<T: Scalar>(&self, t: T) -> T {
        T::lit(self.w0) + T::lit(self.w1) * (T::lit(self.nu) * t).sin()
    }
    fn omega_dot(&self, t: f64) -> f64 {
        self.w1 * self.nu * (self.nu * t).cos()
    }
}

impl Lagrangian for OffsetPendulum {
    fn dof(&self) -> usize {
        1
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], t: T) -> T {
        // resolved in F_B = (ê1, ê2, k̂_A): r = (R, −ℓ sin θ, ℓ cos θ); transport theorem (4.4.1)
        // v⃗ = r⃗^{B•} + ω⃗_{B/A} × r⃗ with ω⃗_{B/A} = ω k̂_A
        let b = Frame::<T>::identity();
        let (s, c) = (q[0].sin(), q[0].cos());
        let l = T::lit(self.ell);
        let r = b.vector([T::lit(self.big_r), -l * s, l * c]);
        let r_rel = b.vector([T::zero(), -l * c * qd[0], -l * s * qd[0]]);
        let v = r_rel + b.k().cross(&r) * self.omega(t);
        T::lit(0.5 * self.m) * v.norm_squared()
    }
    fn potential<T: Scalar>(&self, q: &[T], _t: T) -> T {
        -T::lit(self.m * self.g * self.ell) * q[0].cos()
    }
}

/// P9.16.12 i): ℓθ̈ = Rω̇ cos θ + ℓω² sin θ cos θ − g sin θ (for the conventions above; with the
/// opposite sense of ω or of θ the Rω̇ term changes sign). ii) the reaction on the particle
/// resolved in F_C = (î_C = ê1 the hinge axis, ĵ_C = k̂_C × î_C, k̂_C = ê_link):
/// f1 = m(2ωℓ cos θ θ̇ + ω̇ℓ sin θ − ω²R), f2 = m(−ℓθ̈ + Rω̇ cos θ + ℓω² sin θ cos θ − g sin θ),
/// f3 = −m(ℓθ̇² + Rω̇ sin θ + ℓω² sin²θ + g cos θ). iii) the massless link carries no moment
/// about its hinge, so f2 = 0 — which is i) again, now from Newton–Euler. iv) the arm receives
/// −f⃗_R at a and the moment −ℓk̂_C × f⃗_R, which has no component along the hinge.
#[test]
fn problem_9_16_12_offset_rotating_pendulum() {
    let s = OffsetPendulum { m: 0.7, big_r: 0.5, ell: 0.4, g: 9.8, w0: 2.0, w1: 1.5, nu: 1.3 };
    for (th, thd, t) in [(0.4, 0.9, 0.0), (-1.2, -2.0, 1.7), (PI - 1e-8, 0.0, 0.6), (0.0, 0.0, 2.2)] {
        let thdd = accelerations(&s, &[th], &[thd], t).unwrap()[0];
        let (w, wd) = (s.omega(t), s.omega_dot(t));
        let (sn, cs) = th.sin_cos();
        let want = (s.big_r * wd * cs + s.ell * w * w * sn * cs - s.g * sn) / s.ell;
        let scale = s.big_r * wd.abs() + s.ell * w * w + s.g;
        assert_abs(thdd, want, 64.0 * EPS * scale / s.ell);
        // ii)–iv): the particle's acceleration by the double transport theorem (4.5.1) from F_B
        let fa = LabeledFrame::new("A", Frame::new());
        let psi = 0.3; // the arm's heading: any value (the problem is invariant under it)
        let motion = FrameMotion::from_body_rates(
            FrameLabel::new("B"),
            &fa,
            &orientation_about(Axis::Z, psi),
            [0.0, 0.0, w],
            [0.0, 0.0, wd],
        )
        .unwrap();
        let b = motion.body().frame;
        let r = b.vector([s.big_r, -s.ell * sn, s.ell * cs]);
        let r_rel = b.vector([0.0, -s.ell * cs * thd, -s.ell * sn * thd]);
        let r_rel2 = b.vector([
            0.0,
            s.ell * sn * thd * thd - s.ell * cs * thdd,
            -s.ell * cs * thd * thd - s.ell * sn * thdd,
        ]);
        let jet =
            VectorJet::new(motion.body().label, r, r_rel, r_rel2).unwrap().transported(&motion).unwrap();
        let f_r = jet.second_rate() * s.m - fa.frame.k() * (s.m * s.g);
        let i_c = b.i();
        let k_c = b.vector([0.0, -sn, cs]);
        let j_c = k_c.cross(&i_c);
        let ftol = 64.0 * EPS * s.m * scale * 4.0;
        assert_abs(
            f_r.dot(&i_c),
            s.m * (2.0 * w * s.ell * cs * thd + wd * s.ell * sn - w * w * s.big_r),
            ftol,
        );
        assert_abs(f_r.dot(&j_c), 0.0, ftol);
        assert_abs(
            f_r.dot(&k_c),
            -s.m * (s.ell * thd * thd + s.big_r * wd * sn + s.ell * w * w * sn * sn + s.g * cs),
            ftol,
        );
        let torque_on_arm = -(k_c * s.ell).cross(&f_r);
        assert_abs(torque_on_arm.dot(&i_c), 0.0, ftol * s.ell);
    }
}

// ---------------------------------------------------------------------------------------------
// Property tests: the printed solutions at random parameters and states.

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn problem_9_16_1_random(
        m in [0.1..10.0f64, 0.1..10.0f64], k in [0.0..50.0f64, 0.0..50.0f64, 0.0..50.0f64],
        c in 0.0..5.0f64, rr in [0.0..2.0f64, 0.0..2.0f64, 0.0..2.0f64],
        q in (near_zero_distance(), 0.01..3.0f64), qd in [rate(), rate()],
    ) {
        let q = [q.0, q.1];
        let s = TwoTracks { m1: m[0], m2: m[1], k1: k[0], k2: k[1], k: k[2], c, r1: rr[0], r2: rr[1], r: rr[2] };
        let r = agrees_with_printed(&s, &q, &qd, 0.0, &[1.0, 1.0], |qdd| p9_16_1_printed(&s, &q, &qd, qdd));
        prop_assert!(r.is_ok(), "{r:?}");
    }

    #[test]
    fn problem_9_16_2_random(
        big_m in 0.1..10.0f64, m in 0.1..10.0f64, l in 0.1..3.0f64, k in 0.0..50.0f64, r in 0.0..2.0f64,
        c in 0.0..5.0f64, f in -5.0..5.0f64, th in angle_in(1e-6, FRAC_PI_2 - 1e-6), xd in rate(), thd in rate(),
    ) {
        let s = BlockBar { big_m, m, l, k, r, c, g: 9.8, f };
        let (q, qd) = ([0.0, th], [xd, thd]);
        let res = agrees_with_printed(&s, &q, &qd, 0.0, &[1.0, l], |qdd| p9_16_2_printed(&s, 1.0 / 3.0, &q, &qd, qdd));
        prop_assert!(res.is_ok(), "{res:?}");
    }

    #[test]
    fn problem_9_16_3_random(
        m in [0.1..10.0f64, 0.1..10.0f64], k in [0.0..50.0f64, 0.0..50.0f64], theta in angle_in(0.0, FRAC_PI_2),
        q in [-2.0..2.0f64, -2.0..2.0f64], qd in [rate(), rate()],
    ) {
        let s = WedgeCart { m1: m[0], m2: m[1], k1: k[0], k2: k[1], theta, g: 9.8 };
        let (sn, cs) = theta.sin_cos();
        let res = agrees_with_printed(&s, &q, &qd, 0.0, &[1.0, 1.0], |qdd| vec![
            (s.m1 + s.m2) * qdd[0] + s.m2 * cs * qdd[1] + s.k1 * q[0],
            s.m2 * (qdd[1] + cs * qdd[0]) + s.k2 * q[1] - s.m2 * s.g * sn,
        ]);
        prop_assert!(res.is_ok(), "{res:?}");
    }

    #[test]
    fn problem_9_16_4_random(
        m in 0.1..10.0f64, k in 0.0..50.0f64, l in 0.0..2.0f64, th in [-PI..PI, -2.0..2.0f64, 0.0..5.0f64],
        q in [0.0..3.0f64, 0.0..3.0f64], qd in [rate(), rate()], t in 0.0..20.0f64,
    ) {
        let s = TurnedBar { m, k, l, g: 9.8, th0: th[0], th1: th[1], nu: th[2] };
        let res = agrees_with_printed(&s, &q, &qd, t, &[m, m], |qdd| p9_16_4_printed(&s, &q, t, qdd));
        prop_assert!(res.is_ok(), "{res:?}");
    }

    #[test]
    fn problem_9_16_5_random(
        m in 0.1..10.0f64, l0 in 0.5..3.0f64, l1 in 0.0..0.45f64, nu in 0.0..5.0f64,
        phi in angle_in(1e-6, PI - 1e-6), theta in -PI..PI, qd in [rate(), rate()], t in 0.0..20.0f64,
    ) {
        let s = ReelPendulum { m, g: 9.8, l0, l1, nu };
        let q = [phi, theta];
        let d = [m, m * s.l::<f64>(t) * phi.sin()];
        let res = agrees_with_printed(&s, &q, &qd, t, &d, |qdd| p9_16_5_printed(&s, &q, &qd, t, qdd));
        prop_assert!(res.is_ok(), "{res:?}");
    }

    #[test]
    fn problem_9_16_6_random(
        m in [0.1..10.0f64, 0.1..10.0f64], l in [0.1..3.0f64, 0.1..3.0f64], jf in [0.25..2.0f64, 0.25..2.0f64],
        f in -5.0..5.0f64, q in [angle_in(-PI, PI), angle_in(-PI, PI)], qd in [rate(), rate()],
    ) {
        // J about an end ≥ m(l/2)² (J about the centre ≥ 0): J = jf·m l²
        let s = TwoLink { m1: m[0], m2: m[1], l1: l[0], l2: l[1], j1: jf[0] * m[0] * l[0] * l[0], j2: jf[1] * m[1] * l[1] * l[1], g: 9.8, f };
        let res = agrees_with_printed(&s, &q, &qd, 0.0, &[1.0, 1.0], |qdd| p9_16_6_printed(&s, &q, &qd, qdd));
        prop_assert!(res.is_ok(), "{res:?}");
    }

    #[test]
    fn problem_9_16_7_random(
        jd in 0.1..10.0f64, m in 0.1..10.0f64, h in 0.0..3.0f64, k in 0.0..50.0f64, tau in -5.0..5.0f64,
        q in [-PI..PI, -2.0..2.0f64], qd in [rate(), rate()],
    ) {
        let s = SlotDisk { jd, m, h, k, tau };
        let res = agrees_with_printed(&s, &q, &qd, 0.0, &[1.0, m], |qdd| {
            let (x, thd, xd) = (q[1], qd[0], qd[1]);
            vec![
                (s.jd + s.m * s.h * s.h + s.m * x * x) * qdd[0] + 2.0 * s.m * x * xd * thd - s.m * s.h * qdd[1] - s.tau,
                qdd[1] - s.h * qdd[0] - x * thd * thd + 2.0 * s.k / s.m * x,
            ]
        });
        prop_assert!(res.is_ok(), "{res:?}");
    }

    #[test]
    fn problem_9_16_8_random(
        m in [0.1..10.0f64, 0.1..10.0f64, 0.0..10.0f64], l in 0.1..3.0f64, k in 0.0..50.0f64,
        f in -5.0..5.0f64, moment in -5.0..5.0f64, th in angle_in(1e-6, FRAC_PI_2 - 1e-4), thd in rate(),
    ) {
        let s = Linkage { m1: m[0], m2: m[1], m3: m[2], l, k, g: 9.8, f, moment };
        let (q, qd) = ([th], [thd]);
        let res = agrees_with_printed(&s, &q, &qd, 0.0, &[1.0], |qdd| p9_16_8_printed(&s, &q, &qd, qdd));
        prop_assert!(res.is_ok(), "{res:?}");
    }

    #[test]
    fn problem_9_16_9_random(
        m1 in 0.1..10.0f64, r in 0.05..2.0f64, m2 in 0.1..10.0f64, l in 0.1..3.0f64,
        th in angle_in(-PI, PI), qd in [rate(), rate()],
    ) {
        let s = WheelBar { m1, r, m2, l, g: 9.8 };
        let qdd = accelerations(&s, &[0.0, th], &qd, 0.0).unwrap();
        let ne = p9_16_9_newton_euler(&s, th, qd[1]);
        // both sides are solves of systems with κ ≲ 1e4 over these ranges
        let scale = 9.8 / l.min(r) + qd[1] * qd[1] + 1.0;
        prop_assert!((qdd[0] - ne[0]).abs() <= 1e-11 * scale, "φ̈ {} vs {}", qdd[0], ne[0]);
        prop_assert!((qdd[1] - ne[1]).abs() <= 1e-11 * scale, "θ̈ {} vs {}", qdd[1], ne[1]);
    }

    #[test]
    fn problem_9_16_12_random(
        m in 0.1..10.0f64, big_r in 0.0..2.0f64, ell in 0.1..2.0f64, w in [-5.0..5.0f64, -3.0..3.0f64, 0.0..4.0f64],
        th in angle_in(-PI, PI), thd in rate(), t in 0.0..20.0f64,
    ) {
        let s = OffsetPendulum { m, big_r, ell, g: 9.8, w0: w[0], w1: w[1], nu: w[2] };
        let thdd = accelerations(&s, &[th], &[thd], t).unwrap()[0];
        let (om, wd) = (s.omega(t), s.omega_dot(t));
        let (sn, cs) = th.sin_cos();
        let want = (big_r * wd * cs + ell * om * om * sn * cs - 9.8 * sn) / ell;
        let scale = (big_r * wd.abs() + ell * om * om + 9.8 + ell * thd * thd) / ell;
        prop_assert!((thdd - want).abs() <= 64.0 * EPS * scale, "{thdd} vs {want}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// P9.16.1: vectrix's accelerations equal Newton's law with frame-free forces at random
    /// states (diagonal M, accelerations ≤ 1e3: a few roundings of each force term).
    #[test]
    fn problem_9_16_1_newton_random(q in [0.05..3.0f64, 0.05..3.0f64], qd in [rate(), rate()]) {
        let qdd = accelerations(&TRACKS, &q, &qd, 0.0).unwrap();
        let newton = p9_16_1_newton(&TRACKS, &q, &qd);
        let scale = 1.0 + DVector::from_column_slice(&newton).nan_amax();
        for i in 0..2 {
            prop_assert!((qdd[i] - newton[i]).abs() <= 256.0 * EPS * scale, "{} vs {}", qdd[i], newton[i]);
        }
    }
}
