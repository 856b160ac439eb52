//! The integer forms of `glFog` and `glTexEnv` that GL 1.1 has besides the float ones: each
//! converts as Mesa's does (`main/fog.c`, `main/texenv.c`: colours through `INT_TO_FLOAT`, the
//! rest as they are) and calls the float vector form, so lists, errors and state are its.

use super::consts::*;
use super::types::*;
use super::variants::GlComponent;
use super::Gl;

/// Up to four integers as the float form reads them: a colour normalised, else as they are.
fn converted(color: bool, params: &[GLint]) -> Vec<GLfloat> {
    params.iter().take(4).map(|&p| if color { p.normalized() } else { p as GLfloat }).collect()
}

impl Gl {
    /// `glFogiv`: `GL_FOG_COLOR` normalised, the other names as they are.
    pub fn fogiv(&mut self, pname: GLenum, params: &[GLint]) {
        let values = converted(pname == GL_FOG_COLOR, params);
        self.fogfv(pname, &values);
    }

    /// `glTexEnviv`: `GL_TEXTURE_ENV_COLOR` normalised, the mode as it is.
    pub fn tex_enviv(&mut self, target: GLenum, pname: GLenum, params: &[GLint]) {
        let values = converted(pname == GL_TEXTURE_ENV_COLOR, params);
        self.tex_envfv(target, pname, &values);
    }
}
