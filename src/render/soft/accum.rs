//! The accumulation buffer on the CPU (GL 1.1 spec §4.2.4) with Mesa 22.3's arithmetic
//! (`main/accum.c`): signed 16-bit channels (`RGBA_SNORM16`) holding value · 32767, every
//! product truncated towards zero, sums wrapping as C's `short` does, `GL_RETURN` clamped into
//! the colour buffer through the colour mask. `GL_ADD` and `GL_ACCUM` with 0 and `GL_MULT` with 1
//! do nothing, as in Mesa. Clears and operations cover the scissor box.

use super::framebuffer::Framebuffer;
use super::ops::to_unorm8;
use crate::gl::consts::*;
use crate::gl::fragments::FragmentTests;
use crate::gl::types::GLenum;

/// C's conversion of a float to `GLshort` as x86 compilers make it: truncated to 32 bits
/// (out of range: `INT_MIN`), then the low 16 bits.
fn to_short(x: f32) -> i16 {
    let wide = if x.is_finite() && x.abs() < 2_147_483_648.0 { x as i32 } else { i32::MIN };
    wide as i16
}

/// Mesa's `FLOAT_TO_SHORT` for the clear value: ((int)(65535·x) − 1) / 2.
fn clear_short(x: f32) -> i16 {
    ((65535.0 * x) as i32 - 1).wrapping_div(2) as i16
}

impl Framebuffer {
    /// The accumulation buffer, made (zero) at its first use.
    fn accum_mut(&mut self) -> &mut Vec<[i16; 4]> {
        let n = self.width as usize * self.height as usize;
        self.accum.get_or_insert_with(|| vec![[0; 4]; n])
    }

    /// `glClear(GL_ACCUM_BUFFER_BIT)` within `rect`.
    pub fn clear_accum(&mut self, rect: [u32; 4], value: [f32; 4]) {
        let pixels: Vec<usize> = self.indices(rect).collect();
        let v = value.map(clear_short);
        let accum = self.accum_mut();
        pixels.iter().for_each(|&i| accum[i] = v);
    }

    /// `glAccum(op, value)` within `rect`, reading colour buffer `read` and returning into the
    /// draw buffers of `tests` through its colour mask.
    pub fn accumulate(&mut self, rect: [u32; 4], (op, value): (GLenum, f32), read: u8, tests: &FragmentTests) {
        let pixels: Vec<usize> = self.indices(rect).collect();
        match op {
            GL_LOAD | GL_ACCUM if op == GL_LOAD || value != 0.0 => {
                let colors: Vec<[u8; 4]> = pixels.iter().map(|&i| self.color(read)[i]).collect();
                let scale = value * 32767.0;
                let accum = self.accum_mut();
                for (&i, c) in pixels.iter().zip(colors) {
                    let add = c.map(|c| to_short(f32::from(c) / 255.0 * scale));
                    accum[i] =
                        if op == GL_LOAD { add } else { std::array::from_fn(|k| accum[i][k].wrapping_add(add[k])) };
                }
            }
            GL_ADD if value != 0.0 => {
                let incr = to_short(value * 32767.0);
                let accum = self.accum_mut();
                pixels.iter().for_each(|&i| accum[i] = accum[i].map(|a| a.wrapping_add(incr)));
            }
            GL_MULT if value != 1.0 => {
                let accum = self.accum_mut();
                pixels.iter().for_each(|&i| accum[i] = accum[i].map(|a| to_short(f32::from(a) * value)));
            }
            GL_RETURN => self.accum_return(&pixels, value, tests),
            _ => {}
        }
    }

    /// `GL_RETURN`: value · accum / 32767 into each draw buffer, clamped, through the mask.
    fn accum_return(&mut self, pixels: &[usize], value: f32, tests: &FragmentTests) {
        let scale = value / 32767.0;
        let values: Vec<[u8; 4]> = {
            let accum = self.accum_mut();
            pixels.iter().map(|&i| accum[i].map(|a| to_unorm8(f32::from(a) * scale))).collect()
        };
        for bit in Self::buffers(tests.draw_buffers) {
            let buffer = self.color_mut(bit);
            for (&i, v) in pixels.iter().zip(&values) {
                buffer[i] = std::array::from_fn(|k| if tests.color_write[k] { v[k] } else { buffer[i][k] });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::fragments::FRONT_BUFFER;

    fn one_pixel(color: [u8; 4]) -> Framebuffer {
        let mut fb = Framebuffer::new(1, 1);
        fb.color_mut(FRONT_BUFFER)[0] = color;
        fb
    }

    /// Real Mesa 22.3 (OSMesa, llvmpipe): red, green, blue and white each accumulated with 0.25
    /// return (127, 127, 127, 255); `GL_RETURN` 2 then (255, ...); `GL_MULT` 0.5 then
    /// (64, 64, 64, 127).
    #[test]
    fn the_red_book_average_as_mesa() {
        let tests = FragmentTests::default();
        let rect = [0, 0, 1, 1];
        let mut fb = one_pixel([0; 4]);
        fb.clear_accum(rect, [0.0; 4]);
        for c in [[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255], [255; 4]] {
            fb.color_mut(FRONT_BUFFER)[0] = c;
            fb.accumulate(rect, (GL_ACCUM, 0.25), FRONT_BUFFER, &tests);
        }
        fb.accumulate(rect, (GL_RETURN, 1.0), FRONT_BUFFER, &tests);
        assert_eq!(fb.color(FRONT_BUFFER)[0], [127, 127, 127, 255]);
        fb.accumulate(rect, (GL_RETURN, 2.0), FRONT_BUFFER, &tests);
        assert_eq!(fb.color(FRONT_BUFFER)[0], [255; 4]);
        fb.accumulate(rect, (GL_MULT, 0.5), FRONT_BUFFER, &tests);
        fb.accumulate(rect, (GL_RETURN, 1.0), FRONT_BUFFER, &tests);
        assert_eq!(fb.color(FRONT_BUFFER)[0], [64, 64, 64, 127]);
    }

    /// Real Mesa: `glClearAccum(-0.5, 0.5, 1, 0.25)` returned with 1 gives (0, 127, 255, 64).
    #[test]
    fn clear_values_as_mesa() {
        let mut fb = one_pixel([0; 4]);
        fb.clear_accum([0, 0, 1, 1], [-0.5, 0.5, 1.0, 0.25]);
        fb.accumulate([0, 0, 1, 1], (GL_RETURN, 1.0), FRONT_BUFFER, &FragmentTests::default());
        assert_eq!(fb.color(FRONT_BUFFER)[0], [0, 127, 255, 64]);
    }

    #[test]
    fn huge_values_wrap_without_panicking() {
        let mut fb = one_pixel([255; 4]);
        let tests = FragmentTests::default();
        for (op, v) in [(GL_LOAD, 1e30), (GL_ACCUM, f32::NAN), (GL_ADD, -1e9), (GL_MULT, f32::INFINITY)] {
            fb.accumulate([0, 0, 1, 1], (op, v), FRONT_BUFFER, &tests);
        }
        fb.accumulate([0, 0, 1, 1], (GL_RETURN, f32::MAX), FRONT_BUFFER, &tests);
    }
}
