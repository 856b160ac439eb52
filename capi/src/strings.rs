//! The strings GL and GLU hand C (`glGetString`, `gluErrorString`): NUL-terminated and alive
//! for the whole program, as C expects of a `const GLubyte *` it never frees.

use std::collections::HashMap;
use std::ffi::{c_char, CString};
use std::sync::{Mutex, OnceLock};

/// A C copy of `s`, made once and kept forever.
pub fn static_c_string(s: &'static str) -> *const c_char {
    static MADE: OnceLock<Mutex<HashMap<&'static str, &'static std::ffi::CStr>>> = OnceLock::new();
    let mut made = MADE.get_or_init(Default::default).lock().unwrap_or_else(|e| e.into_inner());
    let c = made.entry(s).or_insert_with(|| {
        let owned = CString::new(s.replace('\0', "")).unwrap_or_default();
        Box::leak(owned.into_boxed_c_str())
    });
    c.as_ptr()
}
