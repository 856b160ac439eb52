//! The current context, per thread as GL's is.
//!
//! Outside GLUT's main loop the current context is the one `glutCreateWindow` made (owned
//! here); inside it, each C callback runs with the `&mut Gl` that `App` hands the Rust
//! closure made current for exactly the callback's duration ([`enter`]). So at any moment
//! one `&mut Gl` is live: the one a C call reaches through [`with_gl`].

use crate::boundary::Fallback;
use gleval::gl::Gl;
use std::cell::{Cell, RefCell};

thread_local! {
    static CURRENT: Cell<*mut Gl> = const { Cell::new(std::ptr::null_mut()) };
    static OWNED: RefCell<Option<Box<Gl>>> = const { RefCell::new(None) };
}

/// Runs `f` on the current context; without one, does nothing and returns the fallback value,
/// as GL calls do with no context current.
pub fn with_gl<R: Fallback>(f: impl FnOnce(&mut Gl) -> R) -> R {
    let current = CURRENT.with(Cell::get);
    if current.is_null() {
        return R::fallback();
    }
    // SAFETY: `current` is either the owned context (alive until `take_owned`) or the
    // `&mut Gl` of the callback running now (`enter`), and no other reference to it is used
    // while this call runs: the caller of `enter` waits for the C callback to return.
    f(unsafe { &mut *current })
}

/// Makes `gl` current while `f` runs (a C callback), then restores what was current.
pub fn enter<R>(gl: &mut Gl, f: impl FnOnce() -> R) -> R {
    struct Restore(*mut Gl);
    impl Drop for Restore {
        fn drop(&mut self) {
            CURRENT.with(|c| c.set(self.0));
        }
    }
    let _restore = Restore(CURRENT.with(|c| c.replace(gl)));
    f()
}

/// Makes `gl` this thread's own current context (`glutCreateWindow`, `OSMesaMakeCurrent`),
/// dropping any context made before.
pub fn install(gl: Gl) {
    let mut boxed = Box::new(gl);
    CURRENT.with(|c| c.set(&mut *boxed));
    OWNED.with(|o| *o.borrow_mut() = Some(boxed));
}

/// Makes a context owned elsewhere (an OSMesa context) current on this thread.
pub fn make_current(gl: &mut Gl) {
    CURRENT.with(|c| c.set(gl));
}

/// Nothing is current any more if `gl` was (it is being destroyed).
pub fn release_if_current(gl: &mut Gl) {
    let gl: *mut Gl = gl;
    CURRENT.with(|c| {
        if c.get() == gl {
            c.set(std::ptr::null_mut());
        }
    });
}

/// Takes the owned context out (`glutMainLoop` hands it to `App`); nothing is current after.
pub fn take_owned() -> Option<Box<Gl>> {
    CURRENT.with(|c| c.set(std::ptr::null_mut()));
    OWNED.with(|o| o.borrow_mut().take())
}

/// Nothing is current any more (GLUT's loop is over and its windows are gone).
pub fn clear_current() {
    CURRENT.with(|c| c.set(std::ptr::null_mut()));
}

/// Whether `gl` is the current context.
pub fn is_current(gl: &Gl) -> bool {
    std::ptr::eq(CURRENT.with(Cell::get), gl)
}

/// The current context's address (null if none), to compare with.
pub fn current_ptr() -> *const Gl {
    CURRENT.with(Cell::get)
}

/// Whether a context is current.
pub fn has_current() -> bool {
    !CURRENT.with(Cell::get).is_null()
}

/// `GL_OUT_OF_MEMORY` on the current context, after a caught panic.
pub(crate) fn out_of_memory() {
    // The context may be mid-call when the panic hit; only the error flag is touched, through
    // the public call that sets it.
    with_gl(|gl| gl.set_out_of_memory());
}
