//! GLU's argument checks for `gluNurbsCurve`, `gluNurbsSurface` and `gluPwlCurve`, in GLU's
//! order and with its error numbers (spec 2.8): they turn C's strided float arrays into the
//! maps of the data model.

use crate::gl::types::*;
use crate::glu::model::maps::{CurveMap, SurfaceMap};
use crate::glu::model::object::NurbsObject;
use crate::glu::model::targets::curve_type;
use crate::math::knots::KnotVector;

/// Copies `count` points of `k` floats at `stride` floats; `None` if the slice is too short.
pub(super) fn gather(ctl: &[f32], count: usize, stride: usize, k: usize) -> Option<Vec<f64>> {
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

/// GLU's checks for `gluNurbsCurve`, reporting the first failure.
#[allow(clippy::too_many_arguments)]
pub(super) fn validate_curve(
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
pub(super) fn validate_surface(
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
