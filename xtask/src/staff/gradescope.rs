//! `cargo xtask gradescope DIR [--topics ...]`: the autograder bundle
//! Gradescope's documented layout expects.
//!
//! Gradescope unpacks the uploaded zip into `/autograder/source`, runs its
//! `setup.sh` once (as root) when it builds the autograder's image, and
//! then runs `run_autograder` for every submission, whose files it puts
//! in `/autograder/submission`; the result is read from
//! `/autograder/results/results.json`. The bundle is:
//!
//! - `course/`: the student edition of the course (see [`crate::staff::release`]):
//!   its tests are the official ones, and it holds no solutions;
//! - `setup.sh`: installs Rust — the release of the toolchain that wrote
//!   the bundle, which the course is built and tested with, pinned by its
//!   version — bubblewrap and the software Vulkan driver, builds the
//!   grader, and grades the untouched edition once as a
//!   submission so that every dependency is compiled into the image;
//! - `run_autograder`: grades `/autograder/submission` with
//!   `cargo xtask grade --submission` and copies its `results.json`
//!   (Gradescope's format: a test per task, the flag of a submission that
//!   changed grading files), or writes one that says why nothing was graded;
//! - `autograder.zip`: the three, ready to upload.
//!
//! **Containment: Gradescope's container is the stated exception.** A
//! grade of record fails closed where bubblewrap, its seccomp filter or
//! the cgroups cannot be had (see `crate::sandbox::Policy`), and in
//! Gradescope's container they usually cannot: it is a Docker container
//! run as root, whose seccomp profile forbids the namespaces bubblewrap
//! makes and whose `/sys/fs/cgroup` is read-only. The container itself is
//! the sandbox there: each submission is graded in a fresh one that holds
//! the student edition alone (no solutions, no other student's work, no
//! token of the course's), with Gradescope's own limits. So both scripts
//! grade with `--unsandboxed-on-purpose`: what the container allows is
//! still used (bubblewrap where it runs), student code runs as `nobody`
//! either way, and every report says what did not hold.
//!
//! `run_autograder` takes `AUTOGRADER_ROOT` (default `/autograder`) and
//! `XTASK` (default: the grader `setup.sh` built), so that a test can run
//! it on a simulated tree.

use std::fs;
use std::path::Path;
use std::process::Command;

use anyhow::{Context, Result, ensure};

use crate::staff::release;
use crate::stage;

/// `setup.sh`: run once by Gradescope, as root, in `/autograder/source`.
const SETUP: &str = r#"#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image
# (written by `cargo xtask gradescope`).
set -euo pipefail
SOURCE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends \
    ca-certificates curl build-essential pkg-config \
    bubblewrap libvulkan1 mesa-vulkan-drivers
# The Rust the course was tested with when this bundle was written.
TOOLCHAIN="@TOOLCHAIN@"
if ! command -v rustup > /dev/null && [ ! -x "$HOME/.cargo/bin/rustup" ]; then
    curl --proto '=https' --tlsv1.2 -sSf https://sh.rustup.rs \
        | sh -s -- -y --profile minimal --default-toolchain "$TOOLCHAIN"
fi
. "$HOME/.cargo/env"
rustup toolchain install "$TOOLCHAIN" --profile minimal
rustup default "$TOOLCHAIN"
cd "$SOURCE/course"
rustc --version
cargo build --release --package xtask
# Grade the untouched edition once, as a submission: every dependency is
# then compiled into the image, and a student's submission compiles only
# its own code. On purpose without the whole sandbox where the container
# forbids it (see run_autograder).
rm -rf /tmp/warm-up && cp -r "$SOURCE/course" /tmp/warm-up && rm -rf /tmp/warm-up/target
target/release/xtask --root "$SOURCE/course" grade --submission /tmp/warm-up --out /tmp/warm-up-grade \
    --unsandboxed-on-purpose > /dev/null
rm -rf /tmp/warm-up /tmp/warm-up-grade
"#;

/// `run_autograder`: run by Gradescope for every submission.
const RUN: &str = r#"#!/usr/bin/env bash
# Gradescope runs this for every submission (written by `cargo xtask
# gradescope`): grades /autograder/submission with the course's official
# tests and leaves results.json where Gradescope reads it.
set -uo pipefail
ROOT="${AUTOGRADER_ROOT:-/autograder}"
COURSE="$ROOT/source/course"
XTASK="${XTASK:-$COURSE/target/release/xtask}"
if [ -f "$HOME/.cargo/env" ]; then . "$HOME/.cargo/env"; fi
RESULTS="$ROOT/results/results.json"
WORK="$ROOT/grading"
mkdir -p "$ROOT/results"
rm -rf "$WORK" && mkdir -p "$WORK"

# An uploaded zip of a repository often unpacks into one folder of its own.
SUBMISSION="$ROOT/submission"
ENTRIES=("$SUBMISSION"/*)
if [ ! -f "$SUBMISSION/Cargo.toml" ] && [ "${#ENTRIES[@]}" -eq 1 ] && [ -d "${ENTRIES[0]}" ]; then
    SUBMISSION="${ENTRIES[0]}"
fi
cp -r "$SUBMISSION" "$WORK/submission"

# Gradescope's container is the stated exception to a grade of record's
# failing closed: a Docker container, run as root, usually forbids the
# namespaces bubblewrap makes and the cgroups that limit a test's processes
# together. The container is the sandbox here (a fresh one per submission,
# holding the student edition alone); what it allows is still used, student
# code runs as nobody, and results.json says what did not hold.
"$XTASK" --root "$COURSE" grade --submission "$WORK/submission" --out "$WORK/grade" \
    --unsandboxed-on-purpose 2>&1 | tee "$WORK/grade.log"
STATUS=${PIPESTATUS[0]}
if [ "$STATUS" -eq 0 ] && [ -f "$WORK/grade/submission/results.json" ]; then
    cp "$WORK/grade/submission/results.json" "$RESULTS"
else
    # Nothing graded: say why, in Gradescope's format.
    python3 - "$WORK/grade.log" "$RESULTS" "$STATUS" <<'PYTHON' || printf '{"score": 0, "output": "The grader failed (exit status %s); see the autograder output."}\n' "$STATUS" > "$RESULTS"
import json, sys
log = open(sys.argv[1], encoding="utf-8", errors="replace").read()
json.dump({
    "score": 0,
    "output": "Not graded: the grader stopped with exit status " + sys.argv[3]
    + ". Is this a checkout of the course (a Cargo.toml and exercises/ at its top)?\n\n"
    + log[-4000:],
}, open(sys.argv[2], "w"))
PYTHON
fi
"#;

/// The files of the bundle beside `course/`, with their modes.
const SCRIPTS: [(&str, &str); 2] = [("setup.sh", SETUP), ("run_autograder", RUN)];

/// The zip Gradescope takes.
pub const ZIP: &str = "autograder.zip";

/// `cargo xtask gradescope DIR [--topics ...]`.
pub fn run(root: &Path, dir: &Path, topics: &[String]) -> Result<()> {
    let dir = stage::outside_course(root, dir)?;
    let release = write(root, &dir, topics)?;
    println!(
        "wrote the Gradescope autograder to {}\n  topics: {}\n  upload {} as the assignment's autograder (Ubuntu base image; allow it 30 minutes or more: a submission compiles its topics)",
        dir.display(),
        release.topics.join(", "),
        dir.join(ZIP).display()
    );
    Ok(())
}

/// Writes the bundle of `topics` (empty: all) into `dir`.
pub fn write(root: &Path, dir: &Path, topics: &[String]) -> Result<release::Release> {
    stage::claim(dir)?;
    let release = release::write(root, &dir.join("course"), topics, None)?;
    let toolchain = toolchain()?;
    for (name, text) in SCRIPTS {
        let path = dir.join(name);
        let text = text.replace("@TOOLCHAIN@", &toolchain);
        fs::write(&path, text).with_context(|| format!("cannot write {}", path.display()))?;
        make_executable(&path)?;
    }
    zip(dir)?;
    Ok(release)
}

/// The version of the Rust toolchain that runs `cargo` here (`1.95.0` of
/// `rustc 1.95.0 (59807616e 2026-04-14)`): the one the course is built and
/// tested with on this machine, which the autograder pins.
fn toolchain() -> Result<String> {
    let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
    let output = Command::new(&rustc)
        .arg("--version")
        .output()
        .context("cannot run `rustc --version`")?;
    ensure!(output.status.success(), "`rustc --version` failed");
    let text = String::from_utf8_lossy(&output.stdout);
    version_of(&text).with_context(|| format!("cannot read a version in `{}`", text.trim()))
}

/// The version in `rustc --version`'s answer.
fn version_of(answer: &str) -> Option<String> {
    let version = answer.split_whitespace().nth(1)?;
    let plain = version
        .split('.')
        .all(|part| !part.is_empty() && part.bytes().all(|b| b.is_ascii_digit()));
    // A nightly or beta (`1.96.0-nightly`) cannot be installed by that
    // name: the autograder then takes the stable release.
    Some(if plain {
        version.to_owned()
    } else {
        "stable".to_owned()
    })
}

#[cfg(unix)]
fn make_executable(path: &Path) -> Result<()> {
    use std::os::unix::fs::PermissionsExt as _;
    fs::set_permissions(path, fs::Permissions::from_mode(0o755))
        .with_context(|| format!("cannot make {} executable", path.display()))
}

#[cfg(not(unix))]
fn make_executable(_: &Path) -> Result<()> {
    Ok(())
}

/// `dir/autograder.zip` of the scripts and the course (without a build),
/// by Info-ZIP's `zip`, installed with `apt-get` when missing.
fn zip(dir: &Path) -> Result<()> {
    let found = || {
        Command::new("zip")
            .arg("-v")
            .stdout(std::process::Stdio::null())
            .status()
            .is_ok_and(|s| s.success())
    };
    if !found() {
        crate::setup::apt_install(
            &["zip"],
            "Info-ZIP's zip, which packs the autograder",
            "the autograder is packed with `zip`, and this machine has none",
        );
    }
    let archive = dir.join(ZIP);
    if archive.exists() {
        fs::remove_file(&archive)
            .with_context(|| format!("cannot replace {}", archive.display()))?;
    }
    let status = Command::new("zip")
        .current_dir(dir)
        .args([
            "-q",
            "-r",
            "-X",
            ZIP,
            "setup.sh",
            "run_autograder",
            "course",
        ])
        .args(["-x", "course/target/*", "course/.git/*"])
        .status()
        .context("cannot run `zip` (install Info-ZIP's zip)")?;
    ensure!(
        status.success(),
        "`zip` failed to pack {}",
        archive.display()
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_toolchain_is_pinned_by_its_release_version() {
        assert_eq!(
            version_of("rustc 1.95.0 (59807616e 2026-04-14)").as_deref(),
            Some("1.95.0")
        );
        assert_eq!(
            version_of("rustc 1.96.0-nightly (abc 2026-05-01)").as_deref(),
            Some("stable")
        );
        assert_eq!(version_of("nonsense"), None);
        let setup = SETUP.replace("@TOOLCHAIN@", "1.95.0");
        assert!(setup.contains("TOOLCHAIN=\"1.95.0\""), "{setup}");
        assert!(setup.contains("rustup default \"$TOOLCHAIN\""), "{setup}");
    }
}
