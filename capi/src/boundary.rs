//! The panic boundary: no Rust panic ever unwinds into C.
//!
//! Every entry point's body runs under [`guard`] (the `entry!` macro writes that for it, as
//! hyper's `ffi_fn!` does). A caught panic is reported on stderr with the function's name, sets
//! `GL_OUT_OF_MEMORY` on the current context (GL's answer when an implementation cannot carry
//! out a call) and the function returns its [`Fallback`] value; C never sees an unwind.

use std::panic::{catch_unwind, AssertUnwindSafe};

/// What an entry point returns when it could not run: no current context, or a caught panic
/// (GL returns 0, `GL_FALSE` or NULL when it has no context).
pub trait Fallback {
    /// The value C receives.
    fn fallback() -> Self;
}

macro_rules! zero_fallback {
    ($($t:ty),*) => { $(impl Fallback for $t { fn fallback() -> Self { Default::default() } })* };
}
zero_fallback!((), u8, u32, i32, u64, f32, f64, usize, String);

impl<T> Fallback for *const T {
    fn fallback() -> Self {
        std::ptr::null()
    }
}

impl<T> Fallback for *mut T {
    fn fallback() -> Self {
        std::ptr::null_mut()
    }
}

/// Runs an entry point's body; a panic becomes `GL_OUT_OF_MEMORY` and the fallback value.
/// With `GLEVAL_DEBUG` set, a GL error the call raised is named on stderr with the call, as
/// `MESA_DEBUG` has Mesa do (only the outermost entry point of a nested call reports).
pub fn guard<R: Fallback>(name: &str, body: impl FnOnce() -> R) -> R {
    let traced = debug_errors() && DEPTH.with(|d| d.replace(d.get() + 1)) == 0;
    let before = if traced { pending_error() } else { 0 };
    let value = match catch_unwind(AssertUnwindSafe(body)) {
        Ok(value) => value,
        Err(_) => {
            eprintln!("gleval: {name} failed inside the library (a bug): GL_OUT_OF_MEMORY is set");
            crate::context::out_of_memory();
            R::fallback()
        }
    };
    if debug_errors() {
        DEPTH.with(|d| d.set(d.get().saturating_sub(1)));
    }
    if traced && before == 0 {
        let after = pending_error();
        if after != 0 {
            eprintln!("gleval: {name}: {}", gleval::gl::error_name(after));
        }
    }
    value
}

thread_local! {
    /// How many entry points are running on this thread (one calling another: the EXT names).
    static DEPTH: std::cell::Cell<u32> = const { std::cell::Cell::new(0) };
}

/// Whether `GLEVAL_DEBUG` is set (read once).
fn debug_errors() -> bool {
    static DEBUG: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *DEBUG.get_or_init(|| std::env::var_os("GLEVAL_DEBUG").is_some_and(|v| !v.is_empty()))
}

/// The current context's error flag, left as it is (0 without a context).
fn pending_error() -> u32 {
    crate::context::with_gl(|gl| gl.pending_error())
}

/// An `extern "C"` entry point: `#[no_mangle]`, its body under [`guard`]. The `unsafe fn`
/// form is for functions that read or write through C pointers: their safety contract is
/// GL's, that each pointer addresses as much memory as the call's arguments say GL uses.
macro_rules! entry {
    ($(#[$m:meta])* fn $name:ident($($a:ident: $t:ty),* $(,)?) $(-> $r:ty)? $body:block) => {
        $(#[$m])*
        #[no_mangle]
        pub extern "C" fn $name($($a: $t),*) $(-> $r)? {
            $crate::boundary::guard(stringify!($name), move || $body)
        }
    };
    ($(#[$m:meta])* unsafe fn $name:ident($($a:ident: $t:ty),* $(,)?) $(-> $r:ty)? $body:block) => {
        $(#[$m])*
        ///
        /// # Safety
        ///
        /// GL's contract: each pointer is NULL or addresses the memory the call's own
        /// arguments say it reads or writes.
        #[no_mangle]
        pub unsafe extern "C" fn $name($($a: $t),*) $(-> $r)? {
            $crate::boundary::guard(stringify!($name), move || $body)
        }
    };
}

/// Entry points that pass their scalar arguments straight to the `Gl` method of the same name
/// (`glVertex3f(x, y, z)` → `gl.vertex3f(x, y, z)`), however many GL's signature has.
macro_rules! forward {
    ($($name:ident($($a:ident: $t:ty),* $(,)?) $(-> $r:ty)? => $method:ident;)*) => {
        $(entry! {
            #[doc = concat!("`", stringify!($name), "`: `Gl::", stringify!($method), "`.")]
            #[allow(clippy::too_many_arguments)]
            fn $name($($a: $t),*) $(-> $r)? { $crate::context::with_gl(|gl| gl.$method($($a),*)) }
        })*
    };
}

/// Entry points taking one fixed-size array (`glVertex3fv(v)` reads 3 floats).
macro_rules! vector {
    ($($name:ident($t:ty; $n:expr) => $method:ident;)*) => {
        $(entry! {
            #[doc = concat!("`", stringify!($name), "`: `Gl::", stringify!($method), "`.")]
            unsafe fn $name(v: *const $t) {
                $crate::context::with_gl(|gl| gl.$method(unsafe { $crate::memory::array(v, Some($n)) }))
            }
        })*
    };
}
