//! The evaluators: maps, grids, evaluation and the map queries.

use crate::context::with_gl;
use crate::memory::{array, array_mut, strided_len};
use gleval::gl::consts::*;
use gleval::gl::types::*;
use gleval::gl::{Gl, MapTarget};

forward! {
    glMapGrid1f(un: GLint, u1: GLfloat, u2: GLfloat) => map_grid1f;
    glMapGrid1d(un: GLint, u1: GLdouble, u2: GLdouble) => map_grid1d;
    glMapGrid2f(un: GLint, u1: GLfloat, u2: GLfloat, vn: GLint, v1: GLfloat, v2: GLfloat) => map_grid2f;
    glMapGrid2d(un: GLint, u1: GLdouble, u2: GLdouble, vn: GLint, v1: GLdouble, v2: GLdouble) => map_grid2d;
    glEvalCoord1f(u: GLfloat) => eval_coord1f;
    glEvalCoord1d(u: GLdouble) => eval_coord1d;
    glEvalCoord2f(u: GLfloat, v: GLfloat) => eval_coord2f;
    glEvalCoord2d(u: GLdouble, v: GLdouble) => eval_coord2d;
    glEvalPoint1(i: GLint) => eval_point1;
    glEvalPoint2(i: GLint, j: GLint) => eval_point2;
    glEvalMesh1(mode: GLenum, i1: GLint, i2: GLint) => eval_mesh1;
    glEvalMesh2(mode: GLenum, i1: GLint, i2: GLint, j1: GLint, j2: GLint) => eval_mesh2;
}

vector! {
    glEvalCoord1fv(GLfloat; 1) => eval_coord1fv;
    glEvalCoord1dv(GLdouble; 1) => eval_coord1dv;
    glEvalCoord2fv(GLfloat; 2) => eval_coord2fv;
    glEvalCoord2dv(GLdouble; 2) => eval_coord2dv;
}

/// Values a `glMap` reads: the last point's offset plus its `k` components, as a display
/// list copies them (for a target of either dimension); `None` for an unknown target, which
/// GL rejects before reading.
fn map_len(target: GLenum, layout: &[(GLint, GLint)]) -> Option<usize> {
    let target = MapTarget::from_enum(target)?;
    strided_len(target.components(), layout, MAX_EVAL_ORDER)
}

entry! {
    /// `glMap1f`: reads `(order − 1) · stride + k` floats.
    unsafe fn glMap1f(target: GLenum, u1: GLfloat, u2: GLfloat, stride: GLint, order: GLint, points: *const GLfloat) {
        let points = unsafe { array(points, map_len(target, &[(stride, order)])) };
        with_gl(|gl| gl.map1f(target, u1, u2, stride, order, points))
    }
}

entry! {
    /// `glMap1d`: as `glMap1f`.
    unsafe fn glMap1d(target: GLenum, u1: GLdouble, u2: GLdouble, stride: GLint, order: GLint, points: *const GLdouble) {
        let points = unsafe { array(points, map_len(target, &[(stride, order)])) };
        with_gl(|gl| gl.map1d(target, u1, u2, stride, order, points))
    }
}

entry! {
    /// `glMap2f`: reads `(uorder − 1) · ustride + (vorder − 1) · vstride + k` floats.
    #[allow(clippy::too_many_arguments)]
    unsafe fn glMap2f(
        target: GLenum, u1: GLfloat, u2: GLfloat, ustride: GLint, uorder: GLint,
        v1: GLfloat, v2: GLfloat, vstride: GLint, vorder: GLint, points: *const GLfloat,
    ) {
        let points = unsafe { array(points, map_len(target, &[(ustride, uorder), (vstride, vorder)])) };
        with_gl(|gl| gl.map2f(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points))
    }
}

entry! {
    /// `glMap2d`: as `glMap2f`.
    #[allow(clippy::too_many_arguments)]
    unsafe fn glMap2d(
        target: GLenum, u1: GLdouble, u2: GLdouble, ustride: GLint, uorder: GLint,
        v1: GLdouble, v2: GLdouble, vstride: GLint, vorder: GLint, points: *const GLdouble,
    ) {
        let points = unsafe { array(points, map_len(target, &[(ustride, uorder), (vstride, vorder)])) };
        with_gl(|gl| gl.map2d(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points))
    }
}

/// Values `glGetMap` writes: `GL_ORDER` one a dimension, `GL_DOMAIN` two, `GL_COEFF` the
/// map's orders times its components (the orders asked of the context, which answers the
/// `GL_ORDER` query without error for a known target); 0 where GL writes nothing.
fn get_map_len(gl: &mut Gl, target: GLenum, query: GLenum) -> usize {
    let Some(map) = MapTarget::from_enum(target) else { return 0 };
    let dims = usize::from(map.dims);
    match query {
        GL_ORDER => dims,
        GL_DOMAIN => 2 * dims,
        GL_COEFF => {
            let mut orders = [0; 2];
            gl.get_mapiv(target, GL_ORDER, &mut orders);
            orders[..dims].iter().map(|&o| o.max(0) as usize).product::<usize>() * map.components()
        }
        _ => 0,
    }
}

/// `glGetMap{f,d,i}v`: the answer is written where GL writes it, as many values as GL writes.
macro_rules! get_map {
    ($($name:ident($t:ty) => $method:ident;)*) => {
        $(entry! {
            #[doc = concat!("`", stringify!($name), "`: `Gl::", stringify!($method), "`.")]
            unsafe fn $name(target: GLenum, query: GLenum, v: *mut $t) {
                with_gl(|gl| {
                    let n = get_map_len(gl, target, query);
                    gl.$method(target, query, unsafe { array_mut(v, n) })
                })
            }
        })*
    };
}

get_map! {
    glGetMapfv(GLfloat) => get_mapfv;
    glGetMapdv(GLdouble) => get_mapdv;
    glGetMapiv(GLint) => get_mapiv;
}
