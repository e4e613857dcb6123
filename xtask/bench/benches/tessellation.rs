//! Uniform tessellation of Bézier patches by the reference solution, in
//! triangles per second, at a few resolutions (the primitive generator of
//! topic 10 is measured in `gpu.rs`).
//!
//! Every triangle counts once: `2 n²` for `n × n` cells (each vertex is
//! evaluated with both tangents and a normal by topic 09's given
//! `Evaluate`: the power form of every row, then of the curve they make).

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use tessellation::bezier::BezierPatch;
use tessellation::patch_grid::PatchGrid;
use tessellation::uniform::tessellate_uniform;

/// Cells per direction.
const LEVELS: [usize; 3] = [8, 32, 128];

fn uniform(c: &mut Criterion) {
    let patches = [
        ("seed surface 3×2", BezierPatch::seed_surface()),
        ("bicubic", PatchGrid::example().patch(1, 1).clone()),
    ];
    for (name, patch) in &patches {
        let mut group = c.benchmark_group(format!("uniform tessellation, {name}"));
        for n in LEVELS {
            group.throughput(Throughput::Elements(2 * (n * n) as u64));
            group.bench_function(format!("{n}×{n} cells"), |b| {
                b.iter(|| black_box(tessellate_uniform(black_box(patch), n, n).unwrap()));
            });
        }
        group.finish();
    }
}

criterion_group!(benches, uniform);
criterion_main!(benches);
