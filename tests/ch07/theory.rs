//! §7.1, §7.4, §7.6, §7.7 (inertial frames, translational and angular momentum, the effect of
//! gravity) and the theoretical problems of §7.16, as numeric checks of each law on small
//! systems of particles (masses, positions, velocities and forces chosen at random by proptest
//! where the law is an identity).

use proptest::prelude::*;
use vectrix::dynamics::particle_acceleration;
use vectrix::dynamics::{Element, Network};
use vectrix::kinematics::{FrameMotion, LabeledFrame, VectorJet};
use vectrix::nalgebra::{SVector, Vector3};
use vectrix::ode::Adaptive;
use vectrix::prelude::*;
use vectrix::statics::{MassProperties, Point, Spring, UniformGravity, Wrench};

use crate::support::{EPS, assert_abs, assert_rel, direction, nan_max, triple};

/// One particle's position, velocity, external force (components in F_A) and mass.
type ParticleData = ([f64; 3], [f64; 3], [f64; 3], f64);

/// Particles with positions, velocities and external forces, joined by springs (internal
/// forces that obey the third law along the line, a Newtonian body, §6.11).
struct System {
    m: Vec<f64>,
    r: Vec<Vector>,
    v: Vec<Vector>,
    f_ext: Vec<Vector>,
    spring: Spring,
}

impl System {
    fn sample(a: &Frame, data: &[ParticleData]) -> Self {
        Self {
            m: data.iter().map(|d| d.3).collect(),
            r: data.iter().map(|d| a.vector(d.0)).collect(),
            v: data.iter().map(|d| a.vector(d.1)).collect(),
            f_ext: data.iter().map(|d| a.vector(d.2)).collect(),
            spring: Spring::new(4.0, 0.5).unwrap(),
        }
    }
    /// Accelerations a⃗_{yᵢ/w/A} = (f⃗ᵢ,ext + Σⱼ f⃗ᵢⱼ)/mᵢ in the inertial F_A (w unforced at rest).
    fn accelerations(&self) -> Vec<Vector> {
        (0..self.m.len())
            .map(|i| {
                let internal = (0..self.m.len())
                    .filter(|&j| j != i)
                    .fold(Vector::zero(), |s, j| s + self.spring.force(&(self.r[i] - self.r[j])).unwrap());
                particle_acceleration(self.m[i], &(self.f_ext[i] + internal)).unwrap()
            })
            .collect()
    }
    fn mass(&self) -> f64 {
        self.m.iter().sum()
    }
    fn centre(&self) -> Vector {
        (0..self.m.len()).fold(Vector::zero(), |s, i| s + self.r[i] * self.m[i]) * (1.0 / self.mass())
    }
}

fn particle() -> impl Strategy<Value = ParticleData> {
    (triple(), triple(), triple(), 0.2..5.0f64)
}

proptest! {
    /// §7.4, Facts 7.4.1–7.4.4: for a body whose internal forces obey the third law,
    /// m_B a⃗_{c/w/A} = Σ f⃗ᵢ,ext (the internal forces cancel) and the momentum
    /// p⃗ = Σ mᵢv⃗ᵢ = m_B v⃗_c has rate Σ f⃗ᵢ,ext.
    #[test]
    fn section_7_4_translational_momentum_of_a_body(ps in proptest::collection::vec(particle(), 2..6)) {
        let a = Frame::new();
        let s = System::sample(&a, &ps);
        let acc = s.accelerations();
        let f_total = s.f_ext.iter().fold(Vector::zero(), |x, f| x + *f);
        let p_rate = (0..s.m.len()).fold(Vector::zero(), |x, i| x + acc[i] * s.m[i]);
        // the rounding lives at the size of the forces that cancel
        let scale = (0..s.m.len()).map(|i| (acc[i] * s.m[i]).norm() + s.f_ext[i].norm()).sum::<f64>() * s.m.len() as f64;
        prop_assert!((p_rate - f_total).norm() <= 64.0 * EPS * scale);
        let v_c = (0..s.m.len()).fold(Vector::zero(), |x, i| x + s.v[i] * s.m[i]) * (1.0 / s.mass());
        let p = (0..s.m.len()).fold(Vector::zero(), |x, i| x + s.v[i] * s.m[i]);
        prop_assert!((p - v_c * s.mass()).norm() <= 16.0 * EPS * p.norm().max(1.0));
    }

    /// §7.6, Facts 7.6.1–7.6.8: H⃗_{B/z/A} = Σ r⃗_{yᵢ/z} × mᵢv⃗_{yᵢ/z/A}; about an unforced w,
    /// Ḣ⃗_{B/w/A} = M⃗_{B/w} (external moments only: the internal ones cancel); about any point z
    /// moving with v⃗_z, a⃗_z, Ḣ⃗_{B/z/A} = M⃗_{B/z} − m_B r⃗_{c/z} × a⃗_{z/w/A} (Fact 7.6.7), and
    /// H⃗_{B/z/A} = H⃗_{B/c/A} + r⃗_{c/z} × m_B v⃗_{c/z/A} (Fact 7.6.5).
    #[test]
    fn section_7_6_angular_momentum_of_a_body(
        ps in proptest::collection::vec(particle(), 2..6), z in triple(), vz in triple(), az in triple(),
    ) {
        let a = Frame::new();
        let s = System::sample(&a, &ps);
        let acc = s.accelerations();
        let (z, vz, az) = (a.vector(z), a.vector(vz), a.vector(az));
        let h = |z: Vector, vz: Vector| (0..s.m.len()).fold(Vector::zero(), |x, i| x + (s.r[i] - z).cross(&((s.v[i] - vz) * s.m[i])));
        // d/dt H about z: Σ (v_i − v_z) × m(v_i − v_z) + (r_i − z) × m(a_i − a_z)
        let h_rate = (0..s.m.len()).fold(Vector::zero(), |x, i| x + (s.r[i] - z).cross(&((acc[i] - az) * s.m[i])));
        let m_ext = (0..s.m.len()).fold(Vector::zero(), |x, i| x + (s.r[i] - z).cross(&s.f_ext[i]));
        let c = s.centre();
        let want = m_ext - (c - z).cross(&az) * s.mass();
        // the rounding lives at the size of the moments that cancel
        let scale = (0..s.m.len())
            .map(|i| ((s.r[i] - z).norm() + s.r[i].norm()) * ((acc[i] - az) * s.m[i]).norm().max((acc[i] * s.m[i]).norm())
                + (s.r[i] - z).norm() * s.f_ext[i].norm() + s.m[i] * (s.v[i] - vz).norm().powi(2))
            .sum::<f64>() * s.m.len() as f64;
        prop_assert!((h_rate - want).norm() <= 256.0 * EPS * scale, "{:e}", (h_rate - want).norm());
        // about the unforced w at rest at the origin: Ḣ = M
        let h_rate_w = (0..s.m.len()).fold(Vector::zero(), |x, i| x + s.r[i].cross(&(acc[i] * s.m[i])));
        let m_w = (0..s.m.len()).fold(Vector::zero(), |x, i| x + s.r[i].cross(&s.f_ext[i]));
        prop_assert!((h_rate_w - m_w).norm() <= 256.0 * EPS * scale);
        // the shift to the centre of mass
        let v_c = (0..s.m.len()).fold(Vector::zero(), |x, i| x + s.v[i] * s.m[i]) * (1.0 / s.mass());
        let shift = h(c, v_c) + (c - z).cross(&((v_c - vz) * s.mass()));
        prop_assert!((h(z, vz) - shift).norm() <= 256.0 * EPS * scale);
    }

    /// P7.16.4: with f⃗₁₂, f⃗₁₃ on y₁, −f⃗₁₂, f⃗₂₃ on y₂, −f⃗₁₃, −f⃗₂₃ on y₃:
    /// m₁m₃/(m₁+m₃) a⃗_{y₁/y₃} = f⃗₁₃ + (m₁f⃗₂₃ + m₃f⃗₁₂)/(m₁+m₃) and
    /// m₂m₃/(m₂+m₃) a⃗_{y₂/y₃} = f⃗₂₃ + (m₂f⃗₁₃ − m₃f⃗₁₂)/(m₂+m₃).
    #[test]
    fn problem_7_16_4_three_particle_relative_accelerations(
        m in proptest::array::uniform3(0.1..10.0f64), f12 in triple(), f13 in triple(), f23 in triple(),
    ) {
        let a = Frame::new();
        let (f12, f13, f23) = (a.vector(f12), a.vector(f13), a.vector(f23));
        let acc = [
            particle_acceleration(m[0], &(f12 + f13)).unwrap(),
            particle_acceleration(m[1], &(f23 - f12)).unwrap(),
            particle_acceleration(m[2], &(-f13 - f23)).unwrap(),
        ];
        let scale = f12.norm() + f13.norm() + f23.norm();
        let lhs1 = (acc[0] - acc[2]) * (m[0] * m[2] / (m[0] + m[2]));
        let rhs1 = f13 + (f23 * m[0] + f12 * m[2]) * (1.0 / (m[0] + m[2]));
        prop_assert!((lhs1 - rhs1).norm() <= 16.0 * EPS * scale);
        let lhs2 = (acc[1] - acc[2]) * (m[1] * m[2] / (m[1] + m[2]));
        let rhs2 = f23 + (f13 * m[1] - f12 * m[2]) * (1.0 / (m[1] + m[2]));
        prop_assert!((lhs2 - rhs2).norm() <= 16.0 * EPS * scale);
    }

    /// P7.16.5: for unforced y and z, a⃗_{x/z/A} = a⃗_{x/y/A} (both move uniformly), while
    /// v⃗_{x/z/A} and v⃗_{x/y/A} differ by v⃗_{y/z/A}, which need not vanish.
    #[test]
    fn problem_7_16_5_acceleration_relative_to_any_unforced_particle(
        x in triple(), vx in triple(), f in direction(), vy in triple(), vz in triple(), m in 0.1..5.0f64,
    ) {
        let a = LabeledFrame::new("A", Frame::new());
        let fr = a.frame;
        let ax = particle_acceleration(m, &fr.vector(f)).unwrap();
        let jet = |p: [f64; 3], v: [f64; 3], acc: Vector| VectorJet::new(a.label, fr.vector(p), fr.vector(v), acc).unwrap();
        let (jx, jy, jz) = (jet(x, vx, ax), jet([1.0, 0.0, 0.0], vy, Vector::zero()), jet([0.0, 2.0, 0.0], vz, Vector::zero()));
        let (a_xy, a_xz) = (jx.second_rate() - jy.second_rate(), jx.second_rate() - jz.second_rate());
        prop_assert!((a_xy - a_xz).norm() == 0.0);
        let (v_xy, v_xz) = (jx.rate() - jy.rate(), jx.rate() - jz.rate());
        prop_assert!(((v_xy - v_xz) - (jz.rate() - jy.rate())).norm() <= 4.0 * EPS * (v_xy.norm() + v_xz.norm()));
    }

    /// P7.16.6 and Facts 7.1.4–7.1.5: for inertial F_A and F_B (ω⃗_{B/A} = 0) and unforced w, y,
    /// r⃗_{y/w}^{A••} = r⃗_{y/w}^{B••} = 0; a frame turning relative to F_A (ω⃗ ≠ 0) is not
    /// inertial: there the same uniform motion has a nonzero second B-derivative.
    #[test]
    fn problem_7_16_6_unforced_particles_do_not_accelerate_in_any_inertial_frame(
        r in direction(), v in triple(), b in crate::support::frame(), w in direction(),
    ) {
        let a = LabeledFrame::new("A", Frame::new());
        let jet = VectorJet::new(a.label, a.frame.vector(r), a.frame.vector(v), Vector::zero()).unwrap();
        let inertial = FrameMotion::new(LabeledFrame::new("B", b), a, Vector::zero(), Vector::zero()).unwrap();
        let in_b = jet.transported(&inertial).unwrap();
        prop_assert!(in_b.second_rate().norm() == 0.0);
        prop_assert!((in_b.rate() - jet.rate()).norm() == 0.0);
        let turning = FrameMotion::new(LabeledFrame::new("C", b), a, a.frame.vector(w), Vector::zero()).unwrap();
        let in_c = jet.transported(&turning).unwrap();
        // −2ω × v⃗^{C•} − ω × (ω × r⃗) = 0 only if the motion happens to be rigid with C
        let want = -(a.frame.vector(w).cross(&in_c.rate()) * 2.0) - a.frame.vector(w).cross(&a.frame.vector(w).cross(&jet.value()));
        prop_assert!((in_c.second_rate() - want).norm() <= 64.0 * EPS * (1.0 + want.norm()));
    }
}

/// §7.1, Fact 7.1.4: F_A is inertial iff ω⃗_{B/A} = 0 for an inertial F_B. Two unforced particles
/// move with constant relative velocity in F_B; in a frame turning at ω⃗ their relative
/// acceleration is −2ω⃗ × v⃗ − ω⃗ × (ω⃗ × r⃗) ≠ 0, so Definition 7.1.1 fails there, and holds when
/// ω⃗ = 0 (even with a translating origin, Fact 7.1.3).
#[test]
fn section_7_1_inertial_frames_are_nonrotating() {
    let b = LabeledFrame::new("B", Frame::new());
    let f = b.frame;
    let r_yw = VectorJet::new(b.label, f.vector([1.0, 2.0, -0.5]), f.vector([0.3, 0.0, 0.7]), Vector::zero())
        .unwrap();
    let at_rest = FrameMotion::new(LabeledFrame::new("A", f), b, Vector::zero(), Vector::zero()).unwrap();
    assert_eq!(r_yw.transported(&at_rest).unwrap().second_rate().norm(), 0.0);
    let spinning =
        FrameMotion::new(LabeledFrame::new("A", f), b, f.vector([0.0, 0.0, 0.2]), Vector::zero()).unwrap();
    assert!(r_yw.transported(&spinning).unwrap().second_rate().norm() > 0.05);
}

/// Three distant stars y₁, y₂, y₃, unforced, seen from an unforced particle w at the origin of
/// the inertial F_A: r⃗_{yᵢ/w} = tα⃗ᵢ + β⃗ᵢ (7.2.1) with β⃗ᵢ mutually orthogonal, along the axes of
/// a turned frame (the star frame F_S at t = 0). `d` scales the distances, `v` the velocities.
fn stars(d: f64, v: f64) -> (Frame, [Vector; 3], [Vector; 3]) {
    let a = Frame::new();
    let s = a.rotated_by_rotor(&Rotor::from_axis_angle(&a.vector([1.0, -2.0, 0.5]), 0.8).unwrap());
    let beta = [s.i() * (1.0 * d), s.j() * (6.2 * d), s.k() * (2.4 * d)];
    let alpha =
        [a.vector([0.8, -0.3, 0.5]) * v, a.vector([-0.2, 0.9, 0.1]) * v, a.vector([0.4, 0.4, -0.7]) * v];
    (s, alpha, beta)
}

/// §7.2, (7.2.1)–(7.2.2): with β⃗ᵢ·β⃗ⱼ = 0 the angle θᵢⱼ between the lines of sight to stars i, j
/// obeys cos θᵢⱼ = (α⃗ᵢ·α⃗ⱼt² + (α⃗ᵢ·β⃗ⱼ + α⃗ⱼ·β⃗ᵢ)t)/(|tα⃗ᵢ + β⃗ᵢ||tα⃗ⱼ + β⃗ⱼ|): checked against
/// vectrix's angle between the position vectors where the angles move a lot (distances 1–6,
/// speeds 1, t ≤ 3); then, for stars 4 to 25 light years away moving at 30 km/s, θᵢⱼ stays within
/// the bound (7.2.2) gives, (|α⃗ᵢ||α⃗ⱼ|t² + (|α⃗ᵢ||β⃗ⱼ| + |α⃗ⱼ||β⃗ᵢ|)t)/((|β⃗ᵢ| − |α⃗ᵢ|t)(|β⃗ⱼ| − |α⃗ⱼ|t)),
/// of π/2 over ten years: a few 10⁻⁴ rad, "approximately π/2".
#[test]
fn eq_7_2_2_angles_between_distant_stars_stay_near_right_angles() {
    let (_, alpha, beta) = stars(1.0, 1.0);
    for t in [0.0, 0.5, 1.7, 3.0] {
        let r: Vec<Vector> = (0..3).map(|i| alpha[i] * t + beta[i]).collect();
        for (i, j) in [(0, 1), (1, 2), (2, 0)] {
            let num = alpha[i].dot(&alpha[j]) * t * t + (alpha[i].dot(&beta[j]) + alpha[j].dot(&beta[i])) * t;
            let want = num / (r[i].norm() * r[j].norm());
            // cos of an atan2 angle against a quotient of O(10) dot products: a few ε
            assert_abs(r[i].angle(&r[j]).cos(), want, 16.0 * EPS);
        }
    }
    let light_year = 9.4607e15;
    let (_, alpha, beta) = stars(4.0 * light_year, 3.0e4);
    let ten_years = 10.0 * 3.156e7;
    for t in [0.0, 86400.0, ten_years] {
        for (i, j) in [(0, 1), (1, 2), (2, 0)] {
            let theta = (alpha[i] * t + beta[i]).angle(&(alpha[j] * t + beta[j]));
            let (ai, aj, bi, bj) = (alpha[i].norm(), alpha[j].norm(), beta[i].norm(), beta[j].norm());
            let bound = (ai * aj * t * t + (ai * bj + aj * bi) * t) / ((bi - ai * t) * (bj - aj * t));
            // |θ − π/2| ≤ asin(|cos θ|), and the angle is exact to a few ε at t = 0
            assert!((theta - std::f64::consts::FRAC_PI_2).abs() <= bound.asin() + 4.0 * EPS, "t = {t}");
            assert!(bound < 1e-3);
        }
    }
}

/// §7.2, (7.2.3)–(7.2.4): the frame of the lines of sight F_S = [r̂_{y₁/w} r̂_{y₂/w} r̂_{y₃/w}]
/// (= [β̂₁ β̂₂ β̂₃] at t = 0) turns relative to the inertial F_A only as fast as the stars cross
/// the sky: r̂ᵢ^{A•} = (I − r̂ᵢr̂ᵢ′)α⃗ᵢ/|β⃗ᵢ| at t = 0, so ω⃗_{S/A} = ½Σ r̂ᵢ × r̂ᵢ^{A•} is at most
/// (3/2)maxᵢ|α⃗ᵢ|/|β⃗ᵢ| and falls as 1/distance: Ω⃗_{S/A} ≈ 0 and F_S is approximately inertial
/// (Fact 7.1.4). The axis rates are exact derivatives (a dual number in t through vectrix's
/// `unit`), and ω⃗_{S/A} is vectrix's `omega_from_axis_rates` (P4.20.5). For stars 4–25 light
/// years away at 30 km/s it is below 10⁻¹² rad/s, 10⁻⁷ of the Earth's spin.
#[test]
fn eq_7_2_4_the_star_frame_is_approximately_inertial() {
    use vectrix::kinematics::omega_from_axis_rates;
    use vectrix::num_dual::Dual64;
    let omega_s_a = |d: f64, v: f64| {
        let (s, alpha, beta) = stars(d, v);
        let a = Frame::new();
        let ad = a.cast::<Dual64>();
        let t = Dual64::new(0.0, 1.0);
        // r̂ᵢ^{A•} at t = 0: the derivative of vectrix's unit vector along tα⃗ᵢ + β⃗ᵢ
        let rate = |i: usize| {
            let (al, be) = (alpha[i].resolve(&a), beta[i].resolve(&a));
            let r = ad.vector([0, 1, 2].map(|k| t * al[k] + be[k]));
            a.vector(r.unit().unwrap().resolve(&ad).map(|x| x.eps).into())
        };
        let w = omega_from_axis_rates(&s, &rate(0), &rate(1), &rate(2));
        // closed form of the same sum
        let want = (0..3).fold(Vector::zero(), |acc, i| {
            let u = beta[i].unit().unwrap();
            acc + u.cross(&((alpha[i] - u * u.dot(&alpha[i])) * (1.0 / beta[i].norm()))) * 0.5
        });
        let fastest = (0..3).map(|i| alpha[i].norm() / beta[i].norm()).fold(0.0, nan_max);
        (w, want, fastest)
    };
    let (w, want, fastest) = omega_s_a(1.0, 1.0);
    assert!((w - want).norm() <= 32.0 * EPS * fastest);
    assert!(w.norm() <= 1.5 * fastest && w.norm() > 0.01 * fastest);
    // ten times farther, ten times slower; twice the speed, twice the rate
    let (w10, _, _) = omega_s_a(10.0, 1.0);
    assert!((w10 * 10.0 - w).norm() <= 32.0 * EPS * w.norm());
    let (w2, _, _) = omega_s_a(1.0, 2.0);
    assert!((w2 - w * 2.0).norm() <= 32.0 * EPS * w.norm());
    // the real sky
    let (w, _, fastest) = omega_s_a(4.0 * 9.4607e15, 3.0e4);
    assert!(w.norm() <= 1.5 * fastest && fastest < 1e-12);
    assert!(w.norm() < 1e-7 * 7.2921e-5);
}

/// §7.7, Facts 7.7.1–7.7.6: uniform gravity adds m_B g⃗ to the translational law and has no
/// moment about the centre of mass, so Ḣ⃗_{B/c/A} is that of the nongravitational forces alone;
/// about another point z it contributes r⃗_{c/z} × m_B g⃗.
#[test]
fn section_7_7_uniform_gravity_has_no_moment_about_the_centre_of_mass() {
    let a = Frame::new();
    let g = UniformGravity::new(a.vector([0.0, 0.0, -9.81])).unwrap();
    let parts = [(2.0, [1.0, 0.0, 0.5]), (1.0, [-0.5, 2.0, 0.0]), (3.0, [0.2, -1.0, 1.5])];
    let body = MassProperties::from_particles(&parts.map(|(m, x)| (m, Point::at(a.vector(x))))).unwrap();
    let c = body.centre_of_mass();
    let about_c = g.wrench_on(&body, c);
    assert_rel(about_c.force.dot(&a.k()), -9.81 * 6.0, EPS);
    assert_abs(about_c.moment.norm(), 0.0, 16.0 * EPS * 6.0 * 9.81);
    let z = Point::at(a.vector([3.0, -1.0, 0.0]));
    let about_z = g.wrench_on(&body, z);
    let want = c.position_rel(&z).cross(&g.force(6.0));
    assert!((about_z.moment - want).norm() <= 16.0 * EPS * want.norm());
    // the same moment, particle by particle
    let sum = parts.iter().fold(Wrench::zero(z), |w, (m, x)| {
        w.plus(&Wrench::from_force(
            &vectrix::statics::AppliedForce::new(g.force(*m), Point::at(a.vector(*x))),
            z,
        ))
    });
    assert!((sum.moment - about_z.moment).norm() <= 16.0 * EPS * want.norm());
}

/// P7.16.1: f⃗ pushes B₁, which pushes B₂ along a line: both accelerate at f/(m₁ + m₂), so the
/// contact force has magnitude m₂|f|/(m₁ + m₂) (and B₁ feels the reaction: m₁a = f − f_R).
#[test]
fn problem_7_16_1_contact_force_between_pushed_bodies() {
    let a = Frame::new();
    let (m1, m2) = (3.0, 1.5);
    let f = a.vector([4.5, 0.0, 0.0]);
    let acc = particle_acceleration(m1 + m2, &f).unwrap();
    let f_r = acc * m2;
    assert_rel(f_r.norm(), m2 * f.norm() / (m1 + m2), 4.0 * EPS);
    let acc1 = particle_acceleration(m1, &(f - f_r)).unwrap();
    assert!((acc1 - acc).norm() <= 4.0 * EPS * acc.norm());
}

/// P7.16.3 (§7.16, printed solution): a dumbbell y₁, y₂ (link ℓ along î_B), f⃗ = f₁î_B + f₂ĵ_B at p
/// on the link: ω̇ = (r⃗_{p/c}·î_B) f₂/J_zz, J_zz = m₁m₂ℓ²/(m₁+m₂);
/// f⃗_{R1} = m₁m₂ℓ/(m₁+m₂) (ω²î_B − ω̇ĵ_B) + m₁/(m₁+m₂) f⃗ and
/// f⃗_{R2} = m₁m₂ℓ/(m₁+m₂)(−ω²î_B + ω̇ĵ_B) + m₂/(m₁+m₂) f⃗. The reactions are mᵢ a⃗_{yᵢ}, with the
/// particle accelerations from vectrix's rigid body (Euler's equation, rank 2) and rigid-point
/// kinematics.
#[test]
fn problem_7_16_3_reactions_on_a_dumbbell_pushed_along_its_link() {
    let a = Frame::new();
    let (m1, m2, l) = (1.5, 0.7, 2.0);
    let th = 0.6;
    let ib = a.vector([f64::cos(th), f64::sin(th), 0.0]);
    let jb = a.k().cross(&ib);
    let (y1, y2) = (Point::origin(), Point::at(ib * l));
    let body = MassProperties::from_particles(&[(m1, y1), (m2, y2)]).unwrap();
    let w = 1.3;
    let rb = RigidBody::new(body, a.vector([0.2, -0.1, 0.0]), a.k() * w);
    for l0 in [0.0, 0.5, l] {
        let p = Point::at(ib * l0);
        let f = ib * 2.0 + jb * -3.0;
        let (a_c, alpha) = rb
            .accelerations(&Wrench::from_force(
                &vectrix::statics::AppliedForce::new(f, p),
                body.centre_of_mass(),
            ))
            .unwrap();
        let mt = m1 + m2;
        let jzz = m1 * m2 * l * l / mt;
        let wd = p.position_rel(&body.centre_of_mass()).dot(&ib) * f.dot(&jb) / jzz;
        assert_abs(alpha.dot(&a.k()), wd, 16.0 * EPS * wd.abs().max(1.0));
        let acc_of = |y: &Point| {
            let r = y.position_rel(&body.centre_of_mass());
            a_c + alpha.cross(&r) + rb.omega.cross(&rb.omega.cross(&r))
        };
        let f_r1 = (ib * (w * w) - jb * wd) * (m1 * m2 * l / mt) + f * (m1 / mt);
        let f_r2 = (ib * (-w * w) + jb * wd) * (m1 * m2 * l / mt) + f * (m2 / mt);
        let scale = f.norm() + m1 * m2 * l / mt * (w * w + wd.abs());
        assert!((acc_of(&y1) * m1 - f_r1).norm() <= 32.0 * EPS * scale, "ℓ₀ = {l0}");
        assert!((acc_of(&y2) * m2 - f_r2).norm() <= 32.0 * EPS * scale, "ℓ₀ = {l0}");
        // the massless link is in equilibrium: f⃗ = f⃗_{R1} + f⃗_{R2}
        assert!((f_r1 + f_r2 - f).norm() <= 8.0 * EPS * scale);
    }
}

/// P7.16.4 specialised to springs: three particles on a line joined by springs k₁₂, k₁₃, k₂₃;
/// the network's accelerations satisfy the identity with f₁₂ = −k₁₂(q₁ − q₂), …, which is the
/// differential equation of the distances d₁₃ = q₁ − q₃, d₂₃ = q₂ − q₃.
#[test]
fn problem_7_16_4_springs_between_three_particles() {
    let (m, k) = ([1.0, 2.0, 0.5], [3.0, 1.5, 4.0]);
    let e = |i, j, v| Element { i, j: Some(j), value: v };
    let net = Network {
        masses: m.to_vec(),
        springs: vec![e(0, 1, k[0]), e(0, 2, k[1]), e(1, 2, k[2])],
        dashpots: vec![],
        inerters: vec![],
    };
    let q = [0.3, -0.2, 0.9];
    let acc = net.accelerations(&q, &[0.0; 3], &[0.0; 3]).unwrap();
    let (f12, f13, f23) = (-k[0] * (q[0] - q[1]), -k[1] * (q[0] - q[2]), -k[2] * (q[1] - q[2]));
    let lhs = m[0] * m[2] / (m[0] + m[2]) * (acc[0] - acc[2]);
    assert_abs(lhs, f13 + (m[0] * f23 + m[2] * f12) / (m[0] + m[2]), 32.0 * EPS);
    let lhs = m[1] * m[2] / (m[1] + m[2]) * (acc[1] - acc[2]);
    assert_abs(lhs, f23 + (m[1] * f13 - m[2] * f12) / (m[1] + m[2]), 32.0 * EPS);
}

/// P7.16.7: a torque-free body spinning about a principal axis keeps spinning about it: Euler's
/// equation gives ω̇ = 0 there (ω⃗ × J⃗ω⃗ = 0). Perturbed slightly, the spin stays close for the
/// largest and smallest moments and departs for the intermediate one (notes ch6-8 §3).
#[test]
fn problem_7_16_7_spin_about_a_principal_axis_persists() {
    let b = Frame::new();
    let jd = [1.0, 2.0, 3.0];
    let props = MassProperties::new(
        1.0,
        Point::origin(),
        b.dyadic(&vectrix::nalgebra::Matrix3::from_diagonal(&Vector3::from(jd))),
    )
    .unwrap();
    let rate = |w: &SVector<f64, 3>| {
        let body = RigidBody::new(props, Vector::zero(), b.vector([w[0], w[1], w[2]]));
        body.accelerations(&Wrench::zero(Point::origin())).unwrap().1.resolve(&b)
    };
    for k in 0..3 {
        let mut w = SVector::<f64, 3>::zeros();
        w[k] = 2.0;
        assert_eq!(rate(&w), Vector3::zeros(), "exact spin about axis {k}");
        // perturbed by 1e-4 in the other components, integrated over 40 time units
        let w0 = w + SVector::<f64, 3>::from_fn(|i, _| if i == k { 0.0 } else { 1e-4 });
        let sol = Adaptive::dop853()
            .rtol(1e-11)
            .atol(1e-13)
            .solve(|_t, w: &SVector<f64, 3>| rate(w), 0.0, &w0, 40.0)
            .unwrap();
        let drift = sol
            .y
            .iter()
            .map(|y| (0..3).filter(|&i| i != k).map(|i| y[i].abs()).fold(0.0, nan_max))
            .fold(0.0, nan_max);
        if k == 1 {
            assert!(drift > 0.5, "intermediate axis: the spin leaves the axis (drift {drift})");
        } else {
            assert!(drift < 1e-3, "axis {k}: the spin stays near the axis (drift {drift})");
        }
    }
}
