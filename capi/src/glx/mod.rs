//! GLX 1.4 (`GL/glx.h`), as Mesa 22.3 answers it on X11, over gleval's contexts: programs
//! that make their context with Xlib and GLX (glxgears, SDL, FLTK, pyglet, piglit through
//! waffle) draw through gleval into their own X windows.
//!
//! gleval renders on the client side: a GLX context is a [`Gl`] (the same as a GLUT window's
//! or an OSMesa context's, made current through [`crate::context`]); a GLX drawable is the
//! program's X window or pixmap, or a pbuffer of gleval's, drawn by [`crate::surface`]. The
//! X server needs no GLX extension; where it has one, GLX's errors carry its codes.
//!
//! | file | what |
//! |---|---|
//! | `configs.rs` | visuals and FBConfigs: `glXChooseVisual`, `glXGetConfig`, `glXChooseFBConfig`, ... |
//! | `contexts.rs` | `glXCreate*Context*`, `glXMakeCurrent`, `glXDestroyContext`, `glXCopyContext`, the current-context queries |
//! | `drawables.rs` | windows, pixmaps, pbuffers, `glXSwapBuffers`, `glXQueryDrawable`, the swap interval, `glXWait*` |
//! | `strings.rs` | versions, extension strings, `glXGetProcAddress` |
//! | `xfont.rs` | `glXUseXFont` |

mod configs;
mod contexts;
mod drawables;
mod strings;
mod xfont;

pub(crate) use configs::visual_of;
pub(crate) use contexts::current_display;
pub(crate) use strings::proc_address;

use crate::x11::{self, Display, Xid};

/// `Bool`.
pub type Bool = std::ffi::c_int;
pub const TRUE: Bool = 1;
pub const FALSE: Bool = 0;

/// GLX's errors, `GLXBad*` (offsets from the extension's first error; `glxproto.h`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum GlxError {
    Context = 0,
    Drawable = 2,
    Pixmap = 3,
    FbConfig = 9,
    Pbuffer = 10,
    Window = 12,
    /// GLX_ARB_create_context_profile's `GLXBadProfileARB`.
    Profile = 13,
}

/// X's core errors GLX reports.
pub const BAD_VALUE: u8 = 2;
pub const BAD_MATCH: u8 = 8;
pub const BAD_ACCESS: u8 = 10;
pub const BAD_ALLOC: u8 = 11;

/// GLX requests' minor opcodes (`glxproto.h`), which an error names.
pub mod request {
    pub const CREATE_CONTEXT: u16 = 3;
    pub const DESTROY_CONTEXT: u16 = 4;
    pub const MAKE_CURRENT: u16 = 5;
    pub const COPY_CONTEXT: u16 = 10;
    pub const SWAP_BUFFERS: u16 = 11;
    pub const CREATE_GLX_PIXMAP: u16 = 13;
    pub const DESTROY_GLX_PIXMAP: u16 = 15;
    pub const GET_FB_CONFIGS: u16 = 21;
    pub const CREATE_PIXMAP: u16 = 22;
    pub const DESTROY_PIXMAP: u16 = 23;
    pub const CREATE_NEW_CONTEXT: u16 = 24;
    pub const QUERY_CONTEXT: u16 = 25;
    pub const MAKE_CONTEXT_CURRENT: u16 = 26;
    pub const CREATE_PBUFFER: u16 = 27;
    pub const DESTROY_PBUFFER: u16 = 28;
    pub const GET_DRAWABLE_ATTRIBUTES: u16 = 29;
    pub const CREATE_WINDOW: u16 = 31;
    pub const DESTROY_WINDOW: u16 = 32;
    pub const CREATE_CONTEXT_ATTRIBS: u16 = 34;
}

/// Reports a GLX error to the program's X error handler (GLX's own numbers are offsets from
/// the server's first GLX error; without a GLX extension on the server only the call's
/// return value tells).
pub fn glx_error(display: *mut Display, error: GlxError, resource: Xid, minor: u16) {
    if let Some((_, first)) = x11::glx_extension(display) {
        x11::send_error(display, first.wrapping_add(error as u8), resource, minor);
    }
}

/// Reports one of X's core errors (`BadValue`, `BadMatch`, ...) for a GLX request.
pub fn x_error(display: *mut Display, code: u8, resource: Xid, minor: u16) {
    x11::send_error(display, code, resource, minor);
}

/// GLX's attribute lists: (name, value) pairs up to a `None` (0) name; `booleans` names the
/// attributes that stand alone (glXChooseVisual's).
///
/// # Safety
/// `list` is NULL or points at a list ended by 0, as GLX's callers promise.
pub unsafe fn attributes(list: *const std::ffi::c_int, booleans: &[i32]) -> Vec<(i32, i32)> {
    let mut out = Vec::new();
    if list.is_null() {
        return out;
    }
    let mut at = list;
    // A list longer than any GLX attribute list is cut, not read on without end.
    for _ in 0..256 {
        // SAFETY: within the list, which ends at its 0 (the caller's promise).
        let name = unsafe { *at };
        if name == 0 {
            break;
        }
        if booleans.contains(&name) {
            out.push((name, 1));
            at = at.wrapping_add(1);
        } else {
            // SAFETY: as above; a name is followed by its value.
            out.push((name, unsafe { *at.add(1) }));
            at = at.wrapping_add(2);
        }
    }
    out
}
