//! `cargo xtask bench [ARGS...]`: the criterion benchmarks of the reference
//! solutions against peer crates, `cargo bench -p course-bench ARGS...`.

use std::path::Path;

use anyhow::{Context, Result, ensure};

use crate::cargo::{self, cargo};

/// Runs the benchmarks, passing `args` through to `cargo bench`.
pub fn run(root: &Path, args: &[String]) -> Result<()> {
    let mut command = cargo();
    command
        .current_dir(root)
        .args(["bench", "--package", "course-bench"])
        .args(args);
    println!("$ {}", cargo::display(&command));
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
