//! The midpoint line from both endpoints at once: the slides' speed-up
//! ("Zur Beschleunigung kann der Algorithmus auch von beiden Endpunkten
//! gleichzeitig gestartet werden", seed 002, "Midpoint Line Algorithmus").
//!
//! Two walkers share one loop: one steps from `from` towards `to`, the
//! other from `to` towards `from`, and they meet in the middle, so the
//! loop runs half as often. Each walker is task 2's midpoint line in its
//! own direction. The second is not simply the first mirrored through the
//! line's centre: at a tie the rule takes the smaller minor coordinate,
//! and the mirror image of "smaller" is "larger". Walking the other way,
//! the second walker's minor axis runs the other way too, so it takes the
//! diagonal step at a tie exactly when the first does not.
//!
//! ```text
//!   plot order:  0   n   1  n−1  2  n−2  …   (pixels numbered from `from`)
//!                ■───────────────────────■
//!                └─▶ walker from `from`  ◀─┘ walker from `to`
//! ```
//!
//! Convention (see `canvas`): pixel centres at integers, y up; both
//! endpoints are drawn; a tie (the midpoint exactly on the line) goes to
//! the pixel with the smaller minor coordinate — the pixels of task 2.

use canvas::{MAX_COORD, Pixel};

/// Rasterizes the line from `from` to `to` as task 2's `midpoint_line`
/// does, from both ends at once, and calls `plot` once per pixel in the
/// order of the two walkers: `from`, `to`, then alternately the next
/// pixel from `from`'s side and the next from `to`'s side, until they
/// meet (the middle pixel of a line with an odd number of pixels comes
/// last, from `from`'s side).
///
/// - With pixels `p₀ = from, p₁, …, p_n = to` (one per column of the major
///   axis, `n = max(|Δx|, |Δy|)`), the order is
///   `p₀, p_n, p₁, p_(n−1), p₂, …`: each exactly once.
/// - **Reporting rule.** Before each step, the walker that takes it
///   reports its own decision variable `d` to `step`, the value the step
///   is decided by; then the pixel it steps to is plotted. So the calls
///   are `plot(p₀)`, `plot(p_n)`, `step(d)`, `plot(p₁)`, `step(d′)`,
///   `plot(p_(n−1))`, …, alternating between the walkers. Each walker's
///   `d` is task 2's, in its own first octant (from its own start towards
///   its own end): it starts at `2·short − long` (`short`, `long`: the
///   line's `|Δ|` along its minor and major axis) and grows by `2·short`
///   after a straight step and by `2·(short − long)` after a diagonal one.
/// - A zero-length line plots one pixel.
/// - Endpoints beyond ±[`MAX_COORD`] draw nothing.
#[transcript::task]
pub fn two_ended_midpoint_line(
    from: Pixel,
    to: Pixel,
    mut plot: impl FnMut(Pixel),
    mut step: impl FnMut(i64),
) {
    // BEGIN SOLUTION two_ended: one midpoint walker from each end, each with its own tie rule, stepped in turn until they meet; before each step report the stepping walker's decision variable to `step`
    if [from.x, from.y, to.x, to.y]
        .iter()
        .any(|c| c.unsigned_abs() > MAX_COORD as u32)
    {
        return;
    }
    let mut near = Walker::new(from, to);
    let mut far = Walker::new(to, from);
    plot(from);
    if near.long == 0 {
        return;
    }
    plot(to);
    // Pixels still to plot between the two ends.
    let mut left = near.long - 1;
    while left >= 2 {
        step(near.d);
        plot(near.step());
        step(far.d);
        plot(far.step());
        left -= 2;
    }
    if left == 1 {
        step(near.d);
        plot(near.step());
    }
    // END SOLUTION
}

// BEGIN SOLUTION
/// Task 2's midpoint line, one step at a time, from `at` towards an end.
struct Walker {
    x: i32,
    y: i32,
    /// Twice `F` at the next midpoint, in this walker's first octant.
    d: i64,
    long: i64,
    short: i64,
    /// 1 when a tie takes the diagonal step (the minor axis runs
    /// backwards, so the diagonal leads to the smaller minor coordinate).
    tie_bias: i64,
    diagonal: (i32, i32),
    straight: (i32, i32),
}

impl Walker {
    fn new(at: Pixel, end: Pixel) -> Self {
        let (dx, dy) = (i64::from(end.x - at.x), i64::from(end.y - at.y));
        let (sx, sy) = (if dx < 0 { -1 } else { 1 }, if dy < 0 { -1 } else { 1 });
        let x_major = dx.abs() >= dy.abs();
        let (long, short) = if x_major {
            (dx.abs(), dy.abs())
        } else {
            (dy.abs(), dx.abs())
        };
        let diagonal_on_tie = if x_major { sy < 0 } else { sx < 0 };
        Self {
            x: at.x,
            y: at.y,
            d: 2 * short - long,
            long,
            short,
            tie_bias: i64::from(diagonal_on_tie),
            diagonal: (sx, sy),
            straight: if x_major { (sx, 0) } else { (0, sy) },
        }
    }

    /// The next pixel: the diagonal step when the midpoint lies below the
    /// line (or on it, where this walker's tie rule says so).
    fn step(&mut self) -> Pixel {
        let step = if self.d + self.tie_bias > 0 {
            self.d += 2 * (self.short - self.long);
            self.diagonal
        } else {
            self.d += 2 * self.short;
            self.straight
        };
        self.x += step.0;
        self.y += step.1;
        Pixel::new(self.x, self.y)
    }
}
// END SOLUTION
