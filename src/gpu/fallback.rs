//! What wgpu's frame rasteriser does not draw, and the honest route for it: a frame that uses
//! the logic op, a blend WebGPU cannot express (`blend.rs`), the accumulation buffer, a swap in the middle of the frame, more than one
//! colour buffer, a texture unit beyond unit 0 (GL 1.3's units: the WGSL fragment stage
//! binds one texture), a texture with GL 1.4's LOD bias (wgpu's samplers take none, and
//! WGSL's `textureSampleBias` clamps otherwise than GL's eq. 3.16), a cube map (GL 1.3: the
//! WGSL fragment stage binds a 2D and a 3D image, not yet a cube), a depth texture (GL 1.4:
//! its depths and shadow comparison are not in the WGSL stage yet) or a rectangle texture
//! (`GL_ARB_texture_rectangle`: its coordinates in texels) is drawn by the CPU rasteriser (`render/soft`, GL's rules, scored against Mesa)
//! and its picture handed back as the wgpu render's. WebGPU has no logic op at all; the
//! accumulation buffer and front and back targets would need a texture each and passes between
//! them, not built. The stencil and scissor tests and the write masks
//! are wgpu's own (`raster.rs`, `passes.rs`, `clear_quads.rs`).

use crate::gl::consts::*;
use crate::gl::{Command, FragmentTests, Frame};

/// Whether wgpu's pipelines draw `tests` as GL does: no logic op, one colour buffer (the same
/// through the frame).
fn plain(tests: &FragmentTests, buffers: &mut Option<u8>) -> bool {
    let one_buffer = match buffers {
        Some(b) => *b == tests.draw_buffers,
        None => {
            *buffers = Some(tests.draw_buffers);
            tests.draw_buffers.count_ones() == 1
        }
    };
    one_buffer && tests.logic_op.is_none()
}

/// Whether a render of `frame` reads the depth buffer back: asked for (`depth`: `glReadPixels`
/// of `GL_DEPTH_COMPONENT`, `glCopyTexImage` of a depth texture), or a `glCopyPixels` of
/// `GL_DEPTH` in it. wgpu's GL backend cannot copy a depth-stencil attachment into a buffer (its
/// submission fails), so there such a frame is the CPU rasteriser's too.
pub(crate) fn reads_depth(frame: &Frame, depth: bool) -> bool {
    depth || frame.pixel_copies.iter().any(|c| c.buffer == GL_DEPTH)
}

/// Whether the CPU rasteriser must draw `frame` for wgpu (see the module's text; a
/// `glCopyPixels` of `GL_STENCIL` writes stencil values, which a draw cannot).
pub(crate) fn needs_cpu(frame: &Frame) -> bool {
    if frame.pixel_copies.iter().any(|c| c.buffer == GL_STENCIL) {
        return true;
    }
    let mut buffers = None;
    let last = frame.commands.len().saturating_sub(1);
    let biased = |s: &crate::gl::DrawState| {
        s.texture.as_ref().is_some_and(|t| t.lod_bias != 0.0 || t.cube_map || t.rectangle || t.depth.is_some())
    };
    let states = frame
        .states
        .iter()
        .any(|s| !plain(&s.fragment_tests, &mut buffers) || !s.more_textures.is_empty() || biased(s))
        || !super::blend::expressible(frame.states.iter().map(|s| &s.blend));
    states
        || frame.commands.iter().enumerate().any(|(k, command)| match command {
            Command::Clear { mask, tests, .. } => mask & !GL_ACCUM_BUFFER_BIT != 0 && !plain(tests, &mut buffers),
            // Occlusion queries are counted by the CPU rasteriser (wgpu's counts on lavapipe
            // are not measured).
            Command::Accum(_) | Command::Query { .. } => true,
            Command::SwapBuffers => k != last,
            Command::Draw(_) | Command::Mesh(_) | Command::CopyPixels(_) => false,
        })
}
