//! `vectrix sweep merge DIR…`: one sweep table from the `sweep.csv` of the shards of a sweep
//! (`vectrix sweep … --shard K/N`), printed in run order. The result equals the table of the
//! unsharded sweep (apart from each run's wall time); folders of different sweeps (other
//! columns), a run present twice, or a missing run are refused with the folder named.
//!
//! Book: — (parameter studies of the scenes of §7.11, ch. 6).

use std::io::Write;
use std::path::PathBuf;

use crate::output::BoxError;

/// Largest sweep.csv read from one shard (10 000 runs of a few hundred bytes each, with room).
const MAX_TABLE_BYTES: u64 = 64 << 20;

/// Reads the shards' tables, checks them, prints the merged table.
pub(crate) fn merge(out: &mut impl Write, dirs: &[PathBuf]) -> Result<(), BoxError> {
    let mut header: Option<(String, PathBuf)> = None;
    let mut rows: Vec<(usize, String, PathBuf)> = Vec::new();
    for d in dirs {
        let p = d.join("sweep.csv");
        let meta = std::fs::metadata(&p)
            .map_err(|e| format!("{}: {e} (valid: the output folder of a sweep shard)", p.display()))?;
        if !meta.is_file() || meta.len() > MAX_TABLE_BYTES {
            return Err(
                format!("{}: not a regular file of at most {MAX_TABLE_BYTES} bytes", p.display()).into()
            );
        }
        let text = std::fs::read_to_string(&p).map_err(|e| format!("{}: {e}", p.display()))?;
        let mut lines = text.lines();
        let h = lines.next().unwrap_or_default().to_string();
        if !h.starts_with("run,") {
            return Err(format!("{}: no sweep table header (run,…)", p.display()).into());
        }
        match &header {
            Some((h0, d0)) if *h0 != h => {
                return Err(format!(
                    "{} and {} hold different sweeps (columns `{h}` vs `{h0}`); valid: shards of one sweep",
                    p.display(),
                    d0.display()
                )
                .into());
            }
            Some(_) => {}
            None => header = Some((h, d.clone())),
        }
        for l in lines.filter(|l| !l.is_empty()) {
            let run: usize = l
                .split(',')
                .next()
                .and_then(|r| r.parse().ok())
                .ok_or_else(|| format!("{}: row `{l}` has no run number", p.display()))?;
            rows.push((run, l.to_string(), d.clone()));
        }
    }
    rows.sort_by_key(|r| r.0);
    for w in rows.windows(2) {
        if w[0].0 == w[1].0 {
            return Err(format!(
                "run {:03} is in {} and in {}; valid: each shard once",
                w[0].0,
                w[0].2.display(),
                w[1].2.display()
            )
            .into());
        }
    }
    if let Some(k) = rows.iter().enumerate().find(|(i, r)| r.0 != *i).map(|(i, _)| i) {
        return Err(
            format!("run {k:03} is in no shard given; valid: every shard of the sweep (K = 1 … N)").into()
        );
    }
    if let Some((h, _)) = header {
        writeln!(out, "{h}")?;
    }
    for (_, l, _) in rows {
        writeln!(out, "{l}")?;
    }
    Ok(())
}
