//! `glEnable` / `glDisable` / `glIsEnabled` for the capabilities this façade knows.

use super::consts::*;
use super::lists::ListCommand;
use super::types::*;
use super::units::{unit_cap, MAX_TEXTURE_UNITS, UNIT_ENABLES};
use super::Gl;
use std::collections::BTreeSet;

/// Capabilities other than the evaluator maps, which live in the evaluator state.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Caps {
    on: BTreeSet<GLenum>,
}

/// Capabilities accepted besides the maps and `GL_AUTO_NORMAL` (all initially off, except
/// `GL_DITHER` and `GL_MULTISAMPLE`, which GL starts enabled).
pub(crate) const KNOWN: &[GLenum] = &[
    GL_POINT_SMOOTH,
    GL_POINT_SPRITE,
    GL_LINE_SMOOTH,
    GL_LINE_STIPPLE,
    GL_POLYGON_SMOOTH,
    GL_CULL_FACE,
    GL_LIGHTING,
    GL_COLOR_MATERIAL,
    GL_FOG,
    GL_DEPTH_TEST,
    GL_NORMALIZE,
    GL_ALPHA_TEST,
    GL_DITHER,
    GL_BLEND,
    GL_SCISSOR_TEST,
    GL_TEXTURE_GEN_S,
    GL_TEXTURE_GEN_T,
    GL_TEXTURE_GEN_R,
    GL_TEXTURE_GEN_Q,
    GL_TEXTURE_1D,
    GL_TEXTURE_2D,
    GL_TEXTURE_3D,
    GL_TEXTURE_CUBE_MAP,
    GL_TEXTURE_RECTANGLE,
    GL_POLYGON_OFFSET_FILL,
    GL_POLYGON_OFFSET_LINE,
    GL_POLYGON_OFFSET_POINT,
    GL_POLYGON_STIPPLE,
    GL_RESCALE_NORMAL,
    GL_COLOR_SUM,
    GL_MULTISAMPLE,
    GL_SAMPLE_ALPHA_TO_COVERAGE,
    GL_SAMPLE_ALPHA_TO_ONE,
    GL_SAMPLE_COVERAGE,
    GL_STENCIL_TEST,
    GL_COLOR_LOGIC_OP,
    GL_INDEX_LOGIC_OP,
];

/// Capabilities no attribute group saves: Mesa 22.3's `attrib.c` keeps GL 1.4's
/// `GL_COLOR_SUM` out of `GL_ENABLE_BIT` and `GL_FOG_BIT` alike (measured:
/// `tests/reference/calls/cases/color_sum.calls`).
pub(crate) const UNSAVED: &[GLenum] = &[GL_COLOR_SUM];

/// The vertex arrays' client states: `glEnableClientState` sets them, and Mesa's compatibility
/// profile takes them in `glEnable`, `glDisable` and `glIsEnabled` too (measured on Mesa 22.3).
/// Client state: `GL_ENABLE_BIT` does not save them (`GL_CLIENT_VERTEX_ARRAY_BIT` does).
pub(crate) const CLIENT_STATES: &[GLenum] = &[
    GL_VERTEX_ARRAY,
    GL_NORMAL_ARRAY,
    GL_COLOR_ARRAY,
    GL_INDEX_ARRAY,
    GL_TEXTURE_COORD_ARRAY,
    GL_EDGE_FLAG_ARRAY,
    GL_SECONDARY_COLOR_ARRAY,
];

impl Caps {
    fn known(cap: GLenum) -> bool {
        KNOWN.contains(&cap)
            || CLIENT_STATES.contains(&cap)
            || (GL_LIGHT0..=GL_LIGHT7).contains(&cap)
            || super::clip::plane_index(cap).is_some()
    }

    pub(crate) fn is_on(&self, cap: GLenum) -> bool {
        let default_on = cap == GL_DITHER || cap == GL_MULTISAMPLE;
        self.on.contains(&cap) != default_on
    }

    pub(crate) fn set(&mut self, cap: GLenum, on: bool) {
        let default_on = cap == GL_DITHER || cap == GL_MULTISAMPLE;
        if on != default_on {
            self.on.insert(cap);
        } else {
            self.on.remove(&cap);
        }
    }
}

impl Gl {
    /// `glEnable`.
    pub fn enable(&mut self, cap: GLenum) {
        self.set_capability(cap, true);
    }

    /// `glDisable`.
    pub fn disable(&mut self, cap: GLenum) {
        self.set_capability(cap, false);
    }

    /// `glIsEnabled`: `GL_TRUE` or `GL_FALSE`; an unknown capability gives `GL_INVALID_ENUM`.
    pub fn is_enabled(&mut self, cap: GLenum) -> GLboolean {
        if self.reject_inside_begin_end() {
            return GL_FALSE;
        }
        let on = if let Some(on) = self.server.eval.is_enabled(cap) {
            on
        } else if let Some(on) = self.client.arrays.is_enabled(cap) {
            on
        } else if UNIT_ENABLES.contains(&cap) {
            let Some(key) = self.active_unit_cap(cap) else { return GL_FALSE };
            self.server.caps.is_on(key)
        } else if Caps::known(cap) {
            self.server.caps.is_on(cap)
        } else {
            self.set_error(GL_INVALID_ENUM);
            return GL_FALSE;
        };
        if on {
            GL_TRUE
        } else {
            GL_FALSE
        }
    }

    fn set_capability(&mut self, cap: GLenum, on: bool) {
        if self.compiled(|| if on { ListCommand::Enable(cap) } else { ListCommand::Disable(cap) }) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        if self.server.eval.set_enabled(cap, on) || self.client.arrays.set_enabled(cap, on) {
            return;
        }
        if UNIT_ENABLES.contains(&cap) {
            if let Some(key) = self.active_unit_cap(cap) {
                self.server.caps.set(key, on);
                self.touch_state();
            }
        } else if Caps::known(cap) {
            let was_on = self.server.caps.is_on(cap);
            self.server.caps.set(cap, on);
            self.touch_state();
            if cap == GL_COLOR_MATERIAL && on && !was_on {
                self.color_material_enabled();
            }
        } else {
            self.set_error(GL_INVALID_ENUM);
        }
    }

    /// Where the active unit keeps `cap`, one of [`UNIT_ENABLES`]. A unit beyond the
    /// fixed-function ones has none: Mesa ignores its targets' enables and answers them false,
    /// and its coordinate generation's are `GL_INVALID_OPERATION` (measured).
    fn active_unit_cap(&mut self, cap: GLenum) -> Option<GLenum> {
        let unit = self.active_unit();
        if unit < MAX_TEXTURE_UNITS {
            return Some(unit_cap(cap, unit));
        }
        if !matches!(cap, GL_TEXTURE_1D | GL_TEXTURE_2D | GL_TEXTURE_3D | GL_TEXTURE_CUBE_MAP | GL_TEXTURE_RECTANGLE) {
            self.set_error(GL_INVALID_OPERATION);
        }
        None
    }

    /// Whether the active unit's enable `cap` (one of [`UNIT_ENABLES`]) is on, for `glGet`.
    pub(crate) fn active_unit_enabled(&self, cap: GLenum) -> bool {
        let unit = self.active_unit();
        unit < MAX_TEXTURE_UNITS && self.server.caps.is_on(unit_cap(cap, unit))
    }

    /// Whether `cap` is a capability `glIsEnabled` takes (evaluator maps included).
    pub(crate) fn is_capability(&self, cap: GLenum) -> bool {
        self.server.eval.is_enabled(cap).is_some() || Caps::known(cap)
    }

    /// Whether a non-evaluator capability is on (for the renderer).
    #[must_use]
    pub fn capability(&self, cap: GLenum) -> bool {
        self.server
            .eval
            .is_enabled(cap)
            .or_else(|| self.client.arrays.is_enabled(cap))
            .unwrap_or_else(|| self.server.caps.is_on(cap))
    }
}
