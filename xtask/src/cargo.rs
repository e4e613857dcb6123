//! Finding the project and running cargo the way the user runs it.

use std::path::{Path, PathBuf};
use std::process::Command;

use serde::Deserialize;

/// `$CARGO` (set by cargo for `cargo xtask ...`, so the same toolchain is
/// used), falling back to `cargo` on the `PATH`.
#[must_use]
pub fn cargo() -> Command {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    Command::new(cargo)
}

/// The workspace root: the parent of the folder this crate lives in.
///
/// `cargo xtask` (`cargo run`) tells the running program where that folder
/// is in `CARGO_MANIFEST_DIR`; that is asked first, because one binary may
/// serve several checkouts (a shared `CARGO_TARGET_DIR` builds xtask once
/// for all of them) and must grade the checkout it was started in. The
/// folder it was compiled in is the fallback.
#[must_use]
pub fn project_root() -> PathBuf {
    let manifest_dir = std::env::var_os("CARGO_MANIFEST_DIR")
        .map_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")), PathBuf::from);
    manifest_dir
        .parent()
        .expect("xtask lives in a subfolder of the workspace")
        .to_path_buf()
}

/// Prints `command` (and the folder it runs in), runs it with its output
/// on the terminal, and fails unless it succeeds.
pub fn run_visibly(command: &mut Command) -> anyhow::Result<()> {
    use anyhow::Context as _;
    let folder = command
        .get_current_dir()
        .map(|dir| format!("   (in {})", dir.display()))
        .unwrap_or_default();
    println!("$ {}{folder}", display(command));
    let status = command
        .status()
        .with_context(|| format!("cannot run `{}`", display(command)))?;
    anyhow::ensure!(status.success(), "`{}` failed ({status})", display(command));
    Ok(())
}

/// A command line as the user would type it, for headings and errors.
#[must_use]
pub fn display(command: &Command) -> String {
    let mut line = Path::new(command.get_program())
        .file_name()
        .unwrap_or(command.get_program())
        .to_string_lossy()
        .into_owned();
    for arg in command.get_args() {
        line.push(' ');
        line.push_str(&arg.to_string_lossy());
    }
    line
}

/// One of cargo's JSON messages (`--message-format json`): the fields the
/// tools read, for every place that reads them.
#[derive(Deserialize)]
pub struct Message {
    /// `compiler-artifact`, `compiler-message`, `build-finished`, …
    pub reason: String,
    #[serde(default)]
    pub manifest_path: Option<PathBuf>,
    #[serde(default)]
    pub target: Option<Target>,
    #[serde(default)]
    pub profile: Option<Profile>,
    #[serde(default)]
    pub executable: Option<PathBuf>,
    #[serde(default)]
    pub filenames: Vec<PathBuf>,
}

#[derive(Deserialize)]
pub struct Target {
    pub name: String,
    pub kind: Vec<String>,
}

#[derive(Deserialize)]
pub struct Profile {
    pub test: bool,
}

impl Message {
    /// One line of cargo's standard output as a message; `None` for a line
    /// that is not one (a test's or a build script's own output).
    #[must_use]
    pub fn parse(line: &str) -> Option<Self> {
        serde_json::from_str(line).ok()
    }

    /// Whether this is the artifact of a built target.
    #[must_use]
    pub fn is_artifact(&self) -> bool {
        self.reason == "compiler-artifact"
    }
}
