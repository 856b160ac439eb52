//! GL 1.5's occlusion queries (`GL_ARB_occlusion_query`): `glGenQueries` … `glGetQueryObjectuiv`,
//! each under its ARB name too, one function for both.

use crate::context::with_gl;
use crate::memory::{array, array_mut, count};
use gleval::gl::types::*;

with_arb! {
    /// `glGenQueries`: writes `n` names.
    unsafe fn glGenQueries / glGenQueriesARB(n: GLsizei, ids: *mut GLuint) {
        let ids = unsafe { array_mut(ids, count(n).unwrap_or(0)) };
        with_gl(|gl| gl.gen_queries(n, ids))
    }
}

with_arb! {
    /// `glDeleteQueries`: reads `n` names.
    unsafe fn glDeleteQueries / glDeleteQueriesARB(n: GLsizei, ids: *const GLuint) {
        let ids = unsafe { array(ids, count(n)) };
        with_gl(|gl| gl.delete_queries(n, ids))
    }
}

with_arb! {
    /// `glIsQuery`: `Gl::is_query`.
    fn glIsQuery / glIsQueryARB(id: GLuint) -> GLboolean {
        with_gl(|gl| gl.is_query(id))
    }
}

with_arb! {
    /// `glBeginQuery`: `Gl::begin_query`.
    fn glBeginQuery / glBeginQueryARB(target: GLenum, id: GLuint) {
        with_gl(|gl| gl.begin_query(target, id))
    }
}

with_arb! {
    /// `glEndQuery`: `Gl::end_query`.
    fn glEndQuery / glEndQueryARB(target: GLenum) {
        with_gl(|gl| gl.end_query(target))
    }
}

with_arb! {
    /// `glGetQueryiv`: writes one value.
    unsafe fn glGetQueryiv / glGetQueryivARB(target: GLenum, pname: GLenum, params: *mut GLint) {
        let params = unsafe { array_mut(params, 1) };
        with_gl(|gl| gl.get_queryiv(target, pname, params))
    }
}

with_arb! {
    /// `glGetQueryObjectiv`: writes one value.
    unsafe fn glGetQueryObjectiv / glGetQueryObjectivARB(id: GLuint, pname: GLenum, params: *mut GLint) {
        let params = unsafe { array_mut(params, 1) };
        with_gl(|gl| gl.get_query_objectiv(id, pname, params))
    }
}

with_arb! {
    /// `glGetQueryObjectuiv`: writes one value.
    unsafe fn glGetQueryObjectuiv / glGetQueryObjectuivARB(id: GLuint, pname: GLenum, params: *mut GLuint) {
        let params = unsafe { array_mut(params, 1) };
        with_gl(|gl| gl.get_query_objectuiv(id, pname, params))
    }
}
