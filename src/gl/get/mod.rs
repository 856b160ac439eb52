//! `glGetBooleanv`, `glGetIntegerv`, `glGetFloatv`, `glGetDoublev` (GL 1.1 spec §6.1.2):
//! every variant reads the one table of state variables in [`table`] (name, count, how Mesa
//! stores it, where it lives; rows kept beside the state they read), then the capabilities
//! `glIsEnabled` knows; each converts as Mesa 22.3's `main/get.c` does.

mod table;

use super::consts::*;
use super::state_var::{Kind, StateVar};
use super::types::*;
use super::Gl;
use table::rows;

/// The most values one `glGet` name has (a matrix).
pub(crate) const MAX_VALUES: usize = 16;

/// One state variable's answer: its values and how they convert.
struct Answer {
    values: [f64; MAX_VALUES],
    count: usize,
    kind: Kind,
}

impl Gl {
    /// `glGetIntegerv`: the values of `pname` (GL 1.1 tables 6.3–6.20). Integers and enums as
    /// they are; floats rounded to the nearest, halves away from zero; colours, normals, the
    /// depth range and matrices map [−1, 1] linearly onto [−2³¹ + 1, 2³¹ − 1], truncated (GL 1.1
    /// §6.1.2; Mesa `FLOAT_TO_INT`, which Mesa also applies to matrices). An unknown name →
    /// `GL_INVALID_ENUM`, inside `begin`/`end` → `GL_INVALID_OPERATION`, a slice shorter than
    /// the answer → `GL_INVALID_VALUE`: nothing written.
    pub fn get_integerv(&mut self, pname: GLenum, params: &mut [GLint]) {
        if let Some(a) = self.answer(pname, params.len()) {
            for (out, v) in params.iter_mut().zip(&a.values[..a.count]) {
                *out = a.kind.to_int(*v);
            }
        }
    }

    /// `glGetFloatv`: as [`Gl::get_integerv`], every value as a float.
    pub fn get_floatv(&mut self, pname: GLenum, params: &mut [GLfloat]) {
        if let Some(a) = self.answer(pname, params.len()) {
            for (out, v) in params.iter_mut().zip(&a.values[..a.count]) {
                *out = match a.kind {
                    // Mesa's `BOOLEAN_TO_FLOAT`: a flag stored as the byte given reads 1.
                    Kind::Bool => f32::from(u8::from(*v != 0.0)),
                    _ => *v as GLfloat,
                };
            }
        }
    }

    /// `glGetDoublev`: as [`Gl::get_integerv`], every value as a double.
    pub fn get_doublev(&mut self, pname: GLenum, params: &mut [GLdouble]) {
        if let Some(a) = self.answer(pname, params.len()) {
            params[..a.count].copy_from_slice(&a.values[..a.count]);
        }
    }

    /// `glGetBooleanv`: as [`Gl::get_integerv`], `GL_TRUE` for every value other than 0 (GL 1.1
    /// §6.1.2; a NaN is true, as in Mesa); a flag as it is kept.
    pub fn get_booleanv(&mut self, pname: GLenum, params: &mut [GLboolean]) {
        if let Some(a) = self.answer(pname, params.len()) {
            for (out, v) in params.iter_mut().zip(&a.values[..a.count]) {
                *out = match a.kind {
                    // Mesa copies a flag's byte as it was given (`glSampleCoverage(v, 7)`
                    // reads back 7).
                    Kind::Bool => *v as GLboolean,
                    _ if *v != 0.0 => GL_TRUE,
                    _ => GL_FALSE,
                };
            }
        }
    }

    /// How many values `glGet*v(pname)` writes (1 for a name it does not answer, where it
    /// writes none and sets `GL_INVALID_ENUM`): what a binding that has only a pointer may
    /// hand `get_*v` as the slice's length.
    #[must_use]
    pub fn get_len(&self, pname: GLenum) -> usize {
        self.lookup(pname).map_or(1, |a| a.count)
    }

    /// Mesa's checks in its order (inside `begin`/`end`, then the name), then the slice's room.
    fn answer(&mut self, pname: GLenum, room: usize) -> Option<Answer> {
        if self.reject_inside_begin_end() {
            return None;
        }
        let Some(a) = self.lookup(pname) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        if super::multitexture::UNIT_COORD_NAMES.contains(&pname)
            && self.active_unit() >= super::units::MAX_TEXTURE_UNITS
        {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        if room < a.count {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        if table::flushes_current(pname) {
            self.flush_current();
        }
        Some(a)
    }

    /// The name's row, else the capability of that name.
    fn lookup(&self, pname: GLenum) -> Option<Answer> {
        let mut values = [0.0; MAX_VALUES];
        if let Some(StateVar { count, kind, read, .. }) = rows().find(|v| v.name == pname) {
            read(self, &mut values);
            return Some(Answer { values, count: *count, kind: *kind });
        }
        if super::units::UNIT_ENABLES.contains(&pname) {
            values[0] = f64::from(u8::from(self.active_unit_enabled(pname)));
            return Some(Answer { values, count: 1, kind: Kind::Bool });
        }
        if self.is_capability(pname) {
            values[0] = f64::from(u8::from(self.capability(pname)));
            return Some(Answer { values, count: 1, kind: Kind::Bool });
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_name_has_one_row_and_is_no_capability() {
        let gl = Gl::new(4, 4);
        let mut names: Vec<GLenum> = rows().map(|r| r.name).collect();
        for r in rows() {
            // A list as long as no compressed format is listed (`texture/compressed.rs`) has
            // no value; every other name has one or more.
            let empty_list = r.name == GL_COMPRESSED_TEXTURE_FORMATS;
            assert!((r.count >= 1 || empty_list) && r.count <= MAX_VALUES, "{:#x}", r.name);
            assert!(!gl.is_capability(r.name), "{:#x} is a row and a capability", r.name);
        }
        let all = names.len();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), all, "a name with two rows");
    }
}
