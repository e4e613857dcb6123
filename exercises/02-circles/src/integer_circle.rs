//! The midpoint circle in integer arithmetic with second-order
//! differences: the slides' "Midpoint Circle Algorithmus" (seed 002) with
//! the float removed that their comparison table still lists
//! ("Operationen: Floating Point"), after Foley et al., *Computer
//! Graphics*, §3.3.2.
//!
//! Convention (see `canvas`): pixel centres at integers, y up; exactly the
//! pixels of `midpoint_circle` for every radius: in each column of the
//! second octant the pixel nearest to the circle, mirrored into the other
//! octants, every pixel plotted once.

#[allow(unused_imports)]
use canvas::{MAX_COORD, Pixel};

/// The decision variables at one pixel of the walk through the second
/// octant, as [`integer_circle`] reports them before the step from it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Decision {
    /// The pixel's column, relative to the centre.
    pub x: i32,
    /// The pixel's row, relative to the centre.
    pub y: i32,
    /// `h = d − ¼`: negative chooses E, otherwise SE.
    pub h: i64,
    /// What `h` grows by when the step goes E: `ΔE = 2x + 3`.
    pub delta_e: i64,
    /// What `h` grows by when the step goes SE: `ΔSE = 2(x − y) + 5`.
    pub delta_se: i64,
}

/// Rasterizes the circle of `radius` around `centre` with integers only
/// and calls `plot` once per pixel, in no particular order; reports the
/// decision variables at every pixel of the walk to `step` before it
/// steps on (see [`Decision`]).
///
/// Two steps turn the slides' float algorithm into an integer one:
///
/// 1. **`h = d − ¼`.** The float `d` starts at `5/4 − R` and only ever
///    grows by integers, so it is always an integer plus ¼. Then
///    `h = d − ¼` is an integer, starts at `1 − R`, grows by the same
///    increments, and `d < 0 ⟺ h < −¼ ⟺ h < 0`: the same decisions.
/// 2. **Second-order differences.** The increments `ΔE = 2x + 3` and
///    `ΔSE = 2(x − y) + 5` are linear in `x` and `y`, so they change by
///    constants as well:
///
/// ```text
///   start (0, R):  h = 1 − R,  ΔE = 3,  ΔSE = 5 − 2R
///   h < 0 → E:     h += ΔE;    ΔE += 2,  ΔSE += 2     (x grew)
///   h ≥ 0 → SE:    h += ΔSE;   ΔE += 2,  ΔSE += 4     (x grew, y shrank)
/// ```
///
/// so the loop adds only, without a single multiplication.
///
/// The walk, the symmetry and the limits are those of `midpoint_circle`:
/// from `(0, R)` while `y > x`, a step past the diagonal is not plotted,
/// each pixel of the eight mirror images is plotted once (write the
/// symmetry yourself, or copy your `circle_points`: each task is graded on
/// its own). Radius 0 plots the centre; a negative radius, or a circle
/// reaching beyond ±[`MAX_COORD`], plots nothing.
pub fn integer_circle(
    centre: Pixel,
    radius: i32,
    mut plot: impl FnMut(Pixel),
    mut step: impl FnMut(Decision),
) {
    // Unused until you write the body:
    let _ = (&centre, &radius, &mut plot, &mut step);
    todo!(
        "integer_circle: the same walk with h = 1 − R, ΔE = 3 and ΔSE = 5 − 2R, adding only; report each pixel's Decision to `step` before stepping on"
    )
}
