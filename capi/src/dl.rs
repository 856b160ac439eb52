//! The dynamic loader, for what gleval reaches at run time rather than at link time: Xlib
//! (only programs that hand gleval an X `Display *` need it, so `libgleval_c` does not link
//! it) and gleval's own exports (`glXGetProcAddress` and its kin answer with them).

use std::ffi::{c_char, c_int, c_void, CStr, CString};

extern "C" {
    fn dlopen(filename: *const c_char, flags: c_int) -> *mut c_void;
    fn dlsym(handle: *mut c_void, symbol: *const c_char) -> *mut c_void;
    fn dladdr(address: *const c_void, info: *mut DlInfo) -> c_int;
}

const RTLD_LAZY: c_int = 0x1;
const RTLD_NOLOAD: c_int = 0x4;
/// glibc's `RTLD_DEFAULT`: the global scope, as the program's own calls see it.
const RTLD_DEFAULT: *mut c_void = std::ptr::null_mut();

#[repr(C)]
struct DlInfo {
    fname: *const c_char,
    fbase: *mut c_void,
    sname: *const c_char,
    saddr: *mut c_void,
}

/// A handle of a library, loaded if it is not yet (`None` if it cannot be).
pub fn open(name: &CStr) -> Option<*mut c_void> {
    // SAFETY: dlopen takes a NUL-terminated name and returns NULL on failure.
    let handle = unsafe { dlopen(name.as_ptr(), RTLD_LAZY) };
    (!handle.is_null()).then_some(handle)
}

/// The address of `name` in `handle` (the global scope for `None`), if it is defined.
pub fn symbol(handle: Option<*mut c_void>, name: &CStr) -> Option<*mut c_void> {
    // SAFETY: as dlopen; a handle from `open` or `object_of` stays valid (nothing is ever
    // closed).
    let address = unsafe { dlsym(handle.unwrap_or(RTLD_DEFAULT), name.as_ptr()) };
    (!address.is_null()).then_some(address)
}

/// The object (shared library, or the program gleval is linked into) an address lies in: its
/// load address and the handle that finds its symbols.
fn object_of(address: *const c_void) -> Option<(*mut c_void, *mut c_void)> {
    let mut info = DlInfo {
        fname: std::ptr::null(),
        fbase: std::ptr::null_mut(),
        sname: std::ptr::null(),
        saddr: std::ptr::null_mut(),
    };
    // SAFETY: dladdr fills `info` for an address inside a loaded object; the file name it
    // gives lives as long as the object.
    if unsafe { dladdr(address, &mut info) } == 0 || info.fname.is_null() {
        return None;
    }
    // SAFETY: `fname` is NUL-terminated (dladdr's contract); RTLD_NOLOAD only finds an object
    // already loaded. The program itself has an empty name: its handle is the global scope's.
    let handle =
        if unsafe { *info.fname } == 0 { RTLD_DEFAULT } else { unsafe { dlopen(info.fname, RTLD_LAZY | RTLD_NOLOAD) } };
    Some((info.fbase, handle))
}

/// gleval's own entry point called `name`, if it exports one: what GetProcAddress answers
/// (`glXGetProcAddress`, `eglGetProcAddress`, `OSMesaGetProcAddress`, `glutGetProcAddress`).
/// A symbol is handed out only if it lies in gleval's own object, so nothing of the C
/// library (`glob`) or of another GL is ever taken for gleval's.
pub fn own_entry_point(name: &[u8]) -> Option<*mut c_void> {
    let name = CString::new(name).ok()?;
    thread_local! {
        static OWN: Option<(*mut c_void, *mut c_void)> = object_of(object_of as *const c_void);
    }
    let (base, handle) = OWN.with(|own| *own)?;
    let address = symbol(Some(handle), &name)?;
    (object_of(address)?.0 == base).then_some(address)
}
