//! A run's view in a notebook: [`View`] shows a run folder's `view.html` inline through
//! evcxr's HTML display (a type with an `evcxr_display` method), in a sandboxed iframe whose
//! `srcdoc` holds the whole page, HTML-escaped, so the page's scripts and styles stay apart from
//! the notebook's.
//!
//! ```no_run
//! // in an evcxr cell, after `vectrix run SCENE --out out`:
//! let view = vectrix_cli::View::open("out/four_bar").unwrap();
//! view.evcxr_display(); // in a cell, ending the cell with `view` shows it the same way
//! ```
//!
//! Book: — (reporting).

use std::path::Path;

use super::page::escape_html;

/// The 3-D view of one run, for a notebook cell.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct View {
    page: String,
}

impl View {
    /// The view of the run folder `folder` (written by `vectrix run`, holding `view.html`).
    ///
    /// # Errors
    /// The folder has no readable `view.html` (a run with `--no-view` or `view = false`).
    pub fn open(folder: impl AsRef<Path>) -> Result<View, Box<dyn std::error::Error + Send + Sync>> {
        let path = folder.as_ref().join("view.html");
        let page = std::fs::read_to_string(&path).map_err(|e| {
            format!("cannot read {}: {e}; valid: a run folder written with its view", path.display())
        })?;
        Ok(View { page })
    }

    /// The view of a page made by [`super::scene_page`] (a run from a library, such as the
    /// Python package's `RunResult.view()`).
    pub fn from_page(page: String) -> View {
        View { page }
    }

    /// The page itself (`view.html`).
    pub fn page(&self) -> &str {
        &self.page
    }

    /// The page in a sandboxed iframe (scripts allowed, nothing else), 100 % wide, 520 px high.
    pub fn iframe(&self) -> String {
        format!(
            "<iframe sandbox=\"allow-scripts\" style=\"width:100%;height:520px;border:1px solid #ccd\" \
             srcdoc=\"{}\"></iframe>",
            escape_html(&self.page)
        )
    }

    /// What evcxr reads from a cell's output to show HTML: the iframe between
    /// `EVCXR_BEGIN_CONTENT text/html` and `EVCXR_END_CONTENT`.
    pub fn display_text(&self) -> String {
        format!("EVCXR_BEGIN_CONTENT text/html\n{}\nEVCXR_END_CONTENT\n", self.iframe())
    }

    /// evcxr's display hook: prints [`View::display_text`].
    pub fn evcxr_display(&self) {
        print!("{}", self.display_text());
    }
}
