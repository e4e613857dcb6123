//! `cargo xtask bench [ARGS...]`: the criterion benchmarks of the reference
//! solutions against peer crates, `cargo bench -p course-bench ARGS...` in
//! the reference stage (see `stage`), whose build cache they share.

use std::path::Path;

use anyhow::Result;

use crate::cargo;
use crate::stage::{self, Overlay};

/// Runs the benchmarks, passing `args` through to `cargo bench`.
pub fn run(root: &Path, args: &[String]) -> Result<()> {
    let staged = stage::stage(root, Overlay::Reference, None)?;
    println!(
        "reports in {}",
        staged.target_dir.join("criterion").display()
    );
    cargo::run_visibly(
        staged
            .cargo()
            .args(["bench", "--package", "course-bench"])
            .args(args),
    )
}
