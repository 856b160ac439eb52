//! The array draws GL 1.2 and 1.4 add (GL 1.2 spec §2.8 `glDrawRangeElements`, GL 1.4 spec
//! §2.8 `glMultiDrawArrays` and `glMultiDrawElements`; `GL_EXT_draw_range_elements`,
//! `GL_EXT_multi_draw_arrays`; Mesa `main/draw.c`, `main/api_validate.c`): each is
//! `glDrawElements` or `glDrawArrays` once checked, so the vertices, the list records and the
//! current values after the draw are theirs.
//!
//! Measured on Mesa 22.3 (`tests/reference/calls/cases/draws.calls`): `glDrawRangeElements`
//! checks `end < start` (`GL_INVALID_VALUE`) before `glDrawElements`' checks, and draws indices
//! outside the range as given; the multi-draws check the primitive count (`GL_INVALID_VALUE`),
//! then the mode (and the index type) (`GL_INVALID_ENUM`), then each of the first `primcount`
//! counts (`GL_INVALID_VALUE`), before drawing anything. Compiled into a display list, an error
//! is raised when the list runs, as `glDrawElements`' are.

use super::client_memory::ArrayElement;
use super::consts::*;
use super::state_var::{int_limit, StateVar};
use super::types::*;
use super::Gl;

/// `GL_MAX_ELEMENTS_VERTICES` and `GL_MAX_ELEMENTS_INDICES`: the sizes `glDrawRangeElements`
/// recommends, llvmpipe's as Mesa 22.3 answers (a hint only: larger draws work).
pub(crate) const MAX_ELEMENTS: i32 = 3000;

impl Gl {
    /// `glDrawRangeElements(mode, start, end, count, type, indices)`: [`Gl::draw_elements`] with
    /// the caller's promise that every index lies in `start ..= end`. `end < start` →
    /// `GL_INVALID_VALUE` (checked first, inside `begin`/`end` aside); indices outside the range
    /// are drawn, as Mesa draws them.
    pub fn draw_range_elements<T: ArrayElement>(
        &mut self,
        mode: GLenum,
        start: GLuint,
        end: GLuint,
        count: GLsizei,
        type_: GLenum,
        indices: &[T],
    ) {
        if !self.inside_begin_end() && end < start {
            return self.draw_error(GL_INVALID_VALUE);
        }
        self.draw_elements(mode, count, type_, indices);
    }

    /// `glDrawRangeElements(mode, start, end, count, type, (void *)offset)` with indices in
    /// the buffer bound to `GL_ELEMENT_ARRAY_BUFFER`: [`Gl::draw_elements_offset`] after the
    /// range's check.
    pub fn draw_range_elements_offset(
        &mut self,
        mode: GLenum,
        start: GLuint,
        end: GLuint,
        count: GLsizei,
        type_: GLenum,
        offset: usize,
    ) {
        if !self.inside_begin_end() && end < start {
            return self.draw_error(GL_INVALID_VALUE);
        }
        self.draw_elements_offset(mode, count, type_, offset);
    }

    /// `glMultiDrawArrays(mode, first, count, primcount)`: [`Gl::draw_arrays`] of
    /// `(first[i], count[i])` for each `i < primcount`. Errors, before anything is drawn: inside
    /// `begin`/`end` (`GL_INVALID_OPERATION`), a negative `primcount` (`GL_INVALID_VALUE`), the
    /// mode (`GL_INVALID_ENUM`), a negative count (`GL_INVALID_VALUE`); `first` or `count`
    /// shorter than `primcount` → `GL_INVALID_VALUE`.
    pub fn multi_draw_arrays(&mut self, mode: GLenum, first: &[GLint], count: &[GLsizei], primcount: GLsizei) {
        let Some(n) = self.multi_draw_count(mode, primcount, true) else { return };
        let (Some(first), Some(count)) = (first.get(..n), count.get(..n)) else {
            return self.set_error(GL_INVALID_VALUE);
        };
        if count.iter().any(|&c| c < 0) {
            return self.draw_error(GL_INVALID_VALUE);
        }
        for (&first, &count) in first.iter().zip(count) {
            self.draw_arrays(mode, first, count);
        }
    }

    /// `glMultiDrawElements(mode, count, type, indices, primcount)`: [`Gl::draw_elements`] of
    /// `(count[i], indices[i])` for each `i < primcount`. Errors as [`Gl::multi_draw_arrays`],
    /// with the index type checked beside the mode (`GL_INVALID_ENUM`); `count` or `indices`
    /// shorter than `primcount`, or an index array shorter than its count → `GL_INVALID_VALUE`.
    pub fn multi_draw_elements<T: ArrayElement>(
        &mut self,
        mode: GLenum,
        count: &[GLsizei],
        type_: GLenum,
        indices: &[&[T]],
        primcount: GLsizei,
    ) {
        let Some(n) = self.multi_draw_elements_count(mode, count, type_, indices.len(), primcount) else { return };
        for (&count, indices) in count[..n].iter().zip(indices) {
            self.draw_elements(mode, count, type_, indices);
        }
    }

    /// `glMultiDrawElements(mode, count, type, indices, primcount)` with indices in the
    /// buffer bound to `GL_ELEMENT_ARRAY_BUFFER`: `offsets` are the byte offsets C passes as
    /// pointers, each drawn as [`Gl::draw_elements_offset`]. Errors as
    /// [`Gl::multi_draw_elements`].
    pub fn multi_draw_elements_offset(
        &mut self,
        mode: GLenum,
        count: &[GLsizei],
        type_: GLenum,
        offsets: &[usize],
        primcount: GLsizei,
    ) {
        let Some(n) = self.multi_draw_elements_count(mode, count, type_, offsets.len(), primcount) else { return };
        for (&count, &offset) in count[..n].iter().zip(offsets) {
            self.draw_elements_offset(mode, count, type_, offset);
        }
    }

    /// `glMultiDrawElements`'s checks, whatever holds the indices (client slices or buffer
    /// offsets, `pointers` of them): [`Gl::multi_draw_count`]'s, then `count` or the pointers
    /// shorter than `primcount` (`GL_INVALID_VALUE`), then a negative count (`GL_INVALID_VALUE`,
    /// compiled as a draw's error). The number of draws when they pass.
    fn multi_draw_elements_count(
        &mut self,
        mode: GLenum,
        count: &[GLsizei],
        type_: GLenum,
        pointers: usize,
        primcount: GLsizei,
    ) -> Option<usize> {
        let index_type = matches!(type_, GL_UNSIGNED_BYTE | GL_UNSIGNED_SHORT | GL_UNSIGNED_INT);
        let n = self.multi_draw_count(mode, primcount, index_type)?;
        if count.len() < n || pointers < n {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        if count[..n].iter().any(|&c| c < 0) {
            self.draw_error(GL_INVALID_VALUE);
            return None;
        }
        Some(n)
    }

    /// The multi-draws' first checks in Mesa's order: inside `begin`/`end`, the primitive
    /// count, then the mode and the index type (`type_known`: `GL_INVALID_ENUM` beside the
    /// mode); the count as a length when they pass.
    fn multi_draw_count(&mut self, mode: GLenum, primcount: GLsizei, type_known: bool) -> Option<usize> {
        let error = if self.inside_begin_end() {
            GL_INVALID_OPERATION
        } else if primcount < 0 {
            GL_INVALID_VALUE
        } else if mode > GL_POLYGON || !type_known {
            GL_INVALID_ENUM
        } else {
            return usize::try_from(primcount).ok();
        };
        self.draw_error(error);
        None
    }
}

/// The limits' `glGet` rows.
pub(crate) static GET_ROWS: &[StateVar] =
    &[int_limit!(GL_MAX_ELEMENTS_VERTICES, MAX_ELEMENTS), int_limit!(GL_MAX_ELEMENTS_INDICES, MAX_ELEMENTS)];

#[cfg(test)]
mod tests {
    use super::*;

    fn points(gl: &mut Gl) -> Vec<[f32; 2]> {
        let frame = gl.frame().clone();
        frame.iter().flat_map(|(_, v)| v.iter().map(|v| [v.position[0], v.position[1]])).collect()
    }

    #[test]
    fn each_draw_is_its_single_draw() {
        let mut gl = Gl::new(4, 4);
        let positions = super::super::ClientArray::new(&[0.0f32, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 1.0]);
        gl.vertex_pointer(2, GL_FLOAT, 0, &positions);
        gl.enable_client_state(GL_VERTEX_ARRAY);
        gl.draw_range_elements(GL_POINTS, 1, 3, 3, GL_UNSIGNED_BYTE, &[3u8, 2, 1]);
        gl.multi_draw_arrays(GL_POINTS, &[0, 2], &[1, 2], 2);
        gl.multi_draw_elements(GL_POINTS, &[1, 1], GL_UNSIGNED_SHORT, &[&[2u16][..], &[0]], 2);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let p = points(&mut gl);
        assert_eq!(p, [[0.0, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 1.0], [0.0, 0.0]]);
    }

    #[test]
    fn mesa_s_errors_in_mesa_s_order() {
        let mut gl = Gl::new(4, 4);
        for (draw, error) in [
            (
                Box::new(|gl: &mut Gl| gl.draw_range_elements(0x1234, 3, 2, -1, GL_FLOAT, &[0u8]))
                    as Box<dyn Fn(&mut Gl)>,
                GL_INVALID_VALUE,
            ),
            (
                Box::new(|gl: &mut Gl| gl.draw_range_elements(0x1234, 0, 2, 1, GL_UNSIGNED_BYTE, &[0u8])),
                GL_INVALID_ENUM,
            ),
            (Box::new(|gl: &mut Gl| gl.multi_draw_arrays(0x1234, &[0], &[1], -1)), GL_INVALID_VALUE),
            (Box::new(|gl: &mut Gl| gl.multi_draw_arrays(0x1234, &[0], &[-1], 1)), GL_INVALID_ENUM),
            (Box::new(|gl: &mut Gl| gl.multi_draw_arrays(GL_POINTS, &[0, 0], &[1, -1], 2)), GL_INVALID_VALUE),
            (
                Box::new(|gl: &mut Gl| gl.multi_draw_elements(GL_POINTS, &[-1], GL_FLOAT, &[&[0u8][..]], 1)),
                GL_INVALID_ENUM,
            ),
            (
                Box::new(|gl: &mut Gl| gl.multi_draw_elements(GL_POINTS, &[1], GL_UNSIGNED_BYTE, &[&[0u8][..]], 2)),
                GL_INVALID_VALUE,
            ),
        ] {
            draw(&mut gl);
            assert_eq!(gl.get_error(), error);
        }
        assert!(gl.frame().primitives.is_empty(), "nothing drawn");
        let mut v = [0; 2];
        gl.get_integerv(GL_MAX_ELEMENTS_VERTICES, &mut v[..1]);
        gl.get_integerv(GL_MAX_ELEMENTS_INDICES, &mut v[1..]);
        assert_eq!(v, [3000, 3000]);
    }
}
