//! What a `glGet` row is (Mesa's `get_hash_params.py`: a name, how many values, how Mesa stores
//! them, where the value lives) and how Mesa 22.3's `main/get.c` converts a stored value for
//! `glGetIntegerv`. A leaf: each attribute group's file writes its `GET_ROWS` with these, and
//! `get` gathers the rows and answers the queries, so that no group imports `get`.

use super::types::*;
use super::Gl;

/// How Mesa stores a state variable (`main/get.c`'s `TYPE_*`), which decides its conversions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    /// `TYPE_BOOLEAN`: a `GLboolean` as Mesa keeps it (0 or 1, or the byte a call gave, as
    /// `glSampleCoverage`'s invert): `glGetBooleanv`, `glGetIntegerv` and `glGetDoublev` give
    /// the byte, `glGetFloatv` 0 or 1.
    Bool,
    /// `TYPE_INT`, `TYPE_ENUM`: exact in every variant.
    Int,
    /// `TYPE_FLOAT`: `glGetIntegerv` rounds (`IROUND`).
    Float,
    /// `TYPE_FLOATN`, `TYPE_DOUBLEN`, `TYPE_MATRIX`: `glGetIntegerv` scales by 2³¹ − 1
    /// (`FLOAT_TO_INT`): colours, normals, the depth range and clear value, the alpha
    /// reference, and the matrices.
    Normalized,
}

/// One state variable: `read` writes its first `count` values.
#[derive(Clone, Copy)]
pub(crate) struct StateVar {
    pub name: GLenum,
    pub count: usize,
    pub kind: Kind,
    pub read: fn(&Gl, &mut [f64]),
}

/// A row: `glGet(name)` is `count` values of `kind`, written by `read`.
pub(crate) const fn row(name: GLenum, count: usize, kind: Kind, read: fn(&Gl, &mut [f64])) -> StateVar {
    StateVar { name, count, kind, read }
}

/// A constant (an implementation limit).
macro_rules! limit {
    ($name:expr, $($v:expr),+) => {
        $crate::gl::state_var::row($name, [$($v as f64),+].len(), $crate::gl::state_var::Kind::Float, |_, o| {
            let values = [$($v as f64),+];
            o[..values.len()].copy_from_slice(&values);
        })
    };
}

/// An integer limit.
macro_rules! int_limit {
    ($name:expr, $($v:expr),+) => {
        $crate::gl::state_var::StateVar { kind: $crate::gl::state_var::Kind::Int, ..$crate::gl::state_var::limit!($name, $($v),+) }
    };
}
pub(crate) use {int_limit, limit};

/// Writes `values` as the answer.
pub(crate) fn put<T: Copy + Into<f64>>(o: &mut [f64], values: &[T]) {
    for (out, v) in o.iter_mut().zip(values) {
        *out = (*v).into();
    }
}

/// Writes an enum (or any one integer) as the answer.
pub(crate) fn put_enum(o: &mut [f64], e: GLenum) {
    o[0] = f64::from(e);
}

/// Writes a flag as the answer (0 or 1).
pub(crate) fn put_flag(o: &mut [f64], b: bool) {
    o[0] = f64::from(u8::from(b));
}

/// Mesa's `FLOAT_TO_INT` (`main/macros.h`) for normalised values (colours, normals, the depth
/// range, and, as Mesa's `TYPE_MATRIX` does, matrices): v · (2³¹ − 1) truncated. A value outside
/// [−1, 1] overflows C's conversion, which gives `INT_MIN` on the machines Mesa runs on (x86's
/// "integer indefinite"); so does this.
pub(crate) fn float_to_int(v: f64) -> GLint {
    let x = v * f64::from(GLint::MAX);
    if !(-2_147_483_648.0..2_147_483_648.0).contains(&x) {
        GLint::MIN
    } else {
        x as GLint
    }
}

/// Mesa's `IROUND` for floats in `glGetIntegerv`: `(int) lroundf(v)`, halves away from zero,
/// the 64-bit `long` then cut to 32 bits (a line width of 3·10⁹ reads back as −1294967296 on
/// Mesa 22.3; measured). Beyond a `long`, x86 gives `LONG_MIN`, whose low half is 0.
pub(crate) fn iround(v: f64) -> GLint {
    let r = v.round();
    if r.abs() < 9.223_372_036_854_776e18 {
        r as i64 as GLint
    } else {
        0
    }
}

impl Kind {
    /// `glGetIntegerv`'s value (Mesa `_mesa_GetIntegerv`).
    pub(crate) fn to_int(self, v: f64) -> GLint {
        match self {
            Kind::Bool | Kind::Int => v as GLint,
            Kind::Float => iround(v),
            Kind::Normalized => float_to_int(v),
        }
    }
}

/// C's `(GLint) f` on x86: truncation, and `INT_MIN` for what does not fit (NaN included).
pub(crate) fn c_int(v: f32) -> GLint {
    if v.is_nan() || !(-2_147_483_648.0..2_147_483_648.0).contains(&v) {
        GLint::MIN
    } else {
        v as GLint
    }
}
