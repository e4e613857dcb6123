//! The engine's side: copydetect installed into a private Python
//! environment, and the script that compares a class's files with it.

use std::fs;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use anyhow::{Context, Result, bail, ensure};
use serde::{Deserialize, Serialize};

use super::{COPYDETECT_VERSION, GUARANTEE, NOISE, Texts};
use crate::setup;

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
pub(super) struct Answer {
    pub(super) files: Vec<AnswerFile>,
}

#[derive(Deserialize)]
pub(super) struct AnswerFile {
    pub(super) path: String,
    /// (member index, tokens).
    pub(super) tokens: Vec<(usize, u64)>,
    pub(super) pairs: Vec<AnswerPair>,
}

#[derive(Deserialize)]
pub(super) struct AnswerPair {
    pub(super) a: usize,
    pub(super) b: usize,
    pub(super) matched: [u64; 2],
    pub(super) ranges: [Vec<[usize; 2]>; 2],
}

/// The Python of copydetect's environment in `tools`, created and
/// installed there first when missing (once): `python3 -m venv`, then
/// `pip install copydetect==VERSION`.
pub(super) fn install(tools: &Path) -> Result<PathBuf> {
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
pub(super) fn detect(python: &Path, stubs: &Texts, texts: &[Texts]) -> Result<Answer> {
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
