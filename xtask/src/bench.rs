//! `cargo xtask bench [ARGS...]`: the criterion benchmarks of the reference
//! solutions against peer crates, `cargo bench -p course-bench ARGS...` in
//! the reference stage (see `stage`), whose build cache they share.

use std::path::Path;

use anyhow::{Context, Result, ensure};

use crate::cargo::{self, cargo};
use crate::stage::{self, Overlay};

/// Runs the benchmarks, passing `args` through to `cargo bench`.
pub fn run(root: &Path, args: &[String]) -> Result<()> {
    let staged = stage::stage(root, Overlay::Reference, None)?;
    let mut command = cargo();
    command
        .current_dir(&staged.root)
        .env("CARGO_TARGET_DIR", &staged.target_dir)
        .args(["bench", "--package", "course-bench"])
        .args(args);
    println!(
        "$ {}   (in {}; reports in {})",
        cargo::display(&command),
        staged.root.display(),
        staged.target_dir.join("criterion").display()
    );
    let status = command
        .status()
        .with_context(|| format!("cannot run `{}`", cargo::display(&command)))?;
    ensure!(
        status.success(),
        "`{}` failed ({status})",
        cargo::display(&command)
    );
    Ok(())
}
