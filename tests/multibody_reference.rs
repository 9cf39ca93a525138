//! §7.11 multibody trees against an independent implementation: Pinocchio 4.1's RNEA, ABA,
//! CRBA and analytical derivatives (computeRNEADerivatives, computeABADerivatives), computed
//! once by `scripts/pin_reference.py` and committed as `tests/data/multibody_reference.json`.
//!
//! The book's claim (§7.11): the per-body Newton–Euler equations 𝒥𝒜 + 𝒱^×𝒥𝒱 = ℱ of a tree,
//! with the joint reactions eliminated, determine τ from (q, v, v̇) and v̇ from (q, v, τ), and
//! the kinetic energy is ½ vᵀM(q)v. Pinocchio shares no code with vectrix; the script rebuilds
//! every vectrix joint from Pinocchio joints (its docstring gives the map, including the
//! free joint's velocity convention) and converts its results into vectrix's coordinates.
//! The link data below are read from the same file, so both sides build one tree.
//!
//! Derivatives are in the tangent space: column k of ∂/∂q is d/dε f(q ⊕ ε eₖ), with ⊕ the
//! `integrate` retraction (for a ball joint a rotation about the link's own k-th axis), which
//! is Pinocchio's convention for its spherical joint too.

mod support;

use crate::support::{NanAmax, nan_max};
use serde_json::Value;
use vectrix::dynamics::multibody::{Joint, Link, Model};
use vectrix::nalgebra::{DMatrix, Matrix3, SymmetricEigen, Vector3};

const EPS: f64 = f64::EPSILON;

/// Tolerance of results that need no linear solve (RNEA τ, CRBA M, ∂τ/∂q, ∂τ/∂v), relative
/// to the largest entry of the reference: each entry is a sum over at most 18 coordinates and
/// 6 tree levels of products of the link data, rounded by both codes in different orders
/// (the worst difference seen is 6.3 ε; 64 ε leaves a factor 10).
const DIRECT_TOL: f64 = 64.0 * EPS;

/// Tolerance factor of results behind a solve with M (ABA v̇, ∂v̇/∂·, M⁻¹): the rounding of
/// the direct results amplified by the condition number κ(M) (computed from the reference M,
/// 2.2e3 for the chain, 2.2e2 for the tree): |Δ| ≤ 4 ε κ(M) × the largest entry (the worst
/// difference seen is 0.3 ε κ(M)).
const SOLVE_TOL_PER_COND: f64 = 4.0 * EPS;

fn data() -> Value {
    let text = include_str!("data/multibody_reference.json");
    serde_json::from_str(text).expect("reference JSON parses")
}

fn vec3(v: &Value) -> Vector3<f64> {
    Vector3::new(v[0].as_f64().unwrap(), v[1].as_f64().unwrap(), v[2].as_f64().unwrap())
}

fn mat3(v: &Value) -> Matrix3<f64> {
    Matrix3::from_fn(|r, c| v[r][c].as_f64().unwrap())
}

fn vector(v: &Value) -> Vec<f64> {
    v.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect()
}

fn matrix(v: &Value) -> DMatrix<f64> {
    let rows = v.as_array().unwrap();
    DMatrix::from_fn(rows.len(), rows.len(), |r, c| rows[r][c].as_f64().unwrap())
}

/// The vectrix model of one entry of the reference file.
fn model(entry: &Value) -> Model {
    let links: Vec<Link> = entry["links"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| {
            let joint = match l["joint"].as_str().unwrap() {
                "pin" => Joint::Pin { axis: vec3(&l["axis"]) },
                "sleeve" => Joint::Sleeve { axis: vec3(&l["axis"]) },
                "collar" => Joint::Collar { axis: vec3(&l["axis"]) },
                "slot" => Joint::Slot { axis: vec3(&l["axis"]), direction: vec3(&l["direction"]) },
                "ball" => Joint::Ball,
                "weld" => Joint::Weld,
                "free" => Joint::Free,
                other => panic!("unknown joint {other}"),
            };
            let mut link = Link::new(
                l["parent"].as_u64().map(|p| p as usize),
                joint,
                vec3(&l["offset"]),
                l["mass"].as_f64().unwrap(),
                vec3(&l["com"]),
                mat3(&l["inertia"]),
            );
            link.orientation = mat3(&l["orientation"]);
            link
        })
        .collect();
    let mut m = Model::new(&links).expect("reference tree is valid");
    let g = data()["gravity"].clone();
    m.gravity = vec3(&g);
    m
}

/// max |got − want| ≤ tol × max |want|, entry by entry, with a message naming the entry.
fn assert_rel_to_max(what: &str, got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len(), "{what}: length");
    let scale = want.iter().fold(0.0f64, |m, x| nan_max(m, x.abs()));
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(
            (g - w).abs() <= tol * scale,
            "{what}[{k}]: got {g:e}, want {w:e}, |Δ| = {:e} > {tol:e} × {scale:e}",
            (g - w).abs()
        );
    }
}

/// |got − want| ≤ tol (absolute), entry by entry.
fn assert_abs_all(what: &str, got: &[f64], want: &[f64], tol: f64) {
    assert_eq!(got.len(), want.len(), "{what}: length");
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(
            (g - w).abs() <= tol,
            "{what}[{k}]: got {g:e}, want {w:e}, |Δ| = {:e} > {tol:e}",
            (g - w).abs()
        );
    }
}

/// κ(M) = λmax/λmin of the reference mass matrix.
fn condition(m: &DMatrix<f64>) -> f64 {
    let e = SymmetricEigen::new(m.clone()).eigenvalues;
    e.max() / e.min()
}

fn for_each_case(mut f: impl FnMut(&str, &Model, &Value)) {
    let d = data();
    for (name, entry) in d["models"].as_object().unwrap() {
        let m = model(entry);
        for c in entry["cases"].as_array().unwrap() {
            f(name, &m, c);
        }
    }
}

/// §7.11 (7.11.13)–(7.11.22): inverse dynamics of a tree with every joint type (and of the
/// benchmark chain) equals Pinocchio's RNEA.
#[test]
fn section_7_11_rnea_matches_pinocchio_on_every_joint_type() {
    for_each_case(|name, m, c| {
        let tau = m.rnea(&vector(&c["q"]), &vector(&c["v"]), &vector(&c["a"]), None).unwrap().tau;
        assert_rel_to_max(&format!("{name} τ"), &tau, &vector(&c["rnea_tau"]), DIRECT_TOL);
    });
}

/// §7.11, §9.3: the mass matrix M(q) of the tree equals Pinocchio's CRBA.
#[test]
fn section_7_11_crba_matches_pinocchio_on_every_joint_type() {
    for_each_case(|name, m, c| {
        let h = m.crba(&vector(&c["q"])).unwrap();
        let want = matrix(&c["crba_m"]);
        assert_rel_to_max(&format!("{name} M"), h.as_slice(), want.as_slice(), DIRECT_TOL);
    });
}

/// §7.11: forward dynamics by ABA (and by CRBA + Cholesky) equals Pinocchio's ABA. The
/// benchmark chain (every pin about ŷ) is planar, so vectrix's ABA runs its planar passes on
/// it (`Model::planar_axis`), and the spatial passes with the reduction turned off: both are
/// checked against Pinocchio's (spatial) ABA.
#[test]
fn section_7_11_aba_matches_pinocchio_on_every_joint_type() {
    for_each_case(|name, m, c| {
        let (q, v, tau) = (vector(&c["q"]), vector(&c["v"]), vector(&c["tau"]));
        let tol = SOLVE_TOL_PER_COND * condition(&matrix(&c["crba_m"]));
        let want = vector(&c["aba_vdot"]);
        assert_eq!(m.planar_axis().is_some(), name == "chain6", "{name}: planar reduction");
        assert_rel_to_max(&format!("{name} v̇ (ABA)"), &m.aba(&q, &v, &tau, None).unwrap(), &want, tol);
        let mut spatial = m.clone();
        spatial.disable_planar_reduction();
        let got = spatial.aba(&q, &v, &tau, None).unwrap();
        assert_rel_to_max(&format!("{name} v̇ (spatial ABA)"), &got, &want, tol);
        let crba = m.forward_dynamics_crba(&q, &v, &tau, None).unwrap();
        assert_rel_to_max(&format!("{name} v̇ (CRBA)"), &crba, &want, tol);
    });
}

/// `Model::aba_checked` (the batch path of the Python package: one work space reused for
/// every state) equals Pinocchio's ABA on every case, visited twice in turn so that each call
/// starts from the work space another state left, and refuses what `Model::aba` refuses.
#[test]
fn aba_checked_with_one_reused_scratch_matches_pinocchio() {
    let d = data();
    for (name, entry) in d["models"].as_object().unwrap() {
        let m = model(entry);
        let mut s = m.aba_scratch();
        let mut vdot = vec![0.0; m.nv()];
        let cases = entry["cases"].as_array().unwrap();
        for c in cases.iter().chain(cases.iter().rev()) {
            let (q, v, tau) = (vector(&c["q"]), vector(&c["v"]), vector(&c["tau"]));
            m.aba_checked(&q, &v, &tau, None, &mut vdot, &mut s).unwrap();
            let tol = SOLVE_TOL_PER_COND * condition(&matrix(&c["crba_m"]));
            assert_rel_to_max(&format!("{name} v̇ (aba_checked)"), &vdot, &vector(&c["aba_vdot"]), tol);
        }
        let c = &cases[0];
        let (mut q, v, tau) = (vector(&c["q"]), vector(&c["v"]), vector(&c["tau"]));
        let short = &mut vec![0.0; m.nv() - 1];
        assert!(m.aba_checked(&q, &v, &tau, None, short, &mut s).is_err(), "{name}: short v̇");
        q[0] = f64::NAN;
        assert!(m.aba_checked(&q, &v, &tau, None, &mut vdot, &mut s).is_err(), "{name}: NaN in q");
    }
}

/// ∂τ/∂q, ∂τ/∂v and ∂τ/∂v̇ = M of RNEA equal Pinocchio's computeRNEADerivatives.
#[test]
fn rnea_derivatives_match_pinocchio() {
    for_each_case(|name, m, c| {
        let d = m.rnea_derivatives(&vector(&c["q"]), &vector(&c["v"]), &vector(&c["a"]), None).unwrap();
        for (what, got, key) in [("∂τ/∂q", &d.dtau_dq, "dtau_dq"), ("∂τ/∂v", &d.dtau_dv, "dtau_dv")]
        {
            assert_rel_to_max(
                &format!("{name} {what}"),
                got.as_slice(),
                matrix(&c[key]).as_slice(),
                DIRECT_TOL,
            );
        }
        assert_rel_to_max(
            &format!("{name} M"),
            d.mass_matrix.as_slice(),
            matrix(&c["crba_m"]).as_slice(),
            DIRECT_TOL,
        );
        assert_rel_to_max(&format!("{name} τ"), &d.tau, &vector(&c["rnea_tau"]), DIRECT_TOL);
    });
}

/// ∂v̇/∂q, ∂v̇/∂v and ∂v̇/∂τ = M⁻¹ of ABA equal Pinocchio's computeABADerivatives.
#[test]
fn aba_derivatives_match_pinocchio() {
    for_each_case(|name, m, c| {
        let d = m.aba_derivatives(&vector(&c["q"]), &vector(&c["v"]), &vector(&c["tau"]), None).unwrap();
        let tol = SOLVE_TOL_PER_COND * condition(&matrix(&c["crba_m"]));
        for (what, got, key) in [
            ("∂v̇/∂q", &d.dvdot_dq, "dvdot_dq"),
            ("∂v̇/∂v", &d.dvdot_dv, "dvdot_dv"),
            ("M⁻¹", &d.dvdot_dtau, "dvdot_dtau"),
        ] {
            assert_rel_to_max(&format!("{name} {what}"), got.as_slice(), matrix(&c[key]).as_slice(), tol);
        }
        assert_rel_to_max(&format!("{name} v̇"), &d.vdot, &vector(&c["aba_vdot"]), tol);
    });
}

/// The analytical derivatives against central differences in the tangent space,
/// (f(q ⊕ h eₖ) − f(q ⊖ h eₖ)) / 2h with h = 1e-6: truncation h²|f'''|/6 ≈ 1e-12 and rounding
/// ε|f|/h ≈ 2e-10 of the scale (the worst difference seen is 4.4e-10), so a loose 1e-8
/// relative to the largest entry separates a wrong column (an error of order 1) from a right one.
#[test]
fn derivatives_agree_with_central_differences() {
    const H: f64 = 1e-6;
    const LOOSE: f64 = 1e-8;
    let d = data();
    let entry = &d["models"]["tree"];
    let m = model(entry);
    let c = &entry["cases"][0];
    let (q, v, tau) = (vector(&c["q"]), vector(&c["v"]), vector(&c["tau"]));
    let n = m.nv();
    let ad = m.aba_derivatives(&q, &v, &tau, None).unwrap();
    let rd = m.rnea_derivatives(&q, &v, &ad.vdot, None).unwrap();
    let zero = vec![0.0; n];
    let mut fd_aba = DMatrix::zeros(n, n);
    let mut fd_rnea = DMatrix::zeros(n, n);
    let mut fd_aba_v = DMatrix::zeros(n, n);
    for k in 0..n {
        let mut e = zero.clone();
        e[k] = 1.0;
        let qp = m.integrate(&q, &e, H).unwrap();
        let qm = m.integrate(&q, &e, -H).unwrap();
        let (ap, am) = (m.aba(&qp, &v, &tau, None).unwrap(), m.aba(&qm, &v, &tau, None).unwrap());
        let (tp, tm) =
            (m.rnea(&qp, &v, &ad.vdot, None).unwrap().tau, m.rnea(&qm, &v, &ad.vdot, None).unwrap().tau);
        let (mut vp, mut vm) = (v.clone(), v.clone());
        vp[k] += H;
        vm[k] -= H;
        let (bp, bm) = (m.aba(&q, &vp, &tau, None).unwrap(), m.aba(&q, &vm, &tau, None).unwrap());
        for r in 0..n {
            fd_aba[(r, k)] = (ap[r] - am[r]) / (2.0 * H);
            fd_rnea[(r, k)] = (tp[r] - tm[r]) / (2.0 * H);
            fd_aba_v[(r, k)] = (bp[r] - bm[r]) / (2.0 * H);
        }
    }
    assert_rel_to_max("∂v̇/∂q vs central differences", ad.dvdot_dq.as_slice(), fd_aba.as_slice(), LOOSE);
    assert_rel_to_max("∂v̇/∂v vs central differences", ad.dvdot_dv.as_slice(), fd_aba_v.as_slice(), LOOSE);
    assert_rel_to_max("∂τ/∂q vs central differences", rd.dtau_dq.as_slice(), fd_rnea.as_slice(), LOOSE);
}

/// ∂M/∂q from dual numbers through CRBA equals the central difference of M (loose, 1e-8 of
/// max |Mᵢⱼ| per unit length, as above),
/// and equals the q-derivative of ∂τ/∂v̇ implied by RNEA: (∂M/∂qₖ) a = ∂τ/∂qₖ at v = 0, g = 0
/// (τ = M(q) a then), an exact identity between two routes.
#[test]
fn mass_matrix_derivative_by_dual_numbers() {
    const H: f64 = 1e-6;
    let d = data();
    let entry = &d["models"]["tree"];
    let mut m = model(entry);
    let c = &entry["cases"][1];
    let (q, a) = (vector(&c["q"]), vector(&c["a"]));
    let n = m.nv();
    let dm = m.mass_matrix_derivatives(&q).unwrap();
    // entries of ∂M/∂q are of the size of M per unit length (the tree spans about 1 m);
    // some are exactly zero (M does not depend on the free joint's translation), so the
    // tolerances are absolute, scaled by max |Mᵢⱼ| and max |aᵢ|
    let m_scale = m.crba(&q).unwrap().nan_amax();
    let a_scale = a.iter().fold(0.0f64, |x, y| nan_max(x, y.abs()));
    m.gravity = Vector3::zeros();
    let rd = m.rnea_derivatives(&q, &vec![0.0; n], &a, None).unwrap();
    for (k, dmk) in dm.iter().enumerate() {
        let mut e = vec![0.0; n];
        e[k] = 1.0;
        let mp = m.crba(&m.integrate(&q, &e, H).unwrap()).unwrap();
        let mm = m.crba(&m.integrate(&q, &e, -H).unwrap()).unwrap();
        let fd = (mp - mm) / (2.0 * H);
        assert_abs_all(&format!("∂M/∂q{k}"), dmk.as_slice(), fd.as_slice(), 1e-8 * m_scale);
        let col: Vec<f64> = (dmk * DMatrix::from_column_slice(n, 1, &a)).iter().copied().collect();
        let want: Vec<f64> = rd.dtau_dq.column(k).iter().copied().collect();
        assert_abs_all(&format!("(∂M/∂q{k}) a"), &col, &want, DIRECT_TOL * m_scale * a_scale);
    }
}
