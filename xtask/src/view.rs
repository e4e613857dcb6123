//! `cargo xtask view [--reference] [ARGS...]`: the course viewer
//! (`xtask/viewer`), built with your own stages in it.
//!
//! The viewer draws with the code of seven topics (lines, circles, fill,
//! clipping, depth test, Bézier curves and surfaces, tessellation). Each is checked first: a topic that does not compile is
//! left out of the build and named in the window, and the others still
//! show. `--reference` stages the solutions instead (for tutors). `ARGS`
//! go to the viewer (`--screenshot FILE`, `--mesh`, `--mode`, ...; see
//! `cargo xtask view -- --help`).

use std::path::Path;

use anyhow::{Context, Result, bail};

use crate::cargo;
use crate::grade::pipeline::{VIEWER, viewer_topics};
use crate::stage::{self, Overlay};
use crate::topics;

/// Builds the viewer with every topic that compiles and runs it with `args`.
pub fn run(root: &Path, reference: bool, args: &[String]) -> Result<()> {
    if !root
        .join("xtask")
        .join("viewer")
        .join("Cargo.toml")
        .is_file()
    {
        bail!("this course has no viewer (xtask/viewer)");
    }
    if reference && !root.join("reference").is_dir() {
        bail!("--reference needs the solutions, and this edition has none (no reference/)");
    }
    let overlay = if reference {
        Overlay::Reference
    } else {
        Overlay::Own
    };
    let course = topics::discover(root)?;
    let staged = stage::stage(root, overlay, None)?;
    let mut features = Vec::new();
    let mut not_compiling = Vec::new();
    let pairs = viewer_topics(root);
    for (feature, topic) in &pairs {
        let Some(found) = course.iter().find(|t| t.name == *topic) else {
            continue; // not in this edition
        };
        eprint!("checking {topic} … ");
        let output = staged
            .cargo()
            .args(["check", "--quiet", "--lib", "--package", &found.package])
            .args(["--message-format", "short"])
            .output()
            .context("cannot run cargo")?;
        if output.status.success() {
            eprintln!("compiles");
            features.push(feature.as_str());
        } else {
            eprintln!("does not compile: left out (`cargo xtask grade {topic}` says why)");
            not_compiling.push(topic.to_owned());
        }
    }
    // `cargo xtask view --screenshot F -- --mesh m.ply` and `cargo xtask
    // view -- --screenshot F --mesh m.ply` mean the same: the separator
    // is cargo's habit, not an option of the viewer's.
    let args: Vec<&String> = args.iter().filter(|a| *a != "--").collect();
    // A picture without a window needs no egui: a quick build.
    let window = !args
        .iter()
        .any(|a| *a == "--screenshot" || a.starts_with("--screenshot="));
    if window {
        features.push("window");
        eprintln!(
            "building the viewer with its window (the first time takes minutes: egui and wgpu) …"
        );
    } else {
        eprintln!("building the viewer without its window (for the screenshot) …");
    }
    let mut build = staged.cargo();
    build.args(["build", "--package", VIEWER, "--no-default-features"]);
    if !features.is_empty() {
        build.args(["--features", &features.join(",")]);
    }
    cargo::run_visibly(&mut build)?;
    let binary = staged.target_dir.join("debug").join(VIEWER);
    // The stage's lock is not needed while the viewer runs: grading in
    // another terminal may go on.
    drop(staged);
    let mut command = std::process::Command::new(&binary);
    for topic in &not_compiling {
        command.args(["--not-compiling", topic]);
    }
    // The pipeline's stages of topics this edition does not hold are drawn
    // by the course's given code.
    for (_, topic) in &pairs {
        if !course.iter().any(|t| t.name == *topic) {
            command.args(["--given", topic]);
        }
    }
    command.args(args);
    let status = command
        .status()
        .with_context(|| format!("cannot run {}", binary.display()))?;
    if !status.success() {
        bail!("the viewer exited with {status}");
    }
    Ok(())
}
