//! §7.5: spring–dashpot networks in matrix form, with the corrected C̃, K̃ (7.5.17–18).

use vectrix::dynamics::{Element, Network};

use crate::support::{EPS, assert_abs, assert_abs_slice, assert_rel, assert_rel_slice};

fn pair(i: usize, j: usize, value: f64) -> Element {
    Element { i, j: Some(j), value }
}

/// (7.5.3–4): "C and K are weighted graph Laplacians"; (7.5.13): "det Γ = m_B".
#[test]
fn eq_7_5_3_laplacians_and_det_gamma() {
    let net = Network {
        masses: vec![1.0, 2.0, 3.0],
        springs: vec![pair(0, 1, 4.0), pair(1, 2, 5.0), pair(0, 2, 6.0)],
        dashpots: vec![pair(0, 1, 0.5)],
        inerters: vec![],
    };
    let (m, c, k) = net.matrices().unwrap();
    assert_rel_slice(m.diagonal().as_slice(), &[1.0, 2.0, 3.0], EPS);
    assert_rel_slice(k.row(0).transpose().as_slice(), &[10.0, -4.0, -6.0], EPS);
    // rows of a Laplacian sum to zero
    for l in [&c, &k] {
        for r in 0..3 {
            assert!(l.row(r).sum().abs() <= 4.0 * EPS * 15.0);
        }
    }
    assert_rel(net.gamma().determinant(), 6.0, 8.0 * EPS);
}

/// (7.5.15–18) with l = 2: "M̃ = diag(m1m2, 1)/m_B" [P], and the **corrected** C̃ = diag(c12, 0),
/// K̃ = diag(k12, 0): the printed (7.5.17–18) are wrong (notes ch6-8 errata, l.8751–8770).
#[test]
fn eq_7_5_17_corrected_relative_matrices_two_masses() {
    let (m1, m2, c12, k12) = (2.0, 3.0, 0.7, 11.0);
    let net = Network {
        masses: vec![m1, m2],
        springs: vec![pair(0, 1, k12)],
        dashpots: vec![pair(0, 1, c12)],
        inerters: vec![],
    };
    let (mt, ct, kt) = net.relative_matrices().unwrap();
    let mb = m1 + m2;
    assert_rel_slice(mt.as_slice(), &[m1 * m2 / mb, 0.0, 0.0, 1.0 / mb], 8.0 * EPS);
    assert_abs_slice(ct.as_slice(), &[c12, 0.0, 0.0, 0.0], 16.0 * EPS);
    assert_rel_slice(kt.as_slice(), &[k12, 0.0, 0.0, 0.0], 16.0 * EPS);
}

/// l = 3: "m_B M̃ = [[m1(m2+m3), m1m3, 0], [m1m3, m3(m1+m2), 0], [0, 0, 1]]" [P], and the
/// corrected C̃ = [[c12+c13, c13, 0], [c13, c13+c23, 0], [0, 0, 0]] without 1/m_B².
#[test]
fn eq_7_5_18_corrected_relative_matrices_three_masses() {
    let (m1, m2, m3) = (1.0, 2.0, 4.0);
    let (c12, c13, c23) = (0.3, 0.5, 0.7);
    let net = Network {
        masses: vec![m1, m2, m3],
        springs: vec![],
        dashpots: vec![pair(0, 1, c12), pair(0, 2, c13), pair(1, 2, c23)],
        inerters: vec![],
    };
    let (mt, ct, _) = net.relative_matrices().unwrap();
    let mb = m1 + m2 + m3;
    let want_m = [m1 * (m2 + m3), m1 * m3, 0.0, m1 * m3, m3 * (m1 + m2), 0.0, 0.0, 0.0, 1.0];
    assert_rel_slice((mt * mb).as_slice(), &want_m, 64.0 * EPS);
    let want_c = [c12 + c13, c13, 0.0, c13, c13 + c23, 0.0, 0.0, 0.0, 0.0];
    assert_rel_slice(ct.as_slice(), &want_c, 64.0 * EPS);
}

/// P7.16.2 (inerter): "(μ + b) d̈ = 0" for two particles joined by an inerter alone; with a
/// spring k: (μ + b) d̈ = −k d, μ = m1m2/(m1+m2) the reduced mass (7.3.5).
#[test]
fn problem_7_16_2_inerter_adds_to_reduced_mass() {
    let (m1, m2, b, k) = (2.0, 3.0, 0.8, 5.0);
    let net = Network {
        masses: vec![m1, m2],
        springs: vec![pair(0, 1, k)],
        dashpots: vec![],
        inerters: vec![pair(0, 1, b)],
    };
    let q = [0.0, 0.4];
    let qdd = net.accelerations(&q, &[0.0, 0.0], &[0.0, 0.0]).unwrap();
    let mu = m1 * m2 / (m1 + m2);
    // d = q2 − q1
    assert_abs(qdd[1] - qdd[0], -k * 0.4 / (mu + b), 16.0 * EPS);
    // the centre of mass does not accelerate
    assert_abs(m1 * qdd[0] + m2 * qdd[1], 0.0, 16.0 * EPS);
}
