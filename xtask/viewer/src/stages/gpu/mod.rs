//! The GPU scene's stage: what to draw (the surface, the levels, the
//! spacing, the trim, the camera) and your topic 10 passes drawing it.

use canvas::Canvas;

use super::Status;
use super::trim::{TrimSetup, TrimShape};

#[cfg(feature = "gpu-tessellation")]
mod frame;

#[cfg(feature = "gpu-tessellation")]
pub use frame::{GpuPieces, gpu_frame};

/// The surfaces of the scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GpuSurface {
    /// Seed 000's hill: one bicubic patch.
    Hill,
    /// Seed 001's bicubic patch.
    SeedSurface,
    /// The NURBS torus: 16 rational patches, raised to bicubic.
    Torus,
    /// The torus from its NURBS data, split by your topic 08.
    NurbsTorus,
    /// The vase (single interior knots), split by your topic 08.
    Vase,
}

impl GpuSurface {
    /// Every surface, in the order of the controls.
    pub const ALL: [Self; 5] = [
        Self::Hill,
        Self::SeedSurface,
        Self::Torus,
        Self::NurbsTorus,
        Self::Vase,
    ];

    /// Its name on screen.
    #[must_use]
    pub fn label(self) -> &'static str {
        match self {
            Self::Hill => "The hill",
            Self::SeedSurface => "The seed's patch",
            Self::Torus => "NURBS torus (16 rational patches, given)",
            Self::NurbsTorus => "NURBS torus, split by your topic 08",
            Self::Vase => "NURBS vase, split by your topic 08",
        }
    }

    /// The NURBS surface your topic 08 splits first, for those that are
    /// one (the chain NURBS → Bézier patches → the GPU's triangles).
    #[must_use]
    pub fn nurbs(self) -> Option<freeform::NurbsSurfaceData> {
        match self {
            Self::NurbsTorus => Some(freeform::NurbsSurfaceData::torus(0.7, 0.25)),
            Self::Vase => Some(freeform::NurbsSurfaceData::vase()),
            Self::Hill | Self::SeedSurface | Self::Torus => None,
        }
    }
}

/// How the control pass sets the levels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Levels {
    /// Every level the same.
    Uniform,
    /// From each boundary curve's length on screen.
    Adaptive,
}

/// The primitive generator's spacing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Spacing {
    /// `equal_spacing`.
    Equal,
    /// `fractional_even_spacing`.
    FractionalEven,
    /// `fractional_odd_spacing`.
    FractionalOdd,
}

/// What to draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GpuSetup {
    /// The surface.
    pub surface: GpuSurface,
    /// Uniform or adaptive levels.
    pub levels: Levels,
    /// The uniform level, `1 ..= 64`.
    pub level: f32,
    /// The adaptive levels' target: pixels per segment on screen.
    pub pixels_per_segment: f32,
    /// The spacing.
    pub spacing: Spacing,
    /// The trim (the surface scene's shapes, in each patch's `(u, v)`).
    pub trim: TrimSetup,
    /// The wireframe over the surface.
    pub wireframe: bool,
    /// The camera's angle around the vertical axis, degrees.
    pub yaw: f32,
    /// Its angle above the horizontal plane, degrees.
    pub pitch: f32,
    /// Its distance from the surface's centre.
    pub distance: f32,
    /// The picture's width in pixels.
    pub width: u32,
    /// Its height in pixels.
    pub height: u32,
}

impl Default for GpuSetup {
    /// The hill at level 8, untrimmed, with its wireframe, seen from above
    /// and in front.
    fn default() -> Self {
        Self {
            surface: GpuSurface::Hill,
            levels: Levels::Uniform,
            level: 8.0,
            pixels_per_segment: 12.0,
            spacing: Spacing::Equal,
            trim: TrimSetup {
                shape: TrimShape::None,
                ..TrimSetup::default()
            },
            wireframe: true,
            yaw: 0.0,
            pitch: 45.0,
            distance: 2.2,
            width: 560,
            height: 420,
        }
    }
}

impl GpuSetup {
    /// Keeps the set-up drawable: every number in range and finite.
    pub fn tidy(&mut self) {
        let defaults = Self::default();
        let finite_or = |v: f32, fallback: f32| if v.is_finite() { v } else { fallback };
        self.level = finite_or(self.level, defaults.level).clamp(1.0, 64.0);
        self.pixels_per_segment =
            finite_or(self.pixels_per_segment, defaults.pixels_per_segment).clamp(1.0, 200.0);
        self.yaw = finite_or(self.yaw, defaults.yaw).clamp(-180.0, 180.0);
        self.pitch = finite_or(self.pitch, defaults.pitch).clamp(-89.0, 89.0);
        self.distance = finite_or(self.distance, defaults.distance).clamp(0.8, 10.0);
        self.width = self.width.clamp(16, 2048);
        self.height = self.height.clamp(16, 2048);
        self.trim.tidy();
    }

    /// Where the camera stands, looking at `target` (y up).
    #[must_use]
    pub fn eye(&self, target: glam::Vec3) -> glam::Vec3 {
        let direction = crate::camera::orbit_direction(f64::from(self.yaw), f64::from(self.pitch));
        target + self.distance * direction.as_vec3()
    }
}

/// One stage of the GPU pipeline and how it fared.
#[derive(Clone, Debug, PartialEq)]
pub struct GpuStageReport {
    /// What it does: "control", "evaluation", ...
    pub name: &'static str,
    /// Your code: file or function.
    pub source: &'static str,
    /// How it fared.
    pub status: Status,
}

/// What the scene shows.
#[derive(Clone, Debug, PartialEq)]
pub struct GpuDrawing {
    /// What was drawn.
    pub setup: GpuSetup,
    /// The picture, when every stage it needs ran.
    pub canvas: Option<Canvas>,
    /// The stages in pipeline order.
    pub stages: Vec<GpuStageReport>,
    /// Triangles drawn.
    pub triangles: usize,
    /// The adapter (`name (backend, type)`), or why there is none.
    pub device: String,
}

/// The stages of the scene, in pipeline order, with their sources.
pub const STAGES: [(&str, &str); 6] = [
    ("control", "10-gpu-tessellation · src/control.wgsl"),
    (
        "primitive generator",
        "10-gpu-tessellation · domain::quad_domain",
    ),
    ("evaluation", "10-gpu-tessellation · src/evaluation.wgsl"),
    ("shading", "10-gpu-tessellation · src/shading.wgsl"),
    ("trimming", "10-gpu-tessellation · src/trimming.wgsl"),
    (
        "wireframe",
        "10-gpu-tessellation · shading::wireframe_edges",
    ),
];
