//! The imaging subset's entry points (`Gl`'s `imaging.rs`): Mesa keeps them in its dispatch
//! table, each raising `GL_INVALID_OPERATION` without reading or writing its pointers; gleval's
//! do the same, so the pointers travel as empty slices.

use gleval::gl::types::*;
use std::ffi::c_void;

/// An entry point whose trailing pointer arguments the call never touches (see the module): the
/// scalars go to the `Gl` method, each pointer as an empty slice of the method's element type.
macro_rules! pointers_untouched {
    ($($name:ident($($a:ident: $t:ty),*; $($p:ident: $pt:ty),+) => $method:ident($($empty:expr),+);)*) => {
        $(entry! {
            #[doc = concat!("`", stringify!($name), "`: `Gl::", stringify!($method), "` (its pointers untouched).")]
            #[allow(clippy::too_many_arguments)]
            fn $name($($a: $t),*, $($p: $pt),+) {
                let _ = ($($p),+);
                $crate::context::with_gl(|gl| gl.$method($($a),*, $($empty),+))
            }
        })*
    };
}

pointers_untouched! {
    glColorTable(target: GLenum, internalformat: GLenum, width: GLsizei, format: GLenum, type_: GLenum; table: *const c_void) => color_table(&[]);
    glColorSubTable(target: GLenum, start: GLsizei, count: GLsizei, format: GLenum, type_: GLenum; data: *const c_void) => color_sub_table(&[]);
    glColorTableParameterfv(target: GLenum, pname: GLenum; params: *const GLfloat) => color_table_parameterfv(&[]);
    glColorTableParameteriv(target: GLenum, pname: GLenum; params: *const GLint) => color_table_parameteriv(&[]);
    glGetColorTable(target: GLenum, format: GLenum, type_: GLenum; table: *mut c_void) => get_color_table(&mut []);
    glGetColorTableParameterfv(target: GLenum, pname: GLenum; params: *mut GLfloat) => get_color_table_parameterfv(&mut []);
    glGetColorTableParameteriv(target: GLenum, pname: GLenum; params: *mut GLint) => get_color_table_parameteriv(&mut []);
    glConvolutionFilter1D(target: GLenum, internalformat: GLenum, width: GLsizei, format: GLenum, type_: GLenum; image: *const c_void) => convolution_filter_1d(&[]);
    glConvolutionFilter2D(target: GLenum, internalformat: GLenum, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum; image: *const c_void) => convolution_filter_2d(&[]);
    glSeparableFilter2D(target: GLenum, internalformat: GLenum, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum; row: *const c_void, column: *const c_void) => separable_filter_2d(&[], &[]);
    glConvolutionParameterfv(target: GLenum, pname: GLenum; params: *const GLfloat) => convolution_parameterfv(&[]);
    glConvolutionParameteriv(target: GLenum, pname: GLenum; params: *const GLint) => convolution_parameteriv(&[]);
    glGetConvolutionFilter(target: GLenum, format: GLenum, type_: GLenum; image: *mut c_void) => get_convolution_filter(&mut []);
    glGetSeparableFilter(target: GLenum, format: GLenum, type_: GLenum; row: *mut c_void, column: *mut c_void, span: *mut c_void) => get_separable_filter(&mut [], &mut [], &mut []);
    glGetConvolutionParameterfv(target: GLenum, pname: GLenum; params: *mut GLfloat) => get_convolution_parameterfv(&mut []);
    glGetConvolutionParameteriv(target: GLenum, pname: GLenum; params: *mut GLint) => get_convolution_parameteriv(&mut []);
    glGetHistogram(target: GLenum, reset: GLboolean, format: GLenum, type_: GLenum; values: *mut c_void) => get_histogram(&mut []);
    glGetHistogramParameterfv(target: GLenum, pname: GLenum; params: *mut GLfloat) => get_histogram_parameterfv(&mut []);
    glGetHistogramParameteriv(target: GLenum, pname: GLenum; params: *mut GLint) => get_histogram_parameteriv(&mut []);
    glGetMinmax(target: GLenum, reset: GLboolean, format: GLenum, type_: GLenum; values: *mut c_void) => get_minmax(&mut []);
    glGetMinmaxParameterfv(target: GLenum, pname: GLenum; params: *mut GLfloat) => get_minmax_parameterfv(&mut []);
    glGetMinmaxParameteriv(target: GLenum, pname: GLenum; params: *mut GLint) => get_minmax_parameteriv(&mut []);
}

forward! {
    glCopyColorTable(target: GLenum, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei) => copy_color_table;
    glCopyColorSubTable(target: GLenum, start: GLsizei, x: GLint, y: GLint, width: GLsizei) => copy_color_sub_table;
    glConvolutionParameterf(target: GLenum, pname: GLenum, param: GLfloat) => convolution_parameterf;
    glConvolutionParameteri(target: GLenum, pname: GLenum, param: GLint) => convolution_parameteri;
    glCopyConvolutionFilter1D(target: GLenum, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei) => copy_convolution_filter_1d;
    glCopyConvolutionFilter2D(target: GLenum, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei, height: GLsizei) => copy_convolution_filter_2d;
    glHistogram(target: GLenum, width: GLsizei, internalformat: GLenum, sink: GLboolean) => histogram;
    glResetHistogram(target: GLenum) => reset_histogram;
    glMinmax(target: GLenum, internalformat: GLenum, sink: GLboolean) => minmax;
    glResetMinmax(target: GLenum) => reset_minmax;
}
