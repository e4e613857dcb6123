//! Topic 02: circles — the midpoint circle with floats and with integers
//! only, the filled circle and the midpoint ellipse. The task sheet is
//! `README.md` next to this crate.
//!
//! Each module below is one task. You edit the files in `src/`: what you
//! build, test and grade is always your own code.
#![warn(missing_docs)]

/// Task 1: the midpoint circle as the slides give it, with 8-way symmetry.
pub mod midpoint_circle;

/// Task 2: the midpoint circle in integers only, with second-order differences.
pub mod integer_circle;

/// Task 3a: the filled circle, one span per row.
pub mod filled_circle;

/// Task 3b: the midpoint ellipse in two regions.
pub mod midpoint_ellipse;
