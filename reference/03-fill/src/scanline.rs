//! Scanline polygon fill with an active edge table, after the lecture
//! slides (seed 002, §5.4 "Füllen von (beliebigen) Polygonen").
//!
//! Convention (see `canvas`): pixel centres at integers, y up. A pixel is
//! filled when its centre is inside the polygon by the even-odd rule; a
//! centre exactly on a crossing belongs to the span starting there (left
//! ends included, right ends excluded, as for `rectangle`).

use std::ops::ControlFlow;

use canvas::{Pixel, Span, Vec2, Viewport};

/// Where the edge from `a` to `b` crosses the row `y`, for an edge with
/// `a.y ≠ b.y`: with `lo` the endpoint of smaller `y` and `hi` the other,
///
/// ```text
///   s = lo.x + ((y − lo.y) · (hi.x − lo.x)) / (hi.y − lo.y)      in f64
/// ```
///
/// evaluated in exactly this order, so that an edge gives the same `s`
/// whichever way round it is given (and the tests can reproduce it bit
/// for bit).
#[must_use]
pub fn crossing(a: Vec2, b: Vec2, y: i32) -> f64 {
    let (lo, hi) = if a.y < b.y { (a, b) } else { (b, a) };
    let (lo_x, lo_y) = (f64::from(lo.x), f64::from(lo.y));
    let (hi_x, hi_y) = (f64::from(hi.x), f64::from(hi.y));
    lo_x + ((f64::from(y) - lo_y) * (hi_x - lo_x)) / (hi_y - lo_y)
}

/// Fills the closed polygon through `vertices` (an edge also joins the last
/// vertex to the first) with the even-odd rule and calls `span` once per
/// run of filled pixels inside `viewport`: rows bottom to top, the runs of
/// a row left to right, never empty, never overlapping. Before the spans
/// of a row, `table(y, active)` reports the active edge table of that row
/// (see below); rows with no active edge are skipped and not reported.
/// When `table` answers [`ControlFlow::Break`], the fill ends there, before
/// that row's spans: a caller that needs only the lowest rows (a hit test,
/// a renderer whose window shows part of the shape) stops the walk, and
/// the rows above cost nothing.
///
/// **Crossings.** Row `y` (through the pixel centres) meets edge `a–b` when
/// `min(a.y, b.y) ≤ y < max(a.y, b.y)`: the lower end counts, the upper end
/// does not. So a vertex on the row counts once where the outline passes
/// through it and twice or not at all at a peak or a valley, and horizontal
/// edges never count (the slides: "horizontale Kanten werden ignoriert").
/// Every row then meets an even number of edges, at `s` = [`crossing`].
///
/// **Spans.** Sort the crossings of a row, `s1 ≤ s2 ≤ … ≤ s2k`, and fill each
/// pair `[s1, s2)`, `[s3, s4)`, … : the pixels `x` with `s1 ≤ x < s2`, that
/// is the [`Span`] `⌈s1⌉ ..= ⌈s2⌉ − 1` (an empty pair gives no span). The slides' interval `[x1 − 0.5, x2 − 0.5]` is
/// this one on their grid, whose pixel centres are at `k + ½`. A pixel is
/// filled exactly when an odd number of crossings lie at or left of its
/// centre: the even-odd rule, also for self-intersecting polygons.
///
/// **Active edge table.** Edges are sorted by their first row; going up
/// row by row, edges join the active list when the row reaches them and
/// leave it after their last row, so each row looks only at the edges
/// that cross it, and a row is ready as soon as the rows below it are.
/// (Departure from the slides, which sort all intersection points of all
/// rows at once: "hoher Sortieraufwand!" — and nothing can be filled until
/// every row's crossings are known, so a shape four billion rows tall
/// cannot even give its first row.)
///
/// ```text
///   row 5   active: e2 (x 3.0)  e0 (x 7.5)     e1 left after row 4,
///   row 4   active: e1 (x 2.5)  e0 (x 7.0)     e2 joined at row 5
///   row 3   active: e1 (x 2.0)  e0 (x 6.5)
/// ```
///
/// `table(y, active)` receives row `y`'s active list after its sort: one
/// [`ActiveEdge`] per edge that crosses the row, in order of `x`, which is
/// [`crossing`] at that row. Only rows inside `viewport` are walked and
/// reported. Departure from the classic table, which keeps `x` and `1/m`
/// in each entry and adds `1/m` per row: a running sum of `f64` steps
/// drifts off the exact crossing in its last bits, and a centre exactly on
/// an edge would then change sides; [`crossing`] costs a multiplication
/// more and is the definition's `x` bit for bit.
///
/// Fewer than three vertices, or any NaN or infinite coordinate, fill
/// nothing and report no row. Huge coordinates are fine: rows and spans are
/// clipped to `viewport` before any pixel is visited.
#[transcript::task]
pub fn fill_spans(
    vertices: &[Vec2],
    viewport: Viewport,
    mut span: impl FnMut(Span),
    mut table: impl FnMut(i32, &[ActiveEdge]) -> ControlFlow<()>,
) {
    // BEGIN SOLUTION scanline: edge table sorted by first row; per row the active edges (report them to `table`, sorted by x, and stop if it says so), then one span ⌈s1⌉ ..= ⌈s2⌉ − 1 per pair
    if vertices.len() < 3 || viewport.is_empty() || !vertices.iter().all(|v| v.is_finite()) {
        return;
    }
    let n = vertices.len();
    // The edge table: each non-horizontal edge with its first and last row
    // (clipped to the viewport), sorted by first row.
    let mut edges: Vec<Edge> = (0..n)
        .filter_map(|i| {
            let (a, b) = (vertices[i], vertices[(i + 1) % n]);
            let (lo, hi) = (f64::from(a.y.min(b.y)), f64::from(a.y.max(b.y)));
            // Rows y with lo ≤ y < hi: ⌈lo⌉ ..= ⌈hi⌉ − 1.
            let first = lo.ceil().max(f64::from(viewport.y_min));
            let last = (hi.ceil() - 1.0).min(f64::from(viewport.y_max));
            #[allow(clippy::cast_possible_truncation)] // clipped to the viewport
            (first <= last).then_some(Edge {
                index: i,
                first: first as i32,
                last: last as i32,
                a,
                b,
            })
        })
        .collect();
    edges.sort_unstable_by_key(|e| e.first);
    // The active edge table: `active` as `table` receives it, in order of
    // x, and `moving`, in the same order, what each of its edges needs to
    // move on to the next row. Edges before `joined` in the edge table
    // have joined.
    let mut active: Vec<ActiveEdge> = Vec::with_capacity(edges.len());
    let mut moving: Vec<Moving> = Vec::with_capacity(edges.len());
    let mut joined = 0;
    let Some(mut y) = edges.first().map(|e| e.first) else {
        return;
    };
    // The viewport's columns, and one past the last, for the span ends.
    let (x_min, x_past) = (f64::from(viewport.x_min), f64::from(viewport.x_max) + 1.0);
    while joined < edges.len() || !active.is_empty() {
        if active.is_empty() {
            y = y.max(edges[joined].first); // skip rows with no edge
        }
        while joined < edges.len() && edges[joined].first == y {
            let edge = &edges[joined];
            active.push(ActiveEdge {
                edge: edge.index,
                x: f64::NAN, // set below
            });
            moving.push(Moving::new(edge));
            joined += 1;
        }
        for (entry, edge) in active.iter_mut().zip(&moving) {
            entry.x = edge.crossing(y);
        }
        // Back in order of x by insertion sort, both lists alike: the
        // order of the row below holds but where edges cross or have just
        // joined, so most rows cost one comparison per edge (and no call
        // of a library sort).
        for i in 1..active.len() {
            let mut j = i;
            while j > 0 && active[j - 1].x > active[j].x {
                active.swap(j - 1, j);
                moving.swap(j - 1, j);
                j -= 1;
            }
        }
        if table(y, &active).is_break() {
            return;
        }
        for pair in active.chunks_exact(2) {
            // ⌈s1⌉ ..= ⌈s2⌉ − 1, clipped to the viewport.
            let x0 = ceil_within(pair[0].x, x_min, x_past);
            let x1 = ceil_within(pair[1].x, x_min, x_past) - 1;
            if x0 <= x1 {
                #[allow(clippy::cast_possible_truncation)] // within the viewport
                span(Span::new(y, x0 as i32, x1 as i32));
            }
        }
        // Edges that end on this row leave both lists.
        let mut i = 0;
        while i < moving.len() {
            if moving[i].last == y {
                active.remove(i);
                moving.remove(i);
            } else {
                i += 1;
            }
        }
        // An edge left ends at or below the viewport's top (its last row
        // is clipped), one still to join starts above `y`: `y + 1` fits.
        if joined < edges.len() || !active.is_empty() {
            y += 1;
        }
    }
    // END SOLUTION
}

/// An entry of the active edge table as [`fill_spans`] reports it: which
/// edge, and where it crosses the row.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ActiveEdge {
    /// The edge from `vertices[edge]` to `vertices[edge + 1]` (the last
    /// edge, `edge = n − 1`, closes the polygon back to `vertices[0]`).
    pub edge: usize,
    /// Where it crosses the row: [`crossing`] of its end points.
    pub x: f64,
}

// BEGIN SOLUTION

/// An entry of the edge table: an edge and the rows it crosses.
struct Edge {
    index: usize,
    first: i32,
    last: i32,
    a: Vec2,
    b: Vec2,
}

/// An active edge on its way up: its last row and the terms of
/// [`crossing`], worked out once when it joins rather than on every row.
struct Moving {
    last: i32,
    lo_x: f64,
    lo_y: f64,
    run: f64,
    rise: f64,
}

impl Moving {
    fn new(edge: &Edge) -> Self {
        let (lo, hi) = if edge.a.y < edge.b.y {
            (edge.a, edge.b)
        } else {
            (edge.b, edge.a)
        };
        let (lo_x, lo_y) = (f64::from(lo.x), f64::from(lo.y));
        Moving {
            last: edge.last,
            lo_x,
            lo_y,
            run: f64::from(hi.x) - lo_x,
            rise: f64::from(hi.y) - lo_y,
        }
    }

    /// [`crossing`] at row `y`: the same operations in the same order, so
    /// the same `x`, bit for bit.
    #[inline]
    fn crossing(&self, y: i32) -> f64 {
        self.lo_x + ((f64::from(y) - self.lo_y) * self.run) / self.rise
    }
}

/// `⌈s⌉` clamped to `[lo, hi]` (whole numbers within `i32`'s range): `s`
/// clamped first, truncated towards zero, then one up where that fell
/// short. `f64::ceil` is a call into the C library on a plain x86-64
/// target (the instruction that rounds, `roundsd`, came with SSE4.1), and
/// two such calls a row cost about as much as the rest of the row's work.
#[inline]
#[allow(clippy::cast_possible_truncation, clippy::cast_precision_loss)] // whole numbers in i32's range and one past it
fn ceil_within(s: f64, lo: f64, hi: f64) -> i64 {
    let s = s.clamp(lo, hi);
    let truncated = s as i64;
    truncated + i64::from((truncated as f64) < s)
}
// END SOLUTION

/// The pixels of [`fill_spans`], one `plot` call per pixel, the table
/// unobserved (given: the tests and the pictures use it).
pub fn fill_polygon(vertices: &[Vec2], viewport: Viewport, mut plot: impl FnMut(Pixel)) {
    fill_spans(
        vertices,
        viewport,
        |span| span.pixels().for_each(&mut plot),
        |_, _| ControlFlow::Continue(()),
    );
}
