//! The transforms around rasterization: model, view and projection into
//! homogeneous clip space, the perspective divide and the viewport
//! transform (sheet, section 2).

use canvas::{Canvas, Rgba, Vertex};
use glam::camera::rh::{proj::opengl, view};
use glam::{Mat4, Vec3};

use crate::{ClipVertex, Mesh, raster};

/// Where the course camera stands, in world space.
pub const EYE: Vec3 = Vec3::new(0.0, 0.0, 4.0);
/// What the course camera looks at.
pub const TARGET: Vec3 = Vec3::ZERO;
/// The course camera's vertical field of view: 45° in radians.
pub const FOV_Y: f32 = std::f32::consts::FRAC_PI_4;
/// Distance from the eye to the near clipping plane (world `z = 3`).
pub const NEAR: f32 = 1.0;
/// Distance from the eye to the far clipping plane (world `z = −6`).
pub const FAR: f32 = 10.0;

/// How polygons are drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// The outline of every polygon (a wireframe), as one-pixel bands.
    Line,
    /// Filled polygons, as triangle fans with edge functions.
    Fill,
}

/// The transforms from model space to the pixels of a `width × height`
/// canvas.
///
/// `clip = projection · view · model · (x, y, z, 1)` (column vectors, as
/// in glam). Then [`Pipeline::screen`] divides by `w` and maps to pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pipeline {
    /// Model space to world space.
    pub model: Mat4,
    /// World space to eye space (right-handed, looking down −z).
    pub view: Mat4,
    /// Eye space to clip space (OpenGL convention: NDC `z ∈ [−1, 1]`).
    pub projection: Mat4,
    /// Canvas width in pixels.
    pub width: u32,
    /// Canvas height in pixels.
    pub height: u32,
}

impl Pipeline {
    /// The course's default camera for the shipped meshes, the same for
    /// every mesh: the model matrix is the identity, the eye stands at
    /// [`EYE`] looking at the origin with y up, and the projection is a
    /// perspective with [`FOV_Y`], the canvas's aspect ratio (1 for an empty
    /// canvas), [`NEAR`] and [`FAR`].
    ///
    /// The sheet names the camera of its `main.m` but does not print its
    /// values; these are the course's own, chosen so that the plain shipped
    /// meshes fill most of the picture.
    ///
    /// Because the camera does not adapt to the mesh, the `clipped_` meshes
    /// reach outside the view volume as the sheet intends (through the near
    /// plane, behind the eye and past the sides); the other shipped meshes
    /// lie inside it. `mesh` does not influence the camera.
    #[must_use]
    pub fn for_mesh(mesh: &Mesh, width: u32, height: u32) -> Self {
        let _ = mesh;
        Self {
            model: Mat4::IDENTITY,
            view: view::look_at_mat4(EYE, TARGET, Vec3::Y),
            projection: opengl::perspective(FOV_Y, aspect_ratio(width, height), NEAR, FAR),
            width,
            height,
        }
    }

    /// `projection · view · model`: model space to clip space.
    #[must_use]
    pub fn model_view_projection(&self) -> Mat4 {
        self.projection * self.view * self.model
    }

    /// Every face of the mesh as a polygon in homogeneous clip space, in
    /// face order, each vertex with its colour (white where the mesh has
    /// fewer colours than positions).
    ///
    /// A face with an index out of range is skipped (a loaded mesh has
    /// none; see [`Mesh`]).
    #[must_use]
    pub fn clip_space(&self, mesh: &Mesh) -> Vec<Vec<ClipVertex>> {
        let mvp = self.model_view_projection();
        mesh.faces
            .iter()
            .filter_map(|face| {
                face.iter()
                    .map(|&i| {
                        let i = i as usize;
                        let position = mesh.positions.get(i)?;
                        let colour = mesh.colours.get(i).copied().unwrap_or(Rgba::WHITE);
                        Some(ClipVertex::new(mvp * position.extend(1.0), colour))
                    })
                    .collect()
            })
            .collect()
    }

    /// Perspective divide and viewport transform of one vertex: the vertex
    /// as rasterizers receive it, or `None` when the result is not finite.
    ///
    /// ```text
    /// NDC:    (x, y, z) = (x_c, y_c, z_c) / w_c
    /// pixel:  x_p = (x + 1) / 2 · (width − 1)
    ///         y_p = (y + 1) / 2 · (height − 1)      (y up, like the canvas)
    /// depth:  d   = (z + 1) / 2                     (near → 0, far → 1)
    /// ```
    ///
    /// NDC `−1` and `+1` land on the centres of the outermost pixels, so a
    /// clipped polygon never rounds to a pixel off the canvas
    /// ([`canvas::ndc_to_pixel`], the course's viewport transform).
    ///
    /// The divide is done even for `w ≤ 0` (a point behind the eye, which
    /// clipping would have removed): its picture is mirrored through the
    /// centre, which is the artefact "without clipping" pictures show.
    /// `w = 0`, NaN or infinite input gives `None`.
    #[must_use]
    pub fn screen(&self, v: ClipVertex) -> Option<Vertex> {
        let ndc = v.position.truncate() / v.position.w;
        let pixel = canvas::ndc_to_pixel(ndc.truncate(), self.width, self.height);
        let depth = canvas::ndc_depth(ndc.z);
        (pixel.is_finite() && depth.is_finite()).then(|| Vertex::new(pixel, depth, v.colour))
    }

    /// Divides, maps to pixels and draws every polygon onto `canvas`.
    ///
    /// - [`Mode::Line`]: each edge `v_i → v_{i+1}` and the closing edge
    ///   `v_{n−1} → v_0` as a one-pixel band ([`raster::draw_line`]); a
    ///   two-vertex polygon is one line.
    /// - [`Mode::Fill`]: a triangle fan `(v_0, v_i, v_{i+1})`
    ///   ([`raster::fill_triangle`]), exact for convex polygons (which
    ///   clipping convex faces produces); fewer than 3 vertices draw nothing.
    ///
    /// Both write a fragment only where its depth is less than the stored
    /// depth ([`raster::depth_test`]); the canvas should be cleared to
    /// [`canvas::DEPTH_CLEAR`] first.
    ///
    /// Polygons are drawn as given, clipped or not. A vertex that
    /// [`Pipeline::screen`] cannot map (`w = 0`, NaN, infinite) is skipped:
    /// its edges are not drawn, and its polygon is not filled. Vertices
    /// behind the eye (`w < 0`) are divided naively; fragments beyond the
    /// canvas are dropped, and lines or triangles reaching past
    /// [`canvas::MAX_COORD`] are not drawn (see [`raster`]). Depth is not
    /// clamped: geometry between the eye and the near plane gets depth
    /// below 0 and wins every depth test, geometry beyond the far plane or
    /// behind the eye mostly gets depth above 1 and fails it. Nothing here
    /// panics or loops longer than the canvas is large.
    pub fn render(&self, polygons: &[Vec<ClipVertex>], mode: Mode, canvas: &mut Canvas) {
        for polygon in polygons {
            let screen: Vec<Option<Vertex>> = polygon.iter().map(|&v| self.screen(v)).collect();
            match mode {
                Mode::Line => {
                    let n = screen.len();
                    let edges = if n == 2 { 1 } else { n };
                    for i in 0..edges {
                        if let (Some(a), Some(b)) = (screen[i], screen[(i + 1) % n]) {
                            raster::draw_line(canvas, a, b);
                        }
                    }
                }
                Mode::Fill => {
                    let Some(vertices) = screen.into_iter().collect::<Option<Vec<_>>>() else {
                        continue;
                    };
                    if let Some((&first, rest)) = vertices.split_first() {
                        for pair in rest.windows(2) {
                            raster::fill_triangle(canvas, [first, pair[0], pair[1]]);
                        }
                    }
                }
            }
        }
    }
}

/// The width-to-height ratio of a `width × height` picture, 1 for an
/// empty one.
#[must_use]
pub fn aspect_ratio(width: u32, height: u32) -> f32 {
    if width == 0 || height == 0 {
        1.0
    } else {
        width as f32 / height as f32
    }
}

/// Whether a clip-space point lies in the view volume
/// `−w ≤ x ≤ w, −w ≤ y ≤ w, −w ≤ z ≤ w` (boundary included). NaN is outside.
#[must_use]
pub fn inside_view_volume(v: &ClipVertex) -> bool {
    // Boundary included, as the sheet's hint on `inside(...)` says (its
    // list in section 5.2 writes `v · p < 0` for "inside", which would
    // exclude points on the plane).
    let p = v.position;
    let w = p.w;
    [p.x, p.y, p.z].iter().all(|&c| -w <= c && c <= w)
}

/// The crudest "clipping": keeps only the polygons whose every vertex lies
/// inside the view volume ([`inside_view_volume`]) and drops the rest
/// whole.
///
/// This is what the `render` example's `--clip` does until an exercise's
/// Sutherland–Hodgman clipper is plugged in: it removes every artefact of
/// unclipped geometry, but also the visible parts of polygons that cross the
/// border, which is why real clipping cuts polygons instead.
#[must_use]
pub fn discard_outside(polygons: &[Vec<ClipVertex>]) -> Vec<Vec<ClipVertex>> {
    polygons
        .iter()
        .filter(|p| p.iter().all(inside_view_volume))
        .cloned()
        .collect()
}
