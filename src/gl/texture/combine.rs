//! GL 1.3's texture combiner, the `GL_COMBINE` environment (GL 1.3 spec §3.8.13, tables
//! 3.19 and 3.20; `GL_ARB_texture_env_combine`, `GL_ARB_texture_env_dot3`; Mesa
//! `main/texenv.c`): its state, what `glTexEnv` takes for it, in Mesa's checks, and the
//! arithmetic both rasterisers apply (the CPU one calls [`Combine::apply`], `fragment.wgsl`'s
//! `combine` mirrors it).

use crate::gl::consts::*;
use crate::gl::types::*;

/// One half of the combiner, RGB or alpha: the function, its three sources and operands, and
/// the scale (1, 2 or 4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Combiner {
    /// `GL_COMBINE_RGB` or `GL_COMBINE_ALPHA`: `GL_REPLACE`, `GL_MODULATE` (initial),
    /// `GL_ADD`, `GL_ADD_SIGNED`, `GL_INTERPOLATE`, `GL_SUBTRACT`, and for RGB `GL_DOT3_RGB` and
    /// `GL_DOT3_RGBA`.
    pub function: GLenum,
    /// `GL_SOURCE0..2_*`: `GL_TEXTURE` (or `GL_TEXTURE0` ... `GL_TEXTURE7`, GL 1.4's
    /// crossbar), `GL_CONSTANT`, `GL_PRIMARY_COLOR`, `GL_PREVIOUS`.
    pub sources: [GLenum; 3],
    /// `GL_OPERAND0..2_*`: `GL_SRC_COLOR`, `GL_ONE_MINUS_SRC_COLOR` (RGB only),
    /// `GL_SRC_ALPHA`, `GL_ONE_MINUS_SRC_ALPHA`.
    pub operands: [GLenum; 3],
    /// `GL_RGB_SCALE` or `GL_ALPHA_SCALE`: 1, 2 or 4.
    pub scale: u8,
}

/// The combiner's state: `GL_TEXTURE_BIT` saves it with the environment.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Combine {
    /// The RGB half.
    pub rgb: Combiner,
    /// The alpha half.
    pub alpha: Combiner,
}

impl Default for Combine {
    /// GL 1.3 table 6.17's initial values (measured on Mesa: `texture_env_combine.calls`).
    fn default() -> Self {
        let sources = [GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT];
        Self {
            rgb: Combiner {
                function: GL_MODULATE,
                sources,
                operands: [GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA],
                scale: 1,
            },
            alpha: Combiner { function: GL_MODULATE, sources, operands: [GL_SRC_ALPHA; 3], scale: 1 },
        }
    }
}

/// Whether `pname` is one of the combiner's `glTexEnv` names.
pub(super) fn is_combine_name(pname: GLenum) -> bool {
    matches!(
        pname,
        GL_COMBINE_RGB
            | GL_COMBINE_ALPHA
            | GL_SOURCE0_RGB..=GL_SOURCE2_RGB
            | GL_SOURCE0_ALPHA..=GL_SOURCE2_ALPHA
            | GL_OPERAND0_RGB..=GL_OPERAND2_RGB
            | GL_OPERAND0_ALPHA..=GL_OPERAND2_ALPHA
            | GL_RGB_SCALE
            | GL_ALPHA_SCALE
    )
}

/// Whether a combiner name is of the alpha half.
fn is_alpha_name(pname: GLenum) -> bool {
    matches!(
        pname,
        GL_COMBINE_ALPHA | GL_SOURCE0_ALPHA..=GL_SOURCE2_ALPHA | GL_OPERAND0_ALPHA..=GL_OPERAND2_ALPHA | GL_ALPHA_SCALE
    )
}

impl Combine {
    /// Sets `pname` (a combiner name, [`is_combine_name`]) to `value` as Mesa's `glTexEnvfv`
    /// takes it: an enum truncated from the float, a scale as it is. A value the name does not
    /// take is `GL_INVALID_ENUM`, a scale other than 1, 2 or 4 `GL_INVALID_VALUE`.
    pub(super) fn set(&mut self, pname: GLenum, value: GLfloat) -> Result<(), GLenum> {
        let alpha = is_alpha_name(pname);
        let half = if alpha { &mut self.alpha } else { &mut self.rgb };
        if matches!(pname, GL_RGB_SCALE | GL_ALPHA_SCALE) {
            if ![1.0, 2.0, 4.0].contains(&value) {
                return Err(GL_INVALID_VALUE);
            }
            half.scale = value as u8;
            return Ok(());
        }
        let v = value as GLint as GLenum;
        let (slot, ok) = match pname {
            GL_COMBINE_RGB | GL_COMBINE_ALPHA => {
                let dot3 = !alpha && matches!(v, GL_DOT3_RGB | GL_DOT3_RGBA);
                let common =
                    matches!(v, GL_REPLACE | GL_MODULATE | GL_ADD | GL_ADD_SIGNED | GL_INTERPOLATE | GL_SUBTRACT);
                (&mut half.function, common || dot3)
            }
            GL_SOURCE0_RGB..=GL_SOURCE2_RGB | GL_SOURCE0_ALPHA..=GL_SOURCE2_ALPHA => {
                let k = ((pname - GL_SOURCE0_RGB) % 8) as usize;
                // Mesa's fixed function has 8 units, each a crossbar source.
                let units = GL_TEXTURE0..=GL_TEXTURE7;
                (
                    &mut half.sources[k],
                    matches!(v, GL_TEXTURE | GL_CONSTANT | GL_PRIMARY_COLOR | GL_PREVIOUS) || units.contains(&v),
                )
            }
            _ => {
                let k = ((pname - GL_OPERAND0_RGB) % 8) as usize;
                let colour = !alpha && matches!(v, GL_SRC_COLOR | GL_ONE_MINUS_SRC_COLOR);
                (&mut half.operands[k], colour || matches!(v, GL_SRC_ALPHA | GL_ONE_MINUS_SRC_ALPHA))
            }
        };
        if !ok {
            return Err(GL_INVALID_ENUM);
        }
        *slot = v;
        Ok(())
    }

    /// What `glGetTexEnv` answers for a combiner name.
    pub(super) fn get(&self, pname: GLenum) -> GLfloat {
        let alpha = is_alpha_name(pname);
        let half = if alpha { &self.alpha } else { &self.rgb };
        match pname {
            GL_COMBINE_RGB | GL_COMBINE_ALPHA => half.function as GLfloat,
            GL_RGB_SCALE | GL_ALPHA_SCALE => GLfloat::from(half.scale),
            GL_SOURCE0_RGB..=GL_SOURCE2_RGB | GL_SOURCE0_ALPHA..=GL_SOURCE2_ALPHA => {
                half.sources[((pname - GL_SOURCE0_RGB) % 8) as usize] as GLfloat
            }
            _ => half.operands[((pname - GL_OPERAND0_RGB) % 8) as usize] as GLfloat,
        }
    }

    /// The combiner's result on unit 0, or with no other unit drawing (see
    /// [`Combine::apply_on_unit`]): `GL_PREVIOUS` is the primary colour, a crossbar source
    /// naming another unit reads zero (GL leaves a disabled unit's texel undefined).
    #[must_use]
    pub fn apply(&self, texture: [f32; 4], primary: [f32; 4], constant: [f32; 4]) -> [f32; 4] {
        self.apply_on_unit(texture, [primary, primary], constant, &|unit| if unit == 0 { texture } else { [0.0; 4] })
    }

    /// The combiner's result for a fragment (GL 1.3 §3.8.13): `texture` the unit's texel as the
    /// base format gives it (see [`texture_source`]), `previous` the previous unit's result
    /// (the fragment's colour on the first), `primary` the fragment's colour, `constant`
    /// `GL_TEXTURE_ENV_COLOR`, and GL 1.4's crossbar `GL_TEXTUREn` unit n's texel as
    /// `unit_texel` gives it; scaled and clamped to [0, 1].
    #[must_use]
    pub fn apply_on_unit(
        &self,
        texture: [f32; 4],
        [previous, primary]: [[f32; 4]; 2],
        constant: [f32; 4],
        unit_texel: &dyn Fn(usize) -> [f32; 4],
    ) -> [f32; 4] {
        let source = |s: GLenum| match s {
            GL_TEXTURE => texture,
            GL_CONSTANT => constant,
            GL_PRIMARY_COLOR => primary,
            GL_PREVIOUS => previous,
            _ => unit_texel(s.wrapping_sub(GL_TEXTURE0) as usize),
        };
        let argument = |half: &Combiner, k: usize| -> [f32; 4] {
            let c = source(half.sources[k]);
            match half.operands[k] {
                GL_SRC_COLOR => c,
                GL_ONE_MINUS_SRC_COLOR => c.map(|x| 1.0 - x),
                GL_SRC_ALPHA => [c[3]; 4],
                _ => [1.0 - c[3]; 4],
            }
        };
        let rgb_args = [0, 1, 2].map(|k| argument(&self.rgb, k));
        let alpha_args = [0, 1, 2].map(|k| argument(&self.alpha, k)[3]);
        let clamp = |x: f32| x.clamp(0.0, 1.0);
        let rgb_scale = f32::from(self.rgb.scale);
        if matches!(self.rgb.function, GL_DOT3_RGB | GL_DOT3_RGBA) {
            let [a, b, _] = rgb_args;
            let dot = 4.0 * (0..3).map(|i| (a[i] - 0.5) * (b[i] - 0.5)).sum::<f32>();
            let value = clamp(dot * rgb_scale);
            // DOT3_RGBA's alpha is the dot product too, under the alpha scale (measured on
            // Mesa: tests/reference/pixels/combine.c, set-up 7).
            let alpha = if self.rgb.function == GL_DOT3_RGBA {
                clamp(dot * f32::from(self.alpha.scale))
            } else {
                clamp(function(self.alpha.function, alpha_args) * f32::from(self.alpha.scale))
            };
            return [value, value, value, alpha];
        }
        let rgb: [f32; 3] =
            std::array::from_fn(|i| clamp(function(self.rgb.function, rgb_args.map(|a| a[i])) * rgb_scale));
        let alpha = clamp(function(self.alpha.function, alpha_args) * f32::from(self.alpha.scale));
        [rgb[0], rgb[1], rgb[2], alpha]
    }
}

/// One component of a combiner function (GL 1.3 table 3.19) of its three arguments.
fn function(f: GLenum, [a0, a1, a2]: [f32; 3]) -> f32 {
    match f {
        GL_REPLACE => a0,
        GL_MODULATE => a0 * a1,
        GL_ADD => a0 + a1,
        GL_ADD_SIGNED => a0 + a1 - 0.5,
        GL_INTERPOLATE => a0 * a2 + a1 * (1.0 - a2),
        _ => a0 - a1,
    }
}

/// The texel as a combiner source, by the texture's base format (GL 1.3 table 3.15): an
/// alpha texture's colour is black, a luminance texture's alpha 1, intensity in all four.
/// Levels keep luminance and intensity in their red component.
#[must_use]
pub fn texture_source(base_format: GLenum, [r, g, b, a]: [f32; 4]) -> [f32; 4] {
    match base_format {
        GL_ALPHA => [0.0, 0.0, 0.0, a],
        GL_LUMINANCE => [r, r, r, 1.0],
        GL_LUMINANCE_ALPHA => [r, r, r, a],
        GL_INTENSITY => [r; 4],
        GL_RGB => [r, g, b, 1.0],
        _ => [r, g, b, a],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_functions_follow_gl_1_3_table_3_19() {
        let texel = [0.8, 0.6, 0.4, 0.5];
        let primary = [0.5, 0.25, 1.0, 0.75];
        let constant = [0.2, 0.4, 0.6, 0.1];
        let mut c = Combine::default();
        // MODULATE of TEXTURE and PREVIOUS: the product.
        let m = c.apply(texel, primary, constant);
        assert_eq!(m, [0.4, 0.15, 0.4, 0.375]);
        c.rgb.function = GL_INTERPOLATE;
        // a0·a2 + a1·(1 − a2) with a2 the constant's alpha 0.1 (operand 2 is its alpha).
        let i = c.apply(texel, primary, constant);
        assert!((i[0] - (0.8 * 0.1 + 0.5 * 0.9)).abs() < 1e-6);
        c.rgb.function = GL_ADD_SIGNED;
        c.rgb.scale = 2;
        let s = c.apply(texel, primary, constant);
        assert!((s[1] - (0.6 + 0.25 - 0.5) * 2.0).abs() < 1e-6 && s[0] == 1.0, "scaled and clamped: {s:?}");
        c.rgb = Combiner {
            function: GL_DOT3_RGBA,
            sources: [GL_TEXTURE, GL_CONSTANT, GL_CONSTANT],
            operands: [GL_SRC_COLOR; 3],
            scale: 1,
        };
        // 4·((0.8−½)(0.2−½) + (0.6−½)(0.4−½) + (0.4−½)(0.6−½)) = 4·(−0.09 − 0.01 − 0.01) < 0.
        assert_eq!(c.apply(texel, primary, constant), [0.0; 4]);
        c.rgb.sources = [GL_TEXTURE, GL_TEXTURE, GL_CONSTANT];
        let d = 4.0 * (0.09 + 0.01 + 0.01f32);
        assert!(c.apply(texel, primary, constant).iter().all(|&x| (x - d).abs() < 1e-6));
    }

    #[test]
    fn operands_and_sources_select_as_gl_says() {
        let c = Combine {
            rgb: Combiner {
                function: GL_REPLACE,
                sources: [GL_CONSTANT; 3],
                operands: [GL_ONE_MINUS_SRC_ALPHA; 3],
                scale: 1,
            },
            alpha: Combiner {
                function: GL_SUBTRACT,
                sources: [GL_PRIMARY_COLOR, GL_TEXTURE, GL_TEXTURE],
                operands: [GL_SRC_ALPHA; 3],
                scale: 4,
            },
        };
        let out = c.apply([0.0, 0.0, 0.0, 0.125], [0.0, 0.0, 0.0, 0.375], [0.0, 0.0, 0.0, 0.25]);
        assert_eq!(out, [0.75, 0.75, 0.75, 1.0]);
        assert_eq!(texture_source(GL_ALPHA, [0.3, 0.3, 0.3, 0.7]), [0.0, 0.0, 0.0, 0.7]);
        assert_eq!(texture_source(GL_LUMINANCE, [0.3, 0.0, 0.0, 0.7]), [0.3, 0.3, 0.3, 1.0]);
    }

    #[test]
    fn set_takes_what_mesa_takes() {
        let mut c = Combine::default();
        assert_eq!(c.set(GL_COMBINE_ALPHA, GL_DOT3_RGB as f32), Err(GL_INVALID_ENUM));
        assert_eq!(c.set(GL_COMBINE_RGB, GL_DOT3_RGBA as f32), Ok(()));
        assert_eq!(c.set(GL_SOURCE2_ALPHA, GL_TEXTURE7 as f32), Ok(()));
        assert_eq!(c.set(GL_SOURCE2_ALPHA, (GL_TEXTURE7 + 1) as f32), Err(GL_INVALID_ENUM));
        assert_eq!(c.set(GL_OPERAND1_ALPHA, GL_SRC_COLOR as f32), Err(GL_INVALID_ENUM));
        assert_eq!(c.set(GL_RGB_SCALE, 1.5), Err(GL_INVALID_VALUE));
        assert_eq!(c.set(GL_ALPHA_SCALE, 4.0), Ok(()));
        assert_eq!(
            (c.get(GL_COMBINE_RGB), c.get(GL_SOURCE2_ALPHA), c.get(GL_ALPHA_SCALE)),
            (GL_DOT3_RGBA as f32, GL_TEXTURE7 as f32, 4.0)
        );
    }
}
