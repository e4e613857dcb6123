//! The reference Bézier topic: surface evaluation by de Casteljau (u then
//! v) against the Bernstein double sum, and trimming by the seed's Newton
//! method against ray-crossing parity, on the same cubic region.
//!
//! Throughput is in points: one surface point, or one (u, v) sample
//! classified, counts 1.

use std::hint::black_box;

use bezier::newton_trim::NewtonTrim;
use bezier::ray_parity::{TrimLoop, TrimRegion};
use bezier::surface::evaluate_u_then_v;
use bezier::{BezierPatch, Trim};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::{DVec2, DVec3};

/// Samples per side of the parameter grid.
const SIDE: usize = 256;

fn grid() -> Vec<DVec2> {
    (0..SIDE * SIDE)
        .map(|k| DVec2::new((k % SIDE) as f64, (k / SIDE) as f64) / (SIDE - 1) as f64)
        .collect()
}

/// The Bernstein double sum for a 4 × 4 net, written out (the baseline).
fn bicubic_bernstein(net: &BezierPatch, uv: DVec2) -> DVec3 {
    let basis = |t: f64| {
        let s = 1.0 - t;
        [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t]
    };
    let (bu, bv) = (basis(uv.x), basis(uv.y));
    let mut sum = DVec3::ZERO;
    for (i, wu) in bu.iter().enumerate() {
        for (j, wv) in bv.iter().enumerate() {
            sum += net.control_point(i, j) * (wu * wv);
        }
    }
    sum
}

fn surface(c: &mut Criterion) {
    let net = BezierPatch::seed_hill();
    let points = grid();
    let mut group = c.benchmark_group("bicubic surface");
    group.throughput(Throughput::Elements(points.len() as u64));
    group.bench_function("reference evaluate_u_then_v (de Casteljau)", |b| {
        b.iter(|| {
            for &uv in &points {
                black_box(evaluate_u_then_v(&net, black_box(uv)).unwrap());
            }
        });
    });
    group.bench_function("Bernstein double sum, unrolled (baseline)", |b| {
        b.iter(|| {
            for &uv in &points {
                black_box(bicubic_bernstein(&net, black_box(uv)));
            }
        });
    });
    group.finish();
}

fn trimming(c: &mut Criterion) {
    let p = freeform::trim::CUBIC_REGION;
    let newton = NewtonTrim::cubic(p).unwrap();
    let upper = vec![p[0], p[1], p[2], p[3]];
    let lower_back = vec![p[3], p[5], p[4], p[0]];
    let parity = TrimRegion::new(vec![TrimLoop::new(vec![upper, lower_back]).unwrap()]);
    let points = grid();
    let mut group = c.benchmark_group("cubic trim");
    group.throughput(Throughput::Elements(points.len() as u64));
    group.bench_function(
        "reference NewtonTrim (seed, 10 iterations, ε = 0.001)",
        |b| {
            b.iter(|| {
                points
                    .iter()
                    .filter(|&&uv| newton.trims(black_box(uv)))
                    .count()
            });
        },
    );
    group.bench_function("reference TrimRegion (ray parity, subdivision)", |b| {
        b.iter(|| {
            points
                .iter()
                .filter(|&&uv| parity.contains(black_box(uv)))
                .count()
        });
    });
    group.finish();
}

criterion_group!(benches, surface, trimming);
criterion_main!(benches);
