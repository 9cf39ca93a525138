//! # vectrix-cli: the `vectrix` command
//!
//! With no arguments it runs the main job. Subcommands are added as the layers land.
#![warn(missing_docs)]

use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod accuracy;
mod tour;

/// Command-line arguments.
#[derive(Debug, Parser)]
#[command(name = "vectrix", version, about = "Frame-free geometry, kinematics, statics and dynamics")]
pub struct Cli {
    /// What to run; the tour when omitted.
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// Subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// A short tour: frames, resolution, a rotor, a contraction.
    Tour,
    /// Work–precision harness of the integrators: writes docs/accuracy/*.svg and prints the
    /// tables of docs/accuracy.md (`cargo run --release -- accuracy`).
    Accuracy {
        /// Directory for the SVG diagrams.
        #[arg(long, default_value = "docs/accuracy")]
        out: std::path::PathBuf,
        /// A few points per line only (seconds instead of a minute).
        #[arg(long)]
        quick: bool,
        /// Also print every measured point.
        #[arg(long)]
        all: bool,
    },
}

/// Entry point of the binary: parses `std::env::args` and runs.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    let mut out = std::io::stdout().lock();
    let result = match cli.command {
        None | Some(Command::Tour) => tour::run(&mut out),
        Some(Command::Accuracy { out: dir, quick, all }) => accuracy::run(&mut out, &dir, quick, all),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
