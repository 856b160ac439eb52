//! The attribute stack: `glPushAttrib` / `glPopAttrib` (GL 1.1 spec §6.1.13 and its state
//! tables; Mesa `main/attrib.c`). Each group a mask names is saved whole and restored whole,
//! with the enables GL files under it. GLU saves `GL_EVAL_BIT` around its drawing
//! (`glcurveval.cc`, `glsurfeval.cc`); GLUT's teapot saves `GL_ENABLE_BIT | GL_EVAL_BIT`.
//!
//! Kept: every group of GL 1.1's table 6.1: current (colour, normal, texture coordinates, index),
//! point, line, polygon, polygon stipple, lighting, fog, depth buffer, viewport, transform,
//! enable, colour buffer (clear colour, blending, alpha test, logic op, masks, draw buffer),
//! stencil, accumulation, scissor, pixel mode (transfer, zoom, read buffer), hint, evaluator,
//! list (base) and texture (unit 0's bindings and environment); and GL 1.3's multisample group. A group with its own struct is
//! saved and restored in one piece; the rest through their areas (`pixel_attrib`,
//! `texture_attrib`).

use super::consts::*;
use super::eval::EvalAttrib;
use super::lighting::Lighting;
use super::lists::ListCommand;
use super::state_var::{int_limit, row, Kind, StateVar};
use super::types::*;
use super::{Current, Gl};

/// Mesa's `MAX_ATTRIB_STACK_DEPTH` (`main/config.h`), GL's minimum.
pub(crate) const MAX_ATTRIB_STACK_DEPTH: usize = 16;

/// The enables GL files under each group besides `GL_ENABLE_BIT` (GL 1.1 tables 6.6–6.19).
const LIGHTING_ENABLES: &[GLenum] = &[
    GL_LIGHTING,
    GL_COLOR_MATERIAL,
    GL_LIGHT0,
    GL_LIGHT0 + 1,
    GL_LIGHT0 + 2,
    GL_LIGHT0 + 3,
    GL_LIGHT0 + 4,
    GL_LIGHT0 + 5,
    GL_LIGHT0 + 6,
    GL_LIGHT0 + 7,
];
const TRANSFORM_ENABLES: &[GLenum] = &[
    GL_NORMALIZE,
    GL_RESCALE_NORMAL,
    GL_CLIP_PLANE0,
    GL_CLIP_PLANE1,
    GL_CLIP_PLANE2,
    GL_CLIP_PLANE3,
    GL_CLIP_PLANE4,
    GL_CLIP_PLANE5,
    GL_CLIP_PLANE5 + 1,
    GL_CLIP_PLANE5 + 2,
];
/// Every unit's targets and coordinate generation (GL 1.3: the texture group and the enable
/// group save them for each unit, as Mesa's `attrib.c` does).
fn texture_enables() -> impl Iterator<Item = GLenum> {
    (0..super::units::MAX_TEXTURE_UNITS)
        .flat_map(|unit| super::units::UNIT_ENABLES.iter().map(move |&cap| super::units::unit_cap(cap, unit)))
}

/// What one `glPushAttrib` saved: the mask, and every group's values (restored by the mask).
#[derive(Clone, Debug)]
struct Saved {
    mask: GLbitfield,
    current: Current,
    viewport: super::viewport::Viewport,
    shade_model: GLenum,
    clip_planes: [[f32; 4]; super::clip::MAX_CLIP_PLANES],
    polygon_stipple: [u32; 32],
    lighting: Option<Lighting>,
    color_buffer: super::color_buffer::ColorBuffer,
    fog: super::fog::FogState,
    stencil: super::stencil::StencilBuffer,
    scissor: [GLint; 4],
    multisample: super::multisample::Multisample,
    clear_accum: [f32; 4],
    depth: super::depth::Depth,
    point: super::point::Point,
    line: super::line::Line,
    polygon: super::polygon::Polygon,
    matrix_mode: usize,
    eval: Option<EvalAttrib>,
    list_base: GLuint,
    texture: super::texture::TextureAttrib,
    hints: super::hint::Hints,
    /// (capability, on) for every enable a group of the mask files.
    enables: Vec<(GLenum, bool)>,
    /// The pixel mode group and the colour-index values of the current and colour-buffer groups.
    pixels: super::pixel_transfer::PixelAttrib,
}

/// The server attribute stack.
#[derive(Clone, Debug, Default)]
pub(crate) struct AttribStack {
    entries: Vec<Saved>,
}

/// The enables the groups of `mask` save (`GL_ENABLE_BIT`: every capability).
fn enables_of(mask: GLbitfield) -> Vec<GLenum> {
    let groups: [(GLbitfield, &[GLenum]); 11] = [
        (GL_POINT_BIT, super::point::POINT_ENABLES),
        (GL_LINE_BIT, super::line::LINE_ENABLES),
        (GL_POLYGON_BIT, super::polygon::POLYGON_ENABLES),
        (GL_LIGHTING_BIT, LIGHTING_ENABLES),
        (GL_FOG_BIT, super::fog::FOG_ENABLES),
        (GL_DEPTH_BUFFER_BIT, super::depth::DEPTH_ENABLES),
        (GL_TRANSFORM_BIT, TRANSFORM_ENABLES),
        (GL_COLOR_BUFFER_BIT, super::color_buffer::COLOR_BUFFER_ENABLES),
        (GL_STENCIL_BUFFER_BIT, super::stencil::STENCIL_ENABLES),
        (GL_SCISSOR_BIT, super::scissor::SCISSOR_ENABLES),
        (GL_MULTISAMPLE_BIT, super::multisample::MULTISAMPLE_ENABLES),
    ];
    let all = mask & GL_ENABLE_BIT != 0;
    let mut caps: Vec<GLenum> =
        groups.iter().filter(|(bit, _)| all || mask & bit != 0).flat_map(|(_, caps)| caps.iter().copied()).collect();
    if all {
        caps.extend(super::enable::KNOWN.iter().copied().filter(|c| !super::enable::UNSAVED.contains(c)));
    }
    if all || mask & GL_TEXTURE_BIT != 0 {
        caps.extend(texture_enables());
    }
    caps.sort_unstable();
    caps.dedup();
    caps
}

/// The attribute stack's calls as a display list holds them.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum AttribCall {
    PushAttrib(GLbitfield),
    PopAttrib,
}

impl Gl {
    /// Replays a listed call of the group.
    pub(crate) fn replay_attrib_call(&mut self, call: &AttribCall) {
        use AttribCall as C;
        match call {
            C::PushAttrib(mask) => self.push_attrib(*mask),
            C::PopAttrib => self.pop_attrib(),
        }
    }
}

impl Gl {
    /// `GL_ATTRIB_STACK_DEPTH`.
    pub(crate) fn attrib_stack_depth(&self) -> usize {
        self.server.attrib_stack.entries.len()
    }

    /// `glPushAttrib(mask)`: saves the groups of `mask`. A full stack → `GL_STACK_OVERFLOW`
    /// (nothing is saved); inside `begin`/`end` → `GL_INVALID_OPERATION`.
    pub fn push_attrib(&mut self, mask: GLbitfield) {
        if self.compiled_state_call(|| ListCommand::Attrib(AttribCall::PushAttrib(mask))) {
            return;
        }
        if self.server.attrib_stack.entries.len() >= MAX_ATTRIB_STACK_DEPTH {
            return self.set_error(GL_STACK_OVERFLOW);
        }
        let saved = self.save_groups(mask);
        self.server.attrib_stack.entries.push(saved);
    }

    /// `glPopAttrib`: restores the groups the matching push saved. An empty stack →
    /// `GL_STACK_UNDERFLOW`; inside `begin`/`end` → `GL_INVALID_OPERATION`.
    pub fn pop_attrib(&mut self) {
        if self.compiled_state_call(|| ListCommand::Attrib(AttribCall::PopAttrib)) {
            return;
        }
        let Some(saved) = self.server.attrib_stack.entries.pop() else {
            return self.set_error(GL_STACK_UNDERFLOW);
        };
        self.restore_saved(saved);
    }

    /// `glXCopyContext(src, dst, mask)` on the destination: the groups of `mask` become
    /// `source`'s, as a push on `source` and a pop here would make them (GLX 1.4 §3.3.7;
    /// Mesa's `_mesa_copy_context`). Neither attribute stack changes.
    pub fn copy_attribs_from(&mut self, source: &mut Gl, mask: GLbitfield) {
        let saved = source.save_groups(mask);
        self.restore_saved(saved);
    }

    /// Restores what [`Gl::save_groups`] saved, as `glPopAttrib` does.
    fn restore_saved(&mut self, saved: Saved) {
        let (materials, tracking) = (self.server.lighting.materials, self.server.caps.is_on(GL_COLOR_MATERIAL));
        self.restore_groups(saved);
        if !tracking && self.server.caps.is_on(GL_COLOR_MATERIAL) {
            // Mesa's pop enables it through glEnable, which copies the colour.
            self.color_material_enabled();
        }
        self.land_pending_materials(materials);
        self.touch_state();
    }

    /// The groups of `mask` as they are now.
    fn save_groups(&mut self, mask: GLbitfield) -> Saved {
        self.flush_current();
        let enables = enables_of(mask).into_iter().map(|cap| (cap, self.server.caps.is_on(cap))).collect();
        Saved {
            mask,
            current: self.server.current,
            viewport: self.server.viewport,
            shade_model: self.server.shade_model,
            clip_planes: self.server.clip_planes,
            polygon_stipple: self.server.polygon_stipple,
            lighting: (mask & GL_LIGHTING_BIT != 0).then(|| self.server.lighting.clone()),
            color_buffer: self.server.color_buffer,
            fog: self.server.fog,
            stencil: self.server.stencil,
            scissor: self.server.scissor,
            multisample: self.server.multisample,
            clear_accum: self.server.clear_accum,
            depth: self.server.depth,
            point: self.server.point,
            line: self.server.line,
            polygon: self.server.polygon,
            matrix_mode: self.server.matrices.mode(),
            // The evaluator group holds the map enables and GL_AUTO_NORMAL, which
            // GL_ENABLE_BIT saves too.
            eval: (mask & (GL_EVAL_BIT | GL_ENABLE_BIT) != 0).then(|| self.server.eval.attrib()),
            list_base: self.list_base_value(),
            texture: self.texture_attrib(),
            hints: self.server.hints,
            enables,
            pixels: self.pixel_attrib(),
        }
    }

    fn restore_groups(&mut self, saved: Saved) {
        self.restore_pixel_attrib(saved.mask, saved.pixels);
        let mask = saved.mask;
        let has = |bit: GLbitfield| mask & bit != 0;
        if has(GL_CURRENT_BIT) {
            self.server.current = saved.current;
        }
        if has(GL_POINT_BIT) {
            self.server.point = saved.point;
        }
        if has(GL_LINE_BIT) {
            self.server.line = saved.line;
        }
        if has(GL_POLYGON_BIT) {
            self.server.polygon = saved.polygon;
        }
        if has(GL_POLYGON_STIPPLE_BIT) {
            self.server.polygon_stipple = saved.polygon_stipple;
        }
        if has(GL_LIGHTING_BIT) {
            self.server.shade_model = saved.shade_model;
        }
        if has(GL_DEPTH_BUFFER_BIT) {
            self.server.depth = saved.depth;
        }
        if has(GL_VIEWPORT_BIT) {
            self.server.viewport = saved.viewport;
        }
        if has(GL_COLOR_BUFFER_BIT) {
            self.server.color_buffer = saved.color_buffer;
        }
        if has(GL_FOG_BIT) {
            // Mesa 22.3 restores every fog value but GL 1.4's GL_FOG_COORD_SRC, though GL
            // files it under the group (table 6.9): a plain program's glPopAttrib(GL_FOG_BIT)
            // leaves the source as it was set since the push, and so does gleval's.
            let source = self.server.fog.params.coord_source;
            self.server.fog = saved.fog;
            self.server.fog.params.coord_source = source;
        }
        if has(GL_STENCIL_BUFFER_BIT) {
            self.server.stencil = saved.stencil;
        }
        if has(GL_ACCUM_BUFFER_BIT) {
            self.server.clear_accum = saved.clear_accum;
        }
        if has(GL_SCISSOR_BIT) {
            self.server.scissor = saved.scissor;
        }
        if has(GL_MULTISAMPLE_BIT) {
            self.server.multisample = saved.multisample;
        }
        if let Some(lighting) = saved.lighting {
            self.server.lighting = lighting;
        }
        if has(GL_TRANSFORM_BIT) {
            self.server.matrices.set_mode(saved.matrix_mode);
            self.server.clip_planes = saved.clip_planes;
        }
        if has(GL_LIST_BIT) {
            self.set_list_base_value(saved.list_base);
        }
        if has(GL_HINT_BIT) {
            self.server.hints = saved.hints;
        }
        if has(GL_TEXTURE_BIT) {
            self.restore_texture_attrib(saved.texture);
        }
        if let Some(eval) = saved.eval {
            // GL_ENABLE_BIT alone restores the map enables and GL_AUTO_NORMAL, not the grids.
            let eval = if has(GL_EVAL_BIT) { eval } else { eval.enables_with_grids_of(&self.server.eval.attrib()) };
            self.server.eval.restore(eval);
        }
        for (cap, on) in saved.enables {
            self.server.caps.set(cap, on);
        }
    }
}

/// The attribute stack's `glGet` rows.
pub(crate) static GET_ROWS: &[StateVar] = &[
    int_limit!(GL_MAX_ATTRIB_STACK_DEPTH, MAX_ATTRIB_STACK_DEPTH),
    row(GL_ATTRIB_STACK_DEPTH, 1, Kind::Int, |gl, o| o[0] = gl.attrib_stack_depth() as f64),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_group_comes_back_whole() {
        let mut gl = Gl::new(10, 10);
        gl.color3f(0.5, 0.25, 0.125);
        gl.enable(GL_LIGHTING);
        gl.light_fv(GL_LIGHT0, GL_DIFFUSE, &[0.1, 0.2, 0.3, 1.0]);
        gl.push_attrib(GL_CURRENT_BIT | GL_LIGHTING_BIT | GL_VIEWPORT_BIT | GL_POLYGON_BIT);
        gl.color3f(1.0, 1.0, 1.0);
        gl.disable(GL_LIGHTING);
        gl.enable(GL_LIGHT3);
        gl.light_fv(GL_LIGHT0, GL_DIFFUSE, &[1.0, 1.0, 1.0, 1.0]);
        gl.shade_model(GL_FLAT);
        gl.viewport(1, 2, 3, 4);
        gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
        gl.enable(GL_CULL_FACE);
        // Not saved: the depth test (GL_DEPTH_BUFFER_BIT, GL_ENABLE_BIT).
        gl.enable(GL_DEPTH_TEST);
        gl.pop_attrib();
        assert_eq!(gl.server.current.color, [0.5, 0.25, 0.125, 1.0]);
        assert_eq!((gl.is_enabled(GL_LIGHTING), gl.is_enabled(GL_LIGHT3)), (GL_TRUE, GL_FALSE));
        assert_eq!(gl.server.lighting.lights[0].diffuse.to_array(), [0.1, 0.2, 0.3, 1.0]);
        assert_eq!(gl.server.shade_model, GL_SMOOTH);
        assert_eq!(gl.server.viewport.rect, [0, 0, 10, 10]);
        assert_eq!(gl.server.polygon.mode, [GL_FILL, GL_FILL]);
        assert_eq!((gl.is_enabled(GL_CULL_FACE), gl.is_enabled(GL_DEPTH_TEST)), (GL_FALSE, GL_TRUE));
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    /// GL 1.1 table 6.13: the polygon stipple group holds the mask alone; its enable belongs
    /// to the polygon and enable groups.
    #[test]
    fn the_polygon_stipple_group_holds_the_mask() {
        let mut gl = Gl::new(10, 10);
        gl.push_attrib(GL_POLYGON_STIPPLE_BIT);
        gl.polygon_stipple(&[0x0F; 128]);
        gl.enable(GL_POLYGON_STIPPLE);
        gl.pop_attrib();
        assert_eq!(gl.server.polygon_stipple, [u32::MAX; 32]);
        assert_eq!(gl.is_enabled(GL_POLYGON_STIPPLE), GL_TRUE);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn the_enable_group_restores_map_enables_but_not_grids() {
        let mut gl = Gl::new(10, 10);
        gl.push_attrib(GL_ENABLE_BIT);
        gl.enable(GL_MAP1_VERTEX_3);
        gl.enable(GL_TEXTURE_2D);
        gl.map_grid1f(7, 0.0, 1.0);
        gl.pop_attrib();
        assert_eq!((gl.is_enabled(GL_MAP1_VERTEX_3), gl.is_enabled(GL_TEXTURE_2D)), (GL_FALSE, GL_FALSE));
        assert_eq!(grid1(&mut gl), [7]);
    }

    fn grid1(gl: &mut Gl) -> [i32; 1] {
        let mut n = [0];
        gl.get_integerv(GL_MAP1_GRID_SEGMENTS, &mut n);
        n
    }

    #[test]
    fn pop_restores_the_eval_group() {
        let mut gl = Gl::new(10, 10);
        gl.push_attrib(GL_EVAL_BIT);
        gl.enable(GL_MAP1_VERTEX_3);
        gl.enable(GL_AUTO_NORMAL);
        gl.map_grid1f(7, 0.0, 1.0);
        gl.pop_attrib();
        assert_eq!(gl.is_enabled(GL_MAP1_VERTEX_3), GL_FALSE);
        assert_eq!(gl.is_enabled(GL_AUTO_NORMAL), GL_FALSE);
        assert_eq!(grid1(&mut gl), [1]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn a_push_without_the_eval_bit_leaves_the_evaluators_alone() {
        let mut gl = Gl::new(10, 10);
        gl.push_attrib(GL_COLOR_BUFFER_BIT);
        gl.map_grid1f(7, 0.0, 1.0);
        gl.pop_attrib();
        assert_eq!(grid1(&mut gl), [7]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn the_seventeenth_push_overflows_and_saves_nothing() {
        let mut gl = Gl::new(10, 10);
        for _ in 0..MAX_ATTRIB_STACK_DEPTH {
            gl.push_attrib(GL_EVAL_BIT);
        }
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        gl.map_grid1f(5, 0.0, 1.0);
        gl.push_attrib(GL_EVAL_BIT);
        assert_eq!(gl.get_error(), GL_STACK_OVERFLOW);
        gl.map_grid1f(9, 0.0, 1.0);
        // The top entry is the sixteenth push's (grid of one segment), not the refused one's.
        gl.pop_attrib();
        assert_eq!(grid1(&mut gl), [1]);
    }

    #[test]
    fn popping_an_empty_stack_underflows() {
        let mut gl = Gl::new(10, 10);
        gl.pop_attrib();
        assert_eq!(gl.get_error(), GL_STACK_UNDERFLOW);
        gl.push_attrib(GL_EVAL_BIT);
        gl.pop_attrib();
        gl.pop_attrib();
        assert_eq!(gl.get_error(), GL_STACK_UNDERFLOW);
    }

    #[test]
    fn inside_begin_end_both_are_invalid_operations() {
        let mut gl = Gl::new(10, 10);
        gl.begin(GL_POINTS);
        gl.push_attrib(GL_EVAL_BIT);
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.pop_attrib();
        assert_eq!(gl.get_error(), GL_STACK_UNDERFLOW, "the push inside begin/end saved nothing");
        gl.push_attrib(GL_EVAL_BIT);
        gl.begin(GL_POINTS);
        gl.pop_attrib();
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.pop_attrib();
        assert_eq!(gl.get_error(), GL_NO_ERROR, "the pop inside begin/end left the entry");
    }
}
