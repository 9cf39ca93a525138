//! Problems 10.11.8–10 (the book prints no answers; each claim is checked against its own
//! closed form at many random and hard attitudes).

use std::f64::consts::{FRAC_PI_2, PI};

use proptest::prelude::*;
use vectrix::flight::*;
use vectrix::kinematics::{FrameLabel, FrameMotion, LabeledFrame, VectorJet};
use vectrix::nalgebra::Vector3;
use vectrix::num_dual::HyperDual64;
use vectrix::prelude::*;

use crate::support::{EPS, NanAmax};

/// An angle in (−π, π] biased toward the hard set 0, ±π/2, π.
fn any_angle() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -PI..PI,
        1 => prop::sample::select(vec![0.0, FRAC_PI_2, -FRAC_PI_2, PI, 1e-9, FRAC_PI_2 - 1e-9]),
    ]
}

/// A pitch or sideslip in [−π/2, π/2], biased toward the ends.
fn half_angle() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => -FRAC_PI_2..FRAC_PI_2,
        1 => prop::sample::select(vec![0.0, FRAC_PI_2, -FRAC_PI_2, FRAC_PI_2 - 1e-9, 1e-9]),
    ]
}

/// P10.11.8: "an aircraft flies at constant speed and zero roll in a horizontal circle of radius
/// R centred at O_E, the left wing pointing to the centre, |ω⃗_{AC/E}| = ω. Use the double
/// transport theorem to find r̈⃗_AC^{E••} in terms of r̂_AC and resolve it in F_AC."
/// r⃗_AC = Rĵ_AC is fixed in F_AC and ω⃗_{AC/E} = −ωk̂_E (a left turn, k̂_E down) is constant, so
/// (4.5.1) leaves r̈⃗ = ω⃗ × (ω⃗ × r⃗) = −ω²R r̂_AC, and r̈⃗|_AC = (0, −ω²R, 0) whatever the pitch.
/// Independent check: r|_E(t) = 𝓞_{E/AC}(t)(0, R, 0) with Ψ(t) = Ψ₀ − ωt, differentiated twice
/// by a hyper-dual number.
#[test]
fn problem_10_11_8_level_circle_centripetal_acceleration() {
    for (big_r, omega, theta, psi0) in
        [(1500.0, 0.05, 0.08, 0.3), (300.0, 0.4, -0.2, -2.5), (2e4, 1e-3, 0.0, PI)]
    {
        let euler = Euler321::new(psi0, theta, 0.0);
        let e = LabeledFrame::new("E", Frame::new());
        // ω|_AC = S(Φ, Θ)[Φ̇, Θ̇, Ψ̇] with Ψ̇ = −ω (10.9.8)
        let pqr = body_rates(&euler, [0.0, 0.0, -omega]);
        let motion =
            FrameMotion::from_body_rates(FrameLabel::new("AC"), &e, &euler.o_ac_e(), pqr, [0.0, 0.0, 0.0])
                .unwrap();
        let ac = motion.body().frame;
        let r = ac.j() * big_r;
        let jet = VectorJet::fixed_in(motion.body().label, r).transported(&motion).unwrap();
        let a = jet.second_rate();
        let a_ac = a.resolve(&ac);
        let tol = 16.0 * EPS * omega * omega * big_r;
        assert!((a_ac - Vector3::new(0.0, -omega * omega * big_r, 0.0)).nan_amax() <= tol, "{a_ac}");
        assert!((a - ac.j() * (-omega * omega * big_r)).norm() <= tol);
        // the speed is ωR along the nose's horizontal direction (a left turn flies forward)
        let v = jet.rate().resolve(&ac);
        assert!((v.norm() - omega * big_r).abs() <= 16.0 * EPS * omega * big_r);
        // independent: differentiate r|_E(t) twice
        let t = HyperDual64::new(0.0, 1.0, 1.0, 0.0);
        let euler_t = Euler321::new(
            HyperDual64::from(psi0) - t * omega,
            HyperDual64::from(theta),
            HyperDual64::from(0.0),
        );
        let r_e = euler_t.o_ac_e().transpose()
            * Vector3::new(HyperDual64::from(0.0), HyperDual64::from(big_r), HyperDual64::from(0.0));
        let a_e = r_e.map(|x| x.eps1eps2);
        assert!((a_e - a.resolve(&e.frame)).nan_amax() <= tol);
    }
}

/// P10.11.9: "with ê_rw along the right wing, î_S = ĵ_S × k̂_S, ĵ_S = ê_rw,
/// k̂_S = (V⃗ × ê_rw)/|V⃗ × ê_rw|; î_W = V⃗_AC, ĵ_W = k̂_W × î_W, k̂_W = k̂_S." Erratum: î_W is the
/// unit vector V̂_AC (10.5.1), not V⃗_AC. Checked frame-free against the stability and wind
/// frames built from α and β (10.4.8), (10.5.5).
#[test]
fn problem_10_11_9_velocity_dependent_frames() {
    let mut runner = proptest::test_runner::TestRunner::new(ProptestConfig::with_cases(256));
    let uvw = (
        prop_oneof![4 => -300.0..300.0f64, 1 => Just(0.0), 1 => Just(1e-6)],
        prop_oneof![4 => -300.0..300.0f64, 1 => Just(0.0)],
        prop_oneof![4 => -300.0..300.0f64, 1 => Just(1e-6)],
    )
        .prop_filter("V_proj ≠ 0", |(u, _, w)| u * u + w * w > 1e-13);
    runner
        .run(&(uvw, any_angle(), half_angle(), any_angle()), |((u, v, w), psi, theta, phi)| {
            let e = Frame::new();
            let ac =
                Frame::from_orientation_rel(&e, &Euler321::new(psi, theta, phi).o_ac_e(), 1e-12).unwrap();
            let vel = ac.vector([u, v, w]);
            let e_rw = ac.j();
            let angles = AeroAngles::from_body_velocity([u, v, w]);
            let s = Frame::from_orientation_rel(&ac, &o_s_ac(angles.alpha), 1e-12).unwrap();
            let wf = Frame::from_orientation_rel(&s, &o_w_s(angles.beta), 1e-12).unwrap();
            let k = vel.cross(&e_rw).unit().unwrap();
            // V⃗ × ê_rw loses |V|/Ū digits when V⃗ nearly lies along the wing (Ū = |V⃗_proj| ≪ |V|)
            let tol = 64.0 * EPS * (1.0 + vel.norm() / u.hypot(w));
            prop_assert!((s.j() - e_rw).norm() <= tol);
            prop_assert!((s.k() - k).norm() <= tol, "k̂_S {:?} vs {:?}", s.k(), k);
            prop_assert!((s.i() - s.j().cross(&s.k())).norm() <= tol);
            prop_assert!((wf.i() - vel.unit().unwrap()).norm() <= tol);
            prop_assert!((wf.k() - k).norm() <= tol);
            prop_assert!((wf.j() - wf.k().cross(&wf.i())).norm() <= tol);
            Ok(())
        })
        .unwrap();
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// P10.11.10: comparing the (2, 3) entries of 𝓞_{AC/E} and 𝓞_{AC/W}𝓞_{W/E}:
    /// sin Φ cos Θ = cos β sin μ cos γ − sin β sin γ, i.e.
    /// sin μ = (sin Φ cos Θ + sin β sin γ)/(cos β cos γ) (notes [C]), for the (η, γ, μ) vectrix
    /// extracts from (10.8.4). Checked in the multiplied form, which also holds where
    /// cos β cos γ = 0.
    #[test]
    fn problem_10_11_10_bank_angle_identity(
        psi in any_angle(), theta in half_angle(), phi in any_angle(), alpha in any_angle(), beta in half_angle(),
    ) {
        let euler = Euler321::new(psi, theta, phi);
        let fp = FlightPathAngles::from_attitude(&euler, alpha, beta);
        let o_ac_e = euler.o_ac_e();
        let o_ac_w = o_w_ac(alpha, beta).transpose();
        let prod = o_ac_w * fp.o_w_e();
        // the extracted (η, γ, μ) reproduce 𝓞_{W/E} to rounding
        prop_assert!((prod[(1, 2)] - o_ac_e[(1, 2)]).abs() <= 64.0 * EPS, "(2,3): {} vs {}", prod[(1, 2)], o_ac_e[(1, 2)]);
        let lhs = phi.sin() * theta.cos();
        let rhs = beta.cos() * fp.mu.sin() * fp.gamma.cos() - beta.sin() * fp.gamma.sin();
        prop_assert!((lhs - rhs).abs() <= 64.0 * EPS, "{lhs} vs {rhs}");
        // the divided form where it is defined (cos β cos γ ≥ 0.1)
        let d = beta.cos() * fp.gamma.cos();
        if d.abs() >= 0.1 {
            let sin_mu = (phi.sin() * theta.cos() + beta.sin() * fp.gamma.sin()) / d;
            prop_assert!((sin_mu - fp.mu.sin()).abs() <= 64.0 * EPS / 0.1);
        }
    }
}
