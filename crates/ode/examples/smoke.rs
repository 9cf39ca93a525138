use vectrix_ode::harness::*;
use vectrix_ode::*;
fn main() {
    let k = Kepler { e: 0.5 };
    for th in [0.3, 0.5, 0.7] {
        let mut prev = 0.0;
        for h in [0.8, 0.4, 0.2, 0.1, 0.05] {
            let sol = Adaptive::dop853()
                .rtol(1.0)
                .atol(1.0)
                .h0(h)
                .h_max(h)
                .dense(true)
                .solve(|t, y| k.rhs(t, y), 0.0, &k.y0(), h)
                .unwrap();
            let e = (sol.sample(th * h).unwrap() - k.exact(th * h)).amax();
            let e1 = (sol.last() - k.exact(h)).amax();
            println!(
                "th {th} h {h} acc {} err {e:e} slope {:.2} end err {e1:e}",
                sol.work.accepted,
                (prev / e as f64).log2()
            );
            prev = e;
        }
    }
}
