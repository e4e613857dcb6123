//! Topic 01: lines — DDA, midpoint, double step, viewport intersection and
//! antialiasing. The task sheet is `README.md` next to this crate.
//!
//! Each module below is one task. You edit the files in `src/`: what you
//! build, test and grade is always your own code.
#![warn(missing_docs)]

/// Task 1: the DDA line with colour and depth interpolation.
pub mod dda;

/// Task 2: the midpoint (Bresenham) line in all octants.
pub mod midpoint;

/// Task 3: the double-step (N-step) line, equal to the midpoint line.
pub mod double_step;

/// Task 3b (bonus): the N-step line for any N, one decision per N pixels,
/// equal to the midpoint line.
pub mod n_step;

/// Task 4: the midpoint line started and ended at the viewport border.
pub mod viewport;

/// Task 5a: antialiasing by unweighted area sampling.
pub mod area_sampling;

/// Task 5b: antialiasing after Gupta and Sproull (cone filter, distance table).
pub mod gupta_sproull;

/// Task 5c: Wu's antialiased line.
pub mod wu;

/// Task 5d: intensity compensation for the slope of aliased lines.
pub mod slope_intensity;

/// Task 6 (bonus): the DDA in lanes of eight columns, each from the closed
/// form (seed 004's vectorised bonus).
pub mod vectorised_dda;

/// Task 7 (bonus): the midpoint line from both endpoints at once (the
/// slides' speed-up).
pub mod two_ended;
