//! Copying GPU memory back to the CPU.
//!
//! A texture-to-buffer copy must use rows whose length in bytes is a
//! multiple of [`wgpu::COPY_BYTES_PER_ROW_ALIGNMENT`] (256): a 3-pixel-wide
//! RGBA8 row of 12 bytes is copied as 256 bytes, and the padding is dropped
//! here.

use crate::{Gpu, GpuError};

/// The bytes per row of a texture copy: `width · bytes_per_pixel` rounded up
/// to a multiple of [`wgpu::COPY_BYTES_PER_ROW_ALIGNMENT`].
#[must_use]
pub fn padded_bytes_per_row(width: u32, bytes_per_pixel: u32) -> u32 {
    let unpadded = width * bytes_per_pixel;
    unpadded.div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT) * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT
}

/// Maps a `MAP_READ` buffer and returns a copy of its first `len` bytes.
fn map_bytes(gpu: &Gpu, buffer: &wgpu::Buffer, len: u64) -> Result<Vec<u8>, GpuError> {
    let slice = buffer.slice(..len);
    let (sender, receiver) = std::sync::mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |result| {
        // The receiver outlives the wait below, so a send cannot fail.
        let _ = sender.send(result);
    });
    gpu.wait()?;
    match receiver.recv() {
        Ok(result) => result?,
        Err(_) => return Err(GpuError::Map(wgpu::BufferAsyncError)),
    }
    let bytes = slice
        .get_mapped_range()
        .map_err(|e| GpuError::MapRange(e.to_string()))?
        .to_vec();
    buffer.unmap();
    Ok(bytes)
}

/// Copies a buffer (usage `COPY_SRC`) back into a `Vec<T>` of
/// `buffer.size() / size_of::<T>()` elements.
pub fn read_buffer<T: bytemuck::Pod>(gpu: &Gpu, buffer: &wgpu::Buffer) -> Result<Vec<T>, GpuError> {
    let size = buffer.size();
    let staging = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback staging"),
        size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let mut encoder = gpu
        .device
        .create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
    encoder.copy_buffer_to_buffer(buffer, 0, &staging, 0, size);
    gpu.queue.submit([encoder.finish()]);
    let bytes = map_bytes(gpu, &staging, size)?;
    let count = bytes.len() / size_of::<T>();
    Ok(bytemuck::pod_collect_to_vec(
        &bytes[..count * size_of::<T>()],
    ))
}

/// Copies an RGBA8 texture back: `height` rows of `width · 4` bytes, texture
/// row 0 first, padding removed.
pub(crate) fn read_texture_rows(
    gpu: &Gpu,
    texture: &wgpu::Texture,
    width: u32,
    height: u32,
) -> Result<Vec<u8>, GpuError> {
    const BYTES_PER_PIXEL: u32 = 4;
    let padded = padded_bytes_per_row(width, BYTES_PER_PIXEL);
    let size = u64::from(padded) * u64::from(height);
    let staging = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("texture readback"),
        size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let mut encoder = gpu
        .device
        .create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
    encoder.copy_texture_to_buffer(
        texture.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &staging,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(padded),
                rows_per_image: Some(height),
            },
        },
        wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        },
    );
    gpu.queue.submit([encoder.finish()]);
    let bytes = map_bytes(gpu, &staging, size)?;
    let row_bytes = (width * BYTES_PER_PIXEL) as usize;
    Ok(bytes
        .chunks_exact(padded as usize)
        .flat_map(|row| &row[..row_bytes])
        .copied()
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_are_padded_to_256_bytes() {
        assert_eq!(padded_bytes_per_row(1, 4), 256);
        assert_eq!(padded_bytes_per_row(3, 4), 256);
        assert_eq!(padded_bytes_per_row(64, 4), 256);
        assert_eq!(padded_bytes_per_row(65, 4), 512);
        assert_eq!(padded_bytes_per_row(0, 4), 0);
    }
}
