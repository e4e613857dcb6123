//! The specification both line clippers meet, written once: plain
//! functions of the clipper, which each task's test file names as its
//! tests with [`line_clipping_spec!`], so the two tasks are graded on
//! their own and agree with each other through the definition in
//! `super::visible_part`.
//!
//! The assertions live in these functions, not in the macro: a panic
//! inside a macro's expansion is reported at the macro call (`tests/
//! liang_barsky.rs:7`), a panic here at its own line of this file.

use canvas::{MAX_COORD, Vec2, Viewport};
use clipping::{ClipError, ClipWindow, Segment};
use proptest::prelude::*;

/// A line clipper: Cohen-Sutherland or Liang-Barsky.
pub type Clipper = fn(Segment, ClipWindow) -> Result<Option<Segment>, ClipError>;

/// Endpoints in `±30` in `f32`: rounding stays far below this.
pub const TOLERANCE: f64 = 1e-4;

/// The clipper's answer for valid input.
#[track_caller]
pub fn clip(clipper: Clipper, segment: Segment, window: ClipWindow) -> Option<Segment> {
    match clipper(segment, window) {
        Ok(piece) => piece,
        Err(e) => panic!("{segment:?} in {window:?} is valid input, yours answers {e:?}"),
    }
}

/// The segment `(x0, y0) → (x1, y1)`.
pub fn s(x0: f32, y0: f32, x1: f32, y1: f32) -> Segment {
    Segment::new(Vec2::new(x0, y0), Vec2::new(x1, y1))
}

/// `[0, 10]²`.
pub fn ten() -> ClipWindow {
    ClipWindow::try_new(Vec2::ZERO, Vec2::splat(10.0)).expect("valid window")
}

/// A segment whose visible part is longer than rounding is kept.
pub fn kept_if_visible(
    got: Option<Segment>,
    segment: Segment,
    window: ClipWindow,
) -> Result<(), TestCaseError> {
    let visible =
        super::visible_part(segment, window).is_some_and(|[a, b]| super::dist(a, b) > 1e-3);
    prop_assert!(
        !visible || got.is_some(),
        "{:?} crosses {:?}: its visible part {:?} is longer than rounding and is kept, yours \
         rejected it",
        segment,
        window,
        super::visible_part(segment, window)
    );
    Ok(())
}

/// The clipped piece is `expected`, to within `1e-5`, or both are `None`.
#[track_caller]
pub fn assert_close(got: Option<Segment>, expected: Option<Segment>, rule: &str) {
    match (got, expected) {
        (Some(g), Some(e)) => assert!(
            g.from.distance(e.from) <= 1e-5 && g.to.distance(e.to) <= 1e-5,
            "{rule}: expected {e:?}, got {g:?}"
        ),
        (g, e) => assert_eq!(g, e, "{rule}"),
    }
}

/// What a segment parallel to two borders (`p_k = 0` for them) must give.
const PARALLEL: &str = "a segment parallel to two borders (p_k = 0 there) is cut only at the \
                        other two; for the parallel ones test the side it lies on (q_k ≥ 0), \
                        never divide by p_k";

pub fn segment_inside_is_unchanged(clipper: Clipper) {
    for seg in [
        s(1.0, 2.0, 9.0, 7.5),
        s(0.0, 0.0, 10.0, 10.0),
        s(3.0, 3.0, 3.0, 3.0),
    ] {
        assert_eq!(
            clip(clipper, seg, ten()),
            Some(seg),
            "{seg:?} in [0, 10]²: a segment inside the window (its border included) is kept as \
             it is"
        );
    }
}

pub fn horizontal_segment_is_cut_at_both_sides_keeping_its_direction(clipper: Clipper) {
    //   ─ ─ ┌──────────┐─ ─ →       (−5, 5) → (15, 5)
    //       │●────────●│            becomes (0, 5) → (10, 5)
    //       └──────────┘
    for (seg, piece) in [
        (s(-5.0, 5.0, 15.0, 5.0), s(0.0, 5.0, 10.0, 5.0)),
        (s(15.0, 5.0, -5.0, 5.0), s(10.0, 5.0, 0.0, 5.0)),
        (s(5.0, -5.0, 5.0, 15.0), s(5.0, 0.0, 5.0, 10.0)),
        (s(5.0, 15.0, 5.0, -5.0), s(5.0, 10.0, 5.0, 0.0)),
    ] {
        assert_eq!(
            clip(clipper, seg, ten()),
            Some(piece),
            "{seg:?} in [0, 10]²: {PARALLEL}; the piece keeps the segment's direction"
        );
    }
}

pub fn diagonal_segment_is_cut_at_two_borders(clipper: Clipper) {
    // y = x / 2 + 4 from x = −4 to x = 16: enters at (0, 4), leaves
    // the top at (12, 10)... past the right border first, at (10, 9).
    let rule = "the piece runs from the last border the line enters by to the first it \
                leaves by";
    assert_close(
        clip(clipper, s(-4.0, 2.0, 16.0, 12.0), ten()),
        Some(s(0.0, 4.0, 10.0, 9.0)),
        rule,
    );
    assert_close(
        clip(clipper, s(16.0, 12.0, -4.0, 2.0), ten()),
        Some(s(10.0, 9.0, 0.0, 4.0)),
        rule,
    );
    // Through two corner regions: from below-left to above-right.
    //   (−2, −6) → (8, 14): y = 2x − 2, enters at y = 0 (x = 1),
    //   leaves at y = 10 (x = 6).
    assert_close(
        clip(clipper, s(-2.0, -6.0, 8.0, 14.0), ten()),
        Some(s(1.0, 0.0, 6.0, 10.0)),
        rule,
    );
}

pub fn segment_touching_a_corner_is_that_point(clipper: Clipper) {
    //        ╲
    //         ●┌───     (−1, 1) → (1, −1) meets the window only
    //          ╲│       at its corner (0, 0)
    let got = clip(clipper, s(-1.0, 1.0, 1.0, -1.0), ten())
        .expect("(−1, 1) → (1, −1) touches the corner (0, 0) of [0, 10]²: the window is closed");
    assert!(
        got.from.distance(Vec2::ZERO) <= 1e-6 && got.to.distance(Vec2::ZERO) <= 1e-6,
        "a segment touching only the corner (0, 0) clips to that point, yours: {got:?}"
    );
}

pub fn segments_that_miss_are_rejected(clipper: Clipper) {
    // Both endpoints beyond the same border (trivial reject).
    assert_eq!(
        clip(clipper, s(-5.0, -1.0, 15.0, -1.0), ten()),
        None,
        "(−5, −1) → (15, −1) runs parallel to the bottom border y = 0, below it \
         (p_k = 0, q_k < 0): rejected"
    );
    assert_eq!(
        clip(clipper, s(11.0, -3.0, 12.0, 30.0), ten()),
        None,
        "(11, −3) → (12, 30) lies wholly right of [0, 10]²"
    );
    // Outcodes LEFT and TOP share no bit, yet the line y = x + 11
    // passes above the corner (0, 10).
    //
    //      ●  (2, 13)
    //     ╱
    //    ╱ ┌────
    //   ●  │         (−2, 9)
    for seg in [s(-2.0, 9.0, 2.0, 13.0), s(2.0, 13.0, -2.0, 9.0)] {
        assert_eq!(
            clip(clipper, seg, ten()),
            None,
            "{seg:?} passes above the corner (0, 10): no trivial reject, but cut at \
             the left border it lies above the window, and nothing is left"
        );
    }
    // A point outside.
    assert_eq!(
        clip(clipper, s(-1.0, 5.0, -1.0, 5.0), ten()),
        None,
        "a segment of length zero outside the window (p_k = 0 for every border): \
         rejected by the border it lies beyond"
    );
    // While one that crosses is kept.
    assert_eq!(
        clip(clipper, s(-5.0, 5.0, 15.0, 5.0), ten()),
        Some(s(0.0, 5.0, 10.0, 5.0)),
        "{PARALLEL}"
    );
}

pub fn viewport_window_reaches_half_a_pixel_beyond_the_border_pixels(clipper: Clipper) {
    // Pixels 0..=9 cover [−½, 9½] (slides: y_min − 0.5, y_max + 0.5).
    let window = ClipWindow::from_viewport(Viewport::new(0, 0, 9, 9)).expect("non-empty");
    let rule = "the window of pixels 0..=9 is [−½, 9½]²";
    assert_close(
        clip(clipper, s(-3.0, 2.0, 12.0, 2.0), window),
        Some(s(-0.5, 2.0, 9.5, 2.0)),
        rule,
    );
    assert_close(
        clip(clipper, s(4.0, -8.0, 4.0, 30.0), window),
        Some(s(4.0, -0.5, 4.0, 9.5)),
        rule,
    );
    assert_eq!(
        clip(clipper, s(-0.6, 0.0, -0.6, 9.0), window),
        None,
        "x = −0.6 runs parallel to the left border x = −0.5, outside it (q_k < 0 with \
         p_k = 0): rejected"
    );
}

pub fn degenerate_windows_clip_to_a_line_or_a_point(clipper: Clipper) {
    let line = ClipWindow::try_new(Vec2::new(0.0, 2.0), Vec2::new(10.0, 2.0)).expect("valid");
    assert_eq!(
        clip(clipper, s(-5.0, 2.0, 15.0, 2.0), line),
        Some(s(0.0, 2.0, 10.0, 2.0)),
        "the window y = 2, 0 ≤ x ≤ 10 (zero high) and a segment along it: {PARALLEL}; \
         lying on a border (q_k = 0) is inside"
    );
    assert_close(
        clip(clipper, s(0.0, 0.0, 4.0, 4.0), line),
        Some(s(2.0, 2.0, 2.0, 2.0)),
        "a diagonal crosses the window y = 2 (zero high) in one point",
    );
    assert_eq!(
        clip(clipper, s(0.0, 3.0, 4.0, 3.0), line),
        None,
        "y = 3 runs parallel to the window y = 2 (zero high), above it: rejected"
    );
}

pub fn very_long_segments_are_cut_to_the_window(clipper: Clipper) {
    let m = MAX_COORD as f32;
    let got = clip(clipper, s(-m, -m, m, m), ten()).expect(
        "(−MAX_COORD, −MAX_COORD) → (MAX_COORD, MAX_COORD) crosses [0, 10]²: a piece is left, \
         yours None",
    );
    assert_close(
        Some(got),
        Some(s(0.0, 0.0, 10.0, 10.0)),
        "a diagonal from −MAX_COORD to MAX_COORD",
    );
    let got = clip(clipper, s(-m, 5.0, m, 5.0), ten())
        .expect("(−MAX_COORD, 5) → (MAX_COORD, 5) crosses [0, 10]²: a piece is left, yours None");
    assert_eq!(
        got,
        s(0.0, 5.0, 10.0, 5.0),
        "a horizontal segment from −MAX_COORD to MAX_COORD: {PARALLEL}"
    );
}

pub fn bad_endpoints_are_errors_not_panics(clipper: Clipper) {
    let window = ten();
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        assert_eq!(
            clipper(s(bad, 0.0, 1.0, 1.0), window),
            Err(ClipError::NonFinite { index: 0 }),
            "({bad}, 0) → (1, 1): a NaN or infinite coordinate is ClipError::NonFinite naming \
             the endpoint, 0 here, not a panic"
        );
        assert_eq!(
            clipper(s(0.0, 0.0, 1.0, bad), window),
            Err(ClipError::NonFinite { index: 1 }),
            "(0, 0) → (1, {bad}): a NaN or infinite coordinate is ClipError::NonFinite naming \
             the endpoint, 1 here, not a panic"
        );
    }
    for huge in [1e30, -1e9, f32::MAX, 2.0 * MAX_COORD as f32] {
        assert_eq!(
            clipper(s(0.0, 0.0, huge, 1.0), window),
            Err(ClipError::OutOfRange { index: 1 }),
            "(0, 0) → ({huge}, 1): a coordinate beyond ±MAX_COORD is ClipError::OutOfRange \
             naming the endpoint, 1 here"
        );
        assert_eq!(
            clipper(s(0.0, huge, 1.0, 1.0), window),
            Err(ClipError::OutOfRange { index: 0 }),
            "(0, {huge}) → (1, 1): a coordinate beyond ±MAX_COORD is ClipError::OutOfRange \
             naming the endpoint, 0 here"
        );
    }
}

pub fn visible_part_is_the_definitions(
    clipper: Clipper,
    segment: Segment,
    window: ClipWindow,
) -> Result<(), TestCaseError> {
    let got = clip(clipper, segment, window);
    let verdict = super::matches_visible_part(got, segment, window, TOLERANCE);
    prop_assert!(
        verdict.is_ok(),
        "{:?} in {:?}: {} (the visible part is the points of the segment in the closed \
         window)",
        segment,
        window,
        verdict.err().unwrap_or_default()
    );
    Ok(())
}

pub fn result_lies_in_the_window_on_the_segment_in_its_direction(
    clipper: Clipper,
    segment: Segment,
    window: ClipWindow,
) -> Result<(), TestCaseError> {
    kept_if_visible(clip(clipper, segment, window), segment, window)?;
    if let Some(got) = clip(clipper, segment, window) {
        let grown = ClipWindow::try_new(
            window.min() - Vec2::splat(1e-4),
            window.max() + Vec2::splat(1e-4),
        )
        .expect("valid window");
        prop_assert!(
            grown.contains(got.from) && grown.contains(got.to),
            "{:?} in {:?}: the piece lies in the window (to 1e-4), yours {:?} leaves it",
            segment,
            window,
            got
        );
        let d = segment.to - segment.from;
        prop_assert!(
            (got.to - got.from).dot(d) >= -1e-6,
            "{:?} in {:?}: the piece keeps the segment's direction, yours {:?} runs the other way",
            segment,
            window,
            got
        );
        for p in [got.from, got.to] {
            let off = (p - segment.from).perp_dot(d).abs() / d.length().max(1e-30);
            prop_assert!(
                off <= 1e-3 || d.length() == 0.0,
                "{:?} in {:?}: the piece lies on the segment's line (to 1e-3), yours {:?} has the \
                 endpoint {} off it by {}",
                segment,
                window,
                got,
                p,
                off
            );
        }
    }
    Ok(())
}

pub fn clipping_twice_changes_nothing(
    clipper: Clipper,
    segment: Segment,
    window: ClipWindow,
) -> Result<(), TestCaseError> {
    kept_if_visible(clip(clipper, segment, window), segment, window)?;
    if let Some(once) = clip(clipper, segment, window) {
        // A piece a rounding error outside may be dropped.
        match clip(clipper, once, window) {
            Some(twice) => prop_assert!(
                twice.from.distance(once.from) <= 1e-4 && twice.to.distance(once.to) <= 1e-4,
                "a clipped piece lies in the window and must come back unchanged: {:?} then {:?}",
                once,
                twice
            ),
            None => prop_assert!(
                once.from.distance(once.to) <= 1e-4,
                "a clipped piece lies in the window, yet clipping it again rejects it: {:?}",
                once
            ),
        }
    }
    Ok(())
}

pub fn reversed_segment_gives_the_reversed_piece(
    clipper: Clipper,
    segment: Segment,
    window: ClipWindow,
) -> Result<(), TestCaseError> {
    let forward = clip(clipper, segment, window);
    let backward = clip(clipper, Segment::new(segment.to, segment.from), window);
    kept_if_visible(forward, segment, window)?;
    match (forward, backward) {
        (Some(f), Some(b)) => prop_assert!(
            f.from.distance(b.to) <= 1e-4 && f.to.distance(b.from) <= 1e-4,
            "{:?} in {:?}: the reversed segment gives the reversed piece (to 1e-4); yours \
             {:?} forwards, {:?} reversed",
            segment,
            window,
            f,
            b
        ),
        (None, None) => {}
        (Some(x), None) | (None, Some(x)) => {
            prop_assert!(
                x.from.distance(x.to) <= 1e-4,
                "{:?} in {:?}: the reversed segment gives the reversed piece; yours keeps {:?} \
                 {} and rejects it {}",
                segment,
                window,
                x,
                if forward.is_some() {
                    "forwards"
                } else {
                    "reversed"
                },
                if forward.is_some() {
                    "reversed"
                } else {
                    "forwards"
                }
            )
        }
    }
    Ok(())
}

/// Names the shared tests for `$clip: fn(Segment, ClipWindow) ->
/// Result<Option<Segment>, ClipError>`, each calling the function of the
/// same name above; also brings `clip`, `s` and `ten` into the test file
/// for its own tests.
#[macro_export]
macro_rules! line_clipping_spec {
    ($clip:path) => {
        #[allow(unused_imports)] // for the test file's own tests
        use canvas::Vec2;
        use clipping::{ClipWindow, Segment};
        #[allow(unused_imports)]
        use common::lines::{s, ten};
        use proptest::prelude::*;

        /// The clipper's answer for valid input.
        #[allow(dead_code)]
        #[track_caller]
        fn clip(segment: Segment, window: ClipWindow) -> Option<Segment> {
            common::lines::clip($clip, segment, window)
        }

        line_clipping_spec!(@plain $clip;
            segment_inside_is_unchanged,
            horizontal_segment_is_cut_at_both_sides_keeping_its_direction,
            diagonal_segment_is_cut_at_two_borders,
            segment_touching_a_corner_is_that_point,
            segments_that_miss_are_rejected,
            viewport_window_reaches_half_a_pixel_beyond_the_border_pixels,
            degenerate_windows_clip_to_a_line_or_a_point,
            very_long_segments_are_cut_to_the_window,
            bad_endpoints_are_errors_not_panics,
        );

        line_clipping_spec!(@property $clip;
            visible_part_is_the_definitions,
            result_lies_in_the_window_on_the_segment_in_its_direction,
            clipping_twice_changes_nothing,
            reversed_segment_gives_the_reversed_piece,
        );
    };
    (@plain $clip:path; $($name:ident),* $(,)?) => {
        $(
            #[testkit::test]
            fn $name() {
                common::lines::$name($clip);
            }
        )*
    };
    (@property $clip:path; $($name:ident),* $(,)?) => {
        $(
            proptest! {
                #![proptest_config(testkit::proptest_config())]

                #[testkit::test]
                fn $name(segment in common::segment(), window in common::window()) {
                    common::lines::$name($clip, segment, window)?;
                }
            }
        )*
    };
}
