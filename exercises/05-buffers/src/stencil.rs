//! The stencil test and stencil operations. Seed 002 lists the stencil
//! buffer in its chapter overview (§6 "Buffer in der Computergrafik"), but
//! the slides' text ends before its section, so this file follows OpenGL
//! 4.6 core specification §17.3.3 "Stencil Test" (`glStencilFunc(func,
//! ref, mask)`, `glStencilOp(sfail, dpfail, dppass)`) and §17.4.2
//! (`glStencilMask`).
//!
//! Convention (see `canvas`): pixel centres at integers, y up; the stencil
//! plane holds 8 bits per pixel ([`canvas::STENCIL_BITS`]), cleared to
//! [`canvas::STENCIL_CLEAR`] = 0.
//!
//! ```text
//!   per fragment:
//!     stencil test  (ref & mask) OP (stored & mask)
//!       fails ─────────────────────────────────────> sfail op,  discard
//!       passes ─> depth test (LESS, if enabled)
//!                   fails ─────────────────────────> dpfail op, discard
//!                   passes ────────────────────────> dppass op, write colour (and depth)
//!   every op writes  (stored & !writemask) | (result & writemask)
//! ```

use canvas::{Canvas, Fragment};

use crate::zbuffer::Compare;

/// What happens to the stored stencil value (`glStencilOp`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum StencilOp {
    /// Keep the value (the default).
    #[default]
    Keep,
    /// Set it to 0.
    Zero,
    /// Set it to the reference value.
    Replace,
    /// Add 1, saturating at 255.
    Incr,
    /// Add 1, wrapping from 255 to 0.
    IncrWrap,
    /// Subtract 1, saturating at 0.
    Decr,
    /// Subtract 1, wrapping from 0 to 255.
    DecrWrap,
    /// Invert every bit.
    Invert,
}

impl StencilOp {
    /// All eight operations.
    pub const ALL: [Self; 8] = [
        Self::Keep,
        Self::Zero,
        Self::Replace,
        Self::Incr,
        Self::IncrWrap,
        Self::Decr,
        Self::DecrWrap,
        Self::Invert,
    ];

    /// The new value for a stored `value` (before the write mask).
    #[must_use]
    #[transcript::task]
    pub fn apply(self, value: u8, reference: u8) -> u8 {
        // Unused until you write the body:
        let _ = (&value, &reference);
        todo!("stencil: one arm per operation; INCR and DECR saturate, the _WRAP ones wrap")
    }
}

/// The stored value after writing `new` through `write_mask`
/// (`glStencilMask`): bits set in the mask come from `new`, the others
/// stay as in `old`: `(old & !write_mask) | (new & write_mask)`.
#[must_use]
#[transcript::task]
pub fn write_masked(old: u8, new: u8, write_mask: u8) -> u8 {
    // Unused until you write the body:
    let _ = (&old, &new, &write_mask);
    todo!("stencil: take the masked bits from new and the others from old")
}

/// The whole stencil state: `glStencilFunc(func, reference, value_mask)`,
/// `glStencilOp(stencil_fail, depth_fail, depth_pass)` and
/// `glStencilMask(write_mask)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct StencilState {
    /// The comparison, `(reference & value_mask) OP (stored & value_mask)`
    /// (default [`Compare::Always`]). Note the order: OpenGL compares the
    /// *reference* with the stored value, so `Less` passes where the
    /// reference is the smaller.
    pub func: Compare,
    /// The reference value `ref`.
    pub reference: u8,
    /// The mask both sides of the comparison are ANDed with.
    pub value_mask: u8,
    /// The bits a stencil operation may change.
    pub write_mask: u8,
    /// The operation when the stencil test fails (`sfail`).
    pub stencil_fail: StencilOp,
    /// The operation when the stencil test passes and the depth test fails
    /// (`dpfail`).
    pub depth_fail: StencilOp,
    /// The operation when both tests pass, or the stencil test passes and
    /// the depth test is disabled (`dppass`).
    pub depth_pass: StencilOp,
}

impl StencilState {
    /// OpenGL's initial state: `ALWAYS`, reference 0, both masks all ones,
    /// `KEEP` everywhere.
    pub const DEFAULT: Self = Self {
        func: Compare::Always,
        reference: 0,
        value_mask: u8::MAX,
        write_mask: u8::MAX,
        stencil_fail: StencilOp::Keep,
        depth_fail: StencilOp::Keep,
        depth_pass: StencilOp::Keep,
    };
}

impl StencilState {
    /// Whether the stencil test passes against the `stored` value:
    /// `(reference & value_mask) OP (stored & value_mask)`, the masked
    /// reference on the left.
    ///
    /// The eight comparisons are written out here, one arm per [`Compare`],
    /// not taken from Task 1's `Compare::passes`: each task is graded on
    /// its own, and on two `u8`s each comparison is one operator.
    #[must_use]
    #[transcript::task]
    pub fn test(&self, stored: u8) -> bool {
        // Unused until you write the body:
        let _ = &stored;
        todo!(
            "stencil: mask the reference and the stored value, then one arm per Compare: reference OP stored (do not call Task 1's Compare::passes)"
        )
    }
}

impl Default for StencilState {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// Which of the three outcomes a fragment met.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum StencilOutcome {
    /// The stencil test failed: `stencil_fail` was applied, nothing drawn.
    StencilFail,
    /// The depth test failed: `depth_fail` was applied, nothing drawn.
    DepthFail,
    /// Both passed: `depth_pass` was applied and the colour written.
    DepthPass,
}

/// Runs one fragment through the stencil and depth tests, in OpenGL's
/// order, and returns the outcome (`None` for a pixel outside the canvas,
/// which changes nothing).
///
/// - The stencil test is [`StencilState::test`] of the stored value.
/// - With `depth_test` on, the depth test is `fragment.depth < stored
///   depth` (`LESS`, written here directly; a NaN depth fails it), and a
///   passing fragment writes its depth. With `depth_test` off the depth
///   test always passes and no depth is written.
/// - The operation of the outcome is applied to the stored stencil value
///   and written through [`write_masked`] with `write_mask`.
/// - Only `DepthPass` writes the fragment's colour.
#[transcript::task]
pub fn stencil_fragment(
    canvas: &mut Canvas,
    fragment: Fragment,
    state: &StencilState,
    depth_test: bool,
) -> Option<StencilOutcome> {
    // Unused until you write the body:
    let _ = (&canvas, &fragment, &state, &depth_test);
    todo!(
        "stencil: stencil test, then depth test; apply the op of the outcome through the write mask; draw on depth pass"
    )
}
