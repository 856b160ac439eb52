//! The headless render target: a colour and a depth texture, and the colour read back through
//! the one read-back ([`read_back`]) without wgpu's row padding.

use super::device::{read_back, RenderError};
use super::raster::DEPTH_FORMAT;

/// A colour and depth texture to render into.
pub(crate) struct Target {
    pub width: u32,
    pub height: u32,
    color: wgpu::Texture,
    depth: wgpu::Texture,
    pub color_view: wgpu::TextureView,
    pub depth_view: wgpu::TextureView,
}

impl Target {
    pub(crate) fn new(device: &wgpu::Device, width: u32, height: u32, format: wgpu::TextureFormat) -> Self {
        let size = wgpu::Extent3d { width, height, depth_or_array_layers: 1 };
        let texture = |format, usage| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some("gleval target"),
                size,
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let color = texture(format, wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC);
        let depth = texture(DEPTH_FORMAT, wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC);
        let color_view = color.create_view(&Default::default());
        let depth_view = depth.create_view(&Default::default());
        Self { width, height, color, depth, color_view, depth_view }
    }

    /// Submits `encoder` with a copy of the colour texture at its end, waits, and returns the
    /// pixels, rows top to bottom, without row padding (a texture drawn upside down, `flip`, is
    /// read from its last row up).
    pub(crate) fn read(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: wgpu::CommandEncoder,
        flip: bool,
    ) -> Result<Vec<u8>, RenderError> {
        self.read_plane(device, queue, encoder, (&self.color, wgpu::TextureAspect::All), flip)
    }

    /// Submits `encoder` with a copy of the depth texture at its end, waits, and returns the
    /// depths (32-bit floats), rows top to bottom (upside down with `flip`, as [`Target::read`]).
    pub(crate) fn read_depth(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: wgpu::CommandEncoder,
        flip: bool,
    ) -> Result<Vec<f32>, RenderError> {
        let plane = (&self.depth, wgpu::TextureAspect::DepthOnly);
        let bytes = self.read_plane(device, queue, encoder, plane, flip)?;
        Ok(bytes.chunks_exact(4).map(|b| f32::from_ne_bytes([b[0], b[1], b[2], b[3]])).collect())
    }

    /// Reads one aspect of a texture of 4 bytes a texel (RGBA8, or the depth as `f32`) back:
    /// rows top to bottom without wgpu's row padding, from the last row up with `flip`.
    fn read_plane(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: wgpu::CommandEncoder,
        (texture, aspect): (&wgpu::Texture, wgpu::TextureAspect),
        flip: bool,
    ) -> Result<Vec<u8>, RenderError> {
        // wgpu copies rows at a multiple of 256 bytes.
        let align = wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
        let padded_row = (self.width * 4).div_ceil(align) * align;
        let size = u64::from(padded_row) * u64::from(self.height);
        let padded = read_back(device, queue, encoder, size, |encoder, buffer| {
            encoder.copy_texture_to_buffer(
                wgpu::TexelCopyTextureInfo { texture, mip_level: 0, origin: wgpu::Origin3d::ZERO, aspect },
                wgpu::TexelCopyBufferInfo {
                    buffer,
                    layout: wgpu::TexelCopyBufferLayout {
                        offset: 0,
                        bytes_per_row: Some(padded_row),
                        rows_per_image: Some(self.height),
                    },
                },
                wgpu::Extent3d { width: self.width, height: self.height, depth_or_array_layers: 1 },
            );
        })?;
        let row = self.width as usize * 4;
        let rows = padded.chunks_exact(padded_row as usize).map(|r| &r[..row]);
        Ok(if flip { rows.rev().flatten().copied().collect() } else { rows.flatten().copied().collect() })
    }
}
