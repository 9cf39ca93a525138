//! `vectrix linearize SCENE`: the linear model of a scene about its initial state
//! (`Scene::linearize`; after `[trim]`, about the trimmed state), written as
//! `<out>/<name>/linearization.json`, `poles.svg` and, with inputs and outputs, `bode.svg`; the
//! modes are printed.
//!
//! Book: §12.6 (linearization), §15.7 (state space), §16.2 (Bode).

use std::io::Write;
use std::path::Path;

use vectrix_lti::{StateSpace, logspace};
use vectrix_plot::control;
use vectrix_scene::LinearModel;

use crate::input::load;
use crate::output::{BoxError, not_inside, write_files};
use crate::sink::Limits;

/// Most Bode curves drawn (input–output pairs); the JSON holds every pair.
const MAX_BODE_CURVES: usize = 12;

/// `vectrix linearize`.
pub(crate) fn linearize(
    out: &mut impl Write,
    path: &Path,
    dir: &Path,
    max_bytes: u64,
) -> Result<(), BoxError> {
    let model = load(path)?.scene.linearize()?;
    not_inside(path, dir, &model.scene)?;
    let files = render(&model)?;
    let dest = write_files(dir, &model.scene, Limits { max_bytes, reserve: 0 }, &files)?;
    print_modes(out, &model)?;
    writeln!(out, "wrote {}", dest.display())?;
    Ok(())
}

/// linearization.json, poles.svg and (with inputs and outputs) bode.svg.
fn render(m: &LinearModel) -> Result<Vec<(&'static str, String)>, BoxError> {
    let mut files = vec![("linearization.json", serde_json::to_string_pretty(m)? + "\n")];
    let poles: Vec<_> = m.eigenvalues.iter().map(|[re, im]| nalgebra::Complex::new(*re, *im)).collect();
    let title = format!("{}: eigenvalues of A", m.scene);
    files.push(("poles.svg", control::pole_zero_map(&title, &poles, &[])?.to_svg()?));
    if !m.inputs.is_empty() && !m.outputs.is_empty() {
        let sys = StateSpace::new(m.a.clone(), m.b.clone(), m.c.clone(), m.d.clone())?;
        let w = logspace(-2.0, 2.0, 400)?;
        let mut curves = Vec::new();
        'pairs: for (j, input) in m.inputs.iter().enumerate() {
            for (i, output) in m.outputs.iter().enumerate() {
                if curves.len() == MAX_BODE_CURVES {
                    break 'pairs;
                }
                let g = sys.to_tf(i, j)?;
                // an output the input does not reach has G = 0: no curve to draw
                if g.num().is_zero() {
                    continue;
                }
                curves.push((format!("{output} ← {input}"), g.bode(&w)?));
            }
        }
        if !curves.is_empty() {
            let named: Vec<(&str, _)> = curves.iter().map(|(n, r)| (n.as_str(), r)).collect();
            let title = format!("{}: frequency response about the initial state", m.scene);
            files.push(("bode.svg", control::bode(&title, &named, None)?.to_svg()?));
        }
    }
    Ok(files)
}

fn print_modes(out: &mut impl Write, m: &LinearModel) -> std::io::Result<()> {
    writeln!(
        out,
        "linearized `{}` about its initial state{}: {} states, {} inputs, {} outputs",
        m.scene,
        if m.steady { " (a steady motion)" } else { "" },
        m.state.len(),
        m.inputs.len(),
        m.outputs.len()
    )?;
    if !m.residual.ok {
        writeln!(
            out,
            "  NOTE: not {}: |v₀|∞ = {:.3e}, |v̇₀|∞ = {:.3e}; the model describes small motions about a state that \
             itself moves",
            if m.steady { "a steady motion" } else { "an equilibrium" },
            m.residual.velocity,
            m.residual.acceleration
        )?;
    }
    for md in &m.modes {
        let [re, im] = md.eigenvalue;
        writeln!(
            out,
            "  λ = {re:+.6e} {} {:.6e}j  ωn = {:.6} rad/s  ζ = {}  τ = {}  ({})",
            if im == 0.0 { "+" } else { "±" },
            im,
            md.natural_frequency,
            md.damping_ratio.map_or("—".to_string(), |z| format!("{z:.4}")),
            md.time_constant.map_or("—".to_string(), |t| format!("{t:.4} s")),
            md.dominant_state
        )?;
    }
    Ok(())
}
