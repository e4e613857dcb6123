//! The reference lines against imageproc, on a 1024² canvas, in one run:
//! the midpoint line, task 1's DDA and the bonus's DDA in lanes (both with
//! colour and depth), imageproc's line; Wu against imageproc's antialiased
//! line.
//!
//! Throughput is in pixels: every line of the set counts
//! `max(|Δx|, |Δy|) + 1` pixels for both contenders.

use std::hint::black_box;

use canvas::{Canvas, Pixel, Rgba, Vertex};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use image::RgbaImage;
use imageproc::drawing::{draw_antialiased_line_segment_mut, draw_line_segment_mut};
use imageproc::pixelops::interpolate;
use lines::dda::dda_line;
use lines::vectorised_dda::vectorised_dda_line;
use lines::{midpoint::midpoint_line, wu::wu_line};

const SIDE: u32 = 1024;
const LINES: usize = 1000;

/// A fixed set of lines in all octants with endpoints on the canvas
/// (a linear congruential generator keeps the set the same in every run).
fn line_set() -> Vec<[Pixel; 2]> {
    let mut state: u64 = 0x2545_F491_4F6C_DD1D;
    let mut next = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((state >> 33) % u64::from(SIDE)) as i32
    };
    (0..LINES)
        .map(|_| [Pixel::new(next(), next()), Pixel::new(next(), next())])
        .collect()
}

fn pixel_count(lines: &[[Pixel; 2]]) -> u64 {
    lines
        .iter()
        .map(|[a, b]| u64::from((a.x - b.x).unsigned_abs().max((a.y - b.y).unsigned_abs())) + 1)
        .sum()
}

fn aliased(c: &mut Criterion) {
    let lines = line_set();
    let mut group = c.benchmark_group("aliased lines, 1024²");
    group.throughput(Throughput::Elements(pixel_count(&lines)));
    let mut canvas = Canvas::new(SIDE, SIDE);
    group.bench_function("reference midpoint_line", |b| {
        b.iter(|| {
            for &[from, to] in &lines {
                midpoint_line(from, to, |p| canvas.set(p, Rgba::WHITE));
            }
            black_box(&canvas);
        });
    });
    // The DDAs interpolate colour and depth as well (white to white here).
    let vertices: Vec<[Vertex; 2]> = lines
        .iter()
        .map(|&[a, b]| [a, b].map(|p| Vertex::new(p.centre(), 0.5, Rgba::WHITE)))
        .collect();
    group.bench_function("reference dda_line (running sum)", |b| {
        b.iter(|| {
            for [from, to] in &vertices {
                dda_line(from, to, |f| canvas.plot(f));
            }
            black_box(&canvas);
        });
    });
    group.bench_function("reference vectorised_dda_line (lanes of 8)", |b| {
        b.iter(|| {
            for [from, to] in &vertices {
                vectorised_dda_line(from, to, |_| {}, |f| canvas.plot(f));
            }
            black_box(&canvas);
        });
    });
    let mut image = RgbaImage::new(SIDE, SIDE);
    group.bench_function("imageproc draw_line_segment_mut", |b| {
        b.iter(|| {
            for &[from, to] in &lines {
                draw_line_segment_mut(
                    &mut image,
                    (from.x as f32, from.y as f32),
                    (to.x as f32, to.y as f32),
                    image::Rgba([255, 255, 255, 255]),
                );
            }
            black_box(&image);
        });
    });
    group.finish();
}

/// The rasterizers alone: every fragment goes into a checksum instead of
/// the canvas, so that what is measured is finding the pixels (and, for
/// the DDAs, mixing colour and depth), not writing them.
fn pixels_only(c: &mut Criterion) {
    let lines = line_set();
    let mut group = c.benchmark_group("aliased lines, pixels only");
    group.throughput(Throughput::Elements(pixel_count(&lines)));
    let vertices: Vec<[Vertex; 2]> = lines
        .iter()
        .map(|&[a, b]| [a, b].map(|p| Vertex::new(p.centre(), 0.5, Rgba::WHITE)))
        .collect();
    let sum = |sum: &mut u64, p: Pixel| {
        *sum = sum
            .wrapping_mul(31)
            .wrapping_add((p.x ^ (p.y << 11)) as u64);
    };
    group.bench_function("reference midpoint_line", |b| {
        b.iter(|| {
            let mut checksum = 0_u64;
            for &[from, to] in &lines {
                midpoint_line(from, to, |p| sum(&mut checksum, p));
            }
            black_box(checksum)
        });
    });
    group.bench_function("reference dda_line (running sum)", |b| {
        b.iter(|| {
            let mut checksum = 0_u64;
            for [from, to] in &vertices {
                dda_line(from, to, |f| sum(&mut checksum, f.pixel));
            }
            black_box(checksum)
        });
    });
    group.bench_function("reference vectorised_dda_line (lanes of 8)", |b| {
        b.iter(|| {
            let mut checksum = 0_u64;
            for [from, to] in &vertices {
                vectorised_dda_line(from, to, |_| {}, |f| sum(&mut checksum, f.pixel));
            }
            black_box(checksum)
        });
    });
    group.finish();
}

fn antialiased(c: &mut Criterion) {
    let lines = line_set();
    let mut group = c.benchmark_group("antialiased lines, 1024²");
    group.throughput(Throughput::Elements(pixel_count(&lines)));
    let mut canvas = Canvas::new(SIDE, SIDE);
    group.bench_function("reference wu_line", |b| {
        b.iter(|| {
            for &[from, to] in &lines {
                wu_line(from, to, |p, w| canvas.blend(p, Rgba::WHITE, w));
            }
            black_box(&canvas);
        });
    });
    let mut image = RgbaImage::new(SIDE, SIDE);
    group.bench_function("imageproc draw_antialiased_line_segment_mut", |b| {
        b.iter(|| {
            for &[from, to] in &lines {
                draw_antialiased_line_segment_mut(
                    &mut image,
                    (from.x, from.y),
                    (to.x, to.y),
                    image::Rgba([255, 255, 255, 255]),
                    interpolate,
                );
            }
            black_box(&image);
        });
    });
    group.finish();
}

criterion_group!(benches, aliased, pixels_only, antialiased);
criterion_main!(benches);
