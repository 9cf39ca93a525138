//! `vectrix sweep … --shard K/N` and `vectrix sweep merge DIR…` (issue 37): the merged table of
//! the shards equals the unsharded sweep's table (every column but the wall time, which is
//! measured), and the merge refuses a missing shard, a shard given twice and another sweep.
//!
//! Book: — (parameter studies of the scenes of §7.11).

use std::path::Path;

use vectrix_cli::run_with_args;

const SCENE: &str = r#"
name = "osc"
duration = 0.5
samples = 10
outputs = ["coordinates:c"]

[[bodies]]
name = "c"
joint = { type = "sleeve", axis = [1.0, 0.0, 0.0] }
mass = { shape = "particle", mass = 2.0 }
q = [1.5]

[[effects]]
type = "spring"
a = { body = "ground" }
b = { body = "c" }
k = 50.0
length = 1.0
"#;

fn cli(args: &[&str]) -> Result<String, String> {
    let mut out = Vec::new();
    let r = run_with_args(std::iter::once("vectrix").chain(args.iter().copied()), &mut out);
    r.map(|_| String::from_utf8_lossy(&out).to_string()).map_err(|e| e.to_string())
}

/// The table without its `wall_seconds` column (the one measured value).
fn without_wall(csv: &str) -> Vec<Vec<String>> {
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let w = header.iter().position(|h| *h == "wall_seconds").expect("wall_seconds column");
    csv.lines()
        .map(|l| l.split(',').enumerate().filter(|(i, _)| *i != w).map(|(_, x)| x.to_string()).collect())
        .collect()
}

fn sweep(scene: &Path, out: &Path, shard: Option<&str>) {
    let mut args = vec![
        "sweep",
        scene.to_str().unwrap(),
        "--quiet",
        "--param",
        "effects.0.k=10,20,40,80",
        "--param",
        "duration=0.25,0.5",
        "--out",
        out.to_str().unwrap(),
    ];
    if let Some(s) = shard {
        args.extend(["--shard", s]);
    }
    cli(&args).unwrap();
}

#[test]
fn sharded_and_merged_sweep_equals_the_unsharded_one() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("osc.toml");
    std::fs::write(&scene, SCENE).unwrap();
    let whole = dir.path().join("whole");
    sweep(&scene, &whole, None);
    let want = std::fs::read_to_string(whole.join("osc-sweep/sweep.csv")).unwrap();
    assert_eq!(want.lines().count(), 9, "{want}");
    let shards = dir.path().join("shards");
    for k in 1..=3 {
        sweep(&scene, &shards, Some(&format!("{k}/3")));
    }
    let d = |k: usize| shards.join(format!("osc-sweep-shard-{k}-of-3"));
    // each shard keeps the global run numbers: shard 2 of 3 ran runs 1, 4, 7
    assert!(d(2).join("run-004/trajectory.csv").exists());
    assert!(!d(2).join("run-000").exists());
    let merged =
        cli(&["sweep", "merge", d(3).to_str().unwrap(), d(1).to_str().unwrap(), d(2).to_str().unwrap()])
            .unwrap();
    assert_eq!(without_wall(&merged), without_wall(&want), "merged:\n{merged}\nwhole:\n{want}");
    // the trajectories themselves are the same bits
    let a = std::fs::read(whole.join("osc-sweep/run-007/trajectory.csv")).unwrap();
    let b = std::fs::read(d(2).join("run-007/trajectory.csv")).unwrap();
    assert_eq!(a, b);

    let e = cli(&["sweep", "merge", d(1).to_str().unwrap(), d(2).to_str().unwrap()]).unwrap_err();
    assert!(e.contains("run 002 is in no shard"), "{e}");
    let e = cli(&["sweep", "merge", d(1).to_str().unwrap(), d(1).to_str().unwrap()]).unwrap_err();
    assert!(e.contains("run 000 is in"), "{e}");
    let e = cli(&["sweep", "merge", d(1).to_str().unwrap(), whole.join("osc-sweep").to_str().unwrap()])
        .unwrap_err();
    assert!(e.contains("run 000 is in"), "{e}");
    for bad in ["0/3", "4/3", "1/0", "x", "1/2/3"] {
        let e =
            cli(&["sweep", scene.to_str().unwrap(), "--param", "duration=1", "--shard", bad]).unwrap_err();
        assert!(e.contains("valid: K/N"), "{bad}: {e}");
    }
}
