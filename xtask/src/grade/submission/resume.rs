//! A class graded again: members whose grade is still good are kept, and
//! a class is split into shards for grading on several machines.
//!
//! A member's grade is still good when it was made from the same files:
//! its report folder keeps a fingerprint ([`FINGERPRINT_FILE`]) of the
//! submission's files and of the official course's, and a member whose
//! fingerprint matches is not graded again. So a class that was
//! interrupted goes on with the members not graded yet, and a submission
//! pushed again, or a course whose tests changed, is graded anew.

use std::fs;
use std::hash::{DefaultHasher, Hash as _, Hasher as _};
use std::path::Path;

use anyhow::{Context, Result, bail, ensure};

use super::gradebook::ROW_FILE;
use crate::files::files_under;

/// The fingerprint of what a member's grade was made from, in its report
/// folder.
pub const FINGERPRINT_FILE: &str = "graded-from.txt";

/// The contents of every file under `root` (its paths and bytes, as
/// `files_under` lists them: no build output, no `.git`), hashed.
pub fn tree_hash(root: &Path) -> Result<u64> {
    let mut hasher = DefaultHasher::new();
    for file in files_under(root)? {
        let bytes = fs::read(root.join(&file))
            .with_context(|| format!("cannot read {}", root.join(&file).display()))?;
        file.hash(&mut hasher);
        bytes.hash(&mut hasher);
    }
    Ok(hasher.finish())
}

/// The fingerprint of grading `submission` against the course whose
/// [`tree_hash`] is `official`, with this grader.
pub fn fingerprint(official: u64, submission: &Path) -> Result<String> {
    Ok(format!(
        "course {official:016x} submission {:016x} grader {}",
        tree_hash(submission)?,
        env!("CARGO_PKG_VERSION")
    ))
}

/// Whether the report folder `out` holds a member's grade made from
/// `fingerprint`.
pub fn is_current(out: &Path, fingerprint: &str) -> bool {
    out.join(ROW_FILE).is_file()
        && fs::read_to_string(out.join(FINGERPRINT_FILE)).is_ok_and(|f| f == fingerprint)
}

/// Keeps the fingerprint of the grade in the report folder `out`.
pub fn save(out: &Path, fingerprint: &str) -> Result<()> {
    let path = out.join(FINGERPRINT_FILE);
    fs::write(&path, fingerprint).with_context(|| format!("cannot write {}", path.display()))
}

/// The `index`-th (from 1) of `count` parts of a class: `--shard 2/3`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    pub index: usize,
    pub count: usize,
}

impl Shard {
    /// Reads `I/N`, `1 ≤ I ≤ N`.
    pub fn parse(text: &str) -> Result<Self> {
        let Some((index, count)) = text.split_once('/') else {
            bail!("a shard is I/N, the I-th of N parts (e.g. 2/5), not `{text}`");
        };
        let number = |part: &str| {
            part.trim()
                .parse::<usize>()
                .with_context(|| format!("`{text}`: `{part}` is not a number"))
        };
        let (index, count) = (number(index)?, number(count)?);
        ensure!(
            count >= 1 && (1..=count).contains(&index),
            "`{text}`: the shard I/N needs 1 ≤ I ≤ N"
        );
        Ok(Self { index, count })
    }

    /// Whether the member `name` belongs to this shard. A member's shard
    /// depends on its name alone (FNV-1a, which is the same on every
    /// machine and Rust version), so it stays the same when the class
    /// grows, and every machine of a grading agrees.
    #[must_use]
    pub fn holds(self, name: &str) -> bool {
        let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
        for byte in name.bytes() {
            hash ^= u64::from(byte);
            hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
        }
        hash % self.count as u64 == (self.index - 1) as u64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_split_a_class_into_parts_that_cover_it_once() {
        assert!(Shard::parse("0/3").is_err());
        assert!(Shard::parse("4/3").is_err());
        assert!(Shard::parse("three").is_err());
        assert_eq!(Shard::parse("2/3").unwrap(), Shard { index: 2, count: 3 });
        let names: Vec<String> = (0..300).map(|i| format!("student-{i:03}")).collect();
        let shards: Vec<Shard> = (1..=3).map(|i| Shard { index: i, count: 3 }).collect();
        let mut sizes = [0usize; 3];
        for name in &names {
            let holding: Vec<usize> = (0..3).filter(|&i| shards[i].holds(name)).collect();
            assert_eq!(holding.len(), 1, "{name} is in exactly one shard");
            sizes[holding[0]] += 1;
        }
        // Equal parts, give or take what hashing gives.
        assert!(sizes.iter().all(|&n| (70..=130).contains(&n)), "{sizes:?}");
        assert!(Shard { index: 1, count: 1 }.holds("anyone"));
    }

    #[test]
    fn a_fingerprint_changes_with_any_file() {
        let dir = std::env::temp_dir().join(format!("xtask-fingerprint-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(dir.join("exercises/01-a/src")).unwrap();
        fs::write(dir.join("exercises/01-a/src/a.rs"), "fn a() {}").unwrap();
        let first = fingerprint(1, &dir).unwrap();
        assert_eq!(first, fingerprint(1, &dir).unwrap());
        assert_ne!(first, fingerprint(2, &dir).unwrap(), "another course");
        fs::create_dir_all(dir.join("target")).unwrap();
        fs::write(dir.join("target/build.log"), "built").unwrap();
        assert_eq!(
            first,
            fingerprint(1, &dir).unwrap(),
            "build output counts not"
        );
        fs::write(dir.join("exercises/01-a/src/a.rs"), "fn a() { }").unwrap();
        assert_ne!(first, fingerprint(1, &dir).unwrap(), "the student's change");
        let _ = fs::remove_dir_all(&dir);
    }
}
