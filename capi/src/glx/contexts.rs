//! GLX contexts: creation (`glXCreateContext`, `glXCreateNewContext`,
//! `glXCreateContextAttribsARB`), binding (`glXMakeCurrent`, `glXMakeContextCurrent`), their
//! end (`glXDestroyContext`), `glXCopyContext`, `glXIsDirect`, `glXQueryContext` and the
//! current-context queries.
//!
//! A context is current in at most one thread (another thread's bind is `BadAccess`); one
//! destroyed while current lives until it is released, as GLX 1.4 §3.3.7 says. The
//! registry of live contexts ([`crate::live_contexts`], as EGL's) tells a handle that is one
//! from one that is not (`GLXBadContext`, never a crash).

use super::configs::{config_of_visual, config_or_error, GLX_FBCONFIG_ID, GLX_RENDER_TYPE, GLX_RGBA_TYPE, GLX_SCREEN};
use super::{glx_error, request, x_error, Bool, GlxError, BAD_ACCESS, BAD_MATCH, BAD_VALUE, FALSE, TRUE};
use crate::configs::Config;
use crate::live_contexts::{ApiContext, Registry};
use crate::surface::{self, Key, Output};
use crate::x11::{self, Display, XVisualInfo, Xid};
use gleval::gl::Gl;
use std::cell::Cell;
use std::ffi::{c_int, c_void};

/// What a `GLXContext` points at.
pub struct GlxContext {
    gl: Gl,
    config: &'static Config,
    /// Whether it was ever bound (its viewport and scissor box are set the first time).
    bound_once: bool,
    display: *mut Display,
    draw: Xid,
    read: Xid,
}

impl ApiContext for GlxContext {
    fn gl(&mut self) -> &mut Gl {
        &mut self.gl
    }
}

thread_local! {
    /// The GLX context current in this thread.
    static CURRENT: Cell<*mut GlxContext> = const { Cell::new(std::ptr::null_mut()) };
}

/// Live GLX contexts.
static CONTEXTS: Registry<GlxContext> = Registry::new(&CURRENT);

/// The live context a handle names.
fn lookup(handle: *mut GlxContext) -> Option<crate::live_contexts::Life> {
    CONTEXTS.life(handle)
}

/// The display of the context current in this thread (NULL if none is a GLX context).
pub(crate) fn current_display() -> *mut Display {
    let ctx = CONTEXTS.current();
    // SAFETY: a current context is live (it is freed only once released).
    unsafe { ctx.as_ref() }.map_or(std::ptr::null_mut(), |c| c.display)
}

/// The draw drawable of the context current in this thread (0 if none is a GLX context).
pub(crate) fn current_drawable() -> Xid {
    current_field(|c| c.draw)
}

/// A new context for `config`, registered.
fn create(display: *mut Display, config: &'static Config) -> *mut GlxContext {
    let mut gl = Gl::new(1, 1);
    gl.set_buffer_config(config.buffers());
    CONTEXTS.register(GlxContext { gl, config, bound_once: false, display, draw: 0, read: 0 })
}

/// The drawable `id` of `display` made known to gleval's drawables (an X window or pixmap is
/// asked its size; a pbuffer was declared when made); `false` if it is none.
pub(super) fn declare_drawable(display: *mut Display, id: Xid) -> bool {
    let key = Key { display: display as usize, drawable: id };
    if surface::size(key).is_some() {
        return true;
    }
    let Some((w, h, _)) = x11::geometry(display, id) else { return false };
    surface::declare(key, Output::X { display, drawable: id }, (w, h));
    true
}

/// `glXMakeContextCurrent`'s work (`glXMakeCurrent` is it with `read` = `draw`).
fn make_current(display: *mut Display, draw: Xid, read: Xid, ctx: *mut GlxContext, minor: u16) -> Bool {
    if ctx.is_null() {
        if draw != 0 || read != 0 {
            x_error(display, BAD_MATCH, draw, minor);
            return FALSE;
        }
        CONTEXTS.release_current();
        return TRUE;
    }
    let Some(life) = lookup(ctx) else {
        glx_error(display, GlxError::Context, ctx as Xid, minor);
        return FALSE;
    };
    let me = std::thread::current().id();
    if life.destroyed || life.current_in.is_some_and(|t| t != me) {
        x_error(display, BAD_ACCESS, ctx as Xid, minor);
        return FALSE;
    }
    // No drawable at all: current without one (nothing drawn lands anywhere), as Mesa
    // allows; one of the two alone is `BadMatch`.
    let none = draw == 0 && read == 0;
    if !none && (draw == 0 || read == 0) {
        x_error(display, BAD_MATCH, draw, minor);
        return FALSE;
    }
    if !none && (!declare_drawable(display, draw) || !declare_drawable(display, read)) {
        glx_error(display, GlxError::Drawable, if declare_drawable(display, draw) { read } else { draw }, minor);
        return FALSE;
    }
    if CONTEXTS.current() != ctx {
        CONTEXTS.release_current();
    }
    // SAFETY: registered, hence live, and current nowhere else.
    let context = unsafe { &mut *ctx };
    context.display = display;
    (context.draw, context.read) = (draw, read);
    CONTEXTS.make_current(context);
    if none {
        surface::unbind();
        return TRUE;
    }
    let first = !context.bound_once;
    context.bound_once = true;
    surface::bind(Key { display: display as usize, drawable: draw }, &mut context.gl, first);
    TRUE
}

entry! {
    /// `glXMakeCurrent`: binds `ctx` to `drawable` in this thread (`ctx` NULL and drawable
    /// `None`: releases the current one). A context current in another thread → `BadAccess`;
    /// a drawable that is not one → `GLXBadDrawable`; a handle that is not a context →
    /// `GLXBadContext`; all answer `False`.
    fn glXMakeCurrent(display: *mut Display, drawable: Xid, ctx: *mut GlxContext) -> Bool {
        make_current(display, drawable, drawable, ctx, request::MAKE_CURRENT)
    }
}

entry! {
    /// `glXMakeContextCurrent`: as `glXMakeCurrent`; gleval reads from the draw drawable
    /// (the read drawable is checked, and answered by `glXGetCurrentReadDrawable`).
    fn glXMakeContextCurrent(display: *mut Display, draw: Xid, read: Xid, ctx: *mut GlxContext) -> Bool {
        make_current(display, draw, read, ctx, request::MAKE_CONTEXT_CURRENT)
    }
}

/// The share list's check: NULL or a live context.
fn share_ok(display: *mut Display, share: *mut GlxContext, minor: u16) -> bool {
    if share.is_null() || lookup(share).is_some() {
        return true;
    }
    glx_error(display, GlxError::Context, share as Xid, minor);
    false
}

entry! {
    /// `glXCreateContext`: a context for the configuration `visual` names; NULL with
    /// `BadValue` for a visual gleval has no configuration for, `GLXBadContext` for a share
    /// context that is not one. Display lists and textures are not shared between contexts.
    unsafe fn glXCreateContext(display: *mut Display, visual: *mut XVisualInfo, share: *mut GlxContext, _direct: Bool) -> *mut GlxContext {
        // SAFETY: GLX's contract: NULL or a visual from Xlib.
        let Some(visual) = (unsafe { visual.as_ref() }) else {
            x_error(display, BAD_VALUE, 0, request::CREATE_CONTEXT);
            return std::ptr::null_mut();
        };
        let Some(config) = config_of_visual(display, visual.visualid) else {
            x_error(display, BAD_VALUE, visual.visualid, request::CREATE_CONTEXT);
            return std::ptr::null_mut();
        };
        if !share_ok(display, share, request::CREATE_CONTEXT) {
            return std::ptr::null_mut();
        }
        create(display, config)
    }
}

entry! {
    /// `glXCreateNewContext`: a context for `config` of `GLX_RGBA_TYPE`; a colour-index
    /// context → `BadMatch` (gleval's configurations are RGBA), another type → `BadValue`.
    fn glXCreateNewContext(display: *mut Display, config: *mut c_void, render_type: c_int, share: *mut GlxContext, _direct: Bool) -> *mut GlxContext {
        let Some(config) = config_or_error(display, config, request::CREATE_NEW_CONTEXT) else { return std::ptr::null_mut() };
        if render_type != GLX_RGBA_TYPE {
            let code = if render_type == super::configs::GLX_COLOR_INDEX_TYPE { BAD_MATCH } else { BAD_VALUE };
            x_error(display, code, render_type as Xid, request::CREATE_NEW_CONTEXT);
            return std::ptr::null_mut();
        }
        if !share_ok(display, share, request::CREATE_NEW_CONTEXT) {
            return std::ptr::null_mut();
        }
        create(display, config)
    }
}

const GLX_CONTEXT_MAJOR_VERSION: c_int = 0x2091;
const GLX_CONTEXT_MINOR_VERSION: c_int = 0x2092;
const GLX_CONTEXT_FLAGS: c_int = 0x2094;
const GLX_CONTEXT_PROFILE_MASK: c_int = 0x9126;
const GLX_CONTEXT_DEBUG_BIT: c_int = 0x1;
const GLX_CONTEXT_FORWARD_COMPATIBLE_BIT: c_int = 0x2;
const GLX_CONTEXT_CORE_PROFILE_BIT: c_int = 0x1;
const GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT: c_int = 0x2;
const GLX_CONTEXT_ES_PROFILE_BIT: c_int = 0x4;

/// Whether a version cannot exist (GLX_ARB_create_context: `BadMatch`): a minor version past
/// the last of its major one, of the majors there are; a major version above 4 is one no
/// configuration offers (`GLXBadFBConfig`), as Mesa answers.
fn version_impossible(major: c_int, minor: c_int) -> bool {
    let last = match major {
        1 => 5,
        2 => 1,
        3 => 3,
        4 => 6,
        m => return m < 1 || minor < 0,
    };
    minor < 0 || minor > last
}

/// Why GLX_ARB_create_context refuses an attribute list, if it does: the error and its
/// kind. gleval makes compatibility contexts of OpenGL 1.0 up to what it implements
/// ([`gleval::gl::VERSION`]).
fn refuse(list: &[(c_int, c_int)]) -> Option<Result<u8, GlxError>> {
    let (mut major, mut minor, mut flags, mut profile) = (1, 0, 0, GLX_CONTEXT_CORE_PROFILE_BIT);
    for &(name, value) in list {
        match name {
            GLX_CONTEXT_MAJOR_VERSION => major = value,
            GLX_CONTEXT_MINOR_VERSION => minor = value,
            GLX_CONTEXT_FLAGS => flags = value,
            GLX_CONTEXT_PROFILE_MASK => profile = value,
            GLX_RENDER_TYPE if value == GLX_RGBA_TYPE => {}
            GLX_RENDER_TYPE => return Some(Ok(BAD_VALUE)),
            _ => return Some(Ok(BAD_VALUE)),
        }
    }
    if flags & !(GLX_CONTEXT_DEBUG_BIT | GLX_CONTEXT_FORWARD_COMPATIBLE_BIT) != 0 {
        return Some(Ok(BAD_VALUE));
    }
    if version_impossible(major, minor) || flags & GLX_CONTEXT_FORWARD_COMPATIBLE_BIT != 0 && major < 3 {
        return Some(Ok(BAD_MATCH));
    }
    // The profile mask counts from OpenGL 3.2 on; one bit, of the three there are.
    let versioned = (major, minor) >= (3, 2);
    if versioned
        && (profile.count_ones() != 1
            || profile
                & !(GLX_CONTEXT_CORE_PROFILE_BIT | GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT | GLX_CONTEXT_ES_PROFILE_BIT)
                != 0)
    {
        return Some(Err(GlxError::Profile));
    }
    // Above what gleval implements, or a forward-compatible context: no configuration can.
    if (major, minor) > gleval::gl::VERSION || flags & GLX_CONTEXT_FORWARD_COMPATIBLE_BIT != 0 {
        return Some(Err(GlxError::FbConfig));
    }
    None
}

entry! {
    /// `glXCreateContextAttribsARB` (GLX_ARB_create_context, _profile): compatibility
    /// contexts of OpenGL 1.0 to 1.5 (`gleval::gl::VERSION`), debug or not. A version that does not exist →
    /// `BadMatch`; one above 1.1 (or a core or ES profile of 3.2 up, or forward-compatible)
    /// → `GLXBadFBConfig`; an attribute or flag it does not know → `BadValue`; a bad profile
    /// mask → `GLXBadProfileARB`.
    unsafe fn glXCreateContextAttribsARB(display: *mut Display, config: *mut c_void, share: *mut GlxContext, _direct: Bool, list: *const c_int) -> *mut GlxContext {
        let Some(config) = config_or_error(display, config, request::CREATE_CONTEXT_ATTRIBS) else { return std::ptr::null_mut() };
        // SAFETY: GLX's contract for the list.
        let list = unsafe { super::attributes(list, &[]) };
        match refuse(&list) {
            Some(Ok(code)) => {
                x_error(display, code, 0, request::CREATE_CONTEXT_ATTRIBS);
                return std::ptr::null_mut();
            }
            Some(Err(error)) => {
                glx_error(display, error, 0, request::CREATE_CONTEXT_ATTRIBS);
                return std::ptr::null_mut();
            }
            None => {}
        }
        if !share_ok(display, share, request::CREATE_CONTEXT_ATTRIBS) {
            return std::ptr::null_mut();
        }
        create(display, config)
    }
}

entry! {
    /// `glXDestroyContext`: frees the context, or, while it is current somewhere, when it is
    /// released; a handle that is not a context → `GLXBadContext`.
    fn glXDestroyContext(display: *mut Display, ctx: *mut GlxContext) {
        let Some(life) = lookup(ctx) else {
            glx_error(display, GlxError::Context, ctx as Xid, request::DESTROY_CONTEXT);
            return;
        };
        CONTEXTS.destroy(ctx, life);
    }
}

entry! {
    /// `glXCopyContext`: the attribute groups of `mask` (as `glPushAttrib` names them) go
    /// from `source` to `dest`. A handle that is not a context → `GLXBadContext`; `dest`
    /// current in a thread → `BadAccess`; the two the same → `BadMatch`.
    fn glXCopyContext(display: *mut Display, source: *mut GlxContext, dest: *mut GlxContext, mask: std::ffi::c_ulong) {
        let (Some(_), Some(to)) = (lookup(source), lookup(dest)) else {
            let bad = if lookup(source).is_none() { source } else { dest };
            glx_error(display, GlxError::Context, bad as Xid, request::COPY_CONTEXT);
            return;
        };
        if source == dest {
            x_error(display, BAD_MATCH, dest as Xid, request::COPY_CONTEXT);
            return;
        }
        if to.current_in.is_some() {
            x_error(display, BAD_ACCESS, dest as Xid, request::COPY_CONTEXT);
            return;
        }
        // What the source recorded stays its own; its state is what is copied.
        // SAFETY: both live and distinct; `dest` is current nowhere, and the source is only
        // read through its own calls.
        let (from, to) = unsafe { (&mut (*source).gl, &mut (*dest).gl) };
        to.copy_attribs_from(from, mask as u32);
    }
}

entry! {
    /// `glXIsDirect`: gleval renders in the program's own process, as a direct context does;
    /// `False` (and `GLXBadContext`) for a handle that is not a context.
    fn glXIsDirect(display: *mut Display, ctx: *mut GlxContext) -> Bool {
        if lookup(ctx).is_some() {
            TRUE
        } else {
            glx_error(display, GlxError::Context, ctx as Xid, request::QUERY_CONTEXT);
            FALSE
        }
    }
}

entry! {
    /// `glXQueryContext`: `GLX_FBCONFIG_ID`, `GLX_RENDER_TYPE`, `GLX_SCREEN`; another
    /// attribute → `GLX_BAD_ATTRIBUTE`; a handle that is not a context → `GLXBadContext`.
    unsafe fn glXQueryContext(display: *mut Display, ctx: *mut GlxContext, name: c_int, value: *mut c_int) -> c_int {
        if lookup(ctx).is_none() {
            glx_error(display, GlxError::Context, ctx as Xid, request::QUERY_CONTEXT);
            return GlxError::Context as c_int;
        }
        // SAFETY: registered, hence live; only its configuration is read.
        let config = unsafe { (*ctx).config };
        let answer = match name {
            GLX_FBCONFIG_ID => config.id,
            GLX_RENDER_TYPE => GLX_RGBA_TYPE,
            GLX_SCREEN => x11::screens(display).map_or(0, |(s, _)| s),
            _ => return super::configs::GLX_BAD_ATTRIBUTE,
        };
        if !value.is_null() {
            // SAFETY: GLX's contract: an int to write.
            unsafe { *value = answer };
        }
        0
    }
}

entry! {
    /// `glXGetCurrentContext`: the GLX context current in this thread; otherwise the current
    /// GLUT window's or OSMesa context (one context model: a toolkit that keys its state by
    /// the current GLX context, as PyOpenGL keys GLUT's callbacks, sees each window's own),
    /// NULL if none.
    fn glXGetCurrentContext() -> *mut c_void {
        let ctx = CONTEXTS.current();
        let current = crate::context::current_ptr();
        // SAFETY: a current GLX context is live.
        if !ctx.is_null() && std::ptr::eq(unsafe { &(*ctx).gl }, current) {
            return ctx.cast();
        }
        current.cast_mut().cast()
    }
}

/// A field of the current GLX context (`None` (0) without one).
fn current_field(f: impl FnOnce(&GlxContext) -> Xid) -> Xid {
    let ctx = CONTEXTS.current();
    // SAFETY: a current context is live.
    unsafe { ctx.as_ref() }.map_or(0, f)
}

entry! {
    /// `glXGetCurrentDrawable`: the current GLX context's draw drawable, `None` without one.
    fn glXGetCurrentDrawable() -> Xid {
        current_field(|c| c.draw)
    }
}

entry! {
    /// `glXGetCurrentReadDrawable`: its read drawable.
    fn glXGetCurrentReadDrawable() -> Xid {
        current_field(|c| c.read)
    }
}

entry! {
    /// `glXGetCurrentDisplay`: the current GLX context's display, NULL without one.
    fn glXGetCurrentDisplay() -> *mut Display {
        current_display()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn create_context_attribs_follows_the_extension() {
        let compat = |major, minor| [(GLX_CONTEXT_MAJOR_VERSION, major), (GLX_CONTEXT_MINOR_VERSION, minor)];
        assert_eq!(refuse(&[]), None);
        assert_eq!(refuse(&compat(1, 0)), None);
        assert_eq!(refuse(&compat(1, 1)), None);
        assert_eq!(refuse(&compat(1, 2)), None);
        assert_eq!(refuse(&compat(1, 3)), None);
        assert_eq!(refuse(&compat(1, 5)), None);
        assert_eq!(refuse(&compat(2, 0)), Some(Err(GlxError::FbConfig)));
        assert_eq!(refuse(&compat(3, 3)), Some(Err(GlxError::FbConfig)));
        assert_eq!(refuse(&compat(1, 7)), Some(Ok(BAD_MATCH)));
        assert_eq!(refuse(&compat(2, 5)), Some(Ok(BAD_MATCH)));
        assert_eq!(refuse(&compat(9, 0)), Some(Err(GlxError::FbConfig)));
        assert_eq!(refuse(&[(GLX_CONTEXT_FLAGS, GLX_CONTEXT_FORWARD_COMPATIBLE_BIT)]), Some(Ok(BAD_MATCH)));
        assert_eq!(refuse(&[(GLX_CONTEXT_FLAGS, 0x40)]), Some(Ok(BAD_VALUE)));
        assert_eq!(refuse(&[(GLX_CONTEXT_FLAGS, GLX_CONTEXT_DEBUG_BIT)]), None);
        assert_eq!(refuse(&[(0x1234, 1)]), Some(Ok(BAD_VALUE)));
        let bad_profile =
            [(GLX_CONTEXT_MAJOR_VERSION, 3), (GLX_CONTEXT_MINOR_VERSION, 2), (GLX_CONTEXT_PROFILE_MASK, 3)];
        assert_eq!(refuse(&bad_profile), Some(Err(GlxError::Profile)));
    }
}
