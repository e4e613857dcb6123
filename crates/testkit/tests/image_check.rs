//! A picture test that fails still leaves its pictures: `check_image`
//! writes `yours.png`, `reference.png` and `difference.png` before the test
//! can fail, and its verdict cannot be forgotten.
//!
//! Each test plants a render in a scratch folder of its own and runs the
//! picture test's body under `catch_unwind`, as libtest would run it.

use std::any::Any;
use std::panic::{self, AssertUnwindSafe};
use std::path::{Path, PathBuf};

use canvas::{Canvas, Pixel, Rgba};
use testkit::image::{ImageCheck, Tolerance, check_image_in};

/// The three pictures every comparison writes.
const PICTURES: [&str; 3] = ["yours.png", "reference.png", "difference.png"];

/// The pixel the planted render gets wrong.
const PLANTED: Pixel = Pixel::new(2, 1);

/// A folder of this process and test alone, emptied, removed when dropped.
struct Scratch(PathBuf);

impl Scratch {
    fn new(test: &str) -> Self {
        let dir =
            std::env::temp_dir().join(format!("testkit-image-check-{}-{test}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("a scratch folder");
        Self(dir)
    }

    /// Where the pictures go (what `output_dir()` is in a real test).
    fn output(&self) -> PathBuf {
        self.0.join("output")
    }

    /// The right picture, saved as the reference PNG.
    fn reference(&self) -> PathBuf {
        let path = self.0.join("reference-source.png");
        right().save_png(&path).expect("the reference written");
        path
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// A small picture with some structure: a grey ramp.
fn right() -> Canvas {
    let mut canvas = Canvas::new(6, 4);
    for (p, _) in canvas.clone().enumerate() {
        canvas.set(p, Rgba::grey(p.x as f32 / 5.0));
    }
    canvas
}

/// The right picture with one pixel wrong.
fn wrong() -> Canvas {
    let mut canvas = right();
    canvas.set(PLANTED, Rgba::GREEN);
    canvas
}

/// The panic message, as the grader shows it.
fn message(payload: &(dyn Any + Send)) -> String {
    payload
        .downcast_ref::<String>()
        .cloned()
        .or_else(|| payload.downcast_ref::<&str>().map(|s| (*s).to_owned()))
        .unwrap_or_default()
}

fn assert_pictures_written(dir: &Path) {
    for file in PICTURES {
        assert!(
            dir.join(file).is_file(),
            "{file} missing in {}",
            dir.display()
        );
    }
}

/// The issue this guards against: an exact frame comparison that fails
/// before the picture is compared left no picture, exactly when the
/// render was wrong.
#[test]
fn a_wrong_render_failing_an_exact_check_still_writes_its_three_pictures() {
    let scratch = Scratch::new("exact");
    let reference = scratch.reference();
    let outcome = panic::catch_unwind(|| {
        let yours = wrong();
        let picture = check_image_in(
            &scratch.output(),
            "planted",
            &yours,
            &reference,
            Tolerance::EXACT,
        );
        assert_eq!(yours, right(), "the exact frame comparison");
        picture.assert_matches();
    });
    let payload = outcome.expect_err("the planted render must fail its test");
    assert!(
        message(payload.as_ref()).contains("the exact frame comparison"),
        "the test fails with its own assertion's message, not the picture's: {:?}",
        message(payload.as_ref())
    );
    let dir = scratch.output().join("planted");
    assert_pictures_written(&dir);
    let difference = Canvas::load_png(dir.join("difference.png")).expect("a PNG");
    assert_eq!(
        difference.pixels_not(Rgba::BLACK),
        vec![PLANTED],
        "the difference shows the planted pixel, and nothing else"
    );
    assert_eq!(difference.get(PLANTED), Some(Rgba::RED));
}

#[test]
fn a_wrong_render_fails_at_the_verdict_naming_its_pictures() {
    let scratch = Scratch::new("verdict");
    let reference = scratch.reference();
    let picture = check_image_in(
        &scratch.output(),
        "planted",
        &wrong(),
        &reference,
        Tolerance::EXACT,
    );
    assert_pictures_written(picture.dir());
    let failure = picture
        .failure()
        .expect("one pixel off fails EXACT")
        .to_owned();
    assert!(failure.contains("1 of 24 pixels"), "{failure}");
    assert!(
        failure.contains("{yours,reference,difference}.png"),
        "{failure}"
    );
    let payload = panic::catch_unwind(AssertUnwindSafe(|| picture.assert_matches()))
        .expect_err("the verdict fails");
    assert_eq!(message(payload.as_ref()), failure);
}

#[test]
fn a_right_render_passes_and_writes_its_three_pictures() {
    let scratch = Scratch::new("right");
    let reference = scratch.reference();
    let picture = check_image_in(
        &scratch.output(),
        "right",
        &right(),
        &reference,
        Tolerance::EXACT,
    );
    assert_eq!(picture.failure(), None);
    assert_pictures_written(picture.dir());
    picture.assert_matches();
}

#[test]
fn a_verdict_never_asserted_fails_the_test() {
    let scratch = Scratch::new("forgotten");
    let reference = scratch.reference();
    let outcome = panic::catch_unwind(|| {
        // A right picture: the forgotten verdict alone must fail.
        let _forgotten: ImageCheck = check_image_in(
            &scratch.output(),
            "forgotten",
            &right(),
            &reference,
            Tolerance::EXACT,
        );
    });
    let payload = outcome.expect_err("dropping an unasserted check fails");
    assert!(
        message(payload.as_ref()).contains("never asserted"),
        "{:?}",
        message(payload.as_ref())
    );
}

#[test]
fn a_missing_reference_still_writes_yours_and_fails_at_the_verdict() {
    let scratch = Scratch::new("missing");
    let picture = check_image_in(
        &scratch.output(),
        "unreferenced",
        &right(),
        scratch.0.join("no-such-reference.png"),
        Tolerance::EXACT,
    );
    assert!(picture.dir().join("yours.png").is_file());
    let failure = picture.failure().expect("no reference, no pass");
    assert!(
        failure.contains("could not read the reference image"),
        "{failure}"
    );
    let outcome = panic::catch_unwind(AssertUnwindSafe(|| picture.assert_matches()));
    assert!(outcome.is_err(), "a missing reference fails the test");
}
