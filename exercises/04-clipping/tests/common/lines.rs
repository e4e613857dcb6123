//! The specification both line clippers meet, written once: each task's
//! test file instantiates it with its own function, so the two tasks are
//! graded on their own and agree with each other through the definition
//! in `super::visible_part`.

/// Expands to the shared tests for `$clip: fn(Segment, ClipWindow) ->
/// Result<Option<Segment>, ClipError>`.
#[macro_export]
macro_rules! line_clipping_spec {
    ($clip:path) => {
        use canvas::{MAX_COORD, Vec2, Viewport};
        use clipping::{ClipError, ClipWindow, Segment};
        use proptest::prelude::*;

        /// Endpoints in `±30` in `f32`: rounding stays far below this.
        const TOLERANCE: f64 = 1e-4;

        fn clip(segment: Segment, window: ClipWindow) -> Option<Segment> {
            $clip(segment, window).expect("valid input")
        }

        fn s(x0: f32, y0: f32, x1: f32, y1: f32) -> Segment {
            Segment::new(Vec2::new(x0, y0), Vec2::new(x1, y1))
        }

        /// `[0, 10]²`.
        fn ten() -> ClipWindow {
            ClipWindow::try_new(Vec2::ZERO, Vec2::splat(10.0)).expect("valid window")
        }

        /// A segment whose visible part is longer than rounding is kept.
        fn kept_if_visible(got: Option<Segment>, segment: Segment, window: ClipWindow) -> Result<(), TestCaseError> {
            let visible = common::visible_part(segment, window).is_some_and(|[a, b]| common::dist(a, b) > 1e-3);
            if visible && got.is_none() {
                return Err(TestCaseError::fail(format!("{segment:?} crosses {window:?} but was rejected")));
            }
            Ok(())
        }

        fn assert_close(got: Option<Segment>, expected: Option<Segment>) {
            match (got, expected) {
                (Some(g), Some(e)) => assert!(
                    g.from.distance(e.from) <= 1e-5 && g.to.distance(e.to) <= 1e-5,
                    "expected {e:?}, got {g:?}"
                ),
                (g, e) => assert_eq!(g, e),
            }
        }

        #[testkit::test]
        fn segment_inside_is_unchanged() {
            for seg in [s(1.0, 2.0, 9.0, 7.5), s(0.0, 0.0, 10.0, 10.0), s(3.0, 3.0, 3.0, 3.0)] {
                assert_eq!(clip(seg, ten()), Some(seg));
            }
        }

        #[testkit::test]
        fn horizontal_segment_is_cut_at_both_sides_keeping_its_direction() {
            //   ─ ─ ┌──────────┐─ ─ →       (−5, 5) → (15, 5)
            //       │●────────●│            becomes (0, 5) → (10, 5)
            //       └──────────┘
            assert_eq!(clip(s(-5.0, 5.0, 15.0, 5.0), ten()), Some(s(0.0, 5.0, 10.0, 5.0)));
            assert_eq!(clip(s(15.0, 5.0, -5.0, 5.0), ten()), Some(s(10.0, 5.0, 0.0, 5.0)));
            assert_eq!(clip(s(5.0, -5.0, 5.0, 15.0), ten()), Some(s(5.0, 0.0, 5.0, 10.0)));
            assert_eq!(clip(s(5.0, 15.0, 5.0, -5.0), ten()), Some(s(5.0, 10.0, 5.0, 0.0)));
        }

        #[testkit::test]
        fn diagonal_segment_is_cut_at_two_borders() {
            // y = x / 2 + 4 from x = −4 to x = 16: enters at (0, 4), leaves
            // the top at (12, 10)... past the right border first, at (10, 9).
            assert_close(clip(s(-4.0, 2.0, 16.0, 12.0), ten()), Some(s(0.0, 4.0, 10.0, 9.0)));
            assert_close(clip(s(16.0, 12.0, -4.0, 2.0), ten()), Some(s(10.0, 9.0, 0.0, 4.0)));
            // Through two corner regions: from below-left to above-right.
            //   (−2, −6) → (8, 14): y = 2x − 2, enters at y = 0 (x = 1),
            //   leaves at y = 10 (x = 6).
            assert_close(clip(s(-2.0, -6.0, 8.0, 14.0), ten()), Some(s(1.0, 0.0, 6.0, 10.0)));
        }

        #[testkit::test]
        fn segment_touching_a_corner_is_that_point() {
            //        ╲
            //         ●┌───     (−1, 1) → (1, −1) meets the window only
            //          ╲│       at its corner (0, 0)
            let got = clip(s(-1.0, 1.0, 1.0, -1.0), ten()).expect("touches the corner");
            assert!(got.from.distance(Vec2::ZERO) <= 1e-6 && got.to.distance(Vec2::ZERO) <= 1e-6,
                "{got:?}");
        }

        #[testkit::test]
        fn segments_that_miss_are_rejected() {
            // Both endpoints beyond the same border (trivial reject).
            assert_eq!(clip(s(-5.0, -1.0, 15.0, -1.0), ten()), None);
            assert_eq!(clip(s(11.0, -3.0, 12.0, 30.0), ten()), None);
            // Outcodes LEFT and TOP share no bit, yet the line y = x + 11
            // passes above the corner (0, 10).
            //
            //      ●  (2, 13)
            //     ╱
            //    ╱ ┌────
            //   ●  │         (−2, 9)
            assert_eq!(clip(s(-2.0, 9.0, 2.0, 13.0), ten()), None);
            assert_eq!(clip(s(2.0, 13.0, -2.0, 9.0), ten()), None);
            // A point outside.
            assert_eq!(clip(s(-1.0, 5.0, -1.0, 5.0), ten()), None);
            // While one that crosses is kept.
            assert_eq!(clip(s(-5.0, 5.0, 15.0, 5.0), ten()), Some(s(0.0, 5.0, 10.0, 5.0)));
        }

        #[testkit::test]
        fn viewport_window_reaches_half_a_pixel_beyond_the_border_pixels() {
            // Pixels 0..=9 cover [−½, 9½] (slides: y_min − 0.5, y_max + 0.5).
            let window = ClipWindow::from_viewport(Viewport::new(0, 0, 9, 9)).expect("non-empty");
            assert_close(clip(s(-3.0, 2.0, 12.0, 2.0), window), Some(s(-0.5, 2.0, 9.5, 2.0)));
            assert_close(clip(s(4.0, -8.0, 4.0, 30.0), window), Some(s(4.0, -0.5, 4.0, 9.5)));
            assert_eq!(clip(s(-0.6, 0.0, -0.6, 9.0), window), None);
        }

        #[testkit::test]
        fn degenerate_windows_clip_to_a_line_or_a_point() {
            let line = ClipWindow::try_new(Vec2::new(0.0, 2.0), Vec2::new(10.0, 2.0)).expect("valid");
            assert_eq!(clip(s(-5.0, 2.0, 15.0, 2.0), line), Some(s(0.0, 2.0, 10.0, 2.0)));
            assert_close(clip(s(0.0, 0.0, 4.0, 4.0), line), Some(s(2.0, 2.0, 2.0, 2.0)));
            assert_eq!(clip(s(0.0, 3.0, 4.0, 3.0), line), None);
        }

        #[testkit::test]
        fn very_long_segments_are_cut_to_the_window() {
            let m = MAX_COORD as f32;
            let got = clip(s(-m, -m, m, m), ten()).expect("crosses the window");
            assert_close(Some(got), Some(s(0.0, 0.0, 10.0, 10.0)));
            let got = clip(s(-m, 5.0, m, 5.0), ten()).expect("crosses the window");
            assert_eq!(got, s(0.0, 5.0, 10.0, 5.0));
        }

        #[testkit::test]
        fn bad_endpoints_are_errors_not_panics() {
            let window = ten();
            for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
                assert_eq!($clip(s(bad, 0.0, 1.0, 1.0), window), Err(ClipError::NonFinite { index: 0 }));
                assert_eq!($clip(s(0.0, 0.0, 1.0, bad), window), Err(ClipError::NonFinite { index: 1 }));
            }
            for huge in [1e30, -1e9, f32::MAX, 2.0 * MAX_COORD as f32] {
                assert_eq!($clip(s(0.0, 0.0, huge, 1.0), window), Err(ClipError::OutOfRange { index: 1 }));
                assert_eq!($clip(s(0.0, huge, 1.0, 1.0), window), Err(ClipError::OutOfRange { index: 0 }));
            }
        }

        proptest! {
            #![proptest_config(testkit::proptest_config())]

            #[testkit::test]
            fn visible_part_is_the_definitions(
                segment in common::segment(),
                window in common::window(),
            ) {
                let got = clip(segment, window);
                if let Err(e) = common::matches_visible_part(got, segment, window, TOLERANCE) {
                    return Err(TestCaseError::fail(format!("{segment:?} in {window:?}: {e}")));
                }
            }

            #[testkit::test]
            fn result_lies_in_the_window_on_the_segment_in_its_direction(
                segment in common::segment(),
                window in common::window(),
            ) {
                kept_if_visible(clip(segment, window), segment, window)?;
                if let Some(got) = clip(segment, window) {
                    let grown = ClipWindow::try_new(
                        window.min() - Vec2::splat(1e-4),
                        window.max() + Vec2::splat(1e-4),
                    ).expect("valid window");
                    prop_assert!(grown.contains(got.from) && grown.contains(got.to), "{:?}", got);
                    let d = segment.to - segment.from;
                    prop_assert!((got.to - got.from).dot(d) >= -1e-6, "direction reversed: {:?}", got);
                    for p in [got.from, got.to] {
                        let off = (p - segment.from).perp_dot(d).abs() / d.length().max(1e-30);
                        prop_assert!(off <= 1e-3 || d.length() == 0.0, "{:?} off the line by {}", p, off);
                    }
                }
            }

            #[testkit::test]
            fn clipping_twice_changes_nothing(
                segment in common::segment(),
                window in common::window(),
            ) {
                kept_if_visible(clip(segment, window), segment, window)?;
                if let Some(once) = clip(segment, window) {
                    // A piece a rounding error outside may be dropped.
                    match clip(once, window) {
                        Some(twice) => prop_assert!(
                            twice.from.distance(once.from) <= 1e-4 && twice.to.distance(once.to) <= 1e-4,
                            "{:?} then {:?}", once, twice
                        ),
                        None => prop_assert!(once.from.distance(once.to) <= 1e-4, "{:?} vanished", once),
                    }
                }
            }

            #[testkit::test]
            fn reversed_segment_gives_the_reversed_piece(
                segment in common::segment(),
                window in common::window(),
            ) {
                let forward = clip(segment, window);
                let backward = clip(Segment::new(segment.to, segment.from), window);
                kept_if_visible(forward, segment, window)?;
                match (forward, backward) {
                    (Some(f), Some(b)) => prop_assert!(
                        f.from.distance(b.to) <= 1e-4 && f.to.distance(b.from) <= 1e-4,
                        "{:?} vs {:?}", f, b
                    ),
                    (None, None) => {}
                    (Some(x), None) | (None, Some(x)) => {
                        prop_assert!(x.from.distance(x.to) <= 1e-4, "one way only: {:?}", x)
                    }
                }
            }
        }
    };
}
