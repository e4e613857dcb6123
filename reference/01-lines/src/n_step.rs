//! The N-step line: lecture slides "N-Schritt-Verfahren" (seed 002). Their
//! pseudo-code stops at the double step ("Algorithmen für Dreifach- und
//! Vierfachschritt nach gleichem Prinzip vorhanden"); here the principle
//! for every N from 1 to [`MAX_N`], in all octants, with one decision
//! variable per N pixels. N = 1 is the midpoint line ("Midpoint-Line-
//! Algorithmus ist Spezialfall des N-Schritt-Verfahrens mit einer
//! Schrittweite von 1 und zwei Mustern"), N = 2 the double step.
//!
//! In the first octant (`0 ≤ Δy ≤ Δx`) a step from the pixel `P` covers
//! the next N columns. Each of its pixels lies on the row of the one
//! before it (E) or one row higher (NE), so a step is a word of N moves,
//! its *pattern*. Of the 2ᴺ words a line of one slope uses at most N + 1:
//! all N rows follow from one number, how far the line passes above or
//! below `P`, and as that number grows the columns take their upper row
//! one at a time, at N thresholds. With N = 3 and a slope `0 < m < ⅓`,
//! at most one pixel of the step rises, and each threshold the decision
//! variable `D` passes (see [`n_step_line`]) moves the rise one column
//! earlier:
//!
//! ```text
//!      D ≤ T₃          T₃ < D ≤ T₂     T₂ < D ≤ T₁     T₁ < D
//!         · · ·           · · ■           · ■ ■           ■ ■ ■
//!      P■ ■ ■ ■        P■ ■ ■ ·        P■ ■ · ·        P■ · · ·
//!         E E E           E E NE          E NE E          NE E E
//!      rises 0b000     0b100           0b010           0b001
//! ```
//!
//! (`·`: the row a column could have taken and did not.)
//!
//! Convention (see `canvas`): pixel centres at integers, y up; both
//! endpoints are drawn; ties go to the smaller minor coordinate, exactly as
//! in `midpoint_line`, whose pixels this must reproduce.

use std::fmt;

use canvas::{MAX_COORD, Pixel};

/// The largest N: a step's pattern is one bit per pixel of a `u32`.
pub const MAX_N: u32 = u32::BITS;

/// One step of N pixels as [`n_step_line`] reports it: the decision
/// variable the pattern was chosen by, and the pattern.
#[transcript::evidence]
#[derive(Clone, Copy, PartialEq, Eq)]
pub struct NStep {
    /// The decision variable *before* this step's update, the value the
    /// pattern was chosen by: twice `F` at the midpoint of the step's last
    /// column (see [`n_step_line`]).
    pub d: i64,
    /// The pattern, in first-octant terms: bit `k − 1` (counted from the
    /// least significant) is set when the step's `k`-th pixel lies one row
    /// above the pixel before it (NE), clear when it lies on the same row
    /// (E). Bits `N` and up are clear. Rows are counted along the minor
    /// axis, away from `from`.
    pub rises: u32,
}

impl NStep {
    /// The row of the step's `k`-th pixel (`k` in `1..=N`) counted from
    /// the pixel before the step: how many of its first `k` pixels rise.
    #[must_use]
    pub fn row(self, k: u32) -> i64 {
        let first_k = 1u32.checked_shl(k).map_or(u32::MAX, |bit| bit - 1);
        i64::from((self.rises & first_k).count_ones())
    }
}

impl fmt::Debug for NStep {
    /// `NStep { d: 6, rises: 0b100 }`: the pattern in binary, so the first
    /// pixel's bit is the rightmost.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("NStep")
            .field("d", &self.d)
            .field("rises", &format_args!("{:#b}", self.rises))
            .finish()
    }
}

/// Rasterizes the line from `from` to `to` `n` pixels per step and calls
/// `plot` once per pixel, in order from `from` to `to`; the pixels are
/// exactly those of the midpoint line, for every `n`.
///
/// **Reporting rule.** Each step of `n` pixels first reports to `step`
/// its decision variable, as it stands when the pattern is chosen, and
/// the pattern it chose ([`NStep`]); only then does it plot its `n`
/// pixels and add its increment to the decision variable. The first
/// pixel, `from`, is plotted before any report; the last `Δmajor mod n`
/// pixels, fewer than a step, are plotted after the last report and
/// report nothing (`n = 2`: the double step's endpoint alone).
///
/// In the first octant (`0 ≤ Δy ≤ Δx`, `F(x, y) = Δy·x − Δx·y`, a step
/// from the pixel `P = (x, y)`), the `k`-th column of the step (`k` in
/// `1..=n`) can hold only two rows, `y + c_k` and `y + c_k + 1`, with
/// `c_k = ⌈k·Δy/Δx⌉ − 1` (`c_k = 0` when `Δy = 0`). It takes the upper one
/// when its midpoint `(x + k, y + c_k + ½)` lies below the line, where
/// `2F > 0`. `F` is linear, so one value decides every column: twice `F`
/// at the midpoint of the *last* column,
///
/// ```text
///   D = 2F(x + n, y + q + ½),   q = c_n,        D₀ = 2nΔy − (2q + 1)Δx
///   2F(x + k, y + c_k + ½) = D − T_k,           T_k = 2(n − k)Δy − 2(q − c_k)Δx
///   column k on row c_k + 1  ⇔  D > T_k         (T_n = 0)
///   after a step that rises r rows in all:      D += 2nΔy − 2rΔx
/// ```
///
/// The thresholds `T_k` are constants of the line: sorted, they cut the
/// range of `D` into `n + 1` intervals, one pattern each. With `n = 1`
/// this is the midpoint line's `d = 2Δy − Δx`; with `n = 2` the double
/// step's `d` (`q = 0`, `T_1 = cond = 2Δy`) for `m ≤ ½` and its `e`
/// (`q = 1`, `T_1 = 2(Δy − Δx)`) for `m > ½`. `D = T_k` is a midpoint
/// exactly on the line, a tie: it goes by the midpoint line's rule (the
/// smaller minor coordinate), which in first-octant terms takes the upper
/// row only where the minor axis runs backwards.
///
/// ```text
///   from ■ ─ step(D₀, w₀) ─ ■ … ■ ─ step(D₁, w₁) ─ ■ … ■ ─ … ─ ■ … ■ to
///          report first,    then the n pixels of w₀,          fewer than n,
///                           and D₁ = D₀ + 2nΔy − 2r₀Δx        no report
/// ```
///
/// `n` outside `1..=`[`MAX_N`] and endpoints beyond ±[`MAX_COORD`] draw
/// nothing.
#[transcript::task]
pub fn n_step_line(
    from: Pixel,
    to: Pixel,
    n: u32,
    mut plot: impl FnMut(Pixel),
    mut step: impl FnMut(NStep),
) {
    // BEGIN SOLUTION n_step: per step of n pixels choose one of the n + 1 patterns by one decision variable, D = 2F at the midpoint of the step's last column, against thresholds set up once per line; report it to `step` before plotting the step's n pixels, plot a last step of fewer than n pixels without a report; the pixels must equal the midpoint line's
    if n == 0
        || n > MAX_N
        || [from.x, from.y, to.x, to.y]
            .iter()
            .any(|c| c.unsigned_abs() > MAX_COORD as u32)
    {
        return;
    }
    let (dx, dy) = (i64::from(to.x - from.x), i64::from(to.y - from.y));
    let (sx, sy) = (if dx < 0 { -1 } else { 1 }, if dy < 0 { -1 } else { 1 });
    let x_major = dx.abs() >= dy.abs();
    let (long, short) = if x_major {
        (dx.abs(), dy.abs())
    } else {
        (dy.abs(), dx.abs())
    };
    // Ties go to the smaller minor coordinate (see `midpoint_line`); in
    // first-octant terms that is "up" when the minor axis runs backwards.
    // "D > T, or D = T when ties go up" is, for integers, "T < D + tie".
    let tie = i64::from(if x_major { sy < 0 } else { sx < 0 });
    // Map first-octant offsets (i along the major axis, j along the minor)
    // back to the line's octant.
    let pixel = |i: i64, j: i64| {
        let (major, minor) = (i as i32, j as i32);
        if x_major {
            Pixel::new(from.x + sx * major, from.y + sy * minor)
        } else {
            Pixel::new(from.x + sx * minor, from.y + sy * major)
        }
    };

    // Once per line: per column k of a step its lower row c_k and its
    // threshold T_k, the thresholds sorted, and the pattern of each of
    // the n + 1 intervals between them.
    let width = n as usize;
    let n = i64::from(n);
    // c_k = ⌈k·short/long⌉ − 1, which for k·short ≥ 1 is ⌊(k·short − 1)/long⌋.
    let lower_row = |k: i64| {
        if short == 0 {
            0
        } else {
            (k * short - 1) / long
        }
    };
    let q = lower_row(n);
    let mut rows = [0; MAX_N as usize + 1];
    let mut thresholds = [(0, 0); MAX_N as usize];
    for k in 1..=width {
        let c = lower_row(k as i64);
        rows[k] = c;
        thresholds[k - 1] = (2 * (n - k as i64) * short - 2 * (q - c) * long, k);
    }
    let thresholds = &mut thresholds[..width];
    thresholds.sort_unstable();
    // The pattern of the rows `rows[1..=width]` above `rows[0] = 0`.
    let word = |rows: &[i64]| {
        (1..=width)
            .filter(|&k| rows[k] > rows[k - 1])
            .fold(0u32, |w, k| w | 1 << (k - 1))
    };
    let mut patterns = [0; MAX_N as usize + 1];
    patterns[0] = word(&rows);
    // Past each threshold, its column takes its upper row.
    for (passed, &(_, k)) in thresholds.iter().enumerate() {
        rows[k] += 1;
        patterns[passed + 1] = word(&rows);
    }

    // Per step: the pattern is the one of D's interval, found by a binary
    // search over the sorted thresholds (⌈log₂(n + 1)⌉ comparisons where
    // the midpoint line makes n).
    let choose = |d: i64| {
        let passed = thresholds.partition_point(|&(t, _)| t < d + tie);
        NStep {
            d,
            rises: patterns[passed],
        }
    };
    plot(from);
    let mut d = 2 * n * short - (2 * q + 1) * long;
    let (mut i, mut j) = (0, 0);
    while i + n <= long {
        let chosen = choose(d);
        // Reported as decided: before its pixels, before `d` moves on.
        step(chosen);
        for k in 1..=n {
            plot(pixel(i + k, j + chosen.row(k as u32)));
        }
        let r = i64::from(chosen.rises.count_ones());
        d += 2 * n * short - 2 * r * long;
        i += n;
        j += r;
    }
    // Fewer than n columns are left: the start of the pattern D picks
    // here (the ideal line goes on beyond `to`), reported by nothing, as
    // the double step's endpoint.
    let last = choose(d);
    for k in 1..=long - i {
        plot(pixel(i + k, j + last.row(k as u32)));
    }
    // END SOLUTION
}
