//! The course GPU library on whatever adapter this machine has (lavapipe in
//! CI). Without an adapter each test prints a skip line and passes, unless
//! `GPU_REQUIRED=1`.

use canvas::{Pixel, Rgba};
use gpu::{COLOUR_FORMAT, DEPTH_FORMAT, Gpu, GpuError, OffscreenTarget, read_buffer, wgpu};
use wgpu::util::DeviceExt;

/// Clear colour of the tests: exact in 8 bits (0.5 would round).
const CLEAR: wgpu::Color = wgpu::Color {
    r: 51.0 / 255.0,
    g: 102.0 / 255.0,
    b: 153.0 / 255.0,
    a: 1.0,
};

fn clear_rgba() -> Rgba {
    Rgba::from_rgba8([51, 102, 153, 255])
}

#[test]
fn adapter_is_described() {
    let Some(gpu) = Gpu::for_tests() else { return };
    let text = gpu.describe();
    assert!(text.contains(&gpu.info.name), "{text}");
    eprintln!("adapter: {text}");
}

#[test]
fn cleared_odd_width_target_reads_back_without_padding() {
    let Some(gpu) = Gpu::for_tests() else { return };
    // 3 pixels = 12 bytes per row, copied as 256: the padding must be dropped.
    let target = OffscreenTarget::new(&gpu, 3, 5);
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    {
        let _pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: None,
            color_attachments: &[Some(target.colour_attachment(CLEAR))],
            depth_stencil_attachment: Some(target.depth_attachment()),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
    }
    gpu.queue.submit([encoder.finish()]);
    let canvas = target.read_colour(&gpu).unwrap();
    assert_eq!((canvas.width(), canvas.height()), (3, 5));
    for (p, c) in canvas.enumerate() {
        assert_eq!(c, clear_rgba(), "pixel {p:?}");
    }
}

/// ```text
///  NDC y = +1  +-------+        the triangle covers the top-left corner:
///              |\ lit  |        canvas rows near the top (high y) are lit
///              |  \    |        at the left, the bottom-right stays clear
///  NDC y = -1  +-------+
/// ```
#[test]
fn rendered_triangle_is_read_back_upright_with_depth_test() {
    let Some(gpu) = Gpu::for_tests() else { return };
    let shader = gpu
        .shader(
            "corner triangle",
            r"
struct Out { @builtin(position) position: vec4<f32>, @location(0) colour: vec4<f32> }
@vertex fn vs(@builtin(vertex_index) i: u32, @builtin(instance_index) k: u32) -> Out {
    // Instance 0: white, far; instance 1: red, near, the same triangle.
    var corners = array(vec2(-1.0, 1.0), vec2(-1.0, -1.0), vec2(1.0, 1.0));
    let depth = select(0.8, 0.2, k == 1u);
    let colour = select(vec4(1.0), vec4(1.0, 0.0, 0.0, 1.0), k == 1u);
    return Out(vec4(corners[i], depth, 1.0), colour);
}
@fragment fn fs(v: Out) -> @location(0) vec4<f32> { return v.colour; }
",
        )
        .unwrap();
    let pipeline = gpu
        .device
        .create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: None,
            layout: None,
            vertex: wgpu::VertexState {
                module: &shader,
                entry_point: Some("vs"),
                compilation_options: Default::default(),
                buffers: &[],
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: Some(wgpu::DepthStencilState {
                format: DEPTH_FORMAT,
                depth_write_enabled: Some(true),
                depth_compare: Some(wgpu::CompareFunction::Less),
                stencil: Default::default(),
                bias: Default::default(),
            }),
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &shader,
                entry_point: Some("fs"),
                compilation_options: Default::default(),
                targets: &[Some(COLOUR_FORMAT.into())],
            }),
            multiview_mask: None,
            cache: None,
        });
    let target = OffscreenTarget::new(&gpu, 8, 8);
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: None,
            color_attachments: &[Some(target.colour_attachment(CLEAR))],
            depth_stencil_attachment: Some(target.depth_attachment()),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(&pipeline);
        // The near red instance first, then the far white one: the depth
        // test must keep red.
        pass.draw(0..3, 1..2);
        pass.draw(0..3, 0..1);
    }
    gpu.queue.submit([encoder.finish()]);
    let canvas = target.read_colour(&gpu).unwrap();
    let red = Rgba::from_rgba8([255, 0, 0, 255]);
    assert_eq!(
        canvas.get(Pixel::new(0, 7)),
        Some(red),
        "top-left is covered"
    );
    assert_eq!(
        canvas.get(Pixel::new(7, 0)),
        Some(clear_rgba()),
        "bottom-right is not"
    );
    assert!(
        canvas
            .enumerate()
            .all(|(_, c)| c == red || c == clear_rgba())
    );
}

#[test]
fn compute_results_are_read_back() {
    let Some(gpu) = Gpu::for_tests() else { return };
    let shader = gpu
        .shader(
            "double",
            r"
@group(0) @binding(0) var<storage, read_write> data: array<f32>;
@compute @workgroup_size(64) fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    if id.x < arrayLength(&data) { data[id.x] = 2.0 * data[id.x] + 1.0; }
}
",
        )
        .unwrap();
    let input: Vec<f32> = (0..100).map(|i| i as f32 * 0.25).collect();
    let buffer = gpu
        .device
        .create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: None,
            contents: bytemuck::cast_slice(&input),
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        });
    let pipeline = gpu
        .device
        .create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: None,
            layout: None,
            module: &shader,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            cache: None,
        });
    let bind_group = gpu.device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[wgpu::BindGroupEntry {
            binding: 0,
            resource: buffer.as_entire_binding(),
        }],
    });
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind_group, &[]);
        pass.dispatch_workgroups(2, 1, 1);
    }
    gpu.queue.submit([encoder.finish()]);
    let output: Vec<f32> = read_buffer(&gpu, &buffer).unwrap();
    // Doubling and adding one is exact in f32 for these quarter steps.
    let expected: Vec<f32> = input.iter().map(|x| 2.0 * x + 1.0).collect();
    assert_eq!(output, expected);
}

#[test]
fn invalid_wgsl_is_an_error_with_the_line_not_a_panic() {
    let Some(gpu) = Gpu::for_tests() else { return };
    let error = gpu
        .shader("broken", "fn f() -> f32 {\n  return undefined_name;\n}\n")
        .unwrap_err();
    let GpuError::Validation { message, .. } = &error else {
        panic!("expected a validation error, got {error}");
    };
    assert!(message.contains("undefined_name"), "{message}");
}
