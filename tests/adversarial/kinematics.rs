//! vectrix-kinematics under hostile input (docs/robustness.md): attitude-rate maps return a
//! finite rate that inverts its partner map, or a typed error (NonFinite, GimbalLock,
//! SingularRateMap, Overflow, invalid tolerance); frame motions and jets check their labels.

use crate::support::NanAmax;
use nalgebra::{Matrix3, Vector3, Vector4};
use vectrix::frames::Frame;
use vectrix::kinematics::attitude::{
    Propagator, alpha_spatial_from_eigenaxis_rates, angle_vector_rate_body, angle_vector_rate_spatial,
    eigenaxis_rates_from_omega_body, eigenaxis_rates_from_omega_spatial, euler_rate_matrix_body,
    euler_rate_matrix_spatial, euler_rates_from_omega_body, euler_rates_from_omega_spatial, gibbs_rate_body,
    gibbs_rate_spatial, jacobian_left, jacobian_left_inverse, jacobian_right, jacobian_right_inverse,
    mrp_rate_body, mrp_rate_spatial, omega_body_from_eigenaxis_rates, omega_body_from_euler_rates,
    omega_body_from_gibbs_rate, omega_body_from_mrp_rate, omega_body_from_quaternion_rate,
    omega_spatial_from_eigenaxis_rates, omega_spatial_from_euler_rates, omega_spatial_from_gibbs_rate,
    omega_spatial_from_mrp_rate, omega_spatial_from_quaternion_rate, propagate_attitude,
    quaternion_rate_body, quaternion_rate_matrix, quaternion_rate_spatial, rewrap_angle_vector,
};
use vectrix::kinematics::{
    Cylindrical, DyadicJet, FrameLabel, FrameMotion, FrenetSerret, Iacr, LabeledFrame, LinkMotion,
    ResolvedLink, Spherical, VectorJet, alpha_body_from_orientation_rates, axis_rates, bishop_frames,
    body_point_acceleration, chain_kinematics, chain_velocity_resolved, chasles_velocity,
    contact_point_velocity, double_transport, iacr, ivcr, ivcr_coefficient, no_slip_velocity,
    omega_body_from_orientation_rate, omega_from_axis_rates, omega_from_axis_rates_projections,
    omega_spatial_from_rotation_rate, poisson_rate, poisson_rate_spatial, rolls_without_slip, screw_axis,
    slip_velocity, transport, transport_dyadic, triple_transport,
};
use vectrix::rotation::{EulerAngles, EulerSequence, Quaternion};

use crate::harness::{err_or, finite, hostile, hostile3, refused};

const EPS: f64 = f64::EPSILON;
const BAD_TOLS: [f64; 4] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -1e-9];

fn fin3(v: &Vector3<f64>) -> bool {
    v.iter().all(|c| c.is_finite())
}

fn close3(a: &Vector3<f64>, b: &Vector3<f64>, rel: f64) -> bool {
    (a - b).nan_amax() <= rel * a.nan_amax().max(b.nan_amax()).max(1e-300)
}

/// `Err` (a typed overflow of the inverse map) or ω back to 1e-12.
trait InverseCheck {
    fn is_none_or_close(&self, w: &Vector3<f64>) -> bool;
}
impl<E> InverseCheck for Result<Vector3<f64>, E> {
    fn is_none_or_close(&self, w: &Vector3<f64>) -> bool {
        self.as_ref().map_or(true, |w2| close3(w2, w, 1e-12))
    }
}

cases! {
    // Angle-vector rates (§4.9): J_l, J_r are finite for every finite Θ (Θ = 1e300 î too) and
    // ω = J Θ̇ inverts Θ̇ = J⁻¹ ω where J⁻¹ exists (|Θ| < 2π).
    angle_vector_rates ["jacobian_left", "jacobian_right", "jacobian_left_inverse", "jacobian_right_inverse",
        "angle_vector_rate_body", "angle_vector_rate_spatial", "rewrap_angle_vector"] {
        let w = Vector3::new(0.3, -0.2, 0.5);
        for x in hostile3() {
            let th = Vector3::from(x);
            if finite(&x) {
                let (jl, jr) = (jacobian_left(&th), jacobian_right(&th));
                assert!(jl.iter().chain(jr.iter()).all(|c| c.is_finite()), "J({x:?})");
                let rw = rewrap_angle_vector(&th);
                assert!(rw.norm() <= std::f64::consts::PI + 1e-9 || th.norm() > 1e15, "rewrap {x:?} = {rw:?}");
            }
            err_or(jacobian_left_inverse(&th), "J_l⁻¹", |ji| (jacobian_left(&th) * ji - Matrix3::identity()).nan_amax() <= 1e-9);
            err_or(jacobian_right_inverse(&th), "J_r⁻¹", |ji| (jacobian_right(&th) * ji - Matrix3::identity()).nan_amax() <= 1e-9);
            err_or(angle_vector_rate_body(&th, &w), "Θ̇ body", |d| fin3(d) && close3(&(jacobian_right(&th) * d), &w, 1e-9));
            err_or(angle_vector_rate_spatial(&th, &w), "Θ̇ spatial", |d| fin3(d) && close3(&(jacobian_left(&th) * d), &w, 1e-9));
        }
        // J_l(1e300 î) = I + (1 − cos θ)/θ n̂^× + (1 − sin θ/θ) n̂^{×2}: n̂^{×2} = diag(0, −1, −1).
        let j = jacobian_left(&Vector3::new(1e300, 0.0, 0.0));
        assert!((j - Matrix3::from_diagonal(&Vector3::new(1.0, 0.0, 0.0))).nan_amax() <= 4.0 * EPS, "{j}");
    }

    // Gibbs and MRP rates (§4.12, §4.13 extension): each rate and its inverse compose to the
    // identity; g = 1e300 overflows into a typed Overflow, never ∞ inside Ok.
    gibbs_mrp_rates ["gibbs_rate_body", "gibbs_rate_spatial", "omega_body_from_gibbs_rate", "omega_spatial_from_gibbs_rate",
        "mrp_rate_body", "mrp_rate_spatial", "omega_body_from_mrp_rate", "omega_spatial_from_mrp_rate"] {
        let w = Vector3::new(0.3, -0.2, 0.5);
        for x in hostile3() {
            let p = Vector3::from(x);
            err_or(gibbs_rate_body(&p, &w), "ġ body", |gd| {
                fin3(gd) && omega_body_from_gibbs_rate(&p, gd).is_ok_and(|w2| close3(&w2, &w, 1e-9) || p.nan_amax() > 1e7)
            });
            err_or(gibbs_rate_spatial(&p, &w), "ġ spatial", |gd| {
                fin3(gd) && omega_spatial_from_gibbs_rate(&p, gd).is_ok_and(|w2| close3(&w2, &w, 1e-9) || p.nan_amax() > 1e7)
            });
            err_or(omega_body_from_gibbs_rate(&p, &w), "ω from ġ (body)", fin3);
            err_or(omega_spatial_from_gibbs_rate(&p, &w), "ω from ġ (spatial)", fin3);
            err_or(mrp_rate_body(&p, &w), "ṗ body", |pd| {
                fin3(pd) && omega_body_from_mrp_rate(&p, pd).is_ok_and(|w2| close3(&w2, &w, 1e-9) || p.nan_amax() > 1e7)
            });
            err_or(mrp_rate_spatial(&p, &w), "ṗ spatial", fin3);
            err_or(omega_body_from_mrp_rate(&p, &w), "ω from ṗ (body)", fin3);
            err_or(omega_spatial_from_mrp_rate(&p, &w), "ω from ṗ (spatial)", fin3);
        }
        // ġ at g = 1e300 î: the true rate ~ g(g·ω) overflows: a typed error.
        refused(gibbs_rate_body(&Vector3::new(1e300, 0.0, 0.0), &Vector3::new(1.0, 0.0, 0.0)), "gibbs_rate_body(1e300)");
        // ω from ġ at g = 1e200 with ġ = 1e-200-scale: finite (no |g|² overflow).
        let r = omega_body_from_gibbs_rate(&Vector3::new(1e200, 0.0, 0.0), &Vector3::new(0.0, 1e200, 0.0)).unwrap();
        assert!(fin3(&r));
    }

    // Quaternion rates (§4.11): q̇ = ½ q ⊗ ω; the inverse recovers ω; non-unit or non-finite q
    // is refused.
    quaternion_rates ["quaternion_rate_matrix", "quaternion_rate_body", "quaternion_rate_spatial",
        "omega_body_from_quaternion_rate", "omega_spatial_from_quaternion_rate"] {
        let q = Quaternion::from_angle_vector(&Vector3::new(0.4, -1.0, 2.0));
        for x in hostile3() {
            let w = Vector3::from(x);
            let m = quaternion_rate_matrix(&w);
            if finite(&x) {
                assert!(m.iter().all(|c| c.is_finite()));
            }
            // the inverse map recovers ω, or reports its own overflow
            err_or(quaternion_rate_body(&q, &w), "q̇ body", |qd| {
                qd.iter().all(|c| c.is_finite()) && omega_body_from_quaternion_rate(&q, qd).is_none_or_close(&w)
            });
            err_or(quaternion_rate_spatial(&q, &w), "q̇ spatial", |qd| {
                qd.iter().all(|c| c.is_finite()) && omega_spatial_from_quaternion_rate(&q, qd).is_none_or_close(&w)
            });
            let qq = Quaternion::new(x[0], x[1], x[2], 1.0);
            err_or(quaternion_rate_body(&qq, &Vector3::zeros()), "q̇ of a raw q", |qd| qd.iter().all(|c| c.is_finite()));
            err_or(omega_body_from_quaternion_rate(&qq, &Vector4::new(0.0, 1.0, 0.0, 0.0)), "ω from q̇", fin3);
        }
    }

    // Euler-angle rates (§4.10): away from lock ω = S(angles) rates inverts; at lock a
    // GimbalLock error; NaN/negative/∞ tolerances are refused for every sequence.
    euler_rates ["euler_rate_matrix_body", "euler_rate_matrix_spatial", "omega_body_from_euler_rates",
        "omega_spatial_from_euler_rates", "euler_rates_from_omega_body", "euler_rates_from_omega_spatial"] {
        let w = Vector3::new(0.3, -0.2, 0.5);
        for seq in EulerSequence::ALL {
            for x in hostile3() {
                let ea = EulerAngles::new(seq, x);
                if finite(&x) {
                    assert!(euler_rate_matrix_body(&ea).iter().chain(euler_rate_matrix_spatial(&ea).iter()).all(|c| c.is_finite()));
                }
                err_or(euler_rates_from_omega_body(&ea, &w, 1e-9), "Euler rates (body)", |r| {
                    r.iter().all(|c| c.is_finite()) && close3(&omega_body_from_euler_rates(&ea, *r), &w, 1e-6)
                });
                err_or(euler_rates_from_omega_spatial(&ea, &w, 1e-9), "Euler rates (spatial)", |r| {
                    r.iter().all(|c| c.is_finite()) && close3(&omega_spatial_from_euler_rates(&ea, *r), &w, 1e-6)
                });
            }
            let ea = EulerAngles::new(seq, [0.1, 0.2, 0.3]);
            for tol in BAD_TOLS {
                refused(euler_rates_from_omega_body(&ea, &w, tol), "euler_rates_from_omega_body(bad tol)");
                refused(euler_rates_from_omega_spatial(&ea, &w, tol), "euler_rates_from_omega_spatial(bad tol)");
            }
        }
    }

    // Eigenaxis rates (§4.7): ω from (θ, θ̇, n̂, n̂̇) and back; θ = 0 (axis undefined) is an error
    // for the inverse map.
    eigenaxis_rates ["omega_spatial_from_eigenaxis_rates", "omega_body_from_eigenaxis_rates",
        "alpha_spatial_from_eigenaxis_rates", "eigenaxis_rates_from_omega_spatial", "eigenaxis_rates_from_omega_body"] {
        let n = Vector3::new(0.0, 0.0, 1.0);
        let w = Vector3::new(0.1, 0.2, 0.3);
        for th in hostile() {
            err_or(eigenaxis_rates_from_omega_spatial(th, &n, &w), "eigenaxis rates (spatial)", |(td, nd)| {
                td.is_finite() && fin3(nd) && close3(&omega_spatial_from_eigenaxis_rates(th, *td, &n, nd), &w, 1e-9)
            });
            err_or(eigenaxis_rates_from_omega_body(th, &n, &w), "eigenaxis rates (body)", |(td, nd)| {
                td.is_finite() && fin3(nd) && close3(&omega_body_from_eigenaxis_rates(th, *td, &n, nd), &w, 1e-9)
            });
            if th.is_finite() && th.abs() < 1e6 {
                assert!(fin3(&alpha_spatial_from_eigenaxis_rates([th, 1.0, 0.0], &n, &Vector3::zeros(), &Vector3::zeros())));
            }
        }
        refused(eigenaxis_rates_from_omega_spatial(0.5, &Vector3::zeros(), &w), "eigenaxis rates, zero axis");
    }

    // Attitude propagation: a bounded step count; NaN ω, invalid intervals and n = 0 are
    // refused; the result is a rotation matrix.
    propagation ["propagate_attitude"] {
        let r0 = Matrix3::identity();
        for method in [Propagator::AngleVectorRk4, Propagator::QuaternionExact, Propagator::GibbsRk4, Propagator::MrpRk4,
            Propagator::QuaternionRk4 { renormalize: true }, Propagator::PoissonRk4 { renormalize: true },
            Propagator::EulerRk4 { sequence: EulerSequence::S321, tol: f64::NAN }] {
            for wz in hostile() {
                err_or(propagate_attitude(method, &r0, |_| Vector3::new(0.0, 0.0, wz), 0.0, 1.0, 10), "propagate", |r| {
                    (r * r.transpose() - Matrix3::identity()).nan_amax() <= 1e-9
                });
            }
            refused(propagate_attitude(method, &r0, |_| Vector3::zeros(), 0.0, 1.0, 0), "propagate(n = 0)");
            refused(propagate_attitude(method, &r0, |_| Vector3::zeros(), 0.0, f64::NAN, 10), "propagate(NaN t1)");
            refused(propagate_attitude(method, &Matrix3::from_element(f64::NAN), |_| Vector3::zeros(), 0.0, 1.0, 10), "propagate(NaN R0)");
        }
    }

    // Poisson's equation (§4.6): ω from a matrix rate and back; non-orthonormal or non-finite
    // input is refused.
    poisson ["omega_body_from_orientation_rate", "alpha_body_from_orientation_rates", "omega_spatial_from_rotation_rate",
        "poisson_rate", "poisson_rate_spatial", "omega_from_axis_rates", "omega_from_axis_rates_projections", "axis_rates"] {
        let r = Quaternion::from_angle_vector(&Vector3::new(0.2, 0.4, -0.1)).rotation_matrix();
        let a = Frame::new();
        let b = Frame::from_orientation_rel(&a, &r.transpose(), 1e-12).unwrap();
        for x in hostile3() {
            let w = Vector3::from(x);
            let rd = poisson_rate(&r, &w);
            if finite(&x) && x.iter().all(|c| c.abs() < 1e300) {
                err_or(omega_spatial_from_rotation_rate(&r, &poisson_rate_spatial(&r, &w)), "ω from Ṙ", |w2| close3(w2, &w, 1e-9));
                err_or(omega_body_from_orientation_rate(&r.transpose(), &rd.transpose()), "ω from Ȯ", fin3);
                let wv = b.vector(x);
                let [i, j, k] = axis_rates(&b, &wv);
                assert!(((omega_from_axis_rates(&b, &i, &j, &k) - wv).norm()) <= 1e-9 * wv.norm().max(1e-300));
                assert!(omega_from_axis_rates_projections(&b, &i, &j, &k).is_finite());
            }
            let m = Matrix3::from_diagonal(&w);
            err_or(omega_body_from_orientation_rate(&m, &m), "ω from a non-rotation", fin3);
            err_or(alpha_body_from_orientation_rates(&m, &m), "α from a non-rotation", fin3);
            err_or(alpha_body_from_orientation_rates(&r.transpose(), &m), "α", fin3);
        }
    }

    // Transport theorem (§4.4), rolling (§4.18), instantaneous axes (§4.15–4.17): finite for
    // finite input; the screw/IVCR/IACR classifiers return a typed result or error.
    transport_rolling_screw ["transport", "transport_dyadic", "double_transport", "triple_transport", "chasles_velocity",
        "contact_point_velocity", "slip_velocity", "rolls_without_slip", "no_slip_velocity", "screw_axis", "ivcr",
        "iacr", "body_point_acceleration", "ivcr_coefficient"] {
        let a = Frame::new();
        let one = a.vector([1.0, 0.5, -0.25]);
        for x in hostile3() {
            let v = a.vector(x);
            if finite(&x) && x.iter().all(|c| c.abs() <= 1e100) {
                assert!(transport(&one, &v, &one).is_finite() && double_transport(&one, &one, &one, &v, &one).is_finite());
                assert!(triple_transport(&one, &one, &one, &one, &v, &one, &one).is_finite());
                assert!(transport_dyadic(&one.outer(&one), &v, &one.outer(&one)).is_finite());
                assert!(chasles_velocity(&v, &one, 1.0, 0.5, &a.k(), &one).is_finite());
                assert!(contact_point_velocity(&v, &one, &one).is_finite() && slip_velocity(&v, &one).is_finite());
                assert!(no_slip_velocity(&v, &one, &one).is_finite() && body_point_acceleration(&v, &one, &one, &one).is_finite());
                assert!(ivcr_coefficient(&v).is_finite());
                assert!(rolls_without_slip(&v, &v, 0.0) && !rolls_without_slip(&v, &v, f64::NAN));
            }
            err_or(screw_axis(&v, &one), "screw_axis", |m| !format!("{m:?}").contains("NaN"));
            err_or(ivcr(&v, &one, 1e-12), "ivcr", |l| l.as_ref().is_none_or(|l| l.point.is_finite() && l.direction.is_finite()));
            err_or(iacr(&v, &one, &one, 1e-12), "iacr", |i| match i {
                Iacr::Point(p) => p.is_finite(),
                Iacr::Line(l) => l.point.is_finite() && l.direction.is_finite(),
                _ => true,
            });
        }
        for tol in BAD_TOLS {
            refused(ivcr(&one, &one, tol), "ivcr(bad tol)");
            refused(iacr(&one, &one, &one, tol), "iacr(bad tol)");
        }
    }

    // Curvilinear coordinates (ch. 5): from_position inverts position_in_a; the frame is
    // orthonormal or an error on the axis (ρ = 0) where it is undefined.
    curvilinear ["Cylindrical::from_position", "Cylindrical::position_in_a", "Cylindrical::o_cyl_a", "Cylindrical::frame",
        "Cylindrical::omega_in_cyl", "Cylindrical::velocity_in_cyl", "Cylindrical::acceleration_in_cyl",
        "Cylindrical::kinematics", "Spherical::from_position", "Spherical::position_in_a", "Spherical::o_sph_a",
        "Spherical::frame", "Spherical::omega_in_sph", "Spherical::velocity_in_sph", "Spherical::acceleration_in_sph",
        "Spherical::coriolis_in_sph", "Spherical::kinematics"] {
        let a = Frame::new();
        for x in hostile3() {
            err_or(Cylindrical::from_position(x), "Cylindrical::from_position", |c| {
                let p = c.position_in_a();
                fin3(&p) && close3(&p, &Vector3::from(x), 1e-14)
                    && c.o_cyl_a().iter().all(|e| e.is_finite())
                    && fin3(&c.omega_in_cyl()) && fin3(&c.velocity_in_cyl()) && fin3(&c.acceleration_in_cyl())
            });
            if let Ok(s) = Spherical::from_position(x) {
                let (acc, cor) = (s.acceleration_in_sph(), s.coriolis_in_sph());
                let p = s.position_in_a();
                assert!(fin3(&p) && close3(&p, &Vector3::from(x), 1e-14), "Spherical position {x:?} → {p:?}");
                assert!(s.o_sph_a().iter().all(|e| e.is_finite()), "o_sph_a {x:?}");
                assert!(fin3(&s.omega_in_sph()) && fin3(&s.velocity_in_sph()), "ω, v {x:?}");
                assert!(fin3(&acc) && fin3(&cor), "a {x:?}: {acc:?}, {cor:?} from {s:?}");
            }
            if let Ok(c) = Cylindrical::from_position(x) {
                err_or(c.frame(&a), "Cylindrical::frame", |f| f.i().is_finite());
                err_or(c.kinematics(&a), "Cylindrical::kinematics", |k| k.iter().all(|v| v.is_finite()));
            }
            if let Ok(s) = Spherical::from_position(x) {
                err_or(s.frame(&a), "Spherical::frame", |f| f.i().is_finite());
                err_or(s.kinematics(&a), "Spherical::kinematics", |k| k.iter().all(|v| v.is_finite()));
            }
        }
    }

    // Frenet–Serret and Bishop frames (§5.6): orthonormal or a typed error for zero speed or
    // curvature, NaN, mismatched lengths and invalid tolerances.
    curve_frames ["FrenetSerret::from_derivatives", "FrenetSerret::radius_of_curvature", "FrenetSerret::darboux",
        "FrenetSerret::darboux_per_parameter", "FrenetSerret::frame", "FrenetSerret::acceleration", "bishop_frames"] {
        let a = Frame::new();
        for x in hostile3() {
            let r1 = a.vector(x);
            err_or(FrenetSerret::from_derivatives(&r1, &a.j(), &a.k(), 1e-12, 1e-12), "Frenet–Serret", |f| {
                f.radius_of_curvature().is_finite() && f.darboux().is_finite() && f.darboux_per_parameter().is_finite()
                    && f.acceleration().is_finite() && f.frame().is_ok()
            });
            err_or(bishop_frames(&[a.vector([0.0; 3]), r1], &[a.i(), r1], &a.j()), "bishop_frames", |fs| fs.iter().all(|f| f.i().is_finite()));
        }
        for tol in BAD_TOLS {
            refused(FrenetSerret::from_derivatives(&a.i(), &a.j(), &a.k(), tol, 1e-12), "Frenet(bad speed tol)");
            refused(FrenetSerret::from_derivatives(&a.i(), &a.j(), &a.k(), 1e-12, tol), "Frenet(bad rel tol)");
        }
        refused(bishop_frames(&[a.i(), a.j()], &[a.i()], &a.j()), "bishop_frames(mismatched lengths)");
        let _ = bishop_frames::<f64>(&[], &[], &a.j());
    }

    // Frame motions and jets (§4.1–4.5): labels are checked (FrameMismatch, SameFrame), NaN is
    // refused, compositions of finite motions are finite, and the inverse motion has −ω.
    motions_and_jets ["FrameLabel::new", "FrameLabel::indexed", "FrameLabel::name", "FrameMotion::new", "FrameMotion::from_body_rates", "FrameMotion::body", "FrameMotion::reference",
        "FrameMotion::omega", "FrameMotion::alpha", "FrameMotion::omega_dyad", "FrameMotion::o_b_a", "FrameMotion::inverse",
        "FrameMotion::compose", "FrameMotion::chain", "FrameMotion::mixed_alpha", "LabeledFrame::new", "LabeledFrame::with_label",
        "VectorJet::new", "VectorJet::fixed_in", "VectorJet::wrt", "VectorJet::value", "VectorJet::rate", "VectorJet::second_rate",
        "VectorJet::rate_wrt", "VectorJet::second_rate_wrt", "VectorJet::transported", "VectorJet::mixed_acceleration",
        "VectorJet::moving_point", "VectorJet::rigid_point", "VectorJet::plus", "DyadicJet::new", "DyadicJet::wrt",
        "DyadicJet::value", "DyadicJet::rate_wrt", "DyadicJet::transported", "chain_kinematics", "chain_velocity_resolved"] {
        let f = Frame::new();
        let (la, lb) = (LabeledFrame::new("A", f), LabeledFrame::with_label(FrameLabel::new("B"), f));
        for name in ["", "..", "/", "\u{202e}"] {
            assert_eq!(FrameLabel::new(name).name(), name);
        }
        assert_ne!(FrameLabel::indexed("link", 0), FrameLabel::indexed("link", u32::MAX));
        refused(FrameMotion::new(la, la, f.k(), f.i()), "FrameMotion with the same frame twice");
        refused(FrameMotion::<f64>::chain(&[]), "FrameMotion::chain(empty)");
        for x in hostile3() {
            let w = f.vector(x);
            let m = FrameMotion::new(lb, la, w, f.i());
            err_or(m, "FrameMotion::new", |m| {
                m.omega().is_finite() && (m.inverse().omega() + m.omega()).norm() == 0.0 && m.omega_dyad().is_finite()
                    && m.o_b_a().iter().all(|c| c.is_finite()) && m.body().label == lb.label && m.reference().label == la.label
                    && m.alpha().is_finite()
            });
            err_or(FrameMotion::from_body_rates(FrameLabel::new("B"), &la, &Matrix3::identity(), x, [0.0; 3]), "from_body_rates", |m| m.omega().is_finite());
            err_or(VectorJet::new(la.label, w, w, w), "VectorJet::new", |j| j.value().is_finite() && j.rate().is_finite() && j.second_rate().is_finite() && j.wrt() == la.label);
            err_or(DyadicJet::new(la.label, w.outer(&w), w.outer(&w)), "DyadicJet::new", |j| j.value().is_finite() && j.wrt() == la.label);
        }
        let m = FrameMotion::new(lb, la, f.k(), f.i()).unwrap();
        let jb = VectorJet::fixed_in(lb.label, f.i());
        let ja = jb.transported(&m).unwrap();
        assert_eq!(ja.wrt(), la.label);
        // (4.4.x): the A-rate of a vector fixed in B is ω × x.
        assert!((ja.rate() - f.k().cross(&f.i())).norm() <= 4.0 * EPS);
        refused(jb.rate_wrt(la.label), "rate_wrt(another frame)");
        refused(jb.second_rate_wrt(la.label), "second_rate_wrt(another frame)");
        refused(jb.plus(&ja), "plus(mismatched frames)");
        assert!(jb.rate_wrt(lb.label).is_ok() && jb.second_rate_wrt(lb.label).is_ok());
        err_or(jb.mixed_acceleration(&m), "mixed_acceleration", |v| v.is_finite());
        err_or(ja.moving_point(&m, &jb), "moving_point", |j| j.value().is_finite());
        err_or(ja.rigid_point(&m, f.j()), "rigid_point", |j| j.value().is_finite());
        let d = DyadicJet::new(lb.label, f.i().outer(&f.j()), f.i().outer(&f.j())).unwrap();
        err_or(d.transported(&m), "DyadicJet::transported", |t| t.value().is_finite());
        refused(d.rate_wrt(la.label), "DyadicJet::rate_wrt(another frame)");
        let lc = LabeledFrame::new("C", f);
        let mc = FrameMotion::new(lc, lb, f.i(), f.j()).unwrap();
        err_or(mc.compose(&m), "compose", |c| (c.omega() - f.k() - f.i()).norm() <= 4.0 * EPS);
        refused(m.compose(&mc), "compose in the wrong order");
        err_or(FrameMotion::chain(&[m, mc]), "chain", |c| c.omega().is_finite());
        err_or(m.mixed_alpha(&mc.compose(&m).unwrap()), "mixed_alpha", |v| v.is_finite());
        refused(chain_kinematics::<f64>(&[]), "chain_kinematics(empty)");
        let link = LinkMotion { body: lb, omega_rel_prev: f.k(), alpha_rel_prev: f.i(), r_joint_prev_joint: f.j() };
        err_or(chain_kinematics(&[link]), "chain_kinematics", |k| !k.twists.is_empty());
        let nan_link = LinkMotion { omega_rel_prev: f.vector([f64::NAN, 0.0, 0.0]), ..link };
        refused(chain_kinematics(&[nan_link]), "chain_kinematics(NaN)");
        let rl = ResolvedLink { o_k_prev: Matrix3::identity(), omega_rel_prev_in_k: Vector3::new(0.0, 0.0, 1.0), r_joint_prev_joint_in_k: Vector3::new(1.0, 0.0, 0.0) };
        err_or(chain_velocity_resolved(&[rl]), "chain_velocity_resolved", |v| v.iter().all(|t| t.iter().all(|c: &f64| c.is_finite())));
        let bad = ResolvedLink { o_k_prev: Matrix3::from_element(f64::NAN), ..rl };
        refused(chain_velocity_resolved(&[bad]), "chain_velocity_resolved(NaN)");
    }
}
