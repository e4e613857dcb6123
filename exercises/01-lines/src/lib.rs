//! Topic 01: lines — DDA, midpoint, double step, viewport intersection and
//! antialiasing. The task sheet is `README.md` next to this crate.
//!
//! Each module below is one task. You edit the files in `src/`; with the
//! `reference` feature the tutor's solutions in `reference/01-lines/src/`
//! are compiled instead, against the very same tests. (Unused-variable
//! warnings are silenced in your files until you fill them in.)
#![warn(missing_docs)]

/// Task 1: the DDA line with colour and depth interpolation.
#[cfg_attr(feature = "reference", path = "../../../reference/01-lines/src/dda.rs")]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod dda;

/// Task 2: the midpoint (Bresenham) line in all octants.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/01-lines/src/midpoint.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod midpoint;

/// Task 3: the double-step (N-step) line, equal to the midpoint line.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/01-lines/src/double_step.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod double_step;

/// Task 4: the midpoint line started and ended at the viewport border.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/01-lines/src/viewport.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod viewport;

/// Task 5a: antialiasing by unweighted area sampling.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/01-lines/src/area_sampling.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod area_sampling;

/// Task 5b: antialiasing after Gupta and Sproull (cone filter, distance table).
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/01-lines/src/gupta_sproull.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod gupta_sproull;

/// Task 5c: Wu's antialiased line.
#[cfg_attr(feature = "reference", path = "../../../reference/01-lines/src/wu.rs")]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod wu;

/// Task 5d: intensity compensation for the slope of aliased lines.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/01-lines/src/slope_intensity.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod slope_intensity;
