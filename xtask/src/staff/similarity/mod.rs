//! `cargo xtask similarity CLASS_DIR`: the pairs of a class whose task
//! files are unusually alike, ranked, for a tutor to look at.
//!
//! The engine is [copydetect](https://github.com/blingenf/copydetect)
//! ([`COPYDETECT_VERSION`], from PyPI), installed once into a private
//! Python environment in the course's tools folder
//! (`target/xtask/tools/copydetect`). It implements winnowing (Schleimer,
//! Wilkerson and Aiken, the algorithm behind MOSS) over code tokenized by
//! Pygments, whose Rust and WGSL lexers it uses as they are: names become
//! one placeholder each, so renaming variables hides nothing, and
//! comments and layout are dropped. Its fingerprints keep their places in
//! the text, which the page shows as highlighted passages; its Python API
//! (`CodeFingerprint`, `compare_files`) works on one pair of files at a
//! time, which lets each file be compared only with the same file of
//! another member, with that file's own stub as the boilerplate. It
//! needs nothing but Python 3 (its dependencies come as wheels from
//! PyPI), and it is pinned, so the scores of a class do not move between
//! machines or terms.
//!
//! What is compared: the course's task files ([`stage::task_files`]: the
//! files of `exercises/*/src` that hold a task) that a member changed;
//! a file still equal to the course's stub holds nothing of the member's.
//! The stub of each file is handed to the engine as boilerplate: every
//! fingerprint of the stub (each of its `NOISE`-character windows of
//! tokens) is dropped from the members' fingerprints before comparing, so
//! the given code, the same for everyone, never counts. (copydetect's
//! own `boilerplate` argument drops the wrong places of a fingerprint that
//! occurs twice in a file, so the script removes them from the
//! fingerprint's table itself.)
//!
//! The page highlights each match on whole tokens, read from the
//! engine's tokens (copydetect's own offsets place a match before the
//! comments and spaces that precede it), and leaves out of a highlight
//! the characters a fingerprint of the stub covers: a match that reaches
//! into a given signature or doc comment is shown without it.
//!
//! The score of a pair: for each member, the share of its own code (the
//! tokens its fingerprints cover, summed over the files both changed)
//! that matches the other's; the pair's score is the larger share, so a
//! member who copied a whole solution and added more is found from the
//! side that was copied. Pairs at or above the threshold are flagged. A
//! high score is a reason to read both, not a verdict: short tasks leave
//! little room to differ.
//!
//! Written to `--out` (default `<root>/target/similarity`):
//! `similarity.json` (every pair with shares, files and matched byte
//! ranges) and `similarity.html` (the ranked table, then the matching
//! passages of the leading pairs side by side).

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail, ensure};
use serde::Serialize;

use crate::{stage, topics};

mod engine;
mod page;

use engine::{Answer, detect, install};
use page::page;

/// The copydetect release installed and driven.
pub const COPYDETECT_VERSION: &str = "0.5.0";

/// The score from which a pair is flagged when the tutor names none.
pub const DEFAULT_THRESHOLD: f64 = 0.5;

/// copydetect's noise threshold: matches shorter than this many
/// characters of tokenized code are ignored (its default).
const NOISE: usize = 25;

/// copydetect's guarantee threshold: matches at least this long are
/// always found (the winnowing window is `GUARANTEE - NOISE + 1`).
const GUARANTEE: usize = 30;

/// How many pairs (besides the flagged ones) the console lists.
const LISTED: usize = 10;

/// How many pairs, from the first, the page shows passages of (the page
/// of a class of copies would otherwise hold every file many times over;
/// `similarity.json` holds every pair's matches).
const DETAILED: usize = 20;

/// Lines of context kept around a highlighted passage on the page.
const CONTEXT_LINES: usize = 2;

/// What `cargo xtask similarity` was asked.
pub struct Options {
    /// The class: a folder of checkouts.
    pub class: PathBuf,
    /// Where the page and the data go.
    pub out: PathBuf,
    /// The score from which a pair is flagged (0 to 1).
    pub threshold: f64,
    /// Only these topics' task files (names as for `grade`); all when empty.
    pub topics: Vec<String>,
}

/// The whole result, as `similarity.json` holds it.
#[derive(Debug, Serialize)]
pub struct Report {
    /// The class folder.
    pub class: PathBuf,
    /// `copydetect <version>`.
    pub engine: String,
    /// copydetect's noise and guarantee thresholds (characters of
    /// tokenized code).
    pub noise: usize,
    pub guarantee: usize,
    /// The score from which a pair is flagged.
    pub threshold: f64,
    /// The members' folder names, in order.
    pub members: Vec<String>,
    /// The task files compared (paths in a checkout).
    pub files: Vec<PathBuf>,
    /// Every pair of members, highest score first.
    pub pairs: Vec<Pair>,
}

/// Two members and how alike their task files are.
#[derive(Debug, Serialize)]
pub struct Pair {
    /// 1 for the highest score.
    pub rank: usize,
    /// The members' folder names.
    pub a: String,
    pub b: String,
    /// The larger of the two shares.
    pub score: f64,
    /// Per member, the share of its code (in the files both changed,
    /// stubs excluded) that matches the other's.
    pub shares: [f64; 2],
    /// Per member, its matched tokens and all its tokens in those files.
    pub matched: [u64; 2],
    pub tokens: [u64; 2],
    /// Whether the score is at or above the threshold.
    pub flagged: bool,
    /// The files with a match, most matched first.
    pub files: Vec<PairFile>,
}

/// One file of a pair with a match.
#[derive(Debug, Serialize)]
pub struct PairFile {
    pub path: PathBuf,
    /// Per member, the share of its code in this file that matches.
    pub shares: [f64; 2],
    /// Per member, the matching byte ranges `[start, end)` of its file.
    pub ranges: [Vec<[usize; 2]>; 2],
}

/// One member's changed task files: path → text (line ends `\n`).
type Texts = BTreeMap<PathBuf, String>;

/// `cargo xtask similarity`: compares, writes both files, prints the
/// leading pairs.
pub fn run(root: &Path, options: &Options) -> Result<()> {
    ensure!(
        (0.0..=1.0).contains(&options.threshold),
        "--threshold is a share between 0 and 1, not {}",
        options.threshold
    );
    let members = members(&options.class)?;
    ensure!(
        members.len() >= 2,
        "{} holds {} checkout(s); comparing needs at least two (a checkout is a folder with exercises/ and Cargo.toml)",
        options.class.display(),
        members.len()
    );
    let files = task_files(root, &options.topics)?;
    ensure!(
        !files.is_empty(),
        "the course at {} has no task files to compare",
        root.display()
    );
    let mut stubs = Texts::new();
    for file in &files {
        let stub = fs::read(root.join(file))
            .with_context(|| format!("cannot read {}", root.join(file).display()))?;
        stubs.insert(file.clone(), text(&stub));
    }
    let texts: Vec<Texts> = members
        .iter()
        .map(|(_, dir)| changed_files(dir, &stubs))
        .collect();
    let python = install(&stage::home(root).join("tools"))?;
    let names: Vec<String> = members.into_iter().map(|(name, _)| name).collect();
    println!(
        "==> comparing {} members' task files ({}, stubs excluded) with copydetect {COPYDETECT_VERSION}",
        names.len(),
        count(files.len(), "file")
    );
    let answer = detect(&python, &stubs, &texts)?;
    let report = rank(&options.class, names, files, options.threshold, &answer);
    fs::create_dir_all(&options.out)
        .with_context(|| format!("cannot create {}", options.out.display()))?;
    let json = options.out.join("similarity.json");
    fs::write(&json, serde_json::to_string_pretty(&report)?)
        .with_context(|| format!("cannot write {}", json.display()))?;
    let html = options.out.join("similarity.html");
    fs::write(&html, page(&report, &texts))
        .with_context(|| format!("cannot write {}", html.display()))?;
    print!("{}", table(&report));
    println!("wrote {} and {}", html.display(), json.display());
    Ok(())
}

/// The checkouts in `class` (folders with `exercises/` and `Cargo.toml`,
/// no links), by name.
fn members(class: &Path) -> Result<Vec<(String, PathBuf)>> {
    let is_checkout = |dir: &Path| {
        let linked = fs::symlink_metadata(dir).is_ok_and(|m| m.file_type().is_symlink());
        !linked && dir.join("exercises").is_dir() && dir.join("Cargo.toml").is_file()
    };
    if is_checkout(class) {
        bail!(
            "{} is one checkout; give the folder that holds the class's checkouts",
            class.display()
        );
    }
    let entries =
        fs::read_dir(class).with_context(|| format!("cannot read {}", class.display()))?;
    let mut members = Vec::new();
    for entry in entries {
        let entry = entry.with_context(|| format!("cannot read {}", class.display()))?;
        let name = entry.file_name().to_string_lossy().into_owned();
        if !name.starts_with('.') && is_checkout(&entry.path()) {
            members.push((name, entry.path()));
        }
    }
    members.sort();
    Ok(members)
}

/// The course's task files, of the `topics` named (all when empty).
fn task_files(root: &Path, wanted: &[String]) -> Result<Vec<PathBuf>> {
    let files = stage::task_files(root)?;
    if wanted.is_empty() {
        return Ok(files);
    }
    let chosen = topics::select(root, wanted)?;
    Ok(files
        .into_iter()
        .filter(|file| {
            chosen
                .iter()
                .any(|topic| file.starts_with(Path::new("exercises").join(&topic.name)))
        })
        .collect())
}

/// Bytes as text with `\n` line ends (a checkout made on Windows has
/// `\r\n`).
fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).replace("\r\n", "\n")
}

/// The task files of the checkout at `dir` that differ from their stub
/// (read as the grader reads them: plain files, bounded in size).
fn changed_files(dir: &Path, stubs: &Texts) -> Texts {
    stubs
        .iter()
        .filter_map(|(file, stub)| {
            let theirs = text(&crate::files::read_plain(dir, file)?);
            (theirs != *stub && !theirs.trim().is_empty()).then(|| (file.clone(), theirs))
        })
        .collect()
}

/// Every pair of members with its score, highest first.
fn rank(
    class: &Path,
    members: Vec<String>,
    files: Vec<PathBuf>,
    threshold: f64,
    answer: &Answer,
) -> Report {
    let share = |matched: u64, tokens: u64| {
        if tokens == 0 {
            0.0
        } else {
            (matched as f64 / tokens as f64).min(1.0)
        }
    };
    let mut pairs = Vec::new();
    for a in 0..members.len() {
        for b in a + 1..members.len() {
            let mut matched = [0_u64; 2];
            let mut tokens = [0_u64; 2];
            let mut pair_files = Vec::new();
            for file in &answer.files {
                let count = |m: usize| file.tokens.iter().find(|(i, _)| *i == m).map(|(_, t)| *t);
                let (Some(tokens_a), Some(tokens_b)) = (count(a), count(b)) else {
                    continue;
                };
                tokens[0] += tokens_a;
                tokens[1] += tokens_b;
                if let Some(found) = file.pairs.iter().find(|p| p.a == a && p.b == b) {
                    matched[0] += found.matched[0];
                    matched[1] += found.matched[1];
                    pair_files.push(PairFile {
                        path: PathBuf::from(&file.path),
                        shares: [
                            share(found.matched[0], tokens_a),
                            share(found.matched[1], tokens_b),
                        ],
                        ranges: found.ranges.clone(),
                    });
                }
            }
            pair_files.sort_by(|x, y| {
                let most = |f: &PairFile| f.shares[0].max(f.shares[1]);
                most(y)
                    .total_cmp(&most(x))
                    .then_with(|| x.path.cmp(&y.path))
            });
            let shares = [share(matched[0], tokens[0]), share(matched[1], tokens[1])];
            let score = shares[0].max(shares[1]);
            pairs.push(Pair {
                rank: 0,
                a: members[a].clone(),
                b: members[b].clone(),
                score,
                shares,
                matched,
                tokens,
                flagged: score > 0.0 && score >= threshold,
                files: pair_files,
            });
        }
    }
    pairs.sort_by(|x, y| {
        y.score
            .total_cmp(&x.score)
            .then_with(|| (&x.a, &x.b).cmp(&(&y.a, &y.b)))
    });
    for (i, pair) in pairs.iter_mut().enumerate() {
        pair.rank = i + 1;
    }
    Report {
        class: class.to_path_buf(),
        engine: format!("copydetect {COPYDETECT_VERSION}"),
        noise: NOISE,
        guarantee: GUARANTEE,
        threshold,
        members,
        files,
        pairs,
    }
}

/// The pairs the console lists: every flagged one, and the first
/// [`LISTED`] with any match.
fn listed(report: &Report) -> impl Iterator<Item = &Pair> {
    report
        .pairs
        .iter()
        .enumerate()
        .filter(|(i, p)| p.flagged || (*i < LISTED && p.score > 0.0))
        .map(|(_, p)| p)
}

/// The pairs whose passages the page shows: the first [`DETAILED`] with
/// any match.
fn detailed(report: &Report) -> impl Iterator<Item = &Pair> {
    report.pairs.iter().take(DETAILED).filter(|p| p.score > 0.0)
}

/// `n thing` or `n things`.
fn count(n: usize, thing: &str) -> String {
    format!("{n} {thing}{}", if n == 1 { "" } else { "s" })
}

fn percent(share: f64) -> String {
    format!("{:.0} %", share * 100.0)
}

/// The console's table of the leading pairs.
fn table(report: &Report) -> String {
    let flagged = report.pairs.iter().filter(|p| p.flagged).count();
    let mut out = format!(
        "{} of {} members; {flagged} at or above {}:\n",
        count(report.pairs.len(), "pair"),
        report.members.len(),
        percent(report.threshold)
    );
    let width = |f: &dyn Fn(&Pair) -> usize| listed(report).map(f).max().unwrap_or(0);
    let wa = width(&|p| p.a.chars().count()).max(1);
    let wb = width(&|p| p.b.chars().count()).max(1);
    let _ = writeln!(
        out,
        "  {:>4}  {:>5}  {:<wa$}  {:<wb$}  shares     files",
        "rank", "score", "a", "b"
    );
    for pair in listed(report) {
        let _ = writeln!(
            out,
            "  {:>4}  {:>5}  {:<wa$}  {:<wb$}  {:>4} {:>4}  {:>5}{}",
            pair.rank,
            percent(pair.score),
            pair.a,
            pair.b,
            percent(pair.shares[0]),
            percent(pair.shares[1]),
            pair.files.len(),
            if pair.flagged { "  FLAGGED" } else { "" }
        );
    }
    let rest = report.pairs.len() - listed(report).count();
    if rest > 0 {
        let _ = writeln!(out, "  ({rest} more pairs with lower scores)");
    }
    out
}
