//! Offscreen render targets: what a window's swap chain would be, as plain
//! textures that can be copied back.

use canvas::Canvas;

use crate::{Gpu, GpuError, readback};

/// The colour format: 8 bits per channel, linear (no sRGB conversion), the
/// same levels a [`Canvas`] stores.
pub const COLOUR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// The depth format: 32-bit float depth in `[0, 1]`, cleared to
/// [`canvas::DEPTH_CLEAR`].
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// A colour and a depth texture of the same size.
#[derive(Debug)]
pub struct OffscreenTarget {
    /// The colour texture ([`COLOUR_FORMAT`]).
    pub colour: wgpu::Texture,
    /// The depth texture ([`DEPTH_FORMAT`]).
    pub depth: wgpu::Texture,
    /// View of the colour texture for a render pass.
    pub colour_view: wgpu::TextureView,
    /// View of the depth texture for a render pass.
    pub depth_view: wgpu::TextureView,
    width: u32,
    height: u32,
}

impl OffscreenTarget {
    /// A `width × height` target (at least 1 × 1; the device's texture limit
    /// caps it, beyond which wgpu reports a validation error).
    #[must_use]
    pub fn new(gpu: &Gpu, width: u32, height: u32) -> Self {
        let size = wgpu::Extent3d {
            width: width.max(1),
            height: height.max(1),
            depth_or_array_layers: 1,
        };
        let texture = |label, format, usage| {
            gpu.device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size,
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let colour = texture(
            "offscreen colour",
            COLOUR_FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        );
        let depth = texture(
            "offscreen depth",
            DEPTH_FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        );
        Self {
            colour_view: colour.create_view(&wgpu::TextureViewDescriptor::default()),
            depth_view: depth.create_view(&wgpu::TextureViewDescriptor::default()),
            colour,
            depth,
            width: size.width,
            height: size.height,
        }
    }

    /// Width in pixels.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The colour attachment, cleared to `clear` at the start of the pass.
    #[must_use]
    pub fn colour_attachment(&self, clear: wgpu::Color) -> wgpu::RenderPassColorAttachment<'_> {
        wgpu::RenderPassColorAttachment {
            view: &self.colour_view,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations {
                load: wgpu::LoadOp::Clear(clear),
                store: wgpu::StoreOp::Store,
            },
        }
    }

    /// The depth attachment, cleared to [`canvas::DEPTH_CLEAR`].
    #[must_use]
    pub fn depth_attachment(&self) -> wgpu::RenderPassDepthStencilAttachment<'_> {
        wgpu::RenderPassDepthStencilAttachment {
            view: &self.depth_view,
            depth_ops: Some(wgpu::Operations {
                load: wgpu::LoadOp::Clear(canvas::DEPTH_CLEAR),
                store: wgpu::StoreOp::Store,
            }),
            stencil_ops: None,
        }
    }

    /// Copies the colour texture into a canvas.
    ///
    /// Texture row 0 is the *top* of the picture (wgpu's framebuffer
    /// convention); canvas row 0 is the bottom, so rows are flipped: the
    /// canvas and the PNG it saves look like the rendered picture.
    pub fn read_colour(&self, gpu: &Gpu) -> Result<Canvas, GpuError> {
        let rows = readback::read_texture_rows(gpu, &self.colour, self.width, self.height)?;
        let mut image = image::RgbaImage::new(self.width, self.height);
        for (row, bytes) in rows.chunks_exact(self.width as usize * 4).enumerate() {
            for (col, px) in bytes.chunks_exact(4).enumerate() {
                image.put_pixel(
                    col as u32,
                    row as u32,
                    image::Rgba([px[0], px[1], px[2], px[3]]),
                );
            }
        }
        Ok(Canvas::from_image(&image))
    }
}
