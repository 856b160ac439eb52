//! `glReadPixels`: `Gl` checks the call and packs the pixels; the frame recorded so far is
//! drawn for it by the CPU rasteriser, or with `GLEVAL_RASTERIZER=wgpu` by a wgpu renderer
//! this thread keeps (made at the first read).

use super::pixel_buffers::pack_into;
use crate::context::with_gl;
use gleval::gl::consts::{GL_DEPTH_STENCIL, GL_STENCIL_INDEX};
use gleval::gl::types::*;
use gleval::gl::{Frame, WindowImage};
#[allow(unused_imports)]
use gleval::render::Image;
use gleval::render::{soft, Rasterizer, Renderer};
use std::cell::{Cell, RefCell};
use std::ffi::c_void;

thread_local! {
    /// Made at the first read and kept for the program's life, never dropped: wgpu's drop
    /// needs thread-locals of its own that are gone while the process exits.
    static RENDERER: Cell<Option<&'static RefCell<Renderer>>> = const { Cell::new(None) };
}

/// This thread's renderer; `None` if none can be made (the message is printed).
fn renderer() -> Option<&'static RefCell<Renderer>> {
    if let Some(renderer) = RENDERER.with(Cell::get) {
        return Some(renderer);
    }
    // No false "error" lines from Vulkan's device-select layer without a desktop session.
    gleval::render::quiet_device_select();
    let made = Renderer::new().map_err(|e| eprintln!("gleval: glReadPixels: {e}")).ok()?;
    let kept: &'static RefCell<Renderer> = Box::leak(Box::new(RefCell::new(made)));
    RENDERER.with(|c| c.set(Some(kept)));
    Some(kept)
}

/// The window's buffers with `frame` drawn; `None` if it cannot be drawn (the message is
/// printed).
fn draw(frame: &Frame, width: i32, height: i32) -> Option<WindowImage> {
    let (width, height) = (width.max(1) as u32, height.max(1) as u32);
    if Rasterizer::from_env() == Rasterizer::Cpu {
        return Some(soft::render_window(frame, width, height));
    }
    let mut renderer = renderer()?.try_borrow_mut().ok()?;
    let image = renderer.render_window(frame, width, height, true);
    image.map_err(|e| eprintln!("gleval: glReadPixels: {e}")).ok()
}

/// The window's stencil buffer (rows top to bottom) with `frame` drawn by the CPU rasteriser.
fn draw_stencil(frame: &Frame, width: i32, height: i32) -> Vec<u8> {
    let mut canvas = soft::Canvas::new(width.max(1) as u32, height.max(1) as u32);
    canvas.draw_frame(frame);
    canvas.stencil().to_vec()
}

/// `glReadPixels` of `GL_STENCIL_INDEX`: `Gl::read_stencil_pixels` on the drawable's (or OSMesa buffer's)
/// stencil or the frame's.
///
/// # Safety
/// `pixels` is NULL or points at the bytes `Gl::packed_image_len` gives (the caller's promise,
/// as for `glReadPixels`).
unsafe fn read_stencil(x: GLint, y: GLint, width: GLsizei, height: GLsizei, type_: GLenum, pixels: *mut c_void) {
    let open: GLboolean = with_gl(|gl| gl.inside_begin_end().into());
    let drawn = if open != 0 { None } else { crate::surface::current_stencil() };
    with_gl(|gl| {
        let len = gl.packed_image_len(width, height, GL_STENCIL_INDEX, type_).unwrap_or(0);
        let (w, h) = (gl.width(), gl.height());
        let draw = |frame: &Frame| Some(drawn.unwrap_or_else(|| draw_stencil(frame, w, h)));
        unsafe {
            pack_into(gl, pixels.cast::<u8>(), len, |gl, out| {
                gl.read_stencil_pixels((x, y), (width, height), type_, draw, out)
            })
        }
    })
}

/// `glReadPixels` of `GL_DEPTH_STENCIL`: `Gl::read_depth_stencil_pixels` on the drawable's (or
/// OSMesa buffer's) depth and stencil, or the frame's.
///
/// # Safety
/// As [`read_stencil`].
unsafe fn read_depth_stencil(x: GLint, y: GLint, width: GLsizei, height: GLsizei, type_: GLenum, pixels: *mut c_void) {
    let open: GLboolean = with_gl(|gl| gl.inside_begin_end().into());
    let drawn = if open != 0 { None } else { crate::surface::flush_current().zip(crate::surface::current_stencil()) };
    with_gl(|gl| {
        let len = gl.packed_image_len(width, height, GL_DEPTH_STENCIL, type_).unwrap_or(0);
        let (w, h) = (gl.width(), gl.height());
        let draw = |frame: &Frame| match drawn {
            Some(buffers) => Some(buffers),
            None => {
                let mut canvas = soft::Canvas::new(w.max(1) as u32, h.max(1) as u32);
                canvas.draw_frame(frame);
                Some((canvas.window_image(), canvas.stencil().to_vec()))
            }
        };
        unsafe {
            pack_into(gl, pixels.cast::<u8>(), len, |gl, out| {
                gl.read_depth_stencil_pixels((x, y), (width, height), type_, draw, out)
            })
        }
    })
}

entry! {
    /// `glReadPixels`: `Gl::read_pixels`, writing `Gl::packed_image_len` bytes at `pixels`.
    unsafe fn glReadPixels(
        x: GLint, y: GLint, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, pixels: *mut c_void,
    ) {
        if format == GL_STENCIL_INDEX {
            return unsafe { read_stencil(x, y, width, height, type_, pixels) };
        }
        if format == GL_DEPTH_STENCIL {
            return unsafe { read_depth_stencil(x, y, width, height, type_, pixels) };
        }
        // A drawable (or OSMesa buffer) is read, brought up to date first (outside `with_gl`: the
        // flush takes the context's frame).
        let open: GLboolean = with_gl(|gl| gl.inside_begin_end().into());
        let drawn = if open != 0 { None } else { crate::surface::flush_current() };
        with_gl(|gl| {
            let len = gl.packed_image_len(width, height, format, type_).unwrap_or(0);
                let (w, h) = (gl.width(), gl.height());
            let draw = move |frame: &Frame| match drawn {
                Some(image) => Some(image),
                None => draw(frame, w, h),
            };
            unsafe { pack_into(gl, pixels.cast::<u8>(), len, |gl, out| gl.read_pixels((x, y), (width, height), format, type_, draw, out)) }
        })
    }
}
