//! The disk the self-test uses. A CI machine's disk is shared and its free
//! space varies from run to run, so every step says what it leaves (the
//! size of `target/` and the space still free), and a build folder that no
//! later step reads is removed as soon as its step is done.

use std::fmt;
use std::path::Path;
use std::process::Command;

/// What the disk holds after a step.
#[derive(Debug, Clone, Copy)]
pub(super) struct Disk {
    /// The size of the checkout's `target/`, in bytes.
    target: Option<u64>,
    /// The space free on its disk, in bytes.
    free: Option<u64>,
}

impl Disk {
    /// Measures `root`'s `target/` and the space free beside it (with `du`
    /// and `df`; `None` where they are missing or fail).
    pub(super) fn measure(root: &Path) -> Disk {
        let target = root.join("target");
        let kibibytes = |program: &str, args: &[&str], column: usize, line: usize| {
            let output = Command::new(program)
                .args(args)
                .arg(&target)
                .output()
                .ok()
                .filter(|output| output.status.success())?;
            let text = String::from_utf8_lossy(&output.stdout).into_owned();
            let row = text.lines().nth(line)?;
            row.split_whitespace().nth(column)?.parse::<u64>().ok()
        };
        Disk {
            target: kibibytes("du", &["-sk"], 0, 0).map(|k| k << 10),
            // POSIX format: `Filesystem 1024-blocks Used Available ...`.
            free: kibibytes("df", &["-Pk"], 3, 1).map(|k| k << 10),
        }
    }
}

impl fmt::Display for Disk {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let shown = |bytes: Option<u64>| bytes.map_or_else(|| "?".to_owned(), gigabytes);
        write!(
            f,
            "target/ {}, {} free",
            shown(self.target),
            shown(self.free)
        )
    }
}

/// `bytes` in GB, to a tenth.
fn gigabytes(bytes: u64) -> String {
    let gb = bytes as f64 / 1e9;
    format!("{gb:.1} GB")
}

/// Removes `folder`, a build folder no later step reads, saying so; a
/// folder that cannot be removed is only reported (it costs disk, not
/// correctness).
pub(crate) fn remove_build(folder: &Path, what: &str) {
    if !folder.exists() {
        return;
    }
    // (It holds what the fixtures' hostile members left: removed by the
    // grader's own bounded removal.)
    match crate::files::remove_tree(folder) {
        Ok(()) => println!("removed {} ({what})", folder.display()),
        Err(error) => println!("cannot remove {} ({what}): {error:#}", folder.display()),
    }
}
