//! `vectrix check` on the model gallery (issue 35): every scene of examples/models/ and every
//! model file alone (`vectrix check arm7.urdf`) loads and validates; `--strict` refuses a
//! model with content that does not map, naming file and line.
//!
//! Book: §7.11.

use std::path::PathBuf;

fn gallery() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/models")
}

fn check(args: &[&str]) -> Result<String, String> {
    let mut out = Vec::new();
    let mut all = vec!["vectrix", "check"];
    all.extend_from_slice(args);
    vectrix_cli::run_with_args(all, &mut out).map_err(|e| e.to_string())?;
    Ok(String::from_utf8(out).unwrap())
}

#[test]
fn every_gallery_scene_and_model_checks() {
    let mut seen = 0;
    for entry in std::fs::read_dir(gallery()).unwrap() {
        let p = entry.unwrap().path();
        let ext = p.extension().and_then(|e| e.to_str()).unwrap_or("");
        if !["toml", "urdf", "xml"].contains(&ext) {
            continue;
        }
        let out = check(&[p.to_str().unwrap()]).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
        assert!(out.contains(": ok — scene"), "{}: {out}", p.display());
        seen += 1;
    }
    // 11 model files and 11 scenes (the geared, welded and stop pendulums of issue 35 included)
    assert_eq!(seen, 22);
}

#[test]
fn the_quadruped_alone_has_its_19_coordinates() {
    let p = gallery().join("quadruped.urdf");
    let out = check(&[p.to_str().unwrap()]).unwrap();
    assert!(out.contains("13 bodies") && out.contains("19 coordinates"), "{out}");
}

#[test]
fn strict_refuses_the_arm_with_its_visual_mesh_at_its_line() {
    let p = gallery().join("arm7.urdf");
    let e = check(&["--strict", p.to_str().unwrap()]).unwrap_err();
    // the base's <visual> (a package:// mesh, never opened) is on line 9
    assert!(e.contains("arm7.urdf:9:") && e.contains("<visual> not used"), "{e}");
    assert!(e.contains("--strict"), "{e}");
    // the double pendulum maps completely: strict accepts it
    let p = gallery().join("double_pendulum.urdf");
    assert!(check(&["--strict", p.to_str().unwrap()]).is_ok());
}
