//! Kinetic energy, work and power (book §8.1–8.4).

use vectrix_statics::Point;
use vectrix_tensor::{Scalar, Vector};

/// Kinetic energy of particles relative to w in F_A: T = ½ Σ m_i |v⃗_{y_i/w/A}|² (8.1.1–2).
///
/// Book: §8.1, (8.1.1), (8.1.2).
pub fn particles_kinetic_energy<T: Scalar>(particles: &[(T, Vector<T>)]) -> T {
    particles.iter().fold(T::zero(), |t, (m, v)| t + T::lit(0.5) * *m * v.norm_squared())
}

/// Kinetic energy relative to the centre of mass from relative velocities only (8.1.6):
/// T_{/c} = ½ Σ_{i<j} (m_i m_j / m_B) |v⃗_{y_i/y_j}|². Zero for an empty or massless set.
///
/// Book: (8.1.6).
pub fn kinetic_energy_about_centre_pairwise<T: Scalar>(particles: &[(T, Vector<T>)]) -> T {
    let m_b = particles.iter().fold(T::zero(), |s, (m, _)| s + *m);
    if m_b.re() <= 0.0 {
        return T::zero();
    }
    let mut sum = T::zero();
    for (i, (mi, vi)) in particles.iter().enumerate() {
        for (mj, vj) in &particles[i + 1..] {
            sum += *mi * *mj * (*vi - *vj).norm_squared();
        }
    }
    T::lit(0.5) * sum / m_b
}

/// Work W = ∫ f⃗ · dr⃗ along a sampled path (trapezoidal rule on the samples (f⃗_k, y_k)), the
/// discrete form of (8.2.1). Exact for forces affine along straight segments.
///
/// Book: §8.2, (8.2.1).
pub fn work_along_path<T: Scalar>(samples: &[(Vector<T>, Point<T>)]) -> T {
    samples.windows(2).fold(T::zero(), |w, s| {
        let dr = s[1].1.position_rel(&s[0].1);
        w + (s[0].0 + s[1].0).dot(&dr) * T::lit(0.5)
    })
}

/// Power of a wrench on a rigid body: P = f⃗_B · v⃗_z + M⃗_{B/z} · ω⃗ (the rate of work (8.2.4)
/// with the moment about the body point z moving with v⃗_z).
///
/// Book: §8.2, (8.2.4)–(8.2.6).
pub fn power<T: Scalar>(force: &Vector<T>, moment_z: &Vector<T>, v_z: &Vector<T>, omega: &Vector<T>) -> T {
    force.dot(v_z) + moment_z.dot(omega)
}
