//! `glMap1{f,d}` and `glMap2{f,d}`: validation in Mesa's order (`main/eval.c` `map1()`,
//! `map2()`) and the packed copy of the control points.

use super::target::{MapTarget, Slot};
use super::EvalCall;
use crate::gl::consts::*;
use crate::gl::lists::ListCommand;
use crate::gl::types::*;
use crate::gl::Gl;

/// One evaluator map as Mesa stores it: packed control points and the domain with its
/// reciprocal length (`du = 1/(u2 − u1)`, in float).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Map {
    pub uorder: usize,
    /// 1 for a 1D map.
    pub vorder: usize,
    pub u1: f32,
    pub u2: f32,
    pub v1: f32,
    pub v2: f32,
    pub du: f32,
    pub dv: f32,
    /// `uorder * vorder * k` floats, point (i, j) at `(i * vorder + j) * k`.
    pub points: Vec<f32>,
}

impl Map {
    /// Order 1 over [0, 1] with the target's default point (spec 1.10).
    pub fn initial(slot: Slot, _dims: u8) -> Self {
        Self {
            uorder: 1,
            vorder: 1,
            u1: 0.0,
            u2: 1.0,
            v1: 0.0,
            v2: 1.0,
            du: 1.0,
            dv: 1.0,
            points: slot.initial_point().to_vec(),
        }
    }

    /// The normalised parameter Mesa evaluates at: `(u − u1) · du`.
    pub fn norm_u(&self, u: f32) -> f32 {
        (u - self.u1) * self.du
    }

    /// The normalised v parameter.
    pub fn norm_v(&self, v: f32) -> f32 {
        (v - self.v1) * self.dv
    }
}

/// Control points given as `f32` or `f64` (the `d` entry points cast to float, as Mesa does).
pub(crate) trait ControlValue: Copy {
    fn to_gl_float(self) -> f32;
}

impl ControlValue for f32 {
    fn to_gl_float(self) -> f32 {
        self
    }
}

impl ControlValue for f64 {
    fn to_gl_float(self) -> f32 {
        self as f32
    }
}

/// Index of the last value read for a strided layout, or `None` on overflow.
fn needed_len(k: usize, strides_and_orders: &[(i64, i64)]) -> Option<usize> {
    let mut last = k as i64;
    for &(stride, order) in strides_and_orders {
        last = last.checked_add(stride.checked_mul(order - 1)?)?;
    }
    usize::try_from(last).ok()
}

/// The control points a display list keeps of a `glMap` call and the strides to read them
/// (Mesa `_mesa_copy_map_points1f`/`2f`): for a known target, `order` points read with the
/// caller's strides, packed (k values a point, v fastest), so that the list replays them with
/// strides k and k · vorder; a stride below k is therefore no error once listed, as in Mesa.
/// An unknown target keeps no points (C's NULL: Mesa then reports `GL_INVALID_VALUE`), and so
/// do orders outside 1..=30 and strides that would read outside `points`.
fn points_for_list<T: ControlValue>(target: GLenum, layout: &[(i32, i32)], points: &[T]) -> (Vec<i32>, Vec<f32>) {
    let given = || layout.iter().map(|l| l.0).collect::<Vec<i32>>();
    let Some(k) = MapTarget::from_enum(target).map(|t| t.components()) else {
        return (vec![0; layout.len()], Vec::new());
    };
    let readable = layout.iter().all(|&(stride, order)| (1..=MAX_EVAL_ORDER).contains(&order) && stride >= 0);
    let wide: Vec<(i64, i64)> = layout.iter().map(|&(s, o)| (i64::from(s), i64::from(o))).collect();
    if !readable || needed_len(k, &wide).is_none_or(|need| points.len() < need) {
        return (given(), Vec::new());
    }
    let orders: Vec<usize> = layout.iter().map(|l| l.1 as usize).collect();
    let total: usize = orders.iter().product();
    let mut packed = Vec::with_capacity(total * k);
    for flat in 0..total {
        // The point's index in each dimension, the last fastest, and where the caller keeps it.
        let (mut rest, mut at) = (flat, 0usize);
        for (d, &order) in orders.iter().enumerate().rev() {
            at += (rest % order) * layout[d].0 as usize;
            rest /= order;
        }
        packed.extend(points[at..at + k].iter().map(|p| p.to_gl_float()));
    }
    let mut strides = vec![0i32; layout.len()];
    let mut step = k;
    for (d, &order) in orders.iter().enumerate().rev() {
        strides[d] = step as i32;
        step *= order;
    }
    (strides, packed)
}

/// Arguments of `glMap2` once decoded.
struct Map2Args {
    u: (f32, f32),
    v: (f32, f32),
    ustride: i32,
    uorder: i32,
    vstride: i32,
    vorder: i32,
}

impl Gl {
    /// Values a `glMap1*` (`layout` one `(stride, order)`) or `glMap2*` (two, u first) call
    /// reads for `target`: the last point's offset plus its components, as a display list
    /// copies them (Mesa's `_mesa_copy_map_points1f`); `None` where GL reads nothing (an
    /// unknown target, an order outside 1..=`GL_MAX_EVAL_ORDER`, a negative stride, an
    /// overflow). What a binding with only a pointer (the C ABI) must have before it makes the
    /// slice.
    #[must_use]
    pub fn map_points_len(target: GLenum, layout: &[(GLint, GLint)]) -> Option<usize> {
        let k = MapTarget::from_enum(target)?.components();
        let readable = layout.iter().all(|&(stride, order)| (1..=MAX_EVAL_ORDER).contains(&order) && stride >= 0);
        let wide: Vec<(i64, i64)> = layout.iter().map(|&(s, o)| (i64::from(s), i64::from(o))).collect();
        readable.then(|| needed_len(k, &wide)).flatten()
    }

    /// `glMap1f`: defines a 1D map. Errors, in Mesa's order: inside begin/end
    /// (`GL_INVALID_OPERATION`), `u1 == u2`, order outside 1..=30, an empty slice (C's NULL)
    /// (`GL_INVALID_VALUE`), an unknown target (`GL_INVALID_ENUM`), `stride < k`
    /// (`GL_INVALID_VALUE`), active texture unit not 0 (`GL_INVALID_OPERATION`), a 2D target
    /// (`GL_INVALID_ENUM`), and last a slice shorter than the layout reads (`GL_INVALID_VALUE`).
    /// On error the previous map is untouched.
    pub fn map1f(&mut self, target: GLenum, u1: GLfloat, u2: GLfloat, stride: GLint, order: GLint, points: &[GLfloat]) {
        self.map1(target, u1, u2, stride, order, points);
    }

    /// `glMap1d`: as [`Gl::map1f`], with the domain and points cast to float.
    pub fn map1d(
        &mut self,
        target: GLenum,
        u1: GLdouble,
        u2: GLdouble,
        stride: GLint,
        order: GLint,
        points: &[GLdouble],
    ) {
        self.map1(target, u1 as f32, u2 as f32, stride, order, points);
    }

    /// `glMap2f`: defines a 2D map; point (i, j) is read at `i*ustride + j*vstride`. Errors, in
    /// Mesa's order: inside begin/end, `u1 == u2`, `v1 == v2`, uorder and vorder outside 1..=30,
    /// unknown target, `ustride < k`, `vstride < k`, active texture unit not 0, a 1D target, and
    /// last a slice shorter than the layout reads. On error the previous map is untouched.
    #[allow(clippy::too_many_arguments)]
    pub fn map2f(
        &mut self,
        target: GLenum,
        u1: GLfloat,
        u2: GLfloat,
        ustride: GLint,
        uorder: GLint,
        v1: GLfloat,
        v2: GLfloat,
        vstride: GLint,
        vorder: GLint,
        points: &[GLfloat],
    ) {
        let args = Map2Args { u: (u1, u2), v: (v1, v2), ustride, uorder, vstride, vorder };
        self.map2(target, args, points);
    }

    /// `glMap2d`: as [`Gl::map2f`], with the domain and points cast to float.
    #[allow(clippy::too_many_arguments)]
    pub fn map2d(
        &mut self,
        target: GLenum,
        u1: GLdouble,
        u2: GLdouble,
        ustride: GLint,
        uorder: GLint,
        v1: GLdouble,
        v2: GLdouble,
        vstride: GLint,
        vorder: GLint,
        points: &[GLdouble],
    ) {
        let args = Map2Args { u: (u1 as f32, u2 as f32), v: (v1 as f32, v2 as f32), ustride, uorder, vstride, vorder };
        self.map2(target, args, points);
    }

    fn map1<T: ControlValue>(&mut self, target: GLenum, u1: f32, u2: f32, stride: i32, order: i32, points: &[T]) {
        if self.compiled(|| {
            let (strides, points) = points_for_list(target, &[(stride, order)], points);
            ListCommand::Eval(EvalCall::Map1 { target, u: (u1, u2), stride: strides[0], order, points })
        }) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        let k = match self.check_map1(target, u1, u2, stride, order, points.is_empty()) {
            Some(k) => k,
            None => return,
        };
        let Some(need) = needed_len(k, &[(stride.into(), order.into())]) else {
            return self.set_error(GL_INVALID_VALUE);
        };
        if points.len() < need {
            return self.set_error(GL_INVALID_VALUE);
        }
        let order = order as usize;
        let slot = MapTarget::from_enum(target).map_or(Slot::Vertex3, |t| t.slot);
        let map = &mut self.server.eval.map1[slot as usize];
        // The old map's storage is reused: programs drawing many curves redefine the map each time.
        let mut packed = std::mem::take(&mut map.points);
        packed.clear();
        for i in 0..order {
            packed.extend(points[i * stride as usize..][..k].iter().map(|p| p.to_gl_float()));
        }
        *map = Map { uorder: order, vorder: 1, u1, u2, v1: 0.0, v2: 1.0, du: 1.0 / (u2 - u1), dv: 1.0, points: packed };
    }

    /// Mesa's checks for `glMap1`, in order; returns k when all pass.
    fn check_map1(&mut self, target: GLenum, u1: f32, u2: f32, stride: i32, order: i32, null: bool) -> Option<usize> {
        if u1 == u2 || !(1..=MAX_EVAL_ORDER).contains(&order) || null {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let Some(t) = MapTarget::from_enum(target) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        let k = t.components();
        if (stride as i64) < k as i64 {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        if self.server.active_texture != GL_TEXTURE0 {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        if t.dims != 1 {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        Some(k)
    }

    fn map2<T: ControlValue>(&mut self, target: GLenum, a: Map2Args, points: &[T]) {
        if self.compiled(|| {
            let (strides, points) = points_for_list(target, &[(a.ustride, a.uorder), (a.vstride, a.vorder)], points);
            let (ustride, vstride) = (strides[0], strides[1]);
            ListCommand::Eval(EvalCall::Map2 {
                target,
                u: a.u,
                ustride,
                uorder: a.uorder,
                v: a.v,
                vstride,
                vorder: a.vorder,
                points,
            })
        }) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        let Some(k) = self.check_map2(target, &a) else {
            return;
        };
        let layout = [(i64::from(a.ustride), i64::from(a.uorder)), (i64::from(a.vstride), i64::from(a.vorder))];
        match needed_len(k, &layout) {
            Some(need) if points.len() >= need => {}
            _ => return self.set_error(GL_INVALID_VALUE),
        }
        let (uo, vo) = (a.uorder as usize, a.vorder as usize);
        let (us, vs) = (a.ustride as usize, a.vstride as usize);
        let slot = MapTarget::from_enum(target).map_or(Slot::Vertex3, |t| t.slot);
        let map = &mut self.server.eval.map2[slot as usize];
        // The old map's storage is reused: programs drawing many patches redefine the map each time.
        let mut packed = std::mem::take(&mut map.points);
        packed.clear();
        for i in 0..uo {
            for j in 0..vo {
                packed.extend(points[i * us + j * vs..][..k].iter().map(|p| p.to_gl_float()));
            }
        }
        *map = Map {
            uorder: uo,
            vorder: vo,
            u1: a.u.0,
            u2: a.u.1,
            v1: a.v.0,
            v2: a.v.1,
            du: 1.0 / (a.u.1 - a.u.0),
            dv: 1.0 / (a.v.1 - a.v.0),
            points: packed,
        };
    }

    /// Mesa's checks for `glMap2`, in order; returns k when all pass.
    fn check_map2(&mut self, target: GLenum, a: &Map2Args) -> Option<usize> {
        let orders_ok = (1..=MAX_EVAL_ORDER).contains(&a.uorder) && (1..=MAX_EVAL_ORDER).contains(&a.vorder);
        if a.u.0 == a.u.1 || a.v.0 == a.v.1 || !orders_ok {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let Some(t) = MapTarget::from_enum(target) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        let k = t.components() as i64;
        if i64::from(a.ustride) < k || i64::from(a.vstride) < k {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        if self.server.active_texture != GL_TEXTURE0 {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        if t.dims != 2 {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        Some(k as usize)
    }
}
