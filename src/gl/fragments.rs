//! What a draw hands the rasterisers' per-fragment stages (GL 1.1 spec §4.1–4.2): the
//! [`FragmentTests`] a recorded primitive, clear or accumulation carries (the scissor box, the
//! stencil test, the write masks, the logic op, the colour buffers written), put together from
//! the groups that own the values (`scissor.rs`, `stencil.rs`, `depth.rs`, `color_buffer.rs`);
//! and the framebuffer's shape ([`BufferConfig`]: which buffers the drawable has), with its
//! `glGet` rows.

use super::consts::*;
use super::state_var::{int_limit, limit, put_flag, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// What buffers a context's framebuffer has besides colour and depth, and whether it is double
/// buffered: what `glutInitDisplayMode` asked of freeglut (measured on Mesa 22.3: 8 stencil bits
/// only with `GLUT_STENCIL`, 16 accumulation bits a channel only with `GLUT_ACCUM`), or what
/// `OSMesaCreateContextExt` was given.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BufferConfig {
    /// Bits of the stencil buffer: 0 (none) or 8.
    pub stencil_bits: u8,
    /// Bits a channel of the accumulation buffer: 0 (none) or 16 (Mesa's `RGBA_SNORM16`).
    pub accum_bits: u8,
    /// A back buffer besides the front one (`GLUT_DOUBLE`).
    pub double: bool,
}

impl BufferConfig {
    /// What freeglut on Mesa 22.3 gives for `glutInitDisplayMode(mode)` (measured under Xvfb
    /// with llvmpipe): 8 stencil bits with `GLUT_STENCIL` (32), 16 accumulation bits with
    /// `GLUT_ACCUM` (4), none without; double buffering with `GLUT_DOUBLE` (2).
    #[must_use]
    pub fn of_display_mode(mode: u32) -> Self {
        let has = |bit: u32| mode & bit != 0;
        Self { stencil_bits: if has(32) { 8 } else { 0 }, accum_bits: if has(4) { 16 } else { 0 }, double: has(2) }
    }
}

impl Default for BufferConfig {
    /// A single-buffered context with a stencil and an accumulation buffer: what a [`Gl::new`]
    /// context has, so that a Rust program gets every buffer without asking.
    fn default() -> Self {
        Self { stencil_bits: 8, accum_bits: 16, double: false }
    }
}

/// `glStencilFunc` and `glStencilOp` (GL 1.1 §4.1.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Stencil {
    /// `GL_NEVER` .. `GL_ALWAYS`.
    pub func: GLenum,
    /// The reference value as given (Mesa keeps it unclamped; the test clamps it to the
    /// buffer's range).
    pub reference: GLint,
    /// The mask ANDed with both sides of the comparison.
    pub value_mask: GLuint,
    /// The operations on stencil failure, depth failure and depth pass.
    pub ops: [GLenum; 3],
    /// `glStencilMask`.
    pub write_mask: GLuint,
}

impl Default for Stencil {
    /// GL's initial state; both masks start as 0xFF in Mesa 22.3 (measured, with or without a
    /// stencil buffer).
    fn default() -> Self {
        Self { func: GL_ALWAYS, reference: 0, value_mask: 0xFF, ops: [GL_KEEP; 3], write_mask: 0xFF }
    }
}

/// The colour buffers a draw or clear writes: bit 0 the front, bit 1 the back (GL 1.1 §4.2.1).
pub const FRONT_BUFFER: u8 = 1;
/// See [`FRONT_BUFFER`].
pub const BACK_BUFFER: u8 = 2;

/// The per-fragment state a primitive, a clear or an accumulation is drawn with.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FragmentTests {
    /// The scissor box (x, y, width, height, origin bottom-left) while `GL_SCISSOR_TEST` is on.
    pub scissor: Option<[i32; 4]>,
    /// The stencil test while `GL_STENCIL_TEST` is on and the framebuffer has a stencil buffer.
    pub stencil: Option<Stencil>,
    /// `glStencilMask` (clears write through it whether or not the test is on).
    pub stencil_write_mask: GLuint,
    /// `glDepthMask`.
    pub depth_write: bool,
    /// `glColorMask`: red, green, blue, alpha.
    pub color_write: [bool; 4],
    /// The logic op while `GL_COLOR_LOGIC_OP` is on (it replaces blending, GL 1.1 §4.1.7).
    pub logic_op: Option<GLenum>,
    /// The colour buffers written: [`FRONT_BUFFER`], [`BACK_BUFFER`], both or none. A
    /// single-buffered context has one buffer, which both names reach.
    pub draw_buffers: u8,
}

impl Default for FragmentTests {
    fn default() -> Self {
        Self {
            scissor: None,
            stencil: None,
            stencil_write_mask: 0xFF,
            depth_write: true,
            color_write: [true; 4],
            logic_op: None,
            draw_buffers: FRONT_BUFFER,
        }
    }
}

impl Gl {
    /// The framebuffer's buffers (see [`BufferConfig`]).
    #[must_use]
    pub fn buffer_config(&self) -> BufferConfig {
        self.server.framebuffer
    }

    /// Gives the context the buffers of `config` (what GLUT's display mode or OSMesa's
    /// creation asked for); the draw and read buffers become GL's initial ones for it (the back
    /// buffer of a double-buffered window, else the front).
    pub fn set_buffer_config(&mut self, config: BufferConfig) {
        self.server.framebuffer = config;
        let initial = if config.double { GL_BACK } else { GL_FRONT };
        self.server.color_buffer.draw_buffer = initial;
        self.server.pixel_state.mode.read_buffer = initial;
        self.touch_state();
    }

    /// The per-fragment state primitives, clears and accumulations are drawn with now.
    pub(crate) fn fragment_tests(&self) -> FragmentTests {
        let (stencil, colors) = (&self.server.stencil.test, &self.server.color_buffer);
        let has_stencil = self.server.framebuffer.stencil_bits > 0;
        FragmentTests {
            scissor: self.capability(GL_SCISSOR_TEST).then_some(self.server.scissor),
            stencil: (has_stencil && self.capability(GL_STENCIL_TEST)).then_some(*stencil),
            stencil_write_mask: stencil.write_mask,
            depth_write: self.server.depth.write,
            color_write: colors.color_write,
            logic_op: self.capability(GL_COLOR_LOGIC_OP).then_some(colors.logic_op),
            draw_buffers: self.buffers_of(colors.draw_buffer),
        }
    }

    /// The largest stencil value, 2^bits − 1 (0 without a stencil buffer).
    pub(crate) fn stencil_max(&self) -> u32 {
        (1u32 << self.server.framebuffer.stencil_bits) - 1
    }
}

/// The framebuffer's `glGet` rows (GL 1.1 table 6.19): what buffers it has.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_DOUBLEBUFFER, 1, Kind::Bool, |gl, o| put_flag(o, gl.server.framebuffer.double)),
    row(GL_STENCIL_BITS, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.server.framebuffer.stencil_bits)),
    row(GL_ACCUM_RED_BITS, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.server.framebuffer.accum_bits)),
    row(GL_ACCUM_GREEN_BITS, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.server.framebuffer.accum_bits)),
    row(GL_ACCUM_BLUE_BITS, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.server.framebuffer.accum_bits)),
    row(GL_ACCUM_ALPHA_BITS, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.server.framebuffer.accum_bits)),
    int_limit!(GL_SUBPIXEL_BITS, 8),
    int_limit!(GL_AUX_BUFFERS, 0),
    StateVar { kind: Kind::Bool, ..limit!(GL_RGBA_MODE, 1) },
    StateVar { kind: Kind::Bool, ..limit!(GL_INDEX_MODE, 0) },
    StateVar { kind: Kind::Bool, ..limit!(GL_STEREO, 0) },
    int_limit!(GL_RED_BITS, 8),
    int_limit!(GL_GREEN_BITS, 8),
    int_limit!(GL_BLUE_BITS, 8),
    int_limit!(GL_ALPHA_BITS, 8),
    int_limit!(GL_INDEX_BITS, 0),
    int_limit!(GL_DEPTH_BITS, 24),
];

#[cfg(test)]
mod tests {
    use super::*;

    fn int(gl: &mut Gl, pname: GLenum) -> Vec<GLint> {
        let mut v = vec![0; gl.get_len(pname)];
        gl.get_integerv(pname, &mut v);
        v
    }

    #[test]
    fn initial_values_are_gl_s() {
        let mut gl = Gl::new(30, 20);
        assert_eq!(int(&mut gl, GL_SCISSOR_BOX), [0, 0, 30, 20]);
        assert_eq!(int(&mut gl, GL_COLOR_WRITEMASK), [1, 1, 1, 1]);
        assert_eq!(int(&mut gl, GL_STENCIL_VALUE_MASK), [255]);
        assert_eq!(int(&mut gl, GL_STENCIL_FUNC), [GL_ALWAYS as i32]);
        assert_eq!(int(&mut gl, GL_LOGIC_OP_MODE), [GL_COPY as i32]);
        assert_eq!(int(&mut gl, GL_DRAW_BUFFER), [GL_FRONT as i32]);
        gl.set_buffer_config(BufferConfig { double: true, ..BufferConfig::default() });
        assert_eq!(int(&mut gl, GL_DRAW_BUFFER), [GL_BACK as i32]);
        assert_eq!(int(&mut gl, GL_READ_BUFFER), [GL_BACK as i32]);
        assert_eq!(int(&mut gl, GL_ACCUM_RED_BITS), [16]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn push_and_pop_by_group() {
        let mut gl = Gl::new(8, 8);
        gl.push_attrib(GL_STENCIL_BUFFER_BIT | GL_SCISSOR_BIT);
        gl.stencil_func(GL_LESS, 3, 7);
        gl.enable(GL_STENCIL_TEST);
        gl.scissor(1, 2, 3, 4);
        gl.enable(GL_SCISSOR_TEST);
        gl.depth_mask(GL_FALSE);
        gl.pop_attrib();
        assert_eq!(int(&mut gl, GL_STENCIL_FUNC), [GL_ALWAYS as i32]);
        assert_eq!(int(&mut gl, GL_SCISSOR_BOX), [0, 0, 8, 8]);
        assert_eq!((gl.is_enabled(GL_STENCIL_TEST), gl.is_enabled(GL_SCISSOR_TEST)), (GL_FALSE, GL_FALSE));
        assert_eq!(int(&mut gl, GL_DEPTH_WRITEMASK), [0], "not in the groups pushed");
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }
}
