//! Spring–dashpot–inerter networks of particles on a line, in matrix form (book §7.5).
//!
//! M q̈ + C q̇ + K q = f (7.5.2, 7.5.7): C and K are weighted graph Laplacians of the dashpots
//! and springs (7.5.3–4), inerters add a Laplacian to the mass matrix (P9.15.1). The
//! transformation Γ to relative coordinates and the total momentum (7.5.9–16) separates
//! the rigid motion.

use nalgebra::{DMatrix, DVector};

use crate::DynamicsError;

/// (M, C, K) or (M̃, C̃, K̃) of a network (7.5.7).
pub type NetworkMatrices = (DMatrix<f64>, DMatrix<f64>, DMatrix<f64>);

/// One element between particles i and j (or between particle i and the ground when
/// `j` is `None`) with coefficient `value` > 0.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Element {
    /// First particle.
    pub i: usize,
    /// Second particle, or `None` for the ground.
    pub j: Option<usize>,
    /// Stiffness k, damping c or inertance b.
    pub value: f64,
}

/// A network of particles joined by springs, dashpots and inerters.
///
/// Book: §7.5, P9.15.1 (inerters enter the mass matrix).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Network {
    /// Particle masses m_i > 0.
    pub masses: Vec<f64>,
    /// Springs k.
    pub springs: Vec<Element>,
    /// Dashpots c.
    pub dashpots: Vec<Element>,
    /// Inerters b.
    pub inerters: Vec<Element>,
}

fn laplacian(n: usize, elems: &[Element], what: &'static str) -> Result<DMatrix<f64>, DynamicsError> {
    let mut l = DMatrix::zeros(n, n);
    for e in elems {
        if !(e.value.is_finite() && e.value >= 0.0) {
            return Err(DynamicsError::OutOfRange { what, value: e.value, valid: "finite ≥ 0" });
        }
        let bad = e.i >= n || e.j.is_some_and(|j| j >= n || j == e.i);
        if bad {
            return Err(DynamicsError::Disconnected { link: e.i, parent: e.j.unwrap_or(e.i), links: n });
        }
        l[(e.i, e.i)] += e.value;
        if let Some(j) = e.j {
            l[(j, j)] += e.value;
            l[(e.i, j)] -= e.value;
            l[(j, e.i)] -= e.value;
        }
    }
    Ok(l)
}

impl Network {
    /// (M, C, K): M = diag(m) + inerter Laplacian, C and K the weighted Laplacians
    /// (7.5.3–4), grounded elements on the diagonal only.
    ///
    /// Book: (7.5.2)–(7.5.7), P9.15.1.
    ///
    /// # Errors
    /// [`DynamicsError::OutOfRange`] for masses ≤ 0 or negative coefficients;
    /// [`DynamicsError::Disconnected`] for an element naming a missing particle.
    pub fn matrices(&self) -> Result<NetworkMatrices, DynamicsError> {
        let n = self.masses.len();
        for &m in &self.masses {
            if !(m.is_finite() && m > 0.0) {
                return Err(DynamicsError::OutOfRange {
                    what: "particle mass",
                    value: m,
                    valid: "finite > 0",
                });
            }
        }
        let m = DMatrix::from_diagonal(&DVector::from_column_slice(&self.masses))
            + laplacian(n, &self.inerters, "b")?;
        Ok((m, laplacian(n, &self.dashpots, "c")?, laplacian(n, &self.springs, "k")?))
    }

    /// The transformation Γ to relative coordinates: rows e_k − e_{k+1} for k < l, last row
    /// the masses (Σ m_i q_i = m_B q_c); det Γ = m_B (7.5.9–13).
    ///
    /// Book: (7.5.9)–(7.5.13).
    pub fn gamma(&self) -> DMatrix<f64> {
        let n = self.masses.len();
        let mut g = DMatrix::zeros(n, n);
        for k in 0..n.saturating_sub(1) {
            g[(k, k)] = 1.0;
            g[(k, k + 1)] = -1.0;
        }
        if n > 0 {
            for (i, m) in self.masses.iter().enumerate() {
                g[(n - 1, i)] = *m;
            }
        }
        g
    }

    /// (M̃, C̃, K̃) = Γ⁻ᵀ(M, C, K)Γ⁻¹ in the relative coordinates q̃ = Γq (7.5.15–18).
    ///
    /// Book: (7.5.14)–(7.5.18) **corrected**: the printed C̃, K̃ (l.8751–8770) are wrong; for
    /// l = 2, C̃ = diag(c₁₂, 0), and for l = 3, C̃ = [[c₁₂+c₁₃, c₁₃, 0], [c₁₃, c₁₃+c₂₃, 0],
    /// [0, 0, 0]], with no 1/m_B² (notes ch6-8 errata); this function computes them exactly.
    ///
    /// # Errors
    /// As [`Network::matrices`]; [`DynamicsError::SingularMassMatrix`] for an empty network.
    pub fn relative_matrices(&self) -> Result<NetworkMatrices, DynamicsError> {
        let (m, c, k) = self.matrices()?;
        let gi = self
            .gamma()
            .try_inverse()
            .ok_or(DynamicsError::SingularMassMatrix { detail: "Γ is singular".into() })?;
        let t = |x: &DMatrix<f64>| gi.transpose() * x * &gi;
        Ok((t(&m), t(&c), t(&k)))
    }

    /// q̈ = M⁻¹(f − Cq̇ − Kq) (7.5.7), Cholesky.
    ///
    /// Book: (7.5.7).
    ///
    /// # Errors
    /// As [`Network::matrices`]; dimension and finiteness errors.
    pub fn accelerations(&self, q: &[f64], qd: &[f64], f: &[f64]) -> Result<DVector<f64>, DynamicsError> {
        let n = self.masses.len();
        for (x, what) in [(q, "q"), (qd, "q̇"), (f, "f")] {
            crate::error::check_len(x.len(), n, what)?;
            crate::error::check_finite(x, what)?;
        }
        let (m, c, k) = self.matrices()?;
        let rhs = DVector::from_column_slice(f)
            - c * DVector::from_column_slice(qd)
            - k * DVector::from_column_slice(q);
        crate::lagrange::cholesky_solve(m, rhs)
    }
}
