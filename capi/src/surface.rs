//! Drawables: what a window-system context (GLX, EGL) draws into. A drawable's buffers are
//! the drawable's, not the context's (GLX 1.4 §2.2): each is a CPU canvas that keeps its
//! picture between frames, made when a context is first bound to the drawable and sized as
//! the drawable is. What the current context recorded is drawn onto its drawable's canvas at
//! `glFlush`, `glFinish`, `glReadPixels`, a swap, or when another context or drawable is
//! bound; a swap (or a flush of a single-buffered drawable) then puts the canvas's front
//! buffer into the X drawable, at its current size (a resize is seen at the next bind or
//! swap, as Mesa's software drivers see it). Pbuffers and EGL's surfaceless surfaces have a
//! canvas and no output.
//!
//! Drawables are kept per thread, as the contexts current in that thread draw into them.

use crate::x11::{self, Display, Xid};
use gleval::gl::{Frame, Gl, WindowImage};
use gleval::render::soft::Canvas;
use std::cell::{Cell, RefCell};
use std::collections::HashMap;

/// A drawable's name: its display (an X `Display *` or an `EGLDisplay`) and its id there.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Key {
    pub display: usize,
    pub drawable: u64,
}

/// Where a drawable's picture goes.
#[derive(Clone, Copy, Debug)]
pub enum Output {
    /// Nowhere (a pbuffer, an EGL pbuffer or surfaceless surface): it is read back only.
    None,
    /// An X window or pixmap of the program's connection.
    X { display: *mut Display, drawable: Xid },
}

/// One drawable's buffers.
struct Surface {
    canvas: Canvas,
    size: (u32, u32),
    /// The X drawable's depth (24 or 32 are drawn).
    depth: u32,
    output: Output,
    /// The colour buffer last read (the back one?) with the depth buffer, since the canvas
    /// was last drawn on (programs read the window one pixel at a time, as piglit's probes
    /// do: one copy serves them all).
    read: Option<(bool, WindowImage)>,
}

/// What is bound on this thread: the drawable and the context drawing into it.
#[derive(Clone, Copy)]
struct Binding {
    key: Key,
    gl: *const Gl,
}

thread_local! {
    static SURFACES: RefCell<HashMap<Key, Surface>> = RefCell::new(HashMap::new());
    static BOUND: Cell<Option<Binding>> = const { Cell::new(None) };
}

/// Runs `f` on this thread's drawables; nothing (the default answer) once the thread's
/// storage is gone (a program's exit handlers may still release their contexts then).
fn surfaces<R: Default>(f: impl FnOnce(&RefCell<HashMap<Key, Surface>>) -> R) -> R {
    SURFACES.try_with(f).unwrap_or_default()
}

/// As [`surfaces`], for the swap intervals.
fn pacing<R: Default>(f: impl FnOnce(&RefCell<HashMap<Key, (u32, Option<std::time::Instant>)>>) -> R) -> R {
    PACING.try_with(f).unwrap_or_default()
}

impl Output {
    /// The drawable's size now, and its depth (`None`: the X drawable is gone).
    fn geometry(&self, fixed: (u32, u32)) -> Option<(u32, u32, u32)> {
        match *self {
            Output::None => Some((fixed.0, fixed.1, 24)),
            Output::X { display, drawable } => x11::geometry(display, drawable),
        }
    }
}

/// Makes a drawable known (a GLX window, pixmap or pbuffer, an EGL surface) with its size
/// for one without output; an existing one keeps its canvas.
pub fn declare(key: Key, output: Output, size: (u32, u32)) {
    surfaces(|s| {
        s.borrow_mut().entry(key).or_insert_with(|| Surface {
            canvas: Canvas::new(size.0, size.1),
            size: (size.0.max(1), size.1.max(1)),
            depth: 24,
            output,
            read: None,
        });
    });
}

/// Forgets a drawable (destroyed); unbound first if it is bound.
pub fn forget(key: Key) {
    if BOUND.with(Cell::get).is_some_and(|b| b.key == key) {
        BOUND.with(|b| b.set(None));
    }
    surfaces(|s| s.borrow_mut().remove(&key));
    pacing(|p| p.borrow_mut().remove(&key));
}

/// A drawable's size, if it is known.
pub fn size(key: Key) -> Option<(u32, u32)> {
    surfaces(|s| s.borrow().get(&key).map(|s| s.size))
}

/// Binds `gl` to the drawable `key` (declared before): what was bound is flushed first, the
/// canvas follows the drawable's size, and `gl` learns it; the first time a context is bound
/// its viewport and scissor box become the drawable's, as GL sets them. `false` if the X
/// drawable is gone.
pub fn bind(key: Key, gl: &mut Gl, first: bool) -> bool {
    flush_current();
    let Some((w, h)) = surfaces(|s| {
        let mut s = s.borrow_mut();
        let surface = s.get_mut(&key)?;
        follow_size(surface);
        Some(surface.size)
    }) else {
        return false;
    };
    gl.set_window_size(w as i32, h as i32);
    if first {
        gl.viewport(0, 0, w as i32, h as i32);
        gl.scissor(0, 0, w as i32, h as i32);
    }
    gl.set_window_reader(read_bound);
    BOUND.with(|b| b.set(Some(Binding { key, gl })));
    true
}

/// Nothing is bound on this thread any more (after its frame is flushed).
pub fn unbind() {
    flush_current();
    BOUND.with(|b| b.set(None));
}

/// The drawable bound on this thread, if the context bound to it is still the current one.
pub fn bound() -> Option<Key> {
    BOUND.with(Cell::get).filter(|b| current_is(b.gl)).map(|b| b.key)
}

fn current_is(gl: *const Gl) -> bool {
    std::ptr::eq(crate::context::current_ptr(), gl)
}

/// A new canvas if the drawable changed size (its picture is not kept, as a resized
/// window's buffers are not in Mesa's software drivers).
fn follow_size(surface: &mut Surface) {
    let Some((w, h, depth)) = surface.output.geometry(surface.size) else { return };
    let (w, h) = (w.max(1), h.max(1));
    surface.depth = depth;
    if (w, h) != surface.size {
        surface.size = (w, h);
        surface.canvas = Canvas::new(w, h);
        surface.read = None;
    }
}

/// Draws what the current context recorded onto its drawable's canvas, and returns the
/// canvas's picture and depth; `None` when no drawable is bound to the current context. An
/// OSMesa context current instead flushes into its buffer.
pub fn flush_current() -> Option<WindowImage> {
    if let Some(image) = crate::osmesa::flush_current() {
        return Some(image);
    }
    let key = bound()?;
    let mut taken = None;
    crate::context::with_gl(|gl| taken = Some((gl.take_frame(), gl.reads_back_buffer())));
    let (frame, back) = taken?;
    let image = surfaces(|s| {
        let mut s = s.borrow_mut();
        let surface = s.get_mut(&key)?;
        if !frame.commands.is_empty() {
            surface.canvas.draw_frame(&frame);
            surface.read = None;
        }
        if surface.read.as_ref().is_none_or(|(b, _)| *b != back) {
            surface.read = Some((back, surface.canvas.buffer_image(back)));
        }
        surface.read.as_ref().map(|(_, image)| image.clone())
    });
    crate::context::with_gl(|gl| gl.recycle_frame(frame));
    image
}

/// The bound drawable's stencil buffer (rows top to bottom), brought up to date first.
pub fn current_stencil() -> Option<Vec<u8>> {
    if let Some(stencil) = crate::osmesa::current_stencil() {
        return Some(stencil);
    }
    flush_current()?;
    let key = bound()?;
    surfaces(|s| s.borrow().get(&key).map(|s| s.canvas.stencil().to_vec()))
}

/// Presents the bound drawable: with `swap`, the back buffer becomes the front one first
/// (a double-buffered context; nothing for a single-buffered one). The front buffer goes to
/// the drawable's output, and the canvas then follows the drawable's size.
pub fn present_current(swap: bool) {
    let Some(key) = bound() else { return };
    if swap {
        crate::context::with_gl(Gl::record_swap_buffers);
    }
    flush_current();
    present(key);
    let size = surfaces(|s| {
        let mut s = s.borrow_mut();
        let surface = s.get_mut(&key)?;
        follow_size(surface);
        Some(surface.size)
    });
    if let Some((w, h)) = size {
        crate::context::with_gl(|gl| gl.set_window_size(w as i32, h as i32));
    }
}

/// `glFlush` and `glFinish`: what was drawn lands on the drawable's canvas, and a
/// single-buffered drawable shows it (a double-buffered one shows its front buffer only at a
/// swap, or when the context draws into the front buffer).
pub fn flush_and_show() {
    let front = crate::context::with_gl(|gl| {
        let mut draw = [0];
        gl.get_integerv(gleval::gl::consts::GL_DRAW_BUFFER, &mut draw);
        u8::from(!gl.buffer_config().double || draw[0] as u32 != gleval::gl::consts::GL_BACK)
    });
    flush_current();
    if front == 1 {
        if let Some(key) = bound() {
            present(key);
        }
    }
}

/// Presents a drawable that no context of this thread is bound to (`glXSwapBuffers` on a
/// drawable other than the current one's: what it holds goes out).
pub fn present(key: Key) {
    surfaces(|s| {
        let s = s.borrow();
        let Some(surface) = s.get(&key) else { return };
        let image = surface.canvas.image();
        if let Output::X { display, drawable } = surface.output {
            x11::put_rgba(display, drawable, surface.depth, image.width, image.height, &image.pixels);
        }
        crate::launcher::frame_presented(&image);
    });
}

thread_local! {
    /// Each drawable's swap interval, and when it was last presented.
    static PACING: RefCell<HashMap<Key, (u32, Option<std::time::Instant>)>> = RefCell::new(HashMap::new());
}

/// A video frame, for the swap interval: gleval presents without a display's vertical
/// blank, so it paces swaps at 60 Hz where an interval is set.
const FRAME: std::time::Duration = std::time::Duration::from_nanos(16_666_667);

/// Sets a drawable's swap interval (0, the default: swaps are not paced, as this machine's
/// Mesa does not pace them without a display's vertical blank).
pub fn set_interval(key: Key, interval: u32) {
    pacing(|p| p.borrow_mut().entry(key).or_default().0 = interval);
}

/// A drawable's swap interval.
pub fn interval(key: Key) -> u32 {
    pacing(|p| p.borrow().get(&key).map_or(0, |p| p.0))
}

/// Waits out the drawable's swap interval since its last swap, then notes this one.
pub fn pace(key: Key) {
    pacing(|p| {
        let mut p = p.borrow_mut();
        let entry = p.entry(key).or_default();
        if let (n @ 1.., Some(last)) = *entry {
            let due = last + FRAME * n;
            if let Some(wait) = due.checked_duration_since(std::time::Instant::now()) {
                std::thread::sleep(wait);
            }
        }
        entry.1 = Some(std::time::Instant::now());
    });
}

/// The bound drawable's canvas with `frame` (recorded since the last flush) drawn over a
/// copy of it: what a context reads mid-frame (`glCopyPixels`, `glCopyTexImage2D`).
fn read_bound(frame: &Frame, _width: u32, _height: u32) -> Option<WindowImage> {
    let key = BOUND.with(Cell::get)?.key;
    surfaces(|s| {
        let s = s.borrow();
        let mut canvas = s.get(&key)?.canvas.clone();
        canvas.draw_frame(frame);
        Some(canvas.window_image())
    })
}
