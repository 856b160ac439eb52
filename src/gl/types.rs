//! C's GL type names, so that ported signatures read the same.

/// `GLenum`.
pub type GLenum = u32;
/// `GLbitfield`.
pub type GLbitfield = u32;
/// `GLboolean` (`GL_TRUE` = 1, `GL_FALSE` = 0).
pub type GLboolean = u8;
/// `GLint`.
pub type GLint = i32;
/// `GLuint`.
pub type GLuint = u32;
/// `GLsizei`.
pub type GLsizei = i32;
/// `GLfloat`.
pub type GLfloat = f32;
/// `GLdouble`.
pub type GLdouble = f64;
/// `GLclampf`.
pub type GLclampf = f32;
/// `GLclampd`.
pub type GLclampd = f64;
/// `GLubyte`.
pub type GLubyte = u8;
/// `GLbyte`.
pub type GLbyte = i8;
/// `GLshort`.
pub type GLshort = i16;
/// `GLushort`.
pub type GLushort = u16;
/// `GLvoid`: only behind a pointer in C; Rust signatures take typed slices (`&[u8]` where GL
/// reads raw memory, as `glCallLists` does).
pub type GLvoid = core::ffi::c_void;

/// C's `GLsizeiptr` (GL 1.5): a buffer object's size in bytes, `ptrdiff_t`.
pub type GLsizeiptr = isize;

/// C's `GLintptr` (GL 1.5): an offset into a buffer object in bytes, `ptrdiff_t`.
pub type GLintptr = isize;
