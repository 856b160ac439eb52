//! The evaluators: maps, grids, evaluation and the map queries.

use crate::context::with_gl;
use crate::memory::{array, array_mut};
use gleval::gl::types::*;
use gleval::gl::Gl;

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

/// `glMap1f` and `glMap1d`, alike but for the type: the control points read as GL reads them,
/// `(order − 1) · stride + k` values (`Gl::map_points_len`).
macro_rules! map1 {
    ($($name:ident($t:ty) => $method:ident;)*) => {
        $(entry! {
            #[doc = concat!("`", stringify!($name), "`: reads `(order − 1) · stride + k` values.")]
            unsafe fn $name(target: GLenum, u1: $t, u2: $t, stride: GLint, order: GLint, points: *const $t) {
                let points = unsafe { array(points, Gl::map_points_len(target, &[(stride, order)])) };
                with_gl(|gl| gl.$method(target, u1, u2, stride, order, points))
            }
        })*
    };
}

map1! {
    glMap1f(GLfloat) => map1f;
    glMap1d(GLdouble) => map1d;
}

/// `glMap2f` and `glMap2d`, likewise: `(uorder − 1) · ustride + (vorder − 1) · vstride + k`
/// values.
macro_rules! map2 {
    ($($name:ident($t:ty) => $method:ident;)*) => {
        $(entry! {
            #[doc = concat!(
                "`", stringify!($name), "`: reads `(uorder − 1) · ustride + (vorder − 1) · vstride + k` values."
            )]
            #[allow(clippy::too_many_arguments)]
            unsafe fn $name(
                target: GLenum, u1: $t, u2: $t, ustride: GLint, uorder: GLint,
                v1: $t, v2: $t, vstride: GLint, vorder: GLint, points: *const $t,
            ) {
                let points =
                    unsafe { array(points, Gl::map_points_len(target, &[(ustride, uorder), (vstride, vorder)])) };
                with_gl(|gl| gl.$method(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points))
            }
        })*
    };
}

map2! {
    glMap2f(GLfloat) => map2f;
    glMap2d(GLdouble) => map2d;
}

/// `glGetMap{f,d,i}v`: the answer is written where GL writes it, as many values as GL writes.
macro_rules! get_map {
    ($($name:ident($t:ty) => $method:ident;)*) => {
        $(entry! {
            #[doc = concat!("`", stringify!($name), "`: `Gl::", stringify!($method), "`.")]
            unsafe fn $name(target: GLenum, query: GLenum, v: *mut $t) {
                with_gl(|gl| {
                    let n = gl.get_map_len(target, query);
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
