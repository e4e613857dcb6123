//! The reference lines against imageproc, on a 1024² canvas, in one run:
//! the midpoint line, task 1's DDA and the bonus's DDA in lanes (both with
//! colour and depth), imageproc's line, and the same pixels written without
//! finding them (the floor any line pays here); the midpoint line and
//! imageproc's on flat and steep lines apart; Wu against imageproc's
//! antialiased line.
//!
//! Throughput is in pixels: every line of the set counts
//! `max(|Δx|, |Δy|) + 1` pixels for both contenders.

use std::hint::black_box;

use canvas::{Canvas, Pixel, Rgba, Vertex};
use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, Criterion, Throughput, criterion_group, criterion_main};
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
    midpoint_lines(&mut group, &mut canvas, &lines);
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
    imageproc_lines(&mut group, &lines);
    // What any rasterizer writing these pixels pays: the same pixels,
    // found beforehand, written in the same order.
    let pixels = midpoint_pixels(&lines);
    canvas_writes(&mut group, &mut canvas, &pixels);
    plain_stores(&mut group, &pixels);
    group.finish();
}

/// The line set split by orientation: flat lines step along rows (a
/// pixel's neighbour is the next 4 bytes), steep lines along columns (a
/// row, 4 KiB, from the last), so the two meet the memory differently.
fn orientations(c: &mut Criterion) {
    let (flat, steep): (Vec<_>, Vec<_>) = line_set()
        .into_iter()
        .partition(|[a, b]| (a.x - b.x).abs() >= (a.y - b.y).abs());
    for (name, lines) in [("flat, |Δx| ≥ |Δy|", flat), ("steep, |Δx| < |Δy|", steep)] {
        let mut group = c.benchmark_group(format!("aliased lines, 1024², {name}"));
        group.throughput(Throughput::Elements(pixel_count(&lines)));
        let mut canvas = Canvas::new(SIDE, SIDE);
        midpoint_lines(&mut group, &mut canvas, &lines);
        imageproc_lines(&mut group, &lines);
        let pixels = midpoint_pixels(&lines);
        canvas_writes(&mut group, &mut canvas, &pixels);
        plain_stores(&mut group, &pixels);
        group.finish();
    }
}

fn midpoint_lines(
    group: &mut BenchmarkGroup<'_, WallTime>,
    canvas: &mut Canvas,
    lines: &[[Pixel; 2]],
) {
    group.bench_function("reference midpoint_line", |b| {
        b.iter(|| {
            for &[from, to] in lines {
                midpoint_line(from, to, |p| canvas.set(p, Rgba::WHITE));
            }
            black_box(&*canvas);
        });
    });
}

fn imageproc_lines(group: &mut BenchmarkGroup<'_, WallTime>, lines: &[[Pixel; 2]]) {
    let mut image = RgbaImage::new(SIDE, SIDE);
    group.bench_function("imageproc draw_line_segment_mut", |b| {
        b.iter(|| {
            for &[from, to] in lines {
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
}

/// Every pixel of the set, in the order the midpoint line plots them.
fn midpoint_pixels(lines: &[[Pixel; 2]]) -> Vec<Pixel> {
    let mut pixels = Vec::new();
    for &[from, to] in lines {
        midpoint_line(from, to, |p| pixels.push(p));
    }
    pixels
}

/// The canvas's part: the pixels written with [`Canvas::set`], found
/// beforehand.
fn canvas_writes(group: &mut BenchmarkGroup<'_, WallTime>, canvas: &mut Canvas, pixels: &[Pixel]) {
    group.bench_function(
        "Canvas::set of the same pixels, found beforehand (the writes alone)",
        |b| {
            b.iter(|| {
                for &p in pixels {
                    canvas.set(p, Rgba::WHITE);
                }
                black_box(&*canvas);
            });
        },
    );
}

/// The floor of the benchmark: the pixels' stores and nothing else (a
/// plain image of the canvas's size, the indices worked out beforehand).
fn plain_stores(group: &mut BenchmarkGroup<'_, WallTime>, pixels: &[Pixel]) {
    let indices: Vec<usize> = pixels
        .iter()
        .map(|p| p.y as usize * SIDE as usize + p.x as usize)
        .collect();
    let mut image = vec![[0_u8; 4]; SIDE as usize * SIDE as usize];
    group.bench_function(
        "plain stores of the same pixels, indices found beforehand (the floor)",
        |b| {
            b.iter(|| {
                for &i in &indices {
                    image[i] = [255; 4];
                }
                black_box(&image);
            });
        },
    );
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

criterion_group!(benches, aliased, orientations, pixels_only, antialiased);
criterion_main!(benches);
