//! The least time a quaternion → rotation-matrix conversion of 10⁶ rotations into a *fresh*
//! (10⁶, 3, 3) float64 array can take on this machine (issue 37 item 5; docs/performance.md,
//! "From Python"): what `Rotation.as_matrix` must do, with nothing else.
//!
//! The kernel here is the conversion (2.15.14) written out by hand, no checks, no Python; the
//! output is allocated the way numpy and the binding allocate large arrays (its pages advised
//! for transparent huge pages on Linux), then written once, on one thread and on two (each
//! thread writes its half, so both fault their pages in). Beside it: filling the same fresh
//! array with a constant (no input, no arithmetic), and the conversion into an array whose pages
//! are already mapped ("warm", which an API returning a new array never gets).
//!
//! ```sh
//! cargo run --release --example as_matrix_floor
//! ```
//!
//! Prints the best of 15 of each, three rounds.
use std::hint::black_box;
use std::time::Instant;

const N: usize = 1_000_000;

/// A vector of `n` values (length n, contents unspecified until written) whose memory is
/// advised for transparent huge pages where it spans whole 2 MiB pages, as numpy does for
/// arrays of 4 MiB and more.
fn fresh(n: usize) -> Vec<f64> {
    let mut v: Vec<f64> = Vec::with_capacity(n);
    #[cfg(target_os = "linux")]
    {
        const HUGE: usize = 2 << 20;
        let (start, len) = (v.as_mut_ptr() as usize, n * 8);
        let (first, last) = (start.next_multiple_of(HUGE), (start + len) / HUGE * HUGE);
        if last > first {
            // SAFETY: [first, last) lies inside the allocation `v` owns; the advice only says
            // how to back it, and a refusal changes nothing.
            unsafe { libc::madvise(first as *mut libc::c_void, last - first, libc::MADV_HUGEPAGE) };
        }
    }
    v
}

/// The rotation matrix of a unit quaternion (η, ε) [w, x, y, z], row-major (2.15.14).
#[inline(always)]
fn matrix(q: &[f64; 4]) -> [f64; 9] {
    let [w, x, y, z] = *q;
    let (xx, yy, zz) = (x * x, y * y, z * z);
    let (xy, xz, yz, wx, wy, wz) = (x * y, x * z, y * z, w * x, w * y, w * z);
    [
        1.0 - 2.0 * (yy + zz),
        2.0 * (xy - wz),
        2.0 * (xz + wy),
        2.0 * (xy + wz),
        1.0 - 2.0 * (xx + zz),
        2.0 * (yz - wx),
        2.0 * (xz - wy),
        2.0 * (yz + wx),
        1.0 - 2.0 * (xx + yy),
    ]
}

fn convert(q: &[[f64; 4]], out: &mut Vec<f64>) {
    out.extend(q.iter().flat_map(matrix));
}

fn fill(n: usize, out: &mut Vec<f64>) {
    out.resize(n, 1.0);
}

/// Runs `f` on the two halves of the rotations on two threads, each writing its own fresh
/// vector (as the binding's two threads write the two halves of one array), so that both
/// threads fault their pages in.
fn halves(f: impl Fn(usize, usize, &mut Vec<f64>) + Sync) -> (Vec<f64>, Vec<f64>) {
    let h = N / 2;
    let (mut a, mut b) = (fresh(9 * h), fresh(9 * (N - h)));
    std::thread::scope(|s| {
        s.spawn(|| f(0, h, &mut a));
        f(h, N, &mut b);
    });
    (a, b)
}

fn best(mut f: impl FnMut()) -> f64 {
    (0..15)
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64() * 1e3
        })
        .fold(f64::INFINITY, f64::min)
}

fn main() {
    let q: Vec<[f64; 4]> = (0..N)
        .map(|k| {
            let (s, c) = (k as f64 * 1e-3).sin_cos();
            [c, 0.6 * s, 0.8 * s, 0.0]
        })
        .collect();
    let mut warm = Vec::with_capacity(9 * N);
    convert(&q, &mut warm);
    println!("ms, best of 15         fill fresh   convert fresh   convert warm");
    for _ in 0..3 {
        let one = [
            best(|| {
                let mut o = fresh(9 * N);
                fill(9 * N, &mut o);
                black_box(&o);
            }),
            best(|| {
                let mut o = fresh(9 * N);
                convert(&q, &mut o);
                black_box(&o);
            }),
            best(|| {
                warm.clear();
                convert(&q, &mut warm);
                black_box(&warm);
            }),
        ];
        let two = [
            best(|| {
                black_box(halves(|s, e, o| fill(9 * (e - s), o)));
            }),
            best(|| {
                black_box(halves(|s, e, o| convert(&q[s..e], o)));
            }),
            best(|| {
                let (a, b) = warm.split_at_mut(9 * N / 2);
                std::thread::scope(|s| {
                    s.spawn(|| {
                        a.chunks_exact_mut(9).zip(&q).for_each(|(o, q)| o.copy_from_slice(&matrix(q)))
                    });
                    b.chunks_exact_mut(9).zip(&q[N / 2..]).for_each(|(o, q)| o.copy_from_slice(&matrix(q)));
                });
                black_box(&warm);
            }),
        ];
        println!("1 thread   {:>14.2} {:>15.2} {:>14.2}", one[0], one[1], one[2]);
        println!("2 threads  {:>14.2} {:>15.2} {:>14.2}", two[0], two[1], two[2]);
    }
}
