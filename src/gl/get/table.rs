//! The state variables `glGet` answers (GL 1.1 spec §6.2, tables 6.3–6.20, and the few later
//! names gleval implements), one row each, as Mesa's `get_hash_params.py` lists them: the name,
//! how many values, how Mesa stores them (which decides every conversion) and where the value
//! lives (a function reading it from `Gl`). Each row sits beside the state it reads, in its
//! attribute group's file (`GET_ROWS`), with the group's limits; [`rows`] goes through them
//! all. Enables are not rows: every capability `glIsEnabled` knows is a one-value boolean
//! (`Gl::lookup`).
//!
//! The limits are llvmpipe's as Mesa 22.3 reports them through OSMesa (measured with
//! `glGetDoublev`; the same figures are in `tests/reference/calls/expected/queries.out`).

use super::super::consts::*;
use super::super::state_var::StateVar;
use super::super::types::*;

/// Every row, group by group in the order of GL 1.1's state tables.
pub(crate) fn rows() -> impl Iterator<Item = &'static StateVar> {
    use super::super::{
        accum, array_draws, arrays, attrib, blend, clip, color_buffer, color_index, current, depth, eval, feedback,
        fog, fragments, hint, lighting, line, lists, matrix, multisample, multitexture, pixel_transfer, pixels, point,
        polygon, raster_pos, scissor, select, stencil, texture, viewport,
    };
    [
        current::GET_ROWS,
        raster_pos::GET_ROWS,
        arrays::GET_ROWS,
        array_draws::GET_ROWS,
        matrix::GET_ROWS,
        viewport::GET_ROWS,
        clip::GET_ROWS,
        fog::GET_ROWS,
        lighting::GET_ROWS,
        point::GET_ROWS,
        line::GET_ROWS,
        polygon::GET_ROWS,
        texture::GET_ROWS,
        texture::COMPRESSION_GET_ROWS,
        multitexture::GET_ROWS,
        scissor::GET_ROWS,
        multisample::GET_ROWS,
        stencil::GET_ROWS,
        depth::GET_ROWS,
        color_buffer::GET_ROWS,
        blend::GET_ROWS,
        color_index::GET_ROWS,
        accum::GET_ROWS,
        fragments::GET_ROWS,
        pixels::GET_ROWS,
        pixels::CLIENT_ATTRIB_ROWS,
        pixel_transfer::GET_ROWS,
        eval::GET_ROWS,
        hint::GET_ROWS,
        lists::GET_ROWS,
        attrib::GET_ROWS,
        feedback::GET_ROWS,
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
