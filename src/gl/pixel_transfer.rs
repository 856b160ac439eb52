//! Pixel transfer (GL 1.1 spec §3.6.3 "Pixel Transfer Operations", §4.3.2; Mesa `main/pixel.c`):
//! `glPixelTransfer` (colour scale and bias, depth scale and bias, index shift and offset, the
//! `GL_MAP_COLOR` and `GL_MAP_STENCIL` switches), `glPixelMap`/`glGetPixelMap` (the ten lookup
//! tables) and `glPixelZoom`'s factors, with their `glGet` names.
//!
//! The transfer applies wherever GL moves pixels: `glDrawPixels`, `glReadPixels`,
//! `glCopyPixels` and `glCopyTexImage`. A draw or copy captures it by value when it is recorded
//! ([`ColorTransfer`], [`DepthTransfer`]), so that the picture does not depend on later calls.
//!
//! `GL_PIXEL_MODE_BIT` saves the transfer values and the zoom, not the maps (Mesa's
//! `gl_pixel_attrib` holds no maps; measured: a map set between push and pop stays).

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{int_limit, put_enum, put_flag, row, Kind, StateVar};
use super::types::*;
use super::Gl;
use std::sync::Arc;

/// Mesa's `MAX_PIXEL_MAP_TABLE`: the longest map `glPixelMap` takes.
pub const MAX_PIXEL_MAP_TABLE: usize = 256;

/// The colour part of the transfer, as a draw, read or copy applies it: each component scaled
/// and biased, then, with `GL_MAP_COLOR`, clamped to [0, 1] and looked up in its map
/// (`GL_PIXEL_MAP_R_TO_R` ... `A_TO_A`) at the nearest entry (Mesa `_mesa_map_rgba`, which
/// rounds half to even).
#[derive(Clone, Debug, PartialEq)]
pub struct ColorTransfer {
    /// `GL_RED_SCALE` ... `GL_ALPHA_SCALE`.
    pub scale: [f32; 4],
    /// `GL_RED_BIAS` ... `GL_ALPHA_BIAS`.
    pub bias: [f32; 4],
    /// The R, G, B and A maps when `GL_MAP_COLOR` is on (an empty map leaves its component
    /// as it is: Mesa's draws map red and green only).
    pub maps: Option<[Vec<f32>; 4]>,
    /// How a component picks its map entry: `false`, the entry nearest c·(n − 1) (reads,
    /// Mesa `_mesa_map_rgba`); `true`, as Mesa's drawing fragment program samples its
    /// 256-texel map texture: entry ⌊⌊c·256⌋·n / 256⌋ (draws and copies, measured: a 4-entry
    /// map steps at 0.25, 0.5 and 0.75).
    pub texture_lookup: bool,
}

impl ColorTransfer {
    /// One pixel through the transfer (not clamped after scale and bias without maps: the
    /// caller clamps where the colour is stored, as GL does).
    #[must_use]
    pub fn apply(&self, c: [f32; 4]) -> [f32; 4] {
        let scaled: [f32; 4] = std::array::from_fn(|k| c[k] * self.scale[k] + self.bias[k]);
        match &self.maps {
            None => scaled,
            Some(maps) => std::array::from_fn(|k| look_up(&maps[k], scaled[k], self.texture_lookup)),
        }
    }
}

/// `map`'s entry for `value` clamped to [0, 1] (see [`ColorTransfer::texture_lookup`]); an
/// empty map gives `value` back.
fn look_up(map: &[f32], value: f32, texture_lookup: bool) -> f32 {
    let Some(last) = map.len().checked_sub(1) else { return value };
    let c = value.clamp(0.0, 1.0);
    let at = if texture_lookup {
        let texel = ((c * 256.0).floor() as usize).min(255);
        texel * map.len() / 256
    } else {
        (c * last as f32).round_ties_even() as usize
    };
    map[at.min(last)]
}

/// The depth part of the transfer: d·scale + bias, clamped to [0, 1] (Mesa
/// `_mesa_scale_and_bias_depth`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthTransfer {
    /// `GL_DEPTH_SCALE`.
    pub scale: f32,
    /// `GL_DEPTH_BIAS`.
    pub bias: f32,
}

impl DepthTransfer {
    /// One depth value through the transfer.
    #[must_use]
    pub fn apply(&self, d: f32) -> f32 {
        (d * self.scale + self.bias).clamp(0.0, 1.0)
    }
}

/// What `GL_PIXEL_MODE_BIT` saves: the transfer values, the zoom and the read buffer (Mesa
/// `gl_pixel_attrib`, with `ReadBuffer` of its `gl_framebuffer`); the maps aside.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PixelMode {
    pub zoom: [f32; 2],
    scale: [f32; 4],
    bias: [f32; 4],
    depth: DepthTransfer,
    index_shift: GLint,
    index_offset: GLint,
    map_color: bool,
    map_stencil: bool,
    /// `glReadBuffer`: the name given (see `draw_buffer.rs`).
    pub read_buffer: GLenum,
}

impl Default for PixelMode {
    fn default() -> Self {
        Self {
            zoom: [1.0; 2],
            scale: [1.0; 4],
            bias: [0.0; 4],
            depth: DepthTransfer { scale: 1.0, bias: 0.0 },
            index_shift: 0,
            index_offset: 0,
            map_color: false,
            map_stencil: false,
            read_buffer: GL_FRONT,
        }
    }
}

/// What `glPushAttrib` keeps of the pixel area (the groups are picked when it is restored).
pub(crate) type PixelAttrib = (PixelMode, super::color_index::ColorIndex);

/// The pixel transfer state: the mode group and the ten maps (each of 1 entry, 0, at first).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PixelState {
    pub mode: PixelMode,
    /// Indexed by `map - GL_PIXEL_MAP_I_TO_I` (I_TO_I, S_TO_S, I_TO_R, G, B, A, R_TO_R, G, B, A).
    maps: [Vec<f32>; 10],
}

impl Default for PixelState {
    fn default() -> Self {
        Self { mode: PixelMode::default(), maps: std::array::from_fn(|_| vec![0.0]) }
    }
}

/// The index of a map name, `None` for another enum.
fn map_index(map: GLenum) -> Option<usize> {
    (GL_PIXEL_MAP_I_TO_I..=GL_PIXEL_MAP_A_TO_A).contains(&map).then(|| (map - GL_PIXEL_MAP_I_TO_I) as usize)
}

/// Mesa's `FLOAT_TO_UINT`: x·(2³² − 1) in doubles, converted as x86 converts to a 64-bit integer,
/// keeping its low 32 bits (measured: −2.5 reads back as 2147483651).
fn float_to_uint(x: f32) -> GLuint {
    let v = f64::from(x) * 4_294_967_295.0;
    if v.is_finite() && v.abs() < 9.2e18 {
        v as i64 as GLuint
    } else {
        0
    }
}

/// Mesa's `CLAMPED_FLOAT_TO_USHORT`: clamped to [0, 1], times 65535 in floats, rounded half to even.
fn clamped_float_to_ushort(x: f32) -> GLushort {
    (x.clamp(0.0, 1.0) * 65535.0).round_ties_even() as GLushort
}

/// A pixel-mode call as a display list holds it.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum PixelTransferCall {
    /// `glPixelZoom`.
    Zoom(GLfloat, GLfloat),
    /// `glPixelTransfer*` (stored as the float call).
    Transfer(GLenum, GLfloat),
    /// `glPixelMap*`: map, size, and the values (as floats) copied at compile time.
    Map(GLenum, GLsizei, Vec<GLfloat>),
    /// `glReadBuffer`.
    ReadBuffer(GLenum),
}

impl Gl {
    /// Replays a listed pixel-mode call.
    pub(crate) fn replay_pixel_transfer_call(&mut self, call: &PixelTransferCall) {
        match call {
            PixelTransferCall::Zoom(x, y) => self.pixel_zoom(*x, *y),
            PixelTransferCall::Transfer(pname, param) => self.pixel_transferf(*pname, *param),
            PixelTransferCall::Map(map, size, values) => self.pixel_mapfv(*map, *size, values),
            PixelTransferCall::ReadBuffer(mode) => self.read_buffer(*mode),
        }
    }

    /// `glPixelZoom`: the factors `glDrawPixels` and `glCopyPixels` scale pixels by (any value,
    /// negative ones mirror, 0 draws nothing). Inside `begin`/`end` → `GL_INVALID_OPERATION`.
    /// Compiled into display lists.
    pub fn pixel_zoom(&mut self, xfactor: GLfloat, yfactor: GLfloat) {
        if self.compiled_state_call(|| ListCommand::PixelTransfer(PixelTransferCall::Zoom(xfactor, yfactor))) {
            return;
        }
        self.server.pixel_state.mode.zoom = [xfactor, yfactor];
    }

    /// `glPixelTransferf`: `GL_MAP_COLOR` and `GL_MAP_STENCIL` (on when not 0), `GL_INDEX_SHIFT`
    /// and `GL_INDEX_OFFSET` (truncated to integers, as Mesa's cast), the colour and depth
    /// scales and biases. Another name → `GL_INVALID_ENUM`. Compiled into display lists.
    pub fn pixel_transferf(&mut self, pname: GLenum, param: GLfloat) {
        if self.compiled_state_call(|| ListCommand::PixelTransfer(PixelTransferCall::Transfer(pname, param))) {
            return;
        }
        let mode = &mut self.server.pixel_state.mode;
        match pname {
            GL_MAP_COLOR => mode.map_color = param != 0.0,
            GL_MAP_STENCIL => mode.map_stencil = param != 0.0,
            GL_INDEX_SHIFT => mode.index_shift = param as GLint,
            GL_INDEX_OFFSET => mode.index_offset = param as GLint,
            GL_DEPTH_SCALE => mode.depth.scale = param,
            GL_DEPTH_BIAS => mode.depth.bias = param,
            _ => match scale_or_bias(pname) {
                Some((false, k)) => mode.scale[k] = param,
                Some((true, k)) => mode.bias[k] = param,
                None => self.set_error(GL_INVALID_ENUM),
            },
        }
    }

    /// `glPixelTransferi`: as [`Gl::pixel_transferf`] with the value converted to a float.
    pub fn pixel_transferi(&mut self, pname: GLenum, param: GLint) {
        self.pixel_transferf(pname, param as GLfloat);
    }

    /// `glPixelMapfv`: sets map `map` to the first `mapsize` values. Errors, in Mesa's order: a
    /// size outside 1..=256, or not a power of two for `GL_PIXEL_MAP_S_TO_S` ...
    /// `GL_PIXEL_MAP_I_TO_A` (Mesa's range, which leaves `I_TO_I` out), or `values` shorter than
    /// `mapsize` → `GL_INVALID_VALUE`; an unknown map → `GL_INVALID_ENUM`. `S_TO_S` rounds to
    /// integers, `I_TO_I` keeps the values, the others clamp to [0, 1]. Compiled into lists.
    pub fn pixel_mapfv(&mut self, map: GLenum, mapsize: GLsizei, values: &[GLfloat]) {
        let kept = || values[..values.len().min(mapsize.clamp(0, MAX_PIXEL_MAP_TABLE as i32) as usize)].to_vec();
        if self.compiled(|| ListCommand::PixelTransfer(PixelTransferCall::Map(map, mapsize, kept())))
            || self.reject_inside_begin_end()
        {
            return;
        }
        let Some(size) = Self::pixel_map_len(mapsize) else { return self.set_error(GL_INVALID_VALUE) };
        let power_of_two_needed = (GL_PIXEL_MAP_S_TO_S..=GL_PIXEL_MAP_I_TO_A).contains(&map);
        if power_of_two_needed && !size.is_power_of_two() {
            return self.set_error(GL_INVALID_VALUE);
        }
        let Some(values) = values.get(..size) else { return self.set_error(GL_INVALID_VALUE) };
        let Some(index) = map_index(map) else { return self.set_error(GL_INVALID_ENUM) };
        self.server.pixel_state.maps[index] = match map {
            GL_PIXEL_MAP_S_TO_S => values.iter().map(|v| v.round()).collect(),
            GL_PIXEL_MAP_I_TO_I => values.to_vec(),
            _ => values.iter().map(|v| v.clamp(0.0, 1.0)).collect(),
        };
    }

    /// Values `glPixelMap*` reads: `mapsize` when GL takes that size (1 to
    /// `GL_MAX_PIXEL_MAP_TABLE`), `None` when it reads none.
    #[must_use]
    pub fn pixel_map_len(mapsize: GLsizei) -> Option<usize> {
        usize::try_from(mapsize).ok().filter(|n| (1..=MAX_PIXEL_MAP_TABLE).contains(n))
    }

    /// `glPixelMapuiv`: as [`Gl::pixel_mapfv`]; the index maps (`I_TO_I`, `S_TO_S`) take the
    /// integers, the others map [0, 2³² − 1] onto [0, 1] (Mesa `UINT_TO_FLOAT`).
    pub fn pixel_mapuiv(&mut self, map: GLenum, mapsize: GLsizei, values: &[GLuint]) {
        let raw = matches!(map, GL_PIXEL_MAP_I_TO_I | GL_PIXEL_MAP_S_TO_S);
        let floats = values.iter().map(|&u| if raw { u as f32 } else { (f64::from(u) / 4_294_967_295.0) as f32 });
        self.pixel_mapfv(map, mapsize, &floats.collect::<Vec<_>>());
    }

    /// `glPixelMapusv`: as [`Gl::pixel_mapuiv`] with [0, 65535] mapped onto [0, 1].
    pub fn pixel_mapusv(&mut self, map: GLenum, mapsize: GLsizei, values: &[GLushort]) {
        let raw = matches!(map, GL_PIXEL_MAP_I_TO_I | GL_PIXEL_MAP_S_TO_S);
        let floats = values.iter().map(|&u| if raw { f32::from(u) } else { f32::from(u) / 65535.0 });
        self.pixel_mapfv(map, mapsize, &floats.collect::<Vec<_>>());
    }

    /// `glGetPixelMapfv`: the map's values into `values` (`GL_PIXEL_MAP_*_SIZE` of them). An
    /// unknown map → `GL_INVALID_ENUM`; `values` shorter than the map → `GL_INVALID_VALUE`.
    /// Executed at once, not compiled.
    pub fn get_pixel_mapfv(&mut self, map: GLenum, values: &mut [GLfloat]) {
        self.get_pixel_map(map, values, |_, v| v);
    }

    /// `glGetPixelMapuiv`: as [`Gl::get_pixel_mapfv`]; `S_TO_S` gives its floats' bits (Mesa
    /// copies the float array as integers: 2 reads back as 1073741824), the others Mesa's
    /// `FLOAT_TO_UINT`.
    pub fn get_pixel_mapuiv(&mut self, map: GLenum, values: &mut [GLuint]) {
        self.get_pixel_map(
            map,
            values,
            |map, v| if map == GL_PIXEL_MAP_S_TO_S { v.to_bits() } else { float_to_uint(v) },
        );
    }

    /// `glGetPixelMapusv`: as [`Gl::get_pixel_mapfv`]; the index maps clamped to [0, 65535] and
    /// truncated, the others Mesa's `CLAMPED_FLOAT_TO_USHORT`.
    pub fn get_pixel_mapusv(&mut self, map: GLenum, values: &mut [GLushort]) {
        self.get_pixel_map(map, values, |map, v| match map {
            GL_PIXEL_MAP_I_TO_I | GL_PIXEL_MAP_S_TO_S => v.clamp(0.0, 65535.0) as GLushort,
            _ => clamped_float_to_ushort(v),
        });
    }

    fn get_pixel_map<T>(&mut self, map: GLenum, out: &mut [T], convert: impl Fn(GLenum, f32) -> T) {
        if self.reject_inside_begin_end() {
            return;
        }
        let Some(index) = map_index(map) else { return self.set_error(GL_INVALID_ENUM) };
        let values = &self.server.pixel_state.maps[index];
        let Some(out) = out.get_mut(..values.len()) else { return self.set_error(GL_INVALID_VALUE) };
        for (o, &v) in out.iter_mut().zip(values) {
            *o = convert(map, v);
        }
    }

    /// How many values `glGetPixelMap*(map)` writes (0 for an unknown map): what a C binding
    /// hands [`Gl::get_pixel_mapfv`] as the slice's length.
    #[must_use]
    pub fn pixel_map_size(&self, map: GLenum) -> usize {
        map_index(map).map_or(0, |i| self.server.pixel_state.maps[i].len())
    }

    /// The colour transfer a draw, read or copy made now applies; `None` when it changes
    /// nothing (Mesa's `_ImageTransferState` without its colour bits).
    pub(crate) fn color_transfer(&self) -> Option<Arc<ColorTransfer>> {
        let mode = &self.server.pixel_state.mode;
        let identity = mode.scale == [1.0; 4] && mode.bias == [0.0; 4];
        if identity && !mode.map_color {
            return None;
        }
        let maps = mode.map_color.then(|| std::array::from_fn(|k| self.server.pixel_state.maps[6 + k].clone()));
        Some(Arc::new(ColorTransfer { scale: mode.scale, bias: mode.bias, maps, texture_lookup: false }))
    }

    /// The colour transfer `glDrawPixels` and `glCopyPixels` apply: Mesa 22 draws through a
    /// fragment program that looks the maps up in a texture
    /// ([`ColorTransfer::texture_lookup`]) and maps red and green only (measured: with
    /// inverting maps on all four components, a drawn or copied (64, 64, 64, 64) becomes
    /// (255, 255, 64, 64), where `glReadPixels` maps all four). Scale and bias apply to all four.
    pub(crate) fn draw_color_transfer(&self) -> Option<Arc<ColorTransfer>> {
        let mut transfer = self.color_transfer()?;
        let t = Arc::make_mut(&mut transfer);
        t.texture_lookup = true;
        if let Some(maps) = &mut t.maps {
            maps[2].clear();
            maps[3].clear();
        }
        Some(transfer)
    }

    /// What reading a stencil index goes through: `GL_INDEX_SHIFT`, `GL_INDEX_OFFSET` and,
    /// with `GL_MAP_STENCIL` on, the `S_TO_S` map.
    pub(crate) fn stencil_transfer_params(&self) -> (GLint, GLint, Option<&[f32]>) {
        let mode = &self.server.pixel_state.mode;
        let map = mode.map_stencil.then(|| &self.server.pixel_state.maps[1][..]);
        (mode.index_shift, mode.index_offset, map)
    }

    /// The depth transfer in force.
    pub(crate) fn depth_transfer(&self) -> DepthTransfer {
        self.server.pixel_state.mode.depth
    }

    /// `glPixelZoom`'s factors.
    pub(crate) fn zoom(&self) -> [f32; 2] {
        self.server.pixel_state.mode.zoom
    }

    /// How a `GL_COLOR_INDEX` pixel of `glDrawPixels` becomes RGBA in an RGBA context: through
    /// the `I_TO_R` ... `I_TO_A` maps, the index truncated to an integer and wrapped by the
    /// map's size (GL 1.1 §3.6.3; Mesa `_mesa_map_ci_to_rgba`). Mesa 22 draws indices without
    /// the index shift and offset the spec applies first (measured: index 1 under
    /// `GL_INDEX_OFFSET` 1 or `GL_INDEX_SHIFT` 1 still draws `I_TO_R[1]`), and so does this.
    pub(crate) fn index_to_rgba(&self, index: f32) -> [f32; 4] {
        let i = if index.is_finite() { index.trunc() as i64 } else { 0 };
        std::array::from_fn(|k| {
            let map = &self.server.pixel_state.maps[2 + k];
            map[i.rem_euclid(map.len() as i64) as usize]
        })
    }

    /// What `glPushAttrib` saves of the pixel area, whatever the mask.
    pub(crate) fn pixel_attrib(&self) -> PixelAttrib {
        (self.server.pixel_state.mode, self.server.color_index)
    }

    /// Restores the groups of `mask` from what [`Gl::pixel_attrib`] saved: `GL_PIXEL_MODE_BIT`
    /// the transfer and zoom, `GL_CURRENT_BIT` the current index, `GL_COLOR_BUFFER_BIT` the
    /// clear index and the index mask (measured on Mesa).
    pub(crate) fn restore_pixel_attrib(&mut self, mask: GLbitfield, (mode, index): PixelAttrib) {
        if mask & GL_PIXEL_MODE_BIT != 0 {
            self.server.pixel_state.mode = mode;
        }
        if mask & GL_CURRENT_BIT != 0 {
            self.server.color_index.current = index.current;
        }
        if mask & GL_COLOR_BUFFER_BIT != 0 {
            (self.server.color_index.clear, self.server.color_index.mask) = (index.clear, index.mask);
        }
    }
}

/// A colour scale or bias name as (bias, component 0 = red ... 3 = alpha); `None` for another.
fn scale_or_bias(pname: GLenum) -> Option<(bool, usize)> {
    Some(match pname {
        GL_RED_SCALE => (false, 0),
        GL_GREEN_SCALE => (false, 1),
        GL_BLUE_SCALE => (false, 2),
        GL_ALPHA_SCALE => (false, 3),
        GL_RED_BIAS => (true, 0),
        GL_GREEN_BIAS => (true, 1),
        GL_BLUE_BIAS => (true, 2),
        GL_ALPHA_BIAS => (true, 3),
        _ => return None,
    })
}

/// `glGet` of a transfer value: `GL_PIXEL_MODE_BIT`'s fields (GL 1.1 table 6.17).
macro_rules! mode_row {
    ($name:expr, $kind:ident, $($field:tt)+) => {
        row($name, 1, Kind::$kind, |gl, o| o[0] = f64::from(gl.server.pixel_state.mode.$($field)+))
    };
}

/// `glGet` of a map's size (GL 1.1 table 6.18).
macro_rules! map_size_row {
    ($name:expr) => {
        row($name, 1, Kind::Int, |gl, o| {
            o[0] = gl.server.pixel_state.maps[($name - GL_PIXEL_MAP_I_TO_I_SIZE) as usize].len() as f64
        })
    };
}

/// The pixel transfer, zoom and map rows of `glGet`.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_MAP_COLOR, 1, Kind::Bool, |gl, o| put_flag(o, gl.server.pixel_state.mode.map_color)),
    row(GL_MAP_STENCIL, 1, Kind::Bool, |gl, o| put_flag(o, gl.server.pixel_state.mode.map_stencil)),
    row(GL_READ_BUFFER, 1, Kind::Int, |gl, o| put_enum(o, gl.server.pixel_state.mode.read_buffer)),
    mode_row!(GL_INDEX_SHIFT, Int, index_shift),
    mode_row!(GL_INDEX_OFFSET, Int, index_offset),
    mode_row!(GL_RED_SCALE, Float, scale[0]),
    mode_row!(GL_GREEN_SCALE, Float, scale[1]),
    mode_row!(GL_BLUE_SCALE, Float, scale[2]),
    mode_row!(GL_ALPHA_SCALE, Float, scale[3]),
    mode_row!(GL_DEPTH_SCALE, Float, depth.scale),
    mode_row!(GL_RED_BIAS, Float, bias[0]),
    mode_row!(GL_GREEN_BIAS, Float, bias[1]),
    mode_row!(GL_BLUE_BIAS, Float, bias[2]),
    mode_row!(GL_ALPHA_BIAS, Float, bias[3]),
    mode_row!(GL_DEPTH_BIAS, Float, depth.bias),
    mode_row!(GL_ZOOM_X, Float, zoom[0]),
    mode_row!(GL_ZOOM_Y, Float, zoom[1]),
    map_size_row!(GL_PIXEL_MAP_I_TO_I_SIZE),
    map_size_row!(GL_PIXEL_MAP_S_TO_S_SIZE),
    map_size_row!(GL_PIXEL_MAP_I_TO_R_SIZE),
    map_size_row!(GL_PIXEL_MAP_I_TO_G_SIZE),
    map_size_row!(GL_PIXEL_MAP_I_TO_B_SIZE),
    map_size_row!(GL_PIXEL_MAP_I_TO_A_SIZE),
    map_size_row!(GL_PIXEL_MAP_R_TO_R_SIZE),
    map_size_row!(GL_PIXEL_MAP_G_TO_G_SIZE),
    map_size_row!(GL_PIXEL_MAP_B_TO_B_SIZE),
    map_size_row!(GL_PIXEL_MAP_A_TO_A_SIZE),
    int_limit!(GL_MAX_PIXEL_MAP_TABLE, MAX_PIXEL_MAP_TABLE),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn maps_store_convert_and_read_back_as_mesa_does() {
        let mut gl = Gl::new(4, 4);
        gl.pixel_mapfv(GL_PIXEL_MAP_S_TO_S, 2, &[1.6, 2.4]);
        let (mut u, mut s) = ([0u32; 2], [0u16; 2]);
        gl.get_pixel_mapuiv(GL_PIXEL_MAP_S_TO_S, &mut u);
        gl.get_pixel_mapusv(GL_PIXEL_MAP_S_TO_S, &mut s);
        assert_eq!((u, s), ([1073741824; 2], [2; 2]));
        gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_I, 2, &[-2.5, 70000.7]);
        gl.get_pixel_mapuiv(GL_PIXEL_MAP_I_TO_I, &mut u);
        gl.get_pixel_mapusv(GL_PIXEL_MAP_I_TO_I, &mut s);
        assert_eq!((u, s), ([2147483651, 3019828879], [0, 65535]));
        gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_R, 2, &[0.3, 1.5]);
        gl.get_pixel_mapuiv(GL_PIXEL_MAP_I_TO_R, &mut u);
        gl.get_pixel_mapusv(GL_PIXEL_MAP_I_TO_R, &mut s);
        assert_eq!((u, s), ([1288490239, 4294967295], [19660, 65535]));
        gl.pixel_mapusv(GL_PIXEL_MAP_B_TO_B, 2, &[0x8000, 0xffff]);
        let mut f = [0.0f32; 2];
        gl.get_pixel_mapfv(GL_PIXEL_MAP_B_TO_B, &mut f);
        assert_eq!(f, [0.500_007_6, 1.0]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn map_errors_in_mesas_order() {
        let mut gl = Gl::new(4, 4);
        gl.pixel_mapfv(0x1234, 0, &[0.0]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE, "the size is checked before the map");
        gl.pixel_mapfv(0x1234, 1, &[0.0]);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_R, 3, &[0.0; 3]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.pixel_mapfv(GL_PIXEL_MAP_R_TO_R, 3, &[0.0; 3]);
        gl.pixel_mapfv(GL_PIXEL_MAP_I_TO_I, 3, &[0.0; 3]);
        assert_eq!(gl.get_error(), GL_NO_ERROR, "colour maps and I_TO_I take any size");
        gl.pixel_mapfv(GL_PIXEL_MAP_R_TO_R, 257, &[0.0; 300]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.pixel_mapfv(GL_PIXEL_MAP_R_TO_R, 4, &[0.0; 3]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE, "a short slice");
        let mut out = [0.0f32; 2];
        gl.get_pixel_mapfv(GL_PIXEL_MAP_R_TO_R, &mut out);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE, "3 values do not fit in 2");
        gl.get_pixel_mapfv(0x1234, &mut out);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    }

    #[test]
    fn transfer_applies_scale_bias_then_maps() {
        let mut gl = Gl::new(4, 4);
        assert!(gl.color_transfer().is_none());
        gl.pixel_transferf(GL_RED_SCALE, 0.5);
        gl.pixel_transferf(GL_GREEN_BIAS, 0.5);
        let t = gl.color_transfer().expect("not the identity");
        assert_eq!(t.apply([1.0, 0.0, 0.25, 1.0]), [0.5, 0.5, 0.25, 1.0]);
        gl.pixel_mapfv(GL_PIXEL_MAP_R_TO_R, 2, &[1.0, 0.0]);
        gl.pixel_transferi(GL_MAP_COLOR, 1);
        let t = gl.color_transfer().expect("maps");
        // Red 0.5 sits half way between the two entries: rounded to even, entry 0.
        assert_eq!(t.apply([1.0, 0.0, 0.0, 0.0])[0], 1.0);
        assert_eq!(t.apply([1.0, 0.0, 0.0, 0.0])[1], 0.0, "G_TO_G's one entry is 0");
        gl.pixel_transferf(0x1234, 1.0);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.pixel_transferf(GL_DEPTH_BIAS, 0.25);
        assert_eq!(gl.depth_transfer().apply(0.9), 1.0);
    }
}
