//! The reference clippers: Sutherland-Hodgman on the faces of
//! `clipped_torus.ply` in clip space, and Cohen-Sutherland against
//! Liang-Barsky on one fixed set of segments.
//!
//! Throughput counts input polygons (faces) and input segments.

use std::hint::black_box;

use canvas::{Vec2, Viewport};
use clipping::cohen_sutherland::cohen_sutherland;
use clipping::liang_barsky::liang_barsky;
use clipping::sutherland_hodgman::clip_polygon;
use clipping::{ClipPlane, ClipWindow, Segment};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};

const SEGMENTS: usize = 1000;

/// The six planes of the clip volume, written out in testkit.
const PLANES: [ClipPlane; 6] = {
    let p = testkit::definitions::CLIP_VOLUME_PLANES;
    [
        ClipPlane::new(p[0]),
        ClipPlane::new(p[1]),
        ClipPlane::new(p[2]),
        ClipPlane::new(p[3]),
        ClipPlane::new(p[4]),
        ClipPlane::new(p[5]),
    ]
};

fn polygons(c: &mut Criterion) {
    let mesh = scene::ply::load(scene::data::path("clipped_torus.ply")).expect("shipped mesh");
    let faces = scene::Pipeline::for_mesh(&mesh, 1024, 1024).clip_space(&mesh);
    let mut group = c.benchmark_group("Sutherland-Hodgman, clipped_torus faces");
    group.throughput(Throughput::Elements(faces.len() as u64));
    group.bench_function("reference clip_polygon", |b| {
        b.iter(|| {
            for face in &faces {
                black_box(clip_polygon(black_box(face), &PLANES).ok());
            }
        });
    });
    group.finish();
}

/// Segments with endpoints in `[−512, 1536)²` around a 1024² viewport: some
/// inside, some crossing, some missing it (a linear congruential generator
/// keeps the set the same in every run).
fn segment_set() -> Vec<Segment> {
    let mut state: u64 = 0x2545_F491_4F6C_DD1D;
    let mut next = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((state >> 33) % 2048) as f32 - 512.0 + 0.25
    };
    (0..SEGMENTS)
        .map(|_| Segment::new(Vec2::new(next(), next()), Vec2::new(next(), next())))
        .collect()
}

fn segments(c: &mut Criterion) {
    let set = segment_set();
    let window = ClipWindow::from_viewport(Viewport::new(0, 0, 1023, 1023)).expect("non-empty");
    let mut group = c.benchmark_group("line clipping, 1000 segments around 1024²");
    group.throughput(Throughput::Elements(set.len() as u64));
    group.bench_function("reference cohen_sutherland", |b| {
        b.iter(|| {
            for &s in &set {
                black_box(cohen_sutherland(black_box(s), window).ok());
            }
        });
    });
    group.bench_function("reference liang_barsky", |b| {
        b.iter(|| {
            for &s in &set {
                black_box(liang_barsky(black_box(s), window).ok());
            }
        });
    });
    group.finish();
}

criterion_group!(benches, polygons, segments);
criterion_main!(benches);
