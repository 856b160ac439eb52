//! The state variables `glGet` answers (GL 1.1 spec §6.2, tables 6.3–6.20, and the few later
//! names gleval implements), one row each: the name, how many values, how Mesa stores them
//! (which decides every conversion) and where the value lives. A row whose state belongs to an
//! area that keeps its own (stencil, accumulation, selection, vertex arrays, pixel transfer)
//! says [`Source::Hook`]: that area answers it from its `AREA_query` function, called by
//! `Gl::query`, and the row still gives its type. Enables are not rows: every capability
//! `glIsEnabled` knows is a one-value boolean (`Gl::lookup`).
//!
//! The limits are llvmpipe's as Mesa 22.3 reports them through OSMesa (measured with
//! `glGetDoublev`; the same figures are in `tests/reference/calls/expected/queries.out`).

use super::super::consts::*;
use super::super::types::*;
use super::super::Gl;

/// How Mesa stores a state variable (`main/get.c`'s `TYPE_*`), which decides its conversions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    /// `TYPE_BOOLEAN`: 0 or 1.
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

/// Where a state variable's value comes from.
#[derive(Clone, Copy)]
pub(crate) enum Source {
    /// Read from `Gl` into the first `count` values.
    Read(fn(&Gl, &mut [f64])),
    /// Answered by the area that owns the state, through `Gl::query`.
    Hook,
}

/// One state variable.
#[derive(Clone, Copy)]
pub(crate) struct StateVar {
    pub name: GLenum,
    pub count: usize,
    pub kind: Kind,
    pub source: Source,
}

const fn row(name: GLenum, count: usize, kind: Kind, read: fn(&Gl, &mut [f64])) -> StateVar {
    StateVar { name, count, kind, source: Source::Read(read) }
}

const fn hook(name: GLenum, count: usize, kind: Kind) -> StateVar {
    StateVar { name, count, kind, source: Source::Hook }
}

/// A constant (an implementation limit).
macro_rules! limit {
    ($name:expr, $($v:expr),+) => {
        row($name, [$($v as f64),+].len(), Kind::Float, |_, o| {
            let values = [$($v as f64),+];
            o[..values.len()].copy_from_slice(&values);
        })
    };
}

/// An integer limit.
macro_rules! int_limit {
    ($name:expr, $($v:expr),+) => {
        StateVar { kind: Kind::Int, ..limit!($name, $($v),+) }
    };
}

fn put<T: Copy + Into<f64>>(o: &mut [f64], values: &[T]) {
    for (out, v) in o.iter_mut().zip(values) {
        *out = (*v).into();
    }
}

fn put_enum(o: &mut [f64], e: GLenum) {
    o[0] = f64::from(e);
}

/// An answer from one of the areas' query functions that write up to four values.
fn from_area(o: &mut [f64], f: impl FnOnce(&mut [f64; 4]) -> Option<usize>) {
    let mut four = [0.0; 4];
    if let Some(n) = f(&mut four) {
        o[..n].copy_from_slice(&four[..n]);
    }
}

fn one_value(o: &mut [f64], v: Option<f64>) {
    o[0] = v.unwrap_or(0.0);
}

fn matrix(o: &mut [f64], m: glam::Mat4) {
    put(o, &m.to_cols_array());
}

/// Names whose `glGet` makes Mesa flush the current values first (`extra_flush_current` in
/// Mesa's `get_hash_params.py`): a `glMaterial` waiting in the vertex buffer takes effect then.
pub(crate) fn flushes_current(pname: GLenum) -> bool {
    matches!(
        pname,
        GL_CURRENT_COLOR
            | GL_CURRENT_INDEX
            | GL_CURRENT_NORMAL
            | GL_CURRENT_TEXTURE_COORDS
            | GL_CURRENT_RASTER_COLOR
            | GL_CURRENT_RASTER_DISTANCE
            | GL_CURRENT_RASTER_INDEX
            | GL_CURRENT_RASTER_POSITION
            | GL_CURRENT_RASTER_POSITION_VALID
            | GL_CURRENT_RASTER_TEXTURE_COORDS
            | GL_EDGE_FLAG
    )
}

use Kind::{Bool, Float, Int, Normalized};

/// Every state variable, in the order of GL 1.1's tables.
pub(crate) static STATE: &[StateVar] = &[
    // Table 6.3: current values.
    row(GL_CURRENT_COLOR, 4, Normalized, |gl, o| put(o, &gl.current.color)),
    hook(GL_CURRENT_INDEX, 1, Float),
    row(GL_CURRENT_TEXTURE_COORDS, 4, Float, |gl, o| put(o, &gl.current.tex_coord)),
    row(GL_CURRENT_NORMAL, 3, Normalized, |gl, o| put(o, &gl.current.normal)),
    row(GL_CURRENT_RASTER_POSITION, 4, Float, |gl, o| {
        from_area(o, |f| gl.raster_pos_query(GL_CURRENT_RASTER_POSITION, f))
    }),
    row(GL_CURRENT_RASTER_DISTANCE, 1, Float, |gl, o| {
        from_area(o, |f| gl.raster_pos_query(GL_CURRENT_RASTER_DISTANCE, f))
    }),
    row(GL_CURRENT_RASTER_COLOR, 4, Normalized, |gl, o| {
        from_area(o, |f| gl.raster_pos_query(GL_CURRENT_RASTER_COLOR, f))
    }),
    hook(GL_CURRENT_RASTER_INDEX, 1, Float),
    row(GL_CURRENT_RASTER_TEXTURE_COORDS, 4, Float, |gl, o| {
        from_area(o, |f| gl.raster_pos_query(GL_CURRENT_RASTER_TEXTURE_COORDS, f));
    }),
    row(GL_CURRENT_RASTER_POSITION_VALID, 1, Bool, |gl, o| {
        from_area(o, |f| gl.raster_pos_query(GL_CURRENT_RASTER_POSITION_VALID, f));
    }),
    hook(GL_EDGE_FLAG, 1, Bool),
    // Table 6.4: vertex arrays (client state; the enables are capabilities).
    hook(GL_VERTEX_ARRAY_SIZE, 1, Int),
    hook(GL_VERTEX_ARRAY_TYPE, 1, Int),
    hook(GL_VERTEX_ARRAY_STRIDE, 1, Int),
    hook(GL_NORMAL_ARRAY_TYPE, 1, Int),
    hook(GL_NORMAL_ARRAY_STRIDE, 1, Int),
    hook(GL_COLOR_ARRAY_SIZE, 1, Int),
    hook(GL_COLOR_ARRAY_TYPE, 1, Int),
    hook(GL_COLOR_ARRAY_STRIDE, 1, Int),
    hook(GL_INDEX_ARRAY_TYPE, 1, Int),
    hook(GL_INDEX_ARRAY_STRIDE, 1, Int),
    hook(GL_TEXTURE_COORD_ARRAY_SIZE, 1, Int),
    hook(GL_TEXTURE_COORD_ARRAY_TYPE, 1, Int),
    hook(GL_TEXTURE_COORD_ARRAY_STRIDE, 1, Int),
    hook(GL_EDGE_FLAG_ARRAY_STRIDE, 1, Int),
    // Table 6.5: transformation.
    row(GL_MODELVIEW_MATRIX, 16, Normalized, |gl, o| matrix(o, gl.matrices.modelview())),
    row(GL_PROJECTION_MATRIX, 16, Normalized, |gl, o| matrix(o, gl.matrices.projection())),
    row(GL_TEXTURE_MATRIX, 16, Normalized, |gl, o| matrix(o, gl.matrices.texture())),
    row(GL_VIEWPORT, 4, Int, |gl, o| put(o, &gl.raster.viewport)),
    row(GL_DEPTH_RANGE, 2, Normalized, |gl, o| put(o, &gl.raster.depth_range)),
    row(GL_MODELVIEW_STACK_DEPTH, 1, Int, |gl, o| o[0] = gl.matrices.depth(0) as f64),
    row(GL_PROJECTION_STACK_DEPTH, 1, Int, |gl, o| o[0] = gl.matrices.depth(1) as f64),
    row(GL_TEXTURE_STACK_DEPTH, 1, Int, |gl, o| o[0] = gl.matrices.depth(2) as f64),
    row(GL_MATRIX_MODE, 1, Int, |gl, o| put_enum(o, [GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE][gl.matrices.mode()])),
    // Table 6.6: colouring.
    row(GL_FOG_COLOR, 4, Normalized, |gl, o| put(o, &gl.fragment_ops.fog.color)),
    row(GL_FOG_INDEX, 1, Float, |gl, o| o[0] = gl.fragment_ops.fog_index.into()),
    row(GL_FOG_DENSITY, 1, Float, |gl, o| o[0] = gl.fragment_ops.fog.density.into()),
    row(GL_FOG_START, 1, Float, |gl, o| o[0] = gl.fragment_ops.fog.start.into()),
    row(GL_FOG_END, 1, Float, |gl, o| o[0] = gl.fragment_ops.fog.end.into()),
    row(GL_FOG_MODE, 1, Int, |gl, o| put_enum(o, gl.fragment_ops.fog.mode)),
    row(GL_SHADE_MODEL, 1, Int, |gl, o| put_enum(o, gl.raster.shade_model)),
    // Table 6.7: lighting (materials and lights through glGetMaterial and glGetLight).
    row(GL_COLOR_MATERIAL_PARAMETER, 1, Int, |gl, o| put_enum(o, gl.lighting.color_material.1)),
    row(GL_COLOR_MATERIAL_FACE, 1, Int, |gl, o| put_enum(o, gl.lighting.color_material.0)),
    row(GL_LIGHT_MODEL_AMBIENT, 4, Normalized, |gl, o| put(o, &gl.lighting.model_ambient.to_array())),
    row(GL_LIGHT_MODEL_LOCAL_VIEWER, 1, Bool, |gl, o| o[0] = f64::from(u8::from(gl.lighting.local_viewer))),
    row(GL_LIGHT_MODEL_TWO_SIDE, 1, Bool, |gl, o| o[0] = f64::from(u8::from(gl.lighting.two_side))),
    // Table 6.8: rasterisation.
    row(GL_POINT_SIZE, 1, Float, |gl, o| o[0] = gl.raster.point_size.into()),
    row(GL_LINE_WIDTH, 1, Float, |gl, o| o[0] = gl.raster.line_width.into()),
    row(GL_LINE_STIPPLE_PATTERN, 1, Int, |gl, o| o[0] = gl.raster.line_stipple.1.into()),
    row(GL_LINE_STIPPLE_REPEAT, 1, Int, |gl, o| o[0] = gl.raster.line_stipple.0.into()),
    row(GL_CULL_FACE_MODE, 1, Int, |gl, o| put_enum(o, gl.raster.cull_face)),
    row(GL_FRONT_FACE, 1, Int, |gl, o| put_enum(o, gl.raster.front_face)),
    row(GL_POLYGON_MODE, 2, Int, |gl, o| put(o, &gl.raster.polygon_mode)),
    row(GL_POLYGON_OFFSET_FACTOR, 1, Float, |gl, o| o[0] = gl.raster.polygon_offset.0.into()),
    row(GL_POLYGON_OFFSET_UNITS, 1, Float, |gl, o| o[0] = gl.raster.polygon_offset.1.into()),
    // Table 6.9: textures (parameters and levels through glGetTex*).
    row(GL_TEXTURE_BINDING_1D, 1, Int, |gl, o| one_value(o, gl.texture_query(GL_TEXTURE_BINDING_1D))),
    row(GL_TEXTURE_BINDING_2D, 1, Int, |gl, o| one_value(o, gl.texture_query(GL_TEXTURE_BINDING_2D))),
    row(GL_ACTIVE_TEXTURE, 1, Int, |gl, o| put_enum(o, gl.active_texture)),
    // Table 6.12: pixel operations.
    hook(GL_SCISSOR_BOX, 4, Int),
    row(GL_ALPHA_TEST_FUNC, 1, Int, |gl, o| put_enum(o, gl.fragment_ops.alpha.0)),
    row(GL_ALPHA_TEST_REF, 1, Normalized, |gl, o| o[0] = gl.fragment_ops.alpha.1.into()),
    hook(GL_STENCIL_FUNC, 1, Int),
    hook(GL_STENCIL_VALUE_MASK, 1, Int),
    hook(GL_STENCIL_REF, 1, Int),
    hook(GL_STENCIL_FAIL, 1, Int),
    hook(GL_STENCIL_PASS_DEPTH_FAIL, 1, Int),
    hook(GL_STENCIL_PASS_DEPTH_PASS, 1, Int),
    row(GL_DEPTH_FUNC, 1, Int, |gl, o| put_enum(o, gl.raster.depth_func)),
    row(GL_BLEND_SRC, 1, Int, |gl, o| put_enum(o, gl.fragment_ops.blend[0])),
    row(GL_BLEND_DST, 1, Int, |gl, o| put_enum(o, gl.fragment_ops.blend[1])),
    hook(GL_LOGIC_OP_MODE, 1, Int),
    // Table 6.13: framebuffer control.
    hook(GL_DRAW_BUFFER, 1, Int),
    hook(GL_INDEX_WRITEMASK, 1, Int),
    hook(GL_COLOR_WRITEMASK, 4, Bool),
    hook(GL_DEPTH_WRITEMASK, 1, Bool),
    hook(GL_STENCIL_WRITEMASK, 1, Int),
    row(GL_COLOR_CLEAR_VALUE, 4, Normalized, |gl, o| put(o, &gl.raster.clear_color)),
    hook(GL_INDEX_CLEAR_VALUE, 1, Float),
    row(GL_DEPTH_CLEAR_VALUE, 1, Normalized, |gl, o| o[0] = gl.raster.clear_depth.into()),
    hook(GL_STENCIL_CLEAR_VALUE, 1, Int),
    hook(GL_ACCUM_CLEAR_VALUE, 4, Normalized),
    // Table 6.14: pixels.
    row(GL_UNPACK_SWAP_BYTES, 1, Bool, |gl, o| o[0] = f64::from(u8::from(gl.pixel_stores.unpack.swap_bytes))),
    row(GL_UNPACK_LSB_FIRST, 1, Bool, |gl, o| o[0] = f64::from(u8::from(gl.pixel_stores.unpack.lsb_first))),
    row(GL_UNPACK_ROW_LENGTH, 1, Int, |gl, o| o[0] = gl.pixel_stores.unpack.row_length as f64),
    row(GL_UNPACK_SKIP_ROWS, 1, Int, |gl, o| o[0] = gl.pixel_stores.unpack.skip_rows as f64),
    row(GL_UNPACK_SKIP_PIXELS, 1, Int, |gl, o| o[0] = gl.pixel_stores.unpack.skip_pixels as f64),
    row(GL_UNPACK_ALIGNMENT, 1, Int, |gl, o| o[0] = gl.pixel_stores.unpack.alignment as f64),
    row(GL_PACK_SWAP_BYTES, 1, Bool, |gl, o| o[0] = f64::from(u8::from(gl.pixel_stores.pack.swap_bytes))),
    row(GL_PACK_LSB_FIRST, 1, Bool, |gl, o| o[0] = f64::from(u8::from(gl.pixel_stores.pack.lsb_first))),
    row(GL_PACK_ROW_LENGTH, 1, Int, |gl, o| o[0] = gl.pixel_stores.pack.row_length as f64),
    row(GL_PACK_SKIP_ROWS, 1, Int, |gl, o| o[0] = gl.pixel_stores.pack.skip_rows as f64),
    row(GL_PACK_SKIP_PIXELS, 1, Int, |gl, o| o[0] = gl.pixel_stores.pack.skip_pixels as f64),
    row(GL_PACK_ALIGNMENT, 1, Int, |gl, o| o[0] = gl.pixel_stores.pack.alignment as f64),
    hook(GL_MAP_COLOR, 1, Bool),
    hook(GL_MAP_STENCIL, 1, Bool),
    hook(GL_INDEX_SHIFT, 1, Int),
    hook(GL_INDEX_OFFSET, 1, Int),
    hook(GL_RED_SCALE, 1, Float),
    hook(GL_GREEN_SCALE, 1, Float),
    hook(GL_BLUE_SCALE, 1, Float),
    hook(GL_ALPHA_SCALE, 1, Float),
    hook(GL_DEPTH_SCALE, 1, Float),
    hook(GL_RED_BIAS, 1, Float),
    hook(GL_GREEN_BIAS, 1, Float),
    hook(GL_BLUE_BIAS, 1, Float),
    hook(GL_ALPHA_BIAS, 1, Float),
    hook(GL_DEPTH_BIAS, 1, Float),
    hook(GL_ZOOM_X, 1, Float),
    hook(GL_ZOOM_Y, 1, Float),
    hook(GL_PIXEL_MAP_I_TO_I_SIZE, 1, Int),
    hook(GL_PIXEL_MAP_S_TO_S_SIZE, 1, Int),
    hook(GL_PIXEL_MAP_I_TO_R_SIZE, 1, Int),
    hook(GL_PIXEL_MAP_I_TO_G_SIZE, 1, Int),
    hook(GL_PIXEL_MAP_I_TO_B_SIZE, 1, Int),
    hook(GL_PIXEL_MAP_I_TO_A_SIZE, 1, Int),
    hook(GL_PIXEL_MAP_R_TO_R_SIZE, 1, Int),
    hook(GL_PIXEL_MAP_G_TO_G_SIZE, 1, Int),
    hook(GL_PIXEL_MAP_B_TO_B_SIZE, 1, Int),
    hook(GL_PIXEL_MAP_A_TO_A_SIZE, 1, Int),
    hook(GL_READ_BUFFER, 1, Int),
    // Table 6.15: evaluators (the maps themselves through glGetMap).
    row(GL_MAP1_GRID_DOMAIN, 2, Float, |gl, o| from_area(o, |f| gl.eval.grid_query(GL_MAP1_GRID_DOMAIN, f))),
    row(GL_MAP2_GRID_DOMAIN, 4, Float, |gl, o| from_area(o, |f| gl.eval.grid_query(GL_MAP2_GRID_DOMAIN, f))),
    row(GL_MAP1_GRID_SEGMENTS, 1, Int, |gl, o| from_area(o, |f| gl.eval.grid_query(GL_MAP1_GRID_SEGMENTS, f))),
    row(GL_MAP2_GRID_SEGMENTS, 2, Int, |gl, o| from_area(o, |f| gl.eval.grid_query(GL_MAP2_GRID_SEGMENTS, f))),
    // Table 6.16: hints.
    row(GL_PERSPECTIVE_CORRECTION_HINT, 1, Int, |gl, o| one_value(o, gl.hint_query(GL_PERSPECTIVE_CORRECTION_HINT))),
    row(GL_POINT_SMOOTH_HINT, 1, Int, |gl, o| one_value(o, gl.hint_query(GL_POINT_SMOOTH_HINT))),
    row(GL_LINE_SMOOTH_HINT, 1, Int, |gl, o| one_value(o, gl.hint_query(GL_LINE_SMOOTH_HINT))),
    row(GL_POLYGON_SMOOTH_HINT, 1, Int, |gl, o| one_value(o, gl.hint_query(GL_POLYGON_SMOOTH_HINT))),
    row(GL_FOG_HINT, 1, Int, |gl, o| one_value(o, gl.hint_query(GL_FOG_HINT))),
    // Tables 6.17–6.19: implementation limits and the framebuffer's configuration (llvmpipe's).
    int_limit!(GL_MAX_LIGHTS, 8),
    int_limit!(GL_MAX_CLIP_PLANES, super::super::clip::MAX_CLIP_PLANES),
    int_limit!(GL_MAX_MODELVIEW_STACK_DEPTH, super::super::matrix::DEPTHS[0]),
    int_limit!(GL_MAX_PROJECTION_STACK_DEPTH, super::super::matrix::DEPTHS[1]),
    int_limit!(GL_MAX_TEXTURE_STACK_DEPTH, super::super::matrix::DEPTHS[2]),
    int_limit!(GL_SUBPIXEL_BITS, 8),
    int_limit!(GL_MAX_TEXTURE_SIZE, super::super::texture::MAX_TEXTURE_SIZE),
    int_limit!(GL_MAX_PIXEL_MAP_TABLE, 256),
    int_limit!(GL_MAX_NAME_STACK_DEPTH, 64),
    int_limit!(GL_MAX_LIST_NESTING, super::super::lists::MAX_LIST_NESTING),
    int_limit!(GL_MAX_EVAL_ORDER, MAX_EVAL_ORDER),
    int_limit!(GL_MAX_VIEWPORT_DIMS, super::super::raster::MAX_VIEWPORT_DIMS, super::super::raster::MAX_VIEWPORT_DIMS),
    int_limit!(GL_MAX_ATTRIB_STACK_DEPTH, super::super::attrib::MAX_ATTRIB_STACK_DEPTH),
    int_limit!(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, super::super::pixels::MAX_CLIENT_ATTRIB_STACK_DEPTH),
    int_limit!(GL_AUX_BUFFERS, 0),
    StateVar { kind: Bool, ..limit!(GL_RGBA_MODE, 1) },
    StateVar { kind: Bool, ..limit!(GL_INDEX_MODE, 0) },
    hook(GL_DOUBLEBUFFER, 1, Bool),
    StateVar { kind: Bool, ..limit!(GL_STEREO, 0) },
    limit!(GL_POINT_SIZE_RANGE, 1, 255),
    limit!(GL_POINT_SIZE_GRANULARITY, 0.1f32),
    limit!(GL_LINE_WIDTH_RANGE, 1, 255),
    limit!(GL_LINE_WIDTH_GRANULARITY, 0.1f32),
    limit!(GL_ALIASED_POINT_SIZE_RANGE, 1, 255),
    limit!(GL_ALIASED_LINE_WIDTH_RANGE, 1, 255),
    int_limit!(GL_RED_BITS, 8),
    int_limit!(GL_GREEN_BITS, 8),
    int_limit!(GL_BLUE_BITS, 8),
    int_limit!(GL_ALPHA_BITS, 8),
    int_limit!(GL_INDEX_BITS, 0),
    int_limit!(GL_DEPTH_BITS, 24),
    hook(GL_STENCIL_BITS, 1, Int),
    hook(GL_ACCUM_RED_BITS, 1, Int),
    hook(GL_ACCUM_GREEN_BITS, 1, Int),
    hook(GL_ACCUM_BLUE_BITS, 1, Int),
    hook(GL_ACCUM_ALPHA_BITS, 1, Int),
    // Table 6.20: miscellaneous.
    row(GL_LIST_BASE, 1, Int, |gl, o| one_value(o, gl.list_query(GL_LIST_BASE))),
    row(GL_LIST_INDEX, 1, Int, |gl, o| one_value(o, gl.list_query(GL_LIST_INDEX))),
    row(GL_LIST_MODE, 1, Int, |gl, o| one_value(o, gl.list_query(GL_LIST_MODE))),
    row(GL_ATTRIB_STACK_DEPTH, 1, Int, |gl, o| o[0] = gl.attrib_stack_depth() as f64),
    row(GL_CLIENT_ATTRIB_STACK_DEPTH, 1, Int, |gl, o| o[0] = gl.client_attrib_stack_depth() as f64),
    hook(GL_NAME_STACK_DEPTH, 1, Int),
    row(GL_RENDER_MODE, 1, Int, |gl, o| put_enum(o, gl.render_mode_value())),
    row(GL_FEEDBACK_BUFFER_SIZE, 1, Int, |gl, o| o[0] = gl.feedback_buffer_spec().0 as f64),
    row(GL_FEEDBACK_BUFFER_TYPE, 1, Int, |gl, o| put_enum(o, gl.feedback_buffer_spec().1)),
    hook(GL_SELECTION_BUFFER_SIZE, 1, Int),
];
