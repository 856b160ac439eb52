//! `GL_COLOR_MATERIAL` as Mesa 22.3 does it, where Mesa and the spec part.
//!
//! GL 1.1 §2.13.3 says that while `GL_COLOR_MATERIAL` is enabled the tracked material
//! parameters always equal the current colour. Mesa keeps `glMaterial` calls made outside
//! `glBegin`/`glEnd` waiting in its vertex buffer until the next "flush" (drawing, a raster
//! position, `glPushAttrib`/`glPopAttrib`, a display list's start, end or call, `glGetMaterial`,
//! `glGet` of a current value), and copies the current colour into the material only when the
//! colour changes value or when tracking starts. Measured with OSMesa (llvmpipe), a lit quad
//! with no `glColor` of its own:
//! - `glMaterial` diffuse 0.5, then `glEnable(GL_COLOR_MATERIAL)` with no flush between (the
//!   Red Book's `colormat.c` initialisation): the waiting material lands after the enable's
//!   copy, so the quad is lit with 0.5, not the current colour, until a `glColor` of another
//!   value; a `glColor` of the same value changes nothing. With a flush between, the enable
//!   copies the colour.
//! - While tracking, a `glMaterial` of a tracked parameter is ignored.
//! - A primitive with a `glColor` inside it takes every vertex's colour as the material, even a
//!   colour equal to the current one; after it the material follows the colour only if the colour
//!   at `glEnd` differs from the one at `glBegin`.

use super::super::consts::*;
use super::super::types::*;
use super::super::Gl;
use super::Material;
use glam::Vec4;

/// A material name's parameters as bits (ambient 1, diffuse 2, specular 4, emission 8,
/// shininess 16): what `GL_COLOR_MATERIAL` tracks and what a `glMaterial` sets.
pub(super) fn material_bits(pname: GLenum) -> u8 {
    match pname {
        GL_AMBIENT => 1,
        GL_DIFFUSE => 2,
        GL_AMBIENT_AND_DIFFUSE => 3,
        GL_SPECULAR => 4,
        GL_EMISSION => 8,
        GL_SHININESS => 16,
        _ => 0,
    }
}

/// The faces a face enum names: front 0, back 1.
fn face_indices(face: GLenum) -> &'static [usize] {
    match face {
        GL_FRONT => &[0],
        GL_BACK => &[1],
        _ => &[0, 1],
    }
}

/// What Mesa's deferred material and colour comparison leave behind.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct ColorMaterialSync {
    /// Per face, the parameters a `glMaterial` set outside `begin`/`end` since the last flush.
    pending: [u8; 2],
    /// Tracking is on but the tracked material kept a waiting `glMaterial` value instead of the
    /// current colour: primitives without a `glColor` of their own use the material.
    desynced: bool,
    /// The current colour when the open primitive began.
    begin_color: [f32; 4],
}

impl Gl {
    /// The tracked parameters of `face` (bits) while `GL_COLOR_MATERIAL` is on, else 0.
    pub(crate) fn tracked_bits(&self, face: usize) -> u8 {
        let (tracked_face, mode) = self.server.lighting.color_material;
        let on = self.server.caps.is_on(GL_COLOR_MATERIAL) && face_indices(tracked_face).contains(&face);
        if on {
            material_bits(mode)
        } else {
            0
        }
    }

    /// A `glMaterial` outside `begin`/`end` set `pname` of `face`: it waits until the next flush.
    pub(crate) fn note_pending_material(&mut self, face: GLenum, pname: GLenum) {
        if !self.inside_begin_end() {
            for &f in face_indices(face) {
                self.server.color_material_sync.pending[f] |= material_bits(pname);
            }
        }
    }

    /// `glPopAttrib` restored the lighting group over `before`: a `glMaterial` still waiting
    /// lands over the restored values (Mesa 22.3: push, glMaterial, pop, and the material
    /// set between stays), and the pop flushes.
    pub(crate) fn land_pending_materials(&mut self, before: [Material; 2]) {
        for (f, old) in before.iter().enumerate() {
            let pending = self.server.color_material_sync.pending[f];
            let m = &mut self.server.lighting.materials[f];
            for (bit, slot, value) in [
                (1, &mut m.ambient, old.ambient),
                (2, &mut m.diffuse, old.diffuse),
                (4, &mut m.specular, old.specular),
                (8, &mut m.emission, old.emission),
            ] {
                if pending & bit != 0 {
                    *slot = value;
                }
            }
            if pending & 16 != 0 {
                m.shininess = old.shininess;
            }
        }
        self.flush_current();
    }

    /// Mesa's `FLUSH_CURRENT`: waiting materials have landed.
    pub(crate) fn flush_current(&mut self) {
        self.server.color_material_sync.pending = [0; 2];
    }

    /// Whether recorded primitives take the vertex colour as the tracked material.
    pub(crate) fn color_material_tracks(&self) -> bool {
        self.server.caps.is_on(GL_COLOR_MATERIAL) && !self.server.color_material_sync.desynced
    }

    /// `glEnable(GL_COLOR_MATERIAL)` turned tracking on: the colour is copied, then the waiting
    /// materials land over it.
    pub(crate) fn color_material_enabled(&mut self) {
        let pending = self.server.color_material_sync.pending;
        let kept = (0..2).any(|f| pending[f] & self.tracked_bits(f) != 0);
        self.copy_color_to_material(pending);
        self.server.color_material_sync.desynced = kept;
    }

    /// `glColorMaterial` changed what is tracked while tracking: a flush, then the copy.
    pub(crate) fn color_material_changed(&mut self) {
        if self.server.caps.is_on(GL_COLOR_MATERIAL) {
            self.flush_current();
            self.copy_color_to_material([0; 2]);
            self.server.color_material_sync.desynced = false;
        }
    }

    /// The current colour was set (from `old`).
    pub(crate) fn color_set(&mut self, old: [f32; 4]) {
        if !self.server.caps.is_on(GL_COLOR_MATERIAL) {
            return;
        }
        if let Some(p) = self.recorder.open_primitive {
            if self.server.color_material_sync.desynced {
                self.track_in_primitive(p);
            }
        } else if old != self.server.current.color {
            self.copy_color_to_material([0; 2]);
            self.server.color_material_sync.desynced = false;
        }
    }

    /// `glBegin` (or an evaluator's primitive) starts: a flush.
    pub(crate) fn color_material_begin(&mut self) {
        self.flush_current();
        self.server.color_material_sync.begin_color = self.server.current.color;
    }

    /// `glEnd`: the material follows the colour if the primitive changed it.
    pub(crate) fn color_material_end(&mut self) {
        if self.server.caps.is_on(GL_COLOR_MATERIAL)
            && self.server.current.color != self.server.color_material_sync.begin_color
        {
            self.copy_color_to_material([0; 2]);
            self.server.color_material_sync.desynced = false;
        }
    }

    /// A `glColor` inside a primitive drawn while desynced: the whole primitive takes its vertex
    /// colours as the material, as Mesa's vertex buffer then carries the colour per vertex.
    fn track_in_primitive(&mut self, p: usize) {
        let state = self.recorder.frame.primitives[p].state;
        if self.recorder.frame.states[state].color_material {
            return;
        }
        let mut tracking = self.recorder.frame.states[state].clone();
        tracking.color_material = true;
        self.recorder.frame.states.push(tracking);
        self.recorder.frame.primitives[p].state = self.recorder.frame.states.len() - 1;
    }

    /// Copies the current colour into the tracked parameters, except the `kept` ones.
    fn copy_color_to_material(&mut self, kept: [u8; 2]) {
        let color = Vec4::from_array(self.server.current.color);
        for f in 0..2 {
            let bits = self.tracked_bits(f) & !kept[f];
            let m = &mut self.server.lighting.materials[f];
            for (bit, slot) in [(1, &mut m.ambient), (2, &mut m.diffuse), (4, &mut m.specular), (8, &mut m.emission)] {
                if bits & bit != 0 {
                    *slot = color;
                }
            }
        }
        self.touch_state();
    }
}
