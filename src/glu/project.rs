//! GLU's coordinate mappings (GLU 1.3 §4.1–4.2; SGI GLU 9.0.2 `libutil/project.c`):
//! `gluProject`, `gluUnProject`, `gluUnProject4` and `gluPickMatrix`, computed in the same
//! order of double-precision operations as GLU's (its row-by-row matrix product, its cofactor
//! inverse that fails only on a zero determinant), so that results agree with the system's
//! libGLU bit for bit (`tests/reference/glu/project`).
//!
//! The matrices are GL's column-major arrays (`glGetDoublev(GL_MODELVIEW_MATRIX)`), the
//! viewport `glGetIntegerv(GL_VIEWPORT)`'s four values. A slice shorter than that (16, 16, 4)
//! makes the call fail (`GL_FALSE`), as a singular matrix does; GLU sets no GL error here.

use crate::gl::consts::*;
use crate::gl::types::*;
use crate::gl::Gl;

/// `out = matrix · in` for a column-major matrix (GLU's `__gluMultMatrixVecd`).
fn mult_matrix_vec(m: &[f64; 16], v: [f64; 4]) -> [f64; 4] {
    std::array::from_fn(|i| v[0] * m[i] + v[1] * m[4 + i] + v[2] * m[8 + i] + v[3] * m[12 + i])
}

/// GLU's `__gluMultMatricesd(a, b)`: `r[i][j] = Σ a[i][k] b[k][j]` on the arrays as rows,
/// which is `b · a` as GL matrices.
fn mult_matrices(a: &[f64; 16], b: &[f64; 16]) -> [f64; 16] {
    std::array::from_fn(|n| {
        let (i, j) = (n / 4, n % 4);
        a[i * 4] * b[j] + a[i * 4 + 1] * b[4 + j] + a[i * 4 + 2] * b[8 + j] + a[i * 4 + 3] * b[12 + j]
    })
}

/// GLU's `__gluInvertMatrixd` (David Moore's cofactor expansion, Mesa bug 6748): `None` when
/// the determinant is exactly zero.
#[rustfmt::skip]
fn invert(m: &[f64; 16]) -> Option<[f64; 16]> {
    let mut inv = [0.0f64; 16];
    inv[0] = m[5]*m[10]*m[15] - m[5]*m[11]*m[14] - m[9]*m[6]*m[15] + m[9]*m[7]*m[14] + m[13]*m[6]*m[11] - m[13]*m[7]*m[10];
    inv[4] = -m[4]*m[10]*m[15] + m[4]*m[11]*m[14] + m[8]*m[6]*m[15] - m[8]*m[7]*m[14] - m[12]*m[6]*m[11] + m[12]*m[7]*m[10];
    inv[8] = m[4]*m[9]*m[15] - m[4]*m[11]*m[13] - m[8]*m[5]*m[15] + m[8]*m[7]*m[13] + m[12]*m[5]*m[11] - m[12]*m[7]*m[9];
    inv[12] = -m[4]*m[9]*m[14] + m[4]*m[10]*m[13] + m[8]*m[5]*m[14] - m[8]*m[6]*m[13] - m[12]*m[5]*m[10] + m[12]*m[6]*m[9];
    inv[1] = -m[1]*m[10]*m[15] + m[1]*m[11]*m[14] + m[9]*m[2]*m[15] - m[9]*m[3]*m[14] - m[13]*m[2]*m[11] + m[13]*m[3]*m[10];
    inv[5] = m[0]*m[10]*m[15] - m[0]*m[11]*m[14] - m[8]*m[2]*m[15] + m[8]*m[3]*m[14] + m[12]*m[2]*m[11] - m[12]*m[3]*m[10];
    inv[9] = -m[0]*m[9]*m[15] + m[0]*m[11]*m[13] + m[8]*m[1]*m[15] - m[8]*m[3]*m[13] - m[12]*m[1]*m[11] + m[12]*m[3]*m[9];
    inv[13] = m[0]*m[9]*m[14] - m[0]*m[10]*m[13] - m[8]*m[1]*m[14] + m[8]*m[2]*m[13] + m[12]*m[1]*m[10] - m[12]*m[2]*m[9];
    inv[2] = m[1]*m[6]*m[15] - m[1]*m[7]*m[14] - m[5]*m[2]*m[15] + m[5]*m[3]*m[14] + m[13]*m[2]*m[7] - m[13]*m[3]*m[6];
    inv[6] = -m[0]*m[6]*m[15] + m[0]*m[7]*m[14] + m[4]*m[2]*m[15] - m[4]*m[3]*m[14] - m[12]*m[2]*m[7] + m[12]*m[3]*m[6];
    inv[10] = m[0]*m[5]*m[15] - m[0]*m[7]*m[13] - m[4]*m[1]*m[15] + m[4]*m[3]*m[13] + m[12]*m[1]*m[7] - m[12]*m[3]*m[5];
    inv[14] = -m[0]*m[5]*m[14] + m[0]*m[6]*m[13] + m[4]*m[1]*m[14] - m[4]*m[2]*m[13] - m[12]*m[1]*m[6] + m[12]*m[2]*m[5];
    inv[3] = -m[1]*m[6]*m[11] + m[1]*m[7]*m[10] + m[5]*m[2]*m[11] - m[5]*m[3]*m[10] - m[9]*m[2]*m[7] + m[9]*m[3]*m[6];
    inv[7] = m[0]*m[6]*m[11] - m[0]*m[7]*m[10] - m[4]*m[2]*m[11] + m[4]*m[3]*m[10] + m[8]*m[2]*m[7] - m[8]*m[3]*m[6];
    inv[11] = -m[0]*m[5]*m[11] + m[0]*m[7]*m[9] + m[4]*m[1]*m[11] - m[4]*m[3]*m[9] - m[8]*m[1]*m[7] + m[8]*m[3]*m[5];
    inv[15] = m[0]*m[5]*m[10] - m[0]*m[6]*m[9] - m[4]*m[1]*m[10] + m[4]*m[2]*m[9] + m[8]*m[1]*m[6] - m[8]*m[2]*m[5];
    let det = m[0] * inv[0] + m[1] * inv[4] + m[2] * inv[8] + m[3] * inv[12];
    if det == 0.0 {
        return None;
    }
    let det = 1.0 / det;
    Some(inv.map(|x| x * det))
}

/// The matrices and viewport of a call, or `None` when a slice is too short.
fn arguments(model: &[GLdouble], proj: &[GLdouble], view: &[GLint]) -> Option<([f64; 16], [f64; 16], [f64; 4])> {
    let model: [f64; 16] = model.get(..16)?.try_into().ok()?;
    let proj: [f64; 16] = proj.get(..16)?.try_into().ok()?;
    let view = view.get(..4)?;
    Some((model, proj, std::array::from_fn(|i| f64::from(view[i]))))
}

/// `(model · proj)⁻¹` as GLU forms it for the unprojections.
fn inverse_of(model: &[f64; 16], proj: &[f64; 16]) -> Option<[f64; 16]> {
    invert(&mult_matrices(model, proj))
}

/// GL's `GL_TRUE`/`GL_FALSE` as `gluProject`'s `GLint`.
fn result(ok: bool) -> GLint {
    GLint::from(if ok { GL_TRUE } else { GL_FALSE })
}

impl Gl {
    /// `gluProject(objX, objY, objZ, model, proj, view, &winX, &winY, &winZ)`: the window
    /// coordinates of an object point. `GL_FALSE` (outputs untouched) when the clip w is 0.
    #[allow(clippy::too_many_arguments)]
    pub fn glu_project(
        &mut self,
        obj_x: GLdouble,
        obj_y: GLdouble,
        obj_z: GLdouble,
        model: &[GLdouble],
        proj: &[GLdouble],
        view: &[GLint],
        win_x: &mut GLdouble,
        win_y: &mut GLdouble,
        win_z: &mut GLdouble,
    ) -> GLint {
        let Some((model, proj, view)) = arguments(model, proj, view) else { return result(false) };
        let eye = mult_matrix_vec(&model, [obj_x, obj_y, obj_z, 1.0]);
        let mut v = mult_matrix_vec(&proj, eye);
        if v[3] == 0.0 {
            return result(false);
        }
        let w = v[3];
        for c in &mut v[..3] {
            *c /= w;
            *c = *c * 0.5 + 0.5;
        }
        *win_x = v[0] * view[2] + view[0];
        *win_y = v[1] * view[3] + view[1];
        *win_z = v[2];
        result(true)
    }

    /// `gluUnProject(winX, winY, winZ, model, proj, view, &objX, &objY, &objZ)`: the object
    /// point at window coordinates (z in [0, 1]). `GL_FALSE` for a singular `proj · model` or a
    /// w of 0.
    #[allow(clippy::too_many_arguments)]
    pub fn glu_un_project(
        &mut self,
        win_x: GLdouble,
        win_y: GLdouble,
        win_z: GLdouble,
        model: &[GLdouble],
        proj: &[GLdouble],
        view: &[GLint],
        obj_x: &mut GLdouble,
        obj_y: &mut GLdouble,
        obj_z: &mut GLdouble,
    ) -> GLint {
        let Some((model, proj, view)) = arguments(model, proj, view) else { return result(false) };
        let Some(inverse) = inverse_of(&model, &proj) else { return result(false) };
        let x = (win_x - view[0]) / view[2];
        let y = (win_y - view[1]) / view[3];
        let out = mult_matrix_vec(&inverse, [x * 2.0 - 1.0, y * 2.0 - 1.0, win_z * 2.0 - 1.0, 1.0]);
        if out[3] == 0.0 {
            return result(false);
        }
        (*obj_x, *obj_y, *obj_z) = (out[0] / out[3], out[1] / out[3], out[2] / out[3]);
        result(true)
    }

    /// `gluUnProject4(winX, winY, winZ, clipW, model, proj, view, near, far, &objX, &objY,
    /// &objZ, &objW)`: as [`Gl::glu_un_project`] with a clip w and the depth range given, the
    /// homogeneous object point undivided.
    #[allow(clippy::too_many_arguments)]
    pub fn glu_un_project4(
        &mut self,
        win_x: GLdouble,
        win_y: GLdouble,
        win_z: GLdouble,
        clip_w: GLdouble,
        model: &[GLdouble],
        proj: &[GLdouble],
        view: &[GLint],
        near_val: GLdouble,
        far_val: GLdouble,
        obj_x: &mut GLdouble,
        obj_y: &mut GLdouble,
        obj_z: &mut GLdouble,
        obj_w: &mut GLdouble,
    ) -> GLint {
        let Some((model, proj, view)) = arguments(model, proj, view) else { return result(false) };
        let Some(inverse) = inverse_of(&model, &proj) else { return result(false) };
        let x = (win_x - view[0]) / view[2];
        let y = (win_y - view[1]) / view[3];
        let z = (win_z - near_val) / (far_val - near_val);
        let out = mult_matrix_vec(&inverse, [x * 2.0 - 1.0, y * 2.0 - 1.0, z * 2.0 - 1.0, clip_w]);
        if out[3] == 0.0 {
            return result(false);
        }
        (*obj_x, *obj_y, *obj_z, *obj_w) = (out[0], out[1], out[2], out[3]);
        result(true)
    }

    /// `gluPickMatrix(x, y, deltaX, deltaY, view)`: multiplies the current matrix so that the
    /// `deltaX` × `deltaY` region centred on window (x, y) fills the viewport, with GLU's
    /// `glTranslatef` and `glScalef` (float arguments). A non-positive size, or a viewport
    /// slice shorter than 4, changes nothing.
    pub fn glu_pick_matrix(&mut self, x: GLdouble, y: GLdouble, delta_x: GLdouble, delta_y: GLdouble, view: &[GLint]) {
        let Some(view) = view.get(..4) else { return };
        if delta_x <= 0.0 || delta_y <= 0.0 {
            return;
        }
        let v: [f64; 4] = std::array::from_fn(|i| f64::from(view[i]));
        let tx = (v[2] - 2.0 * (x - v[0])) / delta_x;
        let ty = (v[3] - 2.0 * (y - v[1])) / delta_y;
        self.translatef(tx as f32, ty as f32, 0.0);
        self.scalef((v[2] / delta_x) as f32, (v[3] / delta_y) as f32, 1.0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const IDENTITY: [f64; 16] = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];

    #[test]
    fn project_and_unproject_are_inverse() {
        let mut gl = Gl::new(4, 4);
        let view = [0, 0, 200, 100];
        let (mut x, mut y, mut z) = (0.0, 0.0, 0.0);
        assert_eq!(gl.glu_project(0.5, -0.5, 0.0, &IDENTITY, &IDENTITY, &view, &mut x, &mut y, &mut z), 1);
        assert_eq!((x, y, z), (150.0, 25.0, 0.5));
        let (mut a, mut b, mut c) = (0.0, 0.0, 0.0);
        assert_eq!(gl.glu_un_project(x, y, z, &IDENTITY, &IDENTITY, &view, &mut a, &mut b, &mut c), 1);
        assert_eq!((a, b, c), (0.5, -0.5, 0.0));
        assert_eq!(gl.glu_un_project(x, y, z, &[0.0; 16], &IDENTITY, &view, &mut a, &mut b, &mut c), 0);
        assert_eq!(gl.glu_project(0.0, 0.0, 0.0, &IDENTITY, &IDENTITY, &view[..3], &mut a, &mut b, &mut c), 0);
    }
}
