//! The reference circles against imageproc, on a 1024² canvas, in one run.
//!
//! Throughput is in pixels: the set's pixel count is what the reference
//! `midpoint_circle` plots (every pixel once), and both contenders are
//! credited with it. imageproc's `draw_hollow_circle_mut` is the integer
//! midpoint circle too; it plots the eight mirror images without skipping
//! coincident ones, so it writes a few pixels more for the same circle.

use std::hint::black_box;

use canvas::{Canvas, Pixel, Rgba};
use circles::{integer_circle::integer_circle, midpoint_circle::midpoint_circle};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use image::RgbaImage;
use imageproc::drawing::draw_hollow_circle_mut;

const SIDE: u32 = 1024;
const CIRCLES: usize = 500;

/// A circle of the set.
#[derive(Clone, Copy)]
struct Circle {
    centre: Pixel,
    radius: i32,
}

/// A fixed set of circles with centres on the canvas and radii 1..=400
/// (a linear congruential generator keeps it the same in every run); many
/// reach past the border, where both contenders drop the pixels.
fn circle_set() -> Vec<Circle> {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = |below: u64| {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((state >> 33) % below) as i32
    };
    (0..CIRCLES)
        .map(|_| Circle {
            centre: Pixel::new(next(u64::from(SIDE)), next(u64::from(SIDE))),
            radius: 1 + next(400),
        })
        .collect()
}

fn pixel_count(circles: &[Circle]) -> u64 {
    let mut count = 0;
    for c in circles {
        midpoint_circle(c.centre, c.radius, |_| count += 1, |_, _, _| {});
    }
    count
}

fn hollow(c: &mut Criterion) {
    let circles = circle_set();
    let mut group = c.benchmark_group("hollow circles, 1024²");
    group.throughput(Throughput::Elements(pixel_count(&circles)));
    let mut canvas = Canvas::new(SIDE, SIDE);
    group.bench_function("reference midpoint_circle", |b| {
        b.iter(|| {
            for c in &circles {
                midpoint_circle(
                    c.centre,
                    c.radius,
                    |p| canvas.set(p, Rgba::WHITE),
                    |_, _, _| {},
                );
            }
            black_box(&canvas);
        });
    });
    group.bench_function("reference integer_circle", |b| {
        b.iter(|| {
            for c in &circles {
                integer_circle(c.centre, c.radius, |p| canvas.set(p, Rgba::WHITE), |_| {});
            }
            black_box(&canvas);
        });
    });
    let mut image = RgbaImage::new(SIDE, SIDE);
    group.bench_function("imageproc draw_hollow_circle_mut", |b| {
        b.iter(|| {
            for c in &circles {
                draw_hollow_circle_mut(
                    &mut image,
                    (c.centre.x, c.centre.y),
                    c.radius,
                    image::Rgba([255, 255, 255, 255]),
                );
            }
            black_box(&image);
        });
    });
    group.finish();
}

criterion_group!(benches, hollow);
criterion_main!(benches);
