//! The math core: Bezier and B-spline curves and tensor-product patches, knot vectors,
//! knot insertion and Bezier decomposition, rational (homogeneous) points, Hermite curves,
//! natural cubic splines, interpolation, and the NURBS constructions of seed 002 (the exact
//! circle, revolution, extrusion).
//!
//! Nothing here knows GL or the GPU. Everything is generic over [`Scalar`] (`f32` for the GL
//! façade, which like Mesa evaluates in single precision; `f64` as the oracle in tests).
//!
//! Every type lives at one path, `gleval::math::Name`. The typed curves and patches are the way
//! in; the flat-slice kernels they are built on (control points as `&[S]` with `dim` values,
//! 1..=4, per point, as GL stores them) are in [`kernel`] for code that works on GL's layout.

pub(crate) mod bezier;
pub(crate) mod bezier_ops;
pub(crate) mod bspline;
pub(crate) mod hermite;
pub(crate) mod insertion;
pub(crate) mod interpolate;
pub mod kernel;
pub(crate) mod knots;
pub(crate) mod patch;
pub(crate) mod rational;
pub(crate) mod scalar;
pub(crate) mod shapes;
pub(crate) mod spline;

pub use bezier::{BezierCurve, Vec4, MAX_DIM};
pub use bezier_ops::Frenet;
pub use bspline::{BSplineCurve, BSplineSurface, Basis, ProjectedSample};
pub use hermite::HermiteCurve;
pub use insertion::{BezierPatches, BezierPieces, Direction, KnotsAndPoints};
pub use interpolate::{interpolate, Parameterization};
pub use knots::{GluKnotError, KnotVector, GLU_MAX_ORDER, GLU_TOLERANCE};
pub use patch::{BezierPatch, PatchSample, MAX_ORDER};
pub use scalar::Scalar;
pub use shapes::{extrude, nurbs_circle, revolve};
pub use spline::CubicSpline;

/// What the typed math API rejects.
#[derive(Clone, Debug, PartialEq)]
pub enum MathError {
    /// Components per point outside 1..=4.
    BadDimension(usize),
    /// Order outside the supported range.
    BadOrder(usize),
    /// The number of values is not what the shape needs.
    PointCount {
        /// Values given.
        len: usize,
        /// Components per point.
        dim: usize,
    },
    /// A knot vector GLU would reject, with GLU's reason.
    Knots(&'static str),
    /// A parameter outside the curve's valid range.
    OutOfRange,
    /// Interpolation data that cannot define the curve, and why.
    BadData(&'static str),
}

impl core::fmt::Display for MathError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::BadDimension(d) => write!(f, "points must have 1 to 4 components, got {d}"),
            Self::BadOrder(o) => write!(f, "order {o} is outside the supported range"),
            Self::PointCount { len, dim } => {
                write!(f, "{len} values do not make whole points of {dim} components")
            }
            Self::Knots(why) => write!(f, "invalid knot vector: {why}"),
            Self::OutOfRange => write!(f, "parameter outside the valid range"),
            Self::BadData(why) => write!(f, "invalid data: {why}"),
        }
    }
}

impl std::error::Error for MathError {}
