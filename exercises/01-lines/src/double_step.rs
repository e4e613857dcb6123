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
#[transcript::evidence]
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

/// One double step as [`double_step_line`] reports it: the decision
/// variable the pattern was chosen by, and the pattern.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DoubleStep {
    /// The decision variable *before* this step's update, the value the
    /// pattern was chosen by: the slides' `d` for slopes `m ≤ ½`, the
    /// mirrored `e` for `m > ½` (see [`double_step_line`]).
    pub d: i64,
    /// The pattern chosen.
    pub pattern: Pattern,
}

/// Rasterizes the line from `from` to `to` two pixels per step and calls
/// `plot` once per pixel, in order from `from` to `to`; the pixels are
/// exactly those of the midpoint line.
///
/// **Reporting rule.** Each double step first reports to `step` its
/// decision variable, as it stands when the pattern is chosen, and the
/// pattern it chose ([`DoubleStep`]); only then does it plot its two
/// pixels and add its increment to the decision variable. The pattern is
/// in first-octant terms: the rows of its two pixels counted along the
/// minor axis, away from `from`. The first pixel, `from`, is plotted
/// before any report; the single last pixel of an odd number of steps,
/// the endpoint, reports nothing.
///
/// In the first octant (`0 ≤ Δy ≤ Δx`) the decision variable is twice
/// `F(x, y) = Δy·x − Δx·y` at a midpoint of the second column ahead. For
/// `m ≤ ½` it is the slides' `d`, at `(x + 2, y + ½)`: it starts at
/// `d = 4Δy − Δx` and picks pattern 1 when `d ≤ 0`, pattern 2 when
/// `d ≤ cond = 2Δy`, and pattern 3 otherwise; it grows by `incr1 = 4Δy`
/// after pattern 1 and by `incr2 = 4Δy − 2Δx` after patterns 2 and 3. For
/// `m > ½` it is the mirror image `e`, at `(x + 2, y + 3/2)`: it starts
/// at `e = 4Δy − 3Δx` and picks pattern 4 when `e > 0`, pattern 2 when
/// `e ≤ 2(Δy − Δx)`, and pattern 3 otherwise; it grows by `4Δy − 4Δx`
/// after pattern 4 and by `4Δy − 2Δx` after patterns 2 and 3. (At
/// `m = ½` both apply and give the same pixels; the slope decides which
/// variable is reported: `d` when `2Δy ≤ Δx`.) A comparison that comes
/// out equal (`d = 0`, `d = cond`, `e = 0`, `e = 2(Δy − Δx)`) is a
/// midpoint exactly on the line, a tie: it goes by the midpoint line's
/// rule (the smaller minor coordinate), which is not always the way the
/// slides compare. When the line has an odd number of steps, the last
/// pixel is its endpoint.
///
/// ```text
///   from ■ ─ step(d₀, p₀) ─ ■ ■ ─ step(d₁, p₁) ─ ■ ■ ─ … ─ (■ to)
///          report first,    then the two pixels of p₀, and d₁ = d₀ + incr(p₀)
/// ```
///
/// Endpoints beyond ±[`MAX_COORD`] draw nothing.
#[transcript::task]
pub fn double_step_line(
    from: Pixel,
    to: Pixel,
    mut plot: impl FnMut(Pixel),
    mut step: impl FnMut(DoubleStep),
) {
    // Unused until you write the body:
    let _ = (&from, &to, &mut plot, &mut step);
    todo!(
        "double_step: choose one of the four patterns per double step (generalise the slides' m < 1/2 pseudo-code), report it with its decision variable to `step` before plotting its two pixels; the pixels must equal the midpoint line's"
    )
}
