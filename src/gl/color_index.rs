//! Colour-index calls in an RGBA context (GL 1.1 spec §2.7, §4.2.2, §4.2.3; Mesa 22 in an
//! OSMesa RGBA context, measured): `glIndex*` sets the current index (a vertex attribute, allowed
//! between `begin` and `end`), `glClearIndex` the clear index, `glIndexMask` the index write
//! mask. An RGBA window has no index buffer, so none of them changes the picture; they keep
//! their state and answer `glGet` as Mesa does: `GL_CURRENT_INDEX` (initially 1),
//! `GL_INDEX_CLEAR_VALUE` (0; Mesa stores the index as an unsigned integer, truncated),
//! `GL_INDEX_WRITEMASK` (all ones, which reads back as −1), `GL_INDEX_MODE` false,
//! `GL_RGBA_MODE` true, `GL_INDEX_BITS` 0, `GL_CURRENT_RASTER_INDEX` 1 (Mesa does not latch the
//! index into the raster position of an RGBA context).

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// The colour-index state: the current index (`GL_CURRENT_BIT`), the clear index and the write
/// mask (`GL_COLOR_BUFFER_BIT`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ColorIndex {
    pub current: f32,
    pub clear: GLuint,
    pub mask: GLuint,
}

impl Default for ColorIndex {
    fn default() -> Self {
        Self { current: 1.0, clear: 0, mask: !0 }
    }
}

/// C's `(GLuint) c` as x86 compiles it (a conversion to a 64-bit integer, low 32 bits kept; out of
/// range gives 0): Mesa's `glClearIndex` (measured: −2 reads back as −2, 10¹⁰ as 1410065408).
fn to_uint(c: f32) -> GLuint {
    if c.is_finite() && c.abs() < 9.2e18 {
        c as i64 as GLuint
    } else {
        0
    }
}

/// A colour-index call as a display list holds it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum ColorIndexCall {
    /// `glIndex*`.
    Index(GLfloat),
    /// `glClearIndex`.
    ClearIndex(GLfloat),
    /// `glIndexMask`.
    IndexMask(GLuint),
}

impl Gl {
    /// Replays a listed colour-index call.
    pub(crate) fn replay_color_index_call(&mut self, call: ColorIndexCall) {
        match call {
            ColorIndexCall::Index(c) => self.indexf(c),
            ColorIndexCall::ClearIndex(c) => self.replay_clear_index(c),
            ColorIndexCall::IndexMask(mask) => self.index_mask(mask),
        }
    }

    /// `glIndexf`: the current colour index. Allowed between `begin` and `end`; compiled into
    /// display lists.
    pub fn indexf(&mut self, c: GLfloat) {
        if self.compiled(|| ListCommand::ColorIndex(ColorIndexCall::Index(c))) {
            return;
        }
        self.server.color_index.current = c;
    }

    /// `glIndexd`: as [`Gl::indexf`] (stored as a float, as Mesa does).
    pub fn indexd(&mut self, c: GLdouble) {
        self.indexf(c as GLfloat);
    }

    /// `glIndexi`: as [`Gl::indexf`].
    pub fn indexi(&mut self, c: GLint) {
        self.indexf(c as GLfloat);
    }

    /// `glIndexs`: as [`Gl::indexf`].
    pub fn indexs(&mut self, c: GLshort) {
        self.indexf(GLfloat::from(c));
    }

    /// `glIndexub`: as [`Gl::indexf`] (0 ..= 255, not normalised).
    pub fn indexub(&mut self, c: GLubyte) {
        self.indexf(GLfloat::from(c));
    }

    /// `glIndexfv`: the first value (an empty slice → `GL_INVALID_VALUE`).
    pub fn indexfv(&mut self, c: &[GLfloat]) {
        if let Some([c]) = self.first::<1, _>(c) {
            self.indexf(c);
        }
    }

    /// `glIndexdv`: the first value.
    pub fn indexdv(&mut self, c: &[GLdouble]) {
        if let Some([c]) = self.first::<1, _>(c) {
            self.indexd(c);
        }
    }

    /// `glIndexiv`: the first value.
    pub fn indexiv(&mut self, c: &[GLint]) {
        if let Some([c]) = self.first::<1, _>(c) {
            self.indexi(c);
        }
    }

    /// `glIndexsv`: the first value.
    pub fn indexsv(&mut self, c: &[GLshort]) {
        if let Some([c]) = self.first::<1, _>(c) {
            self.indexs(c);
        }
    }

    /// `glIndexubv`: the first value.
    pub fn indexubv(&mut self, c: &[GLubyte]) {
        if let Some([c]) = self.first::<1, _>(c) {
            self.indexub(c);
        }
    }

    /// `glClearIndex`: the index `glClear` would write into an index buffer (an RGBA window has
    /// none: the picture does not change). Stored as Mesa stores it, as an unsigned integer.
    /// Inside `begin`/`end` → `GL_INVALID_OPERATION`. Compiled into display lists.
    pub fn clear_index(&mut self, c: GLfloat) {
        if self.compiled_state_call(|| ListCommand::ColorIndex(ColorIndexCall::ClearIndex(c))) {
            return;
        }
        self.server.color_index.clear = to_uint(c);
    }

    /// A `glClearIndex(c)` replayed from a display list as Mesa 22 replays it: its list node
    /// keeps the float and the replay reads the node's bits as an unsigned integer, so 43.0
    /// becomes 1110179840 (measured; Mesa `dlist.c`, `OPCODE_CLEAR_INDEX`).
    pub(crate) fn replay_clear_index(&mut self, c: GLfloat) {
        self.clear_index(c.to_bits() as GLfloat);
    }

    /// `glIndexMask`: which bits of an index buffer are written (none here: the window is
    /// RGBA). Inside `begin`/`end` → `GL_INVALID_OPERATION`. Compiled into display lists.
    pub fn index_mask(&mut self, mask: GLuint) {
        if self.compiled_state_call(|| ListCommand::ColorIndex(ColorIndexCall::IndexMask(mask))) {
            return;
        }
        self.server.color_index.mask = mask;
    }
}

/// `glGet` of the colour-index state (see the module docs; the modes and `GL_INDEX_BITS` are
/// limits in `get/table.rs`). The clear value and mask read as signed (Mesa's `TYPE_INT`).
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_CURRENT_INDEX, 1, Kind::Float, |gl, o| o[0] = f64::from(gl.server.color_index.current)),
    row(GL_CURRENT_RASTER_INDEX, 1, Kind::Float, |_, o| o[0] = 1.0),
    row(GL_INDEX_CLEAR_VALUE, 1, Kind::Float, |gl, o| o[0] = f64::from(gl.server.color_index.clear as GLint)),
    row(GL_INDEX_WRITEMASK, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.server.color_index.mask as GLint)),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn index_state_reads_back_as_mesas() {
        let mut gl = Gl::new(4, 4);
        let mut v = [0i32; 1];
        gl.get_integerv(GL_INDEX_WRITEMASK, &mut v);
        assert_eq!(v, [-1]);
        gl.begin(GL_POINTS);
        gl.indexf(3.7);
        gl.clear_index(3.0);
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION, "glClearIndex, not glIndex, is refused inside");
        gl.get_integerv(GL_CURRENT_INDEX, &mut v);
        assert_eq!(v, [4]);
        gl.clear_index(5.7);
        gl.get_integerv(GL_INDEX_CLEAR_VALUE, &mut v);
        assert_eq!(v, [5]);
        gl.clear_index(-2.0);
        gl.get_integerv(GL_INDEX_CLEAR_VALUE, &mut v);
        assert_eq!(v, [-2]);
        gl.new_list(1, GL_COMPILE);
        gl.clear_index(43.0);
        gl.index_mask(44);
        gl.end_list();
        gl.call_list(1);
        gl.get_integerv(GL_INDEX_CLEAR_VALUE, &mut v);
        assert_eq!(v, [1110179840], "Mesa's list replay reads the float's bits");
        gl.get_integerv(GL_INDEX_WRITEMASK, &mut v);
        assert_eq!(v, [44]);
        gl.indexfv(&[]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    }
}
