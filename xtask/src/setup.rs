//! The set-up the commands do themselves: Mesa's software Vulkan driver
//! (lavapipe) for topics whose task sheet says `gpu = true`, and
//! bubblewrap, the sandbox every test of student code runs in (see
//! [`sandbox`]).
//!
//! wgpu needs a Vulkan (or GL) driver at run time, not at build time. A
//! machine with a GPU has one; a machine without (CI, many laptops in a
//! container) gets lavapipe, which renders on the CPU. Before grading or
//! testing a GPU topic on Linux, the commands check for a Vulkan loader
//! and an installable client driver, and install both with `apt-get` when
//! they are missing and the machine allows it (root, or `sudo` without a
//! password). Anything else is a message saying what to install, never a
//! failure here: the GPU tests then fail with their own clear reason.

use std::path::Path;
use std::process::{Command, Stdio};

/// The variable the `gpu` crate reads: `1` makes a missing adapter a test
/// failure instead of a skip. Grading sets it, so that a machine without a
/// driver never earns the points of a skipped test.
pub const GPU_REQUIRED_VAR: &str = "GPU_REQUIRED";

/// The Debian/Ubuntu packages: the Vulkan loader and Mesa's drivers,
/// lavapipe among them.
pub const VULKAN_PACKAGES: [&str; 2] = ["libvulkan1", "mesa-vulkan-drivers"];

/// Where Vulkan's installable client drivers register (`*.json`).
const ICD_DIRS: [&str; 3] = [
    "/usr/share/vulkan/icd.d",
    "/etc/vulkan/icd.d",
    "/usr/local/share/vulkan/icd.d",
];

/// Where the Vulkan loader lives on common Linux distributions.
const LOADER_PATHS: [&str; 5] = [
    "/usr/lib/x86_64-linux-gnu/libvulkan.so.1",
    "/usr/lib/aarch64-linux-gnu/libvulkan.so.1",
    "/usr/lib64/libvulkan.so.1",
    "/usr/lib/libvulkan.so.1",
    "/lib/x86_64-linux-gnu/libvulkan.so.1",
];

/// Whether a Vulkan loader and at least one driver are installed.
#[must_use]
pub fn vulkan_present() -> bool {
    let loader = LOADER_PATHS.iter().any(|p| Path::new(p).exists());
    let driver = ICD_DIRS.iter().any(|dir| {
        std::fs::read_dir(dir).is_ok_and(|entries| {
            entries
                .flatten()
                .any(|e| e.path().extension().is_some_and(|x| x == "json"))
        })
    });
    loader && driver
}

/// Makes sure a GPU topic can find a Vulkan driver (see the module
/// documentation); prints what it does and never fails.
pub fn ensure_vulkan() {
    if !cfg!(target_os = "linux") || vulkan_present() {
        return;
    }
    let what = "the GPU topics need a Vulkan driver and this machine has none";
    let installed = apt_install(
        &VULKAN_PACKAGES,
        "Mesa's software Vulkan driver for the GPU topics",
        what,
    );
    if installed && !vulkan_present() {
        println!(
            "note: the Vulkan packages are installed, yet no driver was found; the GPU tests will fail"
        );
    }
}

/// Set (to anything), grading runs without the sandbox, as where none can
/// be had: to see what an unsandboxed grade does (its reports say so).
pub const NO_SANDBOX_VAR: &str = "XTASK_NO_SANDBOX";

/// The Debian/Ubuntu package of bubblewrap, the sandbox of every test run.
pub const SANDBOX_PACKAGE: &str = "bubblewrap";

/// The sandbox program, if it runs here: `bwrap` on the `PATH`, installed
/// with `apt-get` when missing and the machine allows it (as for
/// lavapipe), then tried once with the options the grader uses (a
/// container may forbid the namespaces it needs). `None` means tests run
/// unsandboxed, which every report then says. The answer is kept for the
/// rest of the run.
pub fn sandbox() -> Option<std::path::PathBuf> {
    static FOUND: std::sync::OnceLock<Option<std::path::PathBuf>> = std::sync::OnceLock::new();
    FOUND
        .get_or_init(|| {
            if !cfg!(target_os = "linux") {
                return None;
            }
            if std::env::var_os(NO_SANDBOX_VAR).is_some() {
                println!(
                    "note: {NO_SANDBOX_VAR} is set: student code runs unsandboxed, and the reports say so"
                );
                return None;
            }
            let find = || {
                std::env::var_os("PATH").and_then(|path| {
                    std::env::split_paths(&path)
                        .map(|dir| dir.join("bwrap"))
                        .find(|p| p.is_file())
                })
            };
            let program = find().or_else(|| {
                apt_install(
                    &[SANDBOX_PACKAGE],
                    "bubblewrap, the sandbox that tests of student code run in",
                    "tests of student code run in a bubblewrap sandbox, and this machine has none",
                );
                find()
            })?;
            let works = succeeds(Command::new(&program).args([
                "--ro-bind", "/", "/", "--dev", "/dev", "--tmpfs", "/proc", "--unshare-all",
                "--die-with-parent", "--new-session", "true",
            ]));
            if !works {
                println!(
                    "note: {} cannot create its namespaces here (a container that forbids them?); tests run unsandboxed",
                    program.display()
                );
            }
            works.then_some(program)
        })
        .clone()
}

/// Installs Debian `packages` with `apt-get` when this machine allows it
/// (root, or `sudo` without a password), saying what it does; `what` is
/// what they are for, `why` the note printed when they cannot be
/// installed. Returns whether they were installed.
pub fn apt_install(packages: &[&str], what: &str, why: &str) -> bool {
    let manual = format!(
        "apt-get install -y --no-install-recommends {}",
        packages.join(" ")
    );
    if !succeeds(Command::new("apt-get").arg("--version")) {
        println!(
            "note: {why}; install {} (Debian/Ubuntu: `{manual}`)",
            packages.join(", ")
        );
        return false;
    }
    let root = Command::new("id")
        .arg("-u")
        .output()
        .is_ok_and(|out| String::from_utf8_lossy(&out.stdout).trim() == "0");
    let sudo = !root && succeeds(Command::new("sudo").args(["-n", "true"]));
    if !root && !sudo {
        println!("note: {why}; run `sudo {manual}`");
        return false;
    }
    println!("==> installing {what}: {manual}");
    let apt = |args: &[&str]| {
        let mut command = if sudo {
            let mut c = Command::new("sudo");
            c.args(["-n", "apt-get"]);
            c
        } else {
            Command::new("apt-get")
        };
        command
            .args(args)
            .env("DEBIAN_FRONTEND", "noninteractive")
            .stdout(Stdio::null());
        succeeds(&mut command)
    };
    let install: Vec<&str> = ["install", "-y", "-q", "--no-install-recommends"]
        .into_iter()
        .chain(packages.iter().copied())
        .collect();
    // The package lists may be missing or stale on a fresh machine.
    let installed = apt(&install) || (apt(&["update", "-q"]) && apt(&install));
    if installed {
        println!("==> installed: {}", packages.join(", "));
    } else {
        println!("note: installing {} failed; {why}", packages.join(", "));
    }
    installed
}

/// Whether `command` runs and succeeds; it prints nothing (`apt-get
/// --version` would print its banner first thing in a grade).
pub(crate) fn succeeds(command: &mut Command) -> bool {
    command
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|status| status.success())
}
