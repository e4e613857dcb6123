//! Claiming a build folder for the stage or checkout it builds: the files
//! of one built after another are touched, so that cargo rebuilds them.

use std::fs::{self, File};
use std::path::Path;

use anyhow::{Context, Result};

use super::BUILT_FROM;
use crate::files::{files_under, write_file};
/// Makes the build folder `target_dir` build the stage at `stage_root`:
/// when another stage was built there last (cargo would take that stage's
/// artifacts for this one's, see the module's documentation), every file
/// of this stage is touched, so that cargo rebuilds whatever they make.
pub fn claim_build(stage_root: &Path, target_dir: &Path) -> Result<()> {
    claim_files(stage_root, &[], target_dir)
}

/// The folders of a checkout that the test executables are built from.
const TESTED_FOLDERS: [&str; 2] = ["crates", "exercises"];

/// [`claim_build`] for a checkout graded in place (`cargo xtask grade`),
/// whose build folder may have built another copy of the course last (a
/// `CARGO_TARGET_DIR` shared between checkouts): then cargo would run that
/// copy's tests. Only the files the tests are built from are touched
/// (`crates/` and `exercises/`), so the tooling is not rebuilt.
pub fn claim_checkout_build(root: &Path, target_dir: &Path) -> Result<()> {
    claim_files(root, &TESTED_FOLDERS, target_dir)
}

/// [`claim_build`] touching only the files under `folders` of
/// `stage_root` (all of them for none).
fn claim_files(stage_root: &Path, folders: &[&str], target_dir: &Path) -> Result<()> {
    let record = target_dir.join(BUILT_FROM);
    let ours = stage_root.to_string_lossy().into_owned();
    if fs::read_to_string(&record).is_ok_and(|last| last == ours) {
        return Ok(());
    }
    if record.exists() || target_dir.join("debug").exists() {
        let now = std::time::SystemTime::now();
        let touched = files_under(stage_root)?.into_iter().filter(|file| {
            folders.is_empty() || folders.iter().any(|folder| file.starts_with(folder))
        });
        for file in touched {
            let path = stage_root.join(file);
            File::options()
                .write(true)
                .open(&path)
                .and_then(|f| f.set_modified(now))
                .with_context(|| format!("cannot touch {}", path.display()))?;
        }
    }
    write_file(&record, ours)
}
