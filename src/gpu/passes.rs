//! A frame's render passes: GL clears split the frame's draws into passes (a clear is a pass's
//! load operation in wgpu), and GL's viewports become scissor rectangles.

use crate::gl::FragmentTests;
use crate::render::assemble::{viewport_in_target, Batch, Op};

/// What a render pass draws: a batch of assembled vertices or a GPU-tessellated mesh.
pub(crate) enum PassItem {
    Batch(Batch),
    /// Mesh `mesh` of the frame, with its fragment state's index (see `Batch::fragment`).
    Mesh {
        mesh: usize,
        fragment: Option<u32>,
    },
}

/// Draws between two clears share one render pass.
pub(crate) struct Pass {
    pub clear_color: Option<[f32; 4]>,
    pub clear_depth: Option<f32>,
    pub clear_stencil: Option<u32>,
    pub draws: Vec<PassItem>,
}

/// Splits the ops at every clear. The first pass clears to transparent black and depth 1 (the
/// state of a new OSMesa buffer) unless the program clears first, or, with `keep` (a frame
/// drawn over another, as a GLUT menu is), starts from what the target holds.
pub(crate) fn split_passes(ops: &[Op], keep: bool) -> Vec<Pass> {
    let start = if keep { (None, None, None) } else { (Some([0.0; 4]), Some(1.0), Some(0)) };
    let mut passes =
        vec![Pass { clear_color: start.0, clear_depth: start.1, clear_stencil: start.2, draws: Vec::new() }];
    for op in ops {
        match *op {
            // Clears of the scissor box or through masks were made draws (`clear_quads.rs`).
            Op::Clear { color, depth, stencil, .. } => {
                let stencil = stencil.map(|s| (s & 0xFF) as u32);
                let last = passes.last_mut().expect("at least one pass");
                if last.draws.is_empty() {
                    last.clear_color = color.or(last.clear_color);
                    last.clear_depth = depth.or(last.clear_depth);
                    last.clear_stencil = stencil.or(last.clear_stencil);
                } else {
                    passes.push(Pass {
                        clear_color: color,
                        clear_depth: depth,
                        clear_stencil: stencil,
                        draws: Vec::new(),
                    });
                }
            }
            Op::Draw(batch) => passes.last_mut().expect("at least one pass").draws.push(PassItem::Batch(batch)),
            // Frames with these are drawn by the CPU rasteriser (`fallback.rs`).
            Op::Accum(_) | Op::SwapBuffers | Op::Query { .. } => {}
            Op::GpuMesh { mesh, fragment } => {
                passes.last_mut().expect("at least one pass").draws.push(PassItem::Mesh { mesh, fragment })
            }
            // The renderer turns copies into point batches before it splits the passes
            // (`Renderer::render_window`); one left here has nothing to draw.
            Op::CopyPixels { .. } => {}
        }
    }
    passes
}

pub(crate) fn begin_pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    color: &wgpu::TextureView,
    depth: &wgpu::TextureView,
    clear_color: Option<[f32; 4]>,
    (clear_depth, clear_stencil): (Option<f32>, Option<u32>),
) -> wgpu::RenderPass<'e> {
    let color_load = match clear_color {
        Some([r, g, b, a]) => wgpu::LoadOp::Clear(wgpu::Color { r: r.into(), g: g.into(), b: b.into(), a: a.into() }),
        None => wgpu::LoadOp::Load,
    };
    let depth_load = clear_depth.map_or(wgpu::LoadOp::Load, wgpu::LoadOp::Clear);
    let stencil_load = clear_stencil.map_or(wgpu::LoadOp::Load, wgpu::LoadOp::Clear);
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some("gl frame"),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view: color,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations { load: color_load, store: wgpu::StoreOp::Store },
        })],
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: depth,
            depth_ops: Some(wgpu::Operations { load: depth_load, store: wgpu::StoreOp::Store }),
            stencil_ops: Some(wgpu::Operations { load: stencil_load, store: wgpu::StoreOp::Store }),
        }),
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: None,
    })
}

/// Where a draw lands: its viewport's rectangle (see [`scissor_rect`]) within the scissor box
/// of `tests` when the scissor test is on, in a target drawn upside down with `flip`; `None`
/// when empty.
pub(crate) fn draw_rect(viewport: [i32; 4], tests: &FragmentTests, size: (u32, u32), flip: bool) -> Option<[u32; 4]> {
    let [x0, y0, w0, h0] = scissor_rect(viewport, size)?;
    let [left, top, width, height] = match tests.scissor {
        None => [x0, y0, w0, h0],
        Some(b) => {
            let [x1, y1, w1, h1] = scissor_rect(b, size)?;
            let (left, top) = (x0.max(x1), y0.max(y1));
            let (right, bottom) = ((x0 + w0).min(x1 + w1), (y0 + h0).min(y1 + h1));
            if right <= left || bottom <= top {
                return None;
            }
            [left, top, right - left, bottom - top]
        }
    };
    Some(if flip { [left, size.1 - top - height, width, height] } else { [left, top, width, height] })
}

/// The stencil reference a draw sets: GL's, clamped to the 8-bit buffer's range.
pub(crate) fn stencil_reference(tests: &FragmentTests) -> u32 {
    tests.stencil.map_or(0, |s| s.reference.clamp(0, 255) as u32)
}

/// The GL viewport (origin bottom-left) intersected with the target, in wgpu's top-left
/// coordinates as `[x, y, width, height]`; `None` when empty.
pub(crate) fn scissor_rect(viewport: [i32; 4], size: (u32, u32)) -> Option<[u32; 4]> {
    viewport_in_target(viewport, size).map(|[x0, top, x1, bottom]| [x0, top, x1 - x0, bottom - top])
}
