//! The coverage test: every public function of a crate has a case.
//!
//! For each crate the table below says which part of its API is enforced (all of every crate;
//! the command line's only when it is built); a crate being swept can be switched off or
//! restricted to the files already swept while its fixes land (`Enforce::Off`, `Files`). Stale
//! names (a case naming a function that no longer exists) fail for every crate.

use crate::api::{PublicFn, public_functions};

/// Which public functions of a crate must have a case.
#[allow(dead_code)]
pub enum Enforce {
    /// Every public function.
    All,
    /// Every public function except those defined in these files (relative to `src/`).
    AllExcept(&'static [&'static str]),
    /// Only functions defined in these files.
    Files(&'static [&'static str]),
    /// None yet: the uncovered list is printed, not failed.
    Off,
}

impl Enforce {
    fn applies(&self, f: &PublicFn) -> bool {
        match self {
            Enforce::All => true,
            Enforce::AllExcept(files) => !files.contains(&f.file.as_str()),
            Enforce::Files(files) => files.contains(&f.file.as_str()),
            Enforce::Off => false,
        }
    }
}

/// One crate: its folder under `crates/`, its case table and what is enforced.
pub struct Crate {
    pub dir: &'static str,
    pub covered: &'static [&'static str],
    pub enforce: Enforce,
}

/// The crates the suite knows.
pub fn crates() -> Vec<Crate> {
    vec![
        Crate { dir: "tensor", covered: crate::tensor::COVERED, enforce: Enforce::All },
        Crate { dir: "frames", covered: crate::frames::COVERED, enforce: Enforce::All },
        Crate { dir: "rotation", covered: crate::rotation::COVERED, enforce: Enforce::All },
        Crate { dir: "kinematics", covered: crate::kinematics::COVERED, enforce: Enforce::All },
        Crate { dir: "statics", covered: crate::statics::COVERED, enforce: Enforce::All },
        Crate { dir: "ode", covered: crate::ode::COVERED, enforce: Enforce::All },
        // catalog.rs included: flight.rs covers the catalogue (and the scene crate's flight scenes).
        Crate { dir: "flight", covered: crate::flight::COVERED, enforce: Enforce::All },
        // control.rs included: plot.rs covers the control figures.
        Crate { dir: "plot", covered: crate::plot::COVERED, enforce: Enforce::All },
        // Newton–Euler, collisions, energy, networks, 6D (dynamics.rs); multibody, Lagrange,
        // constraints and Kane (multibody.rs).
        Crate {
            dir: "dynamics",
            covered: joined(&[crate::dynamics::COVERED, crate::multibody::COVERED]),
            enforce: Enforce::All,
        },
        // scenes (scene.rs), the format's paths and document (scene_format.rs) and aircraft
        // scenes (aircraft_scene.rs).
        Crate {
            dir: "scene",
            covered: joined(&[
                crate::scene::COVERED,
                crate::scene_format::COVERED,
                crate::aircraft_scene::COVERED,
            ]),
            enforce: Enforce::All,
        },
        Crate { dir: "lti", covered: crate::lti::COVERED, enforce: Enforce::All },
        // cli.rs runs the command (only built with the default `cli` feature).
        Crate {
            dir: "cli",
            covered: crate::cli::COVERED,
            enforce: if cfg!(feature = "cli") { Enforce::All } else { Enforce::Off },
        },
    ]
}

/// The union of several case tables (a crate whose cases live in several files).
fn joined(parts: &[&'static [&'static str]]) -> &'static [&'static str] {
    Box::leak(parts.concat().into_boxed_slice())
}

fn uncovered(c: &Crate) -> (Vec<PublicFn>, Vec<PublicFn>) {
    let api = public_functions(c.dir);
    api.into_iter().filter(|f| !c.covered.contains(&f.name.as_str())).partition(|f| c.enforce.applies(f))
}

#[test]
fn every_public_function_has_an_adversarial_case() {
    let mut report = String::new();
    for c in crates() {
        let (enforced, _) = uncovered(&c);
        for f in enforced {
            report.push_str(&format!("  {}: {} ({})\n", c.dir, f.name, f.file));
        }
    }
    assert!(report.is_empty(), "public functions without an adversarial case:\n{report}");
}

#[test]
fn every_case_names_a_public_function() {
    let mut report = String::new();
    for c in crates() {
        let api = public_functions(c.dir);
        for name in c.covered {
            if !api.iter().any(|f| f.name == *name) {
                report.push_str(&format!("  {}: {name}\n", c.dir));
            }
        }
    }
    assert!(report.is_empty(), "cases name functions that are not public API:\n{report}");
}

/// Prints the functions of the switched-off parts that still need cases, and checks that a
/// crate enforced in full has none
/// (`cargo test --test adversarial pending -- --nocapture`).
#[test]
fn pending_cases_are_listed() {
    for c in crates() {
        let (_, pending) = uncovered(&c);
        // a crate enforced in full has nothing pending (the list is for the switched-off parts)
        assert!(
            pending.is_empty() || !matches!(c.enforce, Enforce::All),
            "{}: enforced in full but {} functions are listed as pending",
            c.dir,
            pending.len()
        );
        if !pending.is_empty() {
            eprintln!("{}: {} public functions without a case (not enforced yet)", c.dir, pending.len());
            for f in pending {
                eprintln!("  {} ({})", f.name, f.file);
            }
        }
    }
}

/// The API walker itself: known functions are found, with their qualified names; private
/// ones are not.
#[test]
fn api_walker_sees_the_public_api() {
    let tensor = public_functions("tensor");
    let names: Vec<&str> = tensor.iter().map(|f| f.name.as_str()).collect();
    for known in ["Vector::unit", "Rotor::exp", "wrap_angle", "Scalar::re"] {
        assert!(names.contains(&known), "{known} missing from {names:?}");
    }
    let kin = public_functions("kinematics");
    // Re-exported through `pub use` (attitude/angle_vector.rs is a private module of the public
    // `attitude`): the bare name.
    assert!(kin.iter().any(|f| f.name == "jacobian_left"), "re-exported names");
    assert!(kin.iter().any(|f| f.name == "FrameMotion::compose"), "methods");
}
