//! The surface scene (topic 07): the seed's hill, a bicubic Bézier patch
//! whose control points you raise and lower, evaluated by your surface
//! code, trimmed by your trims and rendered by your `render_surface` — the thesis's program (seed 000 §3.1, §4), in
//! which the user chooses the trim shape, its parameters and the
//! tessellation level and looks at the result, lit or as a wireframe.
//!
//! ```text
//!   (u, v) ──your surface──▶ position, normal ──your render_surface──▶ picture
//!                              your trim ──▲ (per fragment: discard?)
//! ```
//!
//! Beside the picture, the parameter square as your trim sees it: each
//! sample cut away or kept.

use std::cell::RefCell;

use canvas::{Canvas, Pixel, Rgba};
use glam::{DVec2, DVec3};

use crate::stages::{Stages, Status, SurfaceView, TrimFn, guarded};
use crate::worker::Worker;

/// The trim shapes of seed 000 §3 (and §5's nested regions).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TrimShape {
    /// Nothing is cut away.
    None,
    /// `u` and `v` both in an interval (§3.1).
    Rectangle,
    /// Within a radius of a centre (§3.2).
    Circle,
    /// Inside an axis-aligned ellipse (§3.3, eq. 14).
    Ellipse,
    /// Between two quadratic Bézier curves, found by Newton's method
    /// (§3.4, Abbildung 11).
    NewtonQuadratic,
    /// Between two cubic Bézier curves (Abbildung 24).
    NewtonCubic,
    /// A quadratic region with another one inside it kept (Abbildung 12).
    Nested,
}

impl TrimShape {
    /// Every shape, in the order of the controls.
    pub const ALL: [Self; 7] = [
        Self::None,
        Self::Rectangle,
        Self::Circle,
        Self::Ellipse,
        Self::NewtonQuadratic,
        Self::NewtonCubic,
        Self::Nested,
    ];

    /// Its name on screen.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::None => "No trim",
            Self::Rectangle => "Rectangle",
            Self::Circle => "Circle",
            Self::Ellipse => "Ellipse",
            Self::NewtonQuadratic => "Newton, quadratic curves",
            Self::NewtonCubic => "Newton, cubic curves",
            Self::Nested => "Newton, nested",
        }
    }

    /// Your code that decides it: topic 07's type and method.
    #[must_use]
    pub fn source(self) -> &'static str {
        match self {
            Self::None => "nothing to trim",
            Self::Rectangle => "07-bezier · simple_trim::IntervalTrim::trims",
            Self::Circle => "07-bezier · simple_trim::CircleTrim::trims",
            Self::Ellipse => "07-bezier · simple_trim::EllipseTrim::trims",
            Self::NewtonQuadratic | Self::NewtonCubic => {
                "07-bezier · newton_trim::NewtonTrim::trims (newton, between_crossings)"
            }
            Self::Nested => "07-bezier · newton_trim::NestedNewtonTrim::trims",
        }
    }

    /// Whether Newton's method decides it.
    #[must_use]
    pub fn newton(self) -> bool {
        matches!(
            self,
            Self::NewtonQuadratic | Self::NewtonCubic | Self::Nested
        )
    }
}

/// The region between two quadratic curves of Abbildung 11: the upper
/// curve `P0 P1 P2`, the lower `P0 P3 P2`.
pub const QUADRATIC: [DVec2; 4] = [
    DVec2::new(0.2, 0.5),
    DVec2::new(0.5, 0.9),
    DVec2::new(0.8, 0.5),
    DVec2::new(0.5, 0.1),
];
/// The region between two cubic curves of Abbildung 24: the upper curve
/// `P0 P1 P2 P3`, the lower `P0 P4 P5 P3`.
pub const CUBIC: [DVec2; 6] = [
    DVec2::new(0.1, 0.5),
    DVec2::new(0.1 + 0.8 / 3.0, 0.95),
    DVec2::new(0.1 + 1.6 / 3.0, 0.75),
    DVec2::new(0.9, 0.5),
    DVec2::new(0.1 + 0.8 / 3.0, 0.2),
    DVec2::new(0.1 + 1.6 / 3.0, 0.05),
];
/// The region kept inside [`QUADRATIC`] in the nested trim (Abbildung 12).
pub const INNER: [DVec2; 4] = [
    DVec2::new(0.35, 0.5),
    DVec2::new(0.5, 0.7),
    DVec2::new(0.65, 0.5),
    DVec2::new(0.5, 0.3),
];

/// A trim and its parameters, in the parameter square `[0, 1]²`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrimSetup {
    /// Which shape.
    pub shape: TrimShape,
    /// The shape's centre (Newton regions: where the middle of their
    /// curves' square goes).
    pub centre: DVec2,
    /// Half the rectangle's sides; the circle's radius in `x`; the
    /// ellipse's radii.
    pub size: DVec2,
    /// How much the Newton regions are scaled about their centre.
    pub scale: f64,
    /// Newton's most steps (seed §5.2: 6 and 7 differ).
    pub iterations: u32,
    /// Newton stops after a step shorter than this (seed §5.2: ε from 0.1
    /// to 0.0001).
    pub epsilon: f64,
}

impl Default for TrimSetup {
    /// The circle of the seed's Abbildung 15 with Newton's default
    /// settings (10 steps, ε = 0.001).
    fn default() -> Self {
        Self {
            shape: TrimShape::Circle,
            centre: DVec2::splat(0.5),
            size: DVec2::new(0.2, 0.15),
            scale: 1.0,
            iterations: 10,
            epsilon: 0.001,
        }
    }
}

impl TrimSetup {
    /// The control points of a Newton shape's curves, moved and scaled
    /// (the curves of the seed's figures at the defaults).
    #[must_use]
    pub fn curve_points<const N: usize>(&self, points: [DVec2; N]) -> [DVec2; N] {
        points.map(|p| self.centre + (p - DVec2::splat(0.5)) * self.scale)
    }
}

/// What to draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceSetup {
    /// The heights (`y`) of the control points `P_ij` of the bicubic
    /// patch over `[-0.5, 0.5]²` (`i` along `u` = +x, `j` along `v` = −z):
    /// the seed's hill, or what you make of it.
    pub heights: [[f64; 4]; 4],
    /// The trim.
    pub trim: TrimSetup,
    /// Grid cells per side of the parameter square (the seed's
    /// `tessLevel`), `1 ..= 64`.
    pub level: u32,
    /// The tessellation grid over the shaded surface.
    pub wireframe: bool,
    /// The camera's angle around the hill's vertical axis, in degrees.
    pub yaw: f64,
    /// Its angle above the ground plane, in degrees.
    pub pitch: f64,
    /// Its distance from the hill's centre.
    pub distance: f64,
    /// The picture's width in pixels.
    pub width: u32,
    /// The picture's height in pixels.
    pub height: u32,
}

/// The point the camera looks at: the middle of the hill.
pub const TARGET: DVec3 = DVec3::new(0.0, 0.1, 0.0);
/// The lowest and highest control point.
pub const HEIGHTS: std::ops::RangeInclusive<f64> = -1.5..=1.5;
/// The highest tessellation level (topic 07's `MAX_TESS_LEVEL`).
pub const MAX_LEVEL: u32 = 64;
/// The background of the picture.
pub const BACKGROUND: Rgba = Rgba::rgb(0.15, 0.2, 0.3);
/// Samples per side of the parameter square beside the picture.
pub const UV_SAMPLES: u32 = 96;

impl Default for SurfaceSetup {
    /// The seed's view of the hill (topic 07's figures): from above and in
    /// front, level 24, lit.
    fn default() -> Self {
        let hill = freeform::BezierPatch::seed_hill();
        Self {
            heights: std::array::from_fn(|i| std::array::from_fn(|j| hill.control_point(i, j).y)),
            trim: TrimSetup::default(),
            level: 24,
            wireframe: false,
            yaw: 0.0,
            pitch: 1.5f64.atan2(1.3).to_degrees(),
            distance: 1.5f64.hypot(1.3),
            width: 560,
            height: 420,
        }
    }
}

impl SurfaceSetup {
    /// Keeps the set-up drawable: level, angles, distance, sizes and trim
    /// parameters in range and finite.
    pub fn tidy(&mut self) {
        let finite_or = |v: f64, fallback: f64| if v.is_finite() { v } else { fallback };
        let defaults = Self::default();
        self.level = self.level.clamp(1, MAX_LEVEL);
        self.yaw = finite_or(self.yaw, defaults.yaw).clamp(-180.0, 180.0);
        self.pitch = finite_or(self.pitch, defaults.pitch).clamp(-89.0, 89.0);
        self.distance = finite_or(self.distance, defaults.distance).clamp(0.8, 8.0);
        self.width = self.width.clamp(16, 2048);
        self.height = self.height.clamp(16, 2048);
        for (row, hill) in self.heights.iter_mut().zip(defaults.heights) {
            for (h, fallback) in row.iter_mut().zip(hill) {
                *h = finite_or(*h, fallback).clamp(*HEIGHTS.start(), *HEIGHTS.end());
            }
        }
        let trim = &mut self.trim;
        let fallback = TrimSetup::default();
        if !trim.centre.is_finite() {
            trim.centre = fallback.centre;
        }
        trim.centre = trim.centre.clamp(DVec2::ZERO, DVec2::ONE);
        if !trim.size.is_finite() {
            trim.size = fallback.size;
        }
        trim.size = trim.size.clamp(DVec2::splat(0.01), DVec2::splat(1.0));
        trim.scale = finite_or(trim.scale, 1.0).clamp(0.1, 2.0);
        trim.iterations = trim.iterations.clamp(1, 30);
        trim.epsilon = finite_or(trim.epsilon, fallback.epsilon).clamp(1e-6, 0.5);
    }

    /// The patch: the hill's grid of control points at the set heights.
    ///
    /// # Panics
    /// If a height is not finite (`tidy` keeps them finite).
    #[must_use]
    pub fn net(&self) -> freeform::BezierPatch {
        freeform::BezierPatch::from_fn(3, 3, |i, j| {
            DVec3::new(
                -0.5 + i as f64 / 3.0,
                self.heights[i][j],
                0.5 - j as f64 / 3.0,
            )
        })
        .expect("finite heights")
    }

    /// Where the camera stands.
    #[must_use]
    pub fn eye(&self) -> DVec3 {
        TARGET + self.distance * crate::render::orbit_direction(self.yaw, self.pitch)
    }
}

/// What the scene shows.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceDrawing {
    /// What was drawn.
    pub setup: SurfaceSetup,
    /// The picture, as far as your code got (the background where
    /// nothing was drawn).
    pub canvas: Canvas,
    /// The parameter square as your trim sees it: cut away dark, kept
    /// light; all light where the trim could not be asked.
    pub uv_map: Canvas,
    /// The same samples, row by row from `v = 0` up: whether each is cut
    /// away.
    pub cut: Vec<bool>,
    /// How your surface evaluation fared.
    pub surface: Status,
    /// How your trim fared.
    pub trim: Status,
    /// How your `render_surface` fared.
    pub render: Status,
}

/// The worker that draws the surface.
pub type SurfaceWorker = Worker<SurfaceSetup, SurfaceDrawing>;

/// A worker drawing with `stages`.
#[must_use]
pub fn worker(stages: Stages) -> SurfaceWorker {
    Worker::start(move |setup: SurfaceSetup| draw(&setup, &stages))
}

/// A sample of the parameter square the trim keeps.
const KEPT: Rgba = Rgba::rgb(0.85, 0.8, 0.6);
/// A sample the trim cuts away.
const CUT: Rgba = Rgba::rgb(0.2, 0.12, 0.12);

/// Draws `setup` with your stages.
#[must_use]
pub fn draw(setup: &SurfaceSetup, stages: &Stages) -> SurfaceDrawing {
    let mut setup = *setup;
    setup.tidy();
    let mut canvas = Canvas::new(setup.width, setup.height);
    canvas.clear(BACKGROUND);
    let mut uv_map = Canvas::new(UV_SAMPLES, UV_SAMPLES);
    uv_map.clear(KEPT);

    // The surface: one guarded call per point, so that a `todo!()` is
    // named and stops the evaluation, not the viewer.
    let net = setup.net();
    let surface_status = RefCell::new(match stages.surface.run {
        Some(_) => Status::Unused,
        None => Status::Missing,
    });
    let surface = |uv: DVec2| -> Result<(DVec3, DVec3), String> {
        let Some(run) = &stages.surface.run else {
            return Err("topic 07 is not in this build".to_owned());
        };
        let mut status = surface_status.borrow_mut();
        match guarded(&mut status, || run(&net, uv)) {
            Some(Ok(sample)) => Ok(sample),
            Some(Err(error)) => {
                *status = Status::Failed(error.clone());
                Err(error)
            }
            None => Err(status.describe()),
        }
    };
    // Asked once first, so that an unwritten surface is named even when
    // the render never asks.
    let _ = surface(DVec2::splat(0.5));

    let mut trim_status = match stages.trim.run {
        Some(_) => Status::Unused,
        None => Status::Missing,
    };
    let mut your_trim: Option<TrimFn> = None;
    if setup.trim.shape != TrimShape::None
        && let Some(build) = &stages.trim.run
    {
        match guarded(&mut trim_status, || build(&setup.trim)) {
            Some(Ok(trim)) => your_trim = Some(trim),
            Some(Err(error)) => trim_status = Status::Failed(error),
            None => {}
        }
    } else if setup.trim.shape == TrimShape::None {
        trim_status = Status::Unused;
    }
    let trim_status = RefCell::new(trim_status);
    // A trim that panics is named and trims nothing from then on: the
    // surface still shows.
    let trims = |uv: DVec2| -> bool {
        let Some(trim) = &your_trim else {
            return false;
        };
        guarded(&mut trim_status.borrow_mut(), || trim(uv)).unwrap_or(false)
    };
    let mut cut = Vec::with_capacity((UV_SAMPLES * UV_SAMPLES) as usize);
    for y in 0..UV_SAMPLES as i32 {
        for x in 0..UV_SAMPLES as i32 {
            let uv = (DVec2::new(f64::from(x), f64::from(y)) + 0.5) / f64::from(UV_SAMPLES);
            let trimmed = trims(uv);
            if trimmed {
                uv_map.set(Pixel::new(x, y), CUT);
            }
            cut.push(trimmed);
        }
    }

    let mut render_status = Status::Missing;
    if let Some(render) = &stages.surface_render.run {
        render_status = Status::Unused;
        let view = SurfaceView {
            level: setup.level,
            wireframe: setup.wireframe,
            eye: setup.eye(),
            target: TARGET,
            background: BACKGROUND,
        };
        let drawn = guarded(&mut render_status, || {
            render(&mut canvas, &surface, &trims, &view)
        });
        if let Some(Err(error)) = drawn {
            render_status = if surface_status.borrow().usable() {
                Status::Failed(error)
            } else {
                Status::NotReached
            };
        }
    }
    SurfaceDrawing {
        setup,
        canvas,
        uv_map,
        cut,
        surface: surface_status.into_inner(),
        trim: trim_status.into_inner(),
        render: render_status,
    }
}
