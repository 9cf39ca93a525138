//! Ctrl-C, SIGTERM and SIGHUP: one process-wide flag that a run and the file writers poll.
//!
//! Book: — (command line).

use std::sync::OnceLock;
use std::sync::atomic::{AtomicBool, Ordering};

/// Set by Ctrl-C, SIGTERM or SIGHUP: the run in progress stops after its current step, and
/// writing that began before stops after the current file (see [`crate::sink`]).
pub(crate) fn interrupted() -> &'static AtomicBool {
    static FLAG: AtomicBool = AtomicBool::new(false);
    static HANDLER: OnceLock<()> = OnceLock::new();
    HANDLER.get_or_init(|| {
        // a second signal ends the process at once (its temporary folder, marked with this
        // process, is removed by the next run into the same folder)
        let _ = ctrlc::set_handler(|| {
            if FLAG.swap(true, Ordering::SeqCst) {
                std::process::exit(130);
            }
        });
    });
    &FLAG
}
