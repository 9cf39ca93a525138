//! The linear-systems layer against an independent 60-digit reference (issue 19).
//!
//! `tests/data/lti_reference.json` is written by `scripts/lti_reference.py` (mpmath at 60
//! digits, exact rational arithmetic for the crossover polynomials; see its docstring): 120
//! SISO transfer functions of order 1–10 (stable, integrators, right-half-plane zeros,
//! negative gain, unstable poles, ill-conditioned roots, exactly repeated poles, imaginary-axis
//! poles and zeros), each with its poles and zeros, G(jω), Bode magnitude and phase, every
//! stability-margin crossover as python-control 0.10 defines them, and step, impulse,
//! initial-condition and lsim (ZOH, FOH) responses, all with condition numbers with respect to
//! relative perturbations of the data. The numbers are read exactly (serde_json's
//! `float_roundtrip`).
//!
//! Every check is "error ≤ C·ε·(κ + 1)": κ the componentwise condition number of the quantity
//! (from the reference), C a small multiple stated at each test (Horner's rule perturbs each
//! coefficient by at most (n + 2)ε, so C grows with the degree). Time responses use the
//! issue's bound 1e-12·κ, relative to the window: |ŷ(t_k) − y(t_k)| ≤ 1e-12·max_{j≤k} S(t_j)
//! with S = Σ_p |p·∂y/∂p| over every coefficient, initial state and input sample (S ≥ |y|, so
//! this is a relative error ≤ 1e-12·κ over the elapsed window, growth-relative for unstable
//! systems).

use serde_json::Value;
use std::f64::consts::LN_10;
use vectrix::lti::*;

const EPS: f64 = f64::EPSILON;

fn reference() -> Value {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/lti_reference.json");
    let text = std::fs::read_to_string(&path).expect("tests/data/lti_reference.json");
    serde_json::from_str(&text).expect("valid JSON")
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

fn fvec(v: &Value) -> Vec<f64> {
    v.as_array().expect("array").iter().map(f).collect()
}

/// A system of the reference set.
struct Sys<'a> {
    v: &'a Value,
    name: String,
    g: TransferFunction,
    /// Degree of the denominator.
    n: usize,
}

fn systems(doc: &Value) -> Vec<Sys<'_>> {
    doc["systems"]
        .as_array()
        .expect("systems")
        .iter()
        .map(|v| {
            let (num, den) = (fvec(&v["num"]), fvec(&v["den"]));
            Sys {
                v,
                name: v["name"].as_str().expect("name").to_string(),
                g: TransferFunction::new(&num, &den).expect("valid system"),
                n: den.len() - 1,
            }
        })
        .collect()
}

/// Collects failures and the worst error/tolerance ratio, then asserts none failed.
struct Report {
    what: &'static str,
    failures: Vec<String>,
    worst: f64,
    worst_at: String,
    checks: usize,
}

impl Report {
    fn new(what: &'static str) -> Self {
        Self { what, failures: Vec::new(), worst: 0.0, worst_at: String::new(), checks: 0 }
    }

    /// Records |err| ≤ tol (a NaN error fails).
    fn check(&mut self, err: f64, tol: f64, at: impl FnOnce() -> String) {
        self.checks += 1;
        let ratio = if err == 0.0 { 0.0 } else { err / tol };
        let ok = ratio <= 1.0;
        if ratio > self.worst || ratio.is_nan() {
            self.worst = ratio;
            self.worst_at = at();
            if !ok {
                self.failures.push(format!("{} (error {err:e} > tolerance {tol:e})", self.worst_at));
            }
        } else if !ok {
            self.failures.push(format!("{} (error {err:e} > tolerance {tol:e})", at()));
        }
    }

    fn fail(&mut self, msg: String) {
        self.checks += 1;
        self.failures.push(msg);
    }

    fn finish(self) {
        println!(
            "{}: {} checks, worst error/tolerance {:.3e} at {}",
            self.what, self.checks, self.worst, self.worst_at
        );
        assert!(
            self.failures.is_empty(),
            "{}: {} failures:\n{}",
            self.what,
            self.failures.len(),
            self.failures.join("\n")
        );
    }
}

/// Tolerance multiple for values evaluated by Horner's rule on N (degree m ≤ n) and D
/// (degree n): each is exact for coefficients perturbed by (n + 2)ε relative (Higham §5.1), so
/// the quotient carries at most 2(n + 2)ε·κ plus four roundings to form it.
fn horner_multiple(n: usize) -> f64 {
    2.0 * (n as f64 + 2.0) + 4.0
}

#[test]
fn reference_set_is_large_and_varied() {
    // Issue 19, item 4: ≥ 100 systems of every kind, read exactly.
    let doc = reference();
    let sys = systems(&doc);
    assert!(sys.len() >= 100, "{} systems", sys.len());
    for kind in [
        "stable",
        "integrator",
        "rhp_zero",
        "negative_gain",
        "unstable",
        "ill_conditioned",
        "repeated",
        "axis",
    ] {
        let count = sys.iter().filter(|s| s.v["kind"] == kind).count();
        assert!(count >= 10, "{count} systems of kind {kind}");
    }
    assert!(sys.iter().any(|s| s.n == 10) && sys.iter().any(|s| s.n == 1));
}

#[test]
fn reference_poles_and_zeros_within_root_conditioning() {
    // A root r of multiplicity q moves by at most (ε·κ_q)^{1/q} under relative coefficient
    // perturbations of ε, κ_q = Σ|c_k||r|^k / |p^(q)(r)/q!| (the reference's kappa). The
    // balanced companion eigenvalue problem is backward stable normwise; C = 64n covers the
    // Hessenberg QR's backward error on balanced companion matrices of degree n.
    let doc = reference();
    let mut rep = Report::new("poles and zeros");
    for s in systems(&doc) {
        for (which, computed) in [("poles", s.g.poles().unwrap()), ("zeros", s.g.zeros().unwrap())] {
            let want = s.v[which].as_array().unwrap();
            let expanded: Vec<(Complex64, f64, i32)> = want
                .iter()
                .flat_map(|r| {
                    let q = r["mult"].as_i64().unwrap() as i32;
                    let z = Complex64::new(f(&r["re"]), f(&r["im"]));
                    std::iter::repeat_n((z, f(&r["kappa"]), q), q as usize)
                })
                .collect();
            if expanded.len() != computed.len() {
                rep.fail(format!(
                    "{}: {} {} computed, {} in the reference",
                    s.name,
                    computed.len(),
                    which,
                    expanded.len()
                ));
                continue;
            }
            // greedy nearest matching
            let mut used = vec![false; computed.len()];
            for (z, kappa, q) in expanded {
                let (j, d) = computed
                    .iter()
                    .enumerate()
                    .filter(|(j, _)| !used[*j])
                    .map(|(j, c)| (j, (c - z).norm()))
                    .min_by(|a, b| a.1.total_cmp(&b.1))
                    .unwrap();
                used[j] = true;
                let c = 64.0 * s.n as f64;
                let tol = (c * EPS * kappa).powf(1.0 / q as f64) + 4.0 * EPS * z.norm();
                rep.check(d, tol, || format!("{} {which} {z} (q = {q}, κ = {kappa:.2e})", s.name));
            }
        }
    }
    rep.finish();
}

#[test]
fn reference_dc_gain_is_exact() {
    // G(0) = N(0)/D(0): one correctly rounded division, equal to the reference's correctly
    // rounded exact quotient.
    let doc = reference();
    for s in systems(&doc) {
        let want = s.v["dc_gain"].as_f64();
        match (s.g.dc_gain(), want) {
            (Some(g), Some(w)) => assert_eq!(g, w, "{}", s.name),
            (None, None) => {}
            (g, w) => panic!("{}: dc gain {g:?}, reference {w:?}", s.name),
        }
    }
}

#[test]
fn reference_frequency_response_within_conditioning() {
    // §16.2: G(jω) from the coefficients has relative error ≤ C·ε·(κ_G + 1), κ_G =
    // Σ|c_k ω^k|/|N(jω)| + Σ|d_k ω^k|/|D(jω)|; at an imaginary-axis pole |G| = +∞ (no NaN),
    // at a zero G = 0.
    let doc = reference();
    let mut rep = Report::new("freqresp");
    for s in systems(&doc) {
        let pts = s.v["freq"].as_array().unwrap();
        let w: Vec<f64> = pts.iter().map(|p| f(&p["w"])).collect();
        let g = s.g.freqresp(&w).unwrap();
        for (p, gk) in pts.iter().zip(&g) {
            let at = || format!("{} at ω = {}", s.name, f(&p["w"]));
            if gk.re.is_nan() || gk.im.is_nan() {
                rep.fail(format!("{}: NaN", at()));
            } else if p.get("pole").is_some() {
                if gk.norm() != f64::INFINITY {
                    rep.fail(format!("{}: pole, got {gk}", at()));
                }
            } else if p.get("zero").is_some() {
                if *gk != Complex64::new(0.0, 0.0) {
                    rep.fail(format!("{}: zero, got {gk}", at()));
                }
            } else {
                let want = Complex64::new(f(&p["re"]), f(&p["im"]));
                let tol = horner_multiple(s.n) * EPS * (f(&p["kappa_g"]) + 1.0);
                rep.check((gk - want).norm() / want.norm(), tol, at);
            }
        }
    }
    rep.finish();
}

/// True when some root of N or D lies within its own error bound of the imaginary axis, so
/// that the book's branch of the continuous phase (RHP roots on [0, 2π)) is undecidable there.
fn axis_ambiguous(s: &Sys) -> bool {
    ["poles", "zeros"].iter().any(|which| {
        s.v[*which].as_array().unwrap().iter().any(|r| {
            let re = f(&r["re"]);
            let q = r["mult"].as_i64().unwrap() as f64;
            let tol = (64.0 * s.n as f64 * EPS * f(&r["kappa"])).powf(1.0 / q);
            re.abs() <= tol && !(re == 0.0 && f(&r["im"]) == 0.0)
        })
    })
}

#[test]
fn reference_bode_within_conditioning() {
    // §16.3, (16.6.2): ln|G| to C·ε·(κ_mag + 1) absolute, the phase to C·ε·(κ_phase + 1) rad on
    // the book's continuous branch (exactly the reference's multiple of 360°, except where a
    // root sits within its error of the imaginary axis: then modulo 360°). At an axis pole:
    // +∞ dB and the limiting phase from above.
    let doc = reference();
    let mut mag = Report::new("bode magnitude");
    let mut ph = Report::new("bode phase");
    for s in systems(&doc) {
        let pts = s.v["freq"].as_array().unwrap();
        let w: Vec<f64> = pts.iter().map(|p| f(&p["w"])).collect();
        let b = s.g.bode(&w).unwrap();
        let ambiguous = axis_ambiguous(&s);
        let c = horner_multiple(s.n);
        for (k, p) in pts.iter().enumerate() {
            let at = || format!("{} at ω = {}", s.name, w[k]);
            let (db, phase) = (b.magnitude_db[k], b.phase_deg[k]);
            if db.is_nan() || phase.is_nan() {
                mag.fail(format!("{}: NaN", at()));
                continue;
            }
            let want_phase = f(&p["phase_deg"]);
            let phase_err = |tol_deg: f64| {
                let d = phase - want_phase;
                (if ambiguous { (d - 360.0 * (d / 360.0).round()).abs() } else { d.abs() }) / tol_deg
            };
            if p.get("pole").is_some() || p.get("zero").is_some() {
                let inf = if p.get("pole").is_some() { f64::INFINITY } else { f64::NEG_INFINITY };
                if db != inf {
                    mag.fail(format!("{}: {} dB at an axis pole/zero", at(), db));
                }
                // the limit phase: a few roundings of the factor angles
                ph.check(phase_err(1e-9), 1.0, at);
                continue;
            }
            let ln = db * (LN_10 / 20.0);
            let want_ln = f(&p["ln_mag"]);
            mag.check(
                (ln - want_ln).abs(),
                c * EPS * (f(&p["kappa_mag"]) + 1.0) + 4.0 * EPS * want_ln.abs(),
                at,
            );
            let tol_deg =
                (c * EPS * (f(&p["kappa_phase"]) + 1.0)).to_degrees() + 4.0 * EPS * want_phase.abs();
            ph.check(phase_err(tol_deg), 1.0, at);
        }
    }
    mag.finish();
    ph.finish();
}

#[test]
fn reference_margins_as_python_control_defines_them() {
    // Issue 19, item 1: every phase crossover (with GM), gain crossover (with PM) and
    // stationary minimum of |1 + L| (with the distance) of python-control 0.10's
    // `stability_margins(returnall=True)`, computed exactly; frequencies to C·ε·(κ_ω + 1)
    // relative, GM in dB and PM in degrees to C·ε·(κ + 1) absolute, distances relative. And the
    // selected margins follow python-control's rule on the reference lists.
    let doc = reference();
    let mut rep = Report::new("margins");
    for s in systems(&doc) {
        let m = s.g.margins().unwrap();
        let r = &s.v["margins"];
        let c = 2.0 * horner_multiple(s.n);
        let lists: [(&str, Vec<f64>); 3] = [
            ("phase_crossovers", m.phase_crossovers.iter().map(|x| x.omega).collect()),
            ("gain_crossovers", m.gain_crossovers.iter().map(|x| x.omega).collect()),
            ("stability_points", m.stability_points.iter().map(|x| x.omega).collect()),
        ];
        for (key, got) in &lists {
            let want = r[*key].as_array().unwrap();
            if got.len() != want.len() {
                rep.fail(format!(
                    "{}: {key}: {:?} computed, reference {:?}",
                    s.name,
                    got,
                    want.iter().map(|x| f(&x["w"])).collect::<Vec<_>>()
                ));
                continue;
            }
            for (k, (wg, x)) in got.iter().zip(want).enumerate() {
                let ww = f(&x["w"]);
                let at = || format!("{} {key}[{k}] ω = {ww}", s.name);
                let kw = x["kappa_w"].as_f64().unwrap_or(1e8);
                rep.check((wg - ww).abs(), c * EPS * (kw + 1.0) * ww.max(f64::MIN_POSITIVE), at);
                match *key {
                    "phase_crossovers" => {
                        let got = m.phase_crossovers[k];
                        match x["gm_db"].as_f64() {
                            None => {
                                if got.gain_margin != f64::INFINITY {
                                    rep.fail(format!("{}: GM {} for L = 0", at(), got.gain_margin));
                                }
                            }
                            Some(db) => {
                                let tol = c * EPS * (f(&x["kappa_gm_db"]) + 1.0) + 4.0 * EPS * db.abs();
                                rep.check((got.gain_margin_db - db).abs(), tol, || format!("{} GM dB", at()));
                                let gm = f(&x["gm"]);
                                let rel = tol * LN_10 / 20.0 + 4.0 * EPS;
                                rep.check((got.gain_margin - gm).abs() / gm, rel, || {
                                    format!("{} GM ratio", at())
                                });
                            }
                        }
                    }
                    "gain_crossovers" => {
                        let pm = f(&x["pm_deg"]);
                        let tol = c * EPS * (f(&x["kappa_pm_deg"]) + 1.0) + 4.0 * EPS * 180.0;
                        rep.check((m.gain_crossovers[k].phase_margin_deg - pm).abs(), tol, || {
                            format!("{} PM", at())
                        });
                    }
                    _ => {
                        let sm = f(&x["sm"]);
                        let got = m.stability_points[k].distance;
                        match x["kappa_sm"].as_f64() {
                            // a closed-loop pole on the axis: distance 0 up to the evaluation error
                            None => rep.check(got, c * EPS, || format!("{} SM = 0", at())),
                            Some(ks) => rep.check((got - sm).abs() / sm, c * EPS * (ks + 1.0), || {
                                format!("{} SM", at())
                            }),
                        }
                    }
                }
            }
        }
        // python-control's selection on the reference lists: min |ln GM| among finite GMs,
        // min |PM|, min distance; lowest ω on ties
        let pick = |key: &str, score: &dyn Fn(&Value) -> Option<f64>| -> Option<f64> {
            r[key]
                .as_array()
                .unwrap()
                .iter()
                .filter_map(|x| score(x).map(|sc| (f(&x["w"]), sc)))
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .map(|(w, _)| w)
        };
        let close = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(a), Some(b)) => (a - b).abs() <= 1e-9 * b.max(1e-300),
            (None, None) => true,
            _ => false,
        };
        let wpc = pick("phase_crossovers", &|x| x["gm"].as_f64().map(|g| g.ln().abs()));
        let wgc = pick("gain_crossovers", &|x| x["pm_deg"].as_f64().map(f64::abs));
        let wms = pick("stability_points", &|x| x["sm"].as_f64());
        if !(close(m.phase_crossover_omega(), wpc)
            && close(m.gain_crossover_omega(), wgc)
            && close(m.stability_margin().map(|p| p.omega), wms))
        {
            rep.fail(format!(
                "{}: selected ω (pc, gc, sm) = {:?} {:?} {:?}, python-control's rule gives {wpc:?} {wgc:?} {wms:?}",
                s.name,
                m.phase_crossover_omega(),
                m.gain_crossover_omega(),
                m.stability_margin().map(|p| p.omega)
            ));
        }
    }
    rep.finish();
}

/// The reference grid: 201 points with the dyadic step h (every t_k = k·h exact).
fn grid(s: &Sys) -> (Vec<f64>, usize, usize) {
    let t = &s.v["time"];
    let (h, n) = (f(&t["h"]), t["n"].as_u64().unwrap() as usize);
    let grid = time_grid(h * (n - 1) as f64, n).unwrap();
    for (k, tk) in grid.iter().enumerate() {
        assert_eq!(*tk, k as f64 * h, "t_k must be exact");
    }
    (grid, n, t["keep"].as_u64().unwrap() as usize)
}

/// The exact dyadic input of the reference: u_k = ((37k mod 17) − 8)/8.
fn input(n: usize) -> Vec<f64> {
    (0..n).map(|k| ((37 * k) % 17) as f64 / 8.0 - 1.0).collect()
}

#[test]
fn reference_time_responses_within_1e_12_kappa() {
    // Issue 19, item 3: step, impulse, initial (companion realisation, x0 from the reference)
    // and lsim with zero- and first-order hold agree with the 60-digit reference to
    // 1e-12·κ relative over the elapsed window (see the module documentation).
    let doc = reference();
    let mut reps: Vec<Report> =
        ["step", "impulse", "initial", "zoh", "foh"].into_iter().map(Report::new).collect();
    for s in systems(&doc) {
        let (t, n, keep) = grid(&s);
        let sys = StateSpace::from_tf(&s.g).unwrap();
        let u = input(n);
        let x0 = fvec(&s.v["time"]["x0"]);
        let zero = vec![0.0; sys.n_states()];
        let runs = [
            s.g.step(&t).unwrap(),
            s.g.impulse(&t).unwrap(),
            initial(&sys, &x0, &t).unwrap(),
            lsim(&sys, 0, &u, &t, &zero, Hold::Zoh, 0.0).unwrap(),
            lsim(&sys, 0, &u, &t, &zero, Hold::Foh, 0.0).unwrap(),
        ];
        for (rep, run) in reps.iter_mut().zip(&runs) {
            let r = &s.v["time"][rep.what];
            let (want, smax) = (fvec(&r["y"]), fvec(&r["s_max"]));
            for (j, (yw, sm)) in want.iter().zip(&smax).enumerate() {
                let k = j * keep;
                let got = run.y[0][k];
                rep.check((got - yw).abs(), 1e-12 * sm + f64::MIN_POSITIVE, || {
                    format!("{} at t = {} (y = {yw:e}, S = {sm:e})", s.name, t[k])
                });
            }
        }
    }
    // print every summary before the first assertion fails
    let failed: Vec<&str> = reps.iter().filter(|r| !r.failures.is_empty()).map(|r| r.what).collect();
    for rep in &reps {
        println!(
            "{}: {} checks, {} beyond the bound, worst error/tolerance {:.3e} at {}",
            rep.what,
            rep.checks,
            rep.failures.len(),
            rep.worst,
            rep.worst_at
        );
    }
    assert!(
        failed.is_empty(),
        "failures in {failed:?}: {:?}",
        reps.iter().flat_map(|r| r.failures.iter().take(3)).collect::<Vec<_>>()
    );
}

#[test]
fn reference_time_responses_attained_accuracy() {
    // The bound above is the issue's; this records how far inside it the responses are, as a
    // multiple of ε·max S over the window (printed; asserted at 1e4·ε·S, 44× tighter than the
    // issue's 1e-12·S, so a regression towards the old 8e-7 errors shows here first).
    let doc = reference();
    let mut rep = Report::new("time responses in ε·S");
    for s in systems(&doc) {
        let (t, n, keep) = grid(&s);
        let sys = StateSpace::from_tf(&s.g).unwrap();
        let u = input(n);
        let zero = vec![0.0; sys.n_states()];
        for (mode, run) in [
            ("step", s.g.step(&t).unwrap()),
            ("zoh", lsim(&sys, 0, &u, &t, &zero, Hold::Zoh, 0.0).unwrap()),
            ("foh", lsim(&sys, 0, &u, &t, &zero, Hold::Foh, 0.0).unwrap()),
        ] {
            let r = &s.v["time"][mode];
            for (j, (yw, sm)) in fvec(&r["y"]).iter().zip(fvec(&r["s_max"])).enumerate() {
                let k = j * keep;
                rep.check((run.y[0][k] - yw).abs(), 1e4 * EPS * sm + f64::MIN_POSITIVE, || {
                    format!("{} {mode} t = {}", s.name, t[k])
                });
            }
        }
    }
    rep.finish();
}
