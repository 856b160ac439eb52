//! `glBitmap` and `glDrawPixels` (GL 1.1 spec §3.6.3–3.6.4; Mesa `main/drawpix.c`): images
//! drawn at the current raster position, one fragment per pixel.
//!
//! The image is unpacked from client memory with the unpack modes (`glPixelStore`) when the
//! call is made (or compiled into a display list, as GL copies it then). Its fragments are
//! recorded as a `GL_POINTS` primitive of one-pixel points at the pixel centres, with a draw
//! state that maps window coordinates straight onto the window (identity modelview, a
//! projection from window to clip coordinates, the whole window as viewport), no lighting, the
//! raster position's depth and the current depth test, so the renderer needs nothing new.

use super::consts::*;
use super::frame::{Command, Primitive};
use super::lists::ListCommand;
use super::pixel_unpack::{format_and_type_error, unpack_bitmap, unpack_image};
use super::pixel_zoom::zoomed_pixels;
use super::texture::BoundTexture;
use super::types::*;
use super::vertex::Vertex;
use super::Gl;
use glam::{Mat4, Vec3};

/// Mesa's nudge before flooring a bitmap's origin ("to satisfy conformance tests (matches SGI's
/// OpenGL)", `_mesa_Bitmap`).
const BITMAP_EPSILON: f32 = 0.0001;

/// The matrix that takes window coordinates (x, y, and z already in [0, 1] mapped to NDC
/// [−1, 1]) to clip coordinates for a `width` × `height` viewport at the origin.
fn window_to_clip(width: i32, height: i32) -> Mat4 {
    let scale = Vec3::new(2.0 / width.max(1) as f32, 2.0 / height.max(1) as f32, 1.0);
    Mat4::from_translation(Vec3::new(-1.0, -1.0, 0.0)) * Mat4::from_scale(scale)
}

impl Gl {
    /// `glBitmap`: draws a `width` × `height` bitmap (GL 1.1 §3.6.4): set bit (i, j) is a
    /// fragment at window (⌊xr − xorig⌋ + i, ⌊yr − yorig⌋ + j) in the raster colour at the
    /// raster depth; then the raster position moves by (`xmove`, `ymove`). With an invalid raster
    /// position nothing is drawn and the position does not move (Mesa). `bitmap` is read with the
    /// unpack modes ([`Gl::pixel_storei`]; alignment 4 unless set). Errors: inside
    /// `begin`/`end` → `GL_INVALID_OPERATION`; a negative size, or `bitmap` shorter than the
    /// image → `GL_INVALID_VALUE`. Compiled into display lists with the bits unpacked then.
    #[allow(clippy::too_many_arguments)]
    pub fn bitmap(
        &mut self,
        width: GLsizei,
        height: GLsizei,
        xorig: GLfloat,
        yorig: GLfloat,
        xmove: GLfloat,
        ymove: GLfloat,
        bitmap: &[u8],
    ) {
        let store = self.unpack_store();
        let unpacked = || unpack_bitmap(store, width, height, bitmap);
        let call = BitmapCall { size: (width, height), origin: (xorig, yorig), step: (xmove, ymove) };
        if self.compiled(|| ListCommand::Bitmap(call, unpacked())) {
            return;
        }
        self.draw_bitmap(call, unpacked().as_deref());
    }

    /// Executes an unpacked `glBitmap` (`bits` `None`: the client's slice was too short).
    pub(crate) fn draw_bitmap(&mut self, call: BitmapCall, bits: Option<&[bool]>) {
        if self.reject_inside_begin_end() {
            return;
        }
        let (width, height) = call.size;
        if width < 0 || height < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let Some(bits) = bits else { return self.set_error(GL_INVALID_VALUE) };
        if !self.server.raster_pos.valid {
            return;
        }
        let [xr, yr, z, _] = self.server.raster_pos.window;
        let x0 = (xr + BITMAP_EPSILON - call.origin.0).floor() as i32;
        let y0 = (yr + BITMAP_EPSILON - call.origin.1).floor() as i32;
        let w = width as usize;
        let pixels = bits.iter().enumerate().filter(|(_, &set)| set).map(|(k, _)| {
            let (i, j) = ((k % w) as i32, (k / w) as i32);
            // A raster position or origin far outside the window (1e30, ∞) saturates x0, y0:
            // such pixels lie off the window either way.
            [x0.saturating_add(i), y0.saturating_add(j)]
        });
        let color = self.server.raster_pos.color.map(|c| c.clamp(0.0, 1.0));
        let fragments: Vec<_> = pixels.map(|p| (p, color, z)).collect();
        if !self.feedback_raster_token(GL_BITMAP_TOKEN) {
            self.record_fragments(&fragments);
        }
        self.advance_raster_pos(call.step.0, call.step.1);
    }

    /// `glDrawPixels`: pixel (i, j) of the image, read with the unpack modes from any GL 1.1
    /// type or GL 1.2 packed type (`gl::pixel_unpack`), goes through the pixel transfer
    /// (`glPixelTransfer`, `glPixelMap`) and becomes the fragments that `glPixelZoom` gives it
    /// from window (round(xr), round(yr)) on (Mesa rounds; [`super::pixel_zoom`]): the colour
    /// formats (with `GL_BGR`, `GL_BGRA`) at the raster depth; colour indices (with
    /// `GL_BITMAP` too) through the maps, as an RGBA context draws them; `GL_DEPTH_COMPONENT`
    /// as fragments of the raster colour at the image's depths; `GL_STENCIL_INDEX` into the
    /// stencil buffer (as a stencil `glCopyPixels` writes). Nothing is drawn when the raster
    /// position is invalid. Errors, in Mesa's order: inside `begin`/`end` →
    /// `GL_INVALID_OPERATION`; a negative size → `GL_INVALID_VALUE`; an unknown format or type
    /// → `GL_INVALID_ENUM`; a packed type the format does not fit, or `GL_STENCIL_INDEX`
    /// without a stencil buffer → `GL_INVALID_OPERATION`; `pixels` shorter than the image →
    /// `GL_INVALID_VALUE`.
    pub fn draw_pixels(&mut self, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, pixels: &[u8]) {
        let store = self.unpack_store();
        let unpacked = || unpack_image(store, (width, height), format, type_, pixels);
        if self.compiled(|| ListCommand::DrawPixels((width, height), format, type_, unpacked())) {
            return;
        }
        self.draw_rgba((width, height), format, type_, unpacked().as_deref());
    }

    /// Executes an unpacked `glDrawPixels` (`rgba` `None`: the client's slice was too short).
    pub(crate) fn draw_rgba(
        &mut self,
        (width, height): (GLsizei, GLsizei),
        format: GLenum,
        type_: GLenum,
        rgba: Option<&[[f32; 4]]>,
    ) {
        if self.reject_inside_begin_end() {
            return;
        }
        if width < 0 || height < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        // The image's errors, then a stencil image for a window without stencil (Mesa).
        let no_stencil = matches!(format, GL_STENCIL_INDEX | GL_DEPTH_STENCIL) && !self.window_has(GL_STENCIL);
        if let Some(code) = format_and_type_error(format, type_).or(no_stencil.then_some(GL_INVALID_OPERATION)) {
            return self.set_error(code);
        }
        let Some(rgba) = rgba else { return self.set_error(GL_INVALID_VALUE) };
        if !self.server.raster_pos.valid || self.feedback_raster_token(GL_DRAW_PIXEL_TOKEN) || rgba.is_empty() {
            return;
        }
        if format == GL_STENCIL_INDEX {
            return self.draw_stencil((width, height), rgba);
        }
        if format == GL_DEPTH_STENCIL {
            return self.draw_depth_stencil((width, height), rgba);
        }
        let [xr, yr, z, _] = self.server.raster_pos.window;
        let origin = [xr.round() as i32, yr.round() as i32];
        let transfer = self.draw_color_transfer();
        let (w, h) = (width as usize, height as usize);
        let window = (self.width().max(0) as u32, self.height().max(0) as u32);
        let depth = self.depth_transfer();
        let raster_color = self.server.raster_pos.color.map(|c| c.clamp(0.0, 1.0));
        let fragments: Vec<_> = zoomed_pixels(origin, self.zoom(), (w, h), window)
            .map(|((i, j), (x, y))| {
                let c = rgba[j * w + i];
                let (c, z) = match format {
                    // RGBA mode: an index goes through the index shift and offset and the
                    // I_TO_R .. I_TO_A maps (GL 1.1 §3.6.3; Mesa `_mesa_map_ci_to_rgba`).
                    GL_COLOR_INDEX => (self.index_to_rgba(c[0]), z),
                    // A depth image: fragments of the raster colour at the depths it gives,
                    // scaled, biased and clamped (GL 1.1 §3.6.3 "Final Conversion").
                    GL_DEPTH_COMPONENT => (raster_color, depth.apply(c[0]).clamp(0.0, 1.0)),
                    _ => (transfer.as_ref().map_or(c, |t| t.apply(c)), z),
                };
                ([x as i32, y as i32], c.map(|v| v.clamp(0.0, 1.0)), z)
            })
            .collect();
        self.record_fragments(&fragments);
    }

    /// Records fragments (window pixel, colour, window depth) as one-pixel points at the pixel
    /// centres; those outside the window are dropped.
    fn record_fragments(&mut self, fragments: &[([i32; 2], [f32; 4], f32)]) {
        let state = self.window_state();
        self.record_fragments_in(fragments, state);
    }

    /// [`Gl::record_fragments`] drawn with draw state `state`.
    pub(crate) fn record_fragments_in(&mut self, fragments: &[([i32; 2], [f32; 4], f32)], state: usize) {
        let (w, h) = (self.width(), self.height());
        let inside = |p: &[i32; 2]| (0..w).contains(&p[0]) && (0..h).contains(&p[1]);
        let first = self.recorder.frame.vertices.len();
        for &(p, color, z) in fragments.iter().filter(|(p, _, _)| inside(p)) {
            let position = [p[0] as f32 + 0.5, p[1] as f32 + 0.5, 2.0 * z - 1.0, 1.0];
            let tex_coord = self.server.raster_pos.tex_coord;
            self.recorder.frame.vertices.push(Vertex { position, color, tex_coord, ..self.current_vertex(position) });
        }
        let count = self.recorder.frame.vertices.len() - first;
        if count == 0 {
            return;
        }
        if !self.recorder.frame.states[state].more_textures.is_empty() {
            let units = [[0.0, 0.0, 0.0, 1.0]; 7];
            self.recorder.frame.unit_tex_coords.extend((first..first + count).map(|i| (i, units)));
        }
        self.recorder.frame.primitives.push(Primitive {
            mode: GL_POINTS,
            first,
            count,
            state,
            listed_or_indexed: false,
        });
        self.recorder.frame.commands.push(Command::Draw(self.recorder.frame.primitives.len() - 1));
    }

    /// The index of a draw state that puts window coordinates on their pixels: the current state
    /// (depth test included) with identity modelview, a window-to-clip projection, the whole
    /// window as viewport, depth range [0, 1], no lighting and one-pixel points.
    pub(crate) fn window_state(&mut self) -> usize {
        // The fragments are textured with the raster position's coordinates (GL 1.1 §3.6.4,
        // §3.6.3: "the texture coordinates of the current raster position"), which the raster
        // position already took through the texture matrix: identity here, no texgen. Fog is
        // not applied to them, as Mesa 22.3 on llvmpipe fogs neither `glDrawPixels` nor
        // `glBitmap` fragments (measured: white pixels and a red bitmap at eye distances 4 and
        // 8 under linear fog from 0 to 10 stay white and red, with the fog coordinate source
        // too); blending and the alpha test are kept.
        let texture = self.bound_texture().map(|mut t| {
            t.matrix = Mat4::IDENTITY;
            t.generate = None;
            t
        });
        let mut state = self.snapshot(texture);
        // The other units texture them too, at (0, 0, 0, 1) rather than at the raster
        // position's coordinates: what llvmpipe draws (measured on Mesa 22.3, set-up 7 of
        // tests/reference/pixels/multitexture.c: unit 1's (0.75, 0.25) samples the texel at 0, 0).
        state.more_textures = self
            .more_textures()
            .into_iter()
            .map(|(unit, t)| (unit, BoundTexture { matrix: Mat4::IDENTITY, generate: None, ..t }))
            .collect();
        state.fog = None;
        let (w, h) = (self.width(), self.height());
        state.modelview = Mat4::IDENTITY;
        state.projection = window_to_clip(w, h);
        state.viewport = [0, 0, w, h];
        state.depth_range = [0.0, 1.0];
        state.lighting = None;
        state.point_size = 1.0;
        state.shade_model = GL_FLAT;
        match self.recorder.frame.states.last() {
            Some(last) if *last == state => self.recorder.frame.states.len() - 1,
            _ => {
                self.recorder.frame.states.push(state);
                self.recorder.frame.states.len() - 1
            }
        }
    }
}

/// A `glBitmap` call's sizes and offsets (its bits travel beside it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct BitmapCall {
    pub size: (GLsizei, GLsizei),
    pub origin: (GLfloat, GLfloat),
    pub step: (GLfloat, GLfloat),
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points(gl: &mut Gl) -> Vec<([f32; 2], [f32; 4])> {
        let frame = gl.frame().clone();
        frame.iter().flat_map(|(_, v)| v.iter().map(|v| ([v.position[0], v.position[1]], v.color))).collect()
    }

    #[test]
    fn a_bitmap_draws_at_the_floored_origin_in_the_raster_colour_and_advances() {
        let mut gl = Gl::new(20, 20);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        gl.color3f(1.0, 0.0, 0.0);
        gl.raster_pos2f(0.0, 0.0); // window (10, 10)
        gl.color3f(0.0, 1.0, 0.0);
        gl.bitmap(2, 2, 0.5, 1.0, 5.0, -1.0, &[0b1000_0000, 0b0100_0000]);
        let red = [1.0, 0.0, 0.0, 1.0];
        assert_eq!(points(&mut gl), [([9.5, 9.5], red), ([10.5, 10.5], red)]);
        let mut p = [0.0f32; 4];
        gl.get_floatv(GL_CURRENT_RASTER_POSITION, &mut p);
        assert_eq!(p, [15.0, 9.0, 0.5, 1.0]);
        let frame = gl.frame();
        let state = &frame.states[frame.primitives[0].state];
        assert_eq!((state.viewport, state.lighting.is_none(), state.point_size), ([0, 0, 20, 20], true, 1.0));
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn an_invalid_raster_position_draws_nothing_and_does_not_move() {
        let mut gl = Gl::new(20, 20);
        gl.raster_pos2f(2.0, 0.0);
        gl.bitmap(8, 1, 0.0, 0.0, 8.0, 0.0, &[0xFF, 0, 0, 0]);
        gl.draw_pixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &[255; 4]);
        assert!(points(&mut gl).is_empty());
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn draw_pixels_rounds_the_raster_position() {
        let mut gl = Gl::new(8, 8);
        gl.matrix_mode(GL_PROJECTION);
        gl.ortho(0.0, 8.0, 0.0, 8.0, -1.0, 1.0);
        gl.raster_pos2f(2.6, 3.4);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        gl.draw_pixels(1, 2, GL_RGB, GL_UNSIGNED_BYTE, &[255, 0, 0, 0, 0, 255]);
        assert_eq!(points(&mut gl), [([3.5, 3.5], [1.0, 0.0, 0.0, 1.0]), ([3.5, 4.5], [0.0, 0.0, 1.0, 1.0])]);
    }

    #[test]
    fn bitmap_and_pixels_errors_in_mesas_order() {
        let mut gl = Gl::new(8, 8);
        gl.bitmap(-1, 1, 0.0, 0.0, 0.0, 0.0, &[]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.bitmap(8, 2, 0.0, 0.0, 0.0, 0.0, &[0xFF]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE, "short slice");
        gl.begin(GL_POINTS);
        gl.bitmap(-1, 1, 0.0, 0.0, 0.0, 0.0, &[]);
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.draw_pixels(-1, 1, 0x1234, GL_UNSIGNED_BYTE, &[]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.draw_pixels(1, 1, 0x1234, GL_UNSIGNED_BYTE, &[0; 4]);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.draw_pixels(1, 1, GL_RGB, 0x1234, &[0; 4]);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.draw_pixels(1, 1, GL_RGB, GL_BITMAP, &[0; 4]);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.draw_pixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, &[0; 12]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.draw_pixels(1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &[0; 4]);
        assert_eq!(gl.get_error(), GL_NO_ERROR, "valid, but gleval draws only colours");
    }

    #[test]
    fn a_list_keeps_the_bits_unpacked_when_it_was_compiled() {
        let mut gl = Gl::new(32, 32);
        gl.new_list(1, GL_COMPILE);
        gl.raster_pos2i(0, 0);
        gl.bitmap(8, 1, 0.0, 0.0, 8.0, 0.0, &[0b1100_0000, 0, 0, 0]);
        gl.draw_pixels(1, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, &[255, 0, 0, 0]);
        gl.end_list();
        assert!(points(&mut gl).is_empty());
        gl.pixel_storei(GL_UNPACK_LSB_FIRST, 1);
        gl.call_list(1);
        let xs: Vec<f32> = points(&mut gl).iter().map(|p| p.0[0]).collect();
        assert_eq!(xs, [16.5, 17.5, 24.5]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }
}
