//! vectrix-cli under hostile input (docs/robustness.md): hostile arguments (unknown flags,
//! missing files, unit systems, sweep values `nan`, `inf`, 1e308, empty lists, paths with
//! `..`) are refused with a message, or run and write finite output; the binary's exit
//! code is 0 only for success.

use std::process::Command;

use vectrix_cli::run_with_args;

fn cli(args: &[&str]) -> Result<String, String> {
    let mut out = Vec::new();
    let r = run_with_args(std::iter::once("vectrix").chain(args.iter().copied()), &mut out);
    r.map(|_| String::from_utf8_lossy(&out).to_string()).map_err(|e| e.to_string())
}

cases! {
    // The notebook view (issue 36): a folder without a view is an error naming view.html; a
    // view shows as a sandboxed iframe whose page is escaped inside `srcdoc` (no raw `"` or `<`
    // of the page can end the attribute), wrapped in evcxr's HTML markers.
    cli_notebook_view ["View::open", "View::iframe", "View::display_text", "View::evcxr_display"] {
        let dir = tempfile::tempdir().unwrap();
        let e = vectrix_cli::View::open(dir.path()).unwrap_err().to_string();
        assert!(e.contains("view.html"), "{e}");
        std::fs::write(dir.path().join("view.html"), "<p title=\"x\">a & b</p><script>alert(1)</script>").unwrap();
        let v = vectrix_cli::View::open(dir.path()).unwrap();
        let frame = v.iframe();
        let inner = frame.split("srcdoc=\"").nth(1).unwrap().rsplit_once("\"></iframe>").unwrap().0;
        assert!(!inner.contains('"') && !inner.contains('<'), "{inner}");
        assert!(frame.contains("sandbox=\"allow-scripts\""));
        let text = v.display_text();
        assert!(text.starts_with("EVCXR_BEGIN_CONTENT text/html") && text.trim_end().ends_with("EVCXR_END_CONTENT"));
        v.evcxr_display();
    }

    // The view page from a library call (issue 36, the Python display hook): a page wraps any
    // text and escapes it in its iframe; `scene_page` of a run stays within
    // `scene_page_bound`, and a cancelled second pass still gives a page that says so.
    cli_view_page ["View::from_page", "View::page", "scene_page", "scene_page_bound"] {
        let hostile = "</script><script>alert(1)</script>\"";
        let v = vectrix_cli::View::from_page(hostile.to_string());
        assert_eq!(v.page(), hostile);
        let inner = v.iframe();
        assert!(!inner.contains("<script>alert"), "{inner}");
        let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/scenes/simple_pendulum.toml")).unwrap();
        let scene = vectrix::scene::Scene::from_toml(&text, "p.toml").unwrap();
        let run = scene.run(&mut |_| {}).unwrap();
        let bound = vectrix_cli::scene_page_bound(&scene);
        let page = vectrix_cli::scene_page(&scene, (&text, "p.toml"), &run, vectrix::units::UnitSystem::Si, None);
        assert!(page.len() as u64 <= bound && page.contains("<html"), "{} > {bound}", page.len());
        let cancel = std::sync::atomic::AtomicBool::new(true);
        let stopped = vectrix_cli::scene_page(&scene, (&text, "p.toml"), &run, vectrix::units::UnitSystem::Si, Some(&cancel));
        assert!(stopped.len() as u64 <= bound && stopped.contains("<html"));
        // a name that could end a script or the title is escaped
        let evil = text.replacen("name = \"simple_pendulum\"", "name = \"x\"", 1);
        let s2 = vectrix::scene::Scene::from_toml(&evil, "p.toml").unwrap();
        let r2 = s2.run(&mut |_| {}).unwrap();
        assert!(!vectrix_cli::scene_page(&s2, (&evil, "p.toml"), &r2, vectrix::units::UnitSystem::Si, None).contains("<script>alert"));
    }

    // `check`, `run` and `sweep` with hostile arguments: an error with a message, or output
    // without NaN/∞ (a valid scene is checked; a sweep over non-finite values is refused per
    // value or as a whole). The binary (`main`) exits 0 for `--help`, nonzero for nonsense.
    cli_arguments ["run_with_args", "main"] {
        let dir = tempfile::tempdir().unwrap();
        let scene = dir.path().join("p.toml");
        let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/examples/scenes/simple_pendulum.toml")).unwrap();
        let short = text.lines().map(|l| if l.starts_with("duration") { "duration = 0.2" } else if l.starts_with("samples") { "samples = 5" } else { l }).collect::<Vec<_>>().join("\n");
        std::fs::write(&scene, &short).unwrap();
        let p = scene.to_str().unwrap();
        let out = dir.path().join("out");
        let o = out.to_str().unwrap();
        assert!(cli(&["check", p]).is_ok());
        for args in [
            vec!["--bogus"],
            vec!["check"],
            vec!["check", ""],
            vec!["check", "/nonexistent/scene.toml"],
            vec!["check", dir.path().to_str().unwrap()],
            vec!["run", p, "--units", "parsecs", "--out", o, "--quiet"],
            vec!["run", p, "--units", "", "--out", o, "--quiet"],
            vec!["sweep", p, "--param", "duration=nan,inf", "--out", o, "--quiet"],
            vec!["sweep", p, "--param", "duration=", "--out", o, "--quiet"],
            vec!["sweep", p, "--param", "=1", "--out", o, "--quiet"],
            vec!["sweep", p, "--param", "bodies[99].mass.mass=1", "--out", o, "--quiet"],
            vec!["sweep", p, "--param", "duration=1e308", "--out", o, "--quiet"],
            vec!["sweep", p, "--param", "duration=-1,0,5e-324", "--out", o, "--quiet"],
            vec!["linearize", "/nonexistent.toml", "--out", o],
        ] {
            match cli(&args) {
                Ok(text) => assert!(!text.contains("NaN") && !text.contains(" inf"), "{args:?}: {text}"),
                Err(e) => assert!(!e.is_empty(), "{args:?}: an empty message"),
            }
        }
        let ok = cli(&["run", p, "--out", o, "--quiet"]).unwrap();
        assert!(!ok.contains("NaN"));
        let csv = std::fs::read_dir(&out).unwrap().flatten().find_map(|d| std::fs::read_to_string(d.path().join("trajectory.csv")).ok());
        assert!(csv.is_some_and(|c| c.lines().count() == 7 && !c.contains("NaN") && !c.contains("inf")));
        // the binary itself: main's exit codes
        let bin = env!("CARGO_BIN_EXE_vectrix");
        let run = |args: &[&str]| Command::new(bin).current_dir(dir.path()).args(args).output().unwrap().status;
        assert!(run(&["--help"]).success());
        assert!(!run(&["--bogus"]).success());
        assert!(!run(&["check", "/nonexistent.toml"]).success());
        assert!(run(&["check", p]).success());
    }
}
