//! GL's clears that a render pass's load operation cannot make: wgpu clears a whole attachment,
//! while GL clears only the scissor box, through the colour mask, the depth mask and the stencil
//! write mask (GL 1.1 spec §4.2.3). Such a clear becomes a draw: two triangles over the box at
//! the clear depth, with the clear colour, depth always passing and written, and the stencil
//! always passing and replaced by the clear value, each only where the clear names its buffer
//! and the masks let it through.

use crate::gl::consts::*;
use crate::gl::{FragmentTests, Stencil};
use crate::render::assemble::{Batch, DrawList, Op, RasterVertex, Topology};

/// Whether a clear is a load operation: the whole target, every bit of what it clears written.
pub(crate) fn plain_clear(color: bool, depth: bool, stencil: bool, tests: &FragmentTests) -> bool {
    tests.scissor.is_none()
        && (!color || tests.color_write == [true; 4])
        && (!depth || tests.depth_write)
        && (!stencil || tests.stencil_write_mask & 0xFF == 0xFF)
}

/// `list` with every clear that is not [`plain_clear`] drawn as a quad over the scissor box of
/// a `width` × `height` target (the accumulation buffer's part is not wgpu's: frames that use
/// `glAccum` are drawn by the CPU rasteriser).
pub(crate) fn clears_as_quads(list: &DrawList, (width, height): (u32, u32)) -> std::borrow::Cow<'_, DrawList> {
    let needs = |op: &Op| match op {
        Op::Clear { color, depth, stencil, tests, .. } => {
            !plain_clear(color.is_some(), depth.is_some(), stencil.is_some(), tests)
        }
        _ => false,
    };
    if !list.ops.iter().any(needs) {
        return std::borrow::Cow::Borrowed(list);
    }
    let mut out = DrawList {
        vertices: list.vertices.clone(),
        ops: Vec::new(),
        fragments: list.fragments.clone(),
        pixel_copies: list.pixel_copies.clone(),
        unit_tex: list.unit_tex.clone(),
    };
    let whole = [0, 0, width as i32, height as i32];
    for op in &list.ops {
        let Op::Clear { color, depth, stencil, tests, .. } = op else {
            out.ops.push(*op);
            continue;
        };
        if !needs(op) {
            out.ops.push(*op);
            continue;
        }
        let first = out.vertices.len() as u32;
        let z = depth.unwrap_or(0.0).clamp(0.0, 1.0);
        let c = color.unwrap_or([0.0; 4]);
        let corner = |x: f32, y: f32| RasterVertex { clip: [x, y, z, 1.0], color: c, ..RasterVertex::default() };
        let (a, b, cc, d) = (corner(-1.0, -1.0), corner(1.0, -1.0), corner(1.0, 1.0), corner(-1.0, 1.0));
        out.vertices.extend([a, b, cc, a, cc, d]);
        let stencil_test = stencil.map(|s| Stencil {
            func: GL_ALWAYS,
            reference: s & 0xFF,
            value_mask: 0xFF,
            ops: [GL_REPLACE; 3],
            write_mask: tests.stencil_write_mask,
        });
        let quad_tests = FragmentTests {
            scissor: tests.scissor,
            stencil: stencil_test,
            depth_write: depth.is_some() && tests.depth_write,
            color_write: if color.is_some() { tests.color_write } else { [false; 4] },
            logic_op: None,
            ..*tests
        };
        let depth_test = quad_tests.depth_write.then_some(GL_ALWAYS);
        let batch = Batch {
            viewport: whole,
            depth_test,
            topology: Topology::Triangles,
            first,
            count: 6,
            fragment: None,
            blend: None,
            tests: quad_tests,
        };
        out.ops.push(Op::Draw(batch));
    }
    std::borrow::Cow::Owned(out)
}
