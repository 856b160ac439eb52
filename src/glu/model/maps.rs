//! The geometry GLU keeps from `gluNurbsCurve`, `gluNurbsSurface` and `gluPwlCurve`: validated
//! maps (knots and control points as f64), trim pieces, and the surface being defined.

use crate::gl::types::GLenum;

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
