//! freeglut's font objects: the data symbols whose addresses are GLUT's font handles on Linux.
//!
//! freeglut's `GL/freeglut_std.h` (every platform but Windows) declares `extern void
//! *glutStrokeRoman;` ... `extern void *glutBitmapHelvetica18;` and defines
//! `GLUT_STROKE_ROMAN` as `((void *)&glutStrokeRoman)`: a program built against it passes the
//! address of a symbol libglut exports. gleval's own `GL/glut.h` gives the handles freeglut's
//! small numbers instead (its Windows values). So libgleval_c exports the nine objects, with
//! freeglut's names and size (one pointer), and a C font call accepts either form.
//!
//! A program that takes such an address in its own code is usually linked with a copy
//! relocation: the executable holds its own copy of the object, and every reference in the
//! process, the loader's resolution included, means that copy, not the library's. This crate's
//! code addresses its statics directly, so the handle is compared both with the static's own
//! address and with what the dynamic linker resolves the symbol's name to (`dlsym`), which is
//! the copy when there is one.

use gleval::glut::fonts::{
    GlutBitmapFont, GlutStrokeFont, GLUT_BITMAP_8_BY_13, GLUT_BITMAP_9_BY_15, GLUT_BITMAP_HELVETICA_10,
    GLUT_BITMAP_HELVETICA_12, GLUT_BITMAP_HELVETICA_18, GLUT_BITMAP_TIMES_ROMAN_10, GLUT_BITMAP_TIMES_ROMAN_24,
    GLUT_STROKE_MONO_ROMAN, GLUT_STROKE_ROMAN,
};
use std::ffi::{c_void, CStr};
use std::sync::OnceLock;

/// A font object, the size of freeglut's `void *`. It holds the font's number (freeglut's, as
/// gleval's `GL/glut.h` gives the handle), which keeps the nine objects distinct.
#[repr(transparent)]
pub struct FontObject(usize);

/// The font a handle names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Font {
    Bitmap(GlutBitmapFont),
    Stroke(GlutStrokeFont),
}

macro_rules! font_objects {
    ($($symbol:ident = $number:literal: $kind:ident($font:expr);)*) => {
        $(
            #[doc = concat!("freeglut's `", stringify!($symbol), "`: its address is a font handle.")]
            #[no_mangle]
            #[allow(non_upper_case_globals)]
            pub static $symbol: FontObject = FontObject($number);
        )*
        /// Each object: its symbol's name, the object, the font.
        static OBJECTS: &[(&CStr, &FontObject, Font)] = &[
            $((
                match CStr::from_bytes_with_nul(concat!(stringify!($symbol), "\0").as_bytes()) {
                    Ok(name) => name,
                    Err(_) => panic!("a symbol name has no NUL inside"),
                },
                &$symbol,
                Font::$kind($font),
            )),*
        ];
    };
}

font_objects! {
    glutStrokeRoman = 0: Stroke(GLUT_STROKE_ROMAN);
    glutStrokeMonoRoman = 1: Stroke(GLUT_STROKE_MONO_ROMAN);
    glutBitmap9By15 = 2: Bitmap(GLUT_BITMAP_9_BY_15);
    glutBitmap8By13 = 3: Bitmap(GLUT_BITMAP_8_BY_13);
    glutBitmapTimesRoman10 = 4: Bitmap(GLUT_BITMAP_TIMES_ROMAN_10);
    glutBitmapTimesRoman24 = 5: Bitmap(GLUT_BITMAP_TIMES_ROMAN_24);
    glutBitmapHelvetica10 = 6: Bitmap(GLUT_BITMAP_HELVETICA_10);
    glutBitmapHelvetica12 = 7: Bitmap(GLUT_BITMAP_HELVETICA_12);
    glutBitmapHelvetica18 = 8: Bitmap(GLUT_BITMAP_HELVETICA_18);
}

/// The font a C handle names: freeglut's number for it (gleval's `GL/glut.h`), or the address
/// of its font object (freeglut's `GL/freeglut_std.h` on Linux). Any other pointer is no font.
pub(super) fn font(handle: *const c_void) -> Option<Font> {
    let address = handle as usize;
    let by_number = GlutBitmapFont::from_id(address)
        .map(Font::Bitmap)
        .or_else(|| GlutStrokeFont::from_id(address).map(Font::Stroke));
    by_number.or_else(|| {
        let resolved = resolved();
        OBJECTS
            .iter()
            .zip(resolved)
            .find(|((_, object, _), resolved)| {
                std::ptr::addr_eq(*object, handle) || resolved.is_some_and(|r| r == address)
            })
            .map(|((_, _, font), _)| *font)
    })
}

/// Where the dynamic linker resolves each object's name (a program's copy, or ours), looked
/// up once.
fn resolved() -> &'static [Option<usize>] {
    static RESOLVED: OnceLock<Vec<Option<usize>>> = OnceLock::new();
    RESOLVED.get_or_init(|| OBJECTS.iter().map(|(name, _, _)| lookup(name)).collect())
}

#[cfg(target_os = "linux")]
fn lookup(name: &CStr) -> Option<usize> {
    extern "C" {
        fn dlsym(handle: *mut c_void, symbol: *const std::ffi::c_char) -> *mut c_void;
    }
    /// glibc's `RTLD_DEFAULT`: the global scope, the executable first.
    const RTLD_DEFAULT: *mut c_void = std::ptr::null_mut();
    // SAFETY: `name` is NUL-terminated; dlsym only reads it and the loader's tables.
    let address = unsafe { dlsym(RTLD_DEFAULT, name.as_ptr()) };
    (!address.is_null()).then_some(address as usize)
}

#[cfg(not(target_os = "linux"))]
fn lookup(_name: &CStr) -> Option<usize> {
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_and_object_addresses_name_the_same_fonts() {
        for (_, object, expected) in OBJECTS {
            let by_address = font(std::ptr::from_ref(*object).cast());
            assert_eq!(by_address, Some(*expected));
            assert_eq!(font(object.0 as *const c_void), Some(*expected));
        }
        assert_eq!(OBJECTS.len(), 9);
        assert_eq!(font(9 as *const c_void), None);
        assert_eq!(font(std::ptr::from_ref(&OBJECTS).cast()), None);
    }

    #[test]
    fn objects_are_the_size_of_freeglut_s() {
        // `extern void *glutStrokeRoman;`: a copy relocation copies this many bytes.
        assert_eq!(std::mem::size_of::<FontObject>(), std::mem::size_of::<*const c_void>());
    }
}
