//! `cargo xtask similarity`: on a generated class, a pair that copied
//! (names changed, functions reordered, comments added) is flagged and
//! ranks above a pair that wrote the same textbook algorithm each on
//! their own; the given code, the same for everyone, never counts.
//!
//! The engine (copydetect, from PyPI) is installed on the first run into
//! the fake course's tools folder, which later runs keep.

mod common;

use std::fs;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard};

use serde_json::Value;

/// The given part of the task file `a.rs`: the same in every checkout.
const GIVEN: &str = r#"//! Topic 01: lines and circles on a small canvas.

/// A pixel position.
pub type Point = (i32, i32);

/// A canvas of `width × height` cells, row by row.
pub struct Canvas {
    pub width: usize,
    pub height: usize,
    pub cells: Vec<bool>,
}

impl Canvas {
    /// An empty canvas.
    pub fn new(width: usize, height: usize) -> Self {
        Self {
            width,
            height,
            cells: vec![false; width * height],
        }
    }

    /// Sets the cell at `p` when it lies on the canvas.
    pub fn set(&mut self, p: Point) {
        if p.0 >= 0 && p.1 >= 0 && (p.0 as usize) < self.width && (p.1 as usize) < self.height {
            let index = p.1 as usize * self.width + p.0 as usize;
            self.cells[index] = true;
        }
    }

    /// The canvas as text: `#` for a set cell, `.` otherwise.
    pub fn to_text(&self) -> String {
        let mut text = String::new();
        for row in self.cells.chunks(self.width) {
            for &cell in row {
                text.push(if cell { '#' } else { '.' });
            }
            text.push('\n');
        }
        text
    }
}

"#;

/// The tasks of `a.rs` as handed out.
const TASKS: &str = r#"/// Task `line`: the pixels of the line from `from` to `to`, both
/// included, in order from `from` to `to`.
pub fn line(from: Point, to: Point) -> Vec<Point> {
    todo!("line: the midpoint line from {from:?} to {to:?}")
}

/// Task `circle`: the pixels of the circle of `radius` around `center`,
/// each once, in any order.
pub fn circle(center: Point, radius: i32) -> Vec<Point> {
    todo!("circle: the midpoint circle of radius {radius} around {center:?}")
}
"#;

/// A second task file, long and given in full but for one `todo!`, that
/// no member touches: an unchanged stub holds nothing of a member's.
const UNTOUCHED: &str = r#"//! Topic 01: spans.

use crate::a::Point;

/// A horizontal run of cells on row `y`, from `x0` to `x1` included.
pub struct Span {
    pub y: i32,
    pub x0: i32,
    pub x1: i32,
}

impl Span {
    /// The span's cells, left to right.
    pub fn cells(&self) -> Vec<Point> {
        (self.x0.min(self.x1)..=self.x0.max(self.x1))
            .map(|x| (x, self.y))
            .collect()
    }

    /// Its length in cells.
    pub fn len(&self) -> usize {
        (self.x1 - self.x0).unsigned_abs() as usize + 1
    }
}

/// Task `spans`: the spans that fill the triangle `a b c`.
pub fn spans(a: Point, b: Point, c: Point) -> Vec<Span> {
    todo!("spans of {a:?} {b:?} {c:?}")
}
"#;

/// The original: Bresenham's all-octant line in its error-term form and
/// the midpoint circle with an eight-way mirror.
const ADA: &str = r#"/// Task `line`: the pixels of the line from `from` to `to`, both
/// included, in order from `from` to `to`.
pub fn line(from: Point, to: Point) -> Vec<Point> {
    let (mut x, mut y) = from;
    let dx = (to.0 - x).abs();
    let dy = -(to.1 - y).abs();
    let step_x = if x < to.0 { 1 } else { -1 };
    let step_y = if y < to.1 { 1 } else { -1 };
    let mut error = dx + dy;
    let mut pixels = Vec::with_capacity((dx - dy + 1) as usize);
    loop {
        pixels.push((x, y));
        if x == to.0 && y == to.1 {
            break;
        }
        let twice = 2 * error;
        if twice >= dy {
            error += dy;
            x += step_x;
        }
        if twice <= dx {
            error += dx;
            y += step_y;
        }
    }
    pixels
}

/// The eight mirror images of `(x, y)` around `center`.
fn mirror(center: Point, x: i32, y: i32, out: &mut Vec<Point>) {
    for (a, b) in [(x, y), (y, x), (-x, y), (-y, x), (x, -y), (y, -x), (-x, -y), (-y, -x)] {
        let p = (center.0 + a, center.1 + b);
        if !out.contains(&p) {
            out.push(p);
        }
    }
}

/// Task `circle`: the pixels of the circle of `radius` around `center`,
/// each once, in any order.
pub fn circle(center: Point, radius: i32) -> Vec<Point> {
    let mut out = Vec::new();
    if radius < 0 {
        return out;
    }
    let mut x = radius;
    let mut y = 0;
    let mut decision = 1 - radius;
    while y <= x {
        mirror(center, x, y, &mut out);
        y += 1;
        if decision < 0 {
            decision += 2 * y + 1;
        } else {
            x -= 1;
            decision += 2 * (y - x) + 1;
        }
    }
    out
}
"#;

/// ADA's code with every name changed, the functions in another order
/// and comments added.
const BEN: &str = r#"/// Task `circle`: the pixels of the circle of `radius` around `center`,
/// each once, in any order.
pub fn circle(c: Point, r: i32) -> Vec<Point> {
    let mut result = Vec::new();
    if r < 0 {
        return result;
    }
    let mut px = r;
    let mut py = 0;
    let mut d = 1 - r;
    // walk one octant and mirror it
    while py <= px {
        reflect(c, px, py, &mut result);
        py += 1;
        if d < 0 {
            d += 2 * py + 1;
        } else {
            px -= 1;
            d += 2 * (py - px) + 1;
        }
    }
    result
}

/// Task `line`: the pixels of the line from `from` to `to`, both
/// included, in order from `from` to `to`.
pub fn line(start: Point, end: Point) -> Vec<Point> {
    let (mut cx, mut cy) = start;
    let w = (end.0 - cx).abs();
    let h = -(end.1 - cy).abs();
    let sx = if cx < end.0 { 1 } else { -1 };
    let sy = if cy < end.1 { 1 } else { -1 };
    let mut err = w + h;
    let mut points = Vec::with_capacity((w - h + 1) as usize);
    loop {
        points.push((cx, cy));
        if cx == end.0 && cy == end.1 {
            break;
        }
        let e2 = 2 * err;
        if e2 >= h {
            err += h;
            cx += sx;
        }
        if e2 <= w {
            err += w;
            cy += sy;
        }
    }
    points
}

// symmetric points in all 8 octants
fn reflect(c: Point, px: i32, py: i32, result: &mut Vec<Point>) {
    for (u, v) in [(px, py), (py, px), (-px, py), (-py, px), (px, -py), (py, -px), (-px, -py), (-py, -px)] {
        let q = (c.0 + u, c.1 + v);
        if !result.contains(&q) {
            result.push(q);
        }
    }
}
"#;

/// The textbook midpoint line (steep swap, one loop over x) and a
/// brute-force ring.
const CAI: &str = r#"/// Task `line`: the pixels of the line from `from` to `to`, both
/// included, in order from `from` to `to`.
pub fn line(from: Point, to: Point) -> Vec<Point> {
    let steep = (to.1 - from.1).abs() > (to.0 - from.0).abs();
    let (mut x0, mut y0, mut x1, mut y1) = if steep {
        (from.1, from.0, to.1, to.0)
    } else {
        (from.0, from.1, to.0, to.1)
    };
    let reversed = x0 > x1;
    if reversed {
        std::mem::swap(&mut x0, &mut x1);
        std::mem::swap(&mut y0, &mut y1);
    }
    let dx = x1 - x0;
    let dy = (y1 - y0).abs();
    let ystep = if y0 < y1 { 1 } else { -1 };
    let mut d = 2 * dy - dx;
    let mut y = y0;
    let mut result = Vec::new();
    for x in x0..=x1 {
        result.push(if steep { (y, x) } else { (x, y) });
        if d > 0 {
            y += ystep;
            d -= 2 * dx;
        }
        d += 2 * dy;
    }
    if reversed {
        result.reverse();
    }
    result
}

/// Task `circle`: the pixels of the circle of `radius` around `center`,
/// each once, in any order.
pub fn circle(center: Point, radius: i32) -> Vec<Point> {
    let mut ring = Vec::new();
    let inner = (radius - 1) * (radius - 1) + (radius - 1);
    let outer = radius * radius + radius;
    for dy in -radius..=radius {
        for dx in -radius..=radius {
            let r2 = dx * dx + dy * dy;
            if r2 > inner && r2 <= outer {
                ring.push((center.0 + dx, center.1 + dy));
            }
        }
    }
    ring
}
"#;

/// The textbook midpoint line again, written apart from CAI's: a branch
/// per major axis and a `while` loop; a circle from angles.
const DEE: &str = r#"/// Task `line`: the pixels of the line from `from` to `to`, both
/// included, in order from `from` to `to`.
pub fn line(from: Point, to: Point) -> Vec<Point> {
    let dx = (to.0 - from.0).abs();
    let dy = (to.1 - from.1).abs();
    let sx = if from.0 < to.0 { 1 } else { -1 };
    let sy = if from.1 < to.1 { 1 } else { -1 };
    let mut out = vec![from];
    let (mut x, mut y) = from;
    if dx >= dy {
        let mut decision = 2 * dy - dx;
        while x != to.0 {
            x += sx;
            if decision > 0 {
                y += sy;
                decision += 2 * (dy - dx);
            } else {
                decision += 2 * dy;
            }
            out.push((x, y));
        }
    } else {
        let mut decision = 2 * dx - dy;
        while y != to.1 {
            y += sy;
            if decision > 0 {
                x += sx;
                decision += 2 * (dx - dy);
            } else {
                decision += 2 * dx;
            }
            out.push((x, y));
        }
    }
    out
}

/// Task `circle`: the pixels of the circle of `radius` around `center`,
/// each once, in any order.
pub fn circle(center: Point, radius: i32) -> Vec<Point> {
    let steps = (8 * radius.max(1)) as usize;
    let mut seen = std::collections::BTreeSet::new();
    for i in 0..steps {
        let angle = i as f64 / steps as f64 * std::f64::consts::TAU;
        let px = center.0 + (radius as f64 * angle.cos()).round() as i32;
        let py = center.1 + (radius as f64 * angle.sin()).round() as i32;
        seen.insert((px, py));
    }
    seen.into_iter().collect()
}
"#;

/// A float DDA line and a circle from square roots.
const EVE: &str = r#"/// Task `line`: the pixels of the line from `from` to `to`, both
/// included, in order from `from` to `to`.
pub fn line(from: Point, to: Point) -> Vec<Point> {
    let n = (to.0 - from.0).abs().max((to.1 - from.1).abs());
    if n == 0 {
        return vec![from];
    }
    let step = |a: i32, b: i32| (b - a) as f64 / n as f64;
    let (ix, iy) = (step(from.0, to.0), step(from.1, to.1));
    (0..=n)
        .map(|i| {
            let t = i as f64;
            (
                (from.0 as f64 + ix * t).round() as i32,
                (from.1 as f64 + iy * t).round() as i32,
            )
        })
        .collect()
}

/// Task `circle`: the pixels of the circle of `radius` around `center`,
/// each once, in any order.
pub fn circle(center: Point, radius: i32) -> Vec<Point> {
    let mut cells: Vec<Point> = Vec::new();
    let r = f64::from(radius);
    for col in -radius..=radius {
        let h = (r * r - f64::from(col * col)).max(0.0).sqrt().round() as i32;
        for row in [h, -h] {
            let cell = (center.0 + col, center.1 + row);
            if !cells.contains(&cell) {
                cells.push(cell);
            }
        }
    }
    for row in -radius..=radius {
        let w = (r * r - f64::from(row * row)).max(0.0).sqrt().round() as i32;
        for col in [w, -w] {
            let cell = (center.0 + col, center.1 + row);
            if !cells.contains(&cell) {
                cells.push(cell);
            }
        }
    }
    cells
}
"#;

/// The members: folder name and their `a.rs` solutions.
const MEMBERS: [(&str, &str); 5] = [
    ("s01-ada", ADA),
    ("s02-ben", BEN),
    ("s03-cai", CAI),
    ("s04-dee", DEE),
    ("s05-eve", EVE),
];

/// Writes a checkout of the fake course into `dir`, with `a.rs` as given.
fn checkout(dir: &Path, a: &str) {
    let write = |file: &str, text: &str| {
        let path = dir.join(file);
        fs::create_dir_all(path.parent().unwrap()).unwrap();
        fs::write(path, text).unwrap();
    };
    write("Cargo.toml", "[workspace]\nmembers = [\"exercises/*\"]\n");
    write(
        "exercises/01-x/Cargo.toml",
        "[package]\nname = \"x\"\nversion = \"0.1.0\"\nedition = \"2024\"\n",
    );
    write(
        "exercises/01-x/tasks.toml",
        "[[tasks]]\nid = \"line\"\ntitle = \"Line\"\npoints = 1\n\n\
         [[tasks]]\nid = \"circle\"\ntitle = \"Circle\"\npoints = 1\n\n\
         [[tasks]]\nid = \"spans\"\ntitle = \"Spans\"\npoints = 1\n",
    );
    write("exercises/01-x/src/lib.rs", "pub mod a;\npub mod b;\n");
    write("exercises/01-x/src/a.rs", a);
    write("exercises/01-x/src/b.rs", UNTOUCHED);
}

/// Whether this run wrote the fake course already. The tests of this file
/// run at once and share the course: the first writes it and holds this
/// while it runs (its run installs the engine), the others wait for it,
/// so that none reads a file another is writing or an engine half
/// installed.
static COURSE_WRITTEN: Mutex<bool> = Mutex::new(false);

/// The fake course (kept between runs, with the engine in its tools
/// folder) and a fresh class of [`MEMBERS`]; for the first test of the
/// run, the lock to hold while it runs (see [`COURSE_WRITTEN`]).
fn course_and_class(case: &str) -> (PathBuf, PathBuf, Option<MutexGuard<'static, bool>>) {
    let scratch = Path::new(env!("CARGO_TARGET_TMPDIR"));
    let course = scratch.join("similarity-course");
    let mut written = COURSE_WRITTEN
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    let first = if *written {
        None
    } else {
        checkout(&course, &format!("{GIVEN}{TASKS}"));
        *written = true;
        Some(written)
    };
    let class = scratch.join(format!("similarity-class-{case}"));
    if class.exists() {
        fs::remove_dir_all(&class).unwrap();
    }
    for (name, solution) in MEMBERS {
        checkout(&class.join(name), &format!("{GIVEN}{solution}"));
    }
    (course, class, first)
}

fn pair<'a>(report: &'a Value, a: &str, b: &str) -> &'a Value {
    report["pairs"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["a"] == a && p["b"] == b)
        .unwrap_or_else(|| panic!("no pair {a} {b} in {report:#}"))
}

#[test]
fn a_copied_pair_is_flagged_and_ranks_above_an_accidental_one() {
    let (course, class, _first) = course_and_class("ranking");
    let out = class.join("similarity");
    let output = common::xtask(
        &course,
        &[
            "similarity",
            class.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ],
    );
    assert!(output.status.success(), "similarity must run: {output:?}");
    let report = common::read_json(&out.join("similarity.json"));
    assert_eq!(report["pairs"].as_array().unwrap().len(), 10, "{report:#}");

    let copied = pair(&report, "s01-ada", "s02-ben");
    let accidental = pair(&report, "s03-cai", "s04-dee");
    assert_eq!(copied["rank"], 1, "the copied pair ranks first: {report:#}");
    assert_eq!(copied["flagged"], true, "{copied:#}");
    let score = |p: &Value| p["score"].as_f64().unwrap();
    assert!(
        score(copied) > 0.9,
        "a copy matches almost wholly: {copied:#}"
    );
    assert!(
        score(accidental) < score(copied) - 0.5,
        "the accidental pair is far below the copied one: {accidental:#}"
    );
    // Only the copy is flagged: the given code counts for no pair.
    let flagged: Vec<(&str, &str)> = report["pairs"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|p| p["flagged"] == true)
        .map(|p| (p["a"].as_str().unwrap(), p["b"].as_str().unwrap()))
        .collect();
    assert_eq!(flagged, [("s01-ada", "s02-ben")], "{report:#}");
    for p in report["pairs"].as_array().unwrap() {
        if p["a"] != "s01-ada" || p["b"] != "s02-ben" {
            assert!(score(p) < 0.35, "an independent pair scores low: {p:#}");
        }
        // The untouched stub b.rs is in no pair's files.
        for file in p["files"].as_array().unwrap() {
            assert_eq!(file["path"], "exercises/01-x/src/a.rs", "{p:#}");
        }
    }
    // The matches are where the solutions are, never in the given code.
    let given = GIVEN.len();
    for range in copied["files"][0]["ranges"][0].as_array().unwrap() {
        let start = range[0].as_u64().unwrap() as usize;
        assert!(start >= given, "a match in the given code: {range}");
    }

    let html = fs::read_to_string(out.join("similarity.html")).unwrap();
    assert!(html.contains("s01-ada ↔ s02-ben"), "{html}");
    assert!(html.contains("<mark>"), "{html}");
    let stdout = common::stdout(&output);
    assert!(stdout.contains("FLAGGED"), "{stdout}");
}

#[test]
fn the_threshold_decides_what_is_flagged() {
    let (course, class, _first) = course_and_class("threshold");
    let out = class.join("similarity");
    let output = common::xtask(
        &course,
        &[
            "similarity",
            class.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--threshold",
            "0.99",
            "--topics",
            "x",
        ],
    );
    assert!(output.status.success(), "similarity must run: {output:?}");
    let report = common::read_json(&out.join("similarity.json"));
    assert_eq!(report["threshold"], 0.99);
    assert!(
        report["pairs"]
            .as_array()
            .unwrap()
            .iter()
            .all(|p| p["flagged"] == false),
        "{report:#}"
    );
}

#[test]
fn one_checkout_is_no_class() {
    let (course, class, _first) = course_and_class("one");
    let output = common::xtask(
        &course,
        &["similarity", class.join("s01-ada").to_str().unwrap()],
    );
    assert!(!output.status.success());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("is one checkout"), "{stderr}");
}
