//! # vectrix-cli: the `vectrix` command
//!
//! * `vectrix` (no arguments) and `vectrix run [SCENE]`: run a scene (the embedded default,
//!   the tennis-racket flip, when no file is given) and write `out/<scene>/` with
//!   `trajectory.csv`, `summary.json`, one SVG per requested output and `view.html` (the
//!   run's self-contained 3-D view; `--no-view` or `view = false` skips it).
//! * `vectrix check SCENE`: validate without running.
//! * `vectrix sweep SCENE --param PATH=v1,v2,…`: parameter sweeps in parallel (rayon).
//! * `vectrix tour`, `vectrix accuracy`: the kernel tour and the integrators' work–precision
//!   harness.
//!
//! Every command that writes follows one rule (the `output` module): it writes only inside
//! the folder named with `--out`, into folders it created and marked, never replaces a folder
//! holding a file it did not write (it names them and stops), never writes more than
//! `--max-output-bytes` (default [`DEFAULT_MAX_OUTPUT_BYTES`]), and stops writing at a whole
//! file on Ctrl-C or SIGTERM, marking the output incomplete.
//!
//! [`run_with_args`] is the library entry the binary and the tests call; [`View`] shows a run's
//! `view.html` inline in an evcxr notebook.
//!
//! Book: §7.11, ch. 6, §7.13 (what a scene simulates); §4.11 (integration).
#![warn(missing_docs)]

use std::ffi::OsString;
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use vectrix_units::UnitSystem;

mod accuracy;
mod budget;
mod check;
mod input;
mod interrupt;
mod linearize;
mod output;
mod report;
mod run;
mod sink;
mod sweep;
mod sweep_merge;
mod tour;
mod view;

pub use budget::scene_page_bound;
pub use run::Outcome;
pub use sink::DEFAULT_MAX_OUTPUT_BYTES;
pub use view::{View, scene_page};

/// Command-line arguments.
#[derive(Debug, Parser)]
#[command(name = "vectrix", version, about = "Frame-free geometry, kinematics, statics and dynamics")]
pub struct Cli {
    /// What to run; the default scene when omitted.
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// Subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Runs a scene file (the embedded tennis-racket scene when omitted) and writes
    /// out/<scene>/ with trajectory.csv, summary.json, SVG plots and view.html (a 3-D view
    /// that opens offline in a browser).
    Run {
        /// The scene file (TOML).
        scene: Option<PathBuf>,
        /// Parent directory of the output folder.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// No progress bar.
        #[arg(long)]
        quiet: bool,
        /// Unit system of trajectory.csv, the plots and summary.json: `si` or `imperial`.
        #[arg(long, default_value = "si")]
        units: String,
        /// Most bytes the command may write (`1073741824`, `500MB`, `2GiB`): a run whose
        /// output could exceed it is refused before it starts, and writing stops there.
        #[arg(long, default_value = "1GiB", value_parser = sink::parse_bytes)]
        max_output_bytes: u64,
        /// Refuse a URDF/MJCF model with any element or attribute that does not map
        /// (instead of warning about it).
        #[arg(long)]
        strict: bool,
        /// Do not write view.html, the run's self-contained 3-D view (also `view = false` in
        /// the scene file).
        #[arg(long)]
        no_view: bool,
    },
    /// Validates a scene file (or a URDF/MJCF model) without running it.
    Check {
        /// The scene file (TOML), or a model file (`.urdf`, MJCF `.xml`).
        scene: PathBuf,
        /// Refuse a URDF/MJCF model with any element or attribute that does not map.
        #[arg(long)]
        strict: bool,
    },
    /// Runs a scene for every value of one or more parameters, in parallel; `--shard K/N`
    /// runs one slice of them (a Slurm array task), `sweep merge DIR…` joins the slices.
    #[command(args_conflicts_with_subcommands = true)]
    Sweep {
        /// `merge DIR…`: one table from the sweep.csv of sharded sweeps.
        #[command(subcommand)]
        merge: Option<SweepCommand>,
        /// The scene file (TOML).
        #[arg(required = true)]
        scene: Option<PathBuf>,
        /// `PATH=v1,v2,…` with PATH an item path into the file, as errors name items
        /// (`effects[0].k`, `bodies[1].mass.mass`, `duration`; `effects.0.k` too); several give
        /// the Cartesian product.
        #[arg(long, required = true)]
        param: Vec<String>,
        /// `K/N`: run only the K-th of N slices (runs i with i mod N = K − 1, numbered as in
        /// the whole sweep), into `<out>/<name>-sweep-shard-K-of-N/`.
        #[arg(long, value_parser = sweep::parse_shard)]
        shard: Option<(usize, usize)>,
        /// Parent directory of the output folder.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// No progress bar.
        #[arg(long)]
        quiet: bool,
        /// Unit system of the outputs: `si` or `imperial`.
        #[arg(long, default_value = "si")]
        units: String,
        /// Most bytes the command may write (`1073741824`, `500MB`, `2GiB`): a run whose
        /// output could exceed it is refused before it starts, and writing stops there.
        #[arg(long, default_value = "1GiB", value_parser = sink::parse_bytes)]
        max_output_bytes: u64,
    },
    /// Linearizes a scene about its initial state (an equilibrium, or a steady motion when the
    /// scene says `linearize = { steady = true }`; after `[trim]`, about the trimmed state) and writes
    /// out/<scene>/linearization.json (state, A, B, C, D, eigenvalues, modes), poles.svg and,
    /// with inputs and outputs, bode.svg.
    Linearize {
        /// The scene file (TOML).
        scene: PathBuf,
        /// Parent directory of the output folder.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Most bytes the command may write (`1073741824`, `500MB`, `2GiB`): a run whose
        /// output could exceed it is refused before it starts, and writing stops there.
        #[arg(long, default_value = "1GiB", value_parser = sink::parse_bytes)]
        max_output_bytes: u64,
    },
    /// A short tour: frames, resolution, a rotor, a contraction.
    Tour,
    /// Work–precision harness of the integrators: writes the SVG diagrams into out/accuracy/
    /// and prints the tables of docs/accuracy.md (regenerate the docs' figures with
    /// `cargo run --release -- accuracy --out docs/accuracy/integrators`).
    Accuracy {
        /// The folder of the SVG diagrams, written like a scene's output folder: created, or
        /// replaced when vectrix wrote it and it holds nothing else.
        #[arg(long, default_value = "out/accuracy")]
        out: PathBuf,
        /// A few points per line only (seconds instead of a minute).
        #[arg(long)]
        quick: bool,
        /// Also print every measured point.
        #[arg(long)]
        all: bool,
        /// Most bytes the command may write (`1073741824`, `500MB`, `2GiB`): a run whose
        /// output could exceed it is refused before it starts, and writing stops there.
        #[arg(long, default_value = "1GiB", value_parser = sink::parse_bytes)]
        max_output_bytes: u64,
    },
}

/// Subcommands of `vectrix sweep`.
#[derive(Debug, Subcommand)]
pub enum SweepCommand {
    /// Prints one sweep.csv (rows in run order) from the output folders of the shards of one
    /// sweep; refuses folders of different sweeps, a run given twice, or a missing run.
    Merge {
        /// The shards' output folders (`<name>-sweep-shard-K-of-N`).
        #[arg(required = true)]
        dirs: Vec<PathBuf>,
    },
}

/// Parses `args` (the first is the program name) and runs, printing to `out`. A run that a
/// budget or Ctrl-C stopped early still writes its output and returns its [`Outcome`].
///
/// # Errors
/// Argument errors (clap's message), scene errors with line and column, I/O errors, a refused
/// output folder.
pub fn run_with_args<I, T>(
    args: I,
    out: &mut impl Write,
) -> Result<Outcome, Box<dyn std::error::Error + Send + Sync>>
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let cli = Cli::try_parse_from(args)?;
    input::set_strict(false);
    let done = |r: Result<(), Box<dyn std::error::Error + Send + Sync>>| r.map(|()| Outcome::Complete);
    match cli.command {
        None => {
            let opts = run::Options {
                dir: &PathBuf::from("out"),
                quiet: false,
                units: UnitSystem::Si,
                max_bytes: DEFAULT_MAX_OUTPUT_BYTES,
                view: true,
            };
            run::run(out, None, &opts)
        }
        Some(Command::Run { scene, out: dir, quiet, units, max_output_bytes, strict, no_view }) => {
            input::set_strict(strict);
            let opts = run::Options {
                dir: &dir,
                quiet,
                units: units.parse::<UnitSystem>()?,
                max_bytes: max_output_bytes,
                view: !no_view,
            };
            run::run(out, scene.as_deref(), &opts)
        }
        Some(Command::Check { scene, strict }) => {
            input::set_strict(strict);
            done(check::check(out, &scene))
        }
        Some(Command::Sweep { merge: Some(SweepCommand::Merge { dirs }), .. }) => {
            done(sweep_merge::merge(out, &dirs))
        }
        Some(Command::Sweep { scene, param, shard, out: dir, quiet, units, max_output_bytes, .. }) => {
            let scene = scene.ok_or("sweep: the scene file is missing")?;
            let opts = sweep::Options {
                dir: &dir,
                quiet,
                units: units.parse::<UnitSystem>()?,
                max_output_bytes,
                shard,
            };
            sweep::sweep(out, &scene, &param, &opts)
        }
        Some(Command::Linearize { scene, out: dir, max_output_bytes }) => {
            done(linearize::linearize(out, &scene, &dir, max_output_bytes))
        }
        Some(Command::Tour) => done(tour::run(out).map_err(|e| e.to_string().into())),
        Some(Command::Accuracy { out: dir, quick, all, max_output_bytes }) => {
            accuracy::run(out, &dir, quick, all, max_output_bytes)
        }
    }
}

/// Entry point of the binary: parses `std::env::args` and runs. Exit codes: 0 done, 1 error,
/// a run stopped by its budget or with untrustworthy numbers (output written, marked
/// incomplete), 130 interrupted (Ctrl-C, SIGTERM, SIGHUP).
pub fn main() -> ExitCode {
    // Ctrl-C and SIGTERM stop a run cleanly from the first instant on (the handler sets a flag)
    interrupt::interrupted();
    let mut out = std::io::stdout().lock();
    match run_with_args(std::env::args_os(), &mut out) {
        Ok(Outcome::Complete) => ExitCode::SUCCESS,
        Ok(Outcome::Budget | Outcome::Unreliable) => ExitCode::FAILURE,
        Ok(Outcome::Interrupted) => ExitCode::from(130),
        Err(e) => {
            if let Some(c) = e.downcast_ref::<clap::Error>() {
                let _ = c.print();
                return if c.use_stderr() { ExitCode::FAILURE } else { ExitCode::SUCCESS };
            }
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
