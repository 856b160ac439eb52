//! `glHint` (GL 1.1 spec §5.6): the quality a program asks for. gleval draws one way whatever
//! the hint (as GL allows: hints are only requests), but it keeps them, answers `glGet` with
//! them, saves them with `GL_HINT_BIT` and compiles them into lists, with Mesa's errors
//! (checked against OSMesa: an unknown mode or target → `GL_INVALID_ENUM`).

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{put_enum, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// The targets `glHint` takes, in the order [`Hints`] keeps them.
const TARGETS: [GLenum; 7] = [
    GL_PERSPECTIVE_CORRECTION_HINT,
    GL_POINT_SMOOTH_HINT,
    GL_LINE_SMOOTH_HINT,
    GL_POLYGON_SMOOTH_HINT,
    GL_FOG_HINT,
    GL_GENERATE_MIPMAP_HINT,
    GL_TEXTURE_COMPRESSION_HINT,
];

/// The current hints (all initially `GL_DONT_CARE`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Hints([GLenum; 7]);

impl Default for Hints {
    fn default() -> Self {
        Self([GL_DONT_CARE; 7])
    }
}

impl Hints {
    /// The hint of `target`, if `target` is one.
    pub(crate) fn get(&self, target: GLenum) -> Option<GLenum> {
        TARGETS.iter().position(|&t| t == target).map(|i| self.0[i])
    }
}

impl Gl {
    /// `glHint(target, mode)`: `mode` is `GL_FASTEST`, `GL_NICEST` or `GL_DONT_CARE` for
    /// `GL_PERSPECTIVE_CORRECTION_HINT`, `GL_POINT_SMOOTH_HINT`, `GL_LINE_SMOOTH_HINT`,
    /// `GL_POLYGON_SMOOTH_HINT`, `GL_FOG_HINT`, GL 1.4's `GL_GENERATE_MIPMAP_HINT` or GL 1.3's
    /// `GL_TEXTURE_COMPRESSION_HINT`; recorded,
    /// with no effect on the picture.
    pub fn hint(&mut self, target: GLenum, mode: GLenum) {
        if self.compiled_state_call(|| ListCommand::Hint(target, mode)) {
            return;
        }
        let known_mode = matches!(mode, GL_FASTEST | GL_NICEST | GL_DONT_CARE);
        match TARGETS.iter().position(|&t| t == target) {
            Some(i) if known_mode => self.server.hints.0[i] = mode,
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }
}

/// `glGet` of a hint (GL 1.1 table 6.16).
macro_rules! hint_row {
    ($target:expr) => {
        row($target, 1, Kind::Int, |gl, o| put_enum(o, gl.server.hints.get($target).unwrap_or(0)))
    };
}

/// The hints' `glGet` rows.
pub(crate) static GET_ROWS: &[StateVar] = &[
    hint_row!(GL_PERSPECTIVE_CORRECTION_HINT),
    hint_row!(GL_POINT_SMOOTH_HINT),
    hint_row!(GL_LINE_SMOOTH_HINT),
    hint_row!(GL_POLYGON_SMOOTH_HINT),
    hint_row!(GL_FOG_HINT),
    hint_row!(GL_GENERATE_MIPMAP_HINT),
    hint_row!(GL_TEXTURE_COMPRESSION_HINT),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hints_as_mesa_keeps_them() {
        // Each expectation printed by the same calls on OSMesa (Mesa 22.3).
        let mut gl = Gl::new(8, 8);
        let mut v = [0];
        gl.get_integerv(GL_PERSPECTIVE_CORRECTION_HINT, &mut v);
        assert_eq!(v[0] as GLenum, GL_DONT_CARE);
        gl.hint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
        gl.get_integerv(GL_PERSPECTIVE_CORRECTION_HINT, &mut v);
        assert_eq!(v[0] as GLenum, GL_NICEST);
        for (target, mode) in [(GL_FOG_HINT, 0x1234), (0x1234, GL_NICEST), (0x1234, 0x1234)] {
            gl.hint(target, mode);
            assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        }
        gl.begin(GL_POINTS);
        gl.hint(GL_FOG_HINT, GL_NICEST);
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.push_attrib(GL_HINT_BIT);
        gl.hint(GL_PERSPECTIVE_CORRECTION_HINT, GL_FASTEST);
        gl.pop_attrib();
        gl.get_integerv(GL_PERSPECTIVE_CORRECTION_HINT, &mut v);
        assert_eq!(v[0] as GLenum, GL_NICEST);
        let list = gl.gen_lists(1);
        gl.new_list(list, GL_COMPILE);
        gl.hint(GL_FOG_HINT, GL_NICEST);
        gl.end_list();
        gl.get_integerv(GL_FOG_HINT, &mut v);
        assert_eq!(v[0] as GLenum, GL_DONT_CARE);
        gl.call_list(list);
        gl.get_integerv(GL_FOG_HINT, &mut v);
        assert_eq!(v[0] as GLenum, GL_NICEST);
    }
}
