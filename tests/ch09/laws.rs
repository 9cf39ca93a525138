//! Constants of motion, energy and dissipation laws, and Hamilton's equations (§9.6–9.13).

use vectrix::dynamics::lagrange::{
    accelerations, energy, energy_rate, generalized_momentum, hamilton_rhs, hamiltonian, lagrange_terms,
    velocities_from_momenta,
};
use vectrix::nalgebra::{DVector, SVector};
use vectrix::ode::{Adaptive, GaussLegendre};
use vectrix::prelude::*;

use super::systems::{CART, Oscillator};
use crate::support::{EPS, assert_abs, assert_abs_slice, assert_rel, assert_rel_slice, nan_max};

/// Bead on a freely rotating wire, q = (x, θ): θ is ignorable.
struct FreeWire;
impl Lagrangian for FreeWire {
    fn dof(&self) -> usize {
        2
    }
    fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
        T::lit(0.5) * qd[0] * qd[0] + T::lit(0.5) * (T::one() + q[0] * q[0]) * qd[1] * qd[1]
    }
}

fn rhs<L: Lagrangian>(sys: &L) -> impl FnMut(f64, &DVector<f64>) -> DVector<f64> + '_ {
    move |t, y| {
        let r = sys.dof();
        let (q, qd) = (&y.as_slice()[..r], &y.as_slice()[r..2 * r]);
        let qdd = accelerations(sys, q, qd, t).unwrap_or_else(|_| DVector::from_element(r, f64::NAN));
        let mut out = DVector::zeros(y.len());
        out.as_mut_slice()[..r].copy_from_slice(qd);
        out.as_mut_slice()[r..2 * r].copy_from_slice(qdd.as_slice());
        if y.len() > 2 * r {
            // the dissipation law's integrand, Ė (Fact 9.9.3)
            out[2 * r] = energy_rate(sys, q, qd, t).unwrap_or(f64::NAN);
        }
        out
    }
}

/// Fact 9.6.4: "if Q_j = 0 and ∂T/∂q_j = 0, then ∂T/∂q̇_j is constant": the angular momentum
/// (I + mx²)θ̇ of the bead on the free wire (Ex 9.10.2).
#[test]
fn fact_9_6_4_ignorable_coordinate_momentum_is_constant() {
    let y0 = DVector::from_vec(vec![1.0, 0.0, 0.0, 1.0]);
    let p0 = generalized_momentum(&FreeWire, &[1.0, 0.0], &[0.0, 1.0], 0.0).unwrap()[1];
    assert_rel(p0, 2.0, EPS);
    let sol = Adaptive::dop853().rtol(1e-11).atol(1e-12).solve(rhs(&FreeWire), 0.0, &y0, 10.0).unwrap();
    for y in &sol.y {
        let p = generalized_momentum(&FreeWire, &y.as_slice()[..2], &y.as_slice()[2..], 0.0).unwrap()[1];
        // adaptive tolerance 1e-11 on O(10) states
        assert_rel(p, p0, 1e-9);
    }
}

/// Fact 9.8.4: "if all forces are potential, E = T + U is constant." Gauss–Legendre conserves
/// the (quadratic) energy of the oscillator of Ex 9.10.1 to round-off over 10⁴ periods.
#[test]
fn fact_9_8_4_energy_conserved_gauss_legendre_1e4_periods() {
    let sys = Oscillator { m: 1.0, k: 4.0, c: 0.0, f: 0.0 };
    let period = std::f64::consts::PI; // 2π/√(k/m)
    let y0 = DVector::from_vec(vec![1.0, 0.5]);
    let e0 = energy(&sys, &[1.0], &[0.5], 0.0).unwrap();
    let mut worst = 0.0f64;
    let (y, _) = GaussLegendre::Gauss4
        .integrate(rhs(&sys), 0.0, &y0, 1e4 * period, 80_000, |_, y: &DVector<f64>| {
            let e = energy(&sys, &y.as_slice()[..1], &y.as_slice()[1..], 0.0).unwrap();
            worst = nan_max(worst, ((e - e0) / e0).abs());
        })
        .unwrap();
    assert!(worst < 1e-10, "relative energy drift {worst:e}");
    assert!(y.iter().all(|v| v.is_finite()));
}

/// Fact 9.8.4 for a nonlinear system (Ex 9.10.3 with springs only): Gauss–Legendre of order 6
/// keeps the energy error bounded and tiny (symplectic, no drift).
#[test]
fn fact_9_8_4_energy_bounded_nonlinear_cart_pendulum() {
    let y0 = DVector::from_vec(vec![0.1, 0.7, 0.3, -0.4]);
    let e0 = energy(&CART, &[0.1, 0.7], &[0.3, -0.4], 0.0).unwrap();
    let mut worst = 0.0f64;
    GaussLegendre::Gauss6
        .integrate(rhs(&CART), 0.0, &y0, 200.0, 8_000, |_, y: &DVector<f64>| {
            let e = energy(&CART, &y.as_slice()[..2], &y.as_slice()[2..], 0.0).unwrap();
            worst = nan_max(worst, ((e - e0) / e0).abs());
        })
        .unwrap();
    assert!(worst < 1e-10, "relative energy error {worst:e}");
}

/// Fact 9.9.3: "Ė = −(∂R/∂q̇) q̇" (plus the power of the remaining forces): the integral of
/// the law along a damped, forced trajectory equals the change of E.
#[test]
fn fact_9_9_3_dissipation_law() {
    let sys = Oscillator { m: 1.3, k: 4.0, c: 0.35, f: 0.2 };
    // at one state: Ė = −c q̇² + f q̇
    let rate = energy_rate(&sys, &[0.4], &[-1.1], 0.0).unwrap();
    assert_abs(rate, -0.35 * 1.21 + 0.2 * -1.1, 8.0 * EPS);
    let y0 = DVector::from_vec(vec![1.0, 0.0, 0.0]);
    let sol = Adaptive::dop853().rtol(1e-12).atol(1e-13).solve(rhs(&sys), 0.0, &y0, 8.0).unwrap();
    let y = sol.last();
    let e1 = energy(&sys, &[y[0]], &[y[1]], 0.0).unwrap();
    let e0 = energy(&sys, &[1.0], &[0.0], 0.0).unwrap();
    // tolerance 1e-12 per step on O(1) energies
    assert_rel(e1 - e0, y[2], 1e-9);
    assert!(e1 < e0 + 0.2 * 8.0);
}

/// §9.13: "p = Mq̇ + Fᵀ, H = pᵀq̇ − L; q̇ = ∂H/∂pᵀ, ṗ = −∂H/∂qᵀ + Q_np." For a natural system
/// H = E (9.13.7), the velocities round-trip, and ṗ = d/dt(∂T/∂q̇) along Lagrange's flow.
#[test]
fn section_9_13_hamilton_equations_agree_with_lagrange() {
    let (q, qd) = ([0.1, 0.7], [0.3, -0.4]);
    let p = generalized_momentum(&CART, &q, &qd, 0.0).unwrap();
    let back = velocities_from_momenta(&CART, &q, p.as_slice(), 0.0).unwrap();
    assert_abs_slice(back.as_slice(), &qd, 16.0 * EPS);
    let h = hamiltonian(&CART, &q, p.as_slice(), 0.0).unwrap();
    assert_abs(h, energy(&CART, &q, &qd, 0.0).unwrap(), 16.0 * EPS);
    let (qd_h, pd) = hamilton_rhs(&CART, &q, p.as_slice(), 0.0).unwrap();
    assert_abs_slice(qd_h.as_slice(), &qd, 16.0 * EPS);
    // d/dt ∂T/∂q̇ = M q̈ + (Cq̇ + b)
    let terms = lagrange_terms(&CART, &q, &qd, 0.0).unwrap();
    let qdd = accelerations(&CART, &q, &qd, 0.0).unwrap();
    let want = &terms.mass * qdd + &terms.velocity_terms;
    assert_rel_slice(pd.as_slice(), want.as_slice(), 64.0 * EPS);
}

/// (9.13.7): "H = E − Fq̇ − 2G": for the bead on a wire turning at constant ω,
/// T = ½m(ẋ² + ω²x²) has G = ½mω²x², so H = ½mẋ² − ½mω²x² is conserved while T is not.
#[test]
fn eq_9_13_7_hamiltonian_of_rotating_wire() {
    struct Wire;
    impl Lagrangian for Wire {
        fn dof(&self) -> usize {
            1
        }
        fn kinetic<T: Scalar>(&self, q: &[T], qd: &[T], _t: T) -> T {
            T::lit(0.5) * (qd[0] * qd[0] + T::lit(4.0) * q[0] * q[0])
        }
    }
    let y0 = SVector::<f64, 2>::new(1.0, 0.0);
    let f = |_t: f64, y: &SVector<f64, 2>| {
        let a = accelerations(&Wire, &[y[0]], &[y[1]], 0.0).unwrap()[0];
        SVector::<f64, 2>::new(y[1], a)
    };
    let sol = Adaptive::dop853().rtol(1e-12).atol(1e-13).solve(f, 0.0, &y0, 1.0).unwrap();
    let y = sol.last();
    let h = |y: &SVector<f64, 2>| {
        let p = generalized_momentum(&Wire, &[y[0]], &[y[1]], 0.0).unwrap();
        hamiltonian(&Wire, &[y[0]], p.as_slice(), 0.0).unwrap()
    };
    assert_rel(h(y), h(&y0), 1e-10);
    assert_rel(h(&y0), -2.0, EPS);
}
