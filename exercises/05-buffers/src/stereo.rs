//! Stereo buffering: one picture per eye. Seed 002 §6.1 "Double u. Stereo
//! Buffering": a stereo-capable system has a left and a right colour
//! buffer (`glDrawBuffer(GL_BACK_LEFT)`, `GL_BACK_RIGHT`), each drawn "aus
//! unterschiedlicher Kameraposition" (compare `gluLookAt`), and passive
//! stereo shows both at once through colour filters, "meist rot-grün": an
//! anaglyph.
//!
//! The seed does not say how the two cameras differ. The standard answer
//! (the geometry page the slide links, and Bourke's "Calculating stereo
//! pairs") is the **parallel-axis asymmetric frustum**: each eye stands
//! half the eye separation `s` to the side, looks in the same direction as
//! the mono camera, and its frustum is shifted back towards the middle so
//! that both frusta meet the *zero-parallax plane* at distance `c` in the
//! same window:
//!
//! ```text
//!          ├──────── window on the plane at distance c ────────┤
//!           ╲   ╲                                        ╱   ╱
//!            ╲    ╲  left frustum          right frustum╱   ╱
//!             ╲     ╲                                ╱    ╱
//!              ╲      ╲                           ╱     ╱
//!               L ●─── s/2 ───● mono eye ─── s/2 ───● R
//!               │ both look straight ahead, parallel │
//! ```
//!
//! A point on that plane lands on the same pixel in both pictures; one
//! farther away lies more to the right in the right picture (uncrossed
//! parallax), a nearer one more to the left (crossed). Turning both eyes
//! towards the target instead ("toe-in") is the common mistake: it tilts
//! the two image planes against each other and gives points away from the
//! centre a vertical parallax, which the eyes cannot fuse.
//!
//! Convention (see `canvas` and `scene::pipeline`): right-handed world, y
//! up, OpenGL clip space; the pictures are drawn by the given
//! [`scene::Pipeline`].
//!
//! The file is in two parts: what is given first, then your tasks, the
//! camera's two eyes ([`StereoCamera::eye_position`], `view`,
//! `projection`), [`render_stereo`] and [`anaglyph`].

#[allow(unused_imports)]
use canvas::{Canvas, CanvasError, Rgba};
#[allow(unused_imports)]
use glam::camera::rh::{proj::opengl, view};
use glam::{Mat4, Vec3};
pub use scene::pipeline::aspect_ratio;
#[allow(unused_imports)]
use scene::{Mesh, Mode, Pipeline};

// ─── Given ───────────────────────────────────────────────────────────────
// The eyes, the errors, the camera with its course values and its check,
// the stereo buffer and the glasses: you use them, you do not edit them.

/// One of the two eyes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Eye {
    /// The left eye (`GL_BACK_LEFT`); it looks through the red filter.
    Left,
    /// The right eye (`GL_BACK_RIGHT`); it looks through the green or cyan
    /// filter.
    Right,
}

impl Eye {
    /// Both eyes, left first.
    pub const BOTH: [Self; 2] = [Self::Left, Self::Right];

    /// Which way the eye moves along the camera's right vector: −1 for
    /// the left eye, +1 for the right.
    #[must_use]
    pub const fn side(self) -> f32 {
        match self {
            Self::Left => -1.0,
            Self::Right => 1.0,
        }
    }
}

/// Why a stereo camera or picture cannot be made.
#[transcript::evidence]
#[derive(Clone, Copy, Debug, PartialEq, thiserror::Error)]
pub enum StereoError {
    /// A position, direction or number is NaN or infinite.
    #[error("the stereo camera has a NaN or infinite value")]
    NotFinite,
    /// The eye stands on the target, or `up` is parallel to the view
    /// direction (or zero): there is no right vector.
    #[error("the camera has no view direction or no right vector")]
    NoDirection,
    /// The field of view is not in `(0, π)`, or not `0 < near < far`.
    #[error("the field of view must lie in (0, π) and 0 < near < far")]
    BadLens,
    /// The separation is negative, or the convergence distance not
    /// positive.
    #[error("the eye separation must be ≥ 0 and the convergence distance > 0")]
    BadStereo,
    /// The pictures would exceed [`Canvas::MAX_PIXELS`].
    #[error("the stereo pictures are too large")]
    TooLarge,
}

impl From<CanvasError> for StereoError {
    fn from(_: CanvasError) -> Self {
        Self::TooLarge
    }
}

/// A mono camera (`gluLookAt` and `gluPerspective`) split into two eyes.
///
/// Check a camera you build with [`StereoCamera::check`]; the functions
/// below assume a camera that passes it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StereoCamera {
    /// Where the mono camera stands: the point midway between the eyes.
    pub eye: Vec3,
    /// What the mono camera looks at.
    pub target: Vec3,
    /// Which way is up (need not be perpendicular to the view direction).
    pub up: Vec3,
    /// The vertical field of view in radians, in `(0, π)`.
    pub fov_y: f32,
    /// Distance from the eyes to the near clipping plane, `> 0`.
    pub near: f32,
    /// Distance from the eyes to the far clipping plane, `> near`.
    pub far: f32,
    /// The distance between the eyes, `s ≥ 0`, in world units.
    pub separation: f32,
    /// The distance `c > 0` of the zero-parallax plane from the eyes,
    /// along the view direction: what lies there appears on the screen,
    /// nearer in front of it, farther behind it.
    pub convergence: f32,
}

impl StereoCamera {
    /// The course camera of [`scene::pipeline`] (eye at
    /// [`scene::pipeline::EYE`] looking at the origin, its field of view,
    /// near and far planes) with the given separation, converging on the
    /// target (`c = 4`, the distance from the eye to the origin).
    #[must_use]
    pub fn course(separation: f32) -> Self {
        use scene::pipeline::{EYE, FAR, FOV_Y, NEAR, TARGET};
        Self {
            eye: EYE,
            target: TARGET,
            up: Vec3::Y,
            fov_y: FOV_Y,
            near: NEAR,
            far: FAR,
            separation,
            convergence: EYE.distance(TARGET),
        }
    }

    /// Whether the camera can be split into two eyes: every value finite,
    /// a view direction and a right vector, `0 < fov_y < π`,
    /// `0 < near < far`, `separation ≥ 0` and `convergence > 0`.
    pub fn check(&self) -> Result<(), StereoError> {
        let vectors = [self.eye, self.target, self.up];
        let numbers = [
            self.fov_y,
            self.near,
            self.far,
            self.separation,
            self.convergence,
        ];
        if !vectors.iter().all(|v| v.is_finite()) || !numbers.iter().all(|x| x.is_finite()) {
            return Err(StereoError::NotFinite);
        }
        let right = (self.target - self.eye).cross(self.up);
        if right.length_squared() <= f32::EPSILON * (self.target - self.eye).length_squared() {
            return Err(StereoError::NoDirection);
        }
        let lens = self.fov_y > 0.0
            && self.fov_y < std::f32::consts::PI
            && self.near > 0.0
            && self.near < self.far;
        if !lens {
            return Err(StereoError::BadLens);
        }
        if self.separation < 0.0 || self.convergence <= 0.0 {
            return Err(StereoError::BadStereo);
        }
        Ok(())
    }
}

/// The two back buffers of a stereo framebuffer, one per eye, each a
/// cleared canvas with its own depth plane.
#[transcript::evidence]
#[derive(Clone, Debug, PartialEq)]
pub struct StereoBuffer {
    left: Canvas,
    right: Canvas,
}

impl StereoBuffer {
    /// Two cleared `width × height` canvases (colour black, depth
    /// [`canvas::DEPTH_CLEAR`]).
    pub fn try_new(width: u32, height: u32) -> Result<Self, StereoError> {
        Ok(Self {
            left: Canvas::try_new(width, height)?,
            right: Canvas::try_new(width, height)?,
        })
    }

    /// The picture of `eye`.
    #[must_use]
    pub fn get(&self, eye: Eye) -> &Canvas {
        match eye {
            Eye::Left => &self.left,
            Eye::Right => &self.right,
        }
    }

    /// The buffer that drawing goes to for `eye` (`glDrawBuffer`).
    pub fn draw_buffer(&mut self, eye: Eye) -> &mut Canvas {
        match eye {
            Eye::Left => &mut self.left,
            Eye::Right => &mut self.right,
        }
    }
}

/// Which filters the viewer's glasses have; the left eye always looks
/// through red.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Glasses {
    /// Red left, green right: the seed's "rot-grün" filters.
    RedGreen,
    /// Red left, cyan (green and blue) right: more of the right picture's
    /// colour survives.
    RedCyan,
}

// ─── Your tasks (Task 7) ──────────────────────────────────────────────────

impl StereoCamera {
    /// Where `eye` stands: the mono eye moved by half the separation along
    /// the camera's right vector `normalize((target − eye) × up)`, to the
    /// left (−) for the left eye and to the right (+) for the right eye.
    #[must_use]
    #[transcript::task]
    pub fn eye_position(&self, eye: Eye) -> Vec3 {
        // Unused until you write the body:
        let _ = &eye;
        todo!("stereo: move the mono eye by ±s/2 along normalize((target − eye) × up)")
    }

    /// The view matrix of `eye` (world → eye space, as `gluLookAt`): from
    /// [`StereoCamera::eye_position`], looking in the mono camera's
    /// direction, with its `up`. The two eyes' axes are parallel: do not
    /// turn them towards the target (toe-in).
    #[must_use]
    #[transcript::task]
    pub fn view(&self, eye: Eye) -> Mat4 {
        // Unused until you write the body:
        let _ = &eye;
        todo!(
            "stereo: look from the eye's position at the target moved by the same offset, so the axes stay parallel"
        )
    }

    /// The projection of `eye` for pictures of the given aspect ratio
    /// (width / height): `glFrustum(l, r, b, t, near, far)` with
    ///
    /// ```text
    /// t = near · tan(fov_y / 2),  b = −t           (as gluPerspective)
    /// a = t · aspect                               half the width at near
    /// d = s/2 · near / c                           the frustum's shift
    /// left eye:  l = −a + d,  r = a + d
    /// right eye: l = −a − d,  r = a − d
    /// ```
    ///
    /// Each window is moved towards the middle by the eye's offset `s/2`,
    /// scaled from the zero-parallax plane (distance `c`) back to the near
    /// plane, so that both frusta cut the same window out of the plane at
    /// `c`. With `s = 0` this is `gluPerspective`.
    #[must_use]
    #[transcript::task]
    pub fn projection(&self, eye: Eye, aspect: f32) -> Mat4 {
        // Unused until you write the body:
        let _ = (&eye, &aspect);
        todo!(
            "stereo: the mono window at the near plane (t = near·tan(fov/2), a = t·aspect), shifted by −side·(s/2)·near/c, as glFrustum"
        )
    }
}

/// Renders `mesh` once per eye into a new `width × height` stereo buffer:
/// for each eye, a [`Pipeline`] with the identity model matrix and the
/// eye's [`StereoCamera::view`] and [`StereoCamera::projection`] (for
/// [`aspect_ratio`]) draws the mesh's [`Pipeline::clip_space`] polygons
/// with [`Pipeline::render`] in `mode` into that eye's draw buffer.
///
/// The polygons are not clipped: use a mesh that lies in both view
/// volumes (the shipped `torus.ply` and `star.ply` do for the course
/// camera). An error for a camera that fails [`StereoCamera::check`] (no
/// picture is drawn) or pictures that are too large.
#[transcript::task]
pub fn render_stereo(
    camera: &StereoCamera,
    mesh: &Mesh,
    mode: Mode,
    width: u32,
    height: u32,
) -> Result<StereoBuffer, StereoError> {
    // Unused until you write the body:
    let _ = (&camera, &mesh, &mode, &width, &height);
    todo!(
        "stereo: check the camera, then for each eye build its pipeline and render the mesh into that eye's draw buffer"
    )
}

/// The anaglyph of a stereo pair, for passive stereo with colour filters:
/// every pixel takes its red from the left picture and its green from the
/// right one; its blue comes from the right picture through red-cyan
/// glasses and is 0 through red-green ones; alpha is 1. Each eye's filter
/// then passes (mostly) its own picture.
#[must_use]
#[transcript::task]
pub fn anaglyph(buffer: &StereoBuffer, glasses: Glasses) -> Canvas {
    // Unused until you write the body:
    let _ = (&buffer, &glasses);
    todo!(
        "stereo: per pixel, red from the left picture, green (and through red-cyan glasses blue) from the right one, alpha 1"
    )
}
