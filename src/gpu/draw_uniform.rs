//! GL's state for the mesh rasteriser's vertex and fragment stages, as the draw uniform of
//! `shaders/mesh_raster.wgsl` ([`GpuDraw`]): matrices (the texture's too), the viewport as a clip transform,
//! lighting, materials and lights, with GL's meaning of each field (GL 1.1 spec §2.13).

use super::layout::{GpuDraw, GpuLight, GpuMaterial};
use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::gl::{DrawState, Light, Lighting, Material, Vertex};
use glam::Mat4;

fn light_uniform(l: &Light) -> GpuLight {
    let spot = l.spot_cutoff != 180.0;
    GpuLight {
        ambient: l.ambient.to_array(),
        diffuse: l.diffuse.to_array(),
        specular: l.specular.to_array(),
        position: l.position.to_array(),
        spot_direction: l.spot_direction.extend(l.spot_exponent).to_array(),
        params: [f32::from(u8::from(l.enabled)), f32::from(u8::from(spot)), l.spot_cutoff.to_radians().cos(), 0.0],
        attenuation: l.attenuation.extend(0.0).to_array(),
    }
}

fn material_uniform(m: &Material) -> GpuMaterial {
    GpuMaterial {
        ambient: m.ambient.to_array(),
        diffuse: m.diffuse.to_array(),
        specular: m.specular.to_array(),
        emission: m.emission.to_array(),
        shininess: [m.shininess, 0.0, 0.0, 0.0],
    }
}

fn flag(b: bool) -> f32 {
    f32::from(u8::from(b))
}

/// The draw uniform of a mesh drawn with `state` into a `width` × `height` target, whose
/// vertices' secondary colour and fog coordinate are `template`'s (the current ones when it was
/// recorded: no map evaluates them).
/// With `flip` the target is drawn upside down (the renderer's headless frames).
#[must_use]
pub(crate) fn draw_uniform(
    state: &DrawState,
    (polygon, template): (bool, &Vertex),
    (width, height): (u32, u32),
    flip: bool,
) -> GpuDraw {
    let normal_matrix = Mat4::from_mat3(state.normal_matrix());
    // GL 1.4's GL_FOG_COORD_SRC: the fog coordinate instead of the eye distance (as
    // `gl::shade`, Mesa's absolute value).
    let fog_from_coord = state.fog.is_some_and(|f| f.coord_source == GL_FOG_COORD);
    let [vx, vy, vw, vh] = state.viewport.map(|c| c as f32);
    let (fw, fh) = (width as f32, height as f32);
    let sign = if flip { -1.0 } else { 1.0 };
    let viewport = [vw / fw, (2.0 * vx + vw) / fw - 1.0, sign * vh / fh, sign * ((2.0 * vy + vh) / fh - 1.0)];
    let mut draw = GpuDraw {
        modelview: state.modelview.to_cols_array_2d(),
        projection: state.projection.to_cols_array_2d(),
        normal_matrix: normal_matrix.to_cols_array_2d(),
        texture_matrix: state.texture.as_ref().map_or(Mat4::IDENTITY, |t| t.matrix).to_cols_array_2d(),
        viewport,
        depth_range: [state.depth_range[0], state.depth_range[1], 0.0, 0.0],
        primitive: [flag(polygon), flag(fog_from_coord), template.fog_coord.abs(), 0.0],
        ..GpuDraw::default()
    };
    if state.color_sum && state.lighting.is_none() {
        let [r, g, b, _] = template.secondary_color.map(|c| c.clamp(0.0, 1.0));
        draw.color_sum = [r, g, b, 0.0];
    }
    if let Some(l) = &state.lighting {
        set_lighting(&mut draw, state, l);
    }
    draw
}

/// The lighting fields, while `GL_LIGHTING` is on (they stay zero while it is off).
fn set_lighting(draw: &mut GpuDraw, state: &DrawState, l: &Lighting) {
    draw.flags = [1.0, flag(l.two_side), flag(l.local_viewer), flag(state.normalize)];
    draw.color_sum = [0.0, 0.0, 0.0, flag(l.separate_specular())];
    let (face, mode) = l.color_material;
    let on = |f: GLenum| flag(state.color_material && (face == f || face == GL_FRONT_AND_BACK));
    let mode = match mode {
        GL_AMBIENT => 0.0,
        GL_DIFFUSE => 1.0,
        GL_SPECULAR => 2.0,
        GL_EMISSION => 3.0,
        _ => 4.0,
    };
    draw.color_material = [on(GL_FRONT), on(GL_BACK), mode, 0.0];
    draw.model_ambient = l.model_ambient.to_array();
    draw.materials = [material_uniform(&l.materials[0]), material_uniform(&l.materials[1])];
    draw.lights = std::array::from_fn(|i| light_uniform(&l.lights[i]));
}
