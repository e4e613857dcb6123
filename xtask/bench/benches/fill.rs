//! The reference polygon fills against imageproc and tiny-skia, on a 1024²
//! canvas, in one run.
//!
//! Two sets of triangles: large ones (vertices anywhere on the canvas,
//! throughput in filled pixels: what the reference scanline fill plots,
//! credited to every contender) and small ones (vertices within 16 pixels
//! of each other, throughput in triangles: set-up cost dominates).
//! Contenders: the reference scanline fill with its active edge table
//! (writing spans, and pixel by pixel through `fill_polygon`), the same
//! spans found beforehand and only written (the writes' own cost), the
//! reference edge-function rasterizer (which also interpolates depth
//! and colour per pixel), the same in lanes over the bounding box (task
//! 03/7, seed 004's vectorised bonus: eight pixels of a row at once, depth
//! and colour mixed in every lane), the reference blocked rasterizer (task 03/6: 8 × 8
//! blocks, trivially accepted and rejected, eight lanes per row; coverage
//! only), euc (a software renderer: a pipeline whose vertex stage passes
//! clip positions through and whose fragment stage writes the
//! interpolated colour, no depth test), imageproc's `draw_polygon_mut`,
//! and tiny-skia's `fill_path` without antialiasing. tiny-skia samples
//! pixel centres at +0.5, so its paths are shifted by half a pixel to
//! cover the same pixels.

use std::hint::black_box;
use std::ops::ControlFlow;

use canvas::{Canvas, Rgba, Vec2, Vertex};
use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, Criterion, Throughput, criterion_group, criterion_main};
use euc::buffer::Buffer2d;
use euc::rasterizer::{BackfaceCullingDisabled, Triangles};
use euc::{DepthStrategy, Pipeline};
use fill::blocked::fill_triangle_blocked;
use fill::edge_function::fill_triangle;
use fill::scanline::{fill_polygon, fill_spans};
use fill::vectorised::fill_triangle_vectorised;
use image::RgbaImage;
use imageproc::drawing::draw_polygon_mut;
use imageproc::point::Point;
use tiny_skia::{FillRule, Paint, Path, PathBuilder, Pixmap, Transform};

const SIDE: u32 = 1024;

/// A fixed set of triangles with integer vertices: `count` triangles,
/// each with a first vertex anywhere on the canvas and the other two
/// within `spread` of it (clamped to the canvas). A linear congruential
/// generator keeps the set the same in every run; degenerate triangles
/// are skipped (imageproc rejects some of them).
fn triangle_set(count: usize, spread: i32) -> Vec<[Vec2; 3]> {
    let mut state: u64 = 0xD1B5_4A32_D192_ED03;
    let mut next = |below: i32| {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((state >> 33) % below as u64) as i32
    };
    let side = SIDE as i32;
    let mut triangles = Vec::with_capacity(count);
    while triangles.len() < count {
        let (x, y) = (next(side), next(side));
        let mut near = || {
            let dx = next(2 * spread + 1) - spread;
            let dy = next(2 * spread + 1) - spread;
            Vec2::new(
                (x + dx).clamp(0, side - 1) as f32,
                (y + dy).clamp(0, side - 1) as f32,
            )
        };
        let tri = [Vec2::new(x as f32, y as f32), near(), near()];
        let area = (tri[1] - tri[0]).perp_dot(tri[2] - tri[0]);
        if area != 0.0 {
            triangles.push(tri);
        }
    }
    triangles
}

fn filled_pixels(triangles: &[[Vec2; 3]], viewport: canvas::Viewport) -> u64 {
    let mut count = 0;
    for tri in triangles {
        fill_polygon(tri, viewport, |_| count += 1);
    }
    count
}

fn skia_path(tri: &[Vec2; 3]) -> Path {
    let mut builder = PathBuilder::new();
    builder.move_to(tri[0].x + 0.5, tri[0].y + 0.5);
    builder.line_to(tri[1].x + 0.5, tri[1].y + 0.5);
    builder.line_to(tri[2].x + 0.5, tri[2].y + 0.5);
    builder.close();
    builder
        .finish()
        .expect("a non-degenerate triangle makes a path")
}

/// euc's pipeline for the benchmark: positions in clip space as given, the
/// vertex colour interpolated, no depth test.
struct Gouraud;

impl Pipeline for Gouraud {
    type Vertex = ([f32; 4], [f32; 3]);
    type VsOut = (f32, f32, f32);
    type Pixel = u32;

    fn vert(&self, (position, [r, g, b]): &Self::Vertex) -> ([f32; 4], Self::VsOut) {
        (*position, (*r, *g, *b))
    }

    fn frag(&self, &(r, g, b): &Self::VsOut) -> Self::Pixel {
        let byte = |c: f32| (c.clamp(0.0, 1.0) * 255.0) as u32;
        (byte(r) << 16) | (byte(g) << 8) | byte(b) | 0xFF00_0000
    }

    fn get_depth_strategy(&self) -> DepthStrategy {
        DepthStrategy::None
    }
}

/// A pixel position as euc's clip space (y down in euc's screen).
fn euc_position(v: Vec2) -> [f32; 4] {
    let side = SIDE as f32;
    [
        2.0 * (v.x + 0.5) / side - 1.0,
        1.0 - 2.0 * (v.y + 0.5) / side,
        0.5,
        1.0,
    ]
}

/// Runs all contenders on one triangle set.
fn contenders(group: &mut BenchmarkGroup<'_, WallTime>, triangles: &[[Vec2; 3]]) {
    let mut canvas = Canvas::new(SIDE, SIDE);
    let viewport = canvas.viewport();
    group.bench_function(
        "reference fill_spans (scanline, AET) + Canvas::fill_span",
        |b| {
            b.iter(|| {
                for tri in triangles {
                    fill_spans(
                        tri,
                        viewport,
                        |span| canvas.fill_span(span, Rgba::WHITE),
                        |_, _| ControlFlow::Continue(()),
                    );
                }
                black_box(&canvas);
            });
        },
    );
    // The writes alone: the same spans, found beforehand, filled into the
    // canvas. What the fill's own work costs is the difference.
    let mut spans = Vec::new();
    for tri in triangles {
        fill_spans(
            tri,
            viewport,
            |span| spans.push(span),
            |_, _| ControlFlow::Continue(()),
        );
    }
    group.bench_function(
        "Canvas::fill_span of the same spans, found beforehand (the writes alone)",
        |b| {
            b.iter(|| {
                for &span in &spans {
                    canvas.fill_span(span, Rgba::WHITE);
                }
                black_box(&canvas);
            });
        },
    );
    group.bench_function(
        "reference fill_polygon (scanline, AET, pixel by pixel)",
        |b| {
            b.iter(|| {
                for tri in triangles {
                    fill_polygon(tri, viewport, |p| canvas.set(p, Rgba::WHITE));
                }
                black_box(&canvas);
            });
        },
    );
    let vertices: Vec<[Vertex; 3]> = triangles
        .iter()
        .map(|tri| {
            [
                Vertex::new(tri[0], 0.2, Rgba::RED),
                Vertex::new(tri[1], 0.5, Rgba::GREEN),
                Vertex::new(tri[2], 0.8, Rgba::BLUE),
            ]
        })
        .collect();
    group.bench_function(
        "reference fill_triangle (edge functions, depth + colour)",
        |b| {
            b.iter(|| {
                for tri in &vertices {
                    fill_triangle(*tri, viewport, |f, _| canvas.plot(f));
                }
                black_box(&canvas);
            });
        },
    );
    group.bench_function(
        "reference fill_triangle_vectorised (lanes over the box, depth + colour)",
        |b| {
            b.iter(|| {
                for tri in &vertices {
                    fill_triangle_vectorised(*tri, viewport, |_| {}, |f, _| canvas.plot(f));
                }
                black_box(&canvas);
            });
        },
    );
    group.bench_function(
        "reference fill_triangle_blocked (8 × 8 blocks, lanes; coverage only)",
        |b| {
            b.iter(|| {
                for tri in triangles {
                    fill_triangle_blocked(*tri, viewport, |p| canvas.set(p, Rgba::WHITE), |_| {});
                }
                black_box(&canvas);
            });
        },
    );
    let euc_vertices: Vec<([f32; 4], [f32; 3])> = triangles
        .iter()
        .flat_map(|tri| {
            [
                (euc_position(tri[0]), [1.0, 0.0, 0.0]),
                (euc_position(tri[1]), [0.0, 1.0, 0.0]),
                (euc_position(tri[2]), [0.0, 0.0, 1.0]),
            ]
        })
        .collect();
    let mut colour = Buffer2d::new([SIDE as usize, SIDE as usize], 0_u32);
    group.bench_function("euc Triangles (colour interpolated, no depth test)", |b| {
        b.iter(|| {
            Gouraud.draw::<Triangles<'_, Buffer2d<f32>, BackfaceCullingDisabled>, _>(
                &euc_vertices,
                &mut colour,
                None,
            );
            black_box(&colour);
        });
    });
    let polygons: Vec<[Point<i32>; 3]> = triangles
        .iter()
        .map(|tri| tri.map(|v| Point::new(v.x as i32, v.y as i32)))
        .collect();
    let mut image = RgbaImage::new(SIDE, SIDE);
    group.bench_function("imageproc draw_polygon_mut", |b| {
        b.iter(|| {
            for poly in &polygons {
                draw_polygon_mut(&mut image, poly, image::Rgba([255, 255, 255, 255]));
            }
            black_box(&image);
        });
    });
    let paths: Vec<Path> = triangles.iter().map(skia_path).collect();
    let mut pixmap = Pixmap::new(SIDE, SIDE).expect("a 1024² pixmap");
    let mut paint = Paint::default();
    paint.set_color_rgba8(255, 255, 255, 255);
    paint.anti_alias = false;
    group.bench_function("tiny-skia fill_path (no antialiasing)", |b| {
        b.iter(|| {
            for path in &paths {
                pixmap.fill_path(path, &paint, FillRule::EvenOdd, Transform::identity(), None);
            }
            black_box(&pixmap);
        });
    });
}

fn large_triangles(c: &mut Criterion) {
    let triangles = triangle_set(50, SIDE as i32);
    let mut group = c.benchmark_group("large triangles, 1024²");
    group.throughput(Throughput::Elements(filled_pixels(
        &triangles,
        Canvas::new(SIDE, SIDE).viewport(),
    )));
    contenders(&mut group, &triangles);
    group.finish();
}

fn small_triangles(c: &mut Criterion) {
    let triangles = triangle_set(10_000, 8);
    let mut group = c.benchmark_group("small triangles, 1024²");
    group.throughput(Throughput::Elements(triangles.len() as u64));
    contenders(&mut group, &triangles);
    group.finish();
}

criterion_group!(benches, large_triangles, small_triangles);
criterion_main!(benches);
