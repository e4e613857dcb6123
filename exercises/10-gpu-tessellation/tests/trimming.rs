//! Task 5: trimming in the fragment shader. A flat patch fills the picture
//! under an identity view, so pixel centre `(x, y)` shows
//! `(u, v) = ((x + ½)/w, (y + ½)/h)`; the CPU decides each pixel from the
//! shape's definition (Bézier regions by an even-odd test against a fine
//! polygon of their curves, not by Newton).

mod common;

use canvas::{Canvas, Rgba};
use common::tessellate_patch;
use glam::{DVec2, Mat4, Vec2};
use gpu::Gpu;
use gpu_tessellation::render::{
    DrawMesh, Scene, Shaders, TrimCurve, TrimShape, Trimming, render, vertex_buffer,
};
use gpu_tessellation::wgsl::{self, Piece};
use testkit::image::Tolerance;

/// Picture size.
const SIZE: u32 = 128;
/// 1 % of the pixels may differ: those whose centre lies within Newton's
/// ε or the interpolation's rounding of a shape's boundary.
const TRIMMED: Tolerance = Tolerance {
    channel: 2.0 / 255.0,
    mismatched_fraction: 0.01,
};
/// Segments per curve of the CPU's polygon (far finer than a pixel).
const FLATTENING: usize = 256;

fn trim_render(gpu: &Gpu, piece: Piece, trimming: &Trimming) -> Canvas {
    let domain = common::grid(4);
    let vertices = vertex_buffer(
        gpu,
        &tessellate_patch(&common::full_screen_patch(), &domain.points),
    );
    let mut scene = Scene::orthographic(Vec2::splat(-1.0), Vec2::splat(1.0), 1.0);
    scene.view_proj = Mat4::IDENTITY;
    let shaders = Shaders {
        shading: None,
        trimming: Some((piece, trimming)),
    };
    let mesh = DrawMesh {
        vertices: &vertices,
        triangles: &domain.triangles,
        edges: None,
    };
    render(gpu, SIZE, SIZE, &scene, shaders, &[mesh]).unwrap()
}

fn point(curve: &TrimCurve, t: f64) -> DVec2 {
    let mut p: Vec<DVec2> = match curve {
        TrimCurve::Quadratic(p) => p.iter().map(|q| q.as_dvec2()).collect(),
        TrimCurve::Cubic(p) => p.iter().map(|q| q.as_dvec2()).collect(),
    };
    while p.len() > 1 {
        p = p.windows(2).map(|w| w[0].lerp(w[1], t)).collect();
    }
    p[0]
}

/// The closed polygon around the region: `upper` from its start to its
/// end, then `lower` back to where `upper` started (either curve may run
/// either way).
fn region_polygon(upper: &TrimCurve, lower: &TrimCurve) -> Vec<DVec2> {
    let forward = (0..=FLATTENING).map(|k| point(upper, k as f64 / FLATTENING as f64));
    let lower_starts_at_the_end = point(lower, 0.0).distance(point(upper, 1.0)) < 1e-9;
    let back = (0..=FLATTENING).rev().map(|k| {
        let t = k as f64 / FLATTENING as f64;
        point(lower, if lower_starts_at_the_end { 1.0 - t } else { t })
    });
    forward.chain(back).collect()
}

/// Even-odd rule: crossings of the ray to +u.
fn inside_polygon(polygon: &[DVec2], p: DVec2) -> bool {
    let mut inside = false;
    for (i, &a) in polygon.iter().enumerate() {
        let b = polygon[(i + 1) % polygon.len()];
        if (a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            inside = !inside;
        }
    }
    inside
}

/// The definition of a shape as a predicate "trims `uv`" (Bézier regions
/// flattened once, up front).
fn cpu_predicate(shape: &TrimShape) -> Box<dyn Fn(DVec2) -> bool> {
    match *shape {
        TrimShape::Rectangle { u, v } => {
            let (u, v) = (u.as_dvec2(), v.as_dvec2());
            Box::new(move |p| p.x >= u.x && p.x <= u.y && p.y >= v.x && p.y <= v.y)
        }
        TrimShape::Circle { centre, radius } => {
            Box::new(move |p| p.distance(centre.as_dvec2()) < f64::from(radius))
        }
        TrimShape::Ellipse { centre, radii } => Box::new(move |p| {
            let d = (p - centre.as_dvec2()) / radii.as_dvec2();
            d.length_squared() <= 1.0
        }),
        TrimShape::Bezier { upper, lower } => {
            let polygon = region_polygon(&upper, &lower);
            Box::new(move |p| inside_polygon(&polygon, p))
        }
        TrimShape::Nested { outer, inner } => {
            let outer = region_polygon(&outer[0], &outer[1]);
            let inner = region_polygon(&inner[0], &inner[1]);
            Box::new(move |p| inside_polygon(&outer, p) && !inside_polygon(&inner, p))
        }
    }
}

fn cpu_render(shapes: &[TrimShape]) -> Canvas {
    let predicates: Vec<_> = shapes.iter().map(cpu_predicate).collect();
    common::cpu_picture(SIZE, SIZE, |uv| {
        if predicates.iter().any(|trims| trims(uv)) {
            Rgba::BLACK
        } else {
            Rgba::WHITE
        }
    })
}

#[track_caller]
fn check(name: &str, shapes: Vec<TrimShape>) {
    let piece = wgsl::TRIMMING.written();
    let Some(gpu) = common::gpu() else { return };
    let trimming = Trimming {
        shapes: shapes.clone(),
        ..Trimming::default()
    };
    let yours = trim_render(&gpu, piece, &trimming);
    common::assert_matches_cpu(name, &yours, &cpu_render(&shapes), TRIMMED);
}

fn quadratic(a: (f32, f32), b: (f32, f32), c: (f32, f32)) -> TrimCurve {
    TrimCurve::Quadratic([
        Vec2::new(a.0, a.1),
        Vec2::new(b.0, b.1),
        Vec2::new(c.0, c.1),
    ])
}

/// ```text
///        _---_          upper: (0.2, 0.5) (0.5, 0.95) (0.8, 0.5)
///   (0.2)     (0.8)     lower: (0.2, 0.5) (0.5, 0.1)  (0.8, 0.5)
///        -___-          end points on the line v = 0.5 (the seed's limit)
/// ```
fn quadratic_lens() -> TrimShape {
    TrimShape::Bezier {
        upper: quadratic((0.2, 0.5), (0.5, 0.95), (0.8, 0.5)),
        lower: quadratic((0.2, 0.5), (0.5, 0.1), (0.8, 0.5)),
    }
}

#[testkit::test]
fn rectangle_trims_the_closed_box() {
    check(
        "trim_rectangle",
        vec![TrimShape::Rectangle {
            u: Vec2::new(0.3, 0.7),
            v: Vec2::new(0.4, 0.6),
        }],
    );
}

#[testkit::test]
fn circle_trims_its_open_disk() {
    check(
        "trim_circle",
        vec![TrimShape::Circle {
            centre: Vec2::new(0.45, 0.55),
            radius: 0.3,
        }],
    );
}

#[testkit::test]
fn ellipse_trims_its_closed_inside() {
    check(
        "trim_ellipse",
        vec![TrimShape::Ellipse {
            centre: Vec2::new(0.5, 0.45),
            radii: Vec2::new(0.4, 0.2),
        }],
    );
}

#[testkit::test]
fn several_shapes_trim_their_union() {
    check(
        "trim_union",
        vec![
            TrimShape::Rectangle {
                u: Vec2::new(0.05, 0.3),
                v: Vec2::new(0.6, 0.95),
            },
            TrimShape::Circle {
                centre: Vec2::new(0.7, 0.3),
                radius: 0.2,
            },
            TrimShape::Ellipse {
                centre: Vec2::new(0.6, 0.8),
                radii: Vec2::new(0.1, 0.15),
            },
        ],
    );
}

#[testkit::test]
fn quadratic_bezier_region_is_trimmed_by_newton() {
    check("trim_bezier_quadratic", vec![quadratic_lens()]);
}

/// A curve reversed: the same points, the other way round.
fn reversed(curve: TrimCurve) -> TrimCurve {
    match curve {
        TrimCurve::Quadratic(mut p) => {
            p.reverse();
            TrimCurve::Quadratic(p)
        }
        TrimCurve::Cubic(mut p) => {
            p.reverse();
            TrimCurve::Cubic(p)
        }
    }
}

/// The lens with its curves running right to left: Newton from `t = 1` now
/// finds the *left* crossing, so a point inside has `x₁ < 0 < x₂`, the case
/// the seed's shader (Listing 11) does not test. Both curves reversed, and
/// one of each.
#[testkit::test]
fn curves_running_right_to_left_trim_the_same_region() {
    let TrimShape::Bezier { upper, lower } = quadratic_lens() else {
        unreachable!("the lens is a Bézier region")
    };
    check(
        "trim_bezier_right_to_left",
        vec![TrimShape::Bezier {
            upper: reversed(upper),
            lower: reversed(lower),
        }],
    );
    check(
        "trim_bezier_mixed_directions",
        vec![TrimShape::Bezier {
            upper: reversed(upper),
            lower,
        }],
    );
}

#[testkit::test]
fn cubic_bezier_region_is_trimmed_by_newton() {
    let (l, r) = (Vec2::new(0.15, 0.45), Vec2::new(0.85, 0.45));
    check(
        "trim_bezier_cubic",
        vec![TrimShape::Bezier {
            upper: TrimCurve::Cubic([l, Vec2::new(0.2, 0.95), Vec2::new(0.7, 0.9), r]),
            lower: TrimCurve::Cubic([l, Vec2::new(0.35, 0.1), Vec2::new(0.8, 0.2), r]),
        }],
    );
}

/// ```text
///      ____________
///     /   _____    \      the outer lens is cut away,
///    |   (island)   |     the inner lens stays
///     \____________/
/// ```
#[testkit::test]
fn nested_regions_keep_the_inner_island() {
    let (l, r) = (Vec2::new(0.35, 0.5), Vec2::new(0.65, 0.5));
    check(
        "trim_nested",
        vec![TrimShape::Nested {
            outer: [
                quadratic((0.1, 0.5), (0.5, 1.0), (0.9, 0.5)),
                quadratic((0.1, 0.5), (0.5, 0.0), (0.9, 0.5)),
            ],
            inner: [
                TrimCurve::Cubic([l, Vec2::new(0.4, 0.68), Vec2::new(0.6, 0.68), r]),
                TrimCurve::Cubic([l, Vec2::new(0.4, 0.32), Vec2::new(0.6, 0.32), r]),
            ],
        }],
    );
}

#[testkit::test]
fn one_newton_step_or_a_coarse_epsilon_trims_less() {
    let piece = wgsl::TRIMMING.written();
    let Some(gpu) = common::gpu() else { return };
    let trimmed_pixels = |iterations, epsilon| {
        let trimming = Trimming {
            shapes: vec![quadratic_lens()],
            iterations,
            epsilon,
        };
        trim_render(&gpu, piece, &trimming)
            .pixels_not(Rgba::WHITE)
            .len()
    };
    let converged = trimmed_pixels(10, 0.001);
    let exact = cpu_render(&[quadratic_lens()])
        .pixels_not(Rgba::WHITE)
        .len();
    assert!(
        converged.abs_diff(exact) * 100 <= exact,
        "10 iterations trim {converged} pixels, the region has {exact}"
    );
    // One step from t = 0 or 1 leaves most roots unconverged (residual above
    // the root tolerance): less is trimmed.
    for (iterations, epsilon) in [(1, 0.001), (10, 10.0)] {
        let n = trimmed_pixels(iterations, epsilon);
        assert!(
            n * 10 < converged * 9,
            "{iterations} iterations with epsilon {epsilon} trim {n} pixels, converged {converged}"
        );
    }
}
