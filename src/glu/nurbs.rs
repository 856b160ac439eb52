//! The GLU NURBS object and its API (`gluNewNurbsRenderer` ... `gluEndSurface`), with GLU's
//! nesting rules, automatic begin/end, validation order and error numbers
//! (`nurbsinterfac.cc`, `nurbstess.cc`; spec 2.8).

use super::callbacks::{Callbacks, NurbsCallback, UserData};
use super::consts::*;
use super::props::{NurbsProperties, SamplingMatrices};
use crate::gl::types::*;
use crate::gl::Gl;
use crate::math::knots::KnotVector;

/// A NURBS object (`GLUnurbs*`): a copyable handle into its [`Gl`] context.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct GLUnurbs(pub(crate) usize);

/// One map of a curve: GL target (or trim type), k, order, knots and packed control points.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct CurveMap {
    pub target: GLenum,
    pub k: usize,
    pub order: usize,
    pub knots: Vec<f64>,
    pub points: Vec<f64>,
}

/// One map of a surface: control point (i, j) at `(i * ncv + j) * k`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct SurfaceMap {
    pub target: GLenum,
    pub k: usize,
    pub orders: (usize, usize),
    pub uknots: Vec<f64>,
    pub vknots: Vec<f64>,
    pub points: Vec<f64>,
}

/// A piece of a trim loop.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum TrimPiece {
    /// `gluPwlCurve` points in (u, v).
    Pwl(Vec<[f64; 2]>),
    /// `gluNurbsCurve` with a trim type.
    Curve(CurveMap),
}

/// A surface being defined.
#[derive(Clone, Debug, Default)]
pub(crate) struct SurfaceDef {
    pub maps: Vec<SurfaceMap>,
    pub loops: Vec<Vec<TrimPiece>>,
    /// GLU's `isDataValid`: an error in the definition suppresses drawing.
    pub valid: bool,
}

/// Where the object is in the begin/end nesting.
#[derive(Debug, Default)]
struct Nesting {
    curve: Option<Vec<CurveMap>>,
    /// Pieces of a curve group inside a trim (`gluBeginCurve` within `gluBeginTrim`).
    trim_group: Option<Vec<TrimPiece>>,
    surface: Option<SurfaceDef>,
    /// The surface was begun by `gluBeginTrim` (GLU's `inSurface == 2`): the next
    /// `gluNurbsSurface` ends it.
    auto_surface: bool,
    trim: Option<Vec<TrimPiece>>,
    curve_valid: bool,
}

/// The state of one NURBS object.
pub(crate) struct NurbsObject {
    pub props: NurbsProperties,
    pub callbacks: Callbacks,
    pub matrices: SamplingMatrices,
    /// Two buffers of evaluated tessellator vertices (one filled while the other is issued),
    /// kept between surfaces so that memory is reused.
    pub vertex_scratch: [Vec<[f32; 5]>; 2],
    nesting: Nesting,
}

impl std::fmt::Debug for NurbsObject {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("NurbsObject").field("props", &self.props).field("nesting", &self.nesting).finish()
    }
}

impl NurbsObject {
    fn new() -> Self {
        Self {
            props: NurbsProperties::DEFAULT,
            callbacks: Callbacks::default(),
            matrices: SamplingMatrices::IDENTITY,
            vertex_scratch: [Vec::new(), Vec::new()],
            nesting: Nesting::default(),
        }
    }

    /// Reports `GLU_NURBS_ERRORn` through the error callback (errors are not latched).
    pub fn nurbs_error(&mut self, n: u32) {
        self.callbacks.error(GLU_NURBS_ERROR1 + n - 1);
    }
}

/// Component count and rationality of a curve type; trim types are 2 and 3.
fn curve_type(target: GLenum) -> Option<usize> {
    match target {
        GLU_MAP1_TRIM_2 => Some(2),
        GLU_MAP1_TRIM_3 => Some(3),
        _ => crate::gl::MapTarget::from_enum(target).filter(|t| t.dims == 1).map(|t| t.components()),
    }
}

fn is_trim_type(target: GLenum) -> bool {
    target == GLU_MAP1_TRIM_2 || target == GLU_MAP1_TRIM_3
}

/// Copies `count` points of `k` floats at `stride` floats; `None` if the slice is too short.
fn gather(ctl: &[f32], count: usize, stride: usize, k: usize) -> Option<Vec<f64>> {
    if count == 0 {
        return Some(Vec::new());
    }
    let last = (count - 1).checked_mul(stride)?.checked_add(k)?;
    if ctl.len() < last {
        return None;
    }
    Some((0..count).flat_map(|i| ctl[i * stride..i * stride + k].iter().map(|&v| f64::from(v))).collect())
}

/// Knots as f64, or GLU's knot error number (1..=5), or 10 for a knot slice shorter than
/// `nknots` (GLU's "missing or extra domain data").
fn knot_vector(nknots: i32, knots: &[f32], order: i32) -> Result<Vec<f64>, u32> {
    let order_u = usize::try_from(order).unwrap_or(0);
    if order < 1 || order_u > crate::math::knots::GLU_MAX_ORDER {
        return Err(1);
    }
    let n = usize::try_from(nknots).unwrap_or(0);
    if n < 2 * order_u {
        return Err(2);
    }
    let Some(k) = knots.get(..n) else { return Err(10) };
    let kv = KnotVector::new(k.iter().map(|&v| f64::from(v)).collect());
    kv.glu_check(order_u).map_err(|e| e.number())?;
    Ok(kv.knots)
}

impl Gl {
    fn nurbs(&mut self, nobj: GLUnurbs) -> Option<&mut NurbsObject> {
        self.nurbs.get_mut(nobj.0).and_then(Option::as_mut)
    }

    /// Runs `f` with the object taken out of the context, so that it may draw through `self`.
    pub(crate) fn with_nurbs<R>(
        &mut self,
        nobj: GLUnurbs,
        f: impl FnOnce(&mut Gl, &mut NurbsObject) -> R,
    ) -> Option<R> {
        let mut obj = self.nurbs.get_mut(nobj.0)?.take()?;
        let r = f(self, &mut obj);
        if let Some(slot) = self.nurbs.get_mut(nobj.0) {
            *slot = Some(obj);
        }
        Some(r)
    }

    /// `gluNewNurbsRenderer`: a new NURBS object with GLU's default properties.
    pub fn glu_new_nurbs_renderer(&mut self) -> GLUnurbs {
        self.nurbs.push(Some(NurbsObject::new()));
        GLUnurbs(self.nurbs.len() - 1)
    }

    /// `gluDeleteNurbsRenderer`. Later calls with the handle do nothing.
    pub fn glu_delete_nurbs_renderer(&mut self, nobj: GLUnurbs) {
        if let Some(slot) = self.nurbs.get_mut(nobj.0) {
            *slot = None;
        }
    }

    /// `gluNurbsProperty`. An unknown property → `GLU_INVALID_ENUM`; a bad display mode or
    /// sampling method → `GLU_INVALID_VALUE` (through the error callback; nothing changes).
    pub fn glu_nurbs_property(&mut self, nobj: GLUnurbs, property: GLenum, value: GLfloat) {
        let Some(obj) = self.nurbs(nobj) else { return };
        match obj.props.set(property, value) {
            Ok(()) if obj.props.object_space() => obj.matrices = SamplingMatrices::IDENTITY,
            Ok(()) => {}
            Err(code) => obj.callbacks.error(code),
        }
    }

    /// `gluGetNurbsProperty`: writes the value into `value[0]`.
    pub fn glu_get_nurbs_property(&mut self, nobj: GLUnurbs, property: GLenum, value: &mut [GLfloat]) {
        let Some(obj) = self.nurbs(nobj) else { return };
        match (obj.props.get(property), value.first_mut()) {
            (Ok(v), Some(out)) => *out = v,
            (Ok(_), None) => obj.callbacks.error(GLU_INVALID_VALUE),
            (Err(code), _) => obj.callbacks.error(code),
        }
    }

    /// `gluLoadSamplingMatrices(nobj, model, perspective, view)`: used while
    /// `GLU_AUTO_LOAD_MATRIX` is false.
    pub fn glu_load_sampling_matrices(
        &mut self,
        nobj: GLUnurbs,
        model: &[GLfloat],
        perspective: &[GLfloat],
        view: &[GLint],
    ) {
        let Some(obj) = self.nurbs(nobj) else { return };
        match (model.get(..16), perspective.get(..16), view.get(..4)) {
            (Some(m), Some(p), Some(v)) => {
                obj.matrices = SamplingMatrices {
                    modelview: glam::Mat4::from_cols_slice(m),
                    projection: glam::Mat4::from_cols_slice(p),
                    viewport: [v[0], v[1], v[2], v[3]],
                };
            }
            _ => obj.callbacks.error(GLU_INVALID_VALUE),
        }
    }

    /// `gluNurbsCallback(nobj, which, fn)`; `None` removes the callback. An unknown `which`, or
    /// a callback of another kind than `which` names → `GLU_INVALID_ENUM`.
    pub fn glu_nurbs_callback(&mut self, nobj: GLUnurbs, which: GLenum, callback: Option<NurbsCallback>) {
        let Some(obj) = self.nurbs(nobj) else { return };
        if !obj.callbacks.set(which, callback) {
            obj.callbacks.error(GLU_INVALID_ENUM);
        }
    }

    /// `gluNurbsCallbackData`: the user data the `_DATA` callbacks receive.
    pub fn glu_nurbs_callback_data(&mut self, nobj: GLUnurbs, data: UserData) {
        if let Some(obj) = self.nurbs(nobj) {
            obj.callbacks.data = Some(data);
        }
    }

    /// Loads the sampling matrices from the GL state when `GLU_AUTO_LOAD_MATRIX` is on
    /// (GLU's `bgnrender`).
    fn auto_load_matrices(&mut self, nobj: GLUnurbs) {
        let current = SamplingMatrices {
            modelview: self.matrices.modelview(),
            projection: self.matrices.projection(),
            viewport: self.raster.viewport,
        };
        if let Some(obj) = self.nurbs(nobj) {
            if obj.props.auto_load_matrix {
                obj.matrices = current;
            }
        }
    }

    /// `gluBeginCurve`: inside a curve → error 6 and the old curve is ended first.
    pub fn glu_begin_curve(&mut self, nobj: GLUnurbs) {
        let Some(obj) = self.nurbs(nobj) else { return };
        if obj.nesting.trim.is_some() {
            if obj.nesting.trim_group.is_some() {
                obj.nurbs_error(6);
            }
            obj.nesting.trim_group = Some(Vec::new());
            return;
        }
        if obj.nesting.curve.is_some() {
            obj.nurbs_error(6);
            self.glu_end_curve(nobj);
        }
        self.auto_load_matrices(nobj);
        if let Some(obj) = self.nurbs(nobj) {
            obj.nesting.curve = Some(Vec::new());
            obj.nesting.curve_valid = true;
        }
    }

    /// `gluEndCurve`: without a begin → error 7. Draws the curve.
    pub fn glu_end_curve(&mut self, nobj: GLUnurbs) {
        let Some(obj) = self.nurbs(nobj) else { return };
        if obj.nesting.trim.is_some() {
            match obj.nesting.trim_group.take() {
                Some(group) => obj.nesting.trim.get_or_insert_with(Vec::new).extend(group),
                None => obj.nurbs_error(7),
            }
            return;
        }
        let Some(maps) = obj.nesting.curve.take() else {
            return obj.nurbs_error(7);
        };
        if maps.is_empty() {
            // GLU treats a curve without data as a piecewise-linear one it cannot draw.
            return obj.nurbs_error(9);
        }
        if obj.nesting.curve_valid {
            self.with_nurbs(nobj, |gl, obj| super::draw::draw_curve(gl, obj, &maps));
        }
    }

    /// `gluNurbsCurve(nobj, nknots, knots, stride, ctlarray, order, type)`: stride in floats.
    /// Checks in GLU's order: unknown type (35), empty control array (36), negative stride (34),
    /// knots (1–5); then a knot or control slice shorter than the call reads (10, 8). Outside a
    /// begin/end pair the curve is drawn at once.
    #[allow(clippy::too_many_arguments)]
    pub fn glu_nurbs_curve(
        &mut self,
        nobj: GLUnurbs,
        nknots: GLint,
        knots: &[GLfloat],
        stride: GLint,
        ctlarray: &[GLfloat],
        order: GLint,
        kind: GLenum,
    ) {
        let Some(obj) = self.nurbs(nobj) else { return };
        let Some(map) = validate_curve(obj, nknots, knots, stride, ctlarray, order, kind) else {
            obj.nesting.curve_valid = false;
            if let Some(s) = obj.nesting.surface.as_mut() {
                s.valid &= obj.nesting.trim.is_none();
            }
            return;
        };
        if obj.nesting.trim.is_some() {
            if !is_trim_type(kind) {
                return obj.nurbs_error(14);
            }
            let piece = TrimPiece::Curve(map);
            match obj.nesting.trim_group.as_mut() {
                Some(group) if group.iter().any(|p| matches!(p, TrimPiece::Pwl(_))) => obj.nurbs_error(24),
                Some(group) => group.push(piece),
                None => obj.nesting.trim.get_or_insert_with(Vec::new).push(piece),
            }
            return;
        }
        if is_trim_type(kind) {
            return obj.nurbs_error(22);
        }
        if let Some(curve) = obj.nesting.curve.as_mut() {
            curve.push(map);
            return;
        }
        self.glu_begin_curve(nobj);
        if let Some(curve) = self.nurbs(nobj).and_then(|o| o.nesting.curve.as_mut()) {
            curve.push(map);
        }
        self.glu_end_curve(nobj);
    }

    /// `gluPwlCurve(nobj, count, data, stride, type)`: a piecewise-linear trim curve. Unknown
    /// type (35), a non-trim type (22), `count < 0` (33), `stride < 0` (34), outside a trim (19).
    pub fn glu_pwl_curve(&mut self, nobj: GLUnurbs, count: GLint, data: &[GLfloat], stride: GLint, kind: GLenum) {
        let Some(obj) = self.nurbs(nobj) else { return };
        let Some(k) = curve_type(kind) else { return obj.nurbs_error(35) };
        let checks = [(!is_trim_type(kind), 22), (count < 0, 33), (stride < 0, 34), (obj.nesting.trim.is_none(), 19)];
        if let Some((_, n)) = checks.iter().find(|(bad, _)| *bad) {
            return obj.nurbs_error(*n);
        }
        let Some(values) = gather(data, count as usize, stride as usize, k) else {
            return obj.nurbs_error(8);
        };
        // TRIM_3 points are homogeneous: divide by w.
        let points: Vec<[f64; 2]> =
            values.chunks_exact(k).map(|p| if k == 3 { [p[0] / p[2], p[1] / p[2]] } else { [p[0], p[1]] }).collect();
        let piece = TrimPiece::Pwl(points);
        match obj.nesting.trim_group.as_mut() {
            Some(group) if group.iter().any(|p| matches!(p, TrimPiece::Curve(_))) => obj.nurbs_error(21),
            Some(group) => group.push(piece),
            None => obj.nesting.trim.get_or_insert_with(Vec::new).push(piece),
        }
    }

    /// `gluBeginSurface`: inside a surface → error 27 and the old surface is ended first.
    pub fn glu_begin_surface(&mut self, nobj: GLUnurbs) {
        let Some(obj) = self.nurbs(nobj) else { return };
        if obj.nesting.surface.is_some() {
            obj.nurbs_error(27);
            self.glu_end_surface(nobj);
        }
        self.auto_load_matrices(nobj);
        if let Some(obj) = self.nurbs(nobj) {
            obj.nesting.surface = Some(SurfaceDef { valid: true, ..SurfaceDef::default() });
        }
    }

    /// `gluEndSurface`: inside a trim → error 12 (the trim is ended); without a begin →
    /// error 13. Draws the surface if its definition was valid.
    pub fn glu_end_surface(&mut self, nobj: GLUnurbs) {
        let Some(obj) = self.nurbs(nobj) else { return };
        if obj.nesting.trim.is_some() {
            obj.nurbs_error(12);
            self.glu_end_trim(nobj);
        }
        let Some(obj) = self.nurbs(nobj) else { return };
        let Some(surface) = obj.nesting.surface.take() else {
            return obj.nurbs_error(13);
        };
        // A surface begun by `gluBeginTrim` is over too (GLU's `inSurface = 0`): the next
        // `gluNurbsSurface` must not end its own surface early.
        obj.nesting.auto_surface = false;
        if surface.valid {
            self.with_nurbs(nobj, |gl, obj| super::draw::draw_surface(gl, obj, &surface));
        }
    }

    /// `gluNurbsSurface(nobj, sknot_count, sknots, tknot_count, tknots, s_stride, t_stride,
    /// ctlarray, sorder, torder, type)`: point (i, j) at `i*s_stride + j*t_stride` floats.
    #[allow(clippy::too_many_arguments)]
    pub fn glu_nurbs_surface(
        &mut self,
        nobj: GLUnurbs,
        sknot_count: GLint,
        sknots: &[GLfloat],
        tknot_count: GLint,
        tknots: &[GLfloat],
        s_stride: GLint,
        t_stride: GLint,
        ctlarray: &[GLfloat],
        sorder: GLint,
        torder: GLint,
        kind: GLenum,
    ) {
        let Some(obj) = self.nurbs(nobj) else { return };
        let map = validate_surface(
            obj,
            (sknot_count, sknots, sorder),
            (tknot_count, tknots, torder),
            (s_stride, t_stride),
            ctlarray,
            kind,
        );
        let auto = obj.nesting.surface.is_none() || std::mem::take(&mut obj.nesting.auto_surface);
        if self.nurbs(nobj).is_some_and(|o| o.nesting.surface.is_none()) {
            self.glu_begin_surface(nobj);
        }
        if let Some(s) = self.nurbs(nobj).and_then(|o| o.nesting.surface.as_mut()) {
            match map {
                Some(m) => s.maps.push(m),
                None => s.valid = false,
            }
        }
        if auto {
            self.glu_end_surface(nobj);
        }
    }

    /// `gluBeginTrim`: outside a surface → error 15 (a surface is begun, and the next
    /// `gluNurbsSurface` ends it); inside a trim → error 16 (the open trim is ended first).
    pub fn glu_begin_trim(&mut self, nobj: GLUnurbs) {
        let Some(obj) = self.nurbs(nobj) else { return };
        if obj.nesting.surface.is_none() {
            obj.nurbs_error(15);
            self.glu_begin_surface(nobj);
            if let Some(obj) = self.nurbs(nobj) {
                obj.nesting.auto_surface = true;
            }
        }
        let Some(obj) = self.nurbs(nobj) else { return };
        if obj.nesting.trim.is_some() {
            obj.nurbs_error(16);
            self.glu_end_trim(nobj);
        }
        if let Some(obj) = self.nurbs(nobj) {
            obj.nesting.trim = Some(Vec::new());
        }
    }

    /// `gluEndTrim`: without a begin → error 17; an empty loop → error 18 (the surface is not
    /// drawn).
    pub fn glu_end_trim(&mut self, nobj: GLUnurbs) {
        let Some(obj) = self.nurbs(nobj) else { return };
        let Some(mut pieces) = obj.nesting.trim.take() else {
            return obj.nurbs_error(17);
        };
        if let Some(group) = obj.nesting.trim_group.take() {
            pieces.extend(group);
        }
        let empty = pieces.is_empty();
        if empty {
            obj.nurbs_error(18);
        }
        if let Some(s) = obj.nesting.surface.as_mut() {
            if empty {
                s.valid = false;
            } else {
                s.loops.push(pieces);
            }
        }
    }
}

/// GLU's checks for `gluNurbsCurve`, reporting the first failure.
#[allow(clippy::too_many_arguments)]
fn validate_curve(
    obj: &mut NurbsObject,
    nknots: i32,
    knots: &[f32],
    stride: i32,
    ctl: &[f32],
    order: i32,
    kind: GLenum,
) -> Option<CurveMap> {
    let Some(k) = curve_type(kind) else {
        obj.nurbs_error(35);
        return None;
    };
    if ctl.is_empty() {
        obj.nurbs_error(36);
        return None;
    }
    if stride < 0 {
        obj.nurbs_error(34);
        return None;
    }
    let knots = match knot_vector(nknots, knots, order) {
        Ok(k) => k,
        Err(n) => {
            obj.nurbs_error(n);
            return None;
        }
    };
    let order = order as usize;
    let Some(points) = gather(ctl, knots.len() - order, stride as usize, k) else {
        obj.nurbs_error(8);
        return None;
    };
    Some(CurveMap { target: kind, k, order, knots, points })
}

/// GLU's checks for `gluNurbsSurface` (no NULL check in GLU; an empty slice is reported as
/// error 8 here, like any control array too short for the knots).
fn validate_surface(
    obj: &mut NurbsObject,
    s: (i32, &[f32], i32),
    t: (i32, &[f32], i32),
    (s_stride, t_stride): (i32, i32),
    ctl: &[f32],
    kind: GLenum,
) -> Option<SurfaceMap> {
    let Some(target) = crate::gl::MapTarget::from_enum(kind).filter(|t| t.dims == 2) else {
        obj.nurbs_error(35);
        return None;
    };
    if s_stride < 0 || t_stride < 0 {
        obj.nurbs_error(34);
        return None;
    }
    let uknots = knot_vector(s.0, s.1, s.2).map_err(|n| obj.nurbs_error(n)).ok()?;
    let vknots = knot_vector(t.0, t.1, t.2).map_err(|n| obj.nurbs_error(n)).ok()?;
    let k = target.components();
    let (uo, vo) = (s.2 as usize, t.2 as usize);
    let (nu, nv) = (uknots.len() - uo, vknots.len() - vo);
    let (ss, ts) = (s_stride as usize, t_stride as usize);
    let last = (nu - 1).checked_mul(ss).and_then(|a| (nv - 1).checked_mul(ts).and_then(|b| a.checked_add(b)));
    if last.and_then(|l| l.checked_add(k)).is_none_or(|need| ctl.len() < need) {
        obj.nurbs_error(8);
        return None;
    }
    let points = (0..nu)
        .flat_map(|i| (0..nv).flat_map(move |j| (0..k).map(move |c| i * ss + j * ts + c)))
        .map(|idx| f64::from(ctl[idx]))
        .collect();
    Some(SurfaceMap { target: kind, k, orders: (uo, vo), uknots, vknots, points })
}
