//! The suite's machinery: the hostile inputs, the watchdog and the `cases!` table.

use std::sync::mpsc;
use std::time::Duration;

/// How long one case may run before it counts as a hang. Generous (the machine is shared
/// and tests run at opt-level 1); a real hang never finishes.
pub const WATCHDOG: Duration = Duration::from_secs(20);

/// Run `body` on its own thread and fail if it has not finished within [`WATCHDOG`]:
/// a hang fails the test instead of stalling CI. A panic in the body fails the test with the
/// body's message.
pub fn watchdog<F: FnOnce() + Send + 'static>(name: &str, body: F) {
    let (tx, rx) = mpsc::channel();
    let handle = std::thread::Builder::new()
        .name(name.into())
        .spawn(move || {
            body();
            let _ = tx.send(());
        })
        .expect("spawn the case thread");
    match rx.recv_timeout(WATCHDOG) {
        Ok(()) => handle.join().expect("case thread"),
        Err(mpsc::RecvTimeoutError::Disconnected) => {
            // The body panicked: re-raise its payload.
            if let Err(payload) = handle.join() {
                std::panic::resume_unwind(payload);
            }
        }
        Err(mpsc::RecvTimeoutError::Timeout) => {
            panic!("case {name} did not finish within {WATCHDOG:?}: a hang")
        }
    }
}

/// The hostile scalars every case draws from: zero, ±0, the smallest subnormal, the
/// smallest normal, tiny and huge magnitudes, the largest finite, ±∞ and NaN.
pub const HOSTILE: [f64; 12] = [
    0.0,
    -0.0,
    5e-324,
    -5e-324,
    f64::MIN_POSITIVE,
    1e-300,
    -1e-300,
    1e300,
    -1e300,
    f64::MAX,
    f64::INFINITY,
    f64::NEG_INFINITY,
];

/// [`HOSTILE`] and NaN.
pub fn hostile() -> impl Iterator<Item = f64> + Clone {
    HOSTILE.into_iter().chain([f64::NAN])
}

/// Triples drawn from the hostile set: each hostile value on each axis, the three equal, and
/// a mixed huge/tiny one.
pub fn hostile3() -> Vec<[f64; 3]> {
    let mut out = Vec::new();
    for x in hostile() {
        out.push([x, 0.0, 0.0]);
        out.push([0.0, x, 0.0]);
        out.push([0.0, 0.0, x]);
        out.push([x, x, x]);
        out.push([x, 1.0, -1.0]);
    }
    out.push([1e300, 1e-300, -1e300]);
    out.push([1e-200, 1e-200, 1e-200]);
    out.push([1e200, 1e200, 1e200]);
    out
}

/// True if every number is finite.
pub fn finite(xs: &[f64]) -> bool {
    xs.iter().all(|x| x.is_finite())
}

/// Assert the suite's contract for a `Result`: `Err`, or `Ok` whose value passes `property`.
#[track_caller]
pub fn err_or<T: std::fmt::Debug, E>(r: Result<T, E>, what: &str, property: impl FnOnce(&T) -> bool) {
    if let Ok(v) = r {
        assert!(property(&v), "{what}: Ok({v:?}) fails its defining property");
    }
}

/// Assert the suite's contract for an `Option`: `None`, or `Some` whose value passes
/// `property`.
#[track_caller]
pub fn none_or<T: std::fmt::Debug>(r: Option<T>, what: &str, property: impl FnOnce(&T) -> bool) {
    if let Some(v) = r {
        assert!(property(&v), "{what}: Some({v:?}) fails its defining property");
    }
}

/// Assert that an input outside the documented domain was refused.
#[track_caller]
pub fn refused<T: std::fmt::Debug, E>(r: Result<T, E>, what: &str) {
    if let Ok(v) = r {
        panic!("{what}: accepted ({v:?}); expected a typed error");
    }
}

/// Declare a crate's cases: each is a `#[test]` run under the [`watchdog`], and names the
/// public functions it exercises; their union is the crate's `COVERED` table, which the
/// coverage test compares with the crate's public API.
///
/// ```ignore
/// cases! {
///     unit_vector_scaled ["Vector::unit", "Vector::norm"] {
///         ...assertions...
///     }
/// }
/// ```
macro_rules! cases {
    ($( $(#[$meta:meta])* $name:ident [$($f:literal),* $(,)?] $body:block )*) => {
        /// The public functions this file's cases exercise.
        pub const COVERED: &[&str] = &[$($($f,)*)*];
        $(
            $(#[$meta])*
            #[test]
            fn $name() {
                $crate::harness::watchdog(stringify!($name), || $body);
            }
        )*
    };
}
