//! The reference NURBS surface evaluation against curvo, in one run: a
//! bicubic rational surface (8 × 8 control points, non-uniform clamped
//! knots, weights in `[0.5, 2]`) sampled on a 256 × 256 grid.
//!
//! - `reference sample_grid`: `NurbsSurface::sample_grid`, spans and bases
//!   cached per row and column, the `u` sums done once per row, then
//!   `q + 1` homogeneous products per point;
//! - `curvo regular_sample_points`: curvo's grid sampling (bases cached per
//!   row and column, `(p + 1)(q + 1)` products per point);
//! - `reference point` and `curvo point_at`: one independent evaluation per
//!   grid point (span search and basis every time), for scale.
//!
//! Both libraries get the same knots, weights and control points; the
//! set-up asserts that their grids agree within 1e-9.
//!
//! Throughput is in evaluated points (65 536 per iteration).

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use curvo::prelude::NurbsSurface3D;
use glam::{DVec3, DVec4};
use nalgebra::Point4;
use nurbs::{ControlNet, KnotVector, NurbsSurface, homogeneous};

/// Samples along each side of the grid.
const SIDE: usize = 256;
/// Control points along each side of the net.
const NET: usize = 8;
/// Bicubic.
const DEGREE: usize = 3;
/// The largest distance allowed between the two libraries' grid points.
const AGREEMENT: f64 = 1e-9;

/// Clamped cubic knots with uneven interior spacing (8 control points:
/// 4 interior knots).
fn knots() -> Vec<f64> {
    vec![0.0, 0.0, 0.0, 0.0, 0.15, 0.4, 0.55, 0.8, 1.0, 1.0, 1.0, 1.0]
}

/// A wavy sheet with weights varying over the net, as homogeneous points
/// `(w·x, w·y, w·z, w)`, row `i` along `u`.
fn net() -> Vec<Vec<DVec4>> {
    (0..NET)
        .map(|i| {
            (0..NET)
                .map(|j| {
                    let (x, y) = (i as f64, j as f64);
                    let z = (0.9 * x).sin() * (0.7 * y).cos() * 2.0;
                    let w = 1.25 + 0.75 * ((i * 3 + j * 5) % 7) as f64 / 6.0 - 0.5;
                    homogeneous(DVec3::new(x, y, z), w)
                })
                .collect()
        })
        .collect()
}

fn reference_surface() -> NurbsSurface {
    let knots = KnotVector::try_new(DEGREE, knots()).expect("valid knots");
    let points = net().into_iter().flatten().collect();
    let net = ControlNet::try_new(NET, NET, points).expect("valid net");
    NurbsSurface::try_new(knots.clone(), knots, net).expect("valid surface")
}

fn curvo_surface() -> NurbsSurface3D<f64> {
    let points = net()
        .into_iter()
        .map(|row| {
            row.into_iter()
                .map(|p| Point4::new(p.x, p.y, p.z, p.w))
                .collect()
        })
        .collect();
    NurbsSurface3D::new(DEGREE, DEGREE, knots(), knots(), points)
}

/// Asserts that both libraries sample the same surface.
fn check_agreement(reference: &NurbsSurface, curvo: &NurbsSurface3D<f64>) {
    let ours = reference.sample_grid(SIDE, SIDE).expect("grid");
    let theirs = curvo.regular_sample_points(SIDE - 1, SIDE - 1);
    assert_eq!(theirs.len(), SIDE);
    let mut worst: f64 = 0.0;
    for (i, row) in theirs.iter().enumerate() {
        assert_eq!(row.len(), SIDE);
        for (j, p) in row.iter().enumerate() {
            let d = ours[i * SIDE + j].distance(DVec3::new(p.x, p.y, p.z));
            worst = worst.max(d);
        }
    }
    assert!(
        worst <= AGREEMENT,
        "the libraries disagree by {worst:e} > {AGREEMENT:e}"
    );
}

fn grid(c: &mut Criterion) {
    let reference = reference_surface();
    let curvo = curvo_surface();
    check_agreement(&reference, &curvo);

    let mut group = c.benchmark_group("bicubic NURBS surface, 256² grid");
    group.throughput(Throughput::Elements((SIDE * SIDE) as u64));
    group.bench_function("reference sample_grid", |b| {
        b.iter(|| black_box(reference.sample_grid(SIDE, SIDE).expect("grid")));
    });
    group.bench_function("curvo regular_sample_points", |b| {
        b.iter(|| black_box(curvo.regular_sample_points(SIDE - 1, SIDE - 1)));
    });
    let step = 1.0 / (SIDE - 1) as f64;
    group.bench_function("reference point, one by one", |b| {
        b.iter(|| {
            let mut sum = DVec3::ZERO;
            for i in 0..SIDE {
                for j in 0..SIDE {
                    sum += reference
                        .point(i as f64 * step, j as f64 * step)
                        .expect("in the domain");
                }
            }
            black_box(sum)
        });
    });
    group.bench_function("curvo point_at, one by one", |b| {
        b.iter(|| {
            let mut sum = 0.0;
            for i in 0..SIDE {
                for j in 0..SIDE {
                    sum += curvo.point_at(i as f64 * step, j as f64 * step).z;
                }
            }
            black_box(sum)
        });
    });
    group.finish();
}

criterion_group!(benches, grid);
criterion_main!(benches);
