//! The pixel path's calls as display lists hold them: one `ListCommand::Pixels` variant for
//! all of them, replayed through the methods that recorded them (the list gate of
//! `lists.rs`; GL 1.1 §5.4 compiles every one of these).

use super::copy_texture::{CopyTexImage, CopyTexSubImage, TexSubImage1D};
use super::pixels::PixelStore;
use super::types::*;
use super::Gl;

/// One compiled call of the pixel path (colour index included).
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum PixelCommand {
    /// `glPixelZoom`.
    Zoom(GLfloat, GLfloat),
    /// `glPixelTransfer*` (stored as the float call).
    Transfer(GLenum, GLfloat),
    /// `glPixelMap*`: map, size, and the values (as floats) copied at compile time.
    Map(GLenum, GLsizei, Vec<GLfloat>),
    /// `glCopyPixels`: x, y, width, height and the buffer.
    CopyPixels([GLint; 4], GLenum),
    /// `glCopyTexImage1D/2D`.
    CopyTexImage(CopyTexImage),
    /// `glCopyTexSubImage1D/2D`.
    CopyTexSubImage(CopyTexSubImage),
    /// `glTexSubImage1D` with the client's bytes and the unpack modes of compile time.
    TexSubImage1D(TexSubImage1D, PixelStore, Vec<u8>),
    /// `glPrioritizeTextures`, as (name, priority) pairs.
    PrioritizeTextures(Vec<(GLuint, GLclampf)>),
    /// `glIndex*`.
    Index(GLfloat),
    /// `glClearIndex`.
    ClearIndex(GLfloat),
    /// `glIndexMask`.
    IndexMask(GLuint),
}

impl Gl {
    /// Replays a compiled pixel call.
    pub(crate) fn execute_pixel_command(&mut self, command: &PixelCommand) {
        use PixelCommand as P;
        match command {
            P::Zoom(x, y) => self.pixel_zoom(*x, *y),
            P::Transfer(pname, param) => self.pixel_transferf(*pname, *param),
            P::Map(map, size, values) => self.pixel_mapfv(*map, *size, values),
            P::CopyPixels([x, y, w, h], type_) => self.copy_pixels(*x, *y, *w, *h, *type_),
            P::CopyTexImage(call) => self.copy_tex_image(*call),
            P::CopyTexSubImage(call) => self.copy_tex_sub_image(*call),
            P::TexSubImage1D(call, store, bytes) => self.replay_tex_sub_image_1d(*call, *store, bytes),
            P::PrioritizeTextures(pairs) => {
                for &(name, priority) in pairs {
                    self.prioritize_textures(1, &[name], &[priority]);
                }
            }
            P::Index(c) => self.indexf(*c),
            P::ClearIndex(c) => self.replay_clear_index(*c),
            P::IndexMask(mask) => self.index_mask(*mask),
        }
    }
}
