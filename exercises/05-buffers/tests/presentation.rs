//! Task 8: tearing without VSYNC, waiting for the vertical blank with it,
//! and triple buffering.

use buffers::presentation::{PresentError, Presented, SwapMode, Timing, present};
use canvas::{Canvas, Pixel, Rgba};
use proptest::prelude::*;

/// Each refresh as one line of its rows, top first: the frame a row
/// showed, `-` for none yet.
fn lines(presented: &Presented) -> Vec<String> {
    presented
        .rows
        .iter()
        .map(|rows| {
            rows.iter()
                .map(|row| row.map_or('-', |f| char::from_digit(f % 36, 36).unwrap_or('?')))
                .collect()
        })
        .collect()
}

/// 8 rows, a blank of 2 ticks (a refresh every 10 ticks), a frame every 7.
const SLIDE: Timing = Timing {
    height: 8,
    vblank: 2,
    render: 7,
};

fn run(mode: SwapMode, timing: Timing, refreshes: u32) -> Presented {
    present(mode, timing, refreshes).expect("a valid timing")
}

#[testkit::test]
fn without_vsync_the_swap_tears_the_refresh() {
    //   frames finish at ticks 7, 14, 21, 28, 35 and are swapped in at
    //   once: refresh 1 scans rows 0–3 at ticks 10–13 (frame 0) and rows
    //   4–7 at ticks 14–17 (frame 1): torn at row 4.
    let presented = run(SwapMode::Immediate, SLIDE, 4);
    assert_eq!(
        lines(&presented),
        ["-------0", "00001111", "12222222", "33333444"],
        "VSYNC off: a frame finished at tick t is shown from the row scanned at t on, \
         wherever the scan-out is (tearing); rows are scanned at R·(height + vblank) + r"
    );
    assert_eq!(
        presented.finished, 5,
        "without VSYNC the renderer never waits: frames done at ticks 7, 14, 21, 28, 35, \
         counted up to tick 4 · 10 = 40 inclusive"
    );
}

#[testkit::test]
fn with_vsync_the_swap_waits_for_the_blank_and_so_does_the_renderer() {
    //   frame 0 finishes at 7, swapped at the blank's tick 8; frame 1 is
    //   drawn from 8 to 15 and waits for tick 18; frame 2 from 18 to 25,
    //   swapped at 28; frame 3 from 28 to 35.
    let presented = run(SwapMode::Vsync, SLIDE, 4);
    assert_eq!(
        lines(&presented),
        ["--------", "00000000", "11111111", "22222222"],
        "VSYNC on: a finished frame is swapped in at the next tick of a vertical blank, \
         never while rows are scanned: every refresh shows one frame"
    );
    assert_eq!(
        presented.finished, 4,
        "with two buffers the renderer waits for the swap before it draws the next frame \
         (the seed's 'künstliche Reduktion der Leistung der GPU'): frames at 7, 15, 25, 35"
    );
}

#[testkit::test]
fn triple_buffering_waits_for_the_blank_but_not_the_renderer() {
    //   frames finish at 7, 14, 21, 28, 35 as without VSYNC; at each blank
    //   the newest finished frame is swapped in: 0 at tick 8, 1 at 18,
    //   and at 28 frame 3 (finished at 28) replaces frame 2, never shown.
    let presented = run(SwapMode::Triple, SLIDE, 4);
    assert_eq!(
        lines(&presented),
        ["--------", "00000000", "11111111", "33333333"],
        "triple buffering: the newest finished frame is swapped in at a blank tick (an \
         older one still waiting is dropped), never while rows are scanned"
    );
    assert_eq!(
        presented.finished, 5,
        "with a third buffer the renderer never waits (the seed's 'Kompensation durch \
         Dreifach-Pufferung'): frames at 7, 14, 21, 28, 35"
    );
}

#[testkit::test]
fn timings_without_rows_blank_or_frame_time_are_errors() {
    for (height, vblank, render) in [(0, 2, 7), (8, 0, 7), (8, 2, 0)] {
        assert_eq!(
            present(
                SwapMode::Vsync,
                Timing {
                    height,
                    vblank,
                    render
                },
                3
            ),
            Err(PresentError::Empty),
            "height {height}, vblank {vblank}, render {render}"
        );
    }
    assert_eq!(
        run(SwapMode::Immediate, SLIDE, 0),
        Presented::default(),
        "no refreshes: nothing shown, nothing finished by tick 0"
    );
}

/// Frame `k`'s picture: a bar three pixels wide at `x = 2k`, on a dark
/// background; the display shows at each row the row of the frame it
/// scanned.
fn frame_row(canvas: &mut Canvas, y: i32, frame: Option<u32>, x0: i32) {
    let width = 40;
    for x in 0..width {
        let on_bar = frame.is_some_and(|k| (2 * k as i32..2 * k as i32 + 3).contains(&x));
        let colour = match frame {
            None => Rgba::rgb(0.1, 0.1, 0.1),
            Some(_) if on_bar => Rgba::rgb(1.0, 0.85, 0.2),
            Some(k) if k % 2 == 0 => Rgba::rgb(0.2, 0.3, 0.6),
            Some(_) => Rgba::rgb(0.2, 0.5, 0.4),
        };
        canvas.set(Pixel::new(x0 + x, y), colour);
    }
}

/// The seed's tearing as a picture: a bar moving right by 2 pixels a
/// frame, shown by three refreshes (left to right) of a 32-row display,
/// without VSYNC (top: torn where a swap fell mid-refresh), with VSYNC
/// (middle) and with triple buffering (bottom). The background tells
/// even frames (blue) from odd ones (green).
#[testkit::test]
fn tearing_as_a_picture() {
    let timing = Timing {
        height: 32,
        vblank: 4,
        render: 11,
    };
    let (panel, gap): (i32, i32) = (40, 4);
    let mut canvas = Canvas::new((3 * panel + 2 * gap) as u32, (3 * 32 + 2 * gap) as u32);
    canvas.clear(Rgba::BLACK);
    let modes = [SwapMode::Immediate, SwapMode::Vsync, SwapMode::Triple];
    let mut all = Vec::new();
    for (m, mode) in modes.into_iter().enumerate() {
        let presented = run(mode, timing, 4);
        // Canvas y points up: the first mode on top, row 0 of a refresh at
        // the top of its panel.
        let top = 3 * 32 + 2 * gap - 1 - m as i32 * (32 + gap);
        for (r, rows) in presented.rows.iter().skip(1).enumerate() {
            for (row, &frame) in rows.iter().enumerate() {
                frame_row(
                    &mut canvas,
                    top - row as i32,
                    frame,
                    r as i32 * (panel + gap),
                );
            }
        }
        all.push(presented);
    }
    let picture = testkit::image::check_image(
        "presentation_tearing",
        &canvas,
        concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/images/presentation_tearing.png"
        ),
        testkit::image::Tolerance::EXACT,
    );
    let torn = |p: &Presented| {
        p.rows
            .iter()
            .filter(|rows| rows.windows(2).any(|w| w[0] != w[1]))
            .count()
    };
    assert!(
        torn(&all[0]) >= 2,
        "a frame every 11 ticks on a 36-tick refresh must tear refreshes without VSYNC"
    );
    assert_eq!(torn(&all[1]), 0, "VSYNC never tears");
    assert_eq!(torn(&all[2]), 0, "triple buffering never tears");
    picture.assert_matches();
}

fn timing() -> impl Strategy<Value = Timing> {
    (1u32..=12, 1u32..=4, 1u32..=30).prop_map(|(height, vblank, render)| Timing {
        height,
        vblank,
        render,
    })
}

/// The frame the front buffer holds at tick `t` when frame `k` is
/// finished at `(k + 1)·render` and shown from then on: the newest
/// finished by `t`.
fn newest_by(t: u64, render: u32) -> Option<u32> {
    (t / u64::from(render)).checked_sub(1).map(|k| k as u32)
}

proptest! {
    #![proptest_config(testkit::proptest_config())]

    /// Without VSYNC frame `k` is finished at `(k + 1)·render` and shown
    /// from that very tick: the row scanned at `t` shows the newest frame
    /// finished by `t`.
    #[testkit::test]
    fn without_vsync_each_row_shows_the_newest_frame(timing in timing(), refreshes in 1u32..=6) {
        let presented = run(SwapMode::Immediate, timing, refreshes);
        let period = timing.period();
        for (r, rows) in presented.rows.iter().enumerate() {
            for (row, &frame) in rows.iter().enumerate() {
                let t = r as u64 * period + row as u64;
                prop_assert_eq!(frame, newest_by(t, timing.render), "refresh {}, row {} (tick {})", r, row, t);
            }
        }
        let end = u64::from(refreshes) * period;
        let expected = end / u64::from(timing.render);
        prop_assert!(
            u64::from(presented.finished) == expected,
            "`finished` counts the frames done by tick refreshes · period = {} inclusive; without \
             VSYNC the renderer never waits, so ⌊{} / {}⌋ = {}; yours {}",
            end, end, timing.render, expected, presented.finished
        );
    }

    /// Triple buffering: the renderer never waits, and each refresh shows
    /// the newest frame finished by the last tick of the blank before it.
    #[testkit::test]
    fn triple_buffering_shows_the_newest_frame_of_the_blank(timing in timing(), refreshes in 1u32..=6) {
        let presented = run(SwapMode::Triple, timing, refreshes);
        let period = timing.period();
        for (r, rows) in presented.rows.iter().enumerate() {
            let expected = (r as u64 * period).checked_sub(1).and_then(|b| newest_by(b, timing.render));
            prop_assert!(rows.iter().all(|&f| f == expected), "refresh {}: {:?}, expected every row {:?}", r, rows, expected);
        }
        let end = u64::from(refreshes) * period;
        let expected = end / u64::from(timing.render);
        prop_assert!(
            u64::from(presented.finished) == expected,
            "`finished` counts the frames done by tick refreshes · period = {} inclusive; with a \
             third buffer the renderer never waits, so ⌊{} / {}⌋ = {}; yours {}",
            end, end, timing.render, expected, presented.finished
        );
    }

    /// VSYNC: no refresh is torn, frames appear in order, and the renderer
    /// finishes no more frames than without VSYNC, and each shown frame
    /// was finished; the first frame, finished at tick `render`, is swapped
    /// in at the first blank tick from then on, and every refresh scanned
    /// after that shows a frame.
    #[testkit::test]
    fn vsync_never_tears(timing in timing(), refreshes in 1u32..=6) {
        let presented = run(SwapMode::Vsync, timing, refreshes);
        let free = run(SwapMode::Immediate, timing, refreshes);
        prop_assert_eq!(presented.rows.len(), refreshes as usize, "one list of rows per refresh");
        prop_assert!(presented.rows.iter().all(|rows| rows.len() == timing.height as usize), "height rows per refresh");
        prop_assert!(
            presented.finished <= free.finished,
            "the VSYNC renderer waits, so it finishes no more frames than without VSYNC ({}); yours {}",
            free.finished, presented.finished
        );
        let (period, height, render) = (timing.period(), u64::from(timing.height), u64::from(timing.render));
        let first_swap = if render % period >= height { render } else { render / period * period + height };
        for (r, rows) in presented.rows.iter().enumerate() {
            let shows = r as u64 * period > first_swap;
            prop_assert_eq!(rows[0].is_some(), shows, "refresh {} (first swap at tick {}): {:?}", r, first_swap, rows);
        }
        prop_assert!(
            u64::from(presented.finished) >= u64::from(render <= refreshes as u64 * period),
            "frame 0 is due at tick {} ≤ refreshes · period = {}, and `finished` counts the frames \
             done by that tick inclusive; yours {}", render, refreshes as u64 * period, presented.finished
        );
        let mut last = None;
        for (r, rows) in presented.rows.iter().enumerate() {
            prop_assert!(rows.windows(2).all(|w| w[0] == w[1]), "refresh {} torn: {:?}", r, rows);
            let shown = rows[0];
            prop_assert!(shown >= last, "refresh {} shows {:?} after {:?}", r, shown, last);
            prop_assert!(shown.is_none_or(|f| f < presented.finished), "frame {:?} shown but never finished", shown);
            last = shown;
        }
    }
}
