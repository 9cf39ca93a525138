//! Robertson and Van der Pol (mu = 1000): diffsol BDF / ESDIRK34 / TR-BDF2 (faer dense LU) beside
//! vectrix RADAU5, same sitting, same machine. Errors against scipy Radau at rtol 1e-13
//! (tests/data/stiff_reference.json of the vectrix worktree). Prints one JSON line per point.
use std::time::Instant;

use diffsol::{FaerLU, FaerMat, MatrixCommon, OdeBuilder, OdeSolverMethod};
use nalgebra::{Vector2, Vector3};
use vectrix_ode::Radau5;

type M = FaerMat<f64>;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

fn time<T>(mut run: impl FnMut() -> T) -> (f64, T) {
    let mut times = vec![];
    let mut out = run();
    let budget = Instant::now();
    for _ in 0..15 {
        let s = Instant::now();
        out = run();
        times.push(s.elapsed().as_secs_f64());
        if budget.elapsed().as_secs_f64() > 1.0 {
            break;
        }
    }
    (median(times), out)
}

fn rel_err(got: &[f64], want: &[f64]) -> f64 {
    got.iter().zip(want).map(|(g, w)| ((g - w) / w).abs()).fold(0.0, |m: f64, x| if x.is_nan() { f64::NAN } else { m.max(x) })
}

fn main() {
    let text = std::fs::read_to_string("REPO/tests/data/stiff_reference.json").unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let refy = |name: &str| -> (f64, Vec<f64>) {
        let c = v["cases"].as_array().unwrap().iter().find(|c| c["name"] == name).unwrap();
        (c["t_end"].as_f64().unwrap(), c["y"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect())
    };
    for k in 4..=10 {
        let rtol = 10f64.powi(-k);
        // Robertson on [0, 1e5]: atol scaled to y2 ~ 1e-5 (atol = 1e-6·rtol, as in HW)
        let (t_end, want) = refy("robertson_1e5");
        let atol = rtol * 1e-6;
        let prob = || {
            OdeBuilder::<M>::new()
                .rtol(rtol)
                .atol([atol])
                .rhs_implicit(
                    |x, _p, _t, y| {
                        y[0] = -0.04 * x[0] + 1e4 * x[1] * x[2];
                        y[1] = 0.04 * x[0] - 1e4 * x[1] * x[2] - 3e7 * x[1] * x[1];
                        y[2] = 3e7 * x[1] * x[1];
                    },
                    |x, _p, _t, v, y| {
                        y[0] = -0.04 * v[0] + 1e4 * v[1] * x[2] + 1e4 * x[1] * v[2];
                        y[1] = 0.04 * v[0] - 1e4 * v[1] * x[2] - 1e4 * x[1] * v[2] - 6e7 * x[1] * v[1];
                        y[2] = 6e7 * x[1] * v[1];
                    },
                )
                .init(|_p, _t, y| { y[0] = 1.0; y[1] = 0.0; y[2] = 0.0; }, 3)
                .build()
                .unwrap()
        };
        for method in ["bdf", "esdirk34", "tr_bdf2"] {
            let p = prob();
            let (secs, (y, steps)) = time(|| {
                let run = |r: Result<(M, Vec<f64>, _), _>| r.ok();
                match method {
                    "bdf" => { let mut s = p.bdf::<FaerLU<f64>>().unwrap(); let o = run(s.solve(t_end)); (o, s.get_statistics().number_of_steps) }
                    "esdirk34" => { let mut s = p.esdirk34::<FaerLU<f64>>().unwrap(); let o = run(s.solve(t_end)); (o, s.get_statistics().number_of_steps) }
                    _ => { let mut s = p.tr_bdf2::<FaerLU<f64>>().unwrap(); let o = run(s.solve(t_end)); (o, s.get_statistics().number_of_steps) }
                }
            });
            let err = y.map(|(ys, _, _)| { let c = ys.ncols() - 1; rel_err(&[ys[(0, c)], ys[(1, c)], ys[(2, c)]], &want) }).unwrap_or(f64::INFINITY);
            println!("{{\"problem\":\"robertson\",\"tool\":\"diffsol {method}\",\"rtol\":{rtol:e},\"err\":{err:e},\"secs\":{secs:e},\"steps\":{steps}}}");
        }
        let f = |_: f64, y: &Vector3<f64>| Vector3::new(-0.04 * y[0] + 1e4 * y[1] * y[2], 0.04 * y[0] - 1e4 * y[1] * y[2] - 3e7 * y[1] * y[1], 3e7 * y[1] * y[1]);
        let jac = |_: f64, y: &Vector3<f64>, j: &mut [f64]| j.copy_from_slice(&[-0.04, 1e4 * y[2], 1e4 * y[1], 0.04, -1e4 * y[2] - 6e7 * y[1], -1e4 * y[1], 0.0, 6e7 * y[1], 0.0]);
        let (secs, sol) = time(|| Radau5::new().rtol(rtol).atol(atol).solve_with_jacobian(f, jac, 0.0, &Vector3::new(1.0, 0.0, 0.0), t_end));
        let (err, steps) = sol.map(|s| (rel_err(s.last().as_slice(), &want), s.work.accepted + s.work.rejected)).unwrap_or((f64::INFINITY, 0));
        println!("{{\"problem\":\"robertson\",\"tool\":\"vectrix radau5\",\"rtol\":{rtol:e},\"err\":{err:e},\"secs\":{secs:e},\"steps\":{steps}}}");

        // Van der Pol mu = 1000 on [0, 3000], atol = rtol
        let (t_end, want) = (2.0, vec![1.706167732170483, -0.8928097010247975]); // Test Set VDPOL, eps = 1e-6
        let p = OdeBuilder::<M>::new()
            .rtol(rtol)
            .atol([rtol])
            .rhs_implicit(
                |x, _p, _t, y| { y[0] = x[1]; y[1] = 1e6 * ((1.0 - x[0] * x[0]) * x[1] - x[0]); },
                |x, _p, _t, v, y| { y[0] = v[1]; y[1] = 1e6 * ((-2.0 * x[0] * x[1] - 1.0) * v[0] + (1.0 - x[0] * x[0]) * v[1]); },
            )
            .init(|_p, _t, y| { y[0] = 2.0; y[1] = 0.0; }, 2)
            .build()
            .unwrap();
        for method in ["bdf", "esdirk34", "tr_bdf2"] {
            let (secs, (y, steps)) = time(|| {
                let run = |r: Result<(M, Vec<f64>, _), _>| r.ok();
                match method {
                    "bdf" => { let mut s = p.bdf::<FaerLU<f64>>().unwrap(); let o = run(s.solve(t_end)); (o, s.get_statistics().number_of_steps) }
                    "esdirk34" => { let mut s = p.esdirk34::<FaerLU<f64>>().unwrap(); let o = run(s.solve(t_end)); (o, s.get_statistics().number_of_steps) }
                    _ => { let mut s = p.tr_bdf2::<FaerLU<f64>>().unwrap(); let o = run(s.solve(t_end)); (o, s.get_statistics().number_of_steps) }
                }
            });
            let err = y.map(|(ys, _, _)| { let c = ys.ncols() - 1; rel_err(&[ys[(0, c)], ys[(1, c)]], &want) }).unwrap_or(f64::INFINITY);
            println!("{{\"problem\":\"vdp\",\"tool\":\"diffsol {method}\",\"rtol\":{rtol:e},\"err\":{err:e},\"secs\":{secs:e},\"steps\":{steps}}}");
        }
        let f = |_: f64, y: &Vector2<f64>| Vector2::new(y[1], 1e6 * ((1.0 - y[0] * y[0]) * y[1] - y[0]));
        let jac = |_: f64, y: &Vector2<f64>, j: &mut [f64]| j.copy_from_slice(&[0.0, 1.0, 1e6 * (-2.0 * y[0] * y[1] - 1.0), 1e6 * (1.0 - y[0] * y[0])]);
        let (secs, sol) = time(|| Radau5::new().rtol(rtol).atol(rtol).solve_with_jacobian(f, jac, 0.0, &Vector2::new(2.0, 0.0), t_end));
        let (err, steps) = sol.map(|s| (rel_err(s.last().as_slice(), &want), s.work.accepted + s.work.rejected)).unwrap_or((f64::INFINITY, 0));
        println!("{{\"problem\":\"vdp\",\"tool\":\"vectrix radau5\",\"rtol\":{rtol:e},\"err\":{err:e},\"secs\":{secs:e},\"steps\":{steps}}}");
        if rtol >= 1e-8 {
            let (secs, sol) = time(|| vectrix_ode::Adaptive::dop853().rtol(rtol).atol(rtol).max_steps(20_000_000).solve(f, 0.0, &Vector2::new(2.0, 0.0), t_end));
            let (err, steps) = sol.map(|s| (rel_err(s.last().as_slice(), &want), s.work.accepted + s.work.rejected)).unwrap_or((f64::INFINITY, 0));
            println!("{{\"problem\":\"vdp\",\"tool\":\"vectrix dop853\",\"rtol\":{rtol:e},\"err\":{err:e},\"secs\":{secs:e},\"steps\":{steps}}}");
        }
    }
}
