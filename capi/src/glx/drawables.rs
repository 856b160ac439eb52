//! GLX drawables: `glXCreateWindow`, `glXCreatePixmap`, `glXCreateGLXPixmap`,
//! `glXCreatePbuffer` and their `Destroy` forms, `glXSwapBuffers`, `glXQueryDrawable`, the
//! swap interval (GLX_EXT_swap_control, GLX_MESA_swap_control, GLX_SGI_swap_control) and
//! `glXWaitGL` / `glXWaitX`.
//!
//! A GLX window or pixmap is the X window or pixmap itself (gleval draws on the client
//! side, so no server-side GLX drawable is made: the id handed back is the X id); a pbuffer
//! is a canvas of gleval's with an id of its own (from `PBUFFER_IDS`, beyond what an X
//! server hands out to a client below 2^29).

use super::configs::{config_or_error, GLX_FBCONFIG_ID, MAX_PBUFFER};
use super::contexts::declare_drawable;
use super::{glx_error, request, x_error, GlxError, BAD_ALLOC, BAD_VALUE};
use crate::surface::{self, Key, Output};
use crate::x11::{self, Display, XVisualInfo, Xid};
use std::cell::{Cell, RefCell};
use std::collections::HashMap;
use std::ffi::{c_int, c_uint, c_void};

const GLX_PRESERVED_CONTENTS: c_int = 0x801B;
const GLX_LARGEST_PBUFFER: c_int = 0x801C;
const GLX_WIDTH: c_int = 0x801D;
const GLX_HEIGHT: c_int = 0x801E;
const GLX_EVENT_MASK: c_int = 0x801F;
const GLX_PBUFFER_HEIGHT: c_int = 0x8040;
const GLX_PBUFFER_WIDTH: c_int = 0x8041;
const GLX_SWAP_INTERVAL_EXT: c_int = 0x20F1;
const GLX_MAX_SWAP_INTERVAL_EXT: c_int = 0x20F2;
/// The largest swap interval (Mesa's).
const MAX_SWAP_INTERVAL: c_int = i32::MAX;
/// pbuffer ids: 2^29 up, where no X server's client ids reach.
const FIRST_PBUFFER: Xid = 1 << 29;

/// What gleval keeps of a GLX drawable besides its buffers.
#[derive(Clone, Copy)]
struct Drawable {
    config_id: c_int,
    pbuffer: bool,
    preserved: bool,
}

thread_local! {
    static DRAWABLES: RefCell<HashMap<Key, Drawable>> = RefCell::new(HashMap::new());
    static PBUFFER_IDS: Cell<Xid> = const { Cell::new(FIRST_PBUFFER) };
}

fn key(display: *mut Display, id: Xid) -> Key {
    Key { display: display as usize, drawable: id }
}

fn remember(display: *mut Display, id: Xid, drawable: Drawable) {
    let _ = DRAWABLES.try_with(|d| d.borrow_mut().insert(key(display, id), drawable));
}

fn known(display: *mut Display, id: Xid) -> Option<Drawable> {
    DRAWABLES.try_with(|d| d.borrow().get(&key(display, id)).copied()).ok().flatten()
}

fn plain(config_id: c_int) -> Drawable {
    Drawable { config_id, pbuffer: false, preserved: true }
}

/// An X window or pixmap as a GLX drawable: the X id, once the server knows it.
fn x_drawable(display: *mut Display, config: *mut c_void, id: Xid, minor: u16, bad: GlxError) -> Xid {
    let Some(config) = config_or_error(display, config, minor) else { return 0 };
    if !declare_drawable(display, id) {
        glx_error(display, bad, id, minor);
        return 0;
    }
    remember(display, id, plain(config.id));
    id
}

entry! {
    /// `glXCreateWindow`: the X window as a GLX window (its own id).
    fn glXCreateWindow(display: *mut Display, config: *mut c_void, window: Xid, _list: *const c_int) -> Xid {
        x_drawable(display, config, window, request::CREATE_WINDOW, GlxError::Window)
    }
}

entry! {
    /// `glXCreatePixmap`: the X pixmap as a GLX pixmap (its own id).
    fn glXCreatePixmap(display: *mut Display, config: *mut c_void, pixmap: Xid, _list: *const c_int) -> Xid {
        x_drawable(display, config, pixmap, request::CREATE_PIXMAP, GlxError::Pixmap)
    }
}

entry! {
    /// `glXCreateGLXPixmap`: the X pixmap as a GLX pixmap for the configuration of `visual`.
    unsafe fn glXCreateGLXPixmap(display: *mut Display, visual: *mut XVisualInfo, pixmap: Xid) -> Xid {
        // SAFETY: GLX's contract: NULL or a visual from Xlib.
        let config = unsafe { visual.as_ref() }.and_then(|v| super::configs::config_of_visual(display, v.visualid));
        let Some(config) = config else {
            x_error(display, BAD_VALUE, 0, request::CREATE_GLX_PIXMAP);
            return 0;
        };
        x_drawable(display, config.handle(), pixmap, request::CREATE_GLX_PIXMAP, GlxError::Pixmap)
    }
}

/// Forgets a GLX drawable (its canvas too); `false` if it is not one of `kind`'s.
fn destroy(display: *mut Display, id: Xid, pbuffer: bool) -> bool {
    match known(display, id) {
        Some(d) if d.pbuffer == pbuffer => {
            let _ = DRAWABLES.try_with(|d| d.borrow_mut().remove(&key(display, id)));
            surface::forget(key(display, id));
            true
        }
        _ => false,
    }
}

entry! {
    /// `glXDestroyWindow`; a window that is not a GLX window → `GLXBadWindow`.
    fn glXDestroyWindow(display: *mut Display, window: Xid) {
        if !destroy(display, window, false) {
            glx_error(display, GlxError::Window, window, request::DESTROY_WINDOW);
        }
    }
}

entry! {
    /// `glXDestroyPixmap`; one that is not a GLX pixmap → `GLXBadPixmap`.
    fn glXDestroyPixmap(display: *mut Display, pixmap: Xid) {
        if !destroy(display, pixmap, false) {
            glx_error(display, GlxError::Pixmap, pixmap, request::DESTROY_PIXMAP);
        }
    }
}

entry! {
    /// `glXDestroyGLXPixmap`: as `glXDestroyPixmap`.
    fn glXDestroyGLXPixmap(display: *mut Display, pixmap: Xid) {
        if !destroy(display, pixmap, false) {
            glx_error(display, GlxError::Pixmap, pixmap, request::DESTROY_GLX_PIXMAP);
        }
    }
}

entry! {
    /// `glXCreatePbuffer`: an off-screen drawable of `GLX_PBUFFER_WIDTH` ×
    /// `GLX_PBUFFER_HEIGHT` (0 × 0 by default); larger than gleval draws → `BadAlloc`, or
    /// the largest it draws with `GLX_LARGEST_PBUFFER`.
    unsafe fn glXCreatePbuffer(display: *mut Display, config: *mut c_void, list: *const c_int) -> Xid {
        let Some(config) = config_or_error(display, config, request::CREATE_PBUFFER) else { return 0 };
        let (mut w, mut h, mut largest, mut preserved) = (0, 0, false, true);
        // SAFETY: GLX's contract for the list.
        for (name, value) in unsafe { super::attributes(list, &[]) } {
            match name {
                GLX_PBUFFER_WIDTH => w = value,
                GLX_PBUFFER_HEIGHT => h = value,
                GLX_LARGEST_PBUFFER => largest = value != 0,
                GLX_PRESERVED_CONTENTS => preserved = value != 0,
                _ => {
                    x_error(display, BAD_VALUE, 0, request::CREATE_PBUFFER);
                    return 0;
                }
            }
        }
        if w < 0 || h < 0 {
            x_error(display, BAD_VALUE, 0, request::CREATE_PBUFFER);
            return 0;
        }
        if w > MAX_PBUFFER || h > MAX_PBUFFER {
            if !largest {
                x_error(display, BAD_ALLOC, 0, request::CREATE_PBUFFER);
                return 0;
            }
            (w, h) = (w.min(MAX_PBUFFER), h.min(MAX_PBUFFER));
        }
        let id = PBUFFER_IDS.with(|n| n.replace(n.get() + 1));
        surface::declare(key(display, id), Output::None, (w as u32, h as u32));
        remember(display, id, Drawable { pbuffer: true, preserved, ..plain(config.id) });
        id
    }
}

entry! {
    /// `glXDestroyPbuffer`; one that is not a pbuffer → `GLXBadPbuffer`.
    fn glXDestroyPbuffer(display: *mut Display, pbuffer: Xid) {
        if !destroy(display, pbuffer, true) {
            glx_error(display, GlxError::Pbuffer, pbuffer, request::DESTROY_PBUFFER);
        }
    }
}

entry! {
    /// `glXSwapBuffers`: the current context's frame is drawn, the back buffer becomes the
    /// front one, and the front buffer goes into the X window (after the swap interval, if
    /// one is set). A drawable another context is bound to shows what it holds; one that
    /// is not a drawable → `GLXBadDrawable`.
    fn glXSwapBuffers(display: *mut Display, drawable: Xid) {
        let key = key(display, drawable);
        if surface::bound() == Some(key) {
            surface::pace(key);
            surface::present_current(true);
        } else if surface::size(key).is_some() || declare_drawable(display, drawable) {
            surface::pace(key);
            surface::present(key);
        } else {
            glx_error(display, GlxError::Drawable, drawable, request::SWAP_BUFFERS);
        }
    }
}

entry! {
    /// `glXQueryDrawable`: `GLX_WIDTH`, `GLX_HEIGHT`, `GLX_PRESERVED_CONTENTS`,
    /// `GLX_LARGEST_PBUFFER`, `GLX_FBCONFIG_ID`, `GLX_EVENT_MASK`, `GLX_SWAP_INTERVAL_EXT`,
    /// `GLX_MAX_SWAP_INTERVAL_EXT`; a drawable that is not one → `GLXBadDrawable`, another
    /// attribute → `BadValue`.
    unsafe fn glXQueryDrawable(display: *mut Display, drawable: Xid, name: c_int, value: *mut c_uint) {
        let k = key(display, drawable);
        if surface::size(k).is_none() && !declare_drawable(display, drawable) {
            glx_error(display, GlxError::Drawable, drawable, request::GET_DRAWABLE_ATTRIBUTES);
            return;
        }
        let d = known(display, drawable).unwrap_or(plain(0));
        let size = match d.pbuffer {
            true => surface::size(k),
            false => x11::geometry(display, drawable).map(|(w, h, _)| (w, h)),
        }
        .unwrap_or((0, 0));
        let answer = match name {
            GLX_WIDTH => size.0,
            GLX_HEIGHT => size.1,
            GLX_PRESERVED_CONTENTS => u32::from(d.preserved),
            GLX_LARGEST_PBUFFER => 0,
            GLX_FBCONFIG_ID => d.config_id as c_uint,
            GLX_EVENT_MASK => 0,
            GLX_SWAP_INTERVAL_EXT => surface::interval(k),
            GLX_MAX_SWAP_INTERVAL_EXT => MAX_SWAP_INTERVAL as c_uint,
            _ => {
                x_error(display, BAD_VALUE, drawable, request::GET_DRAWABLE_ATTRIBUTES);
                return;
            }
        };
        if !value.is_null() {
            // SAFETY: GLX's contract: an unsigned int to write.
            unsafe { *value = answer };
        }
    }
}

/// Sets a drawable's swap interval.
fn set_interval(display: *mut Display, drawable: Xid, interval: c_int) {
    surface::set_interval(key(display, drawable), interval as u32);
}

/// The current context's drawable and display, if a GLX context is current.
fn current_drawable() -> Option<(*mut Display, Xid)> {
    let display = super::current_display();
    let drawable = super::contexts::current_drawable();
    (!display.is_null() && drawable != 0).then_some((display, drawable))
}

entry! {
    /// `glXSwapIntervalEXT`: the drawable's swap interval; negative → `BadValue`.
    fn glXSwapIntervalEXT(display: *mut Display, drawable: Xid, interval: c_int) {
        if interval < 0 {
            x_error(display, BAD_VALUE, drawable, request::GET_DRAWABLE_ATTRIBUTES);
            return;
        }
        set_interval(display, drawable, interval);
    }
}

/// GLX_SGI_swap_control's and GLX_MESA_swap_control's errors.
const GLX_BAD_CONTEXT: c_int = 5;
const GLX_BAD_VALUE: c_int = 6;

entry! {
    /// `glXSwapIntervalMESA`: the current drawable's swap interval (0 allowed);
    /// `GLX_BAD_CONTEXT` without a current GLX context, `GLX_BAD_VALUE` for a negative one.
    fn glXSwapIntervalMESA(interval: c_uint) -> c_int {
        let Some((display, drawable)) = current_drawable() else { return GLX_BAD_CONTEXT };
        if interval > i32::MAX as c_uint {
            return GLX_BAD_VALUE;
        }
        set_interval(display, drawable, interval as c_int);
        0
    }
}

entry! {
    /// `glXGetSwapIntervalMESA`: the current drawable's swap interval (0 without one).
    fn glXGetSwapIntervalMESA() -> c_int {
        current_drawable().map_or(0, |(d, id)| surface::interval(key(d, id)) as c_int)
    }
}

entry! {
    /// `glXSwapIntervalSGI`: as `glXSwapIntervalMESA`, but 0 or less is `GLX_BAD_VALUE`.
    fn glXSwapIntervalSGI(interval: c_int) -> c_int {
        let Some((display, drawable)) = current_drawable() else { return GLX_BAD_CONTEXT };
        if interval <= 0 {
            return GLX_BAD_VALUE;
        }
        set_interval(display, drawable, interval);
        0
    }
}

entry! {
    /// `glXWaitGL`: what the current context drew is in its drawable before X draws there
    /// (a single-buffered drawable, or one drawn in its front buffer, shows it).
    fn glXWaitGL() {
        surface::flush_and_show();
    }
}

entry! {
    /// `glXWaitX`: X's drawing reaches the drawable before GL's that follows (the server
    /// has handled every request sent).
    fn glXWaitX() {
        x11::sync(super::current_display());
    }
}

entry! {
    /// `glXSelectEvent`: GLX's events (pbuffer clobbers, swap completions) are not sent by
    /// gleval; the mask is kept for `glXGetSelectedEvent`.
    fn glXSelectEvent(display: *mut Display, drawable: Xid, mask: std::ffi::c_ulong) {
        let _ = SELECTED.try_with(|s| s.borrow_mut().insert(key(display, drawable), mask));
    }
}

entry! {
    /// `glXGetSelectedEvent`: the mask `glXSelectEvent` kept (0 if none).
    unsafe fn glXGetSelectedEvent(display: *mut Display, drawable: Xid, mask: *mut std::ffi::c_ulong) {
        if !mask.is_null() {
            let kept = SELECTED.try_with(|s| s.borrow().get(&key(display, drawable)).copied()).ok().flatten().unwrap_or(0);
            // SAFETY: GLX's contract: an unsigned long to write.
            unsafe { *mask = kept };
        }
    }
}

thread_local! {
    static SELECTED: RefCell<HashMap<Key, std::ffi::c_ulong>> = RefCell::new(HashMap::new());
}
