//! GL 1.5's occlusion queries (GL 1.5 §4.1.6, `GL_ARB_occlusion_query`; Mesa 22.3
//! `main/queryobj.c`): query names, `glBeginQuery`/`glEndQuery` on `GL_SAMPLES_PASSED`, and
//! the queries' answers.
//!
//! The count is the rasteriser's: the frame is drawn after the calls are made, so
//! `glBeginQuery` and `glEndQuery` record a [`Command::Query`] slot in the frame, and the
//! rasteriser that draws it counts the samples passing the depth and stencil tests while a slot
//! is open ([`super::WindowImage::samples`]). A query's count is fetched when it is asked for
//! (the frame so far drawn through the context's reader, [`Gl::set_window_reader`]) or when the
//! frame is taken ([`Gl::take_frame`]), whichever comes first; a query open across frames adds
//! each frame's part. A context without a reader counts nothing (the window GL starts with), as
//! draws in feedback and selection mode make no fragment. wgpu draws frames with queries on the
//! CPU rasteriser (`gpu/fallback.rs`): its own occlusion queries are not measured on lavapipe.
//! The counts agree with Mesa's (`capi/tests/occlusion.c`, through
//! `capi/tests/against_mesa.sh`: a square, a square partly behind another, points and lines
//! with the colour masked, the alpha and stencil tests failing, a query across `glFlush`).
//!
//! Mesa's rules, measured (`tests/reference/calls/cases/occlusion_queries.calls`):
//! - every call inside `begin`/`end` is `GL_INVALID_OPERATION` and does nothing (an active
//!   query stays active);
//! - `glBeginQuery` checks the target (`GL_INVALID_ENUM`), then the name (0:
//!   `GL_INVALID_OPERATION`), then whether a query is active (`GL_INVALID_OPERATION`); a name
//!   never generated is made by it (a compatibility context), and names are not reused: the
//!   next is one past the largest ever made;
//! - `glIsQuery` is true for a name once it has been begun; `glGetQueryObject` of a name never
//!   begun, unknown, or active is `GL_INVALID_OPERATION`, checked before the name asked for;
//! - deleting the active query ends it (no query is active after);
//! - `glBeginQuery` and `glEndQuery` are compiled into display lists, the other calls run at
//!   once;
//! - `GL_QUERY_COUNTER_BITS` is 64, llvmpipe's.

use super::consts::*;
use super::frame::Command;
use super::lists::ListCommand;
use super::types::*;
use super::Gl;
use std::collections::HashMap;

/// `GL_QUERY_COUNTER_BITS` of `GL_SAMPLES_PASSED`: llvmpipe's, as Mesa 22.3 answers.
pub const QUERY_COUNTER_BITS: GLint = 64;

/// One query object: whether it was ever begun, its count so far, and the slot of the frame
/// being recorded that still counts into it.
#[derive(Clone, Copy, Debug, Default)]
struct QueryObject {
    ever_begun: bool,
    result: u64,
    slot: Option<usize>,
}

/// The query objects by name and the one active on `GL_SAMPLES_PASSED`.
#[derive(Debug, Default)]
pub(crate) struct Queries {
    objects: HashMap<GLuint, QueryObject>,
    /// The largest name ever made (names are not reused, as in Mesa).
    max_name: GLuint,
    active: Option<GLuint>,
    /// Slots recorded in the frame being recorded (the next slot's number).
    slots: usize,
}

impl Gl {
    /// `glGenQueries(n, ids)`: `n` names never used before. `n` < 0 or `ids` shorter than `n`
    /// → `GL_INVALID_VALUE`.
    pub fn gen_queries(&mut self, n: GLsizei, ids: &mut [GLuint]) {
        if self.reject_inside_begin_end() {
            return;
        }
        let Some(names) = usize::try_from(n).ok().and_then(|n| ids.get_mut(..n)) else {
            return self.set_error(GL_INVALID_VALUE);
        };
        let queries = &mut self.server.queries;
        for name in names {
            queries.max_name += 1;
            *name = queries.max_name;
            queries.objects.insert(*name, QueryObject::default());
        }
    }

    /// `glDeleteQueries(n, ids)`: deletes the first `n` names (unknown ones and 0 are
    /// ignored); the active query is ended. `n` < 0 or `ids` shorter → `GL_INVALID_VALUE`.
    pub fn delete_queries(&mut self, n: GLsizei, ids: &[GLuint]) {
        if self.reject_inside_begin_end() {
            return;
        }
        let Some(names) = usize::try_from(n).ok().and_then(|n| ids.get(..n)) else {
            return self.set_error(GL_INVALID_VALUE);
        };
        for name in names {
            let Some(query) = self.server.queries.objects.remove(name) else { continue };
            if self.server.queries.active == Some(*name) {
                // Ended: its slot stops counting (nothing reads it any more).
                self.server.queries.active = None;
                if let Some(slot) = query.slot {
                    self.recorder.frame.commands.push(Command::Query { slot, begin: false });
                }
            }
        }
    }

    /// `glIsQuery(id)`: whether `id` names a query that has been begun.
    pub fn is_query(&mut self, id: GLuint) -> GLboolean {
        if self.reject_inside_begin_end() {
            return GL_FALSE;
        }
        GLboolean::from(self.server.queries.objects.get(&id).is_some_and(|q| q.ever_begun))
    }

    /// `glBeginQuery(target, id)`: starts counting into query `id` on `GL_SAMPLES_PASSED`.
    /// Errors in Mesa's order (module docs).
    pub fn begin_query(&mut self, target: GLenum, id: GLuint) {
        if self.compiled_state_call(|| ListCommand::BeginQuery(target, id)) {
            return;
        }
        let error = if target != GL_SAMPLES_PASSED {
            GL_INVALID_ENUM
        } else if id == 0 || self.server.queries.active.is_some() {
            GL_INVALID_OPERATION
        } else {
            let slot = self.open_slot();
            let queries = &mut self.server.queries;
            queries.max_name = queries.max_name.max(id);
            *queries.objects.entry(id).or_default() = QueryObject { ever_begun: true, result: 0, slot: Some(slot) };
            queries.active = Some(id);
            return;
        };
        self.set_error(error);
    }

    /// `glEndQuery(target)`: ends the active query. Another target → `GL_INVALID_ENUM`; no
    /// query active → `GL_INVALID_OPERATION`.
    pub fn end_query(&mut self, target: GLenum) {
        if self.compiled_state_call(|| ListCommand::EndQuery(target)) {
            return;
        }
        if target != GL_SAMPLES_PASSED {
            return self.set_error(GL_INVALID_ENUM);
        }
        match self.server.queries.active.take() {
            Some(id) => {
                let slot = self.server.queries.objects.get(&id).and_then(|q| q.slot);
                if let Some(slot) = slot {
                    self.recorder.frame.commands.push(Command::Query { slot, begin: false });
                }
            }
            None => self.set_error(GL_INVALID_OPERATION),
        }
    }

    /// A new slot of the frame being recorded, begun.
    fn open_slot(&mut self) -> usize {
        let slot = self.server.queries.slots;
        self.server.queries.slots += 1;
        self.recorder.frame.commands.push(Command::Query { slot, begin: true });
        slot
    }

    /// Adds the counts of the frame recorded so far to the queries that count in it (the
    /// frame drawn through the reader), except the active one's, which counts on.
    fn fetch_counts(&mut self) {
        if !self.server.queries.objects.values().any(|q| q.slot.is_some()) {
            return;
        }
        let samples = self.read_window().map(|w| w.samples).unwrap_or_default();
        let active = self.server.queries.active;
        for (id, query) in &mut self.server.queries.objects {
            if Some(*id) != active {
                if let Some(slot) = query.slot.take() {
                    query.result += samples.get(slot).copied().unwrap_or(0);
                }
            }
        }
    }

    /// Before the frame is taken: every query's count from it; the active query counts on in
    /// the next frame (its first slot).
    pub(crate) fn queries_leave_frame(&mut self) {
        if self.server.queries.objects.values().any(|q| q.slot.is_some()) {
            let samples = self.read_window().map(|w| w.samples).unwrap_or_default();
            for query in self.server.queries.objects.values_mut() {
                if let Some(slot) = query.slot.take() {
                    query.result += samples.get(slot).copied().unwrap_or(0);
                }
            }
        }
        self.server.queries.slots = 0;
    }

    /// After the frame is taken: the active query's slot in the new frame.
    pub(crate) fn queries_enter_frame(&mut self) {
        if let Some(id) = self.server.queries.active {
            let slot = self.open_slot();
            if let Some(query) = self.server.queries.objects.get_mut(&id) {
                query.slot = Some(slot);
            }
        }
    }

    /// `glGetQueryiv(target, pname, params)`: `GL_QUERY_COUNTER_BITS` (64) or
    /// `GL_CURRENT_QUERY` (the active query's name, 0 for none) into `params[0]`. Another
    /// target or name → `GL_INVALID_ENUM`; an empty `params` → `GL_INVALID_VALUE`.
    pub fn get_queryiv(&mut self, target: GLenum, pname: GLenum, params: &mut [GLint]) {
        if self.reject_inside_begin_end() {
            return;
        }
        let value = match (target, pname) {
            (GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS) => QUERY_COUNTER_BITS,
            (GL_SAMPLES_PASSED, GL_CURRENT_QUERY) => self.server.queries.active.unwrap_or(0) as GLint,
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        match params.first_mut() {
            Some(p) => *p = value,
            None => self.set_error(GL_INVALID_VALUE),
        }
    }

    /// `glGetQueryObjectiv(id, pname, params)`: `GL_QUERY_RESULT` (the count, at most
    /// `GLint::MAX`) or `GL_QUERY_RESULT_AVAILABLE` (always true: the count is made when asked)
    /// into `params[0]`. Errors in Mesa's order (module docs).
    pub fn get_query_objectiv(&mut self, id: GLuint, pname: GLenum, params: &mut [GLint]) {
        if let Some(value) = self.query_object(id, pname) {
            match params.first_mut() {
                Some(p) => *p = GLint::try_from(value).unwrap_or(GLint::MAX),
                None => self.set_error(GL_INVALID_VALUE),
            }
        }
    }

    /// `glGetQueryObjectuiv(id, pname, params)`: as [`Gl::get_query_objectiv`], the count at
    /// most `GLuint::MAX`.
    pub fn get_query_objectuiv(&mut self, id: GLuint, pname: GLenum, params: &mut [GLuint]) {
        if let Some(value) = self.query_object(id, pname) {
            match params.first_mut() {
                Some(p) => *p = GLuint::try_from(value).unwrap_or(GLuint::MAX),
                None => self.set_error(GL_INVALID_VALUE),
            }
        }
    }

    /// A query object's answer for `pname`, or the error raised instead.
    fn query_object(&mut self, id: GLuint, pname: GLenum) -> Option<u64> {
        if self.reject_inside_begin_end() {
            return None;
        }
        let queries = &self.server.queries;
        let object = queries.objects.get(&id).filter(|q| q.ever_begun && queries.active != Some(id));
        let Some(object) = object.copied() else {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        };
        match pname {
            GL_QUERY_RESULT if object.slot.is_some() => {
                self.fetch_counts();
                self.server.queries.objects.get(&id).map(|q| q.result)
            }
            GL_QUERY_RESULT => Some(object.result),
            GL_QUERY_RESULT_AVAILABLE => Some(u64::from(GL_TRUE)),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                None
            }
        }
    }
}
