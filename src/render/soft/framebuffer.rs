//! The CPU rasteriser's colour and depth buffers, and GL's per-fragment operations after the
//! fragment's colour is known: the depth test (GL 1.1 spec §4.1.5) and blending (§4.1.6),
//! on an RGBA8 colour buffer and a 32-bit float depth buffer, as the wgpu target has them.

use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::render::Image;

/// Colour (RGBA8, rows top to bottom) and depth, one value a pixel.
#[derive(Clone)]
pub(super) struct Framebuffer {
    pub width: u32,
    pub height: u32,
    color: Vec<[u8; 4]>,
    depth: Vec<f32>,
}

impl Framebuffer {
    /// A new buffer as a new OSMesa context has it: transparent black, depth 1.
    pub fn new(width: u32, height: u32) -> Self {
        let n = width as usize * height as usize;
        Self { width, height, color: vec![[0; 4]; n], depth: vec![1.0; n] }
    }

    /// `glClear` of the colour and/or the depth buffer (the whole buffer: no scissor test).
    pub fn clear(&mut self, color: Option<[f32; 4]>, depth: Option<f32>) {
        if let Some(c) = color {
            self.color.fill(c.map(to_unorm8));
        }
        if let Some(d) = depth {
            self.depth.fill(d.clamp(0.0, 1.0));
        }
    }

    /// GL's depth test for pixel `index` at depth `z`: whether the fragment survives. `None`
    /// is `GL_DEPTH_TEST` disabled: no test and no write.
    pub fn depth_passes(&self, index: usize, z: f32, test: Option<GLenum>) -> bool {
        test.is_none_or(|func| compare(func, z, self.depth[index]))
    }

    /// Writes a fragment that passed every test: its depth (when testing) and its colour,
    /// blended with `blend`'s source and destination factors when blending is on.
    pub fn write(&mut self, index: usize, z: f32, color: [f32; 4], test: Option<GLenum>, blend: Option<[GLenum; 2]>) {
        if test.is_some() {
            self.depth[index] = z;
        }
        let source = color.map(|c| c.clamp(0.0, 1.0));
        let out = match blend {
            None => source,
            Some([sf, df]) => {
                let dest = self.color[index].map(|c| f32::from(c) / 255.0);
                let (s, d) = (factor(sf, source, dest), factor(df, source, dest));
                std::array::from_fn(|k| source[k] * s[k] + dest[k] * d[k])
            }
        };
        self.color[index] = out.map(to_unorm8);
    }

    /// The colour buffer as an [`Image`].
    pub fn into_image(self) -> Image {
        let pixels = self.color.into_iter().flatten().collect();
        Image { width: self.width, height: self.height, pixels }
    }

    /// A copy of both buffers.
    pub fn window_image(&self) -> crate::gl::WindowImage {
        let color = self.color.iter().flatten().copied().collect();
        crate::gl::WindowImage { width: self.width, height: self.height, color, depth: self.depth.clone() }
    }

    /// A copy of the colour buffer as an [`Image`].
    pub fn image(&self) -> Image {
        Image { width: self.width, height: self.height, pixels: self.color.iter().flatten().copied().collect() }
    }
}

/// A float colour component in an 8-bit normalised buffer: clamped, rounded to nearest.
fn to_unorm8(c: f32) -> u8 {
    (c.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

/// GL's comparison functions (the depth test's, §4.1.5, and the alpha test's, §4.1.3):
/// whether `value` passes against `reference` under `func` (`GL_ALWAYS` for anything else).
pub(super) fn compare(func: GLenum, value: f32, reference: f32) -> bool {
    match func {
        GL_NEVER => false,
        GL_LESS => value < reference,
        GL_EQUAL => value == reference,
        GL_LEQUAL => value <= reference,
        GL_GREATER => value > reference,
        GL_NOTEQUAL => value != reference,
        GL_GEQUAL => value >= reference,
        _ => true,
    }
}

/// A blend factor (GL 1.1 spec table 4.1 and 4.2) for source colour `s` and destination `d`.
fn factor(f: GLenum, s: [f32; 4], d: [f32; 4]) -> [f32; 4] {
    match f {
        GL_ZERO => [0.0; 4],
        GL_SRC_COLOR => s,
        GL_ONE_MINUS_SRC_COLOR => s.map(|c| 1.0 - c),
        GL_SRC_ALPHA => [s[3]; 4],
        GL_ONE_MINUS_SRC_ALPHA => [1.0 - s[3]; 4],
        GL_DST_ALPHA => [d[3]; 4],
        GL_ONE_MINUS_DST_ALPHA => [1.0 - d[3]; 4],
        GL_DST_COLOR => d,
        GL_ONE_MINUS_DST_COLOR => d.map(|c| 1.0 - c),
        GL_SRC_ALPHA_SATURATE => {
            let f = s[3].min(1.0 - d[3]);
            [f, f, f, 1.0]
        }
        _ => [1.0; 4],
    }
}
