//! Bicubic patch tessellation: the GPU path of topic 10 (the evaluation
//! compute pass with de Casteljau in WGSL, read back) against a CPU
//! evaluation of the same domain points (de Casteljau in f64, below: the
//! course gives students no CPU evaluation, so the benchmark has its own).
//!
//! The adapter is printed first: on a machine without a GPU it is a
//! software rasterizer (lavapipe, device type `Cpu`), and its figures are
//! CPU figures, not GPU figures. The GPU timing is a whole call: upload,
//! shader compilation and pipeline creation, dispatch, readback.
//!
//! ```text
//! cargo xtask bench --features gpu --bench gpu
//! ```

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::{DVec3, Vec3, Vec4};
use gpu::Gpu;
use gpu_tessellation::domain::{Domain, QuadLevels, Spacing, quad_domain};
use gpu_tessellation::passes::{Patches, run_evaluation};
use gpu_tessellation::patch::{BezierPatch, GpuVertex};
use gpu_tessellation::wgsl;

/// De Casteljau on a cubic: the point and the two points of the last step
/// but one, whose difference is a third of the derivative.
fn de_casteljau_cubic(mut p: [DVec3; 4], t: f64) -> (DVec3, DVec3, DVec3) {
    for level in (1..4).rev() {
        for k in 0..level {
            p[k] = p[k] * (1.0 - t) + p[k + 1] * t;
        }
        if level == 2 {
            return (p[0] * (1.0 - t) + p[1] * t, p[0], p[1]);
        }
    }
    unreachable!("a cubic has three levels")
}

/// The patch at every domain point on the CPU, in f64: de Casteljau along
/// u on every row, then along v (and the u-tangent's points along v too).
fn tessellate_patch(patch: &BezierPatch, points: &[Vec3]) -> Vec<GpuVertex> {
    let p = |k: usize| patch.points[k].as_dvec3();
    points
        .iter()
        .map(|d| {
            let (u, v) = (f64::from(d.x), f64::from(d.y));
            let (mut rows, mut row_a, mut row_b) =
                ([DVec3::ZERO; 4], [DVec3::ZERO; 4], [DVec3::ZERO; 4]);
            for j in 0..4 {
                (rows[j], row_a[j], row_b[j]) =
                    de_casteljau_cubic([p(4 * j), p(4 * j + 1), p(4 * j + 2), p(4 * j + 3)], u);
            }
            let (position, va, vb) = de_casteljau_cubic(rows, v);
            let (ua, ..) = de_casteljau_cubic(row_a, v);
            let (ub, ..) = de_casteljau_cubic(row_b, v);
            GpuVertex {
                position: position.as_vec3().extend(1.0),
                normal: (ub - ua)
                    .cross(vb - va)
                    .normalize_or_zero()
                    .as_vec3()
                    .extend(0.0),
                param: Vec4::new(d.x, d.y, 0.0, 0.0),
            }
        })
        .collect()
}

/// Patches per run.
const PATCHES: usize = 256;
/// Uniform tessellation level: 2·L² triangles, (L + 1)² vertices per patch.
const LEVEL: f32 = 32.0;

/// A fixed set of patches (a linear congruential generator keeps it the
/// same in every run).
fn patch_set() -> Vec<BezierPatch> {
    let mut state: u64 = 0x2545_F491_4F6C_DD1D;
    let mut next = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 40) as f32 / (1u64 << 24) as f32 * 2.0 - 1.0
    };
    (0..PATCHES)
        .map(|_| BezierPatch::new(std::array::from_fn(|_| Vec3::new(next(), next(), next()))))
        .collect()
}

fn tessellation(c: &mut Criterion) {
    let patches = patch_set();
    let domain = quad_domain(QuadLevels::uniform(LEVEL), Spacing::Equal);
    let triangles = (domain.triangles.len() * PATCHES) as u64;
    println!(
        "{PATCHES} patches at level {LEVEL}: {} triangles and {} vertices per patch; \
         throughput below is in triangles (patches/s = triangles/s ÷ {})",
        domain.triangles.len(),
        domain.points.len(),
        domain.triangles.len()
    );
    let mut group = c.benchmark_group("bicubic tessellation, 256 patches at level 32");
    group.throughput(Throughput::Elements(triangles));
    group.sample_size(10);
    group.bench_function("cpu tessellate_patch (f64 de Casteljau)", |b| {
        b.iter(|| {
            for p in &patches {
                black_box(tessellate_patch(p, &domain.points));
            }
        });
    });
    match Gpu::new() {
        Ok(gpu) => {
            let kind = if gpu.is_software() {
                "SOFTWARE adapter, not a GPU figure"
            } else {
                "hardware adapter"
            };
            println!("adapter: {} [{kind}]", gpu.describe());
            let domains: Vec<&Domain> = vec![&domain; PATCHES];
            let name = format!("gpu evaluation pass + readback on {}", gpu.info.name);
            group.bench_function(name, |b| {
                b.iter(|| {
                    let mesh =
                        run_evaluation(&gpu, wgsl::EVALUATION, Patches::Quads(&patches), &domains)
                            .expect("the reference evaluation runs");
                    black_box(mesh.read(&gpu).expect("readback"));
                });
            });
        }
        Err(e) => println!("no GPU benchmark: {e}"),
    }
    group.finish();
}

criterion_group!(benches, tessellation);
criterion_main!(benches);
