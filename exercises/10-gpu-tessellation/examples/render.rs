//! Renders the seed's figures (seed 000 §3-4) into `target/gpu-tessellation/`:
//! a plain patch, each trim type, nested trims, the wireframe at level 32,
//! and several patches, through the whole GPU path: your control pass,
//! the primitive generator, your evaluation pass, your shading and trimming.
//!
//! ```text
//! cargo run -p gpu-tessellation --example render
//! ```
//!
//! (Tutors see the solutions' figures by running it in the workspace that
//! `cargo xtask stage --reference DIR` writes.)

use std::path::PathBuf;

use glam::{Vec2, Vec3};
use gpu::Gpu;
use gpu_tessellation::domain::Spacing;
use gpu_tessellation::passes::{ControlSettings, LevelMode, Patches, run_control, run_evaluation};
use gpu_tessellation::patch::BezierPatch;
use gpu_tessellation::render::{DrawMesh, Scene, Shaders, TrimCurve, TrimShape, Trimming, render};
use gpu_tessellation::{TessError, shading, wgsl};

/// Picture size in pixels.
const SIZE: u32 = 512;

/// The seed's default surface (Listing 16's control point moves), moved
/// by `offset`: a unit square patch at y = 0 whose four inner points are
/// lifted to 0.5.
fn seed_patch(offset: Vec3) -> BezierPatch {
    BezierPatch::seed_hill()
        .map(|p| p + offset.as_dvec3())
        .expect("a finite offset")
}

struct Figure {
    name: &'static str,
    patches: Vec<BezierPatch>,
    level: LevelMode,
    trims: Vec<TrimShape>,
    wireframe: bool,
}

fn quad_curve(a: Vec2, b: Vec2, c: Vec2) -> TrimCurve {
    TrimCurve::Quadratic([a, b, c])
}

fn main() -> Result<(), TessError> {
    let Some(gpu) = Gpu::for_tests() else {
        return Ok(());
    };
    println!("adapter: {}", gpu.describe());
    let out = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../target/gpu-tessellation");
    let one = vec![seed_patch(Vec3::ZERO)];
    let (l, r) = (Vec2::new(0.2, 0.5), Vec2::new(0.8, 0.5));
    let lens = TrimShape::Bezier {
        upper: quad_curve(l, Vec2::new(0.5, 0.9), r),
        lower: quad_curve(l, Vec2::new(0.5, 0.1), r),
    };
    let cubic_lens = TrimShape::Bezier {
        upper: TrimCurve::Cubic([l, Vec2::new(0.3, 0.85), Vec2::new(0.7, 0.85), r]),
        lower: TrimCurve::Cubic([l, Vec2::new(0.3, 0.15), Vec2::new(0.7, 0.15), r]),
    };
    let (il, ir) = (Vec2::new(0.38, 0.5), Vec2::new(0.62, 0.5));
    let nested = TrimShape::Nested {
        outer: [
            quad_curve(
                Vec2::new(0.1, 0.5),
                Vec2::new(0.5, 1.0),
                Vec2::new(0.9, 0.5),
            ),
            quad_curve(
                Vec2::new(0.1, 0.5),
                Vec2::new(0.5, 0.0),
                Vec2::new(0.9, 0.5),
            ),
        ],
        inner: [
            quad_curve(il, Vec2::new(0.5, 0.7), ir),
            quad_curve(il, Vec2::new(0.5, 0.3), ir),
        ],
    };
    let uniform = LevelMode::Uniform(32.0);
    let figure = |name, trims: Vec<TrimShape>| Figure {
        name,
        patches: one.clone(),
        level: uniform,
        trims,
        wireframe: false,
    };
    let figures = vec![
        figure("plain", vec![]),
        figure(
            "trim_rectangle",
            vec![TrimShape::Rectangle {
                u: Vec2::new(0.3, 0.7),
                v: Vec2::new(0.4, 0.6),
            }],
        ),
        figure(
            "trim_circle",
            vec![TrimShape::Circle {
                centre: Vec2::splat(0.5),
                radius: 0.25,
            }],
        ),
        figure(
            "trim_ellipse",
            vec![TrimShape::Ellipse {
                centre: Vec2::splat(0.5),
                radii: Vec2::new(0.35, 0.2),
            }],
        ),
        figure("trim_bezier_quadratic", vec![lens]),
        figure("trim_bezier_cubic", vec![cubic_lens]),
        figure("trim_nested", vec![nested]),
        Figure {
            name: "wireframe_level_32",
            patches: one.clone(),
            level: uniform,
            trims: vec![],
            wireframe: true,
        },
        Figure {
            name: "several_patches_adaptive",
            patches: vec![
                seed_patch(Vec3::new(-1.05, 0.0, 0.0)),
                seed_patch(Vec3::ZERO),
                seed_patch(Vec3::new(1.05, 0.0, 0.0)),
                seed_patch(Vec3::new(0.0, 0.0, -1.05)),
            ],
            level: LevelMode::Adaptive {
                pixels_per_segment: 12.0,
            },
            trims: vec![],
            wireframe: true,
        },
    ];
    for figure in figures {
        let many = figure.patches.len() > 1;
        let eye = if many {
            Vec3::new(0.0, 2.2, 2.3)
        } else {
            Vec3::new(0.0, 1.1, 1.2)
        };
        let scene = Scene::perspective(eye, Vec3::new(0.0, 0.1, 0.0), SIZE, SIZE);
        let settings = ControlSettings {
            view_proj: scene.view_proj,
            viewport: Vec2::splat(SIZE as f32),
            mode: figure.level,
        };
        let levels = run_control(&gpu, wgsl::CONTROL, &figure.patches, &settings)?;
        let domains: Vec<_> = levels.iter().map(|l| l.domain(Spacing::Equal)).collect();
        let domain_refs: Vec<_> = domains.iter().collect();
        let mesh = run_evaluation(
            &gpu,
            wgsl::EVALUATION,
            Patches::Quads(&figure.patches),
            &domain_refs,
        )?;
        let edges = figure
            .wireframe
            .then(|| shading::wireframe_edges(&mesh.triangles));
        let trims = Trimming {
            shapes: figure.trims.clone(),
            ..Trimming::default()
        };
        let shaders = Shaders {
            shading: Some(wgsl::SHADING),
            trimming: (!trims.shapes.is_empty()).then_some((wgsl::TRIMMING, &trims)),
        };
        let picture = render(
            &gpu,
            SIZE,
            SIZE,
            &scene,
            shaders,
            &[DrawMesh {
                vertices: &mesh.vertices,
                triangles: &mesh.triangles,
                edges: edges.as_deref(),
            }],
        )?;
        let path = out.join(format!("{}.png", figure.name));
        picture
            .save_png(&path)
            .map_err(|e| TessError::Invalid(e.to_string()))?;
        println!(
            "{}: {} triangles, levels {:?} -> {}",
            figure.name,
            mesh.triangles.len(),
            levels.first().map(|l| l.outer),
            path.display()
        );
    }
    Ok(())
}
