//! Drawing a recorded [`Frame`](crate::gl::Frame): the CPU stages, always available and
//! testable without a GPU: primitive assembly (its vertices lit by `gl`'s shading, which
//! feedback and selection share) (wide lines, square
//! points, viewports, depth range), the image metric the conformance tests score pictures with,
//! and PNG output. The wgpu side (the `Renderer`, the GPU evaluator) lives in the crate's
//! `gpu` module (feature `gpu`); its public types are re-exported here, their one documented
//! home.

pub(crate) mod assemble;
mod clip;
#[cfg(all(feature = "gpu", feature = "png"))]
pub(crate) mod compare;
mod corner;
#[cfg(feature = "gpu")]
mod device_select;
mod image;
mod offset;
pub mod pixel_copy;
mod smooth;
pub mod soft;
mod stipple;

pub use assemble::{assemble, assemble_frame, Batch, DrawList, Op, RasterVertex, Smooth, Topology};
#[cfg(feature = "gpu")]
pub use device_select::{quiet_device_select, NODEVICE_SELECT};
pub use image::Image;

/// Which rasteriser draws a headless picture (a window always draws through wgpu).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Rasterizer {
    /// [`soft`], on the CPU: no device, no driver, no start-up cost; the default.
    #[default]
    Cpu,
    /// wgpu's (feature `gpu`): the same pipeline a window draws with, and the only one the
    /// GPU tessellator's meshes can be drawn by.
    Wgpu,
}

impl Rasterizer {
    /// The environment variable [`crate::app::App`] reads for the headless rasteriser: `cpu`
    /// or `wgpu`.
    pub const ENV: &'static str = "GLEVAL_RASTERIZER";

    /// `Wgpu` when `GLEVAL_RASTERIZER=wgpu`, else `Cpu`.
    #[must_use]
    pub fn from_env() -> Self {
        match std::env::var(Self::ENV) {
            Ok(v) if v.eq_ignore_ascii_case("wgpu") => Self::Wgpu,
            _ => Self::Cpu,
        }
    }
}

#[cfg(feature = "gpu")]
pub use crate::gpu::{tessellate_patches, RenderError, Renderer};

/// Writes an image as an 8-bit RGB PNG: what a window shows (GL's framebuffer alpha, often 0
/// after `glClearColor(r, g, b, 0)`, is not part of the picture).
#[cfg(feature = "png")]
pub fn write_png(path: impl AsRef<std::path::Path>, image: &Image) -> std::io::Result<()> {
    let file = std::io::BufWriter::new(std::fs::File::create(path)?);
    let mut encoder = png::Encoder::new(file, image.width, image.height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    // fdeflate's PNG-tuned mode: a whole-process render spent more time compressing at the
    // default level than drawing (4.7 ms of a 500 × 500 frame, measured with --profile).
    encoder.set_compression(png::Compression::Fast);
    let mut writer = encoder.write_header().map_err(std::io::Error::other)?;
    let rgb: Vec<u8> = image.pixels.chunks_exact(4).flat_map(|p| [p[0], p[1], p[2]]).collect();
    writer.write_image_data(&rgb).map_err(std::io::Error::other)?;
    writer.finish().map_err(std::io::Error::other)
}
