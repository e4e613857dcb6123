//! Topic 02: circles — the midpoint circle with floats and with integers
//! only, the filled circle and the midpoint ellipse. The task sheet is
//! `README.md` next to this crate.
//!
//! Each module below is one task. You edit the files in `src/`; with the
//! `reference` feature the tutor's solutions in `reference/02-circles/src/`
//! are compiled instead, against the very same tests. (Unused-variable
//! warnings are silenced in your files until you fill them in.)
#![warn(missing_docs)]

/// Task 1: the midpoint circle as the slides give it, with 8-way symmetry.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/02-circles/src/midpoint_circle.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod midpoint_circle;

/// Task 2: the midpoint circle in integers only, with second-order differences.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/02-circles/src/integer_circle.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod integer_circle;

/// Task 3a: the filled circle, one span per row.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/02-circles/src/filled_circle.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod filled_circle;

/// Task 3b: the midpoint ellipse in two regions.
#[cfg_attr(
    feature = "reference",
    path = "../../../reference/02-circles/src/midpoint_ellipse.rs"
)]
#[cfg_attr(
    not(feature = "reference"),
    allow(unused_variables, unused_mut, unused_imports, dead_code)
)]
pub mod midpoint_ellipse;
