//! vectrix-tensor under hostile input (docs/robustness.md).
//!
//! Plain-valued kernel operations are total on finite input whose true result is
//! representable (and propagate NaN/∞ otherwise, IEEE style); `Option`/`Result` functions
//! never hand back a non-finite value.

use crate::support::{NanAmax, nan_max};
use nalgebra::Matrix3;
use vectrix::frames::{Frame, Resolve};
use vectrix::tensor::{
    Arg, Bivector, Covector, DEFAULT_MAX_COMPONENTS, Dyadic, HookeMap, Isotropic, Multivector, Rotor, Scalar,
    Tensor, TensorError, Trivector, Vector, adjugate, check_tolerance, congruent, hooke, reflect, wrap_angle,
};

use crate::harness::{err_or, finite, hostile, hostile3, none_or, refused};

const EPS: f64 = f64::EPSILON;

fn v(x: [f64; 3]) -> Vector {
    Frame::new().vector(x)
}

/// x⃗|_A in the frame A = `Frame::new()` that [`v`] builds in.
fn c3(x: &Vector) -> [f64; 3] {
    x.resolve(&Frame::new()).into()
}

/// M⃗ from its resolution in `Frame::new()`, and back.
fn d(m: Matrix3<f64>) -> Dyadic {
    Frame::new().dyadic(&m)
}
fn m3(m: &Dyadic) -> Matrix3<f64> {
    m.resolve(&Frame::new())
}

/// ‖P P − P‖_max ≤ 8ε: P is idempotent (a projector).
fn idempotent(p: &Dyadic) -> bool {
    let pm = m3(p);
    p.is_finite() && (pm * pm - pm).nan_amax() <= 8.0 * EPS
}

fn unit_len(x: &Vector) -> bool {
    (x.norm() - 1.0).abs() <= 4.0 * EPS
}

/// Hostile tolerances: NaN, ±∞ and negative must be refused by every `Result` function.
const BAD_TOLS: [f64; 4] = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -1e-9];

cases! {
    // |x⃗| is exact for every finite x⃗ whose length is representable (scaled, as the book's
    // (2.1.2) needs no squares), and x̂ = x⃗/|x⃗| has length 1 and the direction of x⃗.
    vector_norm_unit_scaled ["Vector::zero", "Vector::norm", "Vector::norm_squared", "Vector::unit",
        "Vector::is_finite", "Vector::cast"] {
        assert_eq!(Vector::<f64>::zero().norm(), 0.0);
        for x in hostile3() {
            let a = v(x);
            assert_eq!(a.is_finite(), finite(&x));
            none_or(a.unit(), "Vector::unit", |u| unit_len(u) && u.dot(&a.unit().unwrap()) > 0.0 && u.is_finite());
            if finite(&x) {
                let m = x.iter().fold(0.0f64, |m, c| nan_max(m, c.abs()));
                let n = a.norm();
                if m * 1.8 < f64::MAX {
                    assert!(n >= m && n <= m * 3f64.sqrt() * (1.0 + 4.0 * EPS), "|{x:?}| = {n}");
                }
                // x̂ exists for every nonzero finite x⃗ (even when |x⃗| overflows).
                assert_eq!(a.unit().is_some(), m > 0.0, "unit of {x:?}");
                let ns = a.norm_squared();
                assert!(ns >= 0.0);
                if x.iter().all(|c| (*c as f32).is_finite()) {
                    let f32v = a.cast::<f32>().resolve(&Frame::<f32>::identity());
                    assert_eq!(f32v.x, x[0] as f32);
                }
            }
        }
        // (1e200, 1e200, 0) and (f64::MAX, f64::MAX, 0): the unit vector (1, 1, 0)/√2.
        for s in [1e200, f64::MAX, 1e-200, 5e-324] {
            let u = v([s, s, 0.0]).unit().expect("nonzero finite vector");
            assert!((c3(&u)[0] - 0.5f64.sqrt()).abs() <= 2.0 * EPS, "unit({s}) = {u:?}");
        }
    }

    // Angles lie in [0, π] (undirected) and (−π, π] (directed, π for anti-parallel); the unit
    // angle vector is a unit vector ⊥ both; projections split x⃗ into parts along/⊥ ŷ.
    vector_angles_projections ["Vector::angle", "Vector::dot", "Vector::cross", "Vector::triple",
        "Vector::is_parallel", "Vector::is_perpendicular", "Vector::unit_angle_vector_rel",
        "Vector::angle_vector_rel", "Vector::directed_angle_rel", "Vector::projection_along",
        "Vector::projection_perp", "Vector::coform", "Vector::outer", "Vector::cross_dyad"] {
        let others = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [1e-300, 1e300, 0.0]];
        for x in hostile3() {
            let a = v(x);
            for y in others {
                let b = v(y);
                let th = a.angle(&b);
                if a.is_finite() {
                    assert!((0.0..=std::f64::consts::PI).contains(&th), "angle {th}");
                }
                none_or(a.unit_angle_vector_rel(&b), "unit_angle_vector_rel", |n| {
                    unit_len(n) && n.dot(&b.unit().unwrap()).abs() <= 8.0 * EPS
                });
                none_or(a.angle_vector_rel(&b), "angle_vector_rel", |t| t.is_finite() && t.norm() <= std::f64::consts::PI + 4.0 * EPS);
                none_or(a.directed_angle_rel(&b, &v([0.0, 0.0, 1.0])), "directed_angle_rel", |t| {
                    t.is_finite() && *t > -std::f64::consts::PI && *t <= std::f64::consts::PI
                });
                none_or(a.directed_angle_rel(&b, &v([0.0, 0.0, f64::NAN])), "directed_angle_rel(NaN n)", |t| t.is_finite());
                none_or(a.projection_along(&b), "projection_along", |p| p.is_finite() && p.cross(&b).norm() <= 8.0 * EPS * p.norm());
                none_or(a.projection_perp(&b), "projection_perp", |p| p.is_finite() && p.dot(&b.unit().unwrap()).abs() <= 8.0 * EPS * a.norm().max(1.0));
                // Predicates under an invalid tolerance answer "no" (docs/robustness.md).
                assert!(!a.is_parallel(&b, f64::NAN) || a.unit().is_none());
                let _ = a.is_perpendicular(&b, f64::NAN);
                if finite(&x) && x.iter().all(|c| c.abs() <= 1.0) {
                    assert!(a.dot(&b).is_finite() && a.cross(&b).is_finite() && a.triple(&b, &b).abs() <= 1e-300f64.max(a.norm() * 4.0 * EPS));
                    assert!((a.coform().apply(&b) - a.dot(&b)).abs() <= 4.0 * EPS);
                    assert!(a.outer(&b).is_finite() && a.cross_dyad().apply(&b).is_finite());
                }
            }
        }
    }

    // Bivectors: x⃗∧y⃗ = 𝒥(x⃗×y⃗); the dual round trips; B̂ has norm 1; î∧ĵ∧k̂ = 𝒥.
    bivector_trivector_hostile ["Bivector::zero", "Bivector::dual_of", "Bivector::undual", "Bivector::norm", "Bivector::area", "Bivector::unit",
        "Bivector::is_finite", "Bivector::to_tensor", "Bivector::from_tensor", "Bivector::wedge",
        "Vector::wedge", "Vector::wedge_bivector", "Vector::wedge3", "Trivector::j", "Trivector::zero",
        "Trivector::new", "Trivector::coefficient", "Trivector::volume", "Trivector::to_tensor",
        "Trivector::from_tensor", "Tensor::wedge", "Tensor::is_alternating", "Tensor::alternating_magnitude"] {
        assert_eq!(Bivector::<f64>::zero().norm(), 0.0);
        assert_eq!(Trivector::<f64>::zero().volume(), 0.0);
        assert_eq!(Trivector::<f64>::j().coefficient(), 1.0);
        let (e1, e2, e3) = (v([1.0, 0.0, 0.0]), v([0.0, 1.0, 0.0]), v([0.0, 0.0, 1.0]));
        assert!((e1.wedge(&e2).wedge(&e3).coefficient() - 1.0).abs() <= EPS);
        assert!((e1.wedge3(&e2, &e3).coefficient() - 1.0).abs() <= EPS);
        assert!((e1.wedge_bivector(&e2.wedge(&e3)).coefficient() - 1.0).abs() <= EPS);
        for x in hostile3() {
            let a = v(x);
            let b = Bivector::dual_of(&a);
            assert_eq!(b.is_finite(), a.is_finite());
            none_or(b.unit(), "Bivector::unit", |u| (u.norm() - 1.0).abs() <= 4.0 * EPS);
            for t in [Trivector::new(x[0]), e1.wedge(&e2).wedge(&a)] {
                err_or(Trivector::from_tensor(&t.to_tensor(), 0.0), "Trivector::from_tensor", |r| r.coefficient().is_finite());
                for tol in BAD_TOLS {
                    refused(Trivector::from_tensor(&t.to_tensor(), tol), "Trivector::from_tensor(bad tol)");
                }
            }
            if a.is_finite() {
                // undual ∘ dual = id, exactly (a relabelling of components)
                assert_eq!(c3(&b.undual()), c3(&a));
                assert!(b.norm() >= 0.0 && b.area() >= 0.0 && Trivector::new(x[0]).volume() >= 0.0);
                err_or(Bivector::from_tensor(&b.to_tensor(), 0.0), "from_tensor", |bb| bb == &b);
                for tol in BAD_TOLS {
                    refused(Bivector::from_tensor(&b.to_tensor(), tol), "Bivector::from_tensor(bad tol)");
                }
                let ta = Tensor::from_vector(&a);
                err_or(ta.wedge(&Tensor::from_vector(&e1)), "Tensor::wedge", |w| {
                    w.is_alternating(0.0) && w.alternating_magnitude() >= 0.0 || !w.is_finite()
                });
            }
        }
    }

    // Dyadics: the inverse satisfies M M⁻¹ = I (relative to |M||M⁻¹|), is refused for singular,
    // non-finite or invalid-tolerance input; projectors are idempotent.
    dyadic_hostile ["Dyadic::zero", "Dyadic::identity", "Dyadic::apply", "Dyadic::coform", "Dyadic::trace", "Dyadic::determinant", "Dyadic::inverse",
        "Dyadic::symmetric_part", "Dyadic::skew_part", "Dyadic::vee", "Dyadic::projector_along",
        "Dyadic::projector_perp", "Dyadic::projector_onto_plane", "Dyadic::is_symmetric", "Dyadic::is_skew",
        "Dyadic::invariants", "Dyadic::cayley_hamilton_residual", "Dyadic::determinant_from_traces",
        "Dyadic::trace_of_inverse", "Dyadic::cross_polynomial_inverse", "Dyadic::norm", "Dyadic::is_finite",
        "Dyadic::cast", "adjugate", "check_tolerance"] {
        assert_eq!(Dyadic::<f64>::identity().trace(), 3.0);
        assert_eq!(Dyadic::<f64>::zero().norm(), 0.0);
        for s in hostile() {
            let m = d(Matrix3::new(s, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0));
            assert_eq!(m.is_finite(), s.is_finite());
            if s.is_finite() {
                assert_eq!(m3(&m)[(0, 0)], s);
            }
            err_or(m.inverse(0.0), "Dyadic::inverse", |mi| {
                let r = (m3(&m) * m3(mi) - Matrix3::identity()).nan_amax();
                mi.is_finite() && r <= 16.0 * EPS * m3(&m).nan_amax() * m3(mi).nan_amax()
            });
            err_or(m.trace_of_inverse(0.0), "trace_of_inverse", |t| t.is_finite());
            for tol in BAD_TOLS {
                refused(m.inverse(tol), "Dyadic::inverse(bad tol)");
                refused(check_tolerance(tol, "tol"), "check_tolerance");
            }
            err_or(Dyadic::cross_polynomial_inverse(&v([s, 0.0, 1.0]), 1.0, 1.0, 0.0), "cross_polynomial_inverse", |d| d.is_finite());
            err_or(Dyadic::cross_polynomial_inverse(&v([1.0, 0.0, 1.0]), s, 1.0, f64::NAN), "cross_polynomial_inverse(NaN tol)", |_| false);
            if s.is_finite() && s.abs() <= 1e100 {
                assert!(m.trace().is_finite() && m.determinant().is_finite() && m.norm().is_finite());
                assert!(m.symmetric_part().is_symmetric(0.0) && m.skew_part().is_skew(0.0));
                assert!(m.vee().is_finite() && m.coform().apply(&v([1.0, 1.0, 1.0])).is_finite());
                assert!(m.invariants().iter().all(|x| x.is_finite()) && m.determinant_from_traces().is_finite());
                assert!(m.cayley_hamilton_residual().is_finite() && adjugate(&m3(&m)).iter().all(|x| x.is_finite()));
                assert_eq!(m.cast::<f32>().resolve(&Frame::<f32>::identity())[(0, 1)], 1.0f32);
            }
        }
        for x in hostile3() {
            let a = v(x);
            none_or(Dyadic::projector_along(&a), "projector_along", idempotent);
            none_or(Dyadic::projector_perp(&a), "projector_perp", idempotent);
            none_or(Dyadic::projector_onto_plane(&a, &v([0.0, 0.0, 1.0])), "projector_onto_plane", idempotent);
        }
    }

    // Rotors: |R| = 1 for every rotor a constructor returns; exp is finite for every finite
    // bivector (exp(1e300 𝒥k̂) is a rotation); log∘exp round trips the rotation; the sandwich
    // preserves length.
    rotor_hostile ["Rotor::identity", "Rotor::from_axis_angle", "Rotor::scalar", "Rotor::bivector",
        "Rotor::from_parts_unchecked", "Rotor::reverse", "Rotor::rotate", "Rotor::then", "Rotor::gp",
        "Rotor::to_dyadic", "Rotor::normalize", "Rotor::from_plane_angle", "Rotor::from_two_vectors",
        "Rotor::between", "Rotor::between_or_half_turn", "Rotor::exp", "Rotor::log", "Rotor::angle",
        "Rotor::sandwich", "Rotor::sandwich_bivector", "Rotor::sandwich_multivector",
        "Rotor::to_multivector", "Rotor::from_multivector", "Rotor::norm", "reflect"] {
        let unit_rotor = |r: &Rotor| r.scalar().is_finite() && r.bivector().is_finite() && (r.norm() - 1.0).abs() <= 8.0 * EPS;
        assert!(unit_rotor(&Rotor::identity()));
        let k = v([0.0, 0.0, 1.0]);
        for th in hostile() {
            none_or(Rotor::from_axis_angle(&k, th), "Rotor::from_axis_angle", unit_rotor);
            none_or(Rotor::from_plane_angle(&v([1.0, 0.0, 0.0]), &v([0.0, 1.0, 0.0]), th), "from_plane_angle", unit_rotor);
            let r = Rotor::exp(&Bivector::dual_of(&v([0.0, 0.0, th])));
            if th.is_finite() {
                assert!(unit_rotor(&r), "exp({th}) = {r:?}");
                // exp(−𝒥k̂θ/2) rotates î by θ about k̂; the rotation it represents has log = that angle mod 2π
                let x = r.sandwich(&v([1.0, 0.0, 0.0]));
                assert!((x.norm() - 1.0).abs() <= 8.0 * EPS && c3(&x)[2].abs() <= 8.0 * EPS);
                let b = r.log();
                assert!(b.is_finite() && (0.0..=std::f64::consts::PI + 4.0 * EPS).contains(&r.angle()));
                assert!((Rotor::exp(&b).rotate(&x) - r.rotate(&x)).norm() <= 16.0 * EPS);
            }
        }
        for x in hostile3() {
            let a = v(x);
            none_or(Rotor::between(&a, &k), "Rotor::between", |r| {
                unit_rotor(r) && (r.rotate(&a.unit().unwrap()) - k).norm() <= 16.0 * EPS
            });
            none_or(Rotor::from_two_vectors(&a, &k), "from_two_vectors", unit_rotor);
            none_or(Rotor::between_or_half_turn(&a, &k, &v([1.0, 0.0, 0.0])), "between_or_half_turn", unit_rotor);
            none_or(reflect(&k, &a), "reflect", |y| (y.norm() - 1.0).abs() <= 8.0 * EPS);
            // Normalising a scaled unit rotor: (1e200, …) and (1e-200, …) come back unit.
            for s in [1e200, 1e-200, 5e-324, f64::MAX, f64::NAN, f64::INFINITY] {
                let raw = Rotor::from_parts_unchecked(s, Bivector::dual_of(&k) * s);
                none_or(raw.normalize(), "Rotor::normalize", unit_rotor);
                if s.is_finite() {
                    assert!(raw.normalize().is_some(), "normalize({s})");
                }
            }
            let r = Rotor::from_axis_angle(&v([1.0, 2.0, 3.0]), 0.7).unwrap();
            if a.is_finite() && a.norm() < 1e300 {
                let y = r.rotate(&a);
                // |R x⃗ R̄| = |x⃗|, relative, with a floor for subnormal components
                assert!((y.norm() - a.norm()).abs() <= (8.0 * EPS * a.norm()).max(16.0 * 5e-324), "rotate {x:?} → {y:?}");
                assert!((r.reverse().then(&r).scalar() - 1.0).abs() <= 4.0 * EPS);
                assert!(unit_rotor(&r.gp(&r)) && r.to_dyadic().is_finite());
                assert!(r.sandwich_bivector(&Bivector::dual_of(&k)).is_finite());
                assert!(r.sandwich_multivector(&Multivector::scalar(1.0)).is_finite());
            }
        }
        let m = Rotor::from_axis_angle(&k, 1.0).unwrap().to_multivector();
        err_or(Rotor::from_multivector(&m, 0.0), "from_multivector", unit_rotor);
        for tol in BAD_TOLS {
            refused(Rotor::from_multivector(&m, tol), "from_multivector(bad tol)");
        }
        refused(Rotor::from_multivector(&Multivector::scalar(f64::NAN), 1.0), "from_multivector(NaN)");
    }

    // Multivectors of Cl(3,0): grades split and recombine; the reverse of a product is the
    // product of reverses; Pauli matrices round trip.
    multivector_hostile ["Multivector::new", "Multivector::zero", "Multivector::scalar",
        "Multivector::pseudoscalar", "Multivector::scalar_part", "Multivector::vector_part",
        "Multivector::bivector_part", "Multivector::trivector_part", "Multivector::grade", "Multivector::gp",
        "Multivector::wedge", "Multivector::reverse", "Multivector::grade_involution",
        "Multivector::clifford_conjugate", "Multivector::book_conjugate", "Multivector::dual",
        "Multivector::undual", "Multivector::norm", "Multivector::grade_tensor", "Multivector::from_grade_tensors",
        "Multivector::is_finite", "Vector::gp", "Multivector::to_pauli", "Multivector::from_pauli"] {
        let f = Frame::new();
        let axes = [f.i(), f.j(), f.k()];
        for x in hostile3() {
            let a = v(x);
            let m = Multivector::new(x[0], &a, &Bivector::dual_of(&a), &Trivector::new(x[1]));
            assert_eq!(m.is_finite(), finite(&x));
            let parts: Vec<Tensor> = (0..=3).filter_map(|k| m.grade_tensor(k)).collect();
            err_or(Multivector::from_grade_tensors(&parts, 0.0), "from_grade_tensors", |r| r == &m);
            for tol in BAD_TOLS {
                refused(Multivector::from_grade_tensors(&parts, tol), "from_grade_tensors(bad tol)");
            }
            assert!(m.grade_tensor(4).is_none());
            if m.is_finite() && x.iter().all(|c| c.abs() <= 1e100) {
                let sum = m.grade(0) + m.grade(1) + m.grade(2) + m.grade(3);
                assert_eq!(sum, m);
                assert_eq!(m.scalar_part(), x[0]);
                assert_eq!(m.vector_part(), a);
                assert_eq!(m.bivector_part(), Bivector::dual_of(&a));
                assert_eq!(m.trivector_part().coefficient(), x[1]);
                let p = Multivector::pseudoscalar();
                assert!((m.gp(&p).reverse() - p.reverse().gp(&m.reverse())).norm() <= 8.0 * EPS * m.norm());
                assert!(m.wedge(&Multivector::scalar(1.0)) == m && m.grade_involution().grade_involution() == m);
                assert!(m.clifford_conjugate().is_finite() && m.book_conjugate().is_finite());
                assert!((m.dual().undual() - m).norm() <= 4.0 * EPS * m.norm());
                assert!(a.gp(&a).scalar_part() >= 0.0);
                let pauli = m.to_pauli(&axes).unwrap();
                err_or(Multivector::from_pauli(&axes, &pauli), "from_pauli", |r| (*r - m).norm() <= 8.0 * EPS * m.norm().max(1e-300));
            }
            assert_eq!(Multivector::<f64>::zero().norm(), 0.0);
        }
        // Non-orthonormal or non-finite axes are refused.
        refused(Multivector::scalar(1.0).to_pauli(&[axes[0], axes[0], axes[2]]), "to_pauli(repeated axis)");
        refused(Multivector::scalar(1.0).to_pauli(&[axes[0], axes[1], v([f64::NAN, 0.0, 1.0])]), "to_pauli(NaN axis)");
    }

    // Tensors: sizes the user controls are bounded (TooLarge, not an abort); shapes are
    // checked; non-finite components are refused at the boundary.
    tensor_sizes_shapes ["Tensor::components_for", "Tensor::max_components", "Tensor::with_max_components",
        "Tensor::zeros", "Tensor::zeros_with_limit", "Tensor::scalar", "Tensor::from_vector", "Tensor::from_covector",
        "Tensor::from_dyadic", "Tensor::from_factors", "Tensor::from_factors_with_limit", "Tensor::p", "Tensor::q",
        "Tensor::order", "Tensor::to_vector", "Tensor::to_covector", "Tensor::to_dyadic", "Tensor::to_scalar",
        "Tensor::frobenius_norm", "Tensor::is_finite", "Tensor::try_add", "Tensor::try_sub", "Tensor::otimes",
        "Tensor::contract", "Tensor::contracted_product", "Tensor::eval", "Tensor::partial_eval",
        "Tensor::coform", "Tensor::permute", "Tensor::metric", "Tensor::cometric", "Tensor::identity",
        "Tensor::levi_civita", "Tensor::u4", "Covector::zero", "Covector::coform", "Covector::apply", "Covector::norm", "Covector::is_finite", "Covector::cast"] {
        for order in [20usize, 40, 64, 1000, usize::MAX] {
            refused(Tensor::<f64>::components_for(order, DEFAULT_MAX_COMPONENTS), "components_for");
            refused(Tensor::<f64>::zeros(order, 0), "zeros(huge)");
            refused(Tensor::<f64>::zeros(0, order), "zeros(huge)");
            refused(Tensor::<f64>::zeros_with_limit(order, 0, DEFAULT_MAX_COMPONENTS), "zeros_with_limit(huge)");
        }
        // 3^order overflows u128 long before usize::MAX bounds it: still a typed error
        refused(Tensor::<f64>::zeros_with_limit(1000, 0, usize::MAX), "zeros_with_limit(3^1000)");
        refused(Tensor::<f64>::zeros_with_limit(usize::MAX, usize::MAX, usize::MAX), "zeros_with_limit(usize::MAX)");
        assert_eq!(Tensor::<f64>::identity().max_components(), DEFAULT_MAX_COMPONENTS);
        let t = Tensor::<f64>::zeros(1, 1).unwrap();
        assert_eq!((t.p(), t.q(), t.order()), (1, 1, 2));
        assert_eq!(Tensor::<f64>::levi_civita().order(), 3);
        assert_eq!(Tensor::<f64>::metric().q(), 2);
        assert_eq!(Tensor::<f64>::cometric().p(), 2);
        assert_eq!(Tensor::<f64>::identity().order(), 2);
        assert_eq!(Tensor::<f64>::u4().order(), 4);
        let _ = Tensor::<f64>::from_factors(&[], &[]);
        let a = Tensor::from_vector(&v([1.0, 2.0, 3.0]));
        let b = Tensor::from_dyadic(&Dyadic::identity());
        refused(a.try_add(&b), "try_add(mismatched)");
        refused(a.try_sub(&b), "try_sub(mismatched)");
        refused(a.contract(&[(1, 1)]), "contract(same slot)");
        refused(a.contract(&[(1, 9)]), "contract(no slot)");
        refused(a.permute(&[2, 1]), "permute(wrong length)");
        refused(b.permute(&[1, 1]), "permute(not a permutation)");
        refused(a.eval(&[], &[]), "eval(missing arguments)");
        refused(b.partial_eval(&[Arg::Vector(v([1.0, 0.0, 0.0]))], &[7]), "partial_eval(no slot)");
        refused(a.contracted_product(&b, &[(5, 5)]), "contracted_product(no slot)");
        for s in hostile() {
            let x = v([s, 1.0, 0.0]);
            let cx = Frame::new().covector([s, 1.0, 0.0]);
            assert_eq!(cx.is_finite(), s.is_finite());
            assert_eq!(Covector::<f64>::zero().norm(), 0.0);
            if s.is_finite() {
                assert_eq!(cx.coform(), x);
            }
            let ts = Tensor::scalar(s);
            assert_eq!(ts.is_finite(), s.is_finite());
            if s.is_finite() && s.abs() <= 1e100 {
                let tx = Tensor::from_vector(&x);
                assert_eq!(tx.to_vector(), Some(x));
                assert_eq!(Tensor::from_covector(&cx).to_covector(), Some(cx));
                assert!(tx.to_dyadic().is_none() && tx.to_scalar().is_none());
                assert_eq!(ts.to_scalar(), Some(s));
                assert!(tx.frobenius_norm() >= s.abs());
                let txx = tx.otimes(&Tensor::from_covector(&cx)).unwrap();
                // contraction pairs (vector slot k, covector slot l), each numbered from 1
                let tr = txx.contract(&[(1, 1)]).unwrap().to_scalar().unwrap();
                assert!((tr - cx.apply(&x)).abs() <= 4.0 * EPS * (s * s + 1.0));
                assert_eq!(tx.coform().q(), 1);
                assert!(tx.eval(&[cx], &[]).unwrap().is_finite());
                assert_eq!(tx.try_add(&tx).unwrap().try_sub(&tx).unwrap(), tx);
                assert!(tx.contracted_product(&Tensor::from_covector(&cx), &[(1, 1)]).unwrap().is_finite());
                assert!(txx.partial_eval(&[Arg::Vector(x)], &[1]).unwrap().is_finite());
                assert!(Tensor::from_factors(&[x], &[cx]).unwrap().is_finite());
                err_or(txx.permute(&[2, 1]), "permute", |t| t.is_finite() && t.order() == 2);
                assert_eq!(cx.cast::<f32>().resolve(&Frame::<f32>::identity())[1], 1.0f32);
                assert!(cx.norm() >= s.abs());
            }
        }
        // The cap travels with each tensor (no process-wide state): a product of two tensors
        // takes the larger cap, and is refused above it before anything is allocated.
        let small = Tensor::<f64>::identity().with_max_components(81).unwrap();
        assert_eq!(small.max_components(), 81);
        let u4 = small.otimes(&small).unwrap(); // order 4: 81 components, at the cap
        assert_eq!(u4.max_components(), 81);
        refused(u4.otimes(&small), "otimes above a lowered cap");
        refused(small.wedge(&small), "wedge of mixed types");
        assert_eq!(small.otimes(&Tensor::identity()).unwrap().max_components(), DEFAULT_MAX_COMPONENTS);
        refused(Tensor::<f64>::zeros_with_limit(5, 0, 81), "zeros_with_limit above the cap");
        refused(Tensor::from_factors_with_limit(&[v([1.0, 0.0, 0.0]); 5], &[], 81), "from_factors_with_limit above the cap");
        err_or(Tensor::from_factors_with_limit(&[v([1.0, 0.0, 0.0]); 4], &[], 81), "from_factors_with_limit", |t| {
            t.max_components() == 81 && t.eval(&[Frame::new().covector([1.0, 0.0, 0.0]); 4], &[]) == Ok(1.0)
        });
        // a cap below the tensor's own size is refused, 0 included; any cap at or above it is kept
        for limit in [0, 1, 8, 80] {
            refused(Tensor::<f64>::u4().with_max_components(limit), "with_max_components below the size");
        }
        for limit in [81, 3usize.pow(16), usize::MAX] {
            err_or(Tensor::<f64>::u4().with_max_components(limit), "with_max_components", |t| t.max_components() == limit);
        }
        // a raised cap admits orders above the default on that tensor (checked here, not allocated)
        let raised = Tensor::<f64>::zeros(7, 0).unwrap().with_max_components(3usize.pow(15)).unwrap();
        refused(Tensor::<f64>::zeros(7, 0).unwrap().otimes(&Tensor::zeros(0, 8).unwrap()), "order 15 at the default cap");
        assert_eq!(raised.otimes(&Tensor::scalar(2.0)).unwrap().max_components(), 3usize.pow(15));
    }

    // Scalars and angles: wrap_angle lands in (−π, π] for every finite angle (1e300 too) and
    // is congruent to its input; the Scalar bound's helpers are exact.
    angles_scalars ["wrap_angle", "congruent", "Scalar::re", "Scalar::lit", "Scalar::eps"] {
        for a in hostile() {
            let w = wrap_angle(a);
            if a.is_finite() {
                assert!(w > -std::f64::consts::PI && w <= std::f64::consts::PI, "wrap_angle({a}) = {w}");
                assert!(congruent(w, a, 1e-9 * a.abs().max(1.0)) || a.abs() > 1e15);
            }
            assert!(!congruent(a, a, f64::NAN), "an invalid tolerance accepts nothing");
            assert_eq!(<f64 as Scalar>::re(&a).to_bits(), a.to_bits());
            assert_eq!(<f64 as Scalar>::lit(a).to_bits(), a.to_bits());
        }
        assert_eq!(<f64 as Scalar>::eps(), EPS);
    }

    // The fast-path hooks of Scalar: for f64 within 1 ulp of libm's values on each side (2ε
    // apart for |value| ≤ 1; 2ε relative for atan2), libm's NaN for NaN and ±∞, the same bits
    // one, three and a slice at a time; the series of cos h and sin h / h only on its range.
    scalar_hooks ["Scalar::fast_sin_cos", "Scalar::fast_sin_cos3", "Scalar::fast_sin_cos_slices",
        "Scalar::fast_atan2", "Scalar::fast_cos_sinc_of_square"] {
        let xs: Vec<f64> = hostile().collect();
        let (mut s, mut c) = (vec![0.0; xs.len()], vec![0.0; xs.len()]);
        f64::fast_sin_cos_slices(&xs, &mut s, &mut c);
        let same = |a: f64, b: f64| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan());
        for (k, &a) in xs.iter().enumerate() {
            let (fs, fc) = a.fast_sin_cos();
            let (ls, lc) = a.sin_cos();
            assert!(same(fs, ls) || (fs - ls).abs() <= 2.0 * EPS, "sin {a:e}: {fs:e} vs {ls:e}");
            assert!(same(fc, lc) || (fc - lc).abs() <= 2.0 * EPS, "cos {a:e}: {fc:e} vs {lc:e}");
            assert!(same(s[k], fs) && same(c[k], fc), "slices at {a:e}");
            for (t3, c3) in f64::fast_sin_cos3([a, 0.5, a]) {
                assert!(t3.is_nan() || t3.abs() <= 1.0, "sin_cos3 at {a:e}");
                assert!(c3.is_nan() || c3.abs() <= 1.0, "sin_cos3 at {a:e}");
            }
            for b in hostile() {
                let (f, l) = (a.fast_atan2(b), a.atan2(b));
                assert!(same(f, l) || (f - l).abs() <= 2.0 * EPS * l.abs(), "atan2({a:e}, {b:e})");
            }
            if let Some((ch, sinc)) = a.fast_cos_sinc_of_square() {
                // cos √u and sin √u / √u, continued to cosh √−u and sinh √−u / √−u for u < 0
                let (want_c, want_s) = if a >= 0.0 {
                    let h = a.sqrt();
                    (h.cos(), if h == 0.0 { 1.0 } else { h.sin() / h })
                } else {
                    let g = (-a).sqrt();
                    (g.cosh(), g.sinh() / g)
                };
                assert!((ch - want_c).abs() <= 4.0 * EPS * want_c.abs().max(1.0), "cos_sinc({a:e})");
                assert!((sinc - want_s).abs() <= 4.0 * EPS * want_s.abs().max(1.0), "cos_sinc({a:e})");
            }
        }
    }

    // Elasticity: moduli are validated (NaN, negative, ν ≥ ½ refused); Hooke's law maps a
    // symmetric strain to a symmetric stress, and strain(stress(ε)) = ε.
    elasticity_hostile ["Isotropic::from_lame", "Isotropic::from_young_poisson", "Isotropic::lambda",
        "Isotropic::mu", "Isotropic::young", "Isotropic::poisson", "Isotropic::bulk", "Isotropic::stiffness",
        "Isotropic::stress", "Isotropic::strain", "hooke", "HookeMap::new", "HookeMap::apply", "HookeMap::apply_many"] {
        for x in hostile() {
            err_or(Isotropic::from_lame(x, 1.0), "from_lame", |m: &Isotropic| m.lambda().is_finite() && m.young().is_finite());
            err_or(Isotropic::from_young_poisson(1.0, x), "from_young_poisson", |m: &Isotropic| {
                m.poisson().is_finite() && m.bulk().is_finite() && m.mu() > 0.0
            });
            err_or(Isotropic::from_young_poisson(x, 0.3), "from_young_poisson", |m: &Isotropic| m.mu().is_finite());
        }
        let iso = Isotropic::from_young_poisson(200e9, 0.3).unwrap();
        let eps = d(Matrix3::new(1e-3, 2e-4, 0.0, 2e-4, 0.0, 0.0, 0.0, 0.0, -1e-3));
        let sigma = iso.stress(&eps);
        assert!(sigma.is_symmetric(1e-6 * sigma.norm()));
        // round trip ε → σ → ε: 1e3 ulps of the strain's scale (1e-3), for the E = 2e11 Pa
        // stiffness and its inverse (condition ≈ 1e1) applied in sequence
        assert!((m3(&iso.strain(&sigma)) - m3(&eps)).nan_amax() <= 1e3 * EPS * 1e-3);
        let k = iso.stiffness();
        let h = hooke(&k, &eps).unwrap();
        assert!((m3(&h) - m3(&sigma)).nan_amax() <= 1e3 * EPS * sigma.norm());
        refused(hooke(&Tensor::from_dyadic(&eps), &eps), "hooke(wrong order)");
        refused(HookeMap::new(&Tensor::from_dyadic(&eps)), "HookeMap::new(wrong order)");
        let map = HookeMap::new(&k).unwrap();
        assert!((m3(&map.apply(&eps)) - m3(&sigma)).nan_amax() <= 1e3 * EPS * sigma.norm());
        let mut out = vec![Dyadic::zero(); 1];
        refused(map.apply_many(&[eps, eps], &mut out), "apply_many(mismatched lengths)");
        map.apply_many(&[], &mut []).unwrap();
        let _: Result<(), TensorError> = map.apply_many(&[eps], &mut out);
        assert!(out[0].is_finite());
    }
}
