//! The flat-slice kernels under the typed curves and patches: control points as `&[S]` with
//! `dim` values (1..=4) per point, in GL's layout, so GL's maps are evaluated without copying.
//!
//! Bezier: Horner's rule as Mesa evaluates (`m_eval.c`), de Casteljau, derivatives, hodograph,
//! split, degree elevation, the Bernstein basis. Patches: the tensor-product Horner and the
//! point with its partials. B-splines: span search, basis functions and their derivatives (The
//! NURBS Book A2.1–A2.3), curve points; knot insertion and refinement (A5.1, A5.4) and Bezier
//! decomposition (A5.6). Rational points: projection and the rational derivative. Hermite basis.
//! Interpolation parameters.

pub use super::bezier::{
    bernstein, bernstein_with_derivative, de_casteljau, derivative, elevate, hodograph, horner, split,
};
pub use super::bspline::{
    basis_funs, basis_with_derivative, curve_derivative, curve_point, curve_point_and_derivative, ders_basis_funs,
};
pub use super::hermite::hermite_basis;
pub use super::insertion::{decompose_curve, decompose_surface, insert_knot, refine_knots};
pub use super::interpolate::parameters;
pub use super::knots::find_span;
pub use super::patch::{horner_patch, patch_with_partials};
pub use super::rational::{cross, normalize, project, rational_derivative};
