//! Polygon offset for hidden-line drawing (seed 002, §6.2 "Z-Buffer:
//! Drahtgittermodelle" and "Hidden-Line"; OpenGL 4.6 core specification
//! §14.6.5 "Depth Offset", `glPolygonOffset(factor, units)`).
//!
//! Convention (see `canvas`): pixel centres at integers, y up; depth 0 is
//! nearest. Fills come from the given [`crate::raster::fill_triangle`]
//! (top-left rule), outlines from the given [`crate::raster::draw_line`]
//! (the one-pixel band around the segment, both ends included); the depth
//! test is `LESS` with depth writes.
//!
//! **Stitching.** A polygon drawn filled and then again as an outline puts
//! two fragments on each edge pixel with (nearly) the same depth: the
//! fill's depth is the plane at the pixel *centre*, the line's the depth
//! along the *edge*. Where the centre lies on the nearer side of the edge,
//! the fill wins and the outline breaks up ("Stitching" durch
//! "z-Fighting"). The remedy pushes the fill back by
//!
//! ```text
//!   o = m · factor + r · units
//!   m = max(|∂z/∂x|, |∂z/∂y|)   the polygon's largest depth slope
//!   r                           the smallest resolvable depth difference
//! ```
//!
//! The seed glosses `m` as "Maximaler z-Unterschied des Objektes" (the
//! largest depth difference across the object); OpenGL's `m` is the
//! largest depth *slope*, the depth change per pixel, which is what
//! decides how far the fill and the line can differ on one pixel.

#[allow(unused_imports)]
use canvas::{Canvas, Fragment, Rgba, Vertex};

#[allow(unused_imports)]
use crate::raster::{draw_line, fill_triangle};

/// `r`, the smallest depth difference the depth buffer resolves: one step
/// of a 24-bit fixed-point depth buffer, `2⁻²⁴`. (The canvas stores `f32`
/// depths; OpenGL's `r` for a float buffer depends on the exponent of the
/// depths involved. A fixed `r` keeps `units` meaning the same everywhere.)
pub const DEPTH_RESOLUTION: f32 = 1.0 / 16_777_216.0;

/// Why a triangle has no depth slope.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum OffsetError {
    /// A position or depth is NaN or infinite.
    #[error("a vertex position or depth is not finite")]
    NotFinite,
    /// The triangle covers no area on screen.
    #[error("the triangle has zero area on screen")]
    Degenerate,
}

/// The parameters of `glPolygonOffset(factor, units)`.
///
/// The seed recommends `factor = units = 1` ("Standardmäßig") as a
/// starting point, more `factor` for wide lines, and "rather too much
/// offset than too little"; OpenGL's own initial values are 0 and 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PolygonOffset {
    /// Multiplies the depth slope `m`.
    pub factor: f32,
    /// Multiplies the resolution `r` ([`DEPTH_RESOLUTION`]).
    pub units: f32,
}

impl PolygonOffset {
    /// The seed's recommended start: `factor = 1`, `units = 1`.
    pub const SLIDES: Self = Self {
        factor: 1.0,
        units: 1.0,
    };

    /// The offset `o = m · factor + r · units` for a polygon of depth
    /// slope `m`.
    #[must_use]
    #[transcript::task]
    pub fn offset(self, m: f32) -> f32 {
        // Unused until you write the body:
        let _ = &m;
        todo!("polygon_offset: o = m · factor + r · units")
    }
}

/// The largest depth slope `m = max(|∂z/∂x|, |∂z/∂y|)` of the triangle's
/// plane `z = a·x + b·y + c` (the approximation OpenGL allows for
/// `√((∂z/∂x)² + (∂z/∂y)²)`), in depth units per pixel.
///
/// With `e1 = V1 − V0`, `e2 = V2 − V0` (positions) and `d1 = z1 − z0`,
/// `d2 = z2 − z0`, Cramer's rule gives
///
/// ```text
///   det   = e1.x · e2.y − e2.x · e1.y
///   ∂z/∂x = (d1 · e2.y − d2 · e1.y) / det
///   ∂z/∂y = (e1.x · d2 − e2.x · d1) / det
/// ```
///
/// An error for a zero-area triangle or a non-finite position or depth.
#[transcript::task]
pub fn max_depth_slope(triangle: [Vertex; 3]) -> Result<f32, OffsetError> {
    // Unused until you write the body:
    let _ = &triangle;
    todo!(
        "polygon_offset: solve for the plane's ∂z/∂x and ∂z/∂y by Cramer's rule, return the larger magnitude"
    )
}

/// The colours of a hidden-line drawing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HiddenLineStyle {
    /// The fill of every triangle (usually the background colour).
    pub fill: Rgba,
    /// The outline.
    pub line: Rgba,
}

/// Which pass of a hidden-line drawing is offset, and by how much: the
/// seed's two remedies for stitching.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum HiddenLineOffset {
    /// No offset: the outline is stitched.
    None,
    /// `glEnable(GL_POLYGON_OFFSET_FILL)`: each triangle's fill moves back
    /// by its offset ("Offset für gefülltes Polygon > 0", factor and
    /// units positive).
    Fill(PolygonOffset),
    /// `glEnable(GL_POLYGON_OFFSET_LINE)`: each triangle's outline moves
    /// forward by the triangle's offset ("Offset für Linie < 0", factor
    /// and units negative).
    Line(PolygonOffset),
}

/// Fills `triangle` with `colour` through the depth test, its depth moved
/// by a polygon offset (`glPolygonOffset` for one filled polygon): every
/// fragment of [`fill_triangle`] gets depth `z + o`, clamped to `[0, 1]`
/// as OpenGL does, where `o` is [`PolygonOffset::offset`] of the
/// triangle's [`max_depth_slope`] (`o = 0` for `None`); it passes where
/// that depth is less than the stored one (`LESS`), and then writes depth
/// and colour. Vertex colours are ignored.
///
/// A polygon drawn onto a coplanar one (a decal on a wall) fights it
/// without an offset: both have the same plane, but their depths are
/// interpolated from other vertices and round differently, so the test
/// passes at some pixels and fails at others (z-fighting). A negative
/// offset brings it in front everywhere. A degenerate or non-finite
/// triangle draws nothing.
#[transcript::task]
pub fn fill_offset(
    canvas: &mut Canvas,
    triangle: [Vertex; 3],
    colour: Rgba,
    offset: Option<PolygonOffset>,
) {
    // Unused until you write the body:
    let _ = (&canvas, &triangle, &colour, &offset);
    todo!(
        "polygon_offset: o from the triangle's slope, then every fragment of fill_triangle at depth clamp(z + o) through a LESS test that writes depth and colour"
    )
}

/// Draws `triangles` as a hidden-line picture, the seed's two passes:
///
/// 1. **Fill** (`GL_FILL`): every triangle by [`fill_offset`] with the fill
///    colour, moved back by the offset of [`HiddenLineOffset::Fill`].
/// 2. **Outline** (`GL_LINE`): the three edges `V0–V1`, `V1–V2`, `V2–V0`
///    of every triangle by [`draw_line`] with the line colour; for
///    [`HiddenLineOffset::Line`] each fragment's depth is moved by the
///    triangle's offset `o` (of its [`max_depth_slope`]) and clamped to
///    `[0, 1]`, like the fill's.
///
/// Both passes use the depth test `LESS` (OpenGL's default) and write
/// depth and colour where it passes; vertex colours are ignored. Without
/// an offset the outline shows stitching; with the fill pushed back by
/// [`PolygonOffset::SLIDES`], or the outline pulled forward by its
/// negative, it is whole, and edges behind other triangles stay hidden.
///
/// Degenerate triangles have no fill and are outlined without an offset;
/// fragments outside the canvas or with a NaN depth are dropped.
#[transcript::task]
pub fn hidden_line(
    canvas: &mut Canvas,
    triangles: &[[Vertex; 3]],
    style: HiddenLineStyle,
    offset: HiddenLineOffset,
) {
    // Unused until you write the body:
    let _ = (&canvas, &triangles, &style, &offset);
    todo!(
        "polygon_offset: fill every triangle (offset if the fill is), then outline every triangle (offset if the line is), both with a LESS depth test"
    )
}
