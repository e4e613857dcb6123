//! The midpoint circle with a floating-point decision variable: lecture
//! slides "5.2 Zeichnen von Kreisen: Midpoint Circle Algorithmus" (seed 002).
//!
//! Convention (see `canvas`): pixel centres at integers, y up; in each
//! column of the second octant the pixel nearest to the circle (the circle
//! never passes exactly between two pixels, so there are no ties); the
//! other seven octants are its mirror images; every pixel is plotted once.

#[allow(unused_imports)]
use canvas::{MAX_COORD, Pixel};

/// Plots the pixels that the eight symmetries of a circle make of the
/// offset `(x, y)` from `centre`, `(±x, ±y)` and `(±y, ±x)`, each pixel
/// once (the slides' `circlePoint`).
///
/// ```text
///              (−x, y) ■  |  ■ (x, y)
///        (−y, x) ■        |        ■ (y, x)
///       ──────────────────┼──────────────────
///        (−y,−x) ■        |        ■ (y,−x)
///              (−x,−y) ■  |  ■ (x,−y)
/// ```
///
/// Where octants meet, some of the eight coincide: the slides' version
/// plots them twice, which a blending or XOR-ing `plot` would show. The
/// rule here: **changing the sign of a zero coordinate and swapping two
/// equal coordinates are skipped.** So
///
/// - `0 < x < y`: 8 pixels;
/// - `x = 0` (12, 3, 6 and 9 o'clock): 4 pixels, `(0, ±y)` and `(±y, 0)`;
/// - `x = y` (the diagonals): 4 pixels, `(±x, ±x)`;
/// - `x = y = 0` (radius 0): the centre alone.
///
/// Meant for offsets of the second octant, `0 ≤ x ≤ y`, whose pixels lie
/// within ±[`MAX_COORD`] (which [`midpoint_circle`] guarantees).
#[transcript::task]
pub fn circle_points(centre: Pixel, x: i32, y: i32, plot: &mut impl FnMut(Pixel)) {
    // Unused until you write the body:
    let _ = (&centre, &x, &y, &plot);
    todo!("midpoint_circle: plot (±x, ±y) and (±y, ±x) once each: no −0, no swap when x = y")
}

/// Rasterizes the circle of `radius` around `centre` with the midpoint
/// algorithm and calls `plot` once per pixel, in no particular order; at
/// every pixel `(x, y)` of the second octant with `y > x` it reports the
/// decision it is about to take, `decide(x, y, d)` (offsets from the
/// centre), before it steps on from there.
///
/// With offsets `(x, y)` from the centre the circle is
/// `F(x, y) = x² + y² − R² = 0`, negative inside and positive outside. The
/// algorithm walks the second octant clockwise, from 12 o'clock `(0, R)`
/// to 1:30 (the diagonal `x = y`), one column per step, and
/// [`circle_points`] mirrors every pixel into the other seven octants.
///
/// ```text
///   P = (x, y) ■  ·  E  = (x + 1, y)       d = F(M) at M = (x + 1, y − ½)
///                 ×  M                     d < 0: M inside  → E,  d += 2x + 3
///                 ·  SE = (x + 1, y − 1)   d ≥ 0: M outside → SE, d += 2(x − y) + 5
/// ```
///
/// - `d` starts at `F(1, R − ½) = 5/4 − R`; both increments use `x` and `y`
///   before the step; the walk goes on while `y > x`. The `d` reported at
///   `(x, y)` is `F(x + 1, y − ½)`, the value that decides the step from
///   there (the tests check it against that closed form and the slides'
///   traces, so a circle found another way, `round(√(R² − x²))` per
///   column, say, shows in it).
/// - The decision variable is an `f64`, as the slides' "float!" asks. It
///   is always an integer plus ¼, so it is never 0 (no midpoint lies on
///   the circle) and an `f64` holds it exactly: this version decides
///   exactly as the integer one. An `f32` holds quarters exactly only below
///   2²², and `|d|` grows to about `2R`: from radii of about eight million
///   on (still inside ±[`MAX_COORD`]) an `f32` version picks wrong pixels.
/// - **Departure from the slides**: their loop also plots the pixel of the
///   step that crosses the diagonal (`x > y`, an SE step from `y = x + 1`).
///   That pixel is the mirror image of the one before it, so its eight
///   copies were all plotted already; it is skipped here.
/// - Radius 0 plots the centre. A negative radius, or a circle that reaches
///   beyond ±[`MAX_COORD`] (`|centre.x| + radius > MAX_COORD`, or the same
///   for y), plots nothing.
#[transcript::task]
pub fn midpoint_circle(
    centre: Pixel,
    radius: i32,
    mut plot: impl FnMut(Pixel),
    mut decide: impl FnMut(i32, i32, f64),
) {
    // Unused until you write the body:
    let _ = (&centre, &radius, &mut plot, &mut decide);
    todo!(
        "midpoint_circle: step E or SE from (0, R) while y > x, d = 5/4 − R as an f64, reporting (x, y, d) before each step"
    )
}
