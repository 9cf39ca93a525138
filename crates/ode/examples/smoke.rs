use vectrix_ode::harness::*;
fn main() {
    let pts = run_all(Budget::Full);
    for p in &pts {
        println!(
            "{:18} {:8} {:9.3e} err {:9.2e} t {:9.3e} fe {:8} {:?}",
            p.problem, p.method, p.param, p.error, p.seconds, p.work.fevals, p.drift
        );
    }
    for d in derive_accuracy(&pts) {
        println!("{d:?}");
    }
}
