//! Visuals and FBConfigs (GLX 1.4 §3.3.3): gleval's configurations (`crate::configs`) with
//! GLX's attributes, matched and sorted as GLX says.
//!
//! Each configuration is tied to one of the screen's TrueColor visuals of depth 24 (the
//! k-th configuration to the k-th such visual, the default visual to the first, wrapping
//! round where the server has fewer), so that `glXChooseVisual`'s answer names the
//! configuration a later `glXCreateContext` gets.

use super::{attributes, glx_error, request, GlxError};
use crate::configs::{meets, sort, Config, Criterion, CHANNEL_BITS, CONFIGS, DEPTH_BITS};
use crate::x11::{self, Display, XVisualInfo};
use std::ffi::{c_int, c_ulong, c_void};

pub const GLX_USE_GL: i32 = 1;
pub const GLX_BUFFER_SIZE: i32 = 2;
pub const GLX_LEVEL: i32 = 3;
pub const GLX_RGBA: i32 = 4;
pub const GLX_DOUBLEBUFFER: i32 = 5;
pub const GLX_STEREO: i32 = 6;
pub const GLX_AUX_BUFFERS: i32 = 7;
pub const GLX_RED_SIZE: i32 = 8;
pub const GLX_GREEN_SIZE: i32 = 9;
pub const GLX_BLUE_SIZE: i32 = 10;
pub const GLX_ALPHA_SIZE: i32 = 11;
pub const GLX_DEPTH_SIZE: i32 = 12;
pub const GLX_STENCIL_SIZE: i32 = 13;
pub const GLX_ACCUM_RED_SIZE: i32 = 14;
pub const GLX_ACCUM_GREEN_SIZE: i32 = 15;
pub const GLX_ACCUM_BLUE_SIZE: i32 = 16;
pub const GLX_ACCUM_ALPHA_SIZE: i32 = 17;
pub const GLX_CONFIG_CAVEAT: i32 = 0x20;
pub const GLX_X_VISUAL_TYPE: i32 = 0x22;
pub const GLX_TRANSPARENT_TYPE: i32 = 0x23;
pub const GLX_TRANSPARENT_INDEX_VALUE: i32 = 0x24;
pub const GLX_TRANSPARENT_ALPHA_VALUE: i32 = 0x28;
pub const GLX_DONT_CARE: i32 = -1;
pub const GLX_NONE: i32 = 0x8000;
pub const GLX_TRUE_COLOR: i32 = 0x8002;
pub const GLX_VISUAL_ID: i32 = 0x800B;
pub const GLX_SCREEN: i32 = 0x800C;
pub const GLX_DRAWABLE_TYPE: i32 = 0x8010;
pub const GLX_RENDER_TYPE: i32 = 0x8011;
pub const GLX_X_RENDERABLE: i32 = 0x8012;
pub const GLX_FBCONFIG_ID: i32 = 0x8013;
pub const GLX_RGBA_TYPE: i32 = 0x8014;
pub const GLX_COLOR_INDEX_TYPE: i32 = 0x8015;
pub const GLX_MAX_PBUFFER_WIDTH: i32 = 0x8016;
pub const GLX_MAX_PBUFFER_HEIGHT: i32 = 0x8017;
pub const GLX_MAX_PBUFFER_PIXELS: i32 = 0x8018;
pub const GLX_WINDOW_BIT: i32 = 1;
pub const GLX_PIXMAP_BIT: i32 = 2;
pub const GLX_PBUFFER_BIT: i32 = 4;
pub const GLX_RGBA_BIT: i32 = 1;
pub const GLX_SAMPLE_BUFFERS: i32 = 100_000;
pub const GLX_SAMPLES: i32 = 100_001;
pub const GLX_FRAMEBUFFER_SRGB_CAPABLE: i32 = 0x20B2;
/// `glXGetConfig`'s and `glXGetFBConfigAttrib`'s answers.
pub const GLX_BAD_SCREEN: c_int = 1;
pub const GLX_BAD_ATTRIBUTE: c_int = 2;
pub const GLX_BAD_VISUAL: c_int = 4;

/// The largest pbuffer, as for the largest viewport (`GL_MAX_VIEWPORT_DIMS`).
pub const MAX_PBUFFER: i32 = 16384;

extern "C" {
    fn malloc(size: usize) -> *mut c_void;
}

/// A configuration's value of a GLX attribute; `None` for an attribute GLX does not have.
/// `visual` is the visual tied to it (0 where there is no display to ask).
pub fn attribute(config: &Config, name: i32, visual: c_ulong) -> Option<i32> {
    Some(match name {
        GLX_USE_GL | GLX_RGBA | GLX_X_RENDERABLE => 1,
        GLX_BUFFER_SIZE => 4 * CHANNEL_BITS,
        GLX_LEVEL | GLX_STEREO | GLX_AUX_BUFFERS | GLX_SAMPLE_BUFFERS | GLX_SAMPLES => 0,
        GLX_FRAMEBUFFER_SRGB_CAPABLE => 0,
        GLX_DOUBLEBUFFER => i32::from(config.double),
        GLX_RED_SIZE | GLX_GREEN_SIZE | GLX_BLUE_SIZE | GLX_ALPHA_SIZE => CHANNEL_BITS,
        GLX_DEPTH_SIZE => DEPTH_BITS,
        GLX_STENCIL_SIZE => config.stencil,
        GLX_ACCUM_RED_SIZE | GLX_ACCUM_GREEN_SIZE | GLX_ACCUM_BLUE_SIZE | GLX_ACCUM_ALPHA_SIZE => config.accum,
        GLX_CONFIG_CAVEAT | GLX_TRANSPARENT_TYPE => GLX_NONE,
        GLX_TRANSPARENT_INDEX_VALUE..=GLX_TRANSPARENT_ALPHA_VALUE => 0,
        GLX_X_VISUAL_TYPE => GLX_TRUE_COLOR,
        GLX_VISUAL_ID => visual as i32,
        GLX_SCREEN => 0,
        GLX_DRAWABLE_TYPE => GLX_WINDOW_BIT | GLX_PIXMAP_BIT | GLX_PBUFFER_BIT,
        GLX_RENDER_TYPE => GLX_RGBA_BIT,
        GLX_FBCONFIG_ID => config.id,
        GLX_MAX_PBUFFER_WIDTH | GLX_MAX_PBUFFER_HEIGHT => MAX_PBUFFER,
        GLX_MAX_PBUFFER_PIXELS => MAX_PBUFFER * MAX_PBUFFER,
        _ => return None,
    })
}

/// How `glXChooseFBConfig` matches an attribute (GLX 1.4 table 3.4).
fn criterion(name: i32) -> Criterion {
    match name {
        GLX_BUFFER_SIZE | GLX_AUX_BUFFERS | GLX_RED_SIZE..=GLX_ACCUM_ALPHA_SIZE | GLX_SAMPLE_BUFFERS | GLX_SAMPLES => {
            Criterion::AtLeast
        }
        GLX_DRAWABLE_TYPE | GLX_RENDER_TYPE => Criterion::Mask,
        _ => Criterion::Exact,
    }
}

/// The configurations matching a GLX attribute list, best first (`fbconfig`: the rules of
/// `glXChooseFBConfig`, else of `glXChooseVisual`); `None` for an attribute GLX does not have
/// (`BadValue` where the caller reports one).
fn choose(requested: &[(i32, i32)], fbconfig: bool) -> Option<Vec<&'static Config>> {
    // The defaults the call assumes for what the list leaves out.
    let mut wanted: Vec<(i32, i32)> = if fbconfig {
        vec![(GLX_LEVEL, 0), (GLX_STEREO, 0), (GLX_RENDER_TYPE, GLX_RGBA_BIT), (GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT)]
    } else {
        // glXChooseVisual: a boolean absent is false. Without GLX_RGBA GLX asks for colour
        // index, which Mesa answers with an RGBA visual where it has no colour index (as
        // llvmpipe, and gleval): so does gleval.
        vec![(GLX_LEVEL, 0), (GLX_STEREO, 0), (GLX_DOUBLEBUFFER, 0)]
    };
    for &(name, value) in requested {
        if fbconfig && name == GLX_RGBA || !fbconfig && name == GLX_RENDER_TYPE {
            return None;
        }
        // A visual type or caveat of GLX_DONT_CARE, or any attribute so, matches everything.
        wanted.retain(|(n, _)| *n != name);
        if value != GLX_DONT_CARE || !fbconfig {
            wanted.push((name, value));
        }
    }
    let mut out = Vec::new();
    for config in &CONFIGS {
        let mut fits = true;
        for &(name, value) in &wanted {
            let have = attribute(config, name, 0)?;
            if name == GLX_VISUAL_ID || name == GLX_SCREEN {
                continue;
            }
            fits &= meets(criterion(name), have, value);
        }
        if fits {
            out.push(config);
        }
    }
    sort(&mut out);
    Some(out)
}

thread_local! {
    /// Each display's TrueColor visuals of depth 24 on its default screen, by id.
    static VISUALS: std::cell::RefCell<Vec<(usize, Vec<c_ulong>)>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// The visual ids of `display`'s default screen that configurations are tied to.
fn visual_ids(display: *mut Display) -> Vec<c_ulong> {
    if let Some(ids) = VISUALS
        .try_with(|v| v.borrow().iter().find(|(d, _)| *d == display as usize).map(|(_, i)| i.clone()))
        .ok()
        .flatten()
    {
        return ids;
    }
    let screen = x11::screens(display).map_or(0, |(s, _)| s);
    let mut ids = Vec::new();
    if let Some((list, n)) = x11::visuals(display, screen, None) {
        // SAFETY: Xlib's list of `n` entries, freed here.
        ids = (0..n).map(|i| unsafe { (*list.add(i)).visualid }).collect();
        x11::free(list.cast());
    }
    let _ = VISUALS.try_with(|v| v.borrow_mut().push((display as usize, ids.clone())));
    ids
}

/// The visual a configuration is tied to on `display` (0 if the screen has none to offer).
pub fn visual_of(display: *mut Display, config: &Config) -> c_ulong {
    let ids = visual_ids(display);
    if ids.is_empty() {
        0
    } else {
        ids[config.index() % ids.len()]
    }
}

/// The configuration a visual names, if it is one gleval's configurations are tied to.
pub fn config_of_visual(display: *mut Display, visualid: c_ulong) -> Option<&'static Config> {
    CONFIGS.iter().find(|c| visual_of(display, c) == visualid)
}

/// The `XVisualInfo` of a configuration's visual, allocated by Xlib (the caller frees it
/// with `XFree`); NULL where the screen has none.
fn visual_info(display: *mut Display, screen: c_int, config: &Config) -> *mut XVisualInfo {
    let id = visual_of(display, config);
    x11::visuals(display, screen, Some(id)).map_or(std::ptr::null_mut(), |(list, _)| list)
}

/// A list of configuration handles the caller frees with `XFree` (C's `free`), as GLX's are.
fn handle_list(configs: &[&'static Config], count: *mut c_int) -> *mut *mut c_void {
    if !count.is_null() {
        // SAFETY: GLX's contract: `count` is NULL or points at an int.
        unsafe { *count = configs.len() as c_int };
    }
    if configs.is_empty() {
        return std::ptr::null_mut();
    }
    // SAFETY: malloc's block holds `configs.len()` pointers, each written once.
    unsafe {
        let list: *mut *mut c_void = malloc(configs.len() * std::mem::size_of::<*mut c_void>()).cast();
        if list.is_null() {
            return list;
        }
        for (i, c) in configs.iter().enumerate() {
            *list.add(i) = c.handle();
        }
        list
    }
}

/// Whether `screen` is one of the display's.
fn screen_exists(display: *mut Display, screen: c_int) -> bool {
    x11::screens(display).is_some_and(|(_, n)| (0..n).contains(&screen))
}

entry! {
    /// `glXChooseVisual`: the visual of the best configuration meeting the list (booleans
    /// stand alone; without `GLX_RGBA` an RGBA one all the same, as Mesa answers without
    /// colour-index visuals). The caller frees it with `XFree`.
    unsafe fn glXChooseVisual(display: *mut Display, screen: c_int, list: *const c_int) -> *mut XVisualInfo {
        let booleans = [GLX_USE_GL, GLX_RGBA, GLX_DOUBLEBUFFER, GLX_STEREO];
        // SAFETY: GLX's contract for the list.
        let requested = unsafe { attributes(list, &booleans) };
        if !screen_exists(display, screen) {
            return std::ptr::null_mut();
        }
        let Some(found) = choose(&requested, false) else { return std::ptr::null_mut() };
        found.first().map_or(std::ptr::null_mut(), |c| visual_info(display, screen, c))
    }
}

entry! {
    /// `glXGetConfig`: a visual's GLX attribute. A visual no configuration is tied to
    /// answers `GLX_USE_GL` false and `GLX_BAD_VISUAL` for the rest; an unknown attribute
    /// `GLX_BAD_ATTRIBUTE`.
    unsafe fn glXGetConfig(display: *mut Display, visual: *mut XVisualInfo, name: c_int, value: *mut c_int) -> c_int {
        if visual.is_null() || value.is_null() {
            return GLX_BAD_VISUAL;
        }
        // SAFETY: GLX's contract: a visual from Xlib, an int to write.
        let (id, screen) = unsafe { ((*visual).visualid, (*visual).screen) };
        if !screen_exists(display, screen) {
            return GLX_BAD_SCREEN;
        }
        match config_of_visual(display, id) {
            Some(config) => match attribute(config, name, id) {
                Some(v) => {
                    unsafe { *value = v };
                    0
                }
                None => GLX_BAD_ATTRIBUTE,
            },
            None if name == GLX_USE_GL => {
                unsafe { *value = 0 };
                0
            }
            None => GLX_BAD_VISUAL,
        }
    }
}

entry! {
    /// `glXChooseFBConfig`: the configurations meeting the list, best first, as a list the
    /// caller frees with `XFree`; NULL (and `*count` 0) if none, or `BadValue` for an
    /// attribute GLX does not have.
    unsafe fn glXChooseFBConfig(display: *mut Display, screen: c_int, list: *const c_int, count: *mut c_int) -> *mut *mut c_void {
        // SAFETY: GLX's contract for the list.
        let requested = unsafe { attributes(list, &[]) };
        if !screen_exists(display, screen) {
            return handle_list(&[], count);
        }
        match choose(&requested, true) {
            Some(found) => handle_list(&found, count),
            None => {
                super::x_error(display, super::BAD_VALUE, 0, request::GET_FB_CONFIGS);
                handle_list(&[], count)
            }
        }
    }
}

entry! {
    /// `glXGetFBConfigs`: every configuration.
    unsafe fn glXGetFBConfigs(display: *mut Display, screen: c_int, count: *mut c_int) -> *mut *mut c_void {
        let all: Vec<&'static Config> = if screen_exists(display, screen) { CONFIGS.iter().collect() } else { Vec::new() };
        handle_list(&all, count)
    }
}

entry! {
    /// `glXGetFBConfigAttrib`: 0 (Success), `GLX_BAD_ATTRIBUTE` for an attribute GLX does not
    /// have; a handle that is not a configuration → `GLXBadFBConfig`.
    unsafe fn glXGetFBConfigAttrib(display: *mut Display, config: *mut c_void, name: c_int, value: *mut c_int) -> c_int {
        let Some(config) = Config::from_handle(config) else {
            glx_error(display, GlxError::FbConfig, 0, request::GET_FB_CONFIGS);
            return GLX_BAD_ATTRIBUTE;
        };
        match attribute(config, name, visual_of(display, config)) {
            Some(v) if !value.is_null() => {
                // SAFETY: GLX's contract: an int to write.
                unsafe { *value = v };
                0
            }
            _ => GLX_BAD_ATTRIBUTE,
        }
    }
}

entry! {
    /// `glXGetVisualFromFBConfig`: the configuration's visual (`XFree` it); NULL for a handle
    /// that is not a configuration.
    unsafe fn glXGetVisualFromFBConfig(display: *mut Display, config: *mut c_void) -> *mut XVisualInfo {
        match Config::from_handle(config) {
            Some(config) => visual_info(display, x11::screens(display).map_or(0, |(s, _)| s), config),
            None => std::ptr::null_mut(),
        }
    }
}

/// Whether a configuration handle is one (`GLXBadFBConfig` reported if not).
pub fn config_or_error(display: *mut Display, handle: *mut c_void, minor: u16) -> Option<&'static Config> {
    let found = Config::from_handle(handle);
    if found.is_none() {
        glx_error(display, GlxError::FbConfig, 0, minor);
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn choose_visual_needs_rgba_and_matches_double_buffering_exactly() {
        assert!(!choose(&[], false).unwrap().is_empty(), "no GLX_RGBA: RGBA all the same, as Mesa answers");
        let single = choose(&[(GLX_RGBA, 1)], false).unwrap();
        assert!(!single.is_empty() && single.iter().all(|c| !c.double));
        let double = choose(&[(GLX_RGBA, 1), (GLX_DOUBLEBUFFER, 1), (GLX_DEPTH_SIZE, 16)], false).unwrap();
        assert!(!double.is_empty() && double.iter().all(|c| c.double));
        assert!(choose(&[(GLX_RGBA, 1), (GLX_DEPTH_SIZE, 32)], false).unwrap().is_empty());
    }

    #[test]
    fn choose_fbconfig_takes_dont_care_and_prefers_fewer_stencil_bits() {
        let any = choose(&[(GLX_DOUBLEBUFFER, GLX_DONT_CARE)], true).unwrap();
        assert_eq!(any.len(), CONFIGS.len());
        let stencil = choose(&[(GLX_STENCIL_SIZE, 1), (GLX_DOUBLEBUFFER, 1)], true).unwrap();
        assert!(stencil.iter().all(|c| c.stencil == 8 && c.double));
        let best = choose(&[(GLX_DOUBLEBUFFER, 1), (GLX_ACCUM_RED_SIZE, 0)], true).unwrap()[0];
        assert_eq!((best.stencil, best.accum), (0, 16), "smaller stencil, larger accumulation first");
        assert!(choose(&[(GLX_SAMPLES, 4)], true).unwrap().is_empty());
        assert!(choose(&[(GLX_RENDER_TYPE, 2)], true).unwrap().is_empty(), "colour index");
        assert!(choose(&[(0x7777, 1)], true).is_none(), "an attribute GLX does not have");
    }

    #[test]
    fn attributes_read_pairs_and_booleans_up_to_none() {
        let list = [GLX_RGBA, GLX_DEPTH_SIZE, 24, GLX_DOUBLEBUFFER, 0, 99];
        let read = unsafe { attributes(list.as_ptr(), &[GLX_RGBA, GLX_DOUBLEBUFFER]) };
        assert_eq!(read, [(GLX_RGBA, 1), (GLX_DEPTH_SIZE, 24), (GLX_DOUBLEBUFFER, 1)]);
        assert!(unsafe { attributes(std::ptr::null(), &[]) }.is_empty());
    }
}
