//! A small framebuffer with a depth plane, an 8-bit stencil plane and a
//! "colour" plane that records which face of which primitive a pixel
//! shows, driven the way OpenGL drives its buffers: a depth function, a
//! stencil function and stencil operations, write masks. Seed 003, §5
//! (Wiegand's adaptation to OpenGL) and §6.2–6.3.
//!
//! **Camera and pixels.** The camera is orthographic: pixel `(x, y)` —
//! centres at integer coordinates, y up, as in `canvas` — looks along one
//! ray `o + t·d` ([`Camera::ray`]); its depth is `t`, smaller is nearer,
//! and the viewer is at `t = −∞`, outside every solid (seed §4.3).
//!
//! **Rasterizing a face** of a convex primitive means: at every pixel
//! whose ray hits the primitive, one fragment at depth `span.near` (front
//! face) or `span.far` (back face). This is exact — no triangles, no
//! interpolation — so the image-based algorithms and the ray caster see
//! bit-identical depths, and a pixel's ray grazing a silhouette (a span
//! of length zero) gives no fragment.
//!
//! **What is drawn** is any [`Solid`]: a convex solid that a viewing ray
//! meets in one span or not at all. A [`Primitive`] is one; so is a
//! primitive moved by an affine map (`transforms::Placed`, seed §2.1), which
//! OpenGL would draw under a model matrix and which is drawn here through
//! the span of the moved primitive.
//!
//! **The fragment stage is topic 05's.** Each fragment goes through the
//! stencil test, the depth test and the stencil operation of its outcome
//! exactly as OpenGL orders them, and the pieces are yours from topic 05:
//! the comparison [`Compare`] (depth and stencil function), the stencil
//! state [`StencilState`] with its masked test, the operations
//! [`StencilOp`] and the write mask [`write_masked`]. Until topic 05's
//! `zbuffer` and `stencil` tasks are done, drawing here stops at their
//! `todo!()`.
//!
//! This module is given: you use it, you do not edit it.

pub use buffers::stencil::{StencilOp, StencilState, write_masked};
pub use buffers::zbuffer::Compare;
use canvas::Pixel;
use glam::Vec3;

use crate::csg::CsgError;
use crate::primitive::{Primitive, Ray, RayInterval};

/// The depth a cleared depth plane holds: farther than everything.
pub const DEPTH_FAR: f32 = f32::INFINITY;

/// The largest framebuffer, in pixels (as `canvas::Canvas::MAX_PIXELS`).
pub const MAX_PIXELS: u64 = 1 << 28;

/// The stencil bit that holds the parity of the parity test (seed §4.3:
/// one bit suffices).
pub const PARITY_BIT: u8 = 0b0000_0001;

/// A convex solid as the framebuffer rasterizes it: where a viewing ray
/// enters and leaves it. The renderers draw any `Solid`: a [`Primitive`],
/// or a primitive placed by the transformations of a CSG tree.
pub trait Solid {
    /// Where `ray` (a unit direction) runs through the solid, in the ray's
    /// depths, `near < far`; `None` where it misses or only grazes it.
    fn span(&self, ray: &Ray) -> Option<RayInterval>;
}

impl Solid for Primitive {
    /// [`Primitive::interval`].
    fn span(&self, ray: &Ray) -> Option<RayInterval> {
        self.interval(ray)
    }
}

/// What a rendering cost, for comparing plain and layered Goldfeather.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Parity tests done: one per pass that draws both faces of one
    /// primitive into the stencil to classify the fragments in the buffer.
    pub parity_tests: u64,
    /// Layers extracted, summed over products (0 for plain Goldfeather).
    pub layers: u64,
}

/// Which side of a convex primitive a fragment comes from.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Face {
    /// Where the viewing ray enters the primitive (`span.near`).
    Front,
    /// Where the viewing ray leaves the primitive (`span.far`).
    Back,
}

/// What a pixel of the colour plane shows: one face of one primitive.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Surface {
    /// The primitive's index.
    pub primitive: usize,
    /// Its face.
    pub face: Face,
}

/// An orthographic camera: a grid of parallel rays.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    width: u32,
    height: u32,
    centre: Vec3,
    right: Vec3,
    up: Vec3,
    forward: Vec3,
    pixels_per_unit: f32,
}

impl Camera {
    /// A `width × height` camera whose middle pixel looks at `centre`.
    /// It is turned as every camera of the course ([`scene::turn`]): it
    /// looks along `−z` tilted by `pitch` about its own x axis (negative:
    /// down), then turned by `yaw` about the world's up axis, y (radians);
    /// one world unit covers `pixels_per_unit` pixels.
    ///
    /// ```text
    ///   ray of pixel (x, y):  o = centre + u·right + v·up,  d = forward
    ///   u = (x − (width − 1)/2) / pixels_per_unit,  v likewise in y
    /// ```
    ///
    /// # Errors
    /// [`CsgError::BadSize`] for an empty or too large grid,
    /// [`CsgError::BadCamera`] for non-finite angles or centre or a scale
    /// that is not finite and positive.
    pub fn new(
        width: u32,
        height: u32,
        centre: Vec3,
        yaw: f32,
        pitch: f32,
        pixels_per_unit: f32,
    ) -> Result<Self, CsgError> {
        if width == 0 || height == 0 || u64::from(width) * u64::from(height) > MAX_PIXELS {
            return Err(CsgError::BadSize { width, height });
        }
        if !centre.is_finite() || !yaw.is_finite() || !pitch.is_finite() {
            return Err(CsgError::BadCamera("centre and angles must be finite"));
        }
        if !pixels_per_unit.is_finite() || pixels_per_unit <= 0.0 {
            return Err(CsgError::BadCamera(
                "pixels_per_unit must be finite and positive",
            ));
        }
        let turn = scene::turn(f64::from(yaw), f64::from(pitch)).as_mat3();
        Ok(Self {
            width,
            height,
            centre,
            right: turn * Vec3::X,
            up: turn * Vec3::Y,
            forward: turn * Vec3::NEG_Z,
            pixels_per_unit,
        })
    }

    /// The grid's width in pixels.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.width
    }

    /// The grid's height in pixels.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The viewing ray of pixel `p` (also outside the grid).
    #[must_use]
    pub fn ray(&self, p: Pixel) -> Ray {
        let u = (p.x as f32 - 0.5 * (self.width as f32 - 1.0)) / self.pixels_per_unit;
        let v = (p.y as f32 - 0.5 * (self.height as f32 - 1.0)) / self.pixels_per_unit;
        Ray {
            origin: self.centre + u * self.right + v * self.up,
            direction: self.forward,
        }
    }

    /// Every pixel of the grid, row by row from the bottom.
    pub fn pixels(&self) -> impl Iterator<Item = Pixel> + use<> {
        let (w, h) = (self.width as i32, self.height as i32);
        (0..h).flat_map(move |y| (0..w).map(move |x| Pixel::new(x, y)))
    }
}

/// Everything that decides what a fragment does (OpenGL's per-fragment
/// state). Start from [`State::DEFAULT`] and change fields.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct State {
    /// The depth function: incoming depth against the stored one.
    pub depth_func: Compare,
    /// Whether a fragment that passes both tests writes its depth.
    pub depth_write: bool,
    /// Whether a fragment that passes both tests writes its surface.
    pub colour_write: bool,
    /// The stencil test, operations and masks.
    pub stencil: StencilState,
}

impl State {
    /// The z-buffer algorithm: depth `Less`, both writes on, stencil off.
    pub const DEFAULT: Self = Self {
        depth_func: Compare::Less,
        depth_write: true,
        colour_write: true,
        stencil: StencilState::DEFAULT,
    };
}

/// Depth, stencil and surface planes over a camera's pixel grid.
#[transcript::evidence]
#[derive(Clone, Debug, PartialEq)]
pub struct Framebuffer {
    camera: Camera,
    depth: Vec<f32>,
    stencil: Vec<u8>,
    surface: Vec<Option<Surface>>,
    fragments: u64,
    /// What [`Framebuffer::merge_less`] received, where recorded.
    merges: Option<Vec<Framebuffer>>,
}

impl Framebuffer {
    /// A cleared framebuffer (depth [`DEPTH_FAR`], stencil 0, no surface)
    /// for `camera`'s grid.
    #[must_use]
    pub fn new(camera: Camera) -> Self {
        let n = camera.width as usize * camera.height as usize;
        Self {
            camera,
            depth: vec![DEPTH_FAR; n],
            stencil: vec![0; n],
            surface: vec![None; n],
            fragments: 0,
            merges: None,
        }
    }

    /// A cleared framebuffer that also keeps a copy of every buffer
    /// merged into it ([`Framebuffer::merges`]): the seed's pictures of
    /// what each pass of a product contributes (Abbildung 9 and 13).
    #[must_use]
    pub fn recording_merges(camera: Camera) -> Self {
        Self {
            merges: Some(Vec::new()),
            ..Self::new(camera)
        }
    }

    /// The buffers merged so far, in order, if this framebuffer was made
    /// by [`Framebuffer::recording_merges`]; empty otherwise.
    #[must_use]
    pub fn merges(&self) -> &[Framebuffer] {
        self.merges.as_deref().unwrap_or_default()
    }

    /// The camera.
    #[must_use]
    pub fn camera(&self) -> &Camera {
        &self.camera
    }

    fn index(&self, p: Pixel) -> Option<usize> {
        let (w, h) = (self.camera.width as i32, self.camera.height as i32);
        ((0..w).contains(&p.x) && (0..h).contains(&p.y)).then(|| (p.y * w + p.x) as usize)
    }

    /// The stored depth, `None` outside the grid.
    #[must_use]
    pub fn depth(&self, p: Pixel) -> Option<f32> {
        self.index(p).map(|i| self.depth[i])
    }

    /// The stored stencil value, `None` outside the grid.
    #[must_use]
    pub fn stencil(&self, p: Pixel) -> Option<u8> {
        self.index(p).map(|i| self.stencil[i])
    }

    /// The surface shown, `None` for background or outside the grid.
    #[must_use]
    pub fn surface(&self, p: Pixel) -> Option<Surface> {
        self.index(p).and_then(|i| self.surface[i])
    }

    /// The largest stencil value of all pixels.
    #[must_use]
    pub fn max_stencil(&self) -> u8 {
        self.stencil.iter().copied().max().unwrap_or(0)
    }

    /// How many fragments all draws so far have produced (a cost measure).
    #[must_use]
    pub fn fragments(&self) -> u64 {
        self.fragments
    }

    /// Resets depth, stencil and surfaces.
    pub fn clear(&mut self) {
        self.clear_depth_and_colour();
        self.clear_stencil(0);
    }

    /// Resets depth to [`DEPTH_FAR`] and surfaces to none.
    pub fn clear_depth_and_colour(&mut self) {
        self.depth.fill(DEPTH_FAR);
        self.surface.fill(None);
    }

    /// Sets every stencil value to `value`.
    pub fn clear_stencil(&mut self, value: u8) {
        self.stencil.fill(value);
    }

    /// Rasterizes one face of `solid` (`surface.face`), recording
    /// `surface` where a fragment passes: every pixel whose ray hits the
    /// solid ([`Solid::span`]) gets one fragment at the face's depth,
    /// processed as OpenGL does:
    ///
    /// ```text
    ///   stencil test fails          → stencil op `fail`
    ///   else depth test fails       → stencil op `depth_fail`
    ///   else                        → stencil op `pass`, then depth and
    ///                                 surface written if their masks allow
    /// ```
    pub fn draw<S: Solid + ?Sized>(&mut self, solid: &S, surface: Surface, state: &State) {
        let camera = self.camera;
        for (i, p) in camera.pixels().enumerate() {
            let Some(span) = solid.span(&camera.ray(p)) else {
                continue;
            };
            let depth = match surface.face {
                Face::Front => span.near,
                Face::Back => span.far,
            };
            if depth.is_finite() {
                self.fragment(i, depth, Some(surface), state);
            }
        }
    }

    /// Draws a fragment at [`DEPTH_FAR`] carrying no surface at every pixel
    /// — a full-screen rectangle on the far plane. With `depth_func:
    /// Always` and a stencil test this is how an OpenGL program erases the
    /// pixels the stencil selects.
    pub fn draw_background(&mut self, state: &State) {
        for i in 0..self.depth.len() {
            self.fragment(i, DEPTH_FAR, None, state);
        }
    }

    fn fragment(&mut self, i: usize, depth: f32, surface: Option<Surface>, state: &State) {
        self.fragments += 1;
        let s = &state.stencil;
        let stored = self.stencil[i];
        let op = if !s.test(stored) {
            s.stencil_fail
        } else if !state.depth_func.passes(depth, self.depth[i]) {
            s.depth_fail
        } else {
            if state.depth_write {
                self.depth[i] = depth;
            }
            if state.colour_write {
                self.surface[i] = surface;
            }
            s.depth_pass
        };
        self.stencil[i] = write_masked(stored, op.apply(stored, s.reference), s.write_mask);
    }

    /// Writes depth and surface at one pixel if `depth` is nearer than the
    /// stored depth (z-less, no stencil): the ray caster's output path.
    pub fn write_less(&mut self, p: Pixel, depth: f32, surface: Surface) {
        if let Some(i) = self.index(p)
            && depth < self.depth[i]
        {
            self.depth[i] = depth;
            self.surface[i] = Some(surface);
        }
    }

    /// Copies every pixel of `other` that is nearer than this one's
    /// (z-less), depth and surface: how a product computed in a second
    /// buffer joins the sum in the frame buffer (seed §4.4).
    ///
    /// Both framebuffers must have the same camera; pixels outside the
    /// smaller grid are ignored.
    pub fn merge_less(&mut self, other: &Self) {
        if let Some(merges) = &mut self.merges {
            merges.push(Self {
                merges: None,
                ..other.clone()
            });
        }
        for p in self.camera.pixels() {
            if let (Some(i), Some(j)) = (self.index(p), other.index(p))
                && other.depth[j] < self.depth[i]
            {
                self.depth[i] = other.depth[j];
                self.surface[i] = other.surface[j];
            }
        }
    }
}
