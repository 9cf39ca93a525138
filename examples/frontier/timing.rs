//! The timing rule of the frontier (the same as `frontier_common.median_time`): run once, then
//! repeat while the total stays under a budget, at most `MAX_REPEATS` runs; the median of
//! the wall times. Not a test: timings never are.

use std::time::Instant;

/// Most runs of one point.
pub const MAX_REPEATS: usize = 21;
/// Repeat while the total wall time stays under this [s].
pub const BUDGET: f64 = 0.5;

/// (median seconds, repeats, the last run's result).
pub fn median_time<T>(mut run: impl FnMut() -> T) -> (f64, usize, T) {
    let t0 = Instant::now();
    let mut out = run();
    let mut times = vec![t0.elapsed().as_secs_f64()];
    while times.len() < MAX_REPEATS && times.iter().sum::<f64>() + times[times.len() - 1] < BUDGET {
        let t0 = Instant::now();
        out = run();
        times.push(t0.elapsed().as_secs_f64());
    }
    (median(&mut times), times.len(), out)
}

/// The median (mean of the middle two for an even count).
pub fn median(x: &mut [f64]) -> f64 {
    x.sort_by(f64::total_cmp);
    let n = x.len();
    if n == 0 {
        f64::NAN
    } else if n % 2 == 1 {
        x[n / 2]
    } else {
        0.5 * (x[n / 2 - 1] + x[n / 2])
    }
}
