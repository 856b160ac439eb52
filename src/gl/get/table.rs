//! The state variables `glGet` answers (GL 1.1 spec §6.2, tables 6.3–6.20, and the few later
//! names gleval implements), one row each, as Mesa's `get_hash_params.py` lists them: the name,
//! how many values, how Mesa stores them (which decides every conversion) and where the value
//! lives (a function reading it from `Gl`). The rows of state whose structs keep their fields
//! private sit in that state's own module (`GET_ROWS` in `arrays`, `select`, `feedback`,
//! `color_index`, `pixel_transfer`, `fragments`, `raster_pos`, `eval`, `hint`, `lists`,
//! `texture`); [`rows`] goes through them all. Enables are not rows: every capability
//! `glIsEnabled` knows is a one-value boolean (`Gl::lookup`).
//!
//! The limits are llvmpipe's as Mesa 22.3 reports them through OSMesa (measured with
//! `glGetDoublev`; the same figures are in `tests/reference/calls/expected/queries.out`).

use super::super::consts::*;
use super::super::state_var::{int_limit, limit, put, put_enum, put_flag, row, Kind, StateVar};
use super::super::types::*;

fn matrix(o: &mut [f64], m: glam::Mat4) {
    put(o, &m.to_cols_array());
}

/// Every row: this file's, then those of the modules that keep their state's fields.
pub(crate) fn rows() -> impl Iterator<Item = &'static StateVar> {
    use super::super::{
        accum, arrays, color_buffer, color_index, depth, eval, fog, fragments, hint, line, lists, pixel_transfer,
        pixels, point, polygon, raster_pos, scissor, select, stencil, texture,
    };
    [
        STATE,
        raster_pos::GET_ROWS,
        pixels::GET_ROWS,
        depth::GET_ROWS,
        point::GET_ROWS,
        line::GET_ROWS,
        polygon::GET_ROWS,
        arrays::GET_ROWS,
        texture::GET_ROWS,
        fragments::GET_ROWS,
        color_buffer::GET_ROWS,
        fog::GET_ROWS,
        stencil::GET_ROWS,
        scissor::GET_ROWS,
        accum::GET_ROWS,
        color_index::GET_ROWS,
        pixel_transfer::GET_ROWS,
        eval::GET_ROWS,
        hint::GET_ROWS,
        lists::GET_ROWS,
        select::GET_ROWS,
    ]
    .into_iter()
    .flatten()
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

/// The state variables of `Gl`'s own fields and the limits, in the order of GL 1.1's tables.
pub(crate) static STATE: &[StateVar] = &[
    // Table 6.3: current values (the raster position's in `raster_pos`, the index in
    // `color_index`, the edge flag in `arrays`).
    row(GL_CURRENT_COLOR, 4, Normalized, |gl, o| put(o, &gl.server.current.color)),
    row(GL_CURRENT_TEXTURE_COORDS, 4, Float, |gl, o| put(o, &gl.server.current.tex_coord)),
    row(GL_CURRENT_NORMAL, 3, Normalized, |gl, o| put(o, &gl.server.current.normal)),
    // Table 6.5: transformation.
    row(GL_MODELVIEW_MATRIX, 16, Normalized, |gl, o| matrix(o, gl.server.matrices.modelview())),
    row(GL_PROJECTION_MATRIX, 16, Normalized, |gl, o| matrix(o, gl.server.matrices.projection())),
    row(GL_TEXTURE_MATRIX, 16, Normalized, |gl, o| matrix(o, gl.server.matrices.texture())),
    row(GL_VIEWPORT, 4, Int, |gl, o| put(o, &gl.server.raster.viewport)),
    row(GL_DEPTH_RANGE, 2, Normalized, |gl, o| put(o, &gl.server.raster.depth_range)),
    row(GL_MODELVIEW_STACK_DEPTH, 1, Int, |gl, o| o[0] = gl.server.matrices.depth(0) as f64),
    row(GL_PROJECTION_STACK_DEPTH, 1, Int, |gl, o| o[0] = gl.server.matrices.depth(1) as f64),
    row(GL_TEXTURE_STACK_DEPTH, 1, Int, |gl, o| o[0] = gl.server.matrices.depth(2) as f64),
    row(GL_MATRIX_MODE, 1, Int, |gl, o| {
        put_enum(o, [GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE][gl.server.matrices.mode()])
    }),
    // Table 6.6: colouring.
    row(GL_SHADE_MODEL, 1, Int, |gl, o| put_enum(o, gl.server.raster.shade_model)),
    // Table 6.7: lighting (materials and lights through glGetMaterial and glGetLight).
    row(GL_COLOR_MATERIAL_PARAMETER, 1, Int, |gl, o| put_enum(o, gl.server.lighting.color_material.1)),
    row(GL_COLOR_MATERIAL_FACE, 1, Int, |gl, o| put_enum(o, gl.server.lighting.color_material.0)),
    row(GL_LIGHT_MODEL_AMBIENT, 4, Normalized, |gl, o| put(o, &gl.server.lighting.model_ambient.to_array())),
    row(GL_LIGHT_MODEL_LOCAL_VIEWER, 1, Bool, |gl, o| put_flag(o, gl.server.lighting.local_viewer)),
    row(GL_LIGHT_MODEL_TWO_SIDE, 1, Bool, |gl, o| put_flag(o, gl.server.lighting.two_side)),
    // Table 6.8: rasterisation.
    // Table 6.9: textures (parameters and levels through glGetTex*).
    row(GL_ACTIVE_TEXTURE, 1, Int, |gl, o| put_enum(o, gl.server.active_texture)),
    // Tables 6.17–6.19: implementation limits and the framebuffer's configuration (llvmpipe's).
    int_limit!(GL_MAX_LIGHTS, 8),
    int_limit!(GL_MAX_CLIP_PLANES, super::super::clip::MAX_CLIP_PLANES),
    int_limit!(GL_MAX_MODELVIEW_STACK_DEPTH, super::super::matrix::DEPTHS[0]),
    int_limit!(GL_MAX_PROJECTION_STACK_DEPTH, super::super::matrix::DEPTHS[1]),
    int_limit!(GL_MAX_TEXTURE_STACK_DEPTH, super::super::matrix::DEPTHS[2]),
    int_limit!(GL_SUBPIXEL_BITS, 8),
    int_limit!(GL_MAX_LIST_NESTING, super::super::lists::MAX_LIST_NESTING),
    int_limit!(GL_MAX_EVAL_ORDER, MAX_EVAL_ORDER),
    int_limit!(GL_MAX_VIEWPORT_DIMS, super::super::raster::MAX_VIEWPORT_DIMS, super::super::raster::MAX_VIEWPORT_DIMS),
    int_limit!(GL_MAX_ATTRIB_STACK_DEPTH, super::super::attrib::MAX_ATTRIB_STACK_DEPTH),
    int_limit!(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, super::super::pixels::MAX_CLIENT_ATTRIB_STACK_DEPTH),
    int_limit!(GL_AUX_BUFFERS, 0),
    StateVar { kind: Bool, ..limit!(GL_RGBA_MODE, 1) },
    StateVar { kind: Bool, ..limit!(GL_INDEX_MODE, 0) },
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
    // Table 6.20: miscellaneous.
    row(GL_ATTRIB_STACK_DEPTH, 1, Int, |gl, o| o[0] = gl.attrib_stack_depth() as f64),
    row(GL_CLIENT_ATTRIB_STACK_DEPTH, 1, Int, |gl, o| o[0] = gl.client_attrib_stack_depth() as f64),
    row(GL_RENDER_MODE, 1, Int, |gl, o| put_enum(o, gl.render_mode_value())),
    row(GL_FEEDBACK_BUFFER_SIZE, 1, Int, |gl, o| o[0] = gl.feedback_buffer_spec().0 as f64),
    row(GL_FEEDBACK_BUFFER_TYPE, 1, Int, |gl, o| put_enum(o, gl.feedback_buffer_spec().1)),
];
