//! The imaging subset of GL 1.2 (§3.6.2 colour tables, §3.6.3 convolution, §3.6.4 colour
//! matrix aside, §3.6.5 histogram and minmax) as Mesa exposes it.
//!
//! The subset is optional: a GL supports it only when `GL_ARB_imaging` is in `GL_EXTENSIONS`
//! (GL 1.2 §3.6.2). Mesa dropped it (22.3 here: llvmpipe does not list `GL_ARB_imaging`) but
//! keeps the entry points in its dispatch table, where each one raises
//! `GL_INVALID_OPERATION` and touches nothing, whatever its arguments, inside or outside
//! `glBegin`, and even while a display list is being compiled (the error is raised then, and
//! nothing is compiled): measured with OSMesa on llvmpipe. gleval answers the same, so a program
//! that probes for the subset by calling it sees what it sees on Mesa. The enables
//! (`GL_COLOR_TABLE`, `GL_CONVOLUTION_1D`, `GL_HISTOGRAM`, ...) and their `glGet` names are
//! unknown names, `GL_INVALID_ENUM`, as on Mesa.
//!
//! The blending part of the subset (`glBlendColor`, `glBlendEquation`) is in `blend.rs`: GL 1.4
//! made it core, and Mesa implements it.

use super::types::*;
use super::Gl;

/// One `Gl` method per entry point of the subset, each answering as Mesa's does.
macro_rules! not_exposed {
    ($($(#[$doc:meta])* fn $name:ident($($arg:ident: $t:ty),* $(,)?);)*) => {
        impl Gl {
            $(
                $(#[$doc])*
                #[allow(clippy::too_many_arguments)]
                pub fn $name(&mut self, $($arg: $t),*) {
                    let _ = ($($arg),*);
                    self.imaging_not_exposed();
                }
            )*
        }
    };
}

impl Gl {
    /// What every entry point of the subset does on Mesa (see the module).
    fn imaging_not_exposed(&mut self) {
        self.set_error(super::consts::GL_INVALID_OPERATION);
    }
}

not_exposed! {
    /// `glColorTable` (GL 1.2 §3.6.2): `GL_INVALID_OPERATION` (see the module).
    fn color_table(target: GLenum, internalformat: GLenum, width: GLsizei, format: GLenum, type_: GLenum, table: &[u8]);
    /// `glColorSubTable`: `GL_INVALID_OPERATION` (see the module).
    fn color_sub_table(target: GLenum, start: GLsizei, count: GLsizei, format: GLenum, type_: GLenum, data: &[u8]);
    /// `glColorTableParameterfv`: `GL_INVALID_OPERATION` (see the module).
    fn color_table_parameterfv(target: GLenum, pname: GLenum, params: &[GLfloat]);
    /// `glColorTableParameteriv`: `GL_INVALID_OPERATION` (see the module).
    fn color_table_parameteriv(target: GLenum, pname: GLenum, params: &[GLint]);
    /// `glCopyColorTable`: `GL_INVALID_OPERATION` (see the module).
    fn copy_color_table(target: GLenum, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei);
    /// `glCopyColorSubTable`: `GL_INVALID_OPERATION` (see the module).
    fn copy_color_sub_table(target: GLenum, start: GLsizei, x: GLint, y: GLint, width: GLsizei);
    /// `glGetColorTable`: `GL_INVALID_OPERATION`, `table` untouched (see the module).
    fn get_color_table(target: GLenum, format: GLenum, type_: GLenum, table: &mut [u8]);
    /// `glGetColorTableParameterfv`: `GL_INVALID_OPERATION`, `params` untouched (see the module).
    fn get_color_table_parameterfv(target: GLenum, pname: GLenum, params: &mut [GLfloat]);
    /// `glGetColorTableParameteriv`: `GL_INVALID_OPERATION`, `params` untouched (see the module).
    fn get_color_table_parameteriv(target: GLenum, pname: GLenum, params: &mut [GLint]);
    /// `glConvolutionFilter1D` (GL 1.2 §3.6.3): `GL_INVALID_OPERATION` (see the module).
    fn convolution_filter_1d(target: GLenum, internalformat: GLenum, width: GLsizei, format: GLenum, type_: GLenum, image: &[u8]);
    /// `glConvolutionFilter2D`: `GL_INVALID_OPERATION` (see the module).
    fn convolution_filter_2d(target: GLenum, internalformat: GLenum, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, image: &[u8]);
    /// `glSeparableFilter2D`: `GL_INVALID_OPERATION` (see the module).
    fn separable_filter_2d(target: GLenum, internalformat: GLenum, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, row: &[u8], column: &[u8]);
    /// `glConvolutionParameterf`: `GL_INVALID_OPERATION` (see the module).
    fn convolution_parameterf(target: GLenum, pname: GLenum, param: GLfloat);
    /// `glConvolutionParameterfv`: `GL_INVALID_OPERATION` (see the module).
    fn convolution_parameterfv(target: GLenum, pname: GLenum, params: &[GLfloat]);
    /// `glConvolutionParameteri`: `GL_INVALID_OPERATION` (see the module).
    fn convolution_parameteri(target: GLenum, pname: GLenum, param: GLint);
    /// `glConvolutionParameteriv`: `GL_INVALID_OPERATION` (see the module).
    fn convolution_parameteriv(target: GLenum, pname: GLenum, params: &[GLint]);
    /// `glCopyConvolutionFilter1D`: `GL_INVALID_OPERATION` (see the module).
    fn copy_convolution_filter_1d(target: GLenum, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei);
    /// `glCopyConvolutionFilter2D`: `GL_INVALID_OPERATION` (see the module).
    fn copy_convolution_filter_2d(target: GLenum, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei, height: GLsizei);
    /// `glGetConvolutionFilter`: `GL_INVALID_OPERATION`, `image` untouched (see the module).
    fn get_convolution_filter(target: GLenum, format: GLenum, type_: GLenum, image: &mut [u8]);
    /// `glGetSeparableFilter`: `GL_INVALID_OPERATION`, nothing written (see the module).
    fn get_separable_filter(target: GLenum, format: GLenum, type_: GLenum, row: &mut [u8], column: &mut [u8], span: &mut [u8]);
    /// `glGetConvolutionParameterfv`: `GL_INVALID_OPERATION`, `params` untouched (see the module).
    fn get_convolution_parameterfv(target: GLenum, pname: GLenum, params: &mut [GLfloat]);
    /// `glGetConvolutionParameteriv`: `GL_INVALID_OPERATION`, `params` untouched (see the module).
    fn get_convolution_parameteriv(target: GLenum, pname: GLenum, params: &mut [GLint]);
    /// `glHistogram` (GL 1.2 §3.6.5): `GL_INVALID_OPERATION` (see the module).
    fn histogram(target: GLenum, width: GLsizei, internalformat: GLenum, sink: GLboolean);
    /// `glResetHistogram`: `GL_INVALID_OPERATION` (see the module).
    fn reset_histogram(target: GLenum);
    /// `glGetHistogram`: `GL_INVALID_OPERATION`, `values` untouched (see the module).
    fn get_histogram(target: GLenum, reset: GLboolean, format: GLenum, type_: GLenum, values: &mut [u8]);
    /// `glGetHistogramParameterfv`: `GL_INVALID_OPERATION`, `params` untouched (see the module).
    fn get_histogram_parameterfv(target: GLenum, pname: GLenum, params: &mut [GLfloat]);
    /// `glGetHistogramParameteriv`: `GL_INVALID_OPERATION`, `params` untouched (see the module).
    fn get_histogram_parameteriv(target: GLenum, pname: GLenum, params: &mut [GLint]);
    /// `glMinmax`: `GL_INVALID_OPERATION` (see the module).
    fn minmax(target: GLenum, internalformat: GLenum, sink: GLboolean);
    /// `glResetMinmax`: `GL_INVALID_OPERATION` (see the module).
    fn reset_minmax(target: GLenum);
    /// `glGetMinmax`: `GL_INVALID_OPERATION`, `values` untouched (see the module).
    fn get_minmax(target: GLenum, reset: GLboolean, format: GLenum, type_: GLenum, values: &mut [u8]);
    /// `glGetMinmaxParameterfv`: `GL_INVALID_OPERATION`, `params` untouched (see the module).
    fn get_minmax_parameterfv(target: GLenum, pname: GLenum, params: &mut [GLfloat]);
    /// `glGetMinmaxParameteriv`: `GL_INVALID_OPERATION`, `params` untouched (see the module).
    fn get_minmax_parameteriv(target: GLenum, pname: GLenum, params: &mut [GLint]);
}
