//! `GL/gl.h`: the GL 1.x entry points `Gl` implements, one file per area.

/// An entry point under its GL 1.5 name and its ARB name, with the same body (buffer objects
/// and occlusion queries).
macro_rules! with_arb {
    ($(#[$m:meta])* unsafe fn $name:ident / $arb:ident($($a:ident: $t:ty),*) $(-> $r:ty)? $body:block) => {
        entry! { $(#[$m])* unsafe fn $name($($a: $t),*) $(-> $r)? $body }
        entry! {
            #[doc = concat!("`", stringify!($arb), "` (the GL 1.5 extension's name): `", stringify!($name), "`.")]
            unsafe fn $arb($($a: $t),*) $(-> $r)? $body
        }
    };
    ($(#[$m:meta])* fn $name:ident / $arb:ident($($a:ident: $t:ty),*) $(-> $r:ty)? $body:block) => {
        entry! { $(#[$m])* fn $name($($a: $t),*) $(-> $r)? $body }
        entry! {
            #[doc = concat!("`", stringify!($arb), "` (the GL 1.5 extension's name): `", stringify!($name), "`.")]
            fn $arb($($a: $t),*) $(-> $r)? $body
        }
    };
}

mod arrays;
mod buffers;
mod compressed;
mod eval;
mod feedback;
mod fragment;
mod fragments;
mod imaging;
mod immediate;
mod lighting;
mod lists;
mod matrix;
mod multitexture;
mod occlusion;
mod pixel_buffers;
mod pixel_transfer;
mod pixels;
mod points;
mod queries;
mod raster_modes;
mod read_pixels;
mod select;
mod state;
mod texgen;
mod texture;
mod variants;
