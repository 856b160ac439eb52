//! The little of Xlib gleval needs to draw into a program's X drawables: their size, a GC, an
//! image put. Looked up at run time (the program that hands gleval a `Display *` has loaded
//! Xlib; otherwise `libX11.so.6` is loaded on first use), so `libgleval_c` links no X
//! library and runs where there is none.

use crate::dl;
use std::ffi::{c_char, c_int, c_long, c_uint, c_ulong, c_void, CStr};
use std::sync::OnceLock;

/// Xlib's `Display` (opaque).
pub type Display = c_void;
/// An X resource id: a window, pixmap, or a GLX drawable gleval hands out.
pub type Xid = c_ulong;

/// Xlib's `XVisualInfo`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct XVisualInfo {
    pub visual: *mut c_void,
    pub visualid: c_ulong,
    pub screen: c_int,
    pub depth: c_int,
    pub class: c_int,
    pub red_mask: c_ulong,
    pub green_mask: c_ulong,
    pub blue_mask: c_ulong,
    pub colormap_size: c_int,
    pub bits_per_rgb: c_int,
}

/// Xlib's `XImage` (its function table filled by `XInitImage`).
#[repr(C)]
struct XImage {
    width: c_int,
    height: c_int,
    xoffset: c_int,
    format: c_int,
    data: *mut c_char,
    byte_order: c_int,
    bitmap_unit: c_int,
    bitmap_bit_order: c_int,
    bitmap_pad: c_int,
    depth: c_int,
    bytes_per_line: c_int,
    bits_per_pixel: c_int,
    red_mask: c_ulong,
    green_mask: c_ulong,
    blue_mask: c_ulong,
    obdata: *mut c_char,
    funcs: [*mut c_void; 6],
}

/// Xlib's `XCharStruct`: one glyph's metrics.
#[repr(C)]
#[derive(Clone, Copy, Default)]
pub struct XCharStruct {
    pub lbearing: i16,
    pub rbearing: i16,
    pub width: i16,
    pub ascent: i16,
    pub descent: i16,
    pub attributes: u16,
}

/// Xlib's `XFontStruct` (what `XQueryFont` answers).
#[repr(C)]
pub struct XFontStruct {
    ext_data: *mut c_void,
    fid: Xid,
    direction: c_uint,
    min_char_or_byte2: c_uint,
    max_char_or_byte2: c_uint,
    min_byte1: c_uint,
    max_byte1: c_uint,
    all_chars_exist: c_int,
    default_char: c_uint,
    n_properties: c_int,
    properties: *mut c_void,
    min_bounds: XCharStruct,
    max_bounds: XCharStruct,
    per_char: *mut XCharStruct,
    ascent: c_int,
    descent: c_int,
}

/// An X server font's glyphs, as `glXUseXFont` draws them into display lists.
pub struct FontGlyphs {
    display: *mut Display,
    info: *mut XFontStruct,
    font: Xid,
}

impl FontGlyphs {
    /// The font `font` of `display`; `None` if it is not one (the server's `BadFont` goes to
    /// the program's error handler).
    pub fn open(display: *mut Display, font: Xid) -> Option<Self> {
        let x = xlib()?;
        if display.is_null() {
            return None;
        }
        // SAFETY: the program's open connection.
        let info = unsafe { (x.query_font)(display, font) };
        (!info.is_null()).then_some(Self { display, info, font })
    }

    /// The metrics of glyph `c` (single-byte fonts; for two-byte ones, row `min_byte1`), or
    /// `None` where the font has none: outside its range, or an empty glyph.
    pub fn metrics(&self, c: u32) -> Option<XCharStruct> {
        // SAFETY: `info` is XQueryFont's answer, alive until drop; `per_char` (when not
        // NULL) has one entry per character of the range.
        let info = unsafe { &*self.info };
        if c < info.min_char_or_byte2 || c > info.max_char_or_byte2 {
            return None;
        }
        let m = if info.per_char.is_null() {
            info.max_bounds
        } else {
            unsafe { *info.per_char.add((c - info.min_char_or_byte2) as usize) }
        };
        let empty = m.width == 0 && m.lbearing == 0 && m.rbearing == 0 && m.ascent == 0 && m.descent == 0;
        (!empty).then_some(m)
    }

    /// Glyph `c` drawn by the server: its bits, rows bottom to top, each row `(width + 7) / 8`
    /// bytes, the leftmost pixel the high bit (as `glBitmap` reads them by default).
    pub fn bitmap(&self, c: u32, m: &XCharStruct) -> Vec<u8> {
        let Some(x) = xlib() else { return Vec::new() };
        let (w, h) = ((m.rbearing - m.lbearing).max(0) as u32, (m.ascent + m.descent).max(0) as u32);
        let stride = w.div_ceil(8) as usize;
        let mut bits = vec![0u8; stride * h as usize];
        if w == 0 || h == 0 {
            return bits;
        }
        let ch = c as u8 as c_char;
        // SAFETY: the program's open connection; the pixmap, GC and image are made and freed
        // here; XGetImage's image is read through its own get_pixel and destroyed by its own
        // destroy_image, as Xlib's macros do.
        unsafe {
            let root = (x.default_root_window)(self.display);
            let pixmap = (x.create_pixmap)(self.display, root, w, h, 1);
            let gc = (x.create_gc)(self.display, pixmap, 0, std::ptr::null_mut());
            (x.set_foreground)(self.display, gc, 0);
            (x.fill_rectangle)(self.display, pixmap, gc, 0, 0, w, h);
            (x.set_foreground)(self.display, gc, 1);
            (x.set_font)(self.display, gc, self.font);
            (x.draw_string)(self.display, pixmap, gc, -c_int::from(m.lbearing), c_int::from(m.ascent), &ch, 1);
            let image = (x.get_image)(self.display, pixmap, 0, 0, w, h, 1, 1); // XYPixmap
            if !image.is_null() {
                type GetPixel = unsafe extern "C" fn(*mut XImage, c_int, c_int) -> c_ulong;
                type Destroy = unsafe extern "C" fn(*mut XImage) -> c_int;
                let get: Option<GetPixel> = std::mem::transmute::<*mut c_void, Option<GetPixel>>((*image).funcs[2]);
                let destroy: Option<Destroy> = std::mem::transmute::<*mut c_void, Option<Destroy>>((*image).funcs[1]);
                if let Some(get) = get {
                    for row in 0..h {
                        // The image's top row is the bitmap's last.
                        let out = &mut bits[(h - 1 - row) as usize * stride..][..stride];
                        for col in 0..w {
                            if get(image, col as c_int, row as c_int) != 0 {
                                out[(col / 8) as usize] |= 0x80 >> (col % 8);
                            }
                        }
                    }
                }
                if let Some(destroy) = destroy {
                    destroy(image);
                }
            }
            (x.free_gc)(self.display, gc);
            (x.free_pixmap)(self.display, pixmap);
        }
        bits
    }
}

impl Drop for FontGlyphs {
    fn drop(&mut self) {
        if let Some(x) = xlib() {
            // SAFETY: XQueryFont's answer, freed once.
            unsafe { (x.free_font_info)(std::ptr::null_mut(), self.info, 1) };
        }
    }
}

/// Xlib's `XErrorEvent`, what the program's error handler is given.
#[repr(C)]
struct XErrorEvent {
    kind: c_int,
    display: *mut Display,
    resource: Xid,
    serial: c_ulong,
    error_code: u8,
    request_code: u8,
    minor_code: u8,
}

/// An X error handler.
type ErrorHandler = Option<unsafe extern "C" fn(*mut Display, *mut XErrorEvent) -> c_int>;

/// The Xlib functions gleval calls: the struct of their addresses, and its loader.
macro_rules! xlib {
    ($($field:ident = $name:literal: fn($($a:ty),*) -> $r:ty;)*) => {
        /// The Xlib functions, as the loader found them.
        struct Xlib {
            $($field: unsafe extern "C" fn($($a),*) -> $r,)*
        }

        /// Each function by name; `None` if one is missing.
        fn load(find: impl Fn(&CStr) -> Option<*mut c_void>) -> Option<Xlib> {
            Some(Xlib {
                $(
                    // SAFETY: the symbol is Xlib's function of that name, whose C signature
                    // the field's type spells.
                    $field: unsafe { std::mem::transmute::<*mut c_void, unsafe extern "C" fn($($a),*) -> $r>(find($name)?) },
                )*
            })
        }
    };
}

xlib! {
    get_geometry = c"XGetGeometry": fn(*mut Display, Xid, *mut Xid, *mut c_int, *mut c_int, *mut c_uint, *mut c_uint, *mut c_uint, *mut c_uint) -> c_int;
    create_gc = c"XCreateGC": fn(*mut Display, Xid, c_ulong, *mut c_void) -> *mut c_void;
    free_gc = c"XFreeGC": fn(*mut Display, *mut c_void) -> c_int;
    init_image = c"XInitImage": fn(*mut XImage) -> c_int;
    put_image = c"XPutImage": fn(*mut Display, Xid, *mut c_void, *mut XImage, c_int, c_int, c_int, c_int, c_uint, c_uint) -> c_int;
    flush = c"XFlush": fn(*mut Display) -> c_int;
    sync = c"XSync": fn(*mut Display, c_int) -> c_int;
    get_visual_info = c"XGetVisualInfo": fn(*mut Display, c_long, *mut XVisualInfo, *mut c_int) -> *mut XVisualInfo;
    default_screen = c"XDefaultScreen": fn(*mut Display) -> c_int;
    screen_count = c"XScreenCount": fn(*mut Display) -> c_int;
    free = c"XFree": fn(*mut c_void) -> c_int;
    query_extension = c"XQueryExtension": fn(*mut Display, *const c_char, *mut c_int, *mut c_int, *mut c_int) -> c_int;
    next_request = c"XNextRequest": fn(*mut Display) -> c_ulong;
    open_display = c"XOpenDisplay": fn(*const c_char) -> *mut Display;
    set_error_handler = c"XSetErrorHandler": fn(ErrorHandler) -> ErrorHandler;
    display_width = c"XDisplayWidth": fn(*mut Display, c_int) -> c_int;
    query_font = c"XQueryFont": fn(*mut Display, Xid) -> *mut XFontStruct;
    free_font_info = c"XFreeFontInfo": fn(*mut c_char, *mut XFontStruct, c_int) -> c_int;
    default_root_window = c"XDefaultRootWindow": fn(*mut Display) -> Xid;
    create_pixmap = c"XCreatePixmap": fn(*mut Display, Xid, c_uint, c_uint, c_uint) -> Xid;
    free_pixmap = c"XFreePixmap": fn(*mut Display, Xid) -> c_int;
    set_font = c"XSetFont": fn(*mut Display, *mut c_void, Xid) -> c_int;
    set_foreground = c"XSetForeground": fn(*mut Display, *mut c_void, c_ulong) -> c_int;
    fill_rectangle = c"XFillRectangle": fn(*mut Display, Xid, *mut c_void, c_int, c_int, c_uint, c_uint) -> c_int;
    draw_string = c"XDrawString": fn(*mut Display, Xid, *mut c_void, c_int, c_int, *const c_char, c_int) -> c_int;
    get_image = c"XGetImage": fn(*mut Display, Xid, c_int, c_int, c_uint, c_uint, c_ulong, c_int) -> *mut XImage;
    display_height = c"XDisplayHeight": fn(*mut Display, c_int) -> c_int;
}

/// Xlib, found in the process or loaded; `None` where there is none.
fn xlib() -> Option<&'static Xlib> {
    static XLIB: OnceLock<Option<Xlib>> = OnceLock::new();
    XLIB.get_or_init(|| {
        let loaded = dl::symbol(None, c"XOpenDisplay").map(|_| None).unwrap_or_else(|| dl::open(c"libX11.so.6"));
        load(|name| dl::symbol(loaded, name))
    })
    .as_ref()
}

/// A drawable's size and depth; `None` if it is not one (the X server's `BadDrawable` then
/// goes to the program's error handler, as for any Xlib call on a bad id).
pub fn geometry(display: *mut Display, drawable: Xid) -> Option<(u32, u32, u32)> {
    let x = xlib()?;
    if display.is_null() || drawable == 0 {
        return None;
    }
    let (mut root, mut px, mut py) = (0, 0, 0);
    let (mut w, mut h, mut border, mut depth) = (0, 0, 0, 0);
    // SAFETY: `display` is the program's open connection (its promise, as for Xlib); the
    // out-pointers are locals.
    let ok = unsafe {
        (x.get_geometry)(display, drawable, &mut root, &mut px, &mut py, &mut w, &mut h, &mut border, &mut depth)
    };
    (ok != 0).then_some((w, h, depth))
}

/// Puts an RGBA picture (rows top to bottom) into a drawable of `depth` 24 or 32 at its top
/// left corner, as a TrueColor ZPixmap of 32-bit pixels (0x00RRGGBB, the visuals gleval's
/// configs name). Other depths are not drawn.
pub fn put_rgba(display: *mut Display, drawable: Xid, depth: u32, width: u32, height: u32, rgba: &[u8]) {
    let Some(x) = xlib() else { return };
    if display.is_null() || !(depth == 24 || depth == 32) || rgba.len() < (width * height * 4) as usize {
        return;
    }
    // Xlib's LSBFirst 32-bit pixels 0xAARRGGBB are the bytes B, G, R, A.
    let mut data: Vec<u8> = Vec::with_capacity(rgba.len());
    for p in rgba.chunks_exact(4) {
        data.extend_from_slice(&[p[2], p[1], p[0], 0xff]);
    }
    let mut image = XImage {
        width: width as c_int,
        height: height as c_int,
        xoffset: 0,
        format: 2, // ZPixmap
        data: data.as_mut_ptr().cast(),
        byte_order: 0, // LSBFirst
        bitmap_unit: 32,
        bitmap_bit_order: 0,
        bitmap_pad: 32,
        depth: depth as c_int,
        bytes_per_line: (width * 4) as c_int,
        bits_per_pixel: 32,
        red_mask: 0xff0000,
        green_mask: 0xff00,
        blue_mask: 0xff,
        obdata: std::ptr::null_mut(),
        funcs: [std::ptr::null_mut(); 6],
    };
    // SAFETY: `image` describes `data`, which outlives the calls; XInitImage fills the
    // function table; the GC is made and freed here.
    unsafe {
        if (x.init_image)(&mut image) == 0 {
            return;
        }
        let gc = (x.create_gc)(display, drawable, 0, std::ptr::null_mut());
        if gc.is_null() {
            return;
        }
        (x.put_image)(display, drawable, gc, &mut image, 0, 0, 0, 0, width, height);
        (x.free_gc)(display, gc);
        (x.flush)(display);
    }
}

/// Waits until the server has handled every request sent (`glXWaitGL`'s and `glXWaitX`'s
/// part on the X side).
pub fn sync(display: *mut Display) {
    if let (Some(x), false) = (xlib(), display.is_null()) {
        // SAFETY: the program's open connection.
        unsafe { (x.sync)(display, 0) };
    }
}

/// The visuals of `screen` matching `visualid` (any for `None`), TrueColor of depth 24 only;
/// the list is Xlib's (freed with `XFree`), `None` if there is none.
pub fn visuals(display: *mut Display, screen: c_int, visualid: Option<c_ulong>) -> Option<(*mut XVisualInfo, usize)> {
    let x = xlib()?;
    if display.is_null() {
        return None;
    }
    // SAFETY: an all-zero XVisualInfo is a valid template (Xlib reads the fields the mask names).
    let mut template: XVisualInfo = unsafe { std::mem::zeroed() };
    template.screen = screen;
    template.depth = 24;
    template.class = 4; // TrueColor
    let mut mask = 0x2 | 0x4 | 0x8; // VisualScreenMask | VisualDepthMask | VisualClassMask
    if let Some(id) = visualid {
        template.visualid = id;
        mask |= 0x1; // VisualIDMask
    }
    let mut n = 0;
    // SAFETY: the program's open connection; `template` and `n` are locals.
    let list = unsafe { (x.get_visual_info)(display, mask, &mut template, &mut n) };
    (!list.is_null() && n > 0).then_some((list, n as usize))
}

/// Frees what Xlib handed out.
pub fn free(pointer: *mut c_void) {
    if let (Some(x), false) = (xlib(), pointer.is_null()) {
        // SAFETY: allocated by Xlib (the caller's promise).
        unsafe { (x.free)(pointer) };
    }
}

/// The display's default screen, and how many screens it has.
pub fn screens(display: *mut Display) -> Option<(c_int, c_int)> {
    let x = xlib()?;
    if display.is_null() {
        return None;
    }
    // SAFETY: the program's open connection.
    Some(unsafe { ((x.default_screen)(display), (x.screen_count)(display)) })
}

/// The default screen's size in pixels of the X server `DISPLAY` names, if there is one
/// (asked once; the connection stays open, as the program's own would).
pub fn default_screen_size() -> Option<(c_int, c_int)> {
    static SIZE: OnceLock<Option<(c_int, c_int)>> = OnceLock::new();
    *SIZE.get_or_init(|| {
        std::env::var_os("DISPLAY").filter(|d| !d.is_empty())?;
        let x = xlib()?;
        let display = open_display(None);
        if display.is_null() {
            return None;
        }
        // SAFETY: a connection just opened.
        let (screen, _) = screens(display)?;
        Some(unsafe { ((x.display_width)(display, screen), (x.display_height)(display, screen)) })
    })
}

/// Opens a connection to the X server `name` names (`DISPLAY` for `None`); NULL if none.
pub fn open_display(name: Option<&CStr>) -> *mut Display {
    let Some(x) = xlib() else { return std::ptr::null_mut() };
    // SAFETY: a NUL-terminated name or NULL, as XOpenDisplay takes.
    unsafe { (x.open_display)(name.map_or(std::ptr::null(), CStr::as_ptr)) }
}

/// The server's GLX extension: its major opcode and first error code, if it has one (gleval
/// draws on the client side and needs none, but reports GLX's errors with the server's codes).
pub fn glx_extension(display: *mut Display) -> Option<(u8, u8)> {
    let x = xlib()?;
    let (mut opcode, mut event, mut error) = (0, 0, 0);
    // SAFETY: the program's open connection; the name is NUL-terminated.
    let ok = unsafe { (x.query_extension)(display, c"GLX".as_ptr(), &mut opcode, &mut event, &mut error) };
    (ok != 0).then_some((opcode as u8, error as u8))
}

/// Reports an X protocol error to the program's error handler, as Mesa's `__glXSendError`
/// does for GLX's errors: `code` is the error's number (a core error, or the GLX extension's
/// first error plus GLX's code), `minor` the GLX request it answers. Xlib's default handler
/// prints the error and ends the program, as it does for Mesa's.
pub fn send_error(display: *mut Display, code: u8, resource: Xid, minor: u16) {
    let Some(x) = xlib() else { return };
    if display.is_null() {
        return;
    }
    let major = glx_extension(display).map_or(0, |(opcode, _)| opcode);
    // SAFETY: the program's open connection. The handler is read by setting the default
    // and putting it straight back (Xlib has no other way to read it); then it is called as
    // Xlib calls it, outside Xlib's display lock.
    unsafe {
        let serial = (x.next_request)(display).wrapping_sub(1);
        let handler = (x.set_error_handler)(None);
        (x.set_error_handler)(handler);
        let mut event = XErrorEvent {
            kind: 0,
            display,
            resource,
            serial,
            error_code: code,
            request_code: major,
            minor_code: minor as u8,
        };
        if let Some(handler) = handler {
            handler(display, &mut event);
        }
    }
}
