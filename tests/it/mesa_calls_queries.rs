//! The commands of `tests/reference/calls/queries.inc.c` on `Gl` (state queries and the
//! parameter forms beside them): `get`, `call NAME ...`, `getv NAME ...`, `get_tex_image`,
//! `get_polygon_stipple`. As in interp.c, how many values a query wrote is measured: the
//! buffer is filled with one pattern, then another, and the count is one past the last element
//! either run changed.

use super::Args;
use gleval::prelude::*;
use std::collections::HashMap;
use std::sync::OnceLock;

/// Every `GL_*` constant by name, read from the crate's table (`src/gl/consts.rs`).
pub(super) fn named_enum(token: &str) -> Option<u32> {
    static NAMES: OnceLock<HashMap<String, u32>> = OnceLock::new();
    let names = NAMES.get_or_init(|| {
        include_str!("../../src/gl/consts.rs")
            .lines()
            .filter_map(|line| {
                let rest = line.strip_prefix("pub const ")?;
                let (name, value) = rest.split_once(':')?;
                let value = value.split_once('=')?.1.trim().trim_end_matches(';').replace('_', "");
                let v = match value.strip_prefix("0x") {
                    Some(hex) => u32::from_str_radix(hex, 16).ok()?,
                    None => value.parse().ok()?,
                };
                Some((name.trim().to_owned(), v))
            })
            .collect()
    });
    names.get(token).copied()
}

/// Runs one of this file's commands; false if `cmd` is not one.
pub(super) fn run(gl: &mut Gl, cmd: &str, a: &mut Args, values: &mut Vec<String>) -> bool {
    match cmd {
        "get" => get(gl, a.e(), values),
        "call" => call(gl, a),
        "getv" => getv(gl, a, values),
        "get_tex_image" => {
            let (target, level, format, type_) = (a.e(), a.int(), a.e(), a.e());
            bytes(values, |out| gl.get_tex_image(target, level, format, type_, out));
        }
        "get_polygon_stipple" => bytes(values, |out| gl.get_polygon_stipple(out)),
        _ => return false,
    }
    true
}

/// The count of elements either run changed, from their bit patterns.
fn changed<T: Copy>(first: &[T], second: &[T], bits: impl Fn(T) -> u64, patterns: (u64, u64)) -> usize {
    let last = (0..first.len()).rev().find(|&k| bits(first[k]) != patterns.0 || bits(second[k]) != patterns.1);
    last.map_or(0, |k| k + 1)
}

/// Runs `query` on two buffers of `T` filled with `a` and `b`; the second with its count.
fn measured<T: Copy>(a: T, b: T, bits: impl Fn(T) -> u64, mut query: impl FnMut(&mut [T])) -> Vec<T> {
    let (mut first, mut second) = (vec![a; 32], vec![b; 32]);
    query(&mut first);
    query(&mut second);
    let n = changed(&first, &second, &bits, (bits(a), bits(b)));
    second.truncate(n);
    second
}

fn floats(values: &mut Vec<String>, v: impl IntoIterator<Item = f64>) {
    values.extend(v.into_iter().map(|x| x.to_string()));
}

fn get(gl: &mut Gl, pname: u32, values: &mut Vec<String>) {
    if matches!(pname, GL_RENDER_MODE | GL_FEEDBACK_BUFFER_SIZE | GL_FEEDBACK_BUFFER_TYPE) {
        // interp.c runs every case in feedback mode with a buffer of 4M floats.
        if gl.feedback_buffer_spec().0 == 0 {
            gl.feedback_buffer(1 << 22, GL_4D_COLOR_TEXTURE);
            gl.render_mode(GL_FEEDBACK);
        }
    }
    values.push("b".into());
    let b = measured(0xA5u8, 0x5A, u64::from, |o| gl.get_booleanv(pname, o));
    values.extend(b.iter().map(u8::to_string));
    values.push("i".into());
    let i = measured(0xA5A5_A5A5u32 as i32, 0x5A5A_5A5A, |v| u64::from(v as u32), |o| gl.get_integerv(pname, o));
    values.extend(i.iter().map(i32::to_string));
    values.push("f".into());
    let f = measured(
        f32::from_bits(0xA5A5_A5A5),
        f32::from_bits(0x5A5A_5A5A),
        |v| u64::from(v.to_bits()),
        |o| gl.get_floatv(pname, o),
    );
    floats(values, f.iter().map(|&x| f64::from(x)));
    values.push("d".into());
    let d = measured(f64::from_bits(0xA5A5_A5A5_A5A5_A5A5), f64::from_bits(0x5A5A_5A5A_5A5A_5A5A), f64::to_bits, |o| {
        gl.get_doublev(pname, o)
    });
    floats(values, d);
}

/// `[ v ... ]` or `null` as integers.
fn ints(a: &mut Args) -> Vec<i32> {
    a.array().iter().map(|&v| v as i32).collect()
}

fn call(gl: &mut Gl, a: &mut Args) {
    let name = a.next().to_owned();
    match name.as_str() {
        "glLightf" => gl.light_f(a.e(), a.e(), a.f()),
        "glLighti" => gl.light_i(a.e(), a.e(), a.int()),
        "glLightfv" => gl.light_fv(a.e(), a.e(), &a.floats()),
        "glLightiv" => gl.light_iv(a.e(), a.e(), &ints(a)),
        "glLightModelf" => gl.light_model_f(a.e(), a.f()),
        "glLightModeli" => gl.light_model_i(a.e(), a.int()),
        "glLightModelfv" => gl.light_model_fv(a.e(), &a.floats()),
        "glLightModeliv" => gl.light_model_iv(a.e(), &ints(a)),
        "glMaterialf" => gl.material_f(a.e(), a.e(), a.f()),
        "glMateriali" => gl.material_i(a.e(), a.e(), a.int()),
        "glMaterialfv" => gl.material_fv(a.e(), a.e(), &a.floats()),
        "glMaterialiv" => gl.material_iv(a.e(), a.e(), &ints(a)),
        "glFogf" => gl.fogf(a.e(), a.f()),
        "glFogi" => gl.fogi(a.e(), a.e() as i32),
        "glFogfv" => gl.fogfv(a.e(), &a.floats()),
        "glFogiv" => gl.fogiv(a.e(), &ints(a)),
        "glTexEnvf" => gl.tex_envf(a.e(), a.e(), a.f()),
        "glTexEnvi" => gl.tex_envi(a.e(), a.e(), a.e() as i32),
        "glTexEnvfv" => gl.tex_envfv(a.e(), a.e(), &a.floats()),
        "glTexEnviv" => gl.tex_enviv(a.e(), a.e(), &ints(a)),
        "glTexParameterf" => gl.tex_parameterf(a.e(), a.e(), a.f()),
        "glTexParameteri" => gl.tex_parameteri(a.e(), a.e(), a.e() as i32),
        "glTexParameterfv" => gl.tex_parameterfv(a.e(), a.e(), &a.floats()),
        "glTexParameteriv" => gl.tex_parameteriv(a.e(), a.e(), &ints(a)),
        "glTexGend" => gl.tex_gend(a.e(), a.e(), a.d()),
        "glTexGenf" => gl.tex_genf(a.e(), a.e(), a.f()),
        "glTexGeni" => gl.tex_geni(a.e(), a.e(), a.e() as i32),
        "glTexGendv" => gl.tex_gendv(a.e(), a.e(), &a.array()),
        "glTexGeniv" => gl.tex_geniv(a.e(), a.e(), &ints(a)),
        "glColorMaterial" => gl.color_material(a.e(), a.e()),
        "glShadeModel" => gl.shade_model(a.e()),
        "glMatrixMode" => gl.matrix_mode(a.e()),
        "glPushMatrix" => gl.push_matrix(),
        "glPopMatrix" => gl.pop_matrix(),
        "glViewport" => gl.viewport(a.int(), a.int(), a.int(), a.int()),
        "glDepthRange" => gl.depth_range(a.d(), a.d()),
        "glPointSize" => gl.point_size(a.f()),
        "glLineWidth" => gl.line_width(a.f()),
        "glFrontFace" => gl.front_face(a.e()),
        "glCullFace" => gl.cull_face(a.e()),
        "glPolygonMode" => gl.polygon_mode(a.e(), a.e()),
        "glDepthFunc" => gl.depth_func(a.e()),
        "glClearColor" => gl.clear_color(a.f(), a.f(), a.f(), a.f()),
        "glClearDepth" => gl.clear_depth(a.d()),
        "glPushClientAttrib" => gl.push_client_attrib(a.e()),
        "glPopClientAttrib" => gl.pop_client_attrib(),
        "glPixelStorei" => gl.pixel_storei(a.e(), a.int()),
        "glPixelStoref" => gl.pixel_storef(a.e(), a.f()),
        "glFrustum" => gl.frustum(a.d(), a.d(), a.d(), a.d(), a.d(), a.d()),
        "glOrtho" => gl.ortho(a.d(), a.d(), a.d(), a.d(), a.d(), a.d()),
        "glColor4f" => gl.color4f(a.f(), a.f(), a.f(), a.f()),
        "glNormal3f" => gl.normal3f(a.f(), a.f(), a.f()),
        "glEnable" => gl.enable(a.e()),
        "glDisable" => gl.disable(a.e()),
        "glBlendFunc" => gl.blend_func(a.e(), a.e()),
        "glBlendFuncSeparate" => gl.blend_func_separate(a.e(), a.e(), a.e(), a.e()),
        "glBlendEquation" => gl.blend_equation(a.e()),
        "glBlendEquationSeparate" => gl.blend_equation_separate(a.e(), a.e()),
        "glBlendColor" => gl.blend_color(a.f(), a.f(), a.f(), a.f()),
        "glSampleCoverage" => gl.sample_coverage(a.f(), a.int() as GLboolean),
        "glSecondaryColor3f" => gl.secondary_color3f(a.f(), a.f(), a.f()),
        "glHint" => gl.hint(a.e(), a.e()),
        "glAlphaFunc" => gl.alpha_func(a.e(), a.f()),
        "glPointParameterf" => gl.point_parameterf(a.e(), a.f()),
        "glPointParameterfv" => gl.point_parameterfv(a.e(), &a.floats()),
        "glPointParameteri" => gl.point_parameteri(a.e(), a.int()),
        "glPointParameteriv" => gl.point_parameteriv(a.e(), &ints(a)),
        "glFogCoordf" => gl.fog_coordf(a.f()),
        "glFogCoordd" => gl.fog_coordd(a.d()),
        "glFogCoordfv" => gl.fog_coordfv(&a.floats()),
        "glFogCoorddv" => gl.fog_coorddv(&a.array()),
        "glCompressedTexImage1D" => {
            let (target, level, internal, width, border, size) = (a.e(), a.int(), a.e(), a.int(), a.int(), a.int());
            let data: Vec<u8> = ints(a).iter().flat_map(|v| v.to_ne_bytes()).collect();
            gl.compressed_tex_image_1d(target, level, internal, width, border, size, &data);
        }
        "glCompressedTexImage2D" => {
            let (target, level, internal) = (a.e(), a.int(), a.e());
            let (width, height, border, size) = (a.int(), a.int(), a.int(), a.int());
            let data: Vec<u8> = ints(a).iter().flat_map(|v| v.to_ne_bytes()).collect();
            gl.compressed_tex_image_2d(target, level, internal, width, height, border, size, &data);
        }
        "glCompressedTexSubImage2D" => {
            let (target, level, x, y, width, height) = (a.e(), a.int(), a.int(), a.int(), a.int(), a.int());
            let (format, size) = (a.e(), a.int());
            let data: Vec<u8> = ints(a).iter().flat_map(|v| v.to_ne_bytes()).collect();
            gl.compressed_tex_sub_image_2d(target, level, [x, y], [width, height], format, size, &data);
        }
        "glResetHistogram" => gl.reset_histogram(a.e()),
        "glResetMinmax" => gl.reset_minmax(a.e()),
        "glMinmax" => gl.minmax(a.e(), a.e(), a.int() as GLboolean),
        "glHistogram" => gl.histogram(a.e(), a.int(), a.e(), a.int() as GLboolean),
        "glConvolutionParameteri" => gl.convolution_parameteri(a.e(), a.e(), a.e() as GLint),
        "glConvolutionParameterf" => gl.convolution_parameterf(a.e(), a.e(), a.f()),
        "glConvolutionParameterfv" => gl.convolution_parameterfv(a.e(), a.e(), &a.floats()),
        "glColorTableParameteriv" => gl.color_table_parameteriv(a.e(), a.e(), &ints(a)),
        "glTexImage1D" => {
            let (target, level, internal, width, border, format, type_) =
                (a.e(), a.int(), a.e() as i32, a.int(), a.int(), a.e(), a.e());
            gl.tex_image_1d(target, level, internal, width, border, format, type_, &a.floats());
        }
        "glActiveTexture" => gl.active_texture(a.e()),
        "glClientActiveTexture" => gl.client_active_texture(a.e()),
        "glMultiTexCoord4f" => gl.multi_tex_coord4f(a.e(), a.f(), a.f(), a.f(), a.f()),
        "glMultiTexCoord2f" => gl.multi_tex_coord2f(a.e(), a.f(), a.f()),
        "glMultiTexCoord1d" => gl.multi_tex_coord1d(a.e(), a.d()),
        "glMultiTexCoord3i" => gl.multi_tex_coord3i(a.e(), a.int(), a.int(), a.int()),
        "glMultiTexCoord4s" => {
            let target = a.e();
            let [s, t, r, q] = [(); 4].map(|()| a.int() as GLshort);
            gl.multi_tex_coord4s(target, s, t, r, q);
        }
        "glMultiTexCoord2fv" => gl.multi_tex_coord2fv(a.e(), &a.floats()),
        "glMultiTexCoord3dv" => gl.multi_tex_coord3dv(a.e(), &a.array()),
        "glMultiTexCoord4iv" => gl.multi_tex_coord4iv(a.e(), &ints(a)),
        "glEnableClientState" => gl.enable_client_state(a.e()),
        "glDisableClientState" => gl.disable_client_state(a.e()),
        "glLoadIdentity" => gl.load_identity(),
        "glTranslatef" => gl.translatef(a.f(), a.f(), a.f()),
        "glRasterPos2f" => gl.raster_pos2f(a.f(), a.f()),
        other => panic!("call {other} not emulated"),
    }
}

fn getv(gl: &mut Gl, a: &mut Args, values: &mut Vec<String>) {
    let name = a.next().to_owned();
    let f_pattern = (f32::from_bits(0xA5A5_A5A5), f32::from_bits(0x5A5A_5A5A));
    let i_pattern = (0xA5A5_A5A5u32 as i32, 0x5A5A_5A5A);
    let d_pattern = (f64::from_bits(0xA5A5_A5A5_A5A5_A5A5), f64::from_bits(0x5A5A_5A5A_5A5A_5A5A));
    let fbits = |v: f32| u64::from(v.to_bits());
    let ibits = |v: i32| u64::from(v as u32);
    macro_rules! f {
        ($($arg:expr),* => $method:ident) => {{
            let args = ($($arg,)*);
            let v = measured(f_pattern.0, f_pattern.1, fbits, |o| f!(@call gl, $method, args, o, $($arg),*));
            floats(values, v.iter().map(|&x| f64::from(x)));
        }};
        (@call $gl:ident, $method:ident, $args:ident, $o:ident, $a:expr, $b:expr) => { $gl.$method($args.0, $args.1, $o) };
        (@call $gl:ident, $method:ident, $args:ident, $o:ident, $a:expr, $b:expr, $c:expr) => { $gl.$method($args.0, $args.1, $args.2, $o) };
    }
    macro_rules! i {
        ($($arg:expr),* => $method:ident) => {{
            let args = ($($arg,)*);
            let v = measured(i_pattern.0, i_pattern.1, ibits, |o| f!(@call gl, $method, args, o, $($arg),*));
            values.extend(v.iter().map(i32::to_string));
        }};
    }
    macro_rules! d {
        ($($arg:expr),* => $method:ident) => {{
            let args = ($($arg,)*);
            let v = measured(d_pattern.0, d_pattern.1, f64::to_bits, |o| f!(@call gl, $method, args, o, $($arg),*));
            floats(values, v);
        }};
    }
    match name.as_str() {
        "glGetLightfv" => f!(a.e(), a.e() => get_light_fv),
        "glGetLightiv" => i!(a.e(), a.e() => get_light_iv),
        "glGetMaterialfv" => f!(a.e(), a.e() => get_material_fv),
        "glGetMaterialiv" => i!(a.e(), a.e() => get_material_iv),
        "glGetTexEnvfv" => f!(a.e(), a.e() => get_tex_envfv),
        "glGetTexEnviv" => i!(a.e(), a.e() => get_tex_enviv),
        "glGetTexParameterfv" => f!(a.e(), a.e() => get_tex_parameterfv),
        "glGetTexParameteriv" => i!(a.e(), a.e() => get_tex_parameteriv),
        "glGetTexLevelParameterfv" => f!(a.e(), a.int(), a.e() => get_tex_level_parameterfv),
        "glGetTexLevelParameteriv" => i!(a.e(), a.int(), a.e() => get_tex_level_parameteriv),
        "glGetTexGenfv" => f!(a.e(), a.e() => get_tex_genfv),
        "glGetTexGeniv" => i!(a.e(), a.e() => get_tex_geniv),
        "glGetTexGendv" => d!(a.e(), a.e() => get_tex_gendv),
        "glGetMapdv" => d!(a.e(), a.e() => get_mapdv),
        "glGetHistogramParameteriv" => i!(a.e(), a.e() => get_histogram_parameteriv),
        "glGetMinmaxParameterfv" => f!(a.e(), a.e() => get_minmax_parameterfv),
        "glGetConvolutionParameteriv" => i!(a.e(), a.e() => get_convolution_parameteriv),
        "glGetColorTableParameterfv" => f!(a.e(), a.e() => get_color_table_parameterfv),
        "glGetCompressedTexImage" => {
            let (target, level) = (a.e(), a.int());
            bytes(values, |o| gl.get_compressed_tex_image(target, level, o));
        }
        "glGetClipPlane" => {
            let plane = a.e();
            let v = measured(d_pattern.0, d_pattern.1, f64::to_bits, |o| gl.get_clip_plane(plane, o));
            floats(values, v);
        }
        other => panic!("getv {other} not emulated"),
    }
}

/// A query writing bytes, printed in hex as interp.c prints them.
fn bytes(values: &mut Vec<String>, mut query: impl FnMut(&mut [u8])) {
    let (mut first, mut second) = (vec![0xA5u8; 512], vec![0x5Au8; 512]);
    query(&mut first);
    query(&mut second);
    let n = changed(&first, &second, u64::from, (0xA5, 0x5A));
    if n > 0 {
        values.push(second[..n].iter().map(|b| format!("{b:02x}")).collect());
    }
}
