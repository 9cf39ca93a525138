//! `vectrix sweep SCENE --param PATH=v1,v2,…`: the Cartesian product of parameter values,
//! each a full scene run, in parallel on all cores (rayon).
//!
//! Book: — (parameter studies of the scenes of §7.11, ch. 6).

use std::io::Write;
use std::path::Path;

use rayon::prelude::*;
use vectrix_dynamics::scene::Scene;

/// One parameter: its dotted path and values.
fn parse_param(p: &str) -> Result<(String, Vec<f64>), String> {
    let (path, values) = p.split_once('=').ok_or_else(|| format!("`{p}`: expected PATH=v1,v2,…"))?;
    let vals = values
        .split(',')
        .map(|v| v.trim().parse::<f64>().map_err(|_| format!("`{v}` in `{p}` is not a number")))
        .collect::<Result<Vec<_>, _>>()?;
    if vals.is_empty() || path.is_empty() {
        return Err(format!("`{p}`: expected PATH=v1,v2,…"));
    }
    Ok((path.to_string(), vals))
}

/// Sets the number at a dotted path (`effects.0.k`) of a TOML document.
fn set(doc: &mut toml::Value, path: &str, x: f64) -> Result<(), String> {
    let mut cur = doc;
    for seg in path.split('.') {
        cur = match cur {
            toml::Value::Table(t) => t.get_mut(seg).ok_or_else(|| format!("`{path}`: no key `{seg}`"))?,
            toml::Value::Array(a) => {
                let i: usize = seg.parse().map_err(|_| format!("`{path}`: `{seg}` must be an index"))?;
                let n = a.len();
                a.get_mut(i).ok_or_else(|| format!("`{path}`: index {i} out of 0..{n}"))?
            }
            _ => return Err(format!("`{path}`: `{seg}` is below a value")),
        };
    }
    match cur {
        toml::Value::Float(_) | toml::Value::Integer(_) => {
            *cur = if matches!(cur, toml::Value::Integer(_)) && x.fract() == 0.0 {
                toml::Value::Integer(x as i64)
            } else {
                toml::Value::Float(x)
            };
            Ok(())
        }
        _ => Err(format!("`{path}` is not a number")),
    }
}

/// `vectrix sweep`.
pub fn sweep(
    out: &mut impl Write,
    path: &Path,
    params: &[String],
    dir: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    crate::check::load(path)?;
    let doc: toml::Value = toml::from_str(&text)?;
    let params = params.iter().map(|p| parse_param(p)).collect::<Result<Vec<_>, _>>()?;
    // Cartesian product of the values
    let mut combos: Vec<Vec<(String, f64)>> = vec![vec![]];
    for (p, vals) in &params {
        combos = combos
            .into_iter()
            .flat_map(|c| vals.iter().map(move |v| [c.clone(), vec![(p.clone(), *v)]].concat()))
            .collect();
    }
    let base = doc.get("name").and_then(|n| n.as_str()).unwrap_or("scene").to_string();
    let sweep_dir = dir.join(format!("{base}-sweep"));
    let results: Vec<Result<String, String>> = combos
        .par_iter()
        .map(|combo| -> Result<String, String> {
            let mut d = doc.clone();
            let label: Vec<String> = combo.iter().map(|(p, v)| format!("{p}={v}")).collect();
            for (p, v) in combo {
                set(&mut d, p, *v)?;
            }
            let name = format!("{base}_{}", label.join("_"));
            if let toml::Value::Table(t) = &mut d {
                t.insert("name".into(), toml::Value::String(name.clone()));
            }
            let src = toml::to_string(&d).map_err(|e| e.to_string())?;
            let scene = Scene::from_toml(&src, &name).map_err(|e| e.to_string())?;
            let run = crate::run::simulate(&scene, true).map_err(|e| e.to_string())?;
            let dest = crate::output::write(&sweep_dir, &scene, &run).map_err(|e| e.to_string())?;
            let drift: Vec<String> =
                run.drift.iter().map(|x| format!("{} {:.1e}", x.invariant.name(), x.max_rel)).collect();
            Ok(format!(
                "| {} | {:.3} | {} | {} | {} |",
                label.join(", "),
                run.work.wall_seconds,
                run.work.fevals,
                drift.join("; "),
                dest.display()
            ))
        })
        .collect();
    writeln!(out, "| parameters | wall [s] | f-evals | drift | output |\n|---|---|---|---|---|")?;
    let mut failed = Vec::new();
    for r in results {
        match r {
            Ok(line) => writeln!(out, "{line}")?,
            Err(e) => {
                writeln!(out, "| error: {e} | | | | |")?;
                failed.push(e);
            }
        }
    }
    if let Some(first) = failed.first() {
        return Err(format!("{} of {} sweep runs failed; first: {first}", failed.len(), combos.len()).into());
    }
    Ok(())
}
