use vectrix_ode::harness::*;
use vectrix_ode::*;
fn main() {
    let k = Kepler { e: 0.9 };
    for rtol in [1e-6, 1e-10, 1e-13] {
        for a in [Adaptive::dopri5(), Adaptive::dop853()] {
            let s = a.rtol(rtol).atol(rtol).solve(|t, y| k.rhs(t, y), 0.0, &k.y0(), k.t_end()).unwrap();
            println!("kepler {:?} {rtol:e} err {:e} {}", a.pair, k.error(s.last()), s.work);
        }
    }
    let rb = RigidBody::default();
    let s = Adaptive::dop853()
        .rtol(1e-13)
        .atol(1e-13)
        .solve(|t, y| rb.rhs(t, y), 0.0, &rb.y0(), rb.t_end())
        .unwrap();
    println!("rigid err {:e} {}", rb.error(s.last()), s.work);
    let rb2 = RigidBody { omega13: [0.2, 2.0], ..rb };
    let s = Adaptive::dop853()
        .rtol(1e-13)
        .atol(1e-13)
        .solve(|t, y| rb2.rhs(t, y), 0.0, &rb2.y0(), rb2.t_end())
        .unwrap();
    println!("rigid2 err {:e} {}", rb2.error(s.last()), s.work);
    let p = Pendulum { theta0: 3.0 };
    let s = Adaptive::dop853()
        .rtol(1e-13)
        .atol(1e-13)
        .solve(|t, y| p.rhs(t, y), 0.0, &p.y0(), p.t_end())
        .unwrap();
    println!("pend err {:e} {}", p.error(s.last()), s.work);
    let c = SpringChain { alpha: 100.0 };
    let s = Adaptive::dop853()
        .rtol(1e-12)
        .atol(1e-12)
        .solve(|t, y| c.rhs(t, y), 0.0, &c.y0(), c.t_end())
        .unwrap();
    println!("chain err {:e} {}", c.error(s.last()), s.work);
    for g in [GaussLegendre::Midpoint, GaussLegendre::Gauss4, GaussLegendre::Gauss6] {
        let (y, w) = g.integrate(|t, y| c.rhs(t, y), 0.0, &c.y0(), c.t_end(), 200, |_, _| {}).unwrap();
        println!("chain {:?} err {:e} {}", g, c.error(&y), w);
        let (y, w) = g.integrate(|t, y| k.rhs(t, y), 0.0, &k.y0(), k.t_end(), 4000, |_, _| {}).unwrap();
        println!("kepler {:?} err {:e} {}", g, k.error(&y), w);
    }
    let a = vectrix_frames::Frame::new();
    let f = rb.lie_rhs(&a);
    for m in [LieMethod::ExponentialEuler, LieMethod::CrouchGrossman3, LieMethod::Rkmk4] {
        for n in [1000, 2000] {
            let (y, w) = integrate_lie(m, &f, 0.0, &rb.lie_y0(&a), rb.t_end, n, |_, _| {}).unwrap();
            println!("lie {:?} {n} {:?} {}", m, rb.lie_error(&a, &y), w);
        }
    }
}
