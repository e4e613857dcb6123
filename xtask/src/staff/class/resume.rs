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
use crate::files::{MAX_SUBMITTED_FILE, files_under, read_capped};

/// The fingerprint of what a member's grade was made from, in its report
/// folder.
pub const FINGERPRINT_FILE: &str = "graded-from.txt";

/// The contents of every file under `root` (its paths and bytes, as
/// `files_under` lists them: no build output, no `.git`), hashed: the
/// official course's, where anything unreadable is an error.
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

/// A member's checkout hashed as [`tree_hash`] hashes the course, but
/// never failing and never without bound: the walk is the bounded one of
/// `files_under`, and a file is read only when it is a plain file of at
/// most [`MAX_SUBMITTED_FILE`] bytes. What it cannot read stands in the
/// hash by what can be said of it: a file too large (a sparse terabyte
/// costs no disk) or no plain file by its size and time, a walk that
/// failed (folders too deep, a path longer than `PATH_MAX`, too many
/// files) by its error. So the same checkout always gives the same hash,
/// and an unreadable one is that member's grade to explain (its grade
/// fails on the same walk, with the reason), never the end of the class.
fn member_hash(root: &Path) -> u64 {
    let mut hasher = DefaultHasher::new();
    let files = match files_under(root) {
        Ok(files) => files,
        Err(error) => {
            format!("unreadable: {error:#}").hash(&mut hasher);
            return hasher.finish();
        }
    };
    for file in files {
        file.hash(&mut hasher);
        let path = root.join(&file);
        match read_capped(&path, MAX_SUBMITTED_FILE) {
            Ok(bytes) => bytes.hash(&mut hasher),
            Err(_) => {
                let meta = fs::symlink_metadata(&path).ok();
                "not read".hash(&mut hasher);
                meta.as_ref().map(fs::Metadata::len).hash(&mut hasher);
                meta.and_then(|m| m.modified().ok()).hash(&mut hasher);
            }
        }
    }
    hasher.finish()
}

/// The fingerprint of grading `submission` against the course whose
/// [`tree_hash`] is `official`, with this grader. Whatever the checkout
/// holds, this is `Ok` (see [`member_hash`]): one member's files never
/// stop a class before it starts.
pub fn fingerprint(official: u64, submission: &Path) -> Result<String> {
    Ok(format!(
        "course {official:016x} submission {:016x} grader {}",
        member_hash(submission),
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

    /// What stopped a class before its first member was graded: a sparse
    /// terabyte (read whole, out of memory), a path longer than
    /// `PATH_MAX` and a chain of folders deeper than any walk goes (the
    /// walk failed, and `?` ended the class). Each gives a fingerprint,
    /// the same one each time, and one that differs from the clean
    /// checkout's.
    // Linux's file system, where a class is graded for the record: Windows
    // limits paths, keeps removed files open and writes other separators.
    #[cfg(unix)]
    #[test]
    fn a_hostile_checkout_has_a_fingerprint_and_stops_nothing() {
        use crate::files::tests::{chain, scratch};
        let dir = scratch("fingerprint-hostile");
        fs::create_dir_all(dir.join("exercises/01-a/src")).unwrap();
        fs::write(dir.join("exercises/01-a/src/a.rs"), "fn a() {}").unwrap();
        let clean = fingerprint(1, &dir).unwrap();
        let huge = fs::File::create(dir.join("huge.bin")).unwrap();
        huge.set_len(1 << 40).unwrap();
        let sparse = fingerprint(1, &dir).unwrap();
        assert_ne!(sparse, clean);
        assert_eq!(sparse, fingerprint(1, &dir).unwrap());
        chain(&dir, "long", 20, &"n".repeat(250));
        let long = fingerprint(1, &dir).unwrap();
        assert_ne!(long, sparse);
        assert_eq!(long, fingerprint(1, &dir).unwrap());
        crate::files::remove_tree(&dir.join("long")).unwrap();
        chain(&dir, "deep", 2_100, "d");
        assert_ne!(fingerprint(1, &dir).unwrap(), sparse);
        crate::files::remove_tree(&dir).unwrap();
    }
}
