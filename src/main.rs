//! The `vectrix` command: `cargo run --release` runs the main job.

fn main() -> std::process::ExitCode {
    vectrix_cli::main()
}
