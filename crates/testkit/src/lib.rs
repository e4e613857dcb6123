//! Test helpers for the course: every raster a test checks can be seen.
//!
//! - [`raster`]: compare pixel sets and canvases, failing with an ASCII diff
//!   (`#` in both, `+` only in yours, `-` only expected) that the grader
//!   shows to students;
//! - [`assert_raster_snapshot!`]: an `insta` snapshot of a canvas as ASCII
//!   art, reviewed by tutors with `cargo insta review`;
//! - [`image`]: compare a canvas with a reference PNG within a tolerance,
//!   writing `yours.png`, `reference.png` and `difference.png` before the
//!   test can fail ([`image::check_image`], its verdict asserted last);
//! - [`strategies`]: proptest strategies for points, pixels, lines and
//!   colours, including hostile values (NaN, infinities, 1e30);
//! - [`pixels`]: collecting what a rasterizer plots, expected pixels as
//!   literal grids ([`grid!`]), duplicates and counts;
//! - [`definitions`]: the pixels of lines, circles and triangles by their
//!   definitions, exactly (what topics 01–03 compare with), and the clip
//!   volume's planes (topic 04);
//! - [`oracles`]: values by their definitions (binomials, Bernstein
//!   polynomials), never by the algorithms the tasks teach;
//! - [`domains`]: regular grids and lattices of parameters, built without
//!   the primitive generator;
//! - [`topology`]: how the triangles of a mesh meet (directed edge counts);
//! - [`test`]: `#[testkit::test]`, the `#[test]` of every graded test: it
//!   tells the grader that the test ran to its end over a channel the code
//!   under test cannot forge.
#![warn(missing_docs)]

pub mod definitions;
pub mod domains;
pub mod image;
pub mod oracles;
pub mod pixels;
pub mod raster;
pub mod strategies;
pub mod topology;

pub use raster::{
    RASTER_DIFF_BEGIN, RASTER_DIFF_END, assert_canvas_eq, assert_pixels_eq, canvas_from_pixels,
    pixel_diff,
};
pub use strategies::proptest_config;
pub use testkit_macros::test;

/// Re-exported so that snapshot macros work without a direct dependency.
pub use insta;

/// Snapshots a canvas as ASCII art (see [`canvas::Canvas::to_ascii`]).
///
/// `assert_raster_snapshot!(canvas)` names the snapshot after the test;
/// `assert_raster_snapshot!("name", canvas)` names it explicitly. The
/// snapshot files live in the test crate's `tests/snapshots/`.
#[macro_export]
macro_rules! assert_raster_snapshot {
    ($canvas:expr $(,)?) => {{
        let raster = ::canvas::Canvas::to_ascii(&$canvas);
        $crate::insta::assert_snapshot!(raster)
    }};
    ($name:expr, $canvas:expr $(,)?) => {{
        let raster = ::canvas::Canvas::to_ascii(&$canvas);
        $crate::insta::assert_snapshot!($name, raster)
    }};
}

/// Where tests write pictures: `$TESTKIT_OUTPUT_DIR` when set (the grader
/// sets it), otherwise `target/testkit/` of the workspace that built the
/// running test.
#[must_use]
pub fn output_dir() -> std::path::PathBuf {
    if let Some(dir) = std::env::var_os("TESTKIT_OUTPUT_DIR") {
        return dir.into();
    }
    // A test executable lives in `<target>/<profile>/deps/`.
    let target = std::env::current_exe().ok().and_then(|exe| {
        exe.ancestors()
            .find(|dir| dir.file_name().is_some_and(|n| n == "deps"))
            .and_then(|deps| deps.parent()?.parent().map(std::path::Path::to_path_buf))
    });
    target
        .unwrap_or_else(|| std::env::temp_dir().join("testkit-target"))
        .join("testkit")
}
