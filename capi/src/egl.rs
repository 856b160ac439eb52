//! EGL 1.5 (`EGL/egl.h`) for desktop OpenGL over gleval's contexts, on two platforms: X11
//! (window surfaces are the program's X windows, drawn as GLX's are) and Mesa's surfaceless
//! platform (`EGL_PLATFORM_SURFACELESS_MESA`: pbuffers only, no X server at all). OpenGL ES is
//! not offered: `eglBindAPI(EGL_OPENGL_ES_API)` is `EGL_BAD_PARAMETER`, and the bound API
//! starts as `EGL_NONE`, as EGL says for an implementation without ES.
//!
//! A context is a [`Gl`]; a surface is a drawable of [`crate::surface`] named by the display's
//! address and the surface's number. Configurations are gleval's double-buffered ones
//! without an accumulation buffer (EGL has none). Every call checks its handles against what
//! was made (`EGL_BAD_DISPLAY`, `EGL_BAD_CONFIG`, `EGL_BAD_CONTEXT`, `EGL_BAD_SURFACE`) and
//! records its error for `eglGetError`; none crashes on a handle that is not one.

use crate::configs::{meets, Config, Criterion, CHANNEL_BITS, CONFIGS, DEPTH_BITS};
use crate::live_contexts::{ApiContext, Registry as Contexts};
use crate::surface::{self, Key, Output};
use crate::x11::{self, Display as XDisplay, Xid};
use gleval::gl::Gl;
use std::cell::Cell;
use std::collections::HashMap;
use std::ffi::{c_char, c_void, CStr};
use std::sync::{Mutex, PoisonError};

type EGLint = i32;
type EGLBoolean = u32;
type EGLenum = u32;
const EGL_TRUE: EGLBoolean = 1;
const EGL_FALSE: EGLBoolean = 0;

const EGL_SUCCESS: EGLint = 0x3000;
const EGL_NOT_INITIALIZED: EGLint = 0x3001;
const EGL_BAD_ACCESS: EGLint = 0x3002;
const EGL_BAD_ALLOC: EGLint = 0x3003;
const EGL_BAD_ATTRIBUTE: EGLint = 0x3004;
const EGL_BAD_CONFIG: EGLint = 0x3005;
const EGL_BAD_CONTEXT: EGLint = 0x3006;
const EGL_BAD_DISPLAY: EGLint = 0x3008;
const EGL_BAD_MATCH: EGLint = 0x3009;
const EGL_BAD_NATIVE_WINDOW: EGLint = 0x300B;
const EGL_BAD_PARAMETER: EGLint = 0x300C;
const EGL_BAD_SURFACE: EGLint = 0x300D;

const EGL_BUFFER_SIZE: EGLint = 0x3020;
const EGL_ALPHA_SIZE: EGLint = 0x3021;
const EGL_BLUE_SIZE: EGLint = 0x3022;
const EGL_GREEN_SIZE: EGLint = 0x3023;
const EGL_RED_SIZE: EGLint = 0x3024;
const EGL_DEPTH_SIZE: EGLint = 0x3025;
const EGL_STENCIL_SIZE: EGLint = 0x3026;
const EGL_CONFIG_CAVEAT: EGLint = 0x3027;
const EGL_CONFIG_ID: EGLint = 0x3028;
const EGL_LEVEL: EGLint = 0x3029;
const EGL_MAX_PBUFFER_HEIGHT: EGLint = 0x302A;
const EGL_MAX_PBUFFER_PIXELS: EGLint = 0x302B;
const EGL_MAX_PBUFFER_WIDTH: EGLint = 0x302C;
const EGL_NATIVE_RENDERABLE: EGLint = 0x302D;
const EGL_NATIVE_VISUAL_ID: EGLint = 0x302E;
const EGL_NATIVE_VISUAL_TYPE: EGLint = 0x302F;
const EGL_SAMPLES: EGLint = 0x3031;
const EGL_SAMPLE_BUFFERS: EGLint = 0x3032;
const EGL_SURFACE_TYPE: EGLint = 0x3033;
const EGL_TRANSPARENT_TYPE: EGLint = 0x3034;
const EGL_TRANSPARENT_BLUE_VALUE: EGLint = 0x3035;
const EGL_TRANSPARENT_RED_VALUE: EGLint = 0x3037;
const EGL_NONE: EGLint = 0x3038;
const EGL_BIND_TO_TEXTURE_RGB: EGLint = 0x3039;
const EGL_BIND_TO_TEXTURE_RGBA: EGLint = 0x303A;
const EGL_MIN_SWAP_INTERVAL: EGLint = 0x303B;
const EGL_MAX_SWAP_INTERVAL: EGLint = 0x303C;
const EGL_LUMINANCE_SIZE: EGLint = 0x303D;
const EGL_ALPHA_MASK_SIZE: EGLint = 0x303E;
const EGL_COLOR_BUFFER_TYPE: EGLint = 0x303F;
const EGL_RENDERABLE_TYPE: EGLint = 0x3040;
const EGL_MATCH_NATIVE_PIXMAP: EGLint = 0x3041;
const EGL_CONFORMANT: EGLint = 0x3042;
const EGL_RGB_BUFFER: EGLint = 0x308E;
const EGL_OPENGL_BIT: EGLint = 0x0008;
const EGL_PBUFFER_BIT: EGLint = 0x0001;
const EGL_WINDOW_BIT: EGLint = 0x0004;
const EGL_DONT_CARE: EGLint = -1;

const EGL_VENDOR: EGLint = 0x3053;
const EGL_VERSION: EGLint = 0x3054;
const EGL_EXTENSIONS: EGLint = 0x3055;
const EGL_CLIENT_APIS: EGLint = 0x308D;
const EGL_HEIGHT: EGLint = 0x3056;
const EGL_WIDTH: EGLint = 0x3057;
const EGL_LARGEST_PBUFFER: EGLint = 0x3058;
const EGL_DRAW: EGLint = 0x3059;
const EGL_READ: EGLint = 0x305A;
const EGL_NO_TEXTURE: EGLint = 0x305C;
const EGL_TEXTURE_FORMAT: EGLint = 0x3080;
const EGL_TEXTURE_TARGET: EGLint = 0x3081;
const EGL_MIPMAP_TEXTURE: EGLint = 0x3082;
const EGL_RENDER_BUFFER: EGLint = 0x3086;
const EGL_BACK_BUFFER: EGLint = 0x3084;
const EGL_SWAP_BEHAVIOR: EGLint = 0x3093;
const EGL_BUFFER_PRESERVED: EGLint = 0x3094;
const EGL_GL_COLORSPACE: EGLint = 0x309D;
const EGL_GL_COLORSPACE_LINEAR: EGLint = 0x308A;
const EGL_CONTEXT_CLIENT_TYPE: EGLint = 0x3097;
const EGL_CONTEXT_MAJOR_VERSION: EGLint = 0x3098;
const EGL_CONTEXT_MINOR_VERSION: EGLint = 0x30FB;
const EGL_CONTEXT_FLAGS_KHR: EGLint = 0x30FC;
const EGL_CONTEXT_OPENGL_PROFILE_MASK: EGLint = 0x30FD;
const EGL_CONTEXT_OPENGL_DEBUG: EGLint = 0x31B0;
const EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE: EGLint = 0x31B1;
const EGL_CONTEXT_OPENGL_ROBUST_ACCESS: EGLint = 0x31B2;
const EGL_CONTEXT_OPENGL_DEBUG_BIT: EGLint = 0x1;
const EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT: EGLint = 0x2;

const EGL_OPENGL_ES_API: EGLenum = 0x30A0;
const EGL_OPENGL_API: EGLenum = 0x30A2;
const EGL_NONE_API: EGLenum = 0x3038;

const EGL_PLATFORM_X11: EGLenum = 0x31D5;
const EGL_PLATFORM_SURFACELESS_MESA: EGLenum = 0x31DD;
/// `EGL_PLATFORM_X11_SCREEN_EXT`, the one display attribute the X11 platform takes.
const EGL_PLATFORM_X11_SCREEN: EGLint = 0x31D6;

/// Without a display: what the client offers.
const CLIENT_EXTENSIONS: &CStr = c"EGL_EXT_client_extensions EGL_EXT_platform_base EGL_KHR_platform_x11 EGL_EXT_platform_x11 EGL_MESA_platform_surfaceless";
/// A display's extensions.
const DISPLAY_EXTENSIONS: &CStr = c"EGL_KHR_create_context EGL_KHR_get_all_proc_addresses EGL_KHR_surfaceless_context";

/// An `EGLDisplay`: a platform and its native display.
struct EglDisplay {
    platform: EGLenum,
    /// The X connection (X11: the program's, or one opened for `EGL_DEFAULT_DISPLAY`).
    native: *mut XDisplay,
    initialized: bool,
}

/// An `EGLContext`.
struct EglContext {
    gl: Gl,
    config: &'static Config,
    display: usize,
    major: EGLint,
    bound_once: bool,
    draw: usize,
    read: usize,
}

impl ApiContext for EglContext {
    fn gl(&mut self) -> &mut Gl {
        &mut self.gl
    }
}

/// An `EGLSurface`.
#[derive(Clone, Copy)]
struct EglSurface {
    display: usize,
    config: &'static Config,
    window: bool,
}

/// Everything made so far, by address (displays live as long as the program: EGL hands the
/// same one back for the same native display).
#[derive(Default)]
struct Registry {
    displays: Vec<usize>,
    surfaces: HashMap<usize, EglSurface>,
    next_surface: usize,
}

static REGISTRY: Mutex<Option<Registry>> = Mutex::new(None);

fn registry<R>(f: impl FnOnce(&mut Registry) -> R) -> R {
    let mut guard = REGISTRY.lock().unwrap_or_else(PoisonError::into_inner);
    f(guard.get_or_insert_with(|| Registry { next_surface: 1, ..Registry::default() }))
}

thread_local! {
    static ERROR: Cell<EGLint> = const { Cell::new(EGL_SUCCESS) };
    static API: Cell<EGLenum> = const { Cell::new(EGL_NONE_API) };
    static CURRENT: Cell<*mut EglContext> = const { Cell::new(std::ptr::null_mut()) };
}

/// Live EGL contexts ([`crate::live_contexts`], as GLX's).
static CONTEXTS: Contexts<EglContext> = Contexts::new(&CURRENT);

/// Records `error` for `eglGetError` and returns `value`.
fn fail<T>(error: EGLint, value: T) -> T {
    ERROR.with(|e| e.set(error));
    value
}

/// Success: `eglGetError` answers `EGL_SUCCESS`.
fn ok<T>(value: T) -> T {
    fail(EGL_SUCCESS, value)
}

/// The display a handle names, if it is one (and initialized, when `initialized`).
fn display(handle: *mut c_void, initialized: bool) -> Result<&'static mut EglDisplay, EGLint> {
    if !registry(|r| r.displays.contains(&(handle as usize))) {
        return Err(EGL_BAD_DISPLAY);
    }
    // SAFETY: registered displays are leaked boxes, alive for the program; EGL's calls on one
    // display do not overlap within a thread.
    let d = unsafe { &mut *handle.cast::<EglDisplay>() };
    if initialized && !d.initialized {
        return Err(EGL_NOT_INITIALIZED);
    }
    Ok(d)
}

/// The display for a platform and native display: the same handle for the same pair.
fn get_display(platform: EGLenum, native: *mut XDisplay) -> *mut c_void {
    registry(|r| {
        for &d in &r.displays {
            // SAFETY: registered displays are alive.
            let known = unsafe { &*(d as *const EglDisplay) };
            if known.platform == platform && known.native == native {
                return d as *mut c_void;
            }
        }
        let made = Box::into_raw(Box::new(EglDisplay { platform, native, initialized: false })) as usize;
        r.displays.push(made);
        made as *mut c_void
    })
}

/// The configurations EGL offers: double-buffered, no accumulation buffer.
fn egl_configs() -> impl Iterator<Item = &'static Config> {
    CONFIGS.iter().filter(|c| c.double && c.accum == 0)
}

/// A configuration handle, if it is one EGL offers.
fn config(handle: *mut c_void) -> Option<&'static Config> {
    Config::from_handle(handle).filter(|c| c.double && c.accum == 0)
}

/// A configuration's value of an EGL attribute on `d` (`None`: EGL has no such attribute).
fn attribute(d: &EglDisplay, c: &Config, name: EGLint) -> Option<EGLint> {
    let x = d.platform == EGL_PLATFORM_X11;
    Some(match name {
        EGL_BUFFER_SIZE => 4 * CHANNEL_BITS,
        EGL_RED_SIZE | EGL_GREEN_SIZE | EGL_BLUE_SIZE | EGL_ALPHA_SIZE => CHANNEL_BITS,
        EGL_DEPTH_SIZE => DEPTH_BITS,
        EGL_STENCIL_SIZE => c.stencil,
        EGL_CONFIG_CAVEAT | EGL_TRANSPARENT_TYPE => EGL_NONE,
        EGL_CONFIG_ID => c.id,
        EGL_LEVEL | EGL_SAMPLES | EGL_SAMPLE_BUFFERS | EGL_LUMINANCE_SIZE | EGL_ALPHA_MASK_SIZE => 0,
        EGL_TRANSPARENT_BLUE_VALUE..=EGL_TRANSPARENT_RED_VALUE => 0,
        EGL_MAX_PBUFFER_WIDTH | EGL_MAX_PBUFFER_HEIGHT => MAX_PBUFFER,
        EGL_MAX_PBUFFER_PIXELS => MAX_PBUFFER * MAX_PBUFFER,
        EGL_NATIVE_RENDERABLE => i32::from(x),
        EGL_NATIVE_VISUAL_ID => {
            if x {
                crate::glx::visual_of(d.native, c) as EGLint
            } else {
                0
            }
        }
        EGL_NATIVE_VISUAL_TYPE => {
            if x {
                4 // TrueColor
            } else {
                EGL_NONE
            }
        }
        EGL_SURFACE_TYPE => {
            if x {
                EGL_WINDOW_BIT | EGL_PBUFFER_BIT
            } else {
                EGL_PBUFFER_BIT
            }
        }
        EGL_BIND_TO_TEXTURE_RGB | EGL_BIND_TO_TEXTURE_RGBA => EGL_FALSE as EGLint,
        EGL_MIN_SWAP_INTERVAL => 0,
        EGL_MAX_SWAP_INTERVAL => MAX_SWAP_INTERVAL,
        EGL_COLOR_BUFFER_TYPE => EGL_RGB_BUFFER,
        EGL_RENDERABLE_TYPE | EGL_CONFORMANT => EGL_OPENGL_BIT,
        EGL_MATCH_NATIVE_PIXMAP => EGL_NONE,
        _ => return None,
    })
}

const MAX_PBUFFER: EGLint = 16384;
const MAX_SWAP_INTERVAL: EGLint = 10;

/// How `eglChooseConfig` matches an attribute (EGL 1.5 table 3.4); `None`: it is not
/// matched at all.
fn criterion(name: EGLint) -> Option<Criterion> {
    Some(match name {
        EGL_BUFFER_SIZE..=EGL_STENCIL_SIZE
        | EGL_SAMPLES
        | EGL_SAMPLE_BUFFERS
        | EGL_LUMINANCE_SIZE
        | EGL_ALPHA_MASK_SIZE => Criterion::AtLeast,
        EGL_SURFACE_TYPE | EGL_RENDERABLE_TYPE | EGL_CONFORMANT => Criterion::Mask,
        EGL_MAX_PBUFFER_HEIGHT..=EGL_MAX_PBUFFER_WIDTH | EGL_NATIVE_VISUAL_ID | EGL_MATCH_NATIVE_PIXMAP => return None,
        _ => Criterion::Exact,
    })
}

/// EGL's attribute lists: pairs up to `EGL_NONE`.
///
/// # Safety
/// `list` is NULL or ends with `EGL_NONE`.
unsafe fn pairs(list: *const EGLint) -> Vec<(EGLint, EGLint)> {
    let mut out = Vec::new();
    if list.is_null() {
        return out;
    }
    for i in 0..128 {
        // SAFETY: within the list, up to its EGL_NONE (the caller's promise).
        let name = unsafe { *list.add(2 * i) };
        if name == EGL_NONE {
            break;
        }
        out.push((name, unsafe { *list.add(2 * i + 1) }));
    }
    out
}

/// EGL 1.5's `EGLAttrib` lists (pointer-sized): pairs up to `EGL_NONE`.
///
/// # Safety
/// `list` is NULL or ends with `EGL_NONE`.
unsafe fn attrib_pairs(list: *const isize) -> Vec<(EGLint, EGLint)> {
    let mut out = Vec::new();
    if list.is_null() {
        return out;
    }
    for i in 0..64 {
        // SAFETY: within the list, up to its EGL_NONE (the caller's promise).
        let name = unsafe { *list.add(2 * i) } as EGLint;
        if name == EGL_NONE {
            break;
        }
        out.push((name, unsafe { *list.add(2 * i + 1) } as EGLint));
    }
    out
}

/// The configurations meeting a list, best first; `Err(EGL_BAD_ATTRIBUTE)` for an attribute
/// EGL has not.
fn choose(d: &EglDisplay, requested: &[(EGLint, EGLint)]) -> Result<Vec<&'static Config>, EGLint> {
    let mut wanted = vec![(EGL_RENDERABLE_TYPE, 1), (EGL_SURFACE_TYPE, EGL_WINDOW_BIT), (EGL_LEVEL, 0)];
    for &(name, value) in requested {
        attribute(d, &CONFIGS[1], name).ok_or(EGL_BAD_ATTRIBUTE)?;
        wanted.retain(|(n, _)| *n != name);
        if value != EGL_DONT_CARE {
            wanted.push((name, value));
        }
    }
    if let Some(&(_, id)) = wanted.iter().find(|(n, _)| *n == EGL_CONFIG_ID) {
        return Ok(egl_configs().filter(|c| c.id == id).collect());
    }
    let mut out: Vec<&'static Config> = egl_configs()
        .filter(|c| {
            wanted.iter().all(|&(name, value)| match (criterion(name), attribute(d, c, name)) {
                (Some(criterion), Some(have)) => meets(criterion, have, value),
                _ => true,
            })
        })
        .collect();
    out.sort_by_key(|c| (c.stencil, c.id));
    Ok(out)
}

/// Writes a list of configuration handles (`configs` NULL: only the count).
///
/// # Safety
/// `configs` is NULL or has room for `size` handles; `count` is NULL or an int.
unsafe fn write_configs(
    list: &[&'static Config],
    configs: *mut *mut c_void,
    size: EGLint,
    count: *mut EGLint,
) -> EGLBoolean {
    if count.is_null() {
        return fail(EGL_BAD_PARAMETER, EGL_FALSE);
    }
    let n = if configs.is_null() { list.len() } else { list.len().min(size.max(0) as usize) };
    // SAFETY: the caller's promise.
    unsafe {
        if !configs.is_null() {
            for (i, c) in list.iter().take(n).enumerate() {
                *configs.add(i) = c.handle();
            }
        }
        *count = n as EGLint;
    }
    ok(EGL_TRUE)
}

entry! {
    /// `eglGetError`: the last call's error in this thread, then `EGL_SUCCESS`.
    fn eglGetError() -> EGLint {
        ERROR.with(|e| e.replace(EGL_SUCCESS))
    }
}

entry! {
    /// `eglGetDisplay`: an X display (`EGL_DEFAULT_DISPLAY`: the one `DISPLAY` names, or the
    /// surfaceless platform where there is none).
    fn eglGetDisplay(native: *mut c_void) -> *mut c_void {
        if !native.is_null() {
            return ok(get_display(EGL_PLATFORM_X11, native));
        }
        let x = std::env::var_os("DISPLAY").is_some_and(|d| !d.is_empty());
        let opened = if x { x11::open_display(None) } else { std::ptr::null_mut() };
        if opened.is_null() {
            ok(get_display(EGL_PLATFORM_SURFACELESS_MESA, std::ptr::null_mut()))
        } else {
            ok(get_display(EGL_PLATFORM_X11, opened))
        }
    }
}

/// `eglGetPlatformDisplay`'s work.
fn platform_display(platform: EGLenum, native: *mut c_void, list: &[(EGLint, EGLint)]) -> *mut c_void {
    match platform {
        EGL_PLATFORM_X11 => {
            if list.iter().any(|&(n, _)| n != EGL_PLATFORM_X11_SCREEN) {
                return fail(EGL_BAD_ATTRIBUTE, std::ptr::null_mut());
            }
            let native = if native.is_null() { x11::open_display(None) } else { native };
            if native.is_null() {
                return fail(EGL_BAD_PARAMETER, std::ptr::null_mut());
            }
            ok(get_display(EGL_PLATFORM_X11, native))
        }
        EGL_PLATFORM_SURFACELESS_MESA => {
            if !native.is_null() {
                return fail(EGL_BAD_PARAMETER, std::ptr::null_mut());
            }
            if !list.is_empty() {
                return fail(EGL_BAD_ATTRIBUTE, std::ptr::null_mut());
            }
            ok(get_display(EGL_PLATFORM_SURFACELESS_MESA, std::ptr::null_mut()))
        }
        _ => fail(EGL_BAD_PARAMETER, std::ptr::null_mut()),
    }
}

entry! {
    /// `eglGetPlatformDisplay` (EGL 1.5): `EGL_PLATFORM_X11_KHR` (a `Display *`, or NULL for
    /// `DISPLAY`'s) or `EGL_PLATFORM_SURFACELESS_MESA` (`EGL_DEFAULT_DISPLAY`); another
    /// platform → `EGL_BAD_PARAMETER`.
    unsafe fn eglGetPlatformDisplay(platform: EGLenum, native: *mut c_void, list: *const isize) -> *mut c_void {
        // SAFETY: EGL's contract for the list.
        let read = unsafe { attrib_pairs(list) };
        platform_display(platform, native, &read)
    }
}

entry! {
    /// `eglGetPlatformDisplayEXT` (EGL_EXT_platform_base): as `eglGetPlatformDisplay`.
    unsafe fn eglGetPlatformDisplayEXT(platform: EGLenum, native: *mut c_void, list: *const EGLint) -> *mut c_void {
        // SAFETY: EGL's contract for the list.
        let read = unsafe { pairs(list) };
        platform_display(platform, native, &read)
    }
}

entry! {
    /// `eglInitialize`: EGL 1.5.
    unsafe fn eglInitialize(handle: *mut c_void, major: *mut EGLint, minor: *mut EGLint) -> EGLBoolean {
        let d = match display(handle, false) {
            Ok(d) => d,
            Err(e) => return fail(e, EGL_FALSE),
        };
        d.initialized = true;
        // SAFETY: EGL's contract: NULL or ints to write.
        unsafe {
            if let Some(m) = major.as_mut() {
                *m = 1;
            }
            if let Some(m) = minor.as_mut() {
                *m = 5;
            }
        }
        ok(EGL_TRUE)
    }
}

entry! {
    /// `eglTerminate`: the display is no longer initialized (its contexts and surfaces stay
    /// valid while current, as EGL says; gleval frees them when destroyed).
    fn eglTerminate(handle: *mut c_void) -> EGLBoolean {
        match display(handle, false) {
            Ok(d) => {
                d.initialized = false;
                ok(EGL_TRUE)
            }
            Err(e) => fail(e, EGL_FALSE),
        }
    }
}

entry! {
    /// `eglQueryString`: `EGL_VENDOR` "gleval", `EGL_VERSION` "1.5", `EGL_CLIENT_APIS`
    /// "OpenGL", `EGL_EXTENSIONS`; without a display, the client extensions (and the
    /// version), as EGL_EXT_client_extensions says.
    fn eglQueryString(handle: *mut c_void, name: EGLint) -> *const c_char {
        if handle.is_null() {
            return match name {
                EGL_EXTENSIONS => ok(CLIENT_EXTENSIONS.as_ptr()),
                EGL_VERSION => ok(c"1.5".as_ptr()),
                _ => fail(EGL_BAD_DISPLAY, std::ptr::null()),
            };
        }
        if let Err(e) = display(handle, true) {
            return fail(e, std::ptr::null());
        }
        match name {
            EGL_VENDOR => ok(c"gleval".as_ptr()),
            EGL_VERSION => ok(c"1.5 gleval".as_ptr()),
            EGL_CLIENT_APIS => ok(c"OpenGL".as_ptr()),
            EGL_EXTENSIONS => ok(DISPLAY_EXTENSIONS.as_ptr()),
            _ => fail(EGL_BAD_PARAMETER, std::ptr::null()),
        }
    }
}

entry! {
    /// `eglGetConfigs`.
    unsafe fn eglGetConfigs(handle: *mut c_void, configs: *mut *mut c_void, size: EGLint, count: *mut EGLint) -> EGLBoolean {
        if let Err(e) = display(handle, true) {
            return fail(e, EGL_FALSE);
        }
        let all: Vec<_> = egl_configs().collect();
        // SAFETY: EGL's contract for the out-pointers.
        unsafe { write_configs(&all, configs, size, count) }
    }
}

entry! {
    /// `eglChooseConfig`: the configurations meeting the list, best first (EGL 1.5 §3.4.1);
    /// the default `EGL_RENDERABLE_TYPE` is OpenGL ES's, which none has.
    unsafe fn eglChooseConfig(handle: *mut c_void, list: *const EGLint, configs: *mut *mut c_void, size: EGLint, count: *mut EGLint) -> EGLBoolean {
        let d = match display(handle, true) {
            Ok(d) => d,
            Err(e) => return fail(e, EGL_FALSE),
        };
        // SAFETY: EGL's contract for the list.
        let requested = unsafe { pairs(list) };
        // EGL's default renderable type is ES's bit.
        let requested: Vec<_> = if requested.iter().any(|(n, _)| *n == EGL_RENDERABLE_TYPE) {
            requested
        } else {
            std::iter::once((EGL_RENDERABLE_TYPE, 1)).chain(requested).collect()
        };
        match choose(d, &requested) {
            // SAFETY: EGL's contract for the out-pointers.
            Ok(found) => unsafe { write_configs(&found, configs, size, count) },
            Err(e) => fail(e, EGL_FALSE),
        }
    }
}

entry! {
    /// `eglGetConfigAttrib`.
    unsafe fn eglGetConfigAttrib(handle: *mut c_void, c: *mut c_void, name: EGLint, value: *mut EGLint) -> EGLBoolean {
        let d = match display(handle, true) {
            Ok(d) => d,
            Err(e) => return fail(e, EGL_FALSE),
        };
        let Some(c) = config(c) else { return fail(EGL_BAD_CONFIG, EGL_FALSE) };
        match attribute(d, c, name) {
            Some(v) if !value.is_null() => {
                // SAFETY: EGL's contract: an int to write.
                unsafe { *value = v };
                ok(EGL_TRUE)
            }
            Some(_) => fail(EGL_BAD_PARAMETER, EGL_FALSE),
            None => fail(EGL_BAD_ATTRIBUTE, EGL_FALSE),
        }
    }
}

entry! {
    /// `eglBindAPI`: `EGL_OPENGL_API`; OpenGL ES (and anything else) → `EGL_BAD_PARAMETER`.
    fn eglBindAPI(api: EGLenum) -> EGLBoolean {
        if api == EGL_OPENGL_API {
            API.with(|a| a.set(api));
            ok(EGL_TRUE)
        } else {
            let _ = EGL_OPENGL_ES_API;
            fail(EGL_BAD_PARAMETER, EGL_FALSE)
        }
    }
}

entry! {
    /// `eglQueryAPI`: the bound API (`EGL_NONE` until `EGL_OPENGL_API` is bound).
    fn eglQueryAPI() -> EGLenum {
        API.with(Cell::get)
    }
}

/// Why a context's attribute list is refused, if it is: gleval makes compatibility contexts
/// (debug or not) of OpenGL 1.0 up to the version it implements ([`gleval::gl::VERSION`]).
fn refuse(list: &[(EGLint, EGLint)]) -> Option<EGLint> {
    let (mut major, mut minor, mut forward) = (1, 0, false);
    for &(name, value) in list {
        match name {
            EGL_CONTEXT_MAJOR_VERSION => major = value,
            EGL_CONTEXT_MINOR_VERSION => minor = value,
            EGL_CONTEXT_FLAGS_KHR
                if value & !(EGL_CONTEXT_OPENGL_DEBUG_BIT | EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT | 0x4) == 0 =>
            {
                forward |= value & EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT != 0;
            }
            EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE => forward |= value != 0,
            EGL_CONTEXT_OPENGL_DEBUG | EGL_CONTEXT_OPENGL_PROFILE_MASK | EGL_CONTEXT_OPENGL_ROBUST_ACCESS => {}
            _ => return Some(EGL_BAD_ATTRIBUTE),
        }
    }
    ((major, minor) > gleval::gl::VERSION || major < 1 || minor < 0 || forward).then_some(EGL_BAD_MATCH)
}

entry! {
    /// `eglCreateContext`: an OpenGL 1.0 to 1.5 context for `config` (the bound API must be
    /// OpenGL: `EGL_BAD_MATCH` otherwise); a higher version or a forward-compatible one →
    /// `EGL_BAD_MATCH`, an attribute EGL has not → `EGL_BAD_ATTRIBUTE`.
    unsafe fn eglCreateContext(handle: *mut c_void, c: *mut c_void, share: *mut c_void, list: *const EGLint) -> *mut c_void {
        if let Err(e) = display(handle, true) {
            return fail(e, std::ptr::null_mut());
        }
        let Some(c) = config(c) else { return fail(EGL_BAD_CONFIG, std::ptr::null_mut()) };
        if API.with(Cell::get) != EGL_OPENGL_API {
            return fail(EGL_BAD_MATCH, std::ptr::null_mut());
        }
        if !share.is_null() && CONTEXTS.life(share.cast()).is_none() {
            return fail(EGL_BAD_CONTEXT, std::ptr::null_mut());
        }
        // SAFETY: EGL's contract for the list.
        let list = unsafe { pairs(list) };
        if let Some(e) = refuse(&list) {
            return fail(e, std::ptr::null_mut());
        }
        let major = list.iter().find(|(n, _)| *n == EGL_CONTEXT_MAJOR_VERSION).map_or(1, |p| p.1);
        let mut gl = Gl::new(1, 1);
        gl.set_buffer_config(c.buffers());
        let ctx = CONTEXTS.register(EglContext { gl, config: c, display: handle as usize, major, bound_once: false, draw: 0, read: 0 });
        ok(ctx.cast())
    }
}

/// The surface a handle names on a display.
fn egl_surface(handle: *mut c_void, d: usize) -> Option<EglSurface> {
    registry(|r| r.surfaces.get(&(handle as usize)).copied()).filter(|s| s.display == d)
}

/// A new surface's handle, its drawable declared.
fn new_surface(d: usize, c: &'static Config, output: Output, size: (u32, u32)) -> *mut c_void {
    let handle = registry(|r| {
        let n = r.next_surface;
        r.next_surface += 1;
        r.surfaces.insert(n, EglSurface { display: d, config: c, window: matches!(output, Output::X { .. }) });
        n
    });
    surface::declare(Key { display: d, drawable: handle as u64 }, output, size);
    handle as *mut c_void
}

/// A window surface's work (`window`: the X window's id).
fn window_surface(handle: *mut c_void, c: *mut c_void, window: Xid, list: &[(EGLint, EGLint)]) -> *mut c_void {
    let d = match display(handle, true) {
        Ok(d) => d,
        Err(e) => return fail(e, std::ptr::null_mut()),
    };
    let Some(c) = config(c) else { return fail(EGL_BAD_CONFIG, std::ptr::null_mut()) };
    if d.platform != EGL_PLATFORM_X11 {
        return fail(EGL_BAD_MATCH, std::ptr::null_mut());
    }
    for &(name, value) in list {
        let fine = match name {
            EGL_RENDER_BUFFER => value == EGL_BACK_BUFFER,
            EGL_GL_COLORSPACE => value == EGL_GL_COLORSPACE_LINEAR,
            _ => false,
        };
        if !fine {
            return fail(EGL_BAD_ATTRIBUTE, std::ptr::null_mut());
        }
    }
    let Some((w, h, _)) = x11::geometry(d.native, window) else {
        return fail(EGL_BAD_NATIVE_WINDOW, std::ptr::null_mut());
    };
    ok(new_surface(handle as usize, c, Output::X { display: d.native, drawable: window }, (w, h)))
}

entry! {
    /// `eglCreateWindowSurface`: the X window (X11 platform; the surfaceless one has no
    /// windows: `EGL_BAD_MATCH`), drawn as a GLX window is.
    unsafe fn eglCreateWindowSurface(handle: *mut c_void, c: *mut c_void, window: Xid, list: *const EGLint) -> *mut c_void {
        // SAFETY: EGL's contract for the list.
        let list = unsafe { pairs(list) };
        window_surface(handle, c, window, &list)
    }
}

entry! {
    /// `eglCreatePlatformWindowSurface` (EGL 1.5): as `eglCreateWindowSurface`, the native
    /// window given by address (a `Window *` on X11).
    unsafe fn eglCreatePlatformWindowSurface(handle: *mut c_void, c: *mut c_void, window: *const Xid, list: *const isize) -> *mut c_void {
        if window.is_null() {
            return fail(EGL_BAD_NATIVE_WINDOW, std::ptr::null_mut());
        }
        // SAFETY: EGL's contract for the list.
        let read = unsafe { attrib_pairs(list) };
        // SAFETY: EGL's contract: the address of the window's id.
        window_surface(handle, c, unsafe { *window }, &read)
    }
}

entry! {
    /// `eglCreatePbufferSurface`: an off-screen surface of `EGL_WIDTH` × `EGL_HEIGHT` (0 × 0
    /// by default); larger than gleval draws → `EGL_BAD_ALLOC` (or the largest it draws with
    /// `EGL_LARGEST_PBUFFER`); textures are not bound to pbuffers (`EGL_NO_TEXTURE` only).
    unsafe fn eglCreatePbufferSurface(handle: *mut c_void, c: *mut c_void, list: *const EGLint) -> *mut c_void {
        if let Err(e) = display(handle, true) {
            return fail(e, std::ptr::null_mut());
        }
        let Some(c) = config(c) else { return fail(EGL_BAD_CONFIG, std::ptr::null_mut()) };
        let (mut w, mut h, mut largest) = (0, 0, false);
        // SAFETY: EGL's contract for the list.
        for (name, value) in unsafe { pairs(list) } {
            match name {
                EGL_WIDTH => w = value,
                EGL_HEIGHT => h = value,
                EGL_LARGEST_PBUFFER => largest = value != 0,
                EGL_TEXTURE_FORMAT | EGL_TEXTURE_TARGET if value == EGL_NO_TEXTURE => {}
                EGL_MIPMAP_TEXTURE if value == 0 => {}
                EGL_GL_COLORSPACE if value == EGL_GL_COLORSPACE_LINEAR => {}
                _ => return fail(EGL_BAD_ATTRIBUTE, std::ptr::null_mut()),
            }
        }
        if w < 0 || h < 0 {
            return fail(EGL_BAD_PARAMETER, std::ptr::null_mut());
        }
        if w > MAX_PBUFFER || h > MAX_PBUFFER {
            if !largest {
                return fail(EGL_BAD_ALLOC, std::ptr::null_mut());
            }
            (w, h) = (w.min(MAX_PBUFFER), h.min(MAX_PBUFFER));
        }
        ok(new_surface(handle as usize, c, Output::None, (w as u32, h as u32)))
    }
}

entry! {
    /// `eglDestroySurface`: the surface and its buffers (unbound first if bound).
    fn eglDestroySurface(handle: *mut c_void, s: *mut c_void) -> EGLBoolean {
        if let Err(e) = display(handle, true) {
            return fail(e, EGL_FALSE);
        }
        if egl_surface(s, handle as usize).is_none() {
            return fail(EGL_BAD_SURFACE, EGL_FALSE);
        }
        registry(|r| r.surfaces.remove(&(s as usize)));
        surface::forget(Key { display: handle as usize, drawable: s as u64 });
        ok(EGL_TRUE)
    }
}

entry! {
    /// `eglMakeCurrent`: binds `ctx` to `draw` (gleval reads from `draw`; `read` is checked)
    /// in this thread, or to no surface at all (EGL_KHR_surfaceless_context: nothing is
    /// drawn); `EGL_NO_CONTEXT` with no surfaces releases. A context current in another
    /// thread → `EGL_BAD_ACCESS`.
    fn eglMakeCurrent(handle: *mut c_void, draw: *mut c_void, read: *mut c_void, ctx: *mut c_void) -> EGLBoolean {
        if let Err(e) = display(handle, true) {
            // Releasing needs no initialized display.
            if !(ctx.is_null() && draw.is_null() && read.is_null() && e == EGL_NOT_INITIALIZED) {
                return fail(e, EGL_FALSE);
            }
        }
        if ctx.is_null() {
            if !draw.is_null() || !read.is_null() {
                return fail(EGL_BAD_MATCH, EGL_FALSE);
            }
            CONTEXTS.release_current();
            return ok(EGL_TRUE);
        }
        let ctx: *mut EglContext = ctx.cast();
        let Some(life) = CONTEXTS.life(ctx) else {
            return fail(EGL_BAD_CONTEXT, EGL_FALSE);
        };
        let me = std::thread::current().id();
        if life.current_in.is_some_and(|t| t != me) {
            return fail(EGL_BAD_ACCESS, EGL_FALSE);
        }
        if draw.is_null() != read.is_null() {
            return fail(EGL_BAD_MATCH, EGL_FALSE);
        }
        let d = handle as usize;
        let surfaces = (egl_surface(draw, d), egl_surface(read, d));
        if !draw.is_null() && (surfaces.0.is_none() || surfaces.1.is_none()) {
            return fail(EGL_BAD_SURFACE, EGL_FALSE);
        }
        // SAFETY: registered, hence live, and current nowhere else.
        let context = unsafe { &mut *ctx };
        if surfaces.0.is_some_and(|s| s.config != context.config) {
            return fail(EGL_BAD_MATCH, EGL_FALSE);
        }
        if CONTEXTS.current() != ctx {
            CONTEXTS.release_current();
        } else {
            surface::unbind();
        }
        (context.draw, context.read) = (draw as usize, read as usize);
        CONTEXTS.make_current(context);
        if !draw.is_null() {
            let first = !context.bound_once;
            context.bound_once = true;
            surface::bind(Key { display: d, drawable: draw as u64 }, &mut context.gl, first);
        }
        ok(EGL_TRUE)
    }
}

entry! {
    /// `eglDestroyContext`: freed now, or when released if it is current.
    fn eglDestroyContext(handle: *mut c_void, ctx: *mut c_void) -> EGLBoolean {
        if let Err(e) = display(handle, true) {
            return fail(e, EGL_FALSE);
        }
        let Some(life) = CONTEXTS.life(ctx.cast()) else {
            return fail(EGL_BAD_CONTEXT, EGL_FALSE);
        };
        CONTEXTS.destroy(ctx.cast(), life);
        ok(EGL_TRUE)
    }
}

/// This thread's current context, if it is an EGL one and still current.
fn current() -> Option<&'static mut EglContext> {
    let ctx = CONTEXTS.current();
    // SAFETY: a current context is live until released.
    let ctx = unsafe { ctx.as_mut() }?;
    std::ptr::eq(&ctx.gl, crate::context::current_ptr()).then_some(ctx)
}

entry! {
    /// `eglSwapBuffers`: a window surface bound to this thread's context shows its back
    /// buffer (after the swap interval); a pbuffer is left as it is. A surface not bound
    /// to this thread's context → `EGL_BAD_SURFACE`.
    fn eglSwapBuffers(handle: *mut c_void, s: *mut c_void) -> EGLBoolean {
        if let Err(e) = display(handle, true) {
            return fail(e, EGL_FALSE);
        }
        let Some(found) = egl_surface(s, handle as usize) else { return fail(EGL_BAD_SURFACE, EGL_FALSE) };
        let key = Key { display: handle as usize, drawable: s as u64 };
        if current().is_none_or(|c| c.draw != s as usize) {
            return fail(EGL_BAD_SURFACE, EGL_FALSE);
        }
        if found.window {
            surface::pace(key);
            surface::present_current(true);
        } else {
            surface::flush_current();
        }
        ok(EGL_TRUE)
    }
}

entry! {
    /// `eglSwapInterval`: the current draw surface's swap interval, clamped to 0..=10.
    fn eglSwapInterval(handle: *mut c_void, interval: EGLint) -> EGLBoolean {
        if let Err(e) = display(handle, true) {
            return fail(e, EGL_FALSE);
        }
        let Some(ctx) = current() else { return fail(EGL_BAD_CONTEXT, EGL_FALSE) };
        if ctx.draw == 0 {
            return fail(EGL_BAD_SURFACE, EGL_FALSE);
        }
        surface::set_interval(Key { display: handle as usize, drawable: ctx.draw as u64 }, interval.clamp(0, MAX_SWAP_INTERVAL) as u32);
        ok(EGL_TRUE)
    }
}

/// A query's answer written where the caller said (`EGL_BAD_PARAMETER` for NULL).
///
/// # Safety
/// `value` is NULL or an int to write.
unsafe fn write_answer(value: *mut EGLint, answer: EGLint) -> EGLBoolean {
    if value.is_null() {
        return fail(EGL_BAD_PARAMETER, EGL_FALSE);
    }
    // SAFETY: the caller's promise.
    unsafe { *value = answer };
    ok(EGL_TRUE)
}

entry! {
    /// `eglQuerySurface`: `EGL_WIDTH`, `EGL_HEIGHT`, `EGL_CONFIG_ID`, `EGL_RENDER_BUFFER`,
    /// `EGL_SWAP_BEHAVIOR` (gleval's buffers are preserved), `EGL_LARGEST_PBUFFER`,
    /// `EGL_TEXTURE_FORMAT`/`TARGET`, `EGL_MIPMAP_TEXTURE`, `EGL_GL_COLORSPACE`.
    unsafe fn eglQuerySurface(handle: *mut c_void, s: *mut c_void, name: EGLint, value: *mut EGLint) -> EGLBoolean {
        if let Err(e) = display(handle, true) {
            return fail(e, EGL_FALSE);
        }
        let Some(found) = egl_surface(s, handle as usize) else { return fail(EGL_BAD_SURFACE, EGL_FALSE) };
        let size = surface::size(Key { display: handle as usize, drawable: s as u64 }).unwrap_or((0, 0));
        let answer = match name {
            EGL_WIDTH => size.0 as EGLint,
            EGL_HEIGHT => size.1 as EGLint,
            EGL_CONFIG_ID => found.config.id,
            EGL_RENDER_BUFFER => EGL_BACK_BUFFER,
            EGL_SWAP_BEHAVIOR => EGL_BUFFER_PRESERVED,
            EGL_LARGEST_PBUFFER | EGL_MIPMAP_TEXTURE => 0,
            EGL_TEXTURE_FORMAT | EGL_TEXTURE_TARGET => EGL_NO_TEXTURE,
            EGL_GL_COLORSPACE => EGL_GL_COLORSPACE_LINEAR,
            _ => return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE),
        };
        // SAFETY: EGL's contract for `value`.
        unsafe { write_answer(value, answer) }
    }
}

entry! {
    /// `eglQueryContext`: `EGL_CONFIG_ID`, `EGL_CONTEXT_CLIENT_TYPE` (OpenGL),
    /// `EGL_CONTEXT_CLIENT_VERSION` (the major version asked for), `EGL_RENDER_BUFFER`.
    unsafe fn eglQueryContext(handle: *mut c_void, ctx: *mut c_void, name: EGLint, value: *mut EGLint) -> EGLBoolean {
        if let Err(e) = display(handle, true) {
            return fail(e, EGL_FALSE);
        }
        if CONTEXTS.life(ctx.cast()).is_none() {
            return fail(EGL_BAD_CONTEXT, EGL_FALSE);
        }
        // SAFETY: registered, hence live; only plain fields are read.
        let c = unsafe { &*ctx.cast::<EglContext>() };
        let answer = match name {
            EGL_CONFIG_ID => c.config.id,
            EGL_CONTEXT_CLIENT_TYPE => EGL_OPENGL_API as EGLint,
            EGL_CONTEXT_MAJOR_VERSION => c.major,
            EGL_RENDER_BUFFER => {
                if c.draw == 0 {
                    EGL_NONE
                } else {
                    EGL_BACK_BUFFER
                }
            }
            _ => return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE),
        };
        // SAFETY: EGL's contract for `value`.
        unsafe { write_answer(value, answer) }
    }
}

entry! {
    /// `eglGetCurrentContext`.
    fn eglGetCurrentContext() -> *mut c_void {
        current().map_or(std::ptr::null_mut(), |c| (c as *mut EglContext).cast())
    }
}

entry! {
    /// `eglGetCurrentSurface`: `EGL_DRAW` or `EGL_READ`; another → `EGL_BAD_PARAMETER`.
    fn eglGetCurrentSurface(which: EGLint) -> *mut c_void {
        let c = current();
        match which {
            EGL_DRAW => ok(c.map_or(0, |c| c.draw) as *mut c_void),
            EGL_READ => ok(c.map_or(0, |c| c.read) as *mut c_void),
            _ => fail(EGL_BAD_PARAMETER, std::ptr::null_mut()),
        }
    }
}

entry! {
    /// `eglGetCurrentDisplay`.
    fn eglGetCurrentDisplay() -> *mut c_void {
        current().map_or(std::ptr::null_mut(), |c| c.display as *mut c_void)
    }
}

entry! {
    /// `eglWaitClient`: what the current context drew is on its surface (shown, if it draws
    /// into the front buffer).
    fn eglWaitClient() -> EGLBoolean {
        surface::flush_and_show();
        ok(EGL_TRUE)
    }
}

entry! {
    /// `eglWaitGL`: `eglWaitClient` for OpenGL.
    fn eglWaitGL() -> EGLBoolean {
        eglWaitClient()
    }
}

entry! {
    /// `eglWaitNative`: the X server has handled every request sent.
    fn eglWaitNative(_engine: EGLint) -> EGLBoolean {
        if let Some(c) = current() {
            // SAFETY: registered displays are alive.
            let d = unsafe { &*(c.display as *const EglDisplay) };
            if d.platform == EGL_PLATFORM_X11 {
                x11::sync(d.native);
            }
        }
        ok(EGL_TRUE)
    }
}

entry! {
    /// `eglReleaseThread`: releases this thread's context; the bound API is reset.
    fn eglReleaseThread() -> EGLBoolean {
        CONTEXTS.release_current();
        API.with(|a| a.set(EGL_NONE_API));
        ok(EGL_TRUE)
    }
}

entry! {
    /// `eglGetProcAddress`: gleval's entry point for every GL and EGL function it
    /// implements (EGL_KHR_get_all_proc_addresses), NULL for any other.
    unsafe fn eglGetProcAddress(name: *const c_char) -> *mut c_void {
        // SAFETY: EGL's contract: a NUL-terminated name.
        unsafe { crate::glx::proc_address(name) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn contexts_of_versions_above_one_five_are_refused() {
        assert_eq!(refuse(&[]), None);
        assert_eq!(refuse(&[(EGL_CONTEXT_MAJOR_VERSION, 1), (EGL_CONTEXT_MINOR_VERSION, 1)]), None);
        assert_eq!(refuse(&[(EGL_CONTEXT_MAJOR_VERSION, 1), (EGL_CONTEXT_MINOR_VERSION, 5)]), None);
        assert_eq!(refuse(&[(EGL_CONTEXT_MAJOR_VERSION, 1), (EGL_CONTEXT_MINOR_VERSION, 6)]), Some(EGL_BAD_MATCH));
        assert_eq!(refuse(&[(EGL_CONTEXT_MAJOR_VERSION, 2)]), Some(EGL_BAD_MATCH));
        assert_eq!(refuse(&[(EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE, 1)]), Some(EGL_BAD_MATCH));
        assert_eq!(refuse(&[(0x1234, 0)]), Some(EGL_BAD_ATTRIBUTE));
    }

    #[test]
    fn the_default_renderable_type_is_es_and_no_configuration_has_it() {
        let d = EglDisplay { platform: EGL_PLATFORM_SURFACELESS_MESA, native: std::ptr::null_mut(), initialized: true };
        assert!(choose(&d, &[(EGL_RENDERABLE_TYPE, 1)]).unwrap().is_empty());
        let gl = choose(&d, &[(EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT), (EGL_SURFACE_TYPE, EGL_PBUFFER_BIT)]).unwrap();
        assert_eq!(gl.len(), 2);
        assert_eq!(gl[0].stencil, 0, "fewer stencil bits first");
        let windows = choose(&d, &[(EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT)]).unwrap();
        assert!(windows.is_empty(), "the surfaceless platform has no windows");
        assert_eq!(choose(&d, &[(0x1234, 0)]), Err(EGL_BAD_ATTRIBUTE));
    }
}
