//! The framebuffer configurations gleval offers through GLX and EGL: what its rasteriser
//! draws into, RGBA8 with a 24-bit depth buffer, single- or double-buffered, with or
//! without an 8-bit stencil buffer and a 16-bit accumulation buffer (`gl::BufferConfig`).
//! No multisampling, no stereo, no auxiliary buffers, no colour index.
//!
//! Each configuration is one static value, so a `GLXFBConfig` or `EGLConfig` is a pointer to
//! it and a handle that is not one is told by its address.

use gleval::gl::BufferConfig;

/// One configuration.
#[derive(Debug, PartialEq, Eq)]
pub struct Config {
    /// `GLX_FBCONFIG_ID` / `EGL_CONFIG_ID`: 1 up.
    pub id: i32,
    pub double: bool,
    pub stencil: i32,
    pub accum: i32,
}

/// Bits of each colour channel, and of the depth buffer.
pub const CHANNEL_BITS: i32 = 8;
pub const DEPTH_BITS: i32 = 24;

const fn config(id: i32, double: bool, stencil: i32, accum: i32) -> Config {
    Config { id, double, stencil, accum }
}

/// Every configuration, in the order `glXGetFBConfigs` lists them.
pub static CONFIGS: [Config; 8] = [
    config(1, true, 8, 16),
    config(2, true, 8, 0),
    config(3, true, 0, 16),
    config(4, true, 0, 0),
    config(5, false, 8, 16),
    config(6, false, 8, 0),
    config(7, false, 0, 16),
    config(8, false, 0, 0),
];

impl Config {
    /// The configuration a handle points at, if it is one of [`CONFIGS`].
    pub fn from_handle<T>(handle: *const T) -> Option<&'static Config> {
        CONFIGS.iter().find(|c| std::ptr::eq((*c as *const Config).cast(), handle))
    }

    /// The handle of this configuration.
    pub fn handle<T>(&'static self) -> *mut T {
        (self as *const Config).cast_mut().cast()
    }

    /// Its index in [`CONFIGS`].
    pub fn index(&self) -> usize {
        (self.id - 1) as usize
    }

    /// What a context made with it has (`Gl::set_buffer_config`).
    pub fn buffers(&self) -> BufferConfig {
        BufferConfig { stencil_bits: self.stencil as u8, accum_bits: self.accum as u8, double: self.double }
    }
}

/// How a requested value is matched (GLX 1.4 table 3.4, EGL 1.5 table 3.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Criterion {
    /// The configuration's value is at least the one asked for.
    AtLeast,
    /// It equals it.
    Exact,
    /// It has every bit the mask asks for.
    Mask,
}

/// Whether a configuration's `value` meets `wanted` under `criterion`.
pub fn meets(criterion: Criterion, value: i32, wanted: i32) -> bool {
    match criterion {
        Criterion::AtLeast => value >= wanted,
        Criterion::Exact => value == wanted,
        Criterion::Mask => value & wanted == wanted,
    }
}

/// The order both GLX and EGL sort matching configurations in, for what gleval's
/// configurations differ in: fewer stencil bits first, then more accumulation bits (GLX 1.4
/// §3.3.3; Mesa's `fbconfig_compare`), single-buffered before double-buffered where the
/// request left that open.
pub fn sort(list: &mut [&'static Config]) {
    list.sort_by_key(|c| (c.double, c.stencil, -c.accum, c.id));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn handles_round_trip_and_strangers_are_refused() {
        for c in &CONFIGS {
            assert_eq!(Config::from_handle(c.handle::<u8>()), Some(c));
            assert_eq!(CONFIGS[c.index()].id, c.id);
        }
        let stranger = 7u64;
        assert_eq!(Config::from_handle(&stranger), None);
        assert_eq!(Config::from_handle(std::ptr::null::<u8>()), None);
    }

    #[test]
    fn sorting_prefers_no_stencil_then_accumulation() {
        let mut all: Vec<&Config> = CONFIGS.iter().collect();
        sort(&mut all);
        let order: Vec<i32> = all.iter().map(|c| c.id).collect();
        assert_eq!(order, [7, 8, 5, 6, 3, 4, 1, 2]);
        assert!(meets(Criterion::AtLeast, 8, 1) && !meets(Criterion::AtLeast, 0, 1));
        assert!(meets(Criterion::Mask, 0b101, 0b100) && !meets(Criterion::Mask, 0b001, 0b100));
    }
}
