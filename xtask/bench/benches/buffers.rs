//! The reference buffers: fragments per second through the depth and the
//! stencil stage, against plain unconditional writes, and jittered
//! accumulation in frames per second.
//!
//! The fragments come from the given rasterizer and are collected before
//! timing, so only the per-fragment stage is measured; every iteration
//! starts from a freshly cleared canvas (the clone is not timed).

use std::hint::black_box;

use buffers::accumulation::{JITTER_8, jittered_antialias};
use buffers::raster::fill_triangle;
use buffers::stencil::{StencilOp, StencilState, stencil_fragment};
use buffers::zbuffer::{DepthState, depth_test};
use canvas::{Canvas, Fragment, Rgba, Vec2, Vertex};
use criterion::{BatchSize, Criterion, Throughput, criterion_group, criterion_main};

const SIDE: u32 = 512;
const TRIANGLES: usize = 2000;

/// A fixed set of triangles with edges of up to 64 pixels, random depths
/// and colours (a linear congruential generator keeps it the same).
fn triangle_set(side: u32, count: usize) -> Vec<[Vertex; 3]> {
    let mut state: u64 = 0x2545_F491_4F6C_DD1D;
    let mut next = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 40) as f32 / (1u64 << 24) as f32
    };
    (0..count)
        .map(|_| {
            let centre = Vec2::new(next(), next()) * side as f32;
            let colour = Rgba::rgb(next(), next(), next());
            [0, 1, 2].map(|_| {
                let corner = centre + (Vec2::new(next(), next()) - 0.5) * 64.0;
                Vertex::new(corner, next(), colour)
            })
        })
        .collect()
}

fn fragments(triangles: &[[Vertex; 3]], canvas: &Canvas) -> Vec<Fragment> {
    let mut out = Vec::new();
    for &t in triangles {
        fill_triangle(t, canvas.viewport(), |f| out.push(f));
    }
    out
}

fn per_fragment(c: &mut Criterion) {
    let cleared = Canvas::new(SIDE, SIDE);
    let fragments = fragments(&triangle_set(SIDE, TRIANGLES), &cleared);
    let mut group = c.benchmark_group("fragments, 512²");
    group.throughput(Throughput::Elements(fragments.len() as u64));
    group.bench_function("canvas plot (no test)", |b| {
        b.iter_batched_ref(
            || cleared.clone(),
            |canvas| {
                for &f in &fragments {
                    canvas.plot(f);
                }
                black_box(canvas);
            },
            BatchSize::LargeInput,
        );
    });
    group.bench_function("reference depth_test (LESS)", |b| {
        b.iter_batched_ref(
            || cleared.clone(),
            |canvas| {
                for &f in &fragments {
                    depth_test(canvas, f, &DepthState::DEFAULT);
                }
                black_box(canvas);
            },
            BatchSize::LargeInput,
        );
    });
    let count = StencilState {
        depth_pass: StencilOp::Incr,
        ..StencilState::DEFAULT
    };
    group.bench_function("reference stencil_fragment (INCR, depth LESS)", |b| {
        b.iter_batched_ref(
            || cleared.clone(),
            |canvas| {
                for &f in &fragments {
                    stencil_fragment(canvas, f, &count, true);
                }
                black_box(canvas);
            },
            BatchSize::LargeInput,
        );
    });
    group.finish();
}

fn accumulation(c: &mut Criterion) {
    let triangles = triangle_set(256, 200);
    let mut group = c.benchmark_group("jittered accumulation, 256², 200 triangles");
    group.throughput(Throughput::Elements(1));
    group.sample_size(20);
    group.bench_function("reference jittered_antialias (8 samples)", |b| {
        b.iter(|| {
            let out = jittered_antialias(256, 256, &JITTER_8, |canvas, j| {
                let viewport = canvas.viewport();
                for t in &triangles {
                    let moved = t.map(|v| Vertex {
                        position: v.position - j,
                        ..v
                    });
                    fill_triangle(moved, viewport, |f| canvas.set(f.pixel, f.colour));
                }
            });
            black_box(out)
        });
    });
    group.finish();
}

criterion_group!(benches, per_fragment, accumulation);
criterion_main!(benches);
