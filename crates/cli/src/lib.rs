//! # vectrix-cli: the `vectrix` command
//!
//! With no arguments it runs the main job. Subcommands are added as the layers land.
#![warn(missing_docs)]

use std::process::ExitCode;

use clap::{Parser, Subcommand};

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
}

/// Entry point of the binary: parses `std::env::args` and runs.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    let mut out = std::io::stdout().lock();
    let result = match cli.command {
        None | Some(Command::Tour) => tour::run(&mut out),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
