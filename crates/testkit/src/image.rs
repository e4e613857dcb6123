//! Comparing a rendered canvas with a reference PNG within a tolerance.
//!
//! Every comparison writes three pictures to
//! `<output_dir>/<name>/`: `yours.png`, `reference.png` and `difference.png`
//! (black where equal, red where a channel differs by more than the
//! tolerance, dim grey where it differs within it), so a student can look
//! rather than read.
//!
//! A wrong render is exactly when the pictures matter, so they are written
//! before anything can fail. [`check_image`] writes them and returns an
//! [`ImageCheck`] that holds the verdict; the test makes its other
//! assertions and ends with [`ImageCheck::assert_matches`]:
//!
//! ```no_run
//! # let canvas = canvas::Canvas::new(4, 4);
//! # let frames_agree = true;
//! use testkit::image::{Tolerance, check_image};
//! let picture = check_image("example", &canvas, "tests/images/example.png", Tolerance::EXACT);
//! assert!(frames_agree, "an exact check that may fail: the pictures are on disk already");
//! picture.assert_matches();
//! ```
//!
//! A check whose verdict is never asserted fails the test when it is
//! dropped, so forgetting the last line cannot pass a wrong picture.
//! [`assert_image_matches`] is the one-call form, for a test that checks
//! nothing but the picture.

use std::path::{Path, PathBuf};

use canvas::{Canvas, Pixel, Rgba};

/// How closely a rendered picture must match its reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    /// The largest difference in any channel (on the 0..1 scale) for a pixel
    /// to count as matching; `2.0 / 255.0` absorbs 8-bit quantization.
    pub channel: f32,
    /// The fraction of pixels (0..1) allowed to exceed `channel`, for
    /// rasterization differences at silhouettes.
    pub mismatched_fraction: f32,
}

impl Tolerance {
    /// Exact up to 8-bit quantization, no mismatching pixel.
    pub const EXACT: Self = Self {
        channel: 2.0 / 255.0,
        mismatched_fraction: 0.0,
    };
}

/// The outcome of a comparison.
#[derive(Clone, Debug, PartialEq)]
pub struct ImageComparison {
    /// Pixels whose largest channel difference exceeds the tolerance.
    pub mismatched: usize,
    /// All pixels.
    pub total: usize,
    /// The largest channel difference seen.
    pub max_difference: f32,
}

/// Compares `yours` with the PNG at `reference` and writes the three
/// pictures under `output_dir()/<name>/`; panics with the counts and the
/// picture paths if the tolerance is exceeded.
///
/// The one-call form of [`check_image`] and [`ImageCheck::assert_matches`],
/// for a test that checks nothing but the picture: a test with other
/// assertions calls [`check_image`] before them, so that its pictures are
/// written however it fails.
///
/// Set `TESTKIT_BLESS=1` to (re)write a missing or outdated reference from
/// `yours`: do that only with a reference solution whose picture you have
/// looked at.
#[track_caller]
pub fn assert_image_matches(
    name: &str,
    yours: &Canvas,
    reference: impl AsRef<Path>,
    tolerance: Tolerance,
) {
    check_image(name, yours, reference, tolerance).assert_matches();
}

/// Writes `yours.png`, `reference.png` and `difference.png` under
/// `output_dir()/<name>/` and compares `yours` with the PNG at
/// `reference`; nothing fails yet: the verdict waits in the returned
/// check for [`ImageCheck::assert_matches`] at the end of the test.
///
/// `yours.png` is written even when the reference cannot be read (a
/// missing reference fails at the assertion). `TESTKIT_BLESS=1` works as
/// for [`assert_image_matches`].
pub fn check_image(
    name: &str,
    yours: &Canvas,
    reference: impl AsRef<Path>,
    tolerance: Tolerance,
) -> ImageCheck {
    check_image_in(&crate::output_dir(), name, yours, reference, tolerance)
}

/// [`check_image`] with the pictures under `output_dir/<name>/` instead of
/// [`crate::output_dir`]'s folder: for tests of the check itself, which
/// must not write into the course's pictures.
pub fn check_image_in(
    output_dir: &Path,
    name: &str,
    yours: &Canvas,
    reference: impl AsRef<Path>,
    tolerance: Tolerance,
) -> ImageCheck {
    let reference = reference.as_ref();
    let dir = output_dir.join(name);
    let failure = compare_and_write(&dir, name, yours, reference, tolerance).err();
    ImageCheck {
        name: name.to_owned(),
        dir,
        failure,
        asserted: false,
    }
}

/// Writes the three pictures into `dir` and says why `yours` fails its
/// reference, if it does.
fn compare_and_write(
    dir: &Path,
    name: &str,
    yours: &Canvas,
    reference: &Path,
    tolerance: Tolerance,
) -> Result<(), String> {
    // Yours first and on its own: it is worth looking at even when there
    // is no reference to compare it with.
    let yours_written = yours
        .save_png(dir.join("yours.png"))
        .map_err(|e| e.to_string());
    if std::env::var_os("TESTKIT_BLESS").is_some_and(|v| v == "1")
        && let Err(e) = yours.save_png(reference)
    {
        return Err(format!("{name}: could not bless the reference image: {e}"));
    }
    let expected = Canvas::load_png(reference).map_err(|e| {
        format!(
            "{name}: could not read the reference image: {e}\n{}",
            written(dir, yours_written.clone().map(|()| "yours.png"))
        )
    })?;
    let comparison = compare(&expected, yours, tolerance.channel);
    let pictures = yours_written
        .and(write_reference_and_difference(
            dir,
            &expected,
            yours,
            tolerance.channel,
        ))
        .map(|()| "{yours,reference,difference}.png");
    let allowed = (tolerance.mismatched_fraction * comparison.total as f32).floor() as usize;
    let sizes_match = (expected.width(), expected.height()) == (yours.width(), yours.height());
    if sizes_match && comparison.mismatched <= allowed {
        return Ok(());
    }
    Err(format!(
        "{name}: the picture differs from {}: {} of {} pixels off by more than {} \
         (allowed: {allowed}; largest difference {:.3}); sizes {}x{} vs yours {}x{}\n{}",
        reference.display(),
        comparison.mismatched,
        comparison.total,
        tolerance.channel,
        comparison.max_difference,
        expected.width(),
        expected.height(),
        yours.width(),
        yours.height(),
        written(dir, pictures),
    ))
}

/// Where the pictures are, or why they could not be written.
fn written(dir: &Path, files: Result<&str, String>) -> String {
    match files {
        Ok(files) => format!("pictures: {}/{files}", dir.display()),
        Err(e) => format!("(pictures could not be written: {e})"),
    }
}

/// A picture compared with its reference and written to disk, whose
/// verdict is still to be asserted: what [`check_image`] returns.
///
/// Call [`assert_matches`](Self::assert_matches) once the test's other
/// assertions are made. A check dropped without it fails the test (a
/// picture test that forgot its verdict would otherwise pass whatever it
/// drew); a check dropped while the test is already failing stays quiet
/// but for a line naming its pictures.
#[must_use = "the pictures are written, but nothing fails until `assert_matches` is called"]
#[derive(Debug)]
pub struct ImageCheck {
    name: String,
    dir: PathBuf,
    /// Why the picture fails, with where its pictures are; `None` when it
    /// matches.
    failure: Option<String>,
    asserted: bool,
}

impl ImageCheck {
    /// The folder that holds `yours.png`, `reference.png` and
    /// `difference.png`.
    #[must_use]
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// Why the picture fails its reference (the counts and where the
    /// pictures are), or `None` when it matches.
    #[must_use]
    pub fn failure(&self) -> Option<&str> {
        self.failure.as_deref()
    }

    /// Panics with the counts and the picture paths if the picture does
    /// not match its reference within the tolerance.
    #[track_caller]
    pub fn assert_matches(mut self) {
        self.asserted = true;
        if let Some(failure) = self.failure.take() {
            panic!("{failure}");
        }
    }
}

impl Drop for ImageCheck {
    fn drop(&mut self) {
        if self.asserted {
            return;
        }
        if std::thread::panicking() {
            // The test failed before its verdict: its own message is the
            // one to read, the pictures are the ones to look at.
            eprintln!(
                "{}: pictures in {} ({})",
                self.name,
                self.dir.display(),
                if self.failure.is_some() {
                    "the picture differs from its reference as well"
                } else {
                    "the picture matches its reference"
                }
            );
        } else {
            panic!(
                "{}: the picture was checked but its verdict never asserted: end the test \
                 with `.assert_matches()` on its `ImageCheck`",
                self.name
            );
        }
    }
}

/// Counts the pixels of `yours` that differ from `expected` by more than
/// `channel` in some channel; pixels outside either canvas count as
/// mismatched.
#[must_use]
pub fn compare(expected: &Canvas, yours: &Canvas, channel: f32) -> ImageComparison {
    let width = expected.width().max(yours.width());
    let height = expected.height().max(yours.height());
    let mut result = ImageComparison {
        mismatched: 0,
        total: (width as usize) * (height as usize),
        max_difference: 0.0,
    };
    for y in 0..height as i32 {
        for x in 0..width as i32 {
            let p = Pixel::new(x, y);
            let d = match (expected.get(p), yours.get(p)) {
                (Some(e), Some(o)) => difference(e, o),
                _ => f32::INFINITY,
            };
            result.max_difference = result.max_difference.max(d);
            // NaN never matches: `d <= channel` is false for it.
            if d.is_nan() || d > channel {
                result.mismatched += 1;
            }
        }
    }
    result
}

/// The largest channel difference between two colours after 8-bit
/// quantization (what a PNG can hold).
fn difference(a: Rgba, b: Rgba) -> f32 {
    let (a, b) = (a.to_rgba8(), b.to_rgba8());
    a.iter()
        .zip(b.iter())
        .map(|(&x, &y)| f32::from(x.abs_diff(y)) / 255.0)
        .fold(0.0, f32::max)
}

/// Writes `reference.png` and `difference.png` beside `yours.png`.
fn write_reference_and_difference(
    dir: &Path,
    expected: &Canvas,
    yours: &Canvas,
    channel: f32,
) -> Result<(), String> {
    let saved = |picture: &Canvas, file: &str| {
        picture
            .save_png(dir.join(file))
            .map_err(|e| format!("{file}: {e}"))
    };
    saved(expected, "reference.png")?;
    let mut diff = Canvas::new(
        expected.width().max(yours.width()),
        expected.height().max(yours.height()),
    );
    for (p, _) in diff.clone().enumerate() {
        let d = match (expected.get(p), yours.get(p)) {
            (Some(e), Some(o)) => difference(e, o),
            _ => f32::INFINITY,
        };
        let shown = if d > channel {
            Rgba::RED
        } else if d > 0.0 {
            Rgba::grey(0.25)
        } else {
            Rgba::BLACK
        };
        diff.set(p, shown);
    }
    saved(&diff, "difference.png")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identical_canvases_match_and_one_pixel_off_does_not() {
        let a = Canvas::new(4, 4);
        let mut b = a.clone();
        assert_eq!(compare(&a, &b, 0.0).mismatched, 0);
        b.set(Pixel::new(1, 2), Rgba::WHITE);
        let c = compare(&a, &b, 2.0 / 255.0);
        assert_eq!((c.mismatched, c.total), (1, 16));
        assert_eq!(c.max_difference, 1.0);
    }

    #[test]
    fn size_mismatch_counts_missing_pixels() {
        let c = compare(&Canvas::new(2, 2), &Canvas::new(3, 2), 0.0);
        assert_eq!((c.mismatched, c.total), (2, 6));
    }
}
