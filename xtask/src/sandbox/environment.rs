//! What a job is given: the toolchain that builds student code, and the
//! environment variables every job gets (an allowlist, never inherited).

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{Context, Result};

/// The toolchain that builds student code: cargo and rustc of the
/// toolchain `cargo xtask` runs on, called directly (no rustup proxy,
/// which would need the home folder), and cargo's home for the sources of
/// the dependencies.
#[derive(Debug, Clone)]
pub struct Toolchain {
    /// The toolchain's root (`rustc --print sysroot`).
    pub sysroot: PathBuf,
    /// cargo's home: the registry and git sources.
    pub cargo_home: PathBuf,
}

impl Toolchain {
    /// The toolchain of this run: `$CARGO`'s (cargo sets it for `cargo
    /// xtask`), else `rustc --print sysroot`.
    pub fn find() -> Result<Self> {
        let from_cargo = std::env::var_os("CARGO")
            .map(PathBuf::from)
            .and_then(|cargo| Some(cargo.parent()?.parent()?.to_path_buf()))
            .filter(|root| root.join("bin").join(exe("rustc")).is_file());
        let sysroot = match from_cargo {
            Some(root) => root,
            None => {
                let output = Command::new("rustc")
                    .args(["--print", "sysroot"])
                    .output()
                    .context("cannot run `rustc --print sysroot`")?;
                anyhow::ensure!(output.status.success(), "`rustc --print sysroot` failed");
                PathBuf::from(String::from_utf8_lossy(&output.stdout).trim())
            }
        };
        let cargo_home = std::env::var_os("CARGO_HOME")
            .map(PathBuf::from)
            .or_else(|| home_dir().map(|home| home.join(".cargo")))
            .context("cannot tell cargo's home folder (set CARGO_HOME)")?;
        Ok(Self {
            sysroot,
            cargo_home,
        })
    }

    /// The cargo program.
    #[must_use]
    pub fn cargo(&self) -> PathBuf {
        self.sysroot.join("bin").join(exe("cargo"))
    }

    /// The rustc program.
    #[must_use]
    pub fn rustc(&self) -> PathBuf {
        self.sysroot.join("bin").join(exe("rustc"))
    }
}

fn exe(name: &str) -> String {
    format!("{name}{}", std::env::consts::EXE_SUFFIX)
}

fn home_dir() -> Option<PathBuf> {
    std::env::var_os(if cfg!(windows) { "USERPROFILE" } else { "HOME" }).map(PathBuf::from)
}

/// The environment of a job: built from nothing, never inherited.
pub struct Environment;

impl Environment {
    /// Variables of the grader's passed on because they choose a GPU driver
    /// or a property test's random cases, or tune a build without changing
    /// what it means; nothing else of the grader's environment (tokens,
    /// keys, paths of other courses) reaches student code.
    pub const PASSED_ON: &[&str] = &[
        "PROPTEST_RNG_SEED",
        "NODEVICE_SELECT",
        "LIBGL_ALWAYS_SOFTWARE",
        "CARGO_INCREMENTAL",
        "CARGO_BUILD_JOBS",
        "RUSTFLAGS",
    ];
    /// Prefixes of variables passed on: GPU drivers' and wgpu's choices.
    pub const PASSED_ON_PREFIXES: &[&str] = &["WGPU_", "VK_", "MESA_", "LP_"];
    /// What Windows programs need to run at all (there is no sandbox
    /// there, so they name nothing the process could not read anyway).
    pub const WINDOWS_SYSTEM: &[&str] = &[
        "SystemRoot",
        "SystemDrive",
        "windir",
        "ComSpec",
        "PATHEXT",
        "TEMP",
        "TMP",
        "USERPROFILE",
        "ProgramData",
        "ProgramFiles",
        "ProgramFiles(x86)",
        "NUMBER_OF_PROCESSORS",
        "PROCESSOR_ARCHITECTURE",
    ];

    /// The test tools' settings, set in every job so that no file can
    /// set them: insta reads each of these from the variable when it is
    /// set and non-empty, and only otherwise from an `insta.yaml` (or
    /// `.config/insta.yaml`, `.insta.yaml`) in the workspace root, so a
    /// configuration file anywhere (a submission's, one in a folder above
    /// the course or the stage) is never consulted (insta 1.49, `env.rs`,
    /// `ToolConfig::from_workspace`). Snapshots fail (no forced pass), are
    /// compared by their contents (metadata aside), show insta's diff (the
    /// grader reads it into the report) and are never written in place; a
    /// test's plan sets `INSTA_UPDATE=new` and `INSTA_PENDING_DIR`, so a
    /// failed one is left as `.snap.new` in the report folder, and
    /// `INSTA_WORKSPACE_ROOT` to the graded course. proptest reads only
    /// `PROPTEST_*` variables, none passed on but the grader's
    /// `PROPTEST_RNG_SEED`; no failure is persisted (no
    /// `proptest-regressions` file read or written). Every other variable
    /// of theirs (`INSTA_DIFF_TOOL`, `INSTA_GLOB_FILTER`, `PROPTEST_CASES`,
    /// …) is unset: the environment is an allowlist.
    pub const TOOL_SETTINGS: &[(&str, &str)] = &[
        ("INSTA_FORCE_PASS", "0"),
        ("INSTA_REQUIRE_FULL_MATCH", "0"),
        ("INSTA_OUTPUT", "diff"),
        ("INSTA_UPDATE", "no"),
        ("INSTA_GLOB_FAIL_FAST", "0"),
        ("PROPTEST_DISABLE_FAILURE_PERSISTENCE", "1"),
    ];

    /// The seed of every property test's cases when the grader was given
    /// none: the course's own (`testkit::SEED`, which `cargo test` uses),
    /// also for a test whose configuration forgot it. Every run of a test
    /// must meet the same cases: a grade is repeatable, and a replayed
    /// test must make the same calls as the recorded run.
    pub const PROPTEST_SEED: u64 = wire::SEED;

    /// The variables every job gets: the grader's [`Self::PASSED_ON`] ones,
    /// the tools' [`Self::TOOL_SETTINGS`], a `PATH` of the system's
    /// programs, a `HOME` and `TMPDIR` of its own (`home`), a UTF-8 locale.
    #[must_use]
    pub fn base(home: &Path, extra_path: Option<&Path>) -> Vec<(OsString, OsString)> {
        let mut env: Vec<(OsString, OsString)> = std::env::vars_os()
            .filter(|(name, _)| {
                let name = name.to_string_lossy();
                Self::PASSED_ON.contains(&name.as_ref())
                    || Self::PASSED_ON_PREFIXES.iter().any(|p| name.starts_with(p))
                    || (cfg!(windows)
                        && Self::WINDOWS_SYSTEM
                            .iter()
                            .any(|w| w.eq_ignore_ascii_case(&name)))
            })
            .collect();
        let mut path: Vec<PathBuf> = extra_path.map(Path::to_path_buf).into_iter().collect();
        if cfg!(windows) {
            // The system's programs, the linker's included, are found
            // through the user's PATH on Windows.
            path.extend(
                std::env::var_os("PATH")
                    .map_or_else(Vec::new, |p| std::env::split_paths(&p).collect::<Vec<_>>()),
            );
        } else {
            path.extend(
                ["/usr/local/bin", "/usr/bin", "/bin", "/usr/sbin", "/sbin"].map(PathBuf::from),
            );
        }
        let path = std::env::join_paths(path).unwrap_or_default();
        env.push(("PATH".into(), path));
        if !cfg!(windows) {
            env.push(("HOME".into(), home.into()));
        }
        env.push(("TMPDIR".into(), home.into()));
        env.push(("LANG".into(), "C.UTF-8".into()));
        if !env.iter().any(|(name, _)| name == "PROPTEST_RNG_SEED") {
            env.push((
                "PROPTEST_RNG_SEED".into(),
                Self::PROPTEST_SEED.to_string().into(),
            ));
        }
        env.extend(
            Self::TOOL_SETTINGS
                .iter()
                .map(|(name, value)| (OsString::from(name), OsString::from(value))),
        );
        env
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_environment_is_built_not_inherited() {
        // SAFETY-free: the test reads the variables, it sets none; the
        // grader's own environment holds PATH and HOME, never passed on.
        let env = Environment::base(Path::new("/scratch"), None);
        let names: Vec<String> = env
            .iter()
            .map(|(name, _)| name.to_string_lossy().into_owned())
            .collect();
        for name in &names {
            assert!(
                ["PATH", "HOME", "TMPDIR", "LANG"].contains(&name.as_str())
                    || Environment::TOOL_SETTINGS.iter().any(|(n, _)| n == name)
                    || Environment::PASSED_ON.contains(&name.as_str())
                    || Environment::PASSED_ON_PREFIXES
                        .iter()
                        .any(|p| name.starts_with(p))
                    || cfg!(windows),
                "{name} is not on the allowlist"
            );
        }
        let home = env.iter().find(|(n, _)| n == "TMPDIR").unwrap();
        assert_eq!(home.1, "/scratch");
    }

    #[test]
    fn every_insta_setting_a_file_could_make_is_set_by_the_grader() {
        // insta 1.49 resolves these five from the environment first and
        // from `insta.yaml` only when the variable is unset or empty.
        let env = Environment::base(Path::new("/scratch"), None);
        for name in [
            "INSTA_FORCE_PASS",
            "INSTA_REQUIRE_FULL_MATCH",
            "INSTA_OUTPUT",
            "INSTA_UPDATE",
            "INSTA_GLOB_FAIL_FAST",
            "PROPTEST_DISABLE_FAILURE_PERSISTENCE",
        ] {
            let value = env.iter().rev().find(|(n, _)| n == name).map(|(_, v)| v);
            assert!(
                value.is_some_and(|v| !v.is_empty()),
                "{name} is left to a configuration file"
            );
        }
        let force = env.iter().rev().find(|(n, _)| n == "INSTA_FORCE_PASS");
        assert_eq!(force.map(|(_, v)| v.to_str()), Some(Some("0")));
    }
}
