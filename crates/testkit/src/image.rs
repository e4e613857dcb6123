//! Comparing a rendered canvas with a reference PNG within a tolerance.
//!
//! Every comparison writes three pictures to
//! `<output_dir>/<name>/`: `yours.png`, `reference.png` and `difference.png`
//! (black where equal, red where a channel differs by more than the
//! tolerance, dim grey where it differs within it), so a student can look
//! rather than read.

use std::path::Path;

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
    let reference = reference.as_ref();
    if std::env::var_os("TESTKIT_BLESS").is_some_and(|v| v == "1")
        && let Err(e) = yours.save_png(reference)
    {
        panic!("{name}: could not bless the reference image: {e}");
    }
    let expected = match Canvas::load_png(reference) {
        Ok(c) => c,
        Err(e) => panic!("{name}: could not read the reference image: {e}"),
    };
    let dir = crate::output_dir().join(name);
    let comparison = compare(&expected, yours, tolerance.channel);
    let written = write_pictures(&dir, &expected, yours, tolerance.channel);
    let allowed = (tolerance.mismatched_fraction * comparison.total as f32).floor() as usize;
    let sizes_match = (expected.width(), expected.height()) == (yours.width(), yours.height());
    if !sizes_match || comparison.mismatched > allowed {
        let pictures = match written {
            Ok(()) => format!(
                "pictures: {}/{{yours,reference,difference}}.png",
                dir.display()
            ),
            Err(e) => format!("(pictures could not be written: {e})"),
        };
        panic!(
            "{name}: the picture differs from {}: {} of {} pixels off by more than {} \
             (allowed: {allowed}; largest difference {:.3}); sizes {}x{} vs yours {}x{}\n{pictures}",
            reference.display(),
            comparison.mismatched,
            comparison.total,
            tolerance.channel,
            comparison.max_difference,
            expected.width(),
            expected.height(),
            yours.width(),
            yours.height(),
        );
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

fn write_pictures(
    dir: &Path,
    expected: &Canvas,
    yours: &Canvas,
    channel: f32,
) -> Result<(), canvas::CanvasError> {
    yours.save_png(dir.join("yours.png"))?;
    expected.save_png(dir.join("reference.png"))?;
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
    diff.save_png(dir.join("difference.png"))
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
