//! The midpoint circle in integer arithmetic with second-order
//! differences: the slides' "Midpoint Circle Algorithmus" (seed 002) with
//! the float removed that their comparison table still lists
//! ("Operationen: Floating Point"), after Foley et al., *Computer
//! Graphics*, §3.3.2.
//!
//! The algorithm is a small machine: its state at a pixel of the walk is a
//! [`Walk`] (the pixel, the decision variable `h` and the increments `ΔE`
//! and `ΔSE`), [`Walk::start`] is its state at 12 o'clock and [`Walk::step`]
//! takes it one column on, by additions alone. [`integer_circle`] (given)
//! runs it and plots.
//!
//! Convention (see `canvas`): pixel centres at integers, y up; exactly the
//! pixels of `midpoint_circle` for every radius: in each column of the
//! second octant the pixel nearest to the circle, mirrored into the other
//! octants, every pixel plotted once.

use canvas::{MAX_COORD, Pixel};

/// The state of the integer walk at one pixel of the second octant: the
/// pixel and the decision variables there, as [`integer_circle`] reports
/// it before the step from it.
///
/// Two steps turn the slides' float algorithm into this one:
///
/// 1. **`h = d − ¼`.** The float `d` starts at `5/4 − R` and only ever
///    grows by integers, so it is always an integer plus ¼. Then
///    `h = d − ¼` is an integer, starts at `1 − R`, grows by the same
///    increments, and `d < 0 ⟺ h < −¼ ⟺ h < 0`: the same decisions.
/// 2. **Second-order differences.** The increments `ΔE = 2x + 3` and
///    `ΔSE = 2(x − y) + 5` are linear in `x` and `y`, so they change by
///    constants as well, and the walk carries them as variables:
///
/// ```text
///   start (0, R):  h = 1 − R,  ΔE = 3,  ΔSE = 5 − 2R
///   h < 0 → E:     h += ΔE;    ΔE += 2,  ΔSE += 2     (x + 1)
///   h ≥ 0 → SE:    h += ΔSE;   ΔE += 2,  ΔSE += 4     (x + 1, y − 1)
/// ```
///
/// so the loop adds only, without a single multiplication. On a walk of a
/// circle the three variables keep their closed forms (below), but the
/// walk never computes those: it adds what it holds.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Walk {
    /// The pixel's column, relative to the centre.
    pub x: i32,
    /// The pixel's row, relative to the centre.
    pub y: i32,
    /// `h = d − ¼`: negative chooses E, otherwise SE. On a circle of
    /// radius `R`, `h = (x + 1)² + y² − y − R²`.
    pub h: i64,
    /// What `h` grows by when the step goes E; on a circle `2x + 3`.
    pub delta_e: i64,
    /// What `h` grows by when the step goes SE; on a circle `2(x − y) + 5`.
    pub delta_se: i64,
}

impl Walk {
    /// The walk at 12 o'clock, the pixel `(0, R)`: `h = 1 − R`, `ΔE = 3`,
    /// `ΔSE = 5 − 2R`. (`radius` is at most [`MAX_COORD`] here: `i64`
    /// holds every value of the walk with room to spare.)
    #[must_use]
    #[transcript::task]
    pub fn start(radius: i32) -> Self {
        // BEGIN SOLUTION integer_circle: the state at (0, R): h = 1 − R, ΔE = 3, ΔSE = 5 − 2R
        let r = i64::from(radius);
        Self {
            x: 0,
            y: radius,
            h: 1 - r,
            delta_e: 3,
            delta_se: 5 - 2 * r,
        }
        // END SOLUTION
    }

    /// Takes the walk one column on, by the table of [`Walk`]: when
    /// `h < 0` the step goes E (`h += ΔE`), otherwise SE (`h += ΔSE`,
    /// `y − 1`); then `ΔE` grows by 2, `ΔSE` by 2 after E and by 4 after
    /// SE, and `x` by 1.
    ///
    /// The step uses nothing but the state it holds and the constants of
    /// the table: it adds the increments it carries, it does not recompute
    /// them from `x` and `y` (nor `h` from the radius), and it stays in
    /// integers. The tests step states that no circle has (`h` near
    /// ±2⁶⁰, increments far from `2x + 3`), where anything else gives
    /// other numbers.
    #[transcript::task]
    pub fn step(&mut self) {
        // BEGIN SOLUTION integer_circle: h < 0: E (h += ΔE), else SE (h += ΔSE, y − 1); then ΔE += 2, ΔSE += 2 after E or 4 after SE, x + 1 — add what the state holds, recompute nothing
        if self.h < 0 {
            self.h += self.delta_e;
            self.delta_se += 2;
        } else {
            self.h += self.delta_se;
            self.delta_se += 4;
            self.y -= 1;
        }
        self.delta_e += 2;
        self.x += 1;
        // END SOLUTION
    }
}

/// Rasterizes the circle of `radius` around `centre` with the integer
/// walk of [`Walk`] and calls `plot` once per pixel, in no particular
/// order; reports the walk's state at every pixel of the second octant
/// with `y > x` to `step`, before it steps on from it (given: your part is
/// [`Walk::start`] and [`Walk::step`]).
///
/// The walk, the symmetry and the limits are those of `midpoint_circle`:
/// from `(0, R)` while `y > x`, a step past the diagonal is not plotted
/// (its mirror images were plotted one step earlier), each pixel of the
/// eight mirror images is plotted once. Radius 0 plots the centre; a
/// negative radius, or a circle reaching beyond ±[`MAX_COORD`], plots
/// nothing.
///
/// # Panics
///
/// If [`Walk::step`] does not move one column right and at most one row
/// down: the walk would not end.
pub fn integer_circle(
    centre: Pixel,
    radius: i32,
    mut plot: impl FnMut(Pixel),
    mut step: impl FnMut(Walk),
) {
    let reach = |c: i32| i64::from(c).abs() + i64::from(radius);
    if radius < 0
        || reach(centre.x) > i64::from(MAX_COORD)
        || reach(centre.y) > i64::from(MAX_COORD)
    {
        return;
    }
    let mut walk = Walk::start(radius);
    eight_way(centre, walk.x, walk.y, &mut plot);
    while walk.y > walk.x {
        step(walk);
        let (x, y) = (walk.x, walk.y);
        walk.step();
        assert!(
            walk.x == x + 1 && (walk.y == y || walk.y == y - 1),
            "Walk::step went from ({x}, {y}) to ({}, {}): a step goes one column right (E) or one right and one down (SE)",
            walk.x,
            walk.y
        );
        if walk.x > walk.y {
            // The mirror image of the previous pixel (see `midpoint_circle`).
            break;
        }
        eight_way(centre, walk.x, walk.y, &mut plot);
    }
}

/// `(±x, ±y)` and `(±y, ±x)` around `centre`, each pixel once: a zero
/// coordinate is not negated, equal coordinates are not swapped (the rule
/// of `circle_points`, repeated here because each task stands alone).
fn eight_way(centre: Pixel, x: i32, y: i32, plot: &mut impl FnMut(Pixel)) {
    for (a, b) in [(x, y), (y, x)]
        .into_iter()
        .take(if x == y { 1 } else { 2 })
    {
        for (sa, sb) in [(1, 1), (-1, 1), (1, -1), (-1, -1)] {
            if (sa < 0 && a == 0) || (sb < 0 && b == 0) {
                continue;
            }
            plot(Pixel::new(centre.x + sa * a, centre.y + sb * b));
        }
    }
}
