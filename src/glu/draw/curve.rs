//! Curves (`gluEndCurve`): the position map's Bezier pieces sampled per GLU's tolerance, then
//! `glMap1f`/`glMapGrid1f`/`glEvalMesh1` per span inside `glPushAttrib(GL_EVAL_BIT)`
//! (GLU `glcurveval.cc`), or line strips through the callbacks.

use crate::gl::consts::*;
use crate::gl::Gl;
use crate::glu::consts::*;
use crate::glu::evaluation::culling::culled;
use crate::glu::evaluation::machine::CurveMachine;
use crate::glu::evaluation::pieces::CurvePieces;
use crate::glu::evaluation::sampling::Sampler;
use crate::glu::model::maps::CurveMap;
use crate::glu::model::object::NurbsObject;
use crate::glu::model::targets::{attribute_rank, callback_kind, is_position};

/// A span of the curve, (r0, r1) in its parameter, and its segments.
type CurveSpan = ((f64, f64), usize);

/// Draws a curve (`gluEndCurve`).
pub(crate) fn draw_curve(gl: &mut Gl, obj: &mut NurbsObject, maps: &[CurveMap]) {
    let Some(position) = maps.iter().rev().find(|m| is_position(m.target)) else {
        return obj.nurbs_error(8);
    };
    if culled(obj, &position.points, position.k) {
        return;
    }
    let Some(pos) = CurvePieces::new(position) else { return obj.nurbs_error(8) };
    let mut all: Vec<CurvePieces> =
        maps.iter().filter(|m| !is_position(m.target)).filter_map(CurvePieces::new).collect();
    all.sort_by_key(|p| attribute_rank(p.target));
    let spans = spans(&pos, &Sampler::new(obj.props, &obj.matrices));
    if obj.props.nurbs_mode == GLU_NURBS_TESSELLATOR {
        for span in spans {
            tessellate_curve_span(gl, obj, &all, &pos, span);
        }
        return;
    }
    // GLU's `OpenGLCurveEvaluator::bgnmap1f`/`endmap1f`: the maps' enables and the grid are
    // the program's again afterwards.
    gl.push_attrib(GL_EVAL_BIT);
    for span in spans {
        render_curve_span(gl, &all, &pos, span);
    }
    gl.pop_attrib();
}

/// Every span GLU samples the position map with, piece by piece.
fn spans(pos: &CurvePieces, sampler: &Sampler) -> Vec<CurveSpan> {
    let mut out = Vec::new();
    for (index, &(a, b)) in pos.pieces.intervals.iter().enumerate() {
        let Some(points) = pos.pieces.piece(index) else { continue };
        for (t0, t1, nu) in sampler.curve_segments(points, pos.pieces.dim, pos.pieces.order, b - a) {
            out.push(((a + t0 * (b - a), a + t1 * (b - a)), nu));
        }
    }
    out
}

/// `glMap1f` for every map, `glMapGrid1f(nu, r0, r1)`, `glEvalMesh1(GL_LINE, 0, nu)`.
fn render_curve_span(gl: &mut Gl, attributes: &[CurvePieces], pos: &CurvePieces, ((r0, r1), nu): CurveSpan) {
    for map in attributes.iter().chain([pos]) {
        let Some(points) = map.on(r0, r1) else { continue };
        let points: Vec<f32> = points.iter().map(|&v| v as f32).collect();
        let (k, order) = (map.pieces.dim as i32, map.pieces.order as i32);
        gl.map1f(map.target, r0 as f32, r1 as f32, k, order, &points);
        gl.enable(map.target);
    }
    gl.map_grid1f(nu as i32, r0 as f32, r1 as f32);
    gl.eval_mesh1(GL_LINE, 0, nu as i32);
}

/// One `GL_LINE_STRIP` of nu + 1 vertices through the callbacks (GLU `inMapMesh1f`): u on
/// GLU's `f32` grid, every map evaluated by GLU's curve evaluator ([`CurveMachine`]) on the
/// whole Bezier piece holding the span, over the piece's breakpoints (`Quilt::downloadAll`
/// hands `curvpts` the piece, not a subdivision of it); the vertex is the raw k-vector (not
/// divided by w, as GLU does for curves).
fn tessellate_curve_span(
    gl: &mut Gl,
    obj: &mut NurbsObject,
    attributes: &[CurvePieces],
    pos: &CurvePieces,
    span: CurveSpan,
) {
    let ((r0, r1), nu) = span;
    let (u0, u1) = (r0 as f32, r1 as f32);
    let machines: Vec<(CurveMachine, u32, usize)> = attributes
        .iter()
        .chain([pos])
        .filter_map(|map| {
            let p = &map.pieces;
            let (points, (a, b)) = piece_for(map, (r0, r1))?;
            Some((CurveMachine::new(&points, p.dim, p.order, (a as f32, b as f32))?, callback_kind(map.target)?, p.dim))
        })
        .collect();
    let du = (u1 - u0) / nu as f32;
    obj.callbacks.begin(gl, GL_LINE_STRIP);
    for i in 0..=nu {
        let u = if i == nu { u1 } else { u0 + i as f32 * du };
        for (machine, kind, dim) in &machines {
            let Some(value) = machine.values(u) else { continue };
            obj.callbacks.attribute(gl, *kind, &value[..*dim]);
        }
    }
    obj.callbacks.end(gl);
}

/// The points and interval a map is evaluated on for a span: the piece holding it, or, where
/// the span crosses one of this map's breakpoints (GLU cuts the spans at every map's
/// breakpoints, `Quilt::getRange`; gleval only at the position map's), the map restricted to
/// the span.
fn piece_for(map: &CurvePieces, (r0, r1): (f64, f64)) -> Option<(Vec<f64>, (f64, f64))> {
    match map.containing(r0, r1) {
        Some((points, interval)) => Some((points.to_vec(), interval)),
        None => Some((map.on(r0, r1)?, (r0, r1))),
    }
}
