//! The vertex stage (GL 1.1 spec §2.10–2.13): the modelview and projection transforms, texture
//! coordinate generation and the texture matrix, and per-vertex lighting (§2.13.1, evaluated
//! on the CPU in `f32`, in eye coordinates, with GL's defaults). It is the one stage every
//! consumer of a recorded primitive shares: both rasterisers (`render::assemble` builds its
//! corners from a [`ShadedVertex`]) and feedback and selection (`feedback_prims` clips
//! [`ShadedVertex`]es itself, as Mesa's draw module does).

use super::clip::Mix;
use super::consts::*;
use super::{DrawState, Lighting, Material, Vertex};
use glam::{Mat3, Vec3, Vec4, Vec4Swizzles};

/// Per-primitive constants derived from a [`DrawState`] once.
pub(crate) struct Shader<'a> {
    state: &'a DrawState,
    normal_matrix: Mat3,
}

/// A vertex after the vertex stage: clip-space position, its front and back colours and
/// secondary colours, its texture coordinates through the texture matrix (zero without a
/// texture) and its fog coordinate, the eye-space distance |z| (Mesa's default,
/// `GL_EYE_PLANE_ABSOLUTE_NV`).
///
/// The secondary colour is what the colour sum adds after texturing (GL 1.4 §3.9), zero where
/// no sum is made: lit, the specular terms with `GL_SEPARATE_SPECULAR_COLOR` (GL 1.2 §2.13.1)
/// and zero with `GL_SINGLE_COLOR`; unlit, the vertex's `glSecondaryColor` when `GL_COLOR_SUM`
/// is enabled. So every rasteriser adds it unconditionally.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ShadedVertex {
    pub clip: Vec4,
    /// The eye-space position, where clip planes are tested.
    pub eye: Vec4,
    pub front: Vec4,
    pub back: Vec4,
    pub front_secondary: Vec4,
    pub back_secondary: Vec4,
    pub tex: Vec4,
    /// Units 1 to 7's texture coordinates through their matrices (zero but for the units that
    /// draw, see [`Shader::unit_tex`]).
    pub units: [Vec4; 7],
    pub fog: f32,
}

/// Clipping interpolates every attribute linearly in clip space (GL 1.1 §2.11); the fog
/// coordinate too (feedback does not report it).
impl Mix for ShadedVertex {
    fn mix(self, other: Self, t: f32) -> Self {
        Self {
            clip: self.clip.lerp(other.clip, t),
            eye: self.eye.lerp(other.eye, t),
            front: self.front.lerp(other.front, t),
            back: self.back.lerp(other.back, t),
            front_secondary: self.front_secondary.lerp(other.front_secondary, t),
            back_secondary: self.back_secondary.lerp(other.back_secondary, t),
            tex: self.tex.lerp(other.tex, t),
            units: std::array::from_fn(|k| self.units[k].lerp(other.units[k], t)),
            fog: self.fog + (other.fog - self.fog) * t,
        }
    }
}

impl<'a> Shader<'a> {
    pub fn new(state: &'a DrawState) -> Self {
        Self { state, normal_matrix: state.normal_matrix() }
    }

    /// Transforms one vertex and lights it (or passes its colour through, clamped).
    pub fn shade(&self, v: &Vertex) -> ShadedVertex {
        let eye = self.state.modelview * Vec4::from_array(v.position);
        let clip = self.state.projection * eye;
        let color = Vec4::from_array(v.color);
        let tex = self.state.texture.as_ref().map_or(Vec4::ZERO, |t| {
            let given = Vec4::from_array(v.tex_coord);
            let generated =
                t.generate.map_or(given, |g| g.apply(given, Vec4::from_array(v.position), eye, self.eye_normal(v)));
            t.matrix * generated
        });
        let fog = match &self.state.fog {
            Some(f) if f.coord_source == GL_FOG_COORD => v.fog_coord.abs(),
            _ => eye.z.abs(),
        };
        let Some(lighting) = &self.state.lighting else {
            let c = color.clamp(Vec4::ZERO, Vec4::ONE);
            let summed = Vec4::from_array(v.secondary_color).truncate().clamp(Vec3::ZERO, Vec3::ONE).extend(0.0);
            let s = if self.state.color_sum { summed } else { Vec4::ZERO };
            let units = [Vec4::ZERO; 7];
            return ShadedVertex {
                clip,
                eye,
                front: c,
                back: c,
                front_secondary: s,
                back_secondary: s,
                tex,
                units,
                fog,
            };
        };
        let n = self.eye_normal(v);
        let position = if eye.w != 0.0 { eye.xyz() / eye.w } else { eye.xyz() };
        let (front, front_secondary) = self.light(lighting, 0, n, position, color);
        let (back, back_secondary) =
            if lighting.two_side { self.light(lighting, 1, -n, position, color) } else { (front, front_secondary) };
        ShadedVertex { clip, eye, front, back, front_secondary, back_secondary, tex, units: [Vec4::ZERO; 7], fog }
    }

    /// Units 1 to 7's texture coordinates of a vertex whose coordinates of those units are
    /// `coords`: for each unit that draws, generated where its `glTexGen` says, then through
    /// its texture matrix (GL 1.3 §2.10.2, §2.10.4: each unit's own), as unit 0's in
    /// [`Shader::shade`].
    pub fn unit_tex(&self, v: &Vertex, coords: &super::UnitTexCoords) -> [Vec4; 7] {
        let mut units = [Vec4::ZERO; 7];
        let eye = self.state.modelview * Vec4::from_array(v.position);
        for (unit, t) in &self.state.more_textures {
            let given = Vec4::from_array(coords[unit - 1]);
            let generated =
                t.generate.map_or(given, |g| g.apply(given, Vec4::from_array(v.position), eye, self.eye_normal(v)));
            units[unit - 1] = t.matrix * generated;
        }
        units
    }

    /// The vertex's normal in eye coordinates, rescaled by `GL_RESCALE_NORMAL` and normalised
    /// by `GL_NORMALIZE` (what lighting and the sphere and normal maps read).
    fn eye_normal(&self, v: &Vertex) -> Vec3 {
        self.state.eye_normal(self.normal_matrix, v.normal)
    }

    /// The material of `face` with `GL_COLOR_MATERIAL` applied.
    fn material(&self, lighting: &Lighting, face: usize, color: Vec4) -> Material {
        let mut m = lighting.materials[face];
        let (cm_face, mode) = lighting.color_material;
        let face_enum = if face == 0 { GL_FRONT } else { GL_BACK };
        if self.state.color_material && (cm_face == face_enum || cm_face == GL_FRONT_AND_BACK) {
            match mode {
                GL_AMBIENT => m.ambient = color,
                GL_DIFFUSE => m.diffuse = color,
                GL_SPECULAR => m.specular = color,
                GL_EMISSION => m.emission = color,
                _ => {
                    m.ambient = color;
                    m.diffuse = color;
                }
            }
        }
        m
    }

    /// The primary and secondary colours of one face (GL 1.2 §2.13.1): the specular terms go
    /// to the secondary colour with `GL_SEPARATE_SPECULAR_COLOR`, else to the primary one.
    fn light(&self, lighting: &Lighting, face: usize, n: Vec3, position: Vec3, color: Vec4) -> (Vec4, Vec4) {
        let m = self.material(lighting, face, color);
        let mut sum = m.emission.xyz() + m.ambient.xyz() * lighting.model_ambient.xyz();
        let mut specular_sum = Vec3::ZERO;
        for light in lighting.lights.iter().filter(|l| l.enabled) {
            let (vp, attenuation) = if light.position.w == 0.0 {
                (light.position.xyz().normalize_or_zero(), 1.0)
            } else {
                let d = light.position.xyz() / light.position.w - position;
                let dist = d.length();
                let k = light.attenuation;
                (d.normalize_or_zero(), 1.0 / (k.x + k.y * dist + k.z * dist * dist))
            };
            let spot = spot_factor(light.spot_cutoff, light.spot_exponent, light.spot_direction, vp);
            let n_dot_vp = n.dot(vp);
            let mut c = m.ambient.xyz() * light.ambient.xyz();
            let mut specular = Vec3::ZERO;
            if n_dot_vp > 0.0 {
                c += n_dot_vp * m.diffuse.xyz() * light.diffuse.xyz();
                let eye_dir = if lighting.local_viewer { -position.normalize_or_zero() } else { Vec3::Z };
                let h = (vp + eye_dir).normalize_or_zero();
                let n_dot_h = n.dot(h).max(0.0);
                specular = n_dot_h.powf(m.shininess) * m.specular.xyz() * light.specular.xyz();
            }
            sum += attenuation * spot * c;
            specular_sum += attenuation * spot * specular;
        }
        let (primary, secondary) =
            if lighting.separate_specular() { (sum, specular_sum) } else { (sum + specular_sum, Vec3::ZERO) };
        (primary.extend(m.diffuse.w).clamp(Vec4::ZERO, Vec4::ONE), secondary.clamp(Vec3::ZERO, Vec3::ONE).extend(0.0))
    }
}

/// The spotlight factor: 1 without a spot (cutoff 180), 0 outside the cone, else
/// (−VP · s)^exponent.
fn spot_factor(cutoff: f32, exponent: f32, direction: Vec3, vp: Vec3) -> f32 {
    if cutoff == 180.0 {
        return 1.0;
    }
    let cos_angle = (-vp).dot(direction.normalize_or_zero());
    if cos_angle < cutoff.to_radians().cos() {
        0.0
    } else {
        cos_angle.max(0.0).powf(exponent)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::Gl;

    fn state_with_light0() -> DrawState {
        let mut gl = Gl::new(10, 10);
        gl.enable(GL_LIGHTING);
        gl.enable(GL_LIGHT0);
        gl.begin(GL_POINTS);
        gl.end();
        gl.take_frame().states.remove(0)
    }

    #[test]
    fn default_light0_on_facing_normal() {
        // Light 0 at (0,0,1,0), white; material defaults: 0.2 ambient x 0.2 model ambient +
        // 0.8 diffuse x 1 = 0.84, alpha = diffuse alpha 1 (GL 1.1 spec defaults).
        let state = state_with_light0();
        let shader = Shader::new(&state);
        let v = Vertex { position: [0.0, 0.0, 0.0, 1.0], normal: [0.0, 0.0, 1.0], ..Vertex::default() };
        let c = shader.shade(&v).front;
        assert!((c - Vec4::new(0.84, 0.84, 0.84, 1.0)).abs().max_element() < 1e-6, "{c:?}");
        // Facing away: ambient only, 0.04.
        let v = Vertex { normal: [0.0, 0.0, -1.0], ..v };
        assert!((shader.shade(&v).front.x - 0.04).abs() < 1e-6);
    }

    #[test]
    fn unlit_colour_is_clamped() {
        let mut gl = Gl::new(10, 10);
        gl.begin(GL_POINTS);
        gl.end();
        let state = gl.take_frame().states.remove(0);
        let v = Vertex { color: [2.0, -1.0, 0.5, 1.0], ..Vertex::default() };
        assert_eq!(Shader::new(&state).shade(&v).front, Vec4::new(1.0, 0.0, 0.5, 1.0));
    }
}
