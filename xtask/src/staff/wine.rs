//! The Windows build, run here: the grader's own unit tests and one
//! topic's tests compiled for `x86_64-pc-windows-gnu` (MinGW's linker)
//! and run under Wine, against the solutions in the stage. What only a
//! real Windows machine can tell (its GPU drivers, the viewer's window)
//! is left to the course's hosted-runner workflow.
//!
//! Debian's Wine (8.0) lacks `bcryptprimitives.dll`, from which the Rust
//! standard library draws its random numbers on Windows 10 and later: a
//! stand-in built from `xtask/windows/bcryptprimitives.c` lies beside the
//! executables (Windows looks for a DLL in the program's folder first).

use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{Context, Result, bail, ensure};

use crate::stage::{self, Overlay};
use crate::{cargo, setup};

/// The Windows target built.
pub const TARGET: &str = "x86_64-pc-windows-gnu";
/// The Debian packages: Wine, and MinGW's compiler (the target's linker).
const PACKAGES: [&str; 2] = ["wine64", "gcc-mingw-w64-x86-64"];
/// Where Debian puts Wine's 64-bit loader.
const WINE: &str = "/usr/lib/wine/wine64";
/// MinGW's C compiler, which links for the target and builds the stand-in.
const MINGW_GCC: &str = "x86_64-w64-mingw32-gcc";
/// The stand-in's source, relative to the course root.
const SHIM_SOURCE: &str = "xtask/windows/bcryptprimitives.c";
/// What is built and run: the grader's unit tests, and a topic whose
/// tests draw, compare pictures and snapshots.
const PACKAGES_TESTED: [(&str, &[&str]); 2] = [("xtask", &["--bins"]), ("lines", &["--tests"])];

/// Builds the Windows test executables in the stage (the solutions) and
/// runs each under Wine; fails unless every test passes.
pub fn tests_under_wine(root: &Path) -> Result<String> {
    if !cfg!(all(target_os = "linux", target_arch = "x86_64")) {
        bail!("the Windows build is run under Wine on x86-64 Linux only");
    }
    crate::staff::setup::rustup_target(TARGET)?;
    if !Path::new(WINE).is_file() || !on_path(MINGW_GCC) {
        setup::apt_install(
            &PACKAGES,
            "Wine and MinGW, to run the Windows build here",
            "the Windows build runs under Wine",
        );
    }
    ensure!(
        Path::new(WINE).is_file() && on_path(MINGW_GCC),
        "Wine ({WINE}) and MinGW ({MINGW_GCC}) are needed: apt-get install {}",
        PACKAGES.join(" ")
    );
    let staged = stage::stage(root, Overlay::Reference, None)?;
    // The stage's own cache: its host artifacts serve, the Windows ones lie
    // in a folder of their own, with Wine's prefix; no other step reads
    // them.
    let windows = staged.target_dir.join(TARGET);
    let result = build_and_run(root, &staged);
    crate::staff::test::disk::remove_build(&windows, "the Windows build and its Wine prefix");
    result
}

/// Builds the Windows test executables in `staged` and runs each under
/// Wine.
fn build_and_run(root: &Path, staged: &stage::Stage) -> Result<String> {
    let target_dir = staged.target_dir.clone();
    let mut executables = Vec::new();
    for (package, kind) in PACKAGES_TESTED {
        let mut build = staged.cargo();
        build
            .env("CARGO_TARGET_DIR", &target_dir)
            .args(["test", "--no-run", "--target", TARGET, "--package", package])
            .args(kind)
            .args(["--message-format", "json-render-diagnostics"]);
        println!("$ {} (for Windows)", cargo::display(&build));
        let output = build
            .output()
            .with_context(|| format!("cannot run `{}`", cargo::display(&build)))?;
        ensure!(
            output.status.success(),
            "the Windows build of {package} failed:\n{}",
            String::from_utf8_lossy(&output.stderr)
        );
        executables.extend(test_executables(&String::from_utf8_lossy(&output.stdout)));
    }
    ensure!(
        !executables.is_empty(),
        "cargo built no Windows test executable"
    );
    let prefix = target_dir.join(TARGET).join("wine-prefix");
    let mut passed = 0;
    let mut failed = Vec::new();
    for executable in &executables {
        let folder = executable
            .parent()
            .context("an executable lies in a folder")?;
        shim(root, folder)?;
        let output = Command::new(WINE)
            .arg(executable)
            .current_dir(&staged.root)
            .env("WINEPREFIX", &prefix)
            .env("WINEDEBUG", "-all")
            .env("INSTA_UPDATE", "no")
            // insta asks cargo where the workspace is; there is no cargo
            // under Wine (the grader names it the same way).
            .env("INSTA_WORKSPACE_ROOT", &staged.root)
            .env_remove("DISPLAY")
            .output()
            .with_context(|| format!("cannot run {WINE}"))?;
        let stdout = String::from_utf8_lossy(&output.stdout);
        passed += stdout
            .lines()
            .filter_map(|line| line.strip_prefix("test result: "))
            .filter_map(|rest| rest.split("; ").next()?.split(". ").nth(1))
            .filter_map(|count| count.strip_suffix(" passed")?.parse::<usize>().ok())
            .sum::<usize>();
        if !output.status.success() {
            let name = executable.file_name().unwrap_or_default().to_string_lossy();
            let failures: Vec<&str> = stdout
                .lines()
                .filter(|line| line.starts_with("test ") && line.ends_with("FAILED"))
                .collect();
            // No failed test: the program did not run (Wine's own errors,
            // a full disk), which only its standard error tells.
            let shown = if failures.is_empty() {
                crate::staff::test::tail(&String::from_utf8_lossy(&output.stderr), 20)
            } else {
                failures.join("\n")
            };
            println!("{name} failed under Wine ({}):\n{shown}", output.status);
            failed.push(if failures.is_empty() {
                format!("{name} (did not run: {})", output.status)
            } else {
                format!("{name} ({} failing)", failures.len())
            });
        }
    }
    ensure!(
        failed.is_empty(),
        "{} of {} Windows test executables failed under Wine ({passed} tests passed): {}",
        failed.len(),
        executables.len(),
        failed.join(", ")
    );
    Ok(format!(
        "{passed} tests of {} Windows executables ({}) pass under Wine",
        executables.len(),
        PACKAGES_TESTED.map(|(p, _)| p).join(", ")
    ))
}

/// The test executables among cargo's JSON messages.
fn test_executables(messages: &str) -> Vec<PathBuf> {
    messages
        .lines()
        .filter_map(crate::cargo::Message::parse)
        .filter(|m| m.is_artifact() && m.profile.as_ref().is_some_and(|p| p.test))
        .filter_map(|m| m.executable)
        .collect()
}

/// Builds the `bcryptprimitives.dll` stand-in into `folder`, unless it is
/// there already.
fn shim(root: &Path, folder: &Path) -> Result<()> {
    let dll = folder.join("bcryptprimitives.dll");
    if dll.is_file() {
        return Ok(());
    }
    let status = Command::new(MINGW_GCC)
        .args(["-shared", "-O2", "-o"])
        .arg(&dll)
        .arg(root.join(SHIM_SOURCE))
        .arg("-ladvapi32")
        .status()
        .with_context(|| format!("cannot run {MINGW_GCC}"))?;
    ensure!(
        status.success(),
        "{MINGW_GCC} could not build {}",
        dll.display()
    );
    Ok(())
}

fn on_path(program: &str) -> bool {
    std::env::var_os("PATH")
        .is_some_and(|path| std::env::split_paths(&path).any(|dir| dir.join(program).is_file()))
}
