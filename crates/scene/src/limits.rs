//! What a scene's run section may ask for, checked before anything runs: the solver, the
//! sizes (duration, samples, samples × columns, wall time) and the corners of the load
//! profiles, which become step ends.
//!
//! Book: §4.11 (integration).

use vectrix_ode::Method;

use super::SceneError;
use super::parts::Src;
use super::spec::SceneSpec;

/// Default bound on the steps of a run (accepted + rejected).
pub const DEFAULT_MAX_STEPS: usize = 10_000_000;
/// Most output samples of a scene (rows of trajectory.csv after the first).
pub const MAX_SAMPLES: usize = 1_000_000;
/// Most output values of a scene (rows × columns), which bounds its memory (8 bytes each).
pub const MAX_SAMPLE_VALUES: usize = 50_000_000;

/// The solver a scene asks for: `method` (with the reason, "named"), else the explicit method
/// of the accuracy table for `accuracy` (default 1e-6; the stiffness test may switch it to
/// RADAU5 once the scene is built, `Scene::choose_method`); with the scene's step budget.
pub(crate) fn solver(spec: &SceneSpec, src: &Src) -> Result<(Method, Option<String>), SceneError> {
    let (a, named) = match super::stiff::named(spec, src)? {
        Some((m, why)) => (m, Some(why)),
        None => (super::stiff::from_accuracy(spec, src)?, None),
    };
    let max_steps = spec.max_steps.unwrap_or(DEFAULT_MAX_STEPS);
    if max_steps == 0 {
        return Err(src.invalid("max_steps", "max_steps = 0; valid: ≥ 1"));
    }
    Ok((a.with_max_steps(max_steps), named))
}

/// Checks the run's sizes: duration, samples (and samples × columns), wall-time budget.
pub(crate) fn check_bounds(
    spec: &SceneSpec,
    built: &super::build::Built,
    outputs: &[super::outputs::Output],
    src: &Src,
) -> Result<(), SceneError> {
    if !(spec.duration > 0.0 && spec.duration.is_finite()) {
        return Err(
            src.invalid("duration", format!("duration = {} s; valid: a finite number > 0", spec.duration))
        );
    }
    if !(1..=MAX_SAMPLES).contains(&spec.samples) {
        return Err(src.invalid("samples", format!("samples = {}; valid: 1 ..= {MAX_SAMPLES}", spec.samples)));
    }
    let columns = super::outputs::count_columns(outputs, built);
    if (spec.samples + 1).saturating_mul(columns.max(1)) > MAX_SAMPLE_VALUES {
        return Err(src.invalid(
            "samples",
            format!(
                "samples = {} with {columns} output columns is {} values; valid: (samples + 1) × columns ≤ \
                 {MAX_SAMPLE_VALUES}",
                spec.samples,
                (spec.samples + 1).saturating_mul(columns)
            ),
        ));
    }
    check_breakpoints(spec, src)?;
    if let Some(w) = spec.max_wall_seconds
        && !(w > 0.0 && w.is_finite())
    {
        return Err(
            src.invalid("max_wall_seconds", format!("max_wall_seconds = {w}; valid: a finite number > 0"))
        );
    }
    Ok(())
}

/// The corners and jumps of the load profiles are step ends: two of them (or one and t = 0 or
/// the end) closer than the time resolution 64 ε · duration, yet distinct, would need a step
/// below round-off. Refused at the later one, with what would be valid.
fn check_breakpoints(spec: &SceneSpec, src: &Src) -> Result<(), SceneError> {
    let resolution = 64.0 * f64::EPSILON * spec.duration;
    let mut times: Vec<(f64, String)> = vec![(0.0, String::new()), (spec.duration, String::new())];
    times.extend(profile_corners(spec));
    times.retain(|(t, _)| (0.0..=spec.duration).contains(t));
    times.sort_by(|a, b| a.0.total_cmp(&b.0));
    for w in times.windows(2) {
        let ((t1, p1), (t2, p2)) = (&w[0], &w[1]);
        if t2 > t1 && t2 - t1 < resolution {
            let (path, other) = if p2.is_empty() {
                (p1, "the end")
            } else {
                (p2, if p1.is_empty() { "t = 0" } else { p1.as_str() })
            };
            return Err(src.invalid(
                path.as_str(),
                format!(
                    "a profile corner {:e} s from {other}: closer than the time resolution 64 ε × duration = \
                     {resolution:e} s, so no integrator step fits between them; valid: the same time, or times at \
                     least {resolution:e} s apart",
                    t2 - t1
                ),
            ));
        }
    }
    Ok(())
}

/// Times in (0, duration) where an applied load profile is discontinuous or has a kink.
pub(crate) fn breakpoints(spec: &SceneSpec) -> Vec<f64> {
    let mut out: Vec<f64> = profile_corners(spec).into_iter().map(|(t, _)| t).collect();
    out.retain(|&t| t > 0.0 && t < spec.duration);
    out.sort_by(f64::total_cmp);
    out.dedup();
    out
}

/// Every corner and jump of the applied-load profiles, with the item path of the key that
/// declares it (`effects[k].profile.at`, `.t0`, `.t1`, `.t[i]`), in declaration order.
fn profile_corners(spec: &SceneSpec) -> Vec<(f64, String)> {
    let mut out = Vec::new();
    for (k, e) in spec.effects.iter().enumerate() {
        for (key, p) in e.profiles() {
            out.extend(p.corners().into_iter().map(|(t, at)| (t, format!("effects[{k}].{key}.{at}"))));
        }
    }
    out
}
