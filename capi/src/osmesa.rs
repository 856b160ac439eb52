//! A stand-in for OSMesa's context calls (`GL/osmesa.h`), so that programs written for
//! off-screen Mesa run on gleval unchanged: a context is a `Gl` made current on this thread,
//! and what it draws lands in the caller's buffer, as with OSMesa. At `glFinish`, `glFlush` and
//! `glReadPixels` the frame recorded since the last of them is drawn by the CPU rasteriser onto
//! the context's canvas (which keeps the buffer's picture between frames), and the canvas is
//! copied into the buffer: RGBA, BGRA, ARGB, RGB or BGR bytes (`GL_UNSIGNED_BYTE`), the first
//! row the bottom one (OSMesa's `OSMESA_Y_UP`). Other buffer types are left untouched.

use crate::context::{is_current, make_current, release_if_current};
use gleval::gl::consts::*;
use gleval::gl::types::*;
use gleval::gl::{BufferConfig, Frame, Gl, WindowImage};
use gleval::render::soft::Canvas;
use gleval::render::Image;
use std::cell::Cell;
use std::ffi::c_void;

const OSMESA_BGRA: GLenum = 0x1;
const OSMESA_ARGB: GLenum = 0x2;
const OSMESA_BGR: GLenum = 0x4;

/// What an `OSMesaContext` points at.
pub struct OSMesaContext {
    gl: Gl,
    /// The pixel format given at creation (`OSMESA_RGBA`, ...).
    format: GLenum,
    /// The buffer of the last `OSMesaMakeCurrent`, if it is one gleval writes.
    target: Option<Target>,
}

/// The caller's buffer and the canvas behind it.
struct Target {
    buffer: *mut u8,
    width: usize,
    height: usize,
    canvas: Canvas,
}

thread_local! {
    /// The OSMesa context current on this thread, if the current context is one.
    static CURRENT: Cell<*mut OSMesaContext> = const { Cell::new(std::ptr::null_mut()) };
}

/// Bytes a pixel and where R, G, B and A go in it (`None`: not stored).
fn layout(format: GLenum) -> Option<(usize, [Option<usize>; 4])> {
    match format {
        GL_RGBA => Some((4, [Some(0), Some(1), Some(2), Some(3)])),
        OSMESA_BGRA => Some((4, [Some(2), Some(1), Some(0), Some(3)])),
        OSMESA_ARGB => Some((4, [Some(1), Some(2), Some(3), Some(0)])),
        GL_RGB => Some((3, [Some(0), Some(1), Some(2), None])),
        OSMESA_BGR => Some((3, [Some(2), Some(1), Some(0), None])),
        _ => None,
    }
}

impl Target {
    /// Copies `image` (the canvas's picture) into the buffer.
    fn write_buffer(&self, format: GLenum, image: &Image) {
        let Some((size, places)) = layout(format) else { return };
        // SAFETY: as in `read_buffer`; no other reference to the buffer is alive during a GL
        // call (the caller waits for it).
        let buffer = unsafe { std::slice::from_raw_parts_mut(self.buffer, self.width * self.height * size) };
        for (row, source) in image.pixels.chunks_exact(self.width * 4).enumerate() {
            let out = &mut buffer[(self.height - 1 - row) * self.width * size..][..self.width * size];
            for (o, s) in out.chunks_exact_mut(size).zip(source.chunks_exact(4)) {
                for (channel, place) in places.iter().enumerate() {
                    if let Some(p) = place {
                        o[*p] = s[channel];
                    }
                }
            }
        }
    }
}

/// Draws what the current OSMesa context recorded since its last flush into its buffer, and
/// returns the buffer's picture and depth; `None` when no OSMesa context with a buffer is
/// current.
pub(crate) fn flush_current() -> Option<WindowImage> {
    let ctx = CURRENT.with(Cell::get);
    // SAFETY: set by OSMesaMakeCurrent from a live context and cleared when it is destroyed;
    // no `&mut Gl` of the context is alive between GL calls, and this runs between them.
    let ctx = unsafe { ctx.as_mut() }?;
    // A GLUT window's context made current since (`glutCreateWindow`) is not this one.
    if !is_current(&ctx.gl) {
        return None;
    }
    let format = ctx.format;
    ctx.target.as_ref()?;
    // Taken before the target is borrowed: taking a frame with occlusion queries in it reads
    // the window through `read_canvas`, which looks at the target.
    let frame = ctx.gl.take_frame();
    let target = ctx.target.as_mut()?;
    target.canvas.draw_frame(&frame);
    ctx.gl.recycle_frame(frame);
    let window = target.canvas.window_image();
    let image = Image { width: window.width, height: window.height, pixels: window.color.clone() };
    target.write_buffer(format, &image);
    Some(window)
}

/// The reader of an OSMesa context's window mid-frame (`glCopyTexImage`): the current context's
/// canvas with `frame` (recorded since the last flush) drawn over a copy of it.
fn read_canvas(frame: &Frame, _width: u32, _height: u32) -> Option<WindowImage> {
    let ctx = CURRENT.with(Cell::get);
    if ctx.is_null() {
        return None;
    }
    // SAFETY: as in `flush_current`; only the `target` field is touched, while the context's
    // `Gl` (another field) is the one calling.
    let target = unsafe { &*std::ptr::addr_of!((*ctx).target) }.as_ref()?;
    let mut canvas = target.canvas.clone();
    canvas.draw_frame(frame);
    Some(canvas.window_image())
}

/// The current OSMesa context's stencil buffer (rows top to bottom), brought up to date first;
/// `None` when no OSMesa context with a buffer is current.
pub(crate) fn current_stencil() -> Option<Vec<u8>> {
    flush_current()?;
    let ctx = CURRENT.with(Cell::get);
    // SAFETY: as in `flush_current`, which just found it current.
    let ctx = unsafe { ctx.as_ref() }?;
    Some(ctx.target.as_ref()?.canvas.stencil().to_vec())
}

entry! {
    /// `OSMesaCreateContextExt`: a context in GL's initial state, single-buffered, with an
    /// 8-bit stencil buffer if `stencil_bits` > 0 and a 16-bit accumulation buffer if
    /// `accum_bits` > 0, as Mesa makes them (gleval's frames always have a depth buffer).
    fn OSMesaCreateContextExt(
        format: GLenum, _depth_bits: GLint, stencil_bits: GLint, accum_bits: GLint, _sharelist: *mut OSMesaContext,
    ) -> *mut OSMesaContext {
        let mut gl = Gl::new(1, 1);
        gl.set_window_reader(read_canvas);
        let stencil_bits = if stencil_bits > 0 { 8 } else { 0 };
        let accum_bits = if accum_bits > 0 { 16 } else { 0 };
        gl.set_buffer_config(BufferConfig { stencil_bits, accum_bits, double: false });
        Box::into_raw(Box::new(OSMesaContext { gl, format, target: None }))
    }
}

entry! {
    /// `OSMesaCreateContext`.
    fn OSMesaCreateContext(format: GLenum, sharelist: *mut OSMesaContext) -> *mut OSMesaContext {
        OSMesaCreateContextExt(format, 16, 0, 0, sharelist)
    }
}

entry! {
    /// `OSMesaMakeCurrent`: makes `ctx` current for a `width` × `height` buffer of `type`
    /// pixels; the first time, the viewport and the scissor box become the whole buffer, as GL
    /// sets them. A new
    /// buffer's framebuffer starts transparent black, and each flush copies it into the
    /// buffer. Returns
    /// `GL_TRUE`, or `GL_FALSE` for a NULL context or buffer or a size that is not positive.
    unsafe fn OSMesaMakeCurrent(
        ctx: *mut OSMesaContext, buffer: *mut c_void, type_: GLenum, width: GLsizei, height: GLsizei,
    ) -> GLboolean {
        // SAFETY: made by OSMesaCreateContext and not destroyed (the caller's promise).
        let Some(context) = (unsafe { ctx.as_mut() }) else { return 0 };
        if width <= 0 || height <= 0 || buffer.is_null() {
            return 0;
        }
        // What another context drew goes to its buffer before this one becomes current.
        flush_current();
        let first = context.gl.width() == 1 && context.gl.height() == 1;
        context.gl.set_window_size(width, height);
        if first {
            // GL's initial viewport and scissor box are the drawable's, set when the context is
            // first made current.
            context.gl.viewport(0, 0, width, height);
            context.gl.scissor(0, 0, width, height);
        }
        let (w, h) = (width as usize, height as usize);
        // Mesa's framebuffer starts transparent black whatever the buffer held, is copied
        // whole into the buffer at a flush, and stays the context's while it draws into the
        // same buffer (measured: capi/tests/osmesa.c).
        let buffer: *mut u8 = buffer.cast();
        let same = context.target.as_ref().is_some_and(|t| t.buffer == buffer && (t.width, t.height) == (w, h));
        if !same {
            context.target = (type_ == GL_UNSIGNED_BYTE && layout(context.format).is_some())
                .then(|| Target { buffer, width: w, height: h, canvas: Canvas::new(width as u32, height as u32) });
        }
        make_current(&mut context.gl);
        CURRENT.with(|c| c.set(ctx));
        1
    }
}

entry! {
    /// `OSMesaDestroyContext`: frees the context (no longer current if it was).
    unsafe fn OSMesaDestroyContext(ctx: *mut OSMesaContext) {
        if !ctx.is_null() {
            CURRENT.with(|c| {
                if c.get() == ctx {
                    c.set(std::ptr::null_mut());
                }
            });
            // SAFETY: made by OSMesaCreateContext (the caller's promise).
            let mut owned = unsafe { Box::from_raw(ctx) };
            release_if_current(&mut owned.gl);
        }
    }
}
