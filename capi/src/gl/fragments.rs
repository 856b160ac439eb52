//! The stencil and accumulation buffers, write masks, the scissor box, the logic op and the
//! draw and read buffers.

use gleval::gl::types::*;

forward! {
    glStencilFunc(func: GLenum, reference: GLint, mask: GLuint) => stencil_func;
    glStencilOp(fail: GLenum, zfail: GLenum, zpass: GLenum) => stencil_op;
    glStencilMask(mask: GLuint) => stencil_mask;
    glClearStencil(s: GLint) => clear_stencil;
    glAccum(op: GLenum, value: GLfloat) => accum;
    glClearAccum(red: GLfloat, green: GLfloat, blue: GLfloat, alpha: GLfloat) => clear_accum;
    glDepthMask(flag: GLboolean) => depth_mask;
    glColorMask(red: GLboolean, green: GLboolean, blue: GLboolean, alpha: GLboolean) => color_mask;
    glScissor(x: GLint, y: GLint, width: GLsizei, height: GLsizei) => scissor;
    glLogicOp(opcode: GLenum) => logic_op;
    glDrawBuffer(mode: GLenum) => draw_buffer;
    glReadBuffer(mode: GLenum) => read_buffer;
}
