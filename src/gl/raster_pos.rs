//! The current raster position (GL 1.1 spec §2.12; Mesa `main/rastpos.c`, which Mesa's gallium
//! drivers use for fixed-function `glRasterPos`): where `glBitmap` and `glDrawPixels` draw.
//!
//! `glRasterPos` treats its argument as a vertex: modelview, projection, a clip test (a
//! position outside the clip volume makes the raster position invalid, and bitmaps and pixels
//! then draw nothing), then the viewport and depth range give window coordinates. The raster
//! colour is the current one at that moment; the texture coordinates are the current ones
//! generated (`glTexGen`) and through the texture matrix, as a vertex's. With `GL_LIGHTING` on,
//! the raster colour is the position lit as a vertex is, by the front material only (Mesa's
//! `shade_rastpos`; measured: a normal facing away, two-sided or not, gets the front's ambient
//! terms; with `GL_SEPARATE_SPECULAR_COLOR` the specular terms are left out).

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{put, put_flag, row, Kind, StateVar};
use super::types::*;
use super::units::MAX_TEXTURE_UNITS;
use super::Gl;
use glam::{Mat4, Vec4};

/// The raster position's state with GL's initial values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct RasterPos {
    /// Window x, y, z, and the clip w.
    pub window: [f32; 4],
    /// `GL_CURRENT_RASTER_POSITION_VALID`.
    pub valid: bool,
    /// The colour bitmaps are drawn in.
    pub color: [f32; 4],
    /// Unit 0's texture coordinates.
    pub tex_coord: [f32; 4],
    /// Units 1 to 7's (GL 1.3 §2.13: each unit's).
    pub unit_tex_coords: [[f32; 4]; MAX_TEXTURE_UNITS - 1],
    /// Distance from the eye to the position (`GL_CURRENT_RASTER_DISTANCE`).
    pub distance: f32,
}

impl Default for RasterPos {
    fn default() -> Self {
        Self {
            window: [0.0, 0.0, 0.0, 1.0],
            valid: true,
            color: [1.0; 4],
            tex_coord: [0.0, 0.0, 0.0, 1.0],
            unit_tex_coords: [[0.0, 0.0, 0.0, 1.0]; MAX_TEXTURE_UNITS - 1],
            distance: 0.0,
        }
    }
}

/// The transforms a raster position goes through.
#[derive(Clone, Debug)]
pub(crate) struct Transform {
    pub modelview: Mat4,
    pub projection: Mat4,
    pub viewport: [i32; 4],
    pub depth_range: [f32; 2],
    /// The enabled clip planes (eye coordinates).
    pub clip_planes: Vec<[f32; 4]>,
}

impl Transform {
    /// Window x, y, z and clip w of object point `p`, and its eye distance; `None` when the
    /// point is outside the clip volume (Mesa's `viewclip_point_z`, then `_xy`: bounds included)
    /// or outside an enabled clip plane (GL 1.1 §2.12; measured on Mesa: a plane through the
    /// point keeps it).
    pub fn project(&self, p: [f32; 4]) -> Option<([f32; 4], f32)> {
        let eye = self.modelview * Vec4::from(p);
        if self.clip_planes.iter().any(|plane| Vec4::from_array(*plane).dot(eye) < 0.0) {
            return None;
        }
        let clip = self.projection * eye;
        let outside = |c: f32| c > clip.w || c < -clip.w;
        if outside(clip.z) || outside(clip.x) || outside(clip.y) {
            return None;
        }
        let d = if clip.w == 0.0 { 1.0 } else { 1.0 / clip.w };
        let [vx, vy, vw, vh] = self.viewport.map(|v| v as f32);
        let [near, far] = self.depth_range;
        let x = clip.x * d * (vw / 2.0) + (vw / 2.0 + vx);
        let y = clip.y * d * (vh / 2.0) + (vh / 2.0 + vy);
        let z = clip.z * d * ((far - near) / 2.0) + (far + near) / 2.0;
        Some(([x, y, z, clip.w], eye.truncate().length()))
    }
}

impl Gl {
    fn raster_transform(&self) -> Transform {
        Transform {
            modelview: self.server.matrices.modelview(),
            projection: self.server.matrices.projection(),
            viewport: self.server.viewport.rect,
            depth_range: self.server.viewport.depth_range,
            clip_planes: self.enabled_clip_planes(),
        }
    }

    fn raster_pos(&mut self, p: [f32; 4]) {
        if self.compiled_state_call(|| ListCommand::RasterPos(p)) {
            return;
        }
        self.flush_current();
        let Some((window, distance)) = self.raster_transform().project(p) else {
            self.server.raster_pos.valid = false;
            return;
        };
        // The raster texture coordinates are each unit's current ones, generated where its
        // `glTexGen` says, through its texture matrix (GL 1.1 §2.12, GL 1.3 §2.13), as a
        // vertex's are. The eye-space normal is never made unit length, as in Mesa's
        // `rastpos.c` (measured: `GL_NORMALIZE` changes nothing, `texgen.calls`).
        let object = Vec4::from_array(p);
        let modelview = self.server.matrices.modelview();
        let eye = modelview * object;
        let normal_matrix = glam::Mat3::from_mat4(modelview).inverse().transpose();
        let normal = normal_matrix * glam::Vec3::from_array(self.server.current.normal);
        let through = |gl: &Self, unit: usize| {
            let coords = Vec4::from_array(gl.server.current.tex_coord_of(unit));
            let coords = gl.tex_gen_state_of(unit).map_or(coords, |g| g.apply(coords, object, eye, normal));
            (gl.server.matrices.texture_of(unit) * coords).to_array()
        };
        let tex_coord = through(self, 0);
        let unit_tex_coords = std::array::from_fn(|u| through(self, u + 1));
        let color = self.raster_color(p);
        self.server.raster_pos = RasterPos { window, valid: true, color, tex_coord, unit_tex_coords, distance };
    }

    /// The raster colour of a position at object point `p`: the current colour, or lit by the
    /// vertex stage's lighting (front face) when `GL_LIGHTING` is on.
    fn raster_color(&self, p: [f32; 4]) -> [f32; 4] {
        if !self.capability(GL_LIGHTING) {
            return self.server.current.color;
        }
        let state = self.snapshot(None);
        let vertex = self.current_vertex(p);
        super::shade::Shader::new(&state).shade(&vertex).front.to_array()
    }

    /// The active unit's raster texture coordinates.
    fn raster_tex_coord(&self) -> [f32; 4] {
        match self.active_unit() {
            unit @ 1..=7 => self.server.raster_pos.unit_tex_coords[unit - 1],
            _ => self.server.raster_pos.tex_coord,
        }
    }

    /// `glRasterPos2f` (z = 0, w = 1). Inside `begin`/`end` → `GL_INVALID_OPERATION`.
    pub fn raster_pos2f(&mut self, x: GLfloat, y: GLfloat) {
        self.raster_pos([x, y, 0.0, 1.0]);
    }

    /// `glRasterPos2i`.
    pub fn raster_pos2i(&mut self, x: GLint, y: GLint) {
        self.raster_pos([x as f32, y as f32, 0.0, 1.0]);
    }

    /// `glRasterPos2d` (cast to float, as Mesa does).
    pub fn raster_pos2d(&mut self, x: GLdouble, y: GLdouble) {
        self.raster_pos([x as f32, y as f32, 0.0, 1.0]);
    }

    /// `glRasterPos3f` (w = 1).
    pub fn raster_pos3f(&mut self, x: GLfloat, y: GLfloat, z: GLfloat) {
        self.raster_pos([x, y, z, 1.0]);
    }

    /// `glRasterPos3i`.
    pub fn raster_pos3i(&mut self, x: GLint, y: GLint, z: GLint) {
        self.raster_pos([x as f32, y as f32, z as f32, 1.0]);
    }

    /// `glRasterPos3d`.
    pub fn raster_pos3d(&mut self, x: GLdouble, y: GLdouble, z: GLdouble) {
        self.raster_pos([x as f32, y as f32, z as f32, 1.0]);
    }

    /// `glRasterPos4f`.
    pub fn raster_pos4f(&mut self, x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) {
        self.raster_pos([x, y, z, w]);
    }

    /// `glRasterPos4d`.
    pub fn raster_pos4d(&mut self, x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble) {
        self.raster_pos([x as f32, y as f32, z as f32, w as f32]);
    }

    /// `glRasterPos2fv`: `v` needs 2 values.
    pub fn raster_pos2fv(&mut self, v: &[GLfloat]) {
        if let Some([x, y]) = self.needs::<2>(v) {
            self.raster_pos2f(x, y);
        }
    }

    /// `glRasterPos3fv`: `v` needs 3 values.
    pub fn raster_pos3fv(&mut self, v: &[GLfloat]) {
        if let Some([x, y, z]) = self.needs::<3>(v) {
            self.raster_pos3f(x, y, z);
        }
    }

    /// `glRasterPos4fv`: `v` needs 4 values.
    pub fn raster_pos4fv(&mut self, v: &[GLfloat]) {
        if let Some([x, y, z, w]) = self.needs::<4>(v) {
            self.raster_pos4f(x, y, z, w);
        }
    }

    /// `glRasterPos2iv`: `v` needs 2 values.
    pub fn raster_pos2iv(&mut self, v: &[GLint]) {
        match v {
            [x, y, ..] => self.raster_pos2i(*x, *y),
            _ => self.set_error(GL_INVALID_VALUE),
        }
    }

    /// `glRasterPos2dv`: `v` needs 2 values.
    pub fn raster_pos2dv(&mut self, v: &[GLdouble]) {
        match v {
            [x, y, ..] => self.raster_pos2d(*x, *y),
            _ => self.set_error(GL_INVALID_VALUE),
        }
    }

    /// `glRasterPos3dv`: `v` needs 3 values.
    pub fn raster_pos3dv(&mut self, v: &[GLdouble]) {
        match v {
            [x, y, z, ..] => self.raster_pos3d(*x, *y, *z),
            _ => self.set_error(GL_INVALID_VALUE),
        }
    }

    /// `glWindowPos3f` (GL_ARB_window_pos, core in GL 1.4): the raster position in window
    /// coordinates, without the matrices, the viewport or clipping: always valid, `z` clamped
    /// to [0, 1] and mapped into the depth range, w 1, the eye distance 0, the current colour
    /// and texture coordinates (not lit), as Mesa's `window_pos3f` sets them.
    pub fn window_pos3f(&mut self, x: GLfloat, y: GLfloat, z: GLfloat) {
        if self.compiled_state_call(|| ListCommand::WindowPos([x, y, z])) {
            return;
        }
        self.flush_current();
        let [near, far] = self.server.viewport.depth_range;
        let z = near + z.clamp(0.0, 1.0) * (far - near);
        self.server.raster_pos = RasterPos {
            window: [x, y, z, 1.0],
            valid: true,
            color: self.server.current.color,
            tex_coord: self.server.current.tex_coord,
            unit_tex_coords: self.server.current.unit_tex_coords,
            distance: 0.0,
        };
    }

    /// Moves a valid raster position by (dx, dy) window pixels (`glBitmap`'s advance).
    pub(crate) fn advance_raster_pos(&mut self, dx: f32, dy: f32) {
        self.server.raster_pos.window[0] += dx;
        self.server.raster_pos.window[1] += dy;
    }
}

/// The raster position's `glGet` rows (GL 1.1 table 6.3; the colour reads clamped, as Mesa's).
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_CURRENT_RASTER_POSITION, 4, Kind::Float, |gl, o| put(o, &gl.server.raster_pos.window)),
    row(GL_CURRENT_RASTER_DISTANCE, 1, Kind::Float, |gl, o| o[0] = f64::from(gl.server.raster_pos.distance)),
    row(GL_CURRENT_RASTER_COLOR, 4, Kind::Normalized, |gl, o| {
        put(o, &gl.server.raster_pos.color.map(|c| c.clamp(0.0, 1.0)))
    }),
    row(GL_CURRENT_RASTER_TEXTURE_COORDS, 4, Kind::Float, |gl, o| put(o, &gl.raster_tex_coord())),
    row(GL_CURRENT_RASTER_POSITION_VALID, 1, Kind::Bool, |gl, o| put_flag(o, gl.server.raster_pos.valid)),
];

#[cfg(test)]
mod tests {
    use super::*;

    fn position(gl: &mut Gl) -> ([f32; 4], bool) {
        let (mut p, mut valid) = ([0.0f32; 4], [0]);
        gl.get_floatv(GL_CURRENT_RASTER_POSITION, &mut p);
        gl.get_integerv(GL_CURRENT_RASTER_POSITION_VALID, &mut valid);
        (p, valid[0] == 1)
    }

    #[test]
    fn a_lit_raster_colour_is_the_front_materials_as_on_mesa() {
        let mut gl = Gl::new(16, 16);
        gl.color4f(0.2, 0.4, 0.6, 0.8);
        gl.enable(GL_LIGHTING);
        gl.enable(GL_LIGHT0);
        gl.light_fv(GL_LIGHT0, GL_POSITION, &[1.0, 1.0, 1.0, 0.0]);
        gl.light_fv(GL_LIGHT0, GL_DIFFUSE, &[0.5, 0.25, 1.0, 1.0]);
        gl.material_fv(GL_FRONT, GL_AMBIENT, &[0.1, 0.1, 0.1, 1.0]);
        gl.material_fv(GL_FRONT, GL_SPECULAR, &[1.0; 4]);
        gl.material_f(GL_FRONT, GL_SHININESS, 10.0);
        let raster = |gl: &mut Gl, normal: [f32; 3]| {
            gl.normal3f(normal[0], normal[1], normal[2]);
            gl.raster_pos2f(0.0, 0.0);
            let mut c = [0.0f32; 4];
            gl.get_floatv(GL_CURRENT_RASTER_COLOR, &mut c);
            c
        };
        // Mesa 22.3's answers to the same calls (printed to 6 places).
        let close = |a: [f32; 4], b: [f32; 4]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 2e-6);
        assert!(close(raster(&mut gl, [0.0, 0.0, 1.0]), [0.556_075, 0.440_604, 0.787_015, 1.0]));
        gl.light_model_i(GL_LIGHT_MODEL_TWO_SIDE, 1);
        assert!(close(raster(&mut gl, [0.0, 0.0, -1.0]), [0.02, 0.02, 0.02, 1.0]), "the front's, facing away");
        gl.light_model_i(GL_LIGHT_MODEL_TWO_SIDE, 0);
        gl.light_model_i(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR as GLint);
        assert!(close(raster(&mut gl, [0.6, 0.0, 0.8]), [0.343_316, 0.181_658, 0.666_632, 1.0]));
    }

    #[test]
    fn window_pos_sets_window_coordinates_directly_and_is_always_valid() {
        let mut gl = Gl::new(100, 50);
        gl.depth_range(0.5, 1.0);
        gl.translatef(30.0, 0.0, 0.0);
        gl.raster_pos2f(1000.0, 0.0);
        assert!(!position(&mut gl).1);
        gl.window_pos3f(12.0, 7.0, 0.5);
        assert_eq!(position(&mut gl), ([12.0, 7.0, 0.75, 1.0], true));
        gl.window_pos2i(-5, 300);
        assert_eq!(position(&mut gl), ([-5.0, 300.0, 0.5, 1.0], true), "outside the window, z 0 → near");
        gl.window_pos3dv(&[1.0, 2.0, 7.0]);
        assert_eq!(position(&mut gl), ([1.0, 2.0, 1.0, 1.0], true), "z clamped to 1 → far");
        gl.window_pos3fv(&[1.0, 2.0]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.begin(GL_POINTS);
        gl.window_pos2f(3.0, 3.0);
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    }

    #[test]
    fn the_initial_raster_position_is_the_origin_and_valid() {
        let mut gl = Gl::new(100, 50);
        assert_eq!(position(&mut gl), ([0.0, 0.0, 0.0, 1.0], true));
    }

    #[test]
    fn a_position_goes_through_the_matrices_viewport_and_depth_range() {
        let mut gl = Gl::new(200, 100);
        gl.viewport(10, 20, 100, 50);
        gl.depth_range(0.5, 1.0);
        gl.matrix_mode(GL_PROJECTION);
        gl.ortho(0.0, 10.0, 0.0, 10.0, -1.0, 1.0);
        gl.matrix_mode(GL_MODELVIEW);
        gl.translatef(1.0, 0.0, 0.0);
        gl.raster_pos3f(4.0, 5.0, 0.5);
        // x: (5 / 10) of 100 + 10; y: (5 / 10) of 50 + 20; z: ndc −0.5 → 0.625 in [0.5, 1].
        assert_eq!(position(&mut gl), ([60.0, 45.0, 0.625, 1.0], true));
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    /// As real Mesa: with the plane x ≥ 0, x = −0.5 is invalid, x = 0.5 and x = 0 are valid.
    #[test]
    fn outside_a_clip_plane_the_position_is_invalid() {
        let mut gl = Gl::new(16, 16);
        gl.clip_plane(GL_CLIP_PLANE0, &[1.0, 0.0, 0.0, 0.0]);
        gl.enable(GL_CLIP_PLANE0);
        let valid = |gl: &mut Gl, x: f32| {
            gl.raster_pos2f(x, 0.0);
            position(gl).1
        };
        assert_eq!([valid(&mut gl, -0.5), valid(&mut gl, 0.5), valid(&mut gl, 0.0)], [false, true, true]);
    }

    #[test]
    fn outside_the_clip_volume_the_position_is_invalid_and_kept() {
        let mut gl = Gl::new(100, 100);
        gl.raster_pos2f(0.5, 0.5);
        gl.raster_pos2f(1.5, 0.0);
        assert_eq!(position(&mut gl), ([75.0, 75.0, 0.5, 1.0], false));
        gl.raster_pos3f(0.0, 0.0, -1.01);
        assert!(!position(&mut gl).1);
        // The clip volume's bounds are inside it.
        gl.raster_pos3f(1.0, -1.0, 1.0);
        assert_eq!(position(&mut gl), ([100.0, 0.0, 1.0, 1.0], true));
        gl.raster_pos4f(0.0, 0.0, 0.0, -1.0);
        assert!(!position(&mut gl).1, "w < 0 clips everything");
    }

    #[test]
    fn the_raster_colour_is_the_current_colour_when_the_position_is_set() {
        let mut gl = Gl::new(10, 10);
        gl.color3f(1.0, 0.5, 0.0);
        gl.raster_pos2i(0, 0);
        gl.color3f(0.0, 0.0, 1.0);
        let mut c = [0.0f32; 4];
        gl.get_floatv(GL_CURRENT_RASTER_COLOR, &mut c);
        assert_eq!(c, [1.0, 0.5, 0.0, 1.0]);
        let mut i = [0; 4];
        gl.get_integerv(GL_CURRENT_RASTER_COLOR, &mut i);
        assert_eq!(i, [i32::MAX, i32::MAX / 2, 0, i32::MAX], "colours map linearly onto the integers");
    }

    #[test]
    fn raster_pos_errors() {
        let mut gl = Gl::new(10, 10);
        gl.begin(GL_POINTS);
        gl.raster_pos2f(0.0, 0.0);
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.raster_pos3fv(&[1.0, 2.0]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.raster_pos2dv(&[0.5, 0.5]);
        assert_eq!(position(&mut gl).0, [7.5, 7.5, 0.5, 1.0]);
    }
}
