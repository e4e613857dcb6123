//! Bicubic patch tessellation: the GPU path of topic 10 (the evaluation
//! compute pass with de Casteljau in WGSL, read back) against a CPU
//! evaluation of the same domain points (de Casteljau in f64, below: the
//! course gives students no CPU evaluation, so the benchmark has its own).
//!
//! The adapter is printed first: on a machine without a GPU it is a
//! software rasterizer (lavapipe, device type `Cpu`), and its figures are
//! CPU figures, not GPU figures. The one-time set-up (the device, the
//! shader's check and compilation, the pipelines) is timed apart from the
//! per-frame work (upload, dispatch, readback), which is measured at
//! several levels up to two million triangles, in triangles per second.
//! The primitive generator (task 2, on the CPU) is measured on its own, in
//! domain triangles per second.
//!
//! ```text
//! cargo xtask bench --features gpu --bench gpu
//! ```

use std::hint::black_box;
use std::time::Instant;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::{DVec3, Vec3, Vec4};
use gpu::Gpu;
use gpu_tessellation::domain::{Spacing, triangle_domain};
use gpu_tessellation::passes::{Domain, QuadLevels};
use gpu_tessellation::passes::{EvaluationPass, Patches};
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
    // The GPU's order: `P_ij` at `4j + i`, row j a curve in u; read once
    // per patch, not once per vertex.
    let net: [DVec3; 16] = std::array::from_fn(|k| patch.control_point(k % 4, k / 4));
    let p = |k: usize| net[k];
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

/// Patches per frame.
const PATCHES: usize = 256;
/// Uniform tessellation levels measured: 2·L² triangles, (L + 1)² vertices
/// per patch; at 64, 256 patches make 2.1 million triangles.
const LEVELS: [f32; 4] = [8.0, 16.0, 32.0, 64.0];

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
        .map(|_| {
            BezierPatch::from_fn(3, 3, |_, _| Vec3::new(next(), next(), next()).as_dvec3())
                .expect("finite points")
        })
        .collect()
}

fn tessellation(c: &mut Criterion) {
    let patches = patch_set();
    let started = Instant::now();
    let gpu = Gpu::new();
    let device_ms = started.elapsed().as_secs_f64() * 1e3;
    let gpu = match gpu {
        Ok(gpu) => {
            let kind = if gpu.is_software() {
                "SOFTWARE adapter, not a GPU figure"
            } else {
                "hardware adapter"
            };
            println!("adapter: {} [{kind}]", gpu.describe());
            println!("set-up: the device in {device_ms:.1} ms (once)");
            Some(gpu)
        }
        Err(e) => {
            println!("no GPU benchmark: {e}");
            None
        }
    };
    let pass = gpu.as_ref().map(|gpu| {
        let mut setup = c.benchmark_group("gpu set-up");
        setup.sample_size(10);
        setup.bench_function(
            "check and compile the evaluation pass (naga, pipelines)",
            |b| {
                b.iter(|| {
                    black_box(
                        EvaluationPass::new(gpu, wgsl::EVALUATION).expect("the reference compiles"),
                    )
                });
            },
        );
        setup.finish();
        EvaluationPass::new(gpu, wgsl::EVALUATION).expect("the reference compiles")
    });
    for level in LEVELS {
        let domain = QuadLevels::uniform(level).domain(Spacing::Equal);
        let triangles = (domain.triangles.len() * PATCHES) as u64;
        println!(
            "{PATCHES} patches at level {level}: {triangles} triangles, {} vertices; \
             throughput in triangles (patches/s = triangles/s ÷ {})",
            domain.points.len() * PATCHES,
            domain.triangles.len()
        );
        let mut group = c.benchmark_group(format!(
            "bicubic tessellation per frame, {PATCHES} patches at level {level}"
        ));
        group.throughput(Throughput::Elements(triangles));
        group.sample_size(10);
        group.bench_function("cpu tessellate_patch (f64 de Casteljau)", |b| {
            b.iter(|| {
                for p in &patches {
                    black_box(tessellate_patch(p, &domain.points));
                }
            });
        });
        if let (Some(gpu), Some(pass)) = (&gpu, &pass) {
            let domains: Vec<&Domain> = vec![&domain; PATCHES];
            let name = format!(
                "gpu evaluation pass: upload, dispatch, readback on {}",
                gpu.info.name
            );
            group.bench_function(name, |b| {
                b.iter(|| {
                    let mesh = pass
                        .run(gpu, Patches::Quads(&patches), &domains)
                        .expect("the reference evaluation runs");
                    black_box(mesh.read(gpu).expect("readback"));
                });
            });
        }
        group.finish();
    }
}

fn primitive_generator(c: &mut Criterion) {
    let mut group = c.benchmark_group("primitive generator, triangles");
    for level in [8.0, 64.0] {
        let count = triangle_domain(level, [level; 3], Spacing::Equal)
            .triangles
            .len();
        group.throughput(Throughput::Elements(count as u64));
        group.bench_function(format!("equal, inner = outer = {level}"), |b| {
            b.iter(|| {
                black_box(triangle_domain(
                    black_box(level),
                    [level; 3],
                    Spacing::Equal,
                ))
            });
        });
    }
    group.finish();
}

criterion_group!(benches, tessellation, primitive_generator);
criterion_main!(benches);
