//! The N-step line with N = 2, the double-step algorithm: lecture slides
//! "N-Schritt-Verfahren" (seed 002), generalised from its pseudo-code for
//! `m < ½` to slopes up to 1 and to all octants.
//!
//! Convention (see `canvas`): pixel centres at integers, y up; both
//! endpoints are drawn; ties go to the smaller minor coordinate, exactly as
//! in `midpoint_line`, whose pixels this must reproduce.

#[allow(unused_imports)]
use canvas::{MAX_COORD, Pixel};

/// The four two-pixel patterns of a double step from the pixel `P` in the
/// first octant: which of the next two columns go up.
///
/// ```text
///   (1)      (2)      (3)      (4)
///   · ·      · ■      ■ ■      · ■
///   · ·      · ·      · ·      ■ ·
///  P■ ■ ■   P■ ■ ·   P■ · ·   P■ · ·
/// ```
///
/// Pattern 4 cannot occur for slopes `m ≤ ½`, pattern 1 not for `m ≥ ½`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pattern {
    /// E, E: both pixels on P's row.
    Flat,
    /// E, NE: the second pixel one row up.
    StepSecond,
    /// NE, E: both pixels one row up.
    StepFirst,
    /// NE, NE: one row up, then two rows up.
    Steep,
}

impl Pattern {
    /// The rows (relative to P) of the two pixels this pattern draws.
    #[must_use]
    pub const fn rows(self) -> [i64; 2] {
        match self {
            Pattern::Flat => [0, 0],
            Pattern::StepSecond => [0, 1],
            Pattern::StepFirst => [1, 1],
            Pattern::Steep => [1, 2],
        }
    }
}

/// Rasterizes the line from `from` to `to` two pixels per step and calls
/// `plot` once per pixel, in order from `from` to `to`; the pixels are
/// exactly those of the midpoint line. Each double step first reports the
/// pattern it chose to `step` (in first-octant terms: the rows of its two
/// pixels counted along the minor axis, away from `from`), then plots its
/// two pixels; the single last pixel of an odd number of steps reports no
/// pattern.
///
/// In the first octant (`0 ≤ Δy ≤ Δx`) the decision variable looks at the
/// midpoints of the two columns ahead. For `m ≤ ½` the slides' variable
/// `d = 4Δy − Δx` picks pattern 1 when `d ≤ 0`, pattern 2 when
/// `d ≤ cond = 2Δy`, and pattern 3 otherwise; it grows by `4Δy` after
/// pattern 1 and by `4Δy − 2Δx` after patterns 2 and 3. For `m > ½` the
/// mirror image, `e = 4Δy − 3Δx`, picks pattern 4 when `e > 0`, pattern 2
/// when `e ≤ 2(Δy − Δx)`, and pattern 3 otherwise; it grows by `4Δy − 4Δx`
/// after pattern 4 and by `4Δy − 2Δx` after patterns 2 and 3. When the
/// line has an odd number of steps, the last pixel is its endpoint.
///
/// Endpoints beyond ±[`MAX_COORD`] draw nothing.
pub fn double_step_line(
    from: Pixel,
    to: Pixel,
    mut plot: impl FnMut(Pixel),
    mut step: impl FnMut(Pattern),
) {
    // Unused until you write the body:
    let _ = (&from, &to, &mut plot, &mut step);
    todo!(
        "double_step: choose one of the four patterns per double step (generalise the slides' m < 1/2 pseudo-code), report it to `step`, plot its two pixels; the pixels must equal the midpoint line's"
    )
}
