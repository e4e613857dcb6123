//! What the surface scene draws: the hill by your surface, trim and
//! render.

use std::cell::RefCell;

use canvas::{Canvas, Pixel, Rgba};
use glam::{DVec2, DVec3};

use crate::stages::trim::{TrimSetup, TrimShape};
use crate::stages::{Stages, Status, SurfaceView, TrimFn, guarded};
use crate::worker::Worker;

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
        self.trim.tidy();
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
        TARGET + self.distance * crate::camera::orbit_direction(self.yaw, self.pitch)
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
