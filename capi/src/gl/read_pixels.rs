//! `glReadPixels`: `Gl` checks the call and packs the pixels; the frame recorded so far is
//! drawn for it by the CPU rasteriser, or with `GLEVAL_RASTERIZER=wgpu` by a wgpu renderer
//! this thread keeps (made at the first read).

use crate::context::with_gl;
use crate::memory::array_mut;
use gleval::gl::types::*;
use gleval::gl::Frame;
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

/// The window's RGBA8 pixels (rows top to bottom) with `frame` drawn; `None` if it cannot be
/// drawn (the message is printed).
fn draw(frame: &Frame, width: i32, height: i32) -> Option<Vec<u8>> {
    if Rasterizer::from_env() == Rasterizer::Cpu {
        return Some(soft::render_frame(frame, width.max(1) as u32, height.max(1) as u32).pixels);
    }
    let mut renderer = renderer()?.try_borrow_mut().ok()?;
    let image = renderer.render_frame(frame, width.max(1) as u32, height.max(1) as u32);
    image.map_err(|e| eprintln!("gleval: glReadPixels: {e}")).ok().map(|i| i.pixels)
}

entry! {
    /// `glReadPixels`: `Gl::read_pixels`, writing `Gl::packed_image_len` bytes at `pixels`.
    unsafe fn glReadPixels(
        x: GLint, y: GLint, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, pixels: *mut c_void,
    ) {
        // An OSMesa context reads its buffer, brought up to date first (outside `with_gl`: the
        // flush takes the context's frame).
        let open: GLboolean = with_gl(|gl| gl.inside_begin_end().into());
        let osmesa = if open != 0 { None } else { crate::osmesa::flush_current() };
        with_gl(|gl| {
            let len = gl.packed_image_len(width, height, format, type_).unwrap_or(0);
            let out = unsafe { array_mut(pixels.cast::<u8>(), len) };
            let (w, h) = (gl.width(), gl.height());
            let draw = |frame: &Frame| match &osmesa {
                Some(image) => Some(image.pixels.clone()),
                None => draw(frame, w, h),
            };
            gl.read_pixels((x, y), (width, height), format, type_, draw, out)
        })
    }
}
