//! Edge fill and fence fill: fill a polygon by inverting pixels right of
//! (or up to a fence from) each edge crossing, after the lecture slides
//! (seed 002, §5.4 "Füllen von Polygonen": Kantenfüllung, Zaunfüllung).
//!
//! Convention (see `canvas`): pixel centres at integers, y up; the filled
//! pixels are exactly those of `scanline` (even-odd rule, left ends of
//! spans included, right ends excluded).

#[allow(unused_imports)]
use canvas::{Canvas, Pixel, Vec2, Viewport};

/// Where the edge `a–b` crosses row `y`: the same formula, evaluated in
/// the same order, as `scanline::crossing` (lower endpoint first, `f64`).
#[must_use]
#[transcript::task]
pub fn crossing(a: Vec2, b: Vec2, y: i32) -> f64 {
    let (lo, hi) = if a.y < b.y { (a, b) } else { (b, a) };
    let (lo_x, lo_y) = (f64::from(lo.x), f64::from(lo.y));
    let (hi_x, hi_y) = (f64::from(hi.x), f64::from(hi.y));
    lo_x + ((f64::from(y) - lo_y) * (hi_x - lo_x)) / (hi_y - lo_y)
}

/// Edge fill: for every crossing of an edge with a row, invert every pixel
/// of that row from the crossing to the right end of `viewport`, reporting
/// each inversion to `invert`; then call `plot` once per pixel left
/// inverted. Returns the number of inversions (of `invert` calls).
///
/// A pixel `x` of row `y` is inverted once for each crossing with
/// `⌈s⌉ ≤ x` (vertices and crossings shifted by −½ on the slides' grid,
/// where centres lie at `k + ½`), so it ends up set exactly when that
/// number is odd: the even-odd rule, the same pixels as `scanline`. Edges
/// may come in any order (the slides: "Reihenfolge der
/// Polygonkanten-Abarbeitung beliebig"); rows are those of `scanline`.
/// Every inversion is reported, all before the first `plot`: the tests
/// count them pixel by pixel against the crossings, so the inverting is
/// graded, not only the pixels it leaves.
///
/// ```text
///   edge 1:       |###########     invert right of each crossing:
///   edge 2:       |      |#####    what lies right of the polygon is
///   result:       |######|         inverted twice and comes back
/// ```
///
/// The work is an inversion per pixel right of every crossing, out to the
/// viewport's right edge — the cost that fence fill cuts. The buffer covers
/// the viewport's width and the polygon's rows. Fewer than three vertices,
/// a NaN or infinite coordinate, or a buffer of more than
/// [`Canvas::MAX_PIXELS`] pixels (no canvas is that large) fill nothing and
/// return 0.
#[transcript::task]
pub fn edge_fill(
    vertices: &[Vec2],
    viewport: Viewport,
    mut plot: impl FnMut(Pixel),
    mut invert: impl FnMut(Pixel),
) -> u64 {
    // Unused until you write the body:
    let _ = (&vertices, &viewport, &mut plot, &mut invert);
    todo!(
        "edge_fence: per crossing invert ⌈s⌉ ..= x_max of its row (report each inversion to `invert`); plot what stays inverted"
    )
}

/// Fence fill: like [`edge_fill`], but each crossing inverts only the
/// pixels between it and the fence column `fence`: `⌈s⌉ ..= fence − 1` for
/// a crossing left of the fence, `fence ..= ⌈s⌉ − 1` for one at or right of
/// it. Each inversion is reported to `invert`, as in [`edge_fill`];
/// returns their number.
///
/// Why the same pixels: inverting `[c, ∞)` equals inverting `[c, fence)`
/// and then `[fence, ∞)` (for `c < fence`), or `[fence, ∞)` and then
/// `[fence, c)` (for `c ≥ fence`). Every crossing of a row inverts
/// `[fence, ∞)` once, and each row has an even number of crossings, so
/// those inversions cancel and can be left out.
///
/// ```text
///              fence
///   edge 1:   |###:          a crossing left of the fence inverts up to it,
///   edge 2:       :###|      one right of it inverts back to the fence
///   result:   |###:###|
/// ```
///
/// With the fence through the middle of the polygon, the work is about the
/// polygon's area instead of everything right of it. The slides put the
/// fence through a vertex ("Vertikale Gerade durch Schnittpunkt zweier
/// Polygonkanten"), the column `⌈v.x⌉`; it may lie anywhere, also outside
/// the polygon or the viewport.
#[transcript::task]
pub fn fence_fill(
    vertices: &[Vec2],
    fence: i32,
    viewport: Viewport,
    mut plot: impl FnMut(Pixel),
    mut invert: impl FnMut(Pixel),
) -> u64 {
    // Unused until you write the body:
    let _ = (&vertices, &fence, &viewport, &mut plot, &mut invert);
    todo!(
        "edge_fence: per crossing invert between ⌈s⌉ and the fence (report each to `invert`); plot what stays inverted"
    )
}
