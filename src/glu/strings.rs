//! `gluGetString` and `gluCheckExtension` (GLU 9.0 `libutil/registry.c`), answering as real
//! GLU 9.0.2 does (`tests/reference/glu/strings.c`).

use crate::gl::consts::{GL_FALSE, GL_TRUE};
use crate::gl::types::*;
use crate::gl::Gl;
use crate::glu::consts::{GLU_EXTENSIONS, GLU_VERSION};

/// GLU 9.0.2's extension string, its trailing space included.
const EXTENSIONS: &str = "GLU_EXT_nurbs_tessellator GLU_EXT_object_space_tess ";

/// `gluGetString` without a context (GLU needs none): see [`Gl::glu_get_string`].
#[must_use]
pub fn glu_get_string(name: GLenum) -> Option<&'static str> {
    match name {
        GLU_VERSION => Some("1.3"),
        GLU_EXTENSIONS => Some(EXTENSIONS),
        _ => None,
    }
}

/// `gluCheckExtension` without a context: see [`Gl::glu_check_extension`].
#[must_use]
pub fn glu_check_extension(ext_name: &[u8], ext_string: &[u8]) -> GLboolean {
    let found = ext_string.split(|&b| b == b' ').any(|word| !word.is_empty() && word == ext_name);
    if found {
        GL_TRUE
    } else {
        GL_FALSE
    }
}

impl Gl {
    /// `gluGetString`: `"1.3"` for `GLU_VERSION`, GLU's extension string for
    /// `GLU_EXTENSIONS`, `None` (C's NULL, no error) for another name.
    ///
    /// ```
    /// use gleval::prelude::*;
    /// let gl = Gl::new(1, 1);
    /// assert_eq!(gl.glu_get_string(GLU_VERSION), Some("1.3"));
    /// assert_eq!(gl.glu_get_string(GL_VERSION), None);
    /// ```
    #[must_use]
    pub fn glu_get_string(&self, name: GLenum) -> Option<&'static str> {
        glu_get_string(name)
    }

    /// `gluCheckExtension`: `GL_TRUE` when `ext_name` is one of the words of `ext_string`,
    /// words being what lies between spaces (GLU splits with `strtok(s, " ")`: only the space
    /// separates, and a name holding a space or an empty name never matches).
    ///
    /// ```
    /// use gleval::prelude::*;
    /// let gl = Gl::new(1, 1);
    /// let exts = gl.glu_get_string(GLU_EXTENSIONS).unwrap();
    /// assert_eq!(gl.glu_check_extension("GLU_EXT_object_space_tess", exts), GL_TRUE);
    /// assert_eq!(gl.glu_check_extension("GLU_EXT", exts), GL_FALSE);
    /// ```
    #[must_use]
    pub fn glu_check_extension(&self, ext_name: impl AsRef<[u8]>, ext_string: impl AsRef<[u8]>) -> GLboolean {
        glu_check_extension(ext_name.as_ref(), ext_string.as_ref())
    }
}
