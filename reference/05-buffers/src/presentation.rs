//! When the back buffer becomes visible: tearing without VSYNC, waiting
//! for the vertical blank with it, and triple buffering, which waits
//! without stalling the renderer. Seed 002, §6.1 "Tausch-Operation":
//! "Ist das Bild auf dem Bildschirm noch nicht vollständig aufgebaut, wird
//! ab der aktuellen Stelle auf dem Bildschirm bereits das neue Bild
//! dargestellt: Tearing-Artefakte"; VSYNC "verhindert Aktualisierung der
//! Bilddaten, während der Bildschirm das Bild aufbaut", at the price of a
//! "künstliche Reduktion der Leistung der GPU", and "Kompensation durch
//! Dreifach-Pufferung".
//!
//! **The simulated display.** Time runs in ticks. The display scans out
//! the front buffer one row per tick, top row first, `height` rows, then
//! rests for `vblank` ticks (the vertical blank), and starts the next
//! refresh: refresh `R` scans row `r` at tick `R·period + r`, with
//! `period = height + vblank`, and its blank begins at tick
//! `R·period + height`. A row shows the frame the front buffer holds at
//! the tick it is scanned; a swap at tick `t` is seen by the rows scanned
//! at `t` and later.
//!
//! ```text
//!   tick:  0 1 2 3 4 5 6 7 8 9 10 …      height 8, vblank 2, period 10
//!   row:   0 1 2 3 4 5 6 7 · · 0  …      · = vertical blank
//! ```
//!
//! **The renderer** draws frames 0, 1, 2, … one after the other, each
//! taking `render` ticks of drawing, starting frame 0 at tick 0; it starts
//! the next frame as soon as it has a buffer to draw into.

/// How the display, the renderer and the swap are timed, in ticks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Timing {
    /// Rows of the display, scanned one per tick; at least 1.
    pub height: u32,
    /// Ticks of vertical blank after the last row of each refresh; at
    /// least 1.
    pub vblank: u32,
    /// Ticks the renderer takes to draw one frame; at least 1.
    pub render: u32,
}

impl Timing {
    /// Ticks from one refresh's first row to the next one's:
    /// `height + vblank`.
    #[must_use]
    pub fn period(&self) -> u64 {
        u64::from(self.height) + u64::from(self.vblank)
    }
}

/// When a finished back buffer becomes the front buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SwapMode {
    /// Double buffering, VSYNC off: swap the moment a frame is finished,
    /// wherever the scan-out is; the renderer goes straight on with the
    /// next frame into the old front buffer. Tears.
    Immediate,
    /// Double buffering, VSYNC on: a finished frame waits for the next
    /// vertical blank to be swapped in (at once if it finishes at a blank
    /// tick); meanwhile the renderer has no buffer to draw into and waits
    /// too, starting the next frame at the swap.
    Vsync,
    /// Triple buffering with VSYNC: a finished frame waits in a third
    /// buffer, replacing a finished frame still waiting there (which is
    /// never shown), while the renderer goes straight on with the next
    /// frame; at every tick of a vertical blank a waiting frame is swapped
    /// in.
    Triple,
}

/// What the display showed.
#[transcript::evidence]
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Presented {
    /// For each refresh, for each row (top first), the frame it showed:
    /// `None` before the first swap.
    pub rows: Vec<Vec<Option<u32>>>,
    /// How many frames the renderer finished by the end of the last
    /// refresh's blank (tick `refreshes · period`), whether shown or not.
    pub finished: u32,
}

/// Why a timing cannot be simulated.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum PresentError {
    /// `height`, `vblank` or `render` is 0 (a display without a blank
    /// never lets VSYNC swap).
    #[error("the display needs a row and a blank of at least one tick, a frame at least one tick")]
    Empty,
}

/// Simulates `refreshes` refreshes of the display under `mode`: which
/// frame every row of every refresh showed, and how many frames the
/// renderer finished by tick `refreshes · period` (a frame finishing at
/// exactly that tick counts).
///
/// Step through the ticks `0, 1, …, refreshes · period` (the last one
/// included); at each tick `t`, in this order: the renderer finishes a
/// frame due at `t`; the swap of `mode` happens; the renderer starts the
/// next frame if it has a free buffer; the row of `t` is scanned (if `t`
/// is not in a blank).
///
/// # Errors
/// [`PresentError::Empty`] for a `height`, `vblank` or `render` of 0.
#[transcript::task]
pub fn present(mode: SwapMode, timing: Timing, refreshes: u32) -> Result<Presented, PresentError> {
    // BEGIN SOLUTION presentation: step through the ticks: finish a frame when due, swap as the mode says (at once, at a blank tick, or the newest waiting one at a blank tick), then scan the tick's row
    if timing.height == 0 || timing.vblank == 0 || timing.render == 0 {
        return Err(PresentError::Empty);
    }
    let period = timing.period();
    let height = u64::from(timing.height);
    let render = u64::from(timing.render);
    let end = u64::from(refreshes) * period;
    let mut rows = vec![vec![None; timing.height as usize]; refreshes as usize];
    let mut front: Option<u32> = None;
    // The frame being drawn and the tick it will be finished, if drawing.
    let mut drawing: Option<(u32, u64)> = Some((0, render));
    // A finished frame waiting for the swap.
    let mut waiting: Option<u32> = None;
    let mut finished = 0;
    for t in 0..=end {
        let in_blank = t % period >= height;
        if let Some((frame, due)) = drawing
            && due == t
        {
            finished += 1;
            waiting = Some(frame);
            drawing = None;
        }
        let swap = match mode {
            SwapMode::Immediate => true,
            SwapMode::Vsync | SwapMode::Triple => in_blank,
        };
        if swap && let Some(frame) = waiting.take() {
            front = Some(frame);
        }
        // The renderer starts the next frame when a buffer is free: with
        // two buffers only once nothing waits, with three always.
        if drawing.is_none() && (mode == SwapMode::Triple || waiting.is_none()) {
            drawing = Some((finished, t + render));
        }
        if !in_blank && t < end {
            rows[(t / period) as usize][(t % period) as usize] = front;
        }
    }
    Ok(Presented { rows, finished })
    // END SOLUTION
}
