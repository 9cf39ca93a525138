//! Shared by the stiff integrator tests (radau5.rs, bdf.rs): Robertson's kinetics with its
//! Jacobian (from the harness), the stored scipy reference (tests/data/stiff_reference.json, made by
//! scripts/stiff_reference.py) and NaN-propagating error measures.
//!
//! Book: §4.11; HW §IV.1 (Robertson, (1.4)).
#![allow(dead_code)]

/// max |x| that is NaN when any x is NaN (a plain `f64::max` fold would skip NaN).
pub fn nan_max(xs: impl IntoIterator<Item = f64>) -> f64 {
    xs.into_iter().fold(0.0, |m, x| if x.is_nan() || m.is_nan() { f64::NAN } else { m.max(x) })
}

pub use vectrix_ode::harness::{robertson, robertson_jacobian as robertson_jac, vdpol, vdpol_jacobian};

/// (t_end, y(t_end), uncertainty) of a case of tests/data/stiff_reference.json.
pub fn reference(name: &str) -> (f64, Vec<f64>, f64) {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/data/stiff_reference.json");
    let text = std::fs::read_to_string(path).unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let case = v["cases"].as_array().unwrap().iter().find(|c| c["name"] == name).unwrap();
    let y = case["y"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    (case["t_end"].as_f64().unwrap(), y, case["uncertainty"].as_f64().unwrap())
}

/// Largest componentwise relative error (NaN if any is NaN).
pub fn rel_err(got: &[f64], want: &[f64]) -> f64 {
    nan_max(got.iter().zip(want).map(|(g, w)| ((g - w) / w).abs()))
}
