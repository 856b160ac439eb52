//! Matrix stacks and the matrix calls (GL 1.1 spec §2.10.2), plus GLU's `gluOrtho2D`,
//! `gluPerspective` and `gluLookAt`. Matrices are column-major as in GL; a call multiplies the
//! current matrix on the right (`C = C · M`), as `glMultMatrix` does. All arithmetic is `f32`,
//! as Mesa's `m_matrix.c`.

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{int_limit, put, put_enum, row, Kind, StateVar};
use super::types::*;
use super::Gl;
use glam::{Mat4, Vec3, Vec4};

/// Mesa's stack depths (`config.h`): MAX_MODELVIEW_STACK_DEPTH 32, projection 32, texture 10.
pub(crate) const DEPTHS: [usize; 3] = [32, 32, 10];

/// The stacks: modelview, projection, one texture stack per unit (GL 1.3 §2.10.2), and one
/// that `GL_TEXTURE` reaches from a unit beyond the fixed-function ones, where Mesa raises no
/// error and changes no unit's matrix (measured).
const STACKS: usize = 3 + super::units::MAX_TEXTURE_UNITS;

/// The matrix stacks; the top of each is its last element.
#[derive(Clone, Debug)]
pub(crate) struct MatrixStacks {
    stacks: [Vec<Mat4>; STACKS],
    mode: usize,
    /// The active texture unit, whose stack `GL_TEXTURE` names.
    unit: usize,
}

impl Default for MatrixStacks {
    fn default() -> Self {
        Self { stacks: std::array::from_fn(|_| vec![Mat4::IDENTITY]), mode: 0, unit: 0 }
    }
}

impl MatrixStacks {
    pub fn modelview(&self) -> Mat4 {
        *self.stacks[0].last().unwrap_or(&Mat4::IDENTITY)
    }

    pub fn projection(&self) -> Mat4 {
        *self.stacks[1].last().unwrap_or(&Mat4::IDENTITY)
    }

    /// The matrix mode as an index: 0 modelview, 1 projection, 2 texture.
    pub fn mode(&self) -> usize {
        self.mode
    }

    /// Sets the matrix mode (an index, as [`MatrixStacks::mode`] gives it).
    pub fn set_mode(&mut self, mode: usize) {
        self.mode = mode.min(2);
    }

    /// The active unit's texture matrix.
    pub fn texture(&self) -> Mat4 {
        *self.stacks[self.index(2)].last().unwrap_or(&Mat4::IDENTITY)
    }

    /// Unit `unit`'s texture matrix.
    pub fn texture_of(&self, unit: usize) -> Mat4 {
        *self.stacks[2 + unit.min(STACKS - 3)].last().unwrap_or(&Mat4::IDENTITY)
    }

    /// Follows `glActiveTexture`: `GL_TEXTURE` names that unit's stack.
    pub fn set_unit(&mut self, unit: usize) {
        self.unit = unit;
    }

    /// The stack of mode `mode` (0 modelview, 1 projection, 2 the active unit's texture).
    fn index(&self, mode: usize) -> usize {
        if mode < 2 {
            mode
        } else {
            2 + self.unit.min(STACKS - 3)
        }
    }

    /// How many matrices a stack holds (`GL_MODELVIEW_STACK_DEPTH`, ...): 0 modelview,
    /// 1 projection, 2 the active unit's texture.
    pub fn depth(&self, stack: usize) -> usize {
        self.stacks[self.index(stack)].len().max(1)
    }

    fn top(&mut self) -> &mut Mat4 {
        let index = self.index(self.mode);
        let stack = &mut self.stacks[index];
        if stack.is_empty() {
            stack.push(Mat4::IDENTITY);
        }
        let last = stack.len() - 1;
        &mut stack[last]
    }
}

/// Rotation by `angle` degrees about (x, y, z) as `glRotate` defines it; a near-zero axis leaves
/// the matrix unchanged (Mesa `_math_matrix_rotate`).
fn rotation(angle: f32, x: f32, y: f32, z: f32) -> Option<Mat4> {
    let axis = Vec3::new(x, y, z);
    let len = axis.length();
    if len <= 1.0e-4 || !len.is_finite() {
        return None;
    }
    Some(Mat4::from_axis_angle(axis / len, angle.to_radians()))
}

/// `glOrtho`'s matrix.
fn ortho_matrix(l: f32, r: f32, b: f32, t: f32, n: f32, f: f32) -> Mat4 {
    Mat4::from_cols(
        Vec4::new(2.0 / (r - l), 0.0, 0.0, 0.0),
        Vec4::new(0.0, 2.0 / (t - b), 0.0, 0.0),
        Vec4::new(0.0, 0.0, -2.0 / (f - n), 0.0),
        Vec4::new(-(r + l) / (r - l), -(t + b) / (t - b), -(f + n) / (f - n), 1.0),
    )
}

/// `glFrustum`'s matrix.
fn frustum_matrix(l: f32, r: f32, b: f32, t: f32, n: f32, f: f32) -> Mat4 {
    Mat4::from_cols(
        Vec4::new(2.0 * n / (r - l), 0.0, 0.0, 0.0),
        Vec4::new(0.0, 2.0 * n / (t - b), 0.0, 0.0),
        Vec4::new((r + l) / (r - l), (t + b) / (t - b), -(f + n) / (f - n), -1.0),
        Vec4::new(0.0, 0.0, -2.0 * f * n / (f - n), 0.0),
    )
}

/// The transform group's calls as a display list holds them: the matrices, the matrix mode and
/// the clip planes.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum TransformCall {
    MatrixMode(GLenum),
    LoadIdentity,
    LoadMatrix([f32; 16]),
    MultMatrix([f32; 16]),
    PushMatrix,
    PopMatrix,
    Translate([f32; 3]),
    Rotate([f32; 4]),
    Scale([f32; 3]),
    Ortho([f64; 6]),
    Frustum([f64; 6]),
    ClipPlane(GLenum, Vec<f64>),
}

impl Gl {
    /// Replays a listed call of the group.
    pub(crate) fn replay_transform_call(&mut self, call: &TransformCall) {
        use TransformCall as C;
        match call {
            C::MatrixMode(mode) => self.matrix_mode(*mode),
            C::LoadIdentity => self.load_identity(),
            C::LoadMatrix(m) => self.load_matrixf(m),
            C::MultMatrix(m) => self.mult_matrixf(m),
            C::PushMatrix => self.push_matrix(),
            C::PopMatrix => self.pop_matrix(),
            C::Translate([x, y, z]) => self.translatef(*x, *y, *z),
            C::Rotate([a, x, y, z]) => self.rotatef(*a, *x, *y, *z),
            C::Scale([x, y, z]) => self.scalef(*x, *y, *z),
            C::Ortho([l, r, b, t, n, f]) => self.ortho(*l, *r, *b, *t, *n, *f),
            C::Frustum([l, r, b, t, n, f]) => self.frustum(*l, *r, *b, *t, *n, *f),
            C::ClipPlane(plane, equation) => self.clip_plane(*plane, equation),
        }
    }
}

impl Gl {
    /// `glMatrixMode`: `GL_MODELVIEW`, `GL_PROJECTION` or `GL_TEXTURE`; else `GL_INVALID_ENUM`.
    pub fn matrix_mode(&mut self, mode: GLenum) {
        if self.compiled(|| ListCommand::Transform(TransformCall::MatrixMode(mode))) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        match mode {
            GL_MODELVIEW..=GL_TEXTURE => self.server.matrices.mode = (mode - GL_MODELVIEW) as usize,
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// Applies `f` to the current matrix (outside begin/end only).
    fn change_matrix(&mut self, f: impl FnOnce(&mut Mat4)) {
        if self.reject_inside_begin_end() {
            return;
        }
        f(self.server.matrices.top());
        self.touch_state();
    }

    /// `glOrtho` and `glFrustum` once listed: the list gate, then (outside `begin`/`end`)
    /// `GL_INVALID_VALUE` unless `valid`, then the current matrix times `matrix` of the planes
    /// (left, right, bottom, top, near, far), made in float as Mesa makes it.
    fn multiply_projection(
        &mut self,
        call: TransformCall,
        valid: bool,
        matrix: fn(f32, f32, f32, f32, f32, f32) -> Mat4,
    ) {
        let (TransformCall::Ortho(planes) | TransformCall::Frustum(planes)) = call else { return };
        if self.compiled(|| ListCommand::Transform(call)) || self.reject_inside_begin_end() {
            return;
        }
        if !valid {
            return self.set_error(GL_INVALID_VALUE);
        }
        let [l, r, b, t, n, f] = planes.map(|p| p as f32);
        self.change_matrix(|top| *top *= matrix(l, r, b, t, n, f));
    }

    /// `glLoadIdentity`.
    pub fn load_identity(&mut self) {
        if self.compiled(|| ListCommand::Transform(TransformCall::LoadIdentity)) {
            return;
        }
        self.change_matrix(|m| *m = Mat4::IDENTITY);
    }

    /// `glLoadMatrixf`: `m` needs 16 values, column-major.
    pub fn load_matrixf(&mut self, m: &[GLfloat]) {
        if let Some(m) = self.needs::<16>(m) {
            if self.compiled(|| ListCommand::Transform(TransformCall::LoadMatrix(m))) {
                return;
            }
            self.change_matrix(|top| *top = Mat4::from_cols_array(&m));
        }
    }

    /// `glMultMatrixf`: `m` needs 16 values, column-major.
    pub fn mult_matrixf(&mut self, m: &[GLfloat]) {
        if let Some(m) = self.needs::<16>(m) {
            if self.compiled(|| ListCommand::Transform(TransformCall::MultMatrix(m))) {
                return;
            }
            self.change_matrix(|top| *top *= Mat4::from_cols_array(&m));
        }
    }

    /// A plane given in object coordinates, as the current modelview matrix M takes it to eye
    /// coordinates (`glClipPlane`, `glTexGen`'s `GL_EYE_PLANE`; GL 1.1 §2.11): the row vector
    /// (p₁ p₂ p₃ p₄) M⁻¹, which is (M⁻¹)ᵀ times the column.
    pub(crate) fn plane_to_eye(&self, plane: glam::Vec4) -> glam::Vec4 {
        self.server.matrices.modelview().inverse().transpose() * plane
    }

    /// `glLoadMatrixd`: as [`Gl::load_matrixf`], the values cast to float (Mesa keeps floats).
    pub fn load_matrixd(&mut self, m: &[GLdouble]) {
        self.load_matrixf(&as_floats(m));
    }

    /// `glMultMatrixd`: as [`Gl::mult_matrixf`], the values cast to float.
    pub fn mult_matrixd(&mut self, m: &[GLdouble]) {
        self.mult_matrixf(&as_floats(m));
    }

    /// `glLoadTransposeMatrixf` (GL 1.3, `GL_ARB_transpose_matrix`): [`Gl::load_matrixf`] of
    /// `m` given row by row. Mesa's `_mesa_LoadTransposeMatrixf` transposes first, so a display
    /// list holds the column-major matrix and a short `m` is `glLoadMatrixf`'s error.
    pub fn load_transpose_matrixf(&mut self, m: &[GLfloat]) {
        self.load_matrixf(&transposed(m));
    }

    /// `glMultTransposeMatrixf` (GL 1.3): [`Gl::mult_matrixf`] of `m` given row by row.
    pub fn mult_transpose_matrixf(&mut self, m: &[GLfloat]) {
        self.mult_matrixf(&transposed(m));
    }

    /// `glLoadTransposeMatrixd` (GL 1.3): as [`Gl::load_transpose_matrixf`], the values cast to
    /// float (Mesa's `_math_transposefd`).
    pub fn load_transpose_matrixd(&mut self, m: &[GLdouble]) {
        self.load_transpose_matrixf(&as_floats(m));
    }

    /// `glMultTransposeMatrixd` (GL 1.3): as [`Gl::mult_transpose_matrixf`], the values cast to
    /// float.
    pub fn mult_transpose_matrixd(&mut self, m: &[GLdouble]) {
        self.mult_transpose_matrixf(&as_floats(m));
    }

    /// `glGetFloatv(GL_MODELVIEW_MATRIX)` for GLU, which loads its sampling matrices so
    /// (`glrenderer.cc`). Unlike `glGet`, it records no error inside `begin`/`end`.
    pub(crate) fn modelview_matrix(&self) -> Mat4 {
        self.server.matrices.modelview()
    }

    /// `glGetFloatv(GL_PROJECTION_MATRIX)` for GLU (see [`Gl::modelview_matrix`]).
    pub(crate) fn projection_matrix(&self) -> Mat4 {
        self.server.matrices.projection()
    }

    /// `glPushMatrix`: `GL_STACK_OVERFLOW` when the stack is full.
    pub fn push_matrix(&mut self) {
        if self.compiled(|| ListCommand::Transform(TransformCall::PushMatrix)) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        let mode = self.server.matrices.mode;
        let index = self.server.matrices.index(mode);
        let top = self.server.matrices.top().to_owned();
        if self.server.matrices.stacks[index].len() >= DEPTHS[mode] {
            return self.set_error(GL_STACK_OVERFLOW);
        }
        self.server.matrices.stacks[index].push(top);
    }

    /// `glPopMatrix`: `GL_STACK_UNDERFLOW` when only one matrix is left.
    pub fn pop_matrix(&mut self) {
        if self.compiled(|| ListCommand::Transform(TransformCall::PopMatrix)) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        let index = self.server.matrices.index(self.server.matrices.mode);
        let stack = &mut self.server.matrices.stacks[index];
        if stack.len() <= 1 {
            return self.set_error(GL_STACK_UNDERFLOW);
        }
        stack.pop();
        self.touch_state();
    }

    /// `glTranslatef`.
    pub fn translatef(&mut self, x: GLfloat, y: GLfloat, z: GLfloat) {
        if self.compiled(|| ListCommand::Transform(TransformCall::Translate([x, y, z]))) {
            return;
        }
        self.change_matrix(|m| *m *= Mat4::from_translation(Vec3::new(x, y, z)));
    }

    /// `glTranslated` (cast to float).
    pub fn translated(&mut self, x: GLdouble, y: GLdouble, z: GLdouble) {
        self.translatef(x as f32, y as f32, z as f32);
    }

    /// `glRotatef`: `angle` in degrees about the axis (x, y, z).
    pub fn rotatef(&mut self, angle: GLfloat, x: GLfloat, y: GLfloat, z: GLfloat) {
        if self.compiled(|| ListCommand::Transform(TransformCall::Rotate([angle, x, y, z]))) {
            return;
        }
        let r = rotation(angle, x, y, z);
        self.change_matrix(|m| {
            if let Some(r) = r {
                *m *= r;
            }
        });
    }

    /// `glRotated` (cast to float).
    pub fn rotated(&mut self, angle: GLdouble, x: GLdouble, y: GLdouble, z: GLdouble) {
        self.rotatef(angle as f32, x as f32, y as f32, z as f32);
    }

    /// `glScalef`.
    pub fn scalef(&mut self, x: GLfloat, y: GLfloat, z: GLfloat) {
        if self.compiled(|| ListCommand::Transform(TransformCall::Scale([x, y, z]))) {
            return;
        }
        self.change_matrix(|m| *m *= Mat4::from_scale(Vec3::new(x, y, z)));
    }

    /// `glScaled` (cast to float).
    pub fn scaled(&mut self, x: GLdouble, y: GLdouble, z: GLdouble) {
        self.scalef(x as f32, y as f32, z as f32);
    }

    /// `glOrtho`: `left == right`, `bottom == top` or `near == far` → `GL_INVALID_VALUE`.
    pub fn ortho(
        &mut self,
        left: GLdouble,
        right: GLdouble,
        bottom: GLdouble,
        top: GLdouble,
        near: GLdouble,
        far: GLdouble,
    ) {
        let planes = [left, right, bottom, top, near, far];
        let valid = left != right && bottom != top && near != far;
        self.multiply_projection(TransformCall::Ortho(planes), valid, ortho_matrix);
    }

    /// `glFrustum`: `near <= 0`, `far <= 0`, `near == far`, `left == right` or
    /// `bottom == top` → `GL_INVALID_VALUE`.
    pub fn frustum(
        &mut self,
        left: GLdouble,
        right: GLdouble,
        bottom: GLdouble,
        top: GLdouble,
        near: GLdouble,
        far: GLdouble,
    ) {
        let planes = [left, right, bottom, top, near, far];
        let valid = near > 0.0 && far > 0.0 && near != far && left != right && top != bottom;
        self.multiply_projection(TransformCall::Frustum(planes), valid, frustum_matrix);
    }

    /// `gluOrtho2D`: `glOrtho(left, right, bottom, top, -1, 1)`.
    pub fn glu_ortho_2d(&mut self, left: GLdouble, right: GLdouble, bottom: GLdouble, top: GLdouble) {
        self.ortho(left, right, bottom, top, -1.0, 1.0);
    }

    /// `gluPerspective`: like GLU, does nothing when `far == near`, `aspect == 0` or the
    /// field of view makes sin(fovy/2) zero.
    pub fn glu_perspective(&mut self, fovy: GLdouble, aspect: GLdouble, near: GLdouble, far: GLdouble) {
        let radians = fovy / 2.0 * std::f64::consts::PI / 180.0;
        let (sine, delta_z) = (radians.sin(), far - near);
        if delta_z == 0.0 || sine == 0.0 || aspect == 0.0 {
            return;
        }
        let cotangent = radians.cos() / sine;
        let mut m = [0.0f32; 16];
        m[0] = (cotangent / aspect) as f32;
        m[5] = cotangent as f32;
        m[10] = (-(far + near) / delta_z) as f32;
        m[11] = -1.0;
        m[14] = (-2.0 * near * far / delta_z) as f32;
        self.mult_matrixf(&m);
    }

    /// `gluLookAt`: eye at `eye`, looking at `center`, with `up` as the up direction.
    #[allow(clippy::too_many_arguments)]
    pub fn glu_look_at(
        &mut self,
        eye_x: GLdouble,
        eye_y: GLdouble,
        eye_z: GLdouble,
        center_x: GLdouble,
        center_y: GLdouble,
        center_z: GLdouble,
        up_x: GLdouble,
        up_y: GLdouble,
        up_z: GLdouble,
    ) {
        let eye = glam::DVec3::new(eye_x, eye_y, eye_z);
        let forward = (glam::DVec3::new(center_x, center_y, center_z) - eye).normalize_or_zero();
        let side = forward.cross(glam::DVec3::new(up_x, up_y, up_z)).normalize_or_zero();
        let up = side.cross(forward);
        #[rustfmt::skip]
        let m = [
            side.x as f32, up.x as f32, -forward.x as f32, 0.0,
            side.y as f32, up.y as f32, -forward.y as f32, 0.0,
            side.z as f32, up.z as f32, -forward.z as f32, 0.0,
            0.0, 0.0, 0.0, 1.0,
        ];
        self.mult_matrixf(&m);
        self.translated(-eye_x, -eye_y, -eye_z);
    }
}

/// A matrix's first 16 doubles cast to float, as the `d` forms pass them to the `f` ones.
fn as_floats(m: &[GLdouble]) -> Vec<GLfloat> {
    m.iter().take(16).map(|&v| v as GLfloat).collect()
}

/// A 4 × 4 matrix given row by row, column by column; a slice of another length as it is (the
/// load or multiply then raises its error).
fn transposed(m: &[GLfloat]) -> Vec<GLfloat> {
    if m.len() < 16 {
        return m.to_vec();
    }
    (0..16).map(|i| m[(i % 4) * 4 + i / 4]).collect()
}

/// Writes a matrix as the answer, column by column.
fn put_matrix(o: &mut [f64], m: glam::Mat4) {
    put(o, &m.to_cols_array());
}

/// The transform group's `glGet` rows (the matrix mode, the matrices and their stacks), and the stacks' limits.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_MODELVIEW_MATRIX, 16, Kind::Normalized, |gl, o| put_matrix(o, gl.server.matrices.modelview())),
    row(GL_PROJECTION_MATRIX, 16, Kind::Normalized, |gl, o| put_matrix(o, gl.server.matrices.projection())),
    row(GL_TEXTURE_MATRIX, 16, Kind::Normalized, |gl, o| put_matrix(o, gl.server.matrices.texture())),
    // GL 1.3's transposed forms (Mesa's `TYPE_MATRIX_T`: converted as the matrices are).
    row(GL_TRANSPOSE_MODELVIEW_MATRIX, 16, Kind::Normalized, |gl, o| {
        put_matrix(o, gl.server.matrices.modelview().transpose())
    }),
    row(GL_TRANSPOSE_PROJECTION_MATRIX, 16, Kind::Normalized, |gl, o| {
        put_matrix(o, gl.server.matrices.projection().transpose())
    }),
    // Mesa 22.3 answers unit 0's whichever unit is active (measured, `multitexture.calls`).
    row(GL_TRANSPOSE_TEXTURE_MATRIX, 16, Kind::Normalized, |gl, o| {
        put_matrix(o, gl.server.matrices.texture_of(0).transpose())
    }),
    row(GL_MODELVIEW_STACK_DEPTH, 1, Kind::Int, |gl, o| o[0] = gl.server.matrices.depth(0) as f64),
    row(GL_PROJECTION_STACK_DEPTH, 1, Kind::Int, |gl, o| o[0] = gl.server.matrices.depth(1) as f64),
    row(GL_TEXTURE_STACK_DEPTH, 1, Kind::Int, |gl, o| o[0] = gl.server.matrices.depth(2) as f64),
    row(GL_MATRIX_MODE, 1, Kind::Int, |gl, o| {
        put_enum(o, [GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE][gl.server.matrices.mode()])
    }),
    int_limit!(GL_MAX_MODELVIEW_STACK_DEPTH, DEPTHS[0]),
    int_limit!(GL_MAX_PROJECTION_STACK_DEPTH, DEPTHS[1]),
    int_limit!(GL_MAX_TEXTURE_STACK_DEPTH, DEPTHS[2]),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_transpose_matrix_is_given_row_by_row() {
        let mut gl = Gl::new(4, 4);
        let rows: Vec<f32> = (1..=16).map(|v| v as f32).collect();
        gl.load_transpose_matrixf(&rows);
        let (mut m, mut t) = ([0.0f32; 16], [0.0f32; 16]);
        gl.get_floatv(GL_MODELVIEW_MATRIX, &mut m);
        gl.get_floatv(GL_TRANSPOSE_MODELVIEW_MATRIX, &mut t);
        assert_eq!((m[1], m[4], t), (5.0, 2.0, std::array::from_fn(|i| rows[i])));
        gl.mult_transpose_matrixd(&[1.0; 15]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE, "a short matrix is glMultMatrix's error");
    }

    #[test]
    fn ortho_maps_box_to_ndc() {
        let m = ortho_matrix(-2.2, 2.2, -1.1, 1.1, -1.0, 1.0);
        let p = m * Vec4::new(2.2, -1.1, 0.5, 1.0);
        assert!((p - Vec4::new(1.0, -1.0, -0.5, 1.0)).abs().max_element() < 1e-6);
    }

    #[test]
    fn frustum_maps_near_and_far_planes() {
        let m = frustum_matrix(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
        let near = m * Vec4::new(1.0, 1.0, -1.0, 1.0);
        let far = m * Vec4::new(0.0, 0.0, -10.0, 1.0);
        assert!((near / near.w - Vec4::new(1.0, 1.0, -1.0, 1.0)).abs().max_element() < 1e-6);
        assert!((far.z / far.w - 1.0).abs() < 1e-5);
    }
}
