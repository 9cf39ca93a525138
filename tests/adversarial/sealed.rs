//! The sealed kernel (issue 38, item 5; DESIGN §1.1, §1.5): only `vectrix-frames` reaches the
//! kernel's hidden components.
//!
//! The accessors live in `vectrix_tensor::frames_access`, a module that exists only with the
//! non-default feature `frames-access` (vectrix-tensor's crate docs, "Sealed components"). Rust
//! has no friend crates and cargo unifies features across a build, so once `vectrix-frames` is
//! in the build the module is compiled for every crate; this source scan is what keeps the
//! other crates, the tests, benches, examples, notebooks and the Python binding from naming
//! it. Everyone else resolves in a frame (`x.resolve(&a)`) and builds through one
//! (`a.vector([..])`, `a.tensor(p, q, ..)`).

use std::fs;
use std::path::{Path, PathBuf};

/// The names that open the sealed module: its path and its cargo feature.
const SEALED: [&str; 2] = ["frames_access", "frames-access"];

/// Files that may name them: the kernel that defines the module and the one crate that uses it.
const ALLOWED_DIRS: [&str; 2] = ["crates/tensor/", "crates/frames/"];

/// Source kinds scanned: Rust, Python (the binding's tests and stubs), notebooks, manifests.
const SCANNED: [&str; 5] = ["rs", "py", "pyi", "ipynb", "toml"];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Every scanned file under `dir`, skipping build output, VCS data and virtual environments.
fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = fs::read_dir(dir) else { return };
    for e in entries.filter_map(Result::ok) {
        let p = e.path();
        let name = e.file_name().to_string_lossy().into_owned();
        if p.is_dir() {
            if !(name.starts_with("target") || name.starts_with('.') || name == "node_modules") {
                sources(&p, out);
            }
        } else if p.extension().and_then(|x| x.to_str()).is_some_and(|x| SCANNED.contains(&x)) {
            out.push(p);
        }
    }
}

/// The (1-based line, name) of every sealed name in `src`.
fn sealed_names(src: &str) -> Vec<(usize, &'static str)> {
    let mut found = Vec::new();
    for (i, line) in src.lines().enumerate() {
        found.extend(SEALED.iter().filter(|n| line.contains(*n)).map(|n| (i + 1, *n)));
    }
    found
}

/// No file outside `crates/tensor` and `crates/frames` names the sealed module or its feature
/// (this file aside, which must name them to look for them).
#[test]
fn only_the_frames_crate_names_the_sealed_accessors() {
    // the matcher itself
    let sample = "use vectrix::tensor::frames_access::Hidden;\nlet x = v.resolve(&a);\n\
                  vectrix-tensor = { path = \"..\", features = [\"frames-access\"] }";
    assert_eq!(sealed_names(sample), [(1, "frames_access"), (3, "frames-access")]);
    let mut files = Vec::new();
    sources(&root(), &mut files);
    files.sort();
    assert!(files.len() > 100, "the scan found only {} files: is the root right?", files.len());
    let mut found = Vec::new();
    for f in &files {
        let rel = f.strip_prefix(root()).unwrap_or(f).to_string_lossy().replace('\\', "/");
        if ALLOWED_DIRS.iter().any(|d| rel.starts_with(d)) || rel == "tests/adversarial/sealed.rs" {
            continue;
        }
        let src = fs::read_to_string(f).unwrap_or_default();
        found.extend(sealed_names(&src).into_iter().map(|(line, name)| format!("{rel}:{line}: {name}")));
    }
    assert!(
        found.is_empty(),
        "the kernel's hidden components are sealed to vectrix-frames; resolve in a frame instead:\n{}",
        found.join("\n")
    );
}

/// Inside the two crates the seal holds too: the feature is off by default and enabled only by
/// the frames crate's dependency line; the kernel defines component accessors only in the
/// sealed module, and the frames crate re-exports nothing from it.
#[test]
fn the_seal_holds_inside_tensor_and_frames() {
    let read = |rel: &str| fs::read_to_string(root().join(rel)).unwrap_or_else(|e| panic!("{rel}: {e}"));
    let tensor_toml = read("crates/tensor/Cargo.toml");
    let default = tensor_toml.lines().find(|l| l.trim_start().starts_with("default")).unwrap_or("");
    assert!(!default.contains("frames-access"), "frames-access must not be a default feature: {default}");
    assert!(read("crates/frames/Cargo.toml").contains("features = [\"frames-access\"]"));
    let mut kernel = Vec::new();
    sources(&root().join("crates/tensor/src"), &mut kernel);
    for f in kernel.iter().filter(|f| !f.ends_with("frames_access.rs")) {
        let src = fs::read_to_string(f).unwrap_or_default();
        for bad in ["fn hidden", "fn from_hidden", "fn hidden_at", "fn map_hidden"] {
            assert!(!src.contains(bad), "{}: `{bad}` outside the sealed module", f.display());
        }
    }
    let mut frames = Vec::new();
    sources(&root().join("crates/frames/src"), &mut frames);
    for f in &frames {
        let src = fs::read_to_string(f).unwrap_or_default();
        assert!(
            !src.contains("pub use vectrix_tensor::frames_access"),
            "{}: re-exports the seal",
            f.display()
        );
        assert!(!src.contains("fn hidden_axes"), "{}: hands out the hidden axes", f.display());
    }
}
