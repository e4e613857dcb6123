//! Double buffering and the accumulation buffer, used for scene
//! antialiasing by jittered accumulation. Seed 002 §6.1 "Double u. Stereo
//! Buffering" describes front and back buffer and the swap; it lists the
//! accumulation buffer in its chapter overview and promises "Szenen-
//! Antialiasing durch … geschickte Nutzung des Accumulationbuffers", but its
//! text ends before that section, so this file follows OpenGL 2.1
//! specification §4.2.4 "The Accumulation Buffer" (`glAccum`, removed from
//! core profiles since 3.1) and the jitter table of the OpenGL
//! Programming Guide ("Red Book"), chapter 10, `jitter.h`.
//!
//! Convention (see `canvas`): pixel centres at integers, y up.
//!
//! ```text
//!   for each jitter offset j (n of them):
//!       clear the back buffer, draw the scene sampled at pixel centre + j
//!       accum(ACCUM, 1/n)              acc += colour / n
//!   accum(RETURN, 1)                   colour = acc  → the antialiased image
//! ```
//!
//! The slides' other route, "Anti-Aliasing bei Linien … Nutzt Alpha
//! Blending" (`glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)` with
//! `GL_POLYGON_SMOOTH`), draws each primitive once: a pixel's fragment
//! carries the fraction of the pixel the primitive covers as its alpha,
//! and [`blend`] mixes it into what is there ([`smooth_triangle`]). It
//! needs no second buffer, but it depends on the drawing order and leaves
//! a seam where two triangles share an edge: each covers half of such a
//! pixel, and half over half blends to ¾, not 1.

#[allow(unused_imports)]
use canvas::{Canvas, CanvasError, Pixel, Rgba, Vec2, Vec4, Vertex};

/// The Red Book's eight jitter offsets (`j8` in `jitter.h`), moved from
/// the pixel square `[0, 1)²` of that table to offsets from the pixel
/// centre in `[−½, ½)²`: well spread, one per row and column of an 8 × 8
/// grid of sixteenths (all exact in `f32`).
pub const JITTER_8: [Vec2; 8] = [
    Vec2::new(0.5625 - 0.5, 0.4375 - 0.5),
    Vec2::new(0.0625 - 0.5, 0.9375 - 0.5),
    Vec2::new(0.3125 - 0.5, 0.6875 - 0.5),
    Vec2::new(0.6875 - 0.5, 0.8125 - 0.5),
    Vec2::new(0.8125 - 0.5, 0.1875 - 0.5),
    Vec2::new(0.9375 - 0.5, 0.5625 - 0.5),
    Vec2::new(0.4375 - 0.5, 0.0625 - 0.5),
    Vec2::new(0.1875 - 0.5, 0.3125 - 0.5),
];

/// A front buffer that is shown and a back buffer that is drawn into
/// (`GLUT_DOUBLE`); [`DoubleBuffer::swap`] exchanges them
/// (`glutSwapBuffers`).
#[transcript::evidence]
#[derive(Clone, Debug, PartialEq)]
pub struct DoubleBuffer {
    front: Canvas,
    back: Canvas,
}

impl DoubleBuffer {
    /// Two cleared canvases of `width × height` pixels.
    pub fn try_new(width: u32, height: u32) -> Result<Self, CanvasError> {
        Ok(Self {
            front: Canvas::try_new(width, height)?,
            back: Canvas::try_new(width, height)?,
        })
    }

    /// The buffer being shown.
    #[must_use]
    pub fn front(&self) -> &Canvas {
        &self.front
    }

    /// The buffer being drawn into; nothing drawn here is seen before the
    /// next [`DoubleBuffer::swap`].
    pub fn back_mut(&mut self) -> &mut Canvas {
        &mut self.back
    }

    /// Exchanges front and back buffer: what was drawn becomes visible,
    /// and the old front becomes the new back buffer (with its old
    /// content — a frame starts by clearing it). Swapping twice restores
    /// the original state. No pixel is copied.
    #[transcript::task]
    pub fn swap(&mut self) {
        todo!("accumulation: exchange the two canvases without copying pixels")
    }
}

/// Why an accumulation-buffer operation failed.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum AccumError {
    /// The canvas and the accumulation buffer differ in size.
    #[error(
        "the canvas is {canvas_width}x{canvas_height}, the accumulation buffer {width}x{height}"
    )]
    SizeMismatch {
        /// Accumulation buffer width.
        width: u32,
        /// Accumulation buffer height.
        height: u32,
        /// Canvas width.
        canvas_width: u32,
        /// Canvas height.
        canvas_height: u32,
    },
    /// The value is NaN or infinite.
    #[error("the accumulation value must be finite")]
    NotFinite,
    /// Jittered accumulation needs at least one offset.
    #[error("no jitter offsets")]
    NoJitter,
    /// The buffers could not be allocated.
    #[error("the canvas is too large")]
    TooLarge,
}

/// The operations of `glAccum(op, value)`, channel by channel on RGBA.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum AccumOp {
    /// `acc += value · colour` (`GL_ACCUM`).
    Accum,
    /// `acc = value · colour` (`GL_LOAD`).
    Load,
    /// `colour = value · acc`, clamped to `[0, 1]` and rounded to 8 bits
    /// by the canvas (`GL_RETURN`).
    Return,
    /// `acc = value · acc` (`GL_MULT`).
    Mult,
    /// `acc = acc + value` (`GL_ADD`).
    Add,
}

/// An accumulation buffer: one RGBA value of `f32` per pixel, unclamped
/// (OpenGL's is typically 16 bits per channel, signed; the range `[−1, 1]`
/// of those is not enforced here), cleared to 0.
#[transcript::evidence]
#[derive(Clone, Debug, PartialEq)]
pub struct AccumulationBuffer {
    width: u32,
    height: u32,
    values: Vec<Vec4>,
}

impl AccumulationBuffer {
    /// A cleared buffer of `width × height` values; an error beyond
    /// [`Canvas::MAX_PIXELS`].
    pub fn try_new(width: u32, height: u32) -> Result<Self, AccumError> {
        let n = u64::from(width) * u64::from(height);
        if n > Canvas::MAX_PIXELS {
            return Err(AccumError::TooLarge);
        }
        Ok(Self {
            width,
            height,
            values: vec![Vec4::ZERO; n as usize],
        })
    }

    /// The value at `p` as `(r, g, b, a)`, or `None` outside.
    #[must_use]
    pub fn get(&self, p: Pixel) -> Option<Vec4> {
        let inside = (p.x as u32) < self.width && (p.y as u32) < self.height;
        inside.then(|| self.values[p.y as usize * self.width as usize + p.x as usize])
    }

    /// Applies `glAccum(op, value)` to every pixel, reading `canvas` for
    /// [`AccumOp::Accum`] and [`AccumOp::Load`] and writing it for
    /// [`AccumOp::Return`] (the others leave it alone).
    ///
    /// An error, changing nothing, when `value` is not finite or the
    /// canvas has another size. Accumulating one frame with `Load` or
    /// `Accum` (value 1, from a cleared buffer) and returning it with value
    /// 1 gives that frame back exactly.
    #[transcript::task]
    pub fn accum(
        &mut self,
        op: AccumOp,
        value: f32,
        canvas: &mut Canvas,
    ) -> Result<(), AccumError> {
        // Unused until you write the body:
        let _ = (&op, &value, &canvas);
        todo!(
            "accumulation: check the value and the size, then apply op to every pixel as glAccum defines it"
        )
    }
}

/// Scene antialiasing by jittered accumulation: for each offset `j` of
/// `jitter`, `render` draws the scene into a cleared `width × height`
/// canvas *as sampled at pixel centre + j* (it moves the scene by `−j`),
/// the frame is accumulated with weight `1/n`, and the average is
/// returned.
///
/// A pixel an edge crosses ends up with the fraction of its `n` samples
/// that hit the scene, as `n + 1` grey levels. One offset `(0, 0)` gives
/// exactly the aliased frame. An error for an empty `jitter` or a canvas
/// beyond [`Canvas::MAX_PIXELS`].
#[transcript::task]
pub fn jittered_antialias(
    width: u32,
    height: u32,
    jitter: &[Vec2],
    mut render: impl FnMut(&mut Canvas, Vec2),
) -> Result<Canvas, AccumError> {
    // Unused until you write the body:
    let _ = (&width, &height, &jitter, &mut render);
    todo!(
        "accumulation: accumulate one frame per offset with weight 1/n, then return the sum into a canvas"
    )
}

/// OpenGL's blending with `glBlendFunc(GL_SRC_ALPHA,
/// GL_ONE_MINUS_SRC_ALPHA)`: the incoming colour `src` weighted by its
/// alpha, over the stored colour `dst` weighted by the rest, every
/// channel alike (alpha too, as OpenGL does with one blend function):
///
/// ```text
///   out = src · src.a + dst · (1 − src.a)
/// ```
///
/// `src.a = 1` gives `src` (an opaque fragment replaces), `src.a = 0`
/// gives `dst`.
#[must_use]
#[transcript::task]
pub fn blend(src: Rgba, dst: Rgba) -> Rgba {
    // Unused until you write the body:
    let _ = (&src, &dst);
    todo!("accumulation: weight src by its alpha and dst by one minus it, channel by channel")
}

/// Draws a triangle of one `colour` antialiased by alpha blending, the
/// slides' OpenGL route (`GL_POLYGON_SMOOTH`): each pixel's coverage `c`
/// is the fraction of the [`JITTER_8`] samples `centre + j` of the pixel
/// that [`crate::raster::fill_triangle`] covers (fill the triangle moved
/// by `−j`, as [`jittered_antialias`] does, and count per pixel), and
/// every pixel with `c > 0` becomes [`blend`] of the colour, its alpha
/// multiplied by `c`, over the canvas's colour there. Pixels outside the
/// canvas are ignored; the depth plane is untouched.
///
/// Blend with this module's [`blend`], not the course's
/// [`Canvas::blend`]: that one is a coverage write with another alpha,
/// `s + old.a · (1 − s)` (1 over an opaque background, where `blend`
/// gives `s·s + 1 − s`, e.g. 0.89 for `s = 1/8`), and rounds `s` to 8 bits.
///
/// On a black canvas a white triangle comes out as jittered accumulation
/// draws it; two triangles sharing an edge do not (the seam).
#[transcript::task]
pub fn smooth_triangle(canvas: &mut Canvas, vertices: [Vec2; 3], colour: Rgba) {
    // Unused until you write the body:
    let _ = (&canvas, &vertices, &colour);
    todo!(
        "accumulation: count per pixel the jittered samples fill_triangle covers, then blend the colour with alpha times that fraction"
    )
}
