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
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use anyhow::{Context, Result, bail, ensure};
use serde::{Deserialize, Serialize};

use crate::{setup, stage, topics};

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

/// The script run with the environment's Python: reads the request
/// (JSON) on stdin, writes per task file every member's token count and
/// every pair's matched tokens and byte ranges (JSON) on stdout.
const ENGINE_SCRIPT: &str = r#"
import io, itertools, json, sys
from copydetect import CodeFingerprint, compare_files
from copydetect.utils import (
    find_fingerprint_overlap, get_copied_slices, get_token_coverage, hashed_kgrams)
from pygments import lexers, token

request = json.load(sys.stdin)
k = request["noise"]
window = request["guarantee"] - k + 1


def fingerprint(name, text, window, boilerplate):
    fp = CodeFingerprint(name, k, window, fp=io.StringIO(text))
    if boilerplate:
        fp.hashes -= boilerplate
        for h in [h for h in fp.hash_idx if h in boilerplate]:
            del fp.hash_idx[h]
        fp.token_coverage = get_token_coverage(fp.hash_idx, k, len(fp.filtered_code))
    return fp


def spans(name, text, filtered):
    """For each character of the filtered code, the characters of `text`
    it stands for, as copydetect's filter_code makes it (its own offsets
    place a match before the comments and spaces that precede it)."""
    out = []
    at = len(text) - len(text.lstrip("\n"))  # Pygments drops leading newlines
    variables = {token.Name, token.Name.Variable, token.Name.Attribute}
    try:
        tokens = lexers.get_lexer_for_filename(name).get_tokens(text)
    except Exception:  # no lexer: copydetect compares the text as it is
        return None
    for kind, value in tokens:
        end = at + len(value)
        if (kind in variables or kind in token.Name.Function or kind in token.Name.Class
                or kind == token.Comment.Preproc or kind == token.Comment.Hashbang):
            out.append((at, end))
        elif kind in token.Text or kind in token.Comment:
            pass
        elif kind in token.Literal.String:
            out.append((at, end))
        else:
            out.extend([(at, end)] * len(value))  # a match covers whole tokens
        at = end
    return out if len(out) == len(filtered) else None


def given(filtered, boilerplate):
    """Which characters of the filtered code a k-gram of the stub covers."""
    mask = [False] * len(filtered)
    for i, h in enumerate(hashed_kgrams(filtered, k)):
        if h in boilerplate:
            mask[i : i + k] = [True] * k
    return mask


def byte_ranges(text, places, mask, slices, fallback):
    if places is None:
        chars = list(zip(fallback[0], fallback[1]))
    else:
        # A match that reaches into given code is shown without it.
        chars = []
        for s, e in zip(slices[0], slices[1]):
            run = None
            for i in range(int(s), int(e)):
                if mask[i]:
                    run = None
                elif run is None:
                    run = [places[i][0], places[i][1]]
                    chars.append(run)
                else:
                    run[1] = places[i][1]
    return [[len(text[: int(s)].encode()), len(text[: int(e)].encode())] for s, e in chars]


files = []
for file in request["files"]:
    name = file["path"]
    boilerplate = set(fingerprint(name, file["stub"], 1, None).hashes)
    prints = []
    for m, t in file["members"]:
        fp = fingerprint(name, t, window, boilerplate)
        places = spans(name, t, fp.filtered_code)
        prints.append((m, t, fp, places, given(fp.filtered_code, boilerplate)))
    pairs = []
    for (a, ta, fa, pa, ga), (b, tb, fb, pb, gb) in itertools.combinations(prints, 2):
        overlap, (share_a, share_b), (raw_a, raw_b) = compare_files(fa, fb)
        if overlap == 0:
            continue
        idx_a, idx_b = find_fingerprint_overlap(fa.hashes, fb.hashes, fa.hash_idx, fb.hash_idx)
        slices_a, slices_b = get_copied_slices(idx_a, k), get_copied_slices(idx_b, k)
        pairs.append({
            "a": a,
            "b": b,
            "matched": [
                round(float(share_a) * float(fa.token_coverage)),
                round(float(share_b) * float(fb.token_coverage)),
            ],
            "ranges": [
                byte_ranges(ta, pa, ga, slices_a, raw_a),
                byte_ranges(tb, pb, gb, slices_b, raw_b),
            ],
        })
    files.append({
        "path": name,
        "tokens": [[m, int(fp.token_coverage)] for m, _, fp, _, _ in prints],
        "pairs": pairs,
    })
json.dump({"files": files}, sys.stdout)
"#;

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

#[derive(Serialize)]
struct Request<'a> {
    noise: usize,
    guarantee: usize,
    files: Vec<RequestFile<'a>>,
}

#[derive(Serialize)]
struct RequestFile<'a> {
    path: String,
    stub: &'a str,
    /// (member index, text).
    members: Vec<(usize, &'a str)>,
}

#[derive(Deserialize)]
struct Answer {
    files: Vec<AnswerFile>,
}

#[derive(Deserialize)]
struct AnswerFile {
    path: String,
    /// (member index, tokens).
    tokens: Vec<(usize, u64)>,
    pairs: Vec<AnswerPair>,
}

#[derive(Deserialize)]
struct AnswerPair {
    a: usize,
    b: usize,
    matched: [u64; 2],
    ranges: [Vec<[usize; 2]>; 2],
}

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

/// The Python of copydetect's environment in `tools`, created and
/// installed there first when missing (once): `python3 -m venv`, then
/// `pip install copydetect==VERSION`.
fn install(tools: &Path) -> Result<PathBuf> {
    let venv = tools.join("copydetect");
    let python = if cfg!(windows) {
        venv.join("Scripts").join("python.exe")
    } else {
        venv.join("bin").join("python")
    };
    let marker = venv.join(format!("installed-copydetect-{COPYDETECT_VERSION}"));
    let installed = || marker.is_file() && python.is_file();
    if installed() {
        return Ok(python);
    }
    // One installation at a time; a run that waited finds it done.
    fs::create_dir_all(tools).with_context(|| format!("cannot create {}", tools.display()))?;
    let lock_path = tools.join("copydetect.lock");
    let lock = fs::File::create(&lock_path)
        .with_context(|| format!("cannot create {}", lock_path.display()))?;
    lock.lock()
        .with_context(|| format!("cannot lock {}", lock_path.display()))?;
    if installed() {
        return Ok(python);
    }
    let system = if cfg!(windows) { "python" } else { "python3" };
    let runs = |program: &str| {
        Command::new(program)
            .arg("--version")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status()
            .is_ok_and(|s| s.success())
    };
    if !runs(system) {
        setup::apt_install(
            &["python3", "python3-venv"],
            "Python, which runs copydetect",
            "the similarity engine, copydetect, needs Python 3",
        );
        ensure!(
            runs(system),
            "the similarity engine, copydetect, runs on Python 3, and `{system}` is not on the PATH; \
             install Python 3 (Debian/Ubuntu: `apt-get install python3 python3-venv`)"
        );
    }
    println!(
        "==> installing copydetect {COPYDETECT_VERSION}, the similarity engine (once): \
         {system} -m venv {} && pip install copydetect=={COPYDETECT_VERSION}",
        venv.display()
    );
    if venv.exists() {
        fs::remove_dir_all(&venv).with_context(|| format!("cannot remove {}", venv.display()))?;
    }
    let make_venv = || {
        Command::new(system)
            .args(["-m", "venv"])
            .arg(&venv)
            .stdin(Stdio::null())
            .status()
            .is_ok_and(|s| s.success())
    };
    if !make_venv() {
        // Debian and Ubuntu ship venv's pip bootstrap separately.
        let _ = fs::remove_dir_all(&venv);
        setup::apt_install(
            &["python3-venv"],
            "Python's venv, for copydetect's environment",
            "copydetect is installed into a Python virtual environment, and venv is missing",
        );
        ensure!(
            make_venv(),
            "cannot create a Python virtual environment in {} (Debian/Ubuntu: `apt-get install python3-venv`)",
            venv.display()
        );
    }
    let status = Command::new(&python)
        .args([
            "-m",
            "pip",
            "install",
            "--quiet",
            "--disable-pip-version-check",
        ])
        .arg(format!("copydetect=={COPYDETECT_VERSION}"))
        .stdin(Stdio::null())
        .status()
        .context("cannot run pip in copydetect's environment")?;
    ensure!(
        status.success(),
        "`pip install copydetect=={COPYDETECT_VERSION}` failed: it needs PyPI (set HTTPS_PROXY behind a proxy, \
         or PIP_INDEX_URL for a mirror)"
    );
    fs::write(&marker, "").with_context(|| format!("cannot write {}", marker.display()))?;
    Ok(python)
}

/// Runs the engine on the members' `texts` against the `stubs`.
fn detect(python: &Path, stubs: &Texts, texts: &[Texts]) -> Result<Answer> {
    let request = Request {
        noise: NOISE,
        guarantee: GUARANTEE,
        files: stubs
            .iter()
            .map(|(path, stub)| RequestFile {
                path: path.to_string_lossy().replace('\\', "/"),
                stub,
                members: texts
                    .iter()
                    .enumerate()
                    .filter_map(|(i, files)| files.get(path).map(|t| (i, t.as_str())))
                    .collect(),
            })
            .filter(|file| file.members.len() >= 2)
            .collect(),
    };
    let input = serde_json::to_vec(&request)?;
    let cache = python
        .parent()
        .and_then(Path::parent)
        .map_or_else(|| PathBuf::from("."), |venv| venv.join("matplotlib"));
    let mut child = Command::new(python)
        .arg("-c")
        .arg(ENGINE_SCRIPT)
        // Python's string hashes are the fingerprints: a fixed seed makes
        // the winnowing, and so the scores, the same on every run.
        .env("PYTHONHASHSEED", "0")
        .env("PYTHONIOENCODING", "utf-8")
        .env("MPLBACKEND", "Agg")
        .env("MPLCONFIGDIR", cache)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .with_context(|| format!("cannot run {}", python.display()))?;
    let mut stdin = child.stdin.take().context("the engine's stdin")?;
    let writer = std::thread::spawn(move || stdin.write_all(&input));
    let output = child
        .wait_with_output()
        .context("cannot wait for copydetect")?;
    let written = writer.join();
    ensure!(
        output.status.success(),
        "copydetect failed: {}",
        String::from_utf8_lossy(&output.stderr).trim()
    );
    if let Ok(Err(error)) = written {
        bail!("cannot hand the files to copydetect: {error}");
    }
    serde_json::from_slice(&output.stdout).context("cannot read copydetect's answer")
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

/// Escapes text for HTML element content and attribute values.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// Styles for the page: those of the grade report, with two code
/// columns and highlighted matches.
const STYLE: &str = "body{font-family:system-ui,sans-serif;margin:2em;max-width:110em}\
table{border-collapse:collapse;margin:.5em 0}td,th{padding:.25em .75em;text-align:left;\
border-bottom:1px solid #8884}td.num{text-align:right}.ok{color:#197a32}.fail{color:#b3261e}\
.flag{color:#b3261e;font-weight:600}small{color:#888}\
.sides{display:grid;grid-template-columns:1fr 1fr;gap:1em;margin:.5em 0 1.5em}.sides>div{min-width:0}\
.sides h4{margin:.25em 0;font-weight:600}\
pre{background:#8881;padding:.75em;overflow-x:auto;margin:0;font-size:.85em;line-height:1.35}\
pre .n{display:inline-block;width:3.5em;color:#888;user-select:none}\
pre .gap{color:#888;font-style:italic}\
mark{background:#f4c43066;color:inherit;border-radius:2px}";

/// The whole page.
fn page(report: &Report, texts: &[Texts]) -> String {
    let mut html = String::new();
    let class = report.class.file_name().map_or_else(
        || report.class.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let flagged = report.pairs.iter().filter(|p| p.flagged).count();
    let _ = writeln!(
        html,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <title>Similarity: {class}</title><style>{STYLE}</style></head><body>\n\
         <h1>Similarity: {class}</h1>\n\
         <p>{members} members, {pairs}, {files} compared with {engine} \
         (winnowing over tokens; names, comments and layout ignored; the course's stubs excluded). \
         A pair's score is the larger of the two shares: the part of a member's own code that \
         matches the other's. <span class=\"{class_flag}\">{flagged} at or above {threshold}</span>.</p>",
        class = escape(&class),
        members = report.members.len(),
        pairs = count(report.pairs.len(), "pair"),
        files = count(report.files.len(), "task file"),
        engine = escape(&report.engine),
        class_flag = if flagged > 0 { "flag" } else { "ok" },
        flagged = count(flagged, "pair"),
        threshold = percent(report.threshold),
    );
    html.push_str(
        "<table><tr><th>rank</th><th>members</th><th>score</th><th>shares</th>\
         <th>files alike</th><th></th></tr>\n",
    );
    let ranks: Vec<usize> = detailed(report).map(|p| p.rank).collect();
    for pair in &report.pairs {
        let names = format!("{} ↔ {}", escape(&pair.a), escape(&pair.b));
        let names = if ranks.contains(&pair.rank) {
            format!("<a href=\"#pair-{}\">{names}</a>", pair.rank)
        } else {
            names
        };
        let _ = writeln!(
            html,
            "<tr><td class=\"num\">{}</td><td>{names}</td><td class=\"num\">{}</td>\
             <td class=\"num\">{} / {}</td><td class=\"num\">{}</td><td>{}</td></tr>",
            pair.rank,
            percent(pair.score),
            percent(pair.shares[0]),
            percent(pair.shares[1]),
            pair.files.len(),
            if pair.flagged {
                "<span class=\"flag\">flagged</span>"
            } else {
                ""
            }
        );
    }
    html.push_str("</table>\n");
    if report.pairs.iter().filter(|p| p.score > 0.0).count() > ranks.len() {
        let _ = writeln!(
            html,
            "<p>The passages of the first {DETAILED} pairs follow; <code>similarity.json</code> \
             holds every pair's matches.</p>"
        );
    }
    let index = |name: &str| report.members.iter().position(|m| m == name);
    for pair in detailed(report) {
        let _ = writeln!(
            html,
            "<h2 id=\"pair-{rank}\">{rank}. {a} ↔ {b}: {score}{flag}</h2>\n\
             <p>{a}: {sa} of its code ({ma} of {ta} tokens) matches; {b}: {sb} ({mb} of {tb}).</p>",
            rank = pair.rank,
            a = escape(&pair.a),
            b = escape(&pair.b),
            score = percent(pair.score),
            flag = if pair.flagged {
                " <span class=\"flag\">flagged</span>"
            } else {
                ""
            },
            sa = percent(pair.shares[0]),
            sb = percent(pair.shares[1]),
            ma = pair.matched[0],
            ta = pair.tokens[0],
            mb = pair.matched[1],
            tb = pair.tokens[1],
        );
        let (Some(ia), Some(ib)) = (index(&pair.a), index(&pair.b)) else {
            continue;
        };
        for file in &pair.files {
            let _ = writeln!(
                html,
                "<h3><code>{}</code> <small>{} / {}</small></h3>\n<div class=\"sides\">",
                escape(&file.path.display().to_string()),
                percent(file.shares[0]),
                percent(file.shares[1]),
            );
            for (side, (member, name)) in [(ia, &pair.a), (ib, &pair.b)].into_iter().enumerate() {
                let text = texts[member].get(&file.path).map_or("", String::as_str);
                let _ = writeln!(
                    html,
                    "<div><h4>{}</h4>{}</div>",
                    escape(name),
                    passages(text, &file.ranges[side])
                );
            }
            html.push_str("</div>\n");
        }
    }
    html.push_str("</body></html>\n");
    html
}

/// `text` as a `<pre>` with line numbers, the byte `ranges` highlighted,
/// and only the lines near a highlight kept (the others are counted).
fn passages(text: &str, ranges: &[[usize; 2]]) -> String {
    // Ranges on char boundaries, sorted, within the text.
    let fix = |mut i: usize| {
        i = i.min(text.len());
        while !text.is_char_boundary(i) {
            i -= 1;
        }
        i
    };
    let mut ranges: Vec<(usize, usize)> = ranges
        .iter()
        .map(|[s, e]| (fix(*s), fix(*e)))
        .filter(|(s, e)| s < e)
        .collect();
    ranges.sort_unstable();
    let mut lines = Vec::new();
    let mut start = 0;
    for line in text.split_inclusive('\n') {
        lines.push((start, start + line.trim_end_matches('\n').len()));
        start += line.len();
    }
    let marked: Vec<bool> = lines
        .iter()
        .map(|&(s, e)| ranges.iter().any(|&(rs, re)| rs < e.max(s + 1) && re > s))
        .collect();
    let keep: Vec<bool> = (0..lines.len())
        .map(|i| {
            let from = i.saturating_sub(CONTEXT_LINES);
            let to = (i + CONTEXT_LINES + 1).min(lines.len());
            marked[from..to].iter().any(|&m| m)
        })
        .collect();
    let mut html = String::from("<pre>");
    let mut skipped = 0;
    let gap = |html: &mut String, skipped: &mut usize| {
        if *skipped > 0 {
            let _ = writeln!(
                html,
                "<span class=\"gap\">   ⋯ {} line{} without a match</span>",
                skipped,
                if *skipped == 1 { "" } else { "s" }
            );
            *skipped = 0;
        }
    };
    for (i, &(s, e)) in lines.iter().enumerate() {
        if !keep[i] {
            skipped += 1;
            continue;
        }
        gap(&mut html, &mut skipped);
        let _ = write!(html, "<span class=\"n\">{}</span>", i + 1);
        let mut at = s;
        for &(rs, re) in &ranges {
            let (rs, re) = (rs.max(s), re.min(e));
            if rs >= re || re <= at {
                continue;
            }
            let rs = rs.max(at);
            html.push_str(&escape(&text[at..rs]));
            let _ = write!(html, "<mark>{}</mark>", escape(&text[rs..re]));
            at = re;
        }
        html.push_str(&escape(&text[at..e]));
        html.push('\n');
    }
    gap(&mut html, &mut skipped);
    html.push_str("</pre>");
    html
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn passages_highlight_ranges_and_fold_lines_far_from_them() {
        let text: String = (1..=12).map(|i| format!("line {i} <x>\n")).collect();
        let start = text.find("line 6").unwrap();
        let html = passages(&text, &[[start, start + 6]]);
        assert!(html.contains("<mark>line 6</mark> &lt;x&gt;"), "{html}");
        assert!(html.contains("⋯ 3 lines without a match"), "{html}");
        assert!(html.contains("⋯ 4 lines without a match"), "{html}");
        assert!(!html.contains("line 3 "), "{html}");
        assert!(html.contains("line 4 "), "{html}");
    }

    #[test]
    fn a_range_across_lines_is_highlighted_on_each() {
        let text = "fn a() {\n    b();\n}\n";
        let html = passages(text, &[[3, 15]]);
        assert!(html.contains("fn <mark>a() {</mark>"), "{html}");
        assert!(html.contains("<mark>    b(</mark>);"), "{html}");
    }

    #[test]
    fn escape_covers_markup_and_quotes() {
        assert_eq!(
            escape("<a href=\"x\">&'"),
            "&lt;a href=&quot;x&quot;&gt;&amp;&#39;"
        );
    }
}
