//! The math core: Bezier and B-spline curves and tensor-product patches, knot vectors,
//! knot insertion and Bezier decomposition, rational (homogeneous) points.
//!
//! Nothing here knows GL or the GPU. Everything is generic over [`Scalar`] (`f32` for the GL
//! façade, which like Mesa evaluates in single precision; `f64` as the oracle in tests).
//! Control points are flat slices with `dim` (1..=4, GL's component counts) values per point.

pub mod bezier;
pub mod bezier_ops;
pub mod bspline;
pub mod hermite;
pub mod insertion;
pub mod interpolate;
pub mod knots;
pub mod patch;
pub mod rational;
pub mod scalar;
pub mod shapes;
pub mod spline;
pub mod teapot;

pub use bezier::{BezierCurve, Vec4, MAX_DIM};
pub use bezier_ops::Frenet;
pub use hermite::HermiteCurve;
pub use patch::{BezierPatch, PatchSample, MAX_ORDER};
pub use scalar::Scalar;
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
pub use bspline::{BSplineCurve, BSplineSurface, ProjectedSample};
pub use insertion::{BezierPatches, BezierPieces, Direction};
pub use knots::{GluKnotError, KnotVector};
