//! Selection mode (GL 1.1 §5.2; Mesa 22.3 `main/feedback.c`): `glSelectBuffer`, the name
//! stack (`glInitNames`, `glLoadName`, `glPushName`, `glPopName`) and `glRenderMode(GL_SELECT)`,
//! how a program asks which named objects would draw inside the view volume (picking, with
//! `gluPickMatrix`).
//!
//! In selection mode nothing is drawn. Every primitive that survives clipping and culling (the
//! primitives feedback would report, `feedback_prims`) sets the hit flag and widens the hit's
//! window-depth range. When the name stack changes, and when the program leaves selection mode,
//! a set hit flag writes a hit record: the stack depth, the minimum and maximum depth scaled to
//! 0 .. 2³² − 1, the names. Mesa scales with a float 2³² and converts as the machine does, so a
//! depth of exactly 1 wraps to 0 (measured, `tests/reference/calls/cases/select.calls`); so
//! does gleval. A buffer too small keeps the values that fit, and `glRenderMode` returns −1.
//! Read the records with [`Gl::select_hits`] (or the raw values with [`Gl::select_values`])
//! after `render_mode` leaves selection mode.

use super::consts::*;
use super::feedback_prims::FeedbackPrimitive;
use super::lists::ListCommand;
use super::state_var::{int_limit, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// Mesa's `MAX_NAME_STACK_DEPTH`.
pub(crate) const MAX_NAME_STACK_DEPTH: usize = 64;

/// The selection state of a context.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Selection {
    /// `glSelectBuffer`'s size in values (0: no buffer).
    size: usize,
    names: Vec<GLuint>,
    /// The hit flag with the hit's minimum and maximum window depth.
    hit: Option<(f32, f32)>,
    /// The values written in this pass, at most `size`, and how many were wanted.
    written: Vec<GLuint>,
    wanted: usize,
    hits: GLint,
    /// Frame commands recorded before the primitives not yet tested for hits.
    start: usize,
    /// What the last pass wrote.
    values: Vec<GLuint>,
}

/// One hit record of a selection pass: the window depths of the hit's primitives, scaled to
/// 0 .. 2³² − 1, and the name stack when it was written (bottom first).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SelectHit<'a> {
    /// The smallest window depth of the hit's primitives.
    pub z_min: GLuint,
    /// The largest.
    pub z_max: GLuint,
    /// The name stack, bottom first.
    pub names: &'a [GLuint],
}

/// The complete records of `values` (name count, minimum and maximum depth, the names, record
/// after record); a record cut short at the end is left out.
fn hit_records(values: &[GLuint]) -> impl Iterator<Item = SelectHit<'_>> {
    let mut rest = values;
    std::iter::from_fn(move || {
        let (&[count, z_min, z_max], after) = rest.split_first_chunk::<3>()?;
        let names = after.get(..usize::try_from(count).ok()?)?;
        rest = &after[names.len()..];
        Some(SelectHit { z_min, z_max, names })
    })
}

impl Selection {
    fn write(&mut self, value: GLuint) {
        if self.wanted < self.size {
            self.written.push(value);
        }
        self.wanted += 1;
    }

    /// Writes the hit record of a set hit flag (Mesa's `write_hit_record`).
    fn write_hit_record(&mut self) {
        let Some((min, max)) = self.hit.take() else { return };
        // Mesa: (GLuint) (zmin * (GLfloat) ~0u), the float being 2^32.
        let scale = |z: f32| (z * 4_294_967_296.0f32) as u64 as u32;
        self.write(self.names.len() as GLuint);
        self.write(scale(min));
        self.write(scale(max));
        for i in 0..self.names.len() {
            self.write(self.names[i]);
        }
        self.hits += 1;
    }
}

/// The name stack's calls as a display list holds them.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum NameCall {
    InitNames,
    LoadName(GLuint),
    PushName(GLuint),
    PopName,
}

impl Gl {
    /// Replays a listed call of the group.
    pub(crate) fn replay_name_call(&mut self, call: &NameCall) {
        use NameCall as C;
        match call {
            C::InitNames => self.init_names(),
            C::LoadName(name) => self.load_name(*name),
            C::PushName(name) => self.push_name(*name),
            C::PopName => self.pop_name(),
        }
    }
}

impl Gl {
    /// The error `glSelectBuffer(size)` raises now, in Mesa's order (inside `begin`/`end`, a
    /// negative size, selection mode), `None` when it takes the buffer: what a binding that
    /// keeps the caller's buffer asks before it does.
    #[must_use]
    pub fn select_buffer_error(&self, size: GLsizei) -> Option<GLenum> {
        if self.inside_begin_end() {
            Some(GL_INVALID_OPERATION)
        } else if size < 0 {
            Some(GL_INVALID_VALUE)
        } else if self.render_mode_value() == GL_SELECT {
            Some(GL_INVALID_OPERATION)
        } else {
            None
        }
    }

    /// `glSelectBuffer(size, buffer)`: selection mode writes up to `size` values, read with
    /// [`Gl::select_values`]. Errors: a negative size (`GL_INVALID_VALUE`), in selection mode
    /// or inside `begin`/`end` (`GL_INVALID_OPERATION`). Not compiled into lists.
    pub fn select_buffer(&mut self, size: GLsizei) {
        if let Some(error) = self.select_buffer_error(size) {
            return self.set_error(error);
        }
        let s = &mut self.client.select;
        let size = size as usize;
        (s.size, s.hit, s.wanted) = (size, None, 0);
        s.written.clear();
    }

    /// The size the last successful `select_buffer` set: a binding that keeps the caller's
    /// buffer knows from it whether the call took.
    #[must_use]
    pub fn select_buffer_size(&self) -> usize {
        self.client.select.size
    }

    /// The values the last selection pass wrote (at most the buffer's size): hit records of
    /// (name count, minimum depth, maximum depth, names…).
    #[must_use]
    pub fn select_values(&self) -> &[GLuint] {
        &self.client.select.values
    }

    /// The complete hit records of the last selection pass, in the order written
    /// ([`Gl::select_values`] read as GL 1.1 §5.2 lays them out); a record a buffer too small
    /// cut short is left out.
    pub fn select_hits(&self) -> impl Iterator<Item = SelectHit<'_>> {
        hit_records(&self.client.select.values)
    }

    /// Entering selection mode (from `render_mode`): without a buffer → `GL_INVALID_OPERATION`,
    /// the mode changes all the same (as Mesa).
    pub(crate) fn start_select(&mut self) {
        if self.client.select.size == 0 {
            self.set_error(GL_INVALID_OPERATION);
        }
        self.evaluate_pending_meshes();
        self.client.select.start = self.recorder.frame.commands.len();
    }

    /// Leaving selection mode: the last hit record, and the number of hits (−1 when the buffer
    /// overflowed); the name stack empties.
    pub(crate) fn finish_select(&mut self) -> GLint {
        self.gather_hits();
        let s = &mut self.client.select;
        s.write_hit_record();
        let result = if s.wanted > s.size { -1 } else { s.hits };
        s.values = std::mem::take(&mut s.written);
        (s.wanted, s.hits) = (0, 0);
        s.names.clear();
        result
    }

    /// Tests the primitives drawn since the last time for hits, and takes them out of the frame.
    fn gather_hits(&mut self) {
        self.evaluate_pending_meshes();
        let start = self.client.select.start.min(self.recorder.frame.commands.len());
        let commands: Vec<_> = self.recorder.frame.commands.drain(start..).collect();
        for command in &commands {
            for prim in self.command_primitives(command) {
                let vertices = match &prim {
                    FeedbackPrimitive::Point(v) => vec![*v],
                    FeedbackPrimitive::Line(a, b, _) => vec![*a, *b],
                    FeedbackPrimitive::Polygon(vs) => vs.clone(),
                };
                for v in vertices {
                    let z = v.window[2];
                    let (min, max) = self.client.select.hit.unwrap_or((1.0, 0.0));
                    self.client.select.hit = Some((min.min(z), max.max(z)));
                }
            }
        }
    }

    /// The common start of the name-stack calls: compiled, rejected inside `begin`/`end`,
    /// ignored outside selection mode; else the hits so far are gathered. True to go on.
    fn name_call(&mut self, command: ListCommand) -> bool {
        if self.compiled_state_call(|| command) {
            return false;
        }
        if self.render_mode_value() != GL_SELECT {
            return false;
        }
        self.gather_hits();
        true
    }

    /// `glInitNames`: empties the name stack (writing the pending hit record).
    pub fn init_names(&mut self) {
        if self.name_call(ListCommand::Names(NameCall::InitNames)) {
            self.client.select.write_hit_record();
            self.client.select.names.clear();
        }
    }

    /// `glLoadName(name)`: replaces the top of the name stack; an empty stack →
    /// `GL_INVALID_OPERATION`.
    pub fn load_name(&mut self, name: GLuint) {
        if !self.name_call(ListCommand::Names(NameCall::LoadName(name))) {
            return;
        }
        if self.client.select.names.is_empty() {
            return self.set_error(GL_INVALID_OPERATION);
        }
        self.client.select.write_hit_record();
        if let Some(top) = self.client.select.names.last_mut() {
            *top = name;
        }
    }

    /// `glPushName(name)`: a full stack (64 names) → `GL_STACK_OVERFLOW`.
    pub fn push_name(&mut self, name: GLuint) {
        if !self.name_call(ListCommand::Names(NameCall::PushName(name))) {
            return;
        }
        self.client.select.write_hit_record();
        if self.client.select.names.len() >= MAX_NAME_STACK_DEPTH {
            return self.set_error(GL_STACK_OVERFLOW);
        }
        self.client.select.names.push(name);
    }

    /// `glPopName`: an empty stack → `GL_STACK_UNDERFLOW`.
    pub fn pop_name(&mut self) {
        if !self.name_call(ListCommand::Names(NameCall::PopName)) {
            return;
        }
        self.client.select.write_hit_record();
        if self.client.select.names.pop().is_none() {
            self.set_error(GL_STACK_UNDERFLOW);
        }
    }
}

/// Selection's `glGet` rows (GL 1.1 tables 6.18 and 6.20).
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_SELECTION_BUFFER_SIZE, 1, Kind::Int, |gl, o| o[0] = gl.client.select.size as f64),
    row(GL_NAME_STACK_DEPTH, 1, Kind::Int, |gl, o| o[0] = gl.client.select.names.len() as f64),
    int_limit!(GL_MAX_NAME_STACK_DEPTH, MAX_NAME_STACK_DEPTH),
];

#[cfg(test)]
mod tests {
    use super::*;

    fn point(gl: &mut Gl, z: f32) {
        gl.begin(GL_POINTS);
        gl.vertex3f(0.0, 0.0, z);
        gl.end();
    }

    #[test]
    fn hits_record_names_and_scaled_depths() {
        let mut gl = Gl::new(4, 4);
        gl.select_buffer(16);
        gl.render_mode(GL_SELECT);
        gl.init_names();
        gl.push_name(7);
        point(&mut gl, 0.5);
        point(&mut gl, -0.5);
        gl.load_name(8);
        point(&mut gl, 3.0); // outside: no hit
        assert_eq!(gl.render_mode(GL_RENDER), 1);
        assert_eq!(gl.select_values(), &[1, 1 << 30, 3 << 30, 7]);
        let hits: Vec<SelectHit<'_>> = gl.select_hits().collect();
        assert_eq!(hits, [SelectHit { z_min: 1 << 30, z_max: 3 << 30, names: &[7] }]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        assert!(gl.frame().commands.is_empty(), "selection draws nothing");
    }

    #[test]
    fn a_small_buffer_overflows() {
        let mut gl = Gl::new(4, 4);
        gl.select_buffer(3);
        gl.render_mode(GL_SELECT);
        gl.init_names();
        gl.push_name(1);
        point(&mut gl, 0.0);
        assert_eq!(gl.render_mode(GL_RENDER), -1);
        assert_eq!(gl.select_values(), &[1, 1 << 31, 1 << 31]);
        assert_eq!(gl.select_hits().count(), 0, "the record lost its name: cut short");
    }

    /// Records are read as GL 1.1 §5.2 lays them out, and what a buffer cut short (or a count
    /// larger than the values) is left out without a panic.
    #[test]
    fn hit_records_read_the_layout() {
        let values = [2, 10, 20, 5, 6, 0, 1, 2, 1, 3, 4];
        let hits: Vec<SelectHit<'_>> = hit_records(&values).collect();
        assert_eq!(
            hits,
            [SelectHit { z_min: 10, z_max: 20, names: &[5, 6] }, SelectHit { z_min: 1, z_max: 2, names: &[] }]
        );
        assert_eq!(hit_records(&[u32::MAX, 0, 0, 1]).count(), 0);
        assert_eq!(hit_records(&[0, 1]).count(), 0);
        assert_eq!(hit_records(&[]).count(), 0);
    }
}
