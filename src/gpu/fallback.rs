//! What wgpu's frame rasteriser does not draw yet, and the honest route for it: a frame that
//! uses the stencil buffer, the scissor test, write masks, the logic op, the accumulation buffer,
//! a swap in the middle of the frame, or more than one colour buffer is drawn by the CPU
//! rasteriser (`render/soft`, GL's rules, scored against Mesa) and its picture handed back as
//! the wgpu render's. wgpu has no logic op at all (WebGPU has none); the others need a
//! depth-stencil format, per-draw scissor rectangles, write masks, clears drawn as quads and an
//! accumulation texture with its passes, which are not built yet (README, "Still missing").

use crate::gl::consts::*;
use crate::gl::{Command, FragmentTests, Frame};

/// Whether wgpu's pipelines draw `tests` as GL does: no scissor, no stencil, all writes on, no
/// logic op, one colour buffer.
fn plain(tests: &FragmentTests, buffers: &mut Option<u8>) -> bool {
    let one_buffer = match buffers {
        Some(b) => *b == tests.draw_buffers,
        None => {
            *buffers = Some(tests.draw_buffers);
            tests.draw_buffers.count_ones() == 1
        }
    };
    one_buffer
        && tests.scissor.is_none()
        && tests.stencil.is_none()
        && tests.depth_write
        && tests.color_write == [true; 4]
        && tests.logic_op.is_none()
}

/// Whether the CPU rasteriser must draw `frame` for wgpu (see the module's text).
pub(crate) fn needs_cpu(frame: &Frame) -> bool {
    let mut buffers = None;
    let last = frame.commands.len().saturating_sub(1);
    let states = frame.states.iter().any(|s| !plain(&s.fragment_tests, &mut buffers));
    states
        || frame.commands.iter().enumerate().any(|(k, command)| match command {
            Command::Clear { mask, tests, .. } => {
                mask & (GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT) != 0 || !plain(tests, &mut buffers)
            }
            Command::Accum { .. } => true,
            Command::SwapBuffers => k != last,
            Command::Draw(_) | Command::Mesh(_) => false,
        })
}
