//! The other systems (steps 12 and 13): clippy for macOS and Windows
//! targets of the code that differs between systems, and the course's workflow for the hosted runners linted.

use std::fs;
use std::path::Path;

use anyhow::{Context, Result, ensure};

use crate::cargo;
use crate::stage::{self, Overlay};

/// The course's workflow that grades the solutions and draws the viewer's
/// picture on GitHub's hosted macOS and Windows runners (course only).
pub(super) const PLATFORMS_WORKFLOW: &str = ".github/workflows/platforms.yml";

/// Checks [`PLATFORMS_WORKFLOW`] with actionlint, and that it runs on both
/// systems the project has no machine of.
pub(super) fn platforms_workflow(root: &Path) -> Result<String> {
    let file = root.join(PLATFORMS_WORKFLOW);
    let text = fs::read_to_string(&file)
        .with_context(|| format!("the course has no {PLATFORMS_WORKFLOW}"))?;
    for runner in ["macos-latest", "windows-latest"] {
        ensure!(
            text.contains(runner),
            "{PLATFORMS_WORKFLOW} does not run on {runner}"
        );
    }
    let findings = crate::staff::setup::actionlint(&stage::home(root).join("tools"), &file)
        .context("cannot lint the hosted-runner workflow")?;
    ensure!(
        findings.is_empty(),
        "actionlint finds fault with {PLATFORMS_WORKFLOW}:\n{}",
        findings.join("\n")
    );
    Ok(format!(
        "{PLATFORMS_WORKFLOW}: macOS and Windows, actionlint finds nothing"
    ))
}

/// The packages with code for one system and not another: the grader
/// (`cfg(windows)`, `cfg(unix)`, the sandbox), the GPU library and the
/// viewer (wgpu's Metal and DX12 backends, eframe's windows, notify), and
/// topic 10, which draws through them. The rest is the same Rust on every
/// system; the hosted runners' workflow lints the whole workspace there
/// ([`PLATFORMS_WORKFLOW`]).
const PLATFORM_PACKAGES: [&str; 4] = ["xtask", "gpu", "course-viewer", "gpu-tessellation"];

/// The systems students use besides Linux, with the target cargo checks
/// for each: no machine of the project runs them.
pub(super) const OTHER_SYSTEMS: [(&str, &str); 2] = [
    ("macOS", "aarch64-apple-darwin"),
    ("Windows", "x86_64-pc-windows-gnu"),
];

/// `cargo clippy` over the packages with code of their own for each system
/// ([`PLATFORM_PACKAGES`]; the solutions staged, all targets) for macOS
/// and Windows: the code behind `cfg(windows)` and `cfg(unix)`,
/// wgpu's Metal and DX12 backends, eframe's and notify's platform code. A
/// check links nothing, so no cross linker is needed; a target that is
/// missing is installed with rustup. The other targets' artifacts lie in
/// their own folders of the stage's cache, removed when checked.
pub(super) fn clippy_for_other_systems(root: &Path) -> Result<String> {
    let packages = PLATFORM_PACKAGES
        .map(|package| ["--package", package])
        .concat();
    for (_, target) in OTHER_SYSTEMS {
        crate::staff::setup::rustup_target(target)?;
    }
    // In the stage's own cache: the host's build scripts and procedural
    // macros, built by the steps before, serve the other targets too.
    let staged = stage::stage(root, Overlay::Reference, None)?;
    for (system, target) in OTHER_SYSTEMS {
        let checked = cargo::run_visibly(
            staged
                .cargo()
                .args([
                    "clippy",
                    "--all-targets",
                    "--all-features",
                    "--target",
                    target,
                ])
                .args(&packages)
                .args(["--", "-D", "warnings"]),
        );
        // No other step reads the other systems' artifacts.
        super::disk::remove_build(
            &staged.target_dir.join(target),
            &format!("the check for {system}"),
        );
        checked?;
    }
    let systems: Vec<String> = OTHER_SYSTEMS
        .iter()
        .map(|(system, target)| format!("{system} ({target})"))
        .collect();
    Ok(format!(
        "no warnings in {} for {}",
        PLATFORM_PACKAGES.join(", "),
        systems.join(" and ")
    ))
}
