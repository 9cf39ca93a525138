//! How many bytes a command will write, bounded before it runs, so that an output larger
//! than `--max-output-bytes` is refused with an error at the scene's `samples` before any
//! work is done; the [`crate::sink::Sink`] then counts the bytes actually written.
//!
//! The bounds follow the writers:
//! * a CSV number is written in the shortest round-trip form `{:e}`, at most 24 characters
//!   (`-2.2250738585072014e-308`) and a separator: [`NUM`] bytes per value;
//! * a figure draws each series as one polyline whose thinned points are each at most two
//!   pixel coordinates clamped to ±10⁴ with two decimals (`-10000.00,-10000.00 `, [`POINT`]
//!   bytes; thinning only drops points), plus a fixed frame (axes, ticks, labels: [`FIGURE`]
//!   and six bytes per character of text, the worst case of SVG escaping) and per series a
//!   legend entry and at most [`crate::report`]'s 40 point markers ([`SERIES`]);
//! * summaries are bounded per column, output and invariant.
//!
//! Book: — (reporting).

use vectrix_scene::spec::EffectSpec;
use vectrix_scene::{MAX_CONTACT_EVENTS, Scene};

use crate::report::belongs;
use crate::sink::Limits;

/// Bytes of one CSV value and its separator.
pub(crate) const NUM: u64 = 25;
/// Bytes of one drawn point of a polyline.
pub(crate) const POINT: u64 = 20;
/// Bytes of a figure's frame: axes, grid, ticks and their labels, clip path.
pub(crate) const FIGURE: u64 = 32 << 10;
/// Bytes of a series besides its points: polyline element, legend entry, markers.
pub(crate) const SERIES: u64 = 8 << 10;
/// Bytes of a unit label in a header (`slug*ft^2/s`), bounded generously.
const UNIT: u64 = 32;
/// Bytes of one line of a manifest (a relative path).
const MANIFEST_LINE: u64 = 160;

/// An upper bound of what one command writes: data files, and the summaries that are always
/// written (summary.json, sweep.csv, the marker).
#[derive(Debug, Clone, Default)]
pub(crate) struct Estimate {
    /// The largest parts by name (`trajectory.csv`, `figures`), for the message.
    pub parts: Vec<(String, u64)>,
    /// Data files.
    pub data: u64,
    /// Summaries and the marker.
    pub summaries: u64,
}

impl Estimate {
    /// Adds a data file (or a group of them) of at most `n` bytes.
    pub(crate) fn data(&mut self, name: impl Into<String>, n: u64) {
        self.data = self.data.saturating_add(n);
        self.parts.push((name.into(), n));
    }

    fn summary(&mut self, n: u64) {
        self.summaries = self.summaries.saturating_add(n);
    }

    fn add(&mut self, other: Estimate) {
        self.data = self.data.saturating_add(other.data);
        self.summaries = self.summaries.saturating_add(other.summaries);
        for (name, n) in other.parts {
            match self.parts.iter_mut().find(|(m, _)| *m == name) {
                Some((_, m)) => *m = m.saturating_add(n),
                None => self.parts.push((name, n)),
            }
        }
    }

    /// Everything.
    pub fn total(&self) -> u64 {
        self.data.saturating_add(self.summaries)
    }

    /// The limits of a sink for this output under `max_bytes`, or a message saying what would
    /// be written and what is valid.
    pub fn limits(&self, max_bytes: u64) -> Result<Limits, String> {
        if self.total() <= max_bytes {
            return Ok(Limits { max_bytes, reserve: self.summaries });
        }
        let mut parts = self.parts.clone();
        parts.sort_by_key(|p| std::cmp::Reverse(p.1));
        let shown: Vec<String> = parts.iter().take(3).map(|(n, b)| format!("{n} {}", human(*b))).collect();
        Err(format!(
            "the output would take up to {} ({}{}); valid: at most max_output_bytes = {max_bytes} bytes ({}; set \
             with --max-output-bytes), or fewer samples or outputs",
            human(self.total()),
            shown.join(", "),
            if parts.len() > 3 { ", …" } else { "" },
            human(max_bytes)
        ))
    }
}

/// `1.2 GB`, `340 kB`, `12 bytes`.
pub(crate) fn human(n: u64) -> String {
    let x = n as f64;
    match n {
        0..1000 => format!("{n} bytes"),
        1000..1_000_000 => format!("{:.1} kB", x / 1e3),
        1_000_000..1_000_000_000 => format!("{:.1} MB", x / 1e6),
        _ => format!("{:.1} GB", x / 1e9),
    }
}

fn mul(a: u64, b: u64) -> u64 {
    a.saturating_mul(b)
}

/// A figure with the given texts and series (name length, points).
pub(crate) fn figure(text_len: usize, series: impl IntoIterator<Item = (usize, usize)>) -> u64 {
    series.into_iter().fold(FIGURE + mul(6, text_len as u64), |acc, (name, points)| {
        acc.saturating_add(SERIES + mul(6, name as u64)).saturating_add(mul(POINT, points as u64))
    })
}

/// A CSV of `rows` rows of `values` values each, under a header of `header` bytes.
fn csv(rows: usize, values: usize, header: u64, per_value: u64) -> u64 {
    header.saturating_add(mul(mul(rows as u64, values as u64), per_value))
}

/// Whether a scene can write contacts.csv.
fn has_contacts(scene: &Scene) -> bool {
    scene.spec().effects.iter().any(|e| {
        matches!(
            e,
            EffectSpec::ContactSpheres { .. }
                | EffectSpec::ContactPlane { .. }
                | EffectSpec::JointStop { .. }
        )
    })
}

/// Files one body-scene run writes (see [`crate::report::write_scene`]).
pub(crate) fn scene(s: &Scene) -> Estimate {
    let spec = s.spec();
    let rows = spec.samples + 1;
    let columns = s.columns();
    let mut e = Estimate::default();
    let header = columns.iter().map(|c| c.len() as u64 + UNIT + 4).sum::<u64>() + 16;
    e.data("trajectory.csv", csv(rows, columns.len() + 1, header, NUM));
    if has_contacts(s) {
        e.data("contacts.csv", csv(MAX_CONTACT_EVENTS, 5, 128, NUM));
    }
    let name = spec.name.len() + 64;
    let mut figures = 0u64;
    let mut files = 3u64;
    for o in &spec.outputs {
        let cols: Vec<&String> = columns.iter().filter(|c| belongs(c, o)).collect();
        figures = figures.saturating_add(figure(name + 2 * o.len(), cols.iter().map(|c| (c.len(), rows))));
        files += 1;
        if o.starts_with("position:") {
            figures = figures.saturating_add(figure(name + 2 * o.len(), [(o.len(), rows)]));
            files += 1;
        }
    }
    e.data("figures", figures);
    let summary = columns.iter().map(|c| c.len() as u64 + UNIT + 96).sum::<u64>()
        + spec.outputs.iter().map(|o| 2 * o.len() as u64 + 48).sum::<u64>()
        + (16 << 10);
    // the trim's unknowns: a name (an item path, bounded by the file) and a number each
    let trim = s.trim_report().map_or(0, |t| t.free.iter().map(|f| 6 * f.len() as u64 + 2 * NUM + 16).sum());
    e.summary(summary.saturating_add(trim));
    e.summary(mul(files, MANIFEST_LINE));
    e
}

/// An upper bound of the bytes of [`crate::view::scene_page`] for `scene` (the bound `vectrix
/// run` checks against `--max-output-bytes` before it runs).
pub fn scene_page_bound(scene: &Scene) -> u64 {
    scene_view(scene)
}

/// view.html of a body-scene run (see [`crate::view`]): at most [`crate::view::frames`]
/// instants of every body's pose and of the first heads-up columns, whatever `samples` is.
pub(crate) fn scene_view(s: &Scene) -> u64 {
    let spec = s.spec();
    let bodies = spec.bodies.len();
    let rows = crate::view::frames(spec.samples + 1, bodies);
    let columns = s.columns();
    let hud = columns.len().min(crate::view::MAX_HUD_COLUMNS);
    let text = spec.name.len()
        + spec.bodies.iter().map(|b| 2 * b.name.len()).sum::<usize>()
        + columns.iter().take(hud).map(|c| c.len() + UNIT as usize).sum::<usize>()
        + spec.frames.iter().map(|f| f.name.len()).sum::<usize>()
        + spec.loops.len() * (vectrix_scene::MAX_NAME_CHARS + 16);
    let items = bodies + spec.loops.len() + spec.effects.len() + spec.frames.len();
    crate::view::page_bound(rows * bodies, rows, hud, text, items)
}

/// Files of a sweep: every run's folder, one overlay per output, sweep.csv. `labels` holds
/// the length of each run's legend suffix (`effects.0.k=2`), `params` and `checks` count the
/// columns of sweep.csv.
pub(crate) fn sweep(scenes: &[&Scene], labels: &[usize], params: usize) -> Estimate {
    let mut e = Estimate::default();
    for s in scenes {
        let mut one = scene(s);
        one.summary(mul(8, MANIFEST_LINE));
        e.add(one);
    }
    let Some(first) = scenes.first() else { return e };
    let name = first.spec().name.len() + 64;
    for o in &first.spec().outputs {
        let series = scenes.iter().zip(labels).flat_map(|(s, l)| {
            let rows = s.spec().samples + 1;
            s.columns()
                .into_iter()
                .filter(|c| belongs(c, o))
                .map(move |c| (c.len() + l + 4, rows))
                .collect::<Vec<_>>()
        });
        let f = figure(name + 2 * o.len(), series);
        e.data("overlay figures", f);
    }
    let header = 64 + (params as u64) * 64 + 4 * 64;
    e.summary(csv(scenes.len(), 1 + params + 6 + 4, header, NUM));
    e
}

#[cfg(test)]
mod tests;
