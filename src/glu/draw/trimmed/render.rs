//! Trimmed surfaces in renderer mode: the triangulation as `GL_TRIANGLES` (each vertex
//! evaluated as GL's evaluators would for GLU's `glEvalCoord2f`), the trim loops as line loops
//! for `GLU_OUTLINE_PATCH`, or the GPU tessellator's scattered mesh. The polygon mode is saved
//! and restored as GLU's `bgnmap2f`/`endmap2f` do (`glsurfeval.cc`).

use super::domain::BY_CELLS;
use super::gpu::record_on_gpu;
use super::Region;
use crate::gl::consts::*;
use crate::gl::{Gl, MeshMode, Slot, Tessellator, Vertex};
use crate::glu::consts::*;
use crate::glu::evaluation::normals::surface_normal;
use crate::glu::evaluation::surface::Surface;
use crate::glu::model::object::NurbsObject;
use crate::tess::trim::{triangulate_with, TrimLoop};

/// Draws the trimmed region through GL calls, in the object's display mode.
pub(super) fn render_trimmed(gl: &mut Gl, obj: &mut NurbsObject, region: &Region) {
    let Region { surface, loops, domain, us, vs } = *region;
    let mesh = match triangulate_with(loops, domain, us, vs, &BY_CELLS) {
        Ok(m) => m,
        Err(e) => return obj.nurbs_error(e.glu_number()),
    };
    // Evaluated vertices take GL's normal when `GL_AUTO_NORMAL` is on, as GL's evaluator does.
    let auto_normal = gl.capability(GL_AUTO_NORMAL);
    if obj.props.display_mode == GLU_OUTLINE_PATCH {
        return outline_loops(gl, surface, loops, auto_normal);
    }
    let saved_mode = gl.polygon_modes();
    if obj.props.display_mode == GLU_OUTLINE_POLYGON {
        gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
    } else {
        gl.polygon_mode(GL_FRONT_AND_BACK, GL_FILL);
    }
    if gl.tessellator() == Tessellator::Gpu && obj.props.display_mode == GLU_FILL && gl.gpu_draws(MeshMode::Triangles) {
        record_on_gpu(gl, surface, &mesh.points, mesh.triangles(), auto_normal);
    } else {
        // Each point evaluated once; the triangles issue the shared vertices.
        let vertices: Vec<Option<Vertex>> =
            mesh.points.iter().map(|&[u, v]| trimmed_vertex(gl, surface, u, v, auto_normal)).collect();
        gl.begin(GL_TRIANGLES);
        for tri in mesh.triangles() {
            for i in tri {
                if let Some(vertex) = vertices[i as usize] {
                    gl.emit_listed_vertex(vertex);
                }
            }
        }
        gl.end();
    }
    gl.polygon_mode(GL_FRONT, saved_mode[0]);
    gl.polygon_mode(GL_BACK, saved_mode[1]);
}

/// `GLU_OUTLINE_PATCH` of a trimmed surface: the trim loops drawn on the surface.
fn outline_loops(gl: &mut Gl, surface: &Surface, loops: &[TrimLoop], auto_normal: bool) {
    for l in loops {
        gl.begin(GL_LINE_LOOP);
        for &[u, v] in &l.points {
            if let Some(vertex) = trimmed_vertex(gl, surface, u, v, auto_normal) {
                gl.emit_listed_vertex(vertex);
            }
        }
        gl.end();
    }
}

/// One vertex as GL's evaluators would produce it for GLU's `glEvalCoord2f`: evaluated
/// attributes over the current ones and, with `GL_AUTO_NORMAL` (`auto_normal`), the unit
/// normal. Evaluated values never become current.
fn trimmed_vertex(gl: &Gl, surface: &Surface, u: f64, v: f64, auto_normal: bool) -> Option<Vertex> {
    let (pos, attributes, k) = surface.view_ref();
    let mut vertex = gl.current_vertex([0.0, 0.0, 0.0, 1.0]);
    for map in attributes {
        let (Some(s), Some(slot)) = (map.eval(u, v), crate::gl::MapTarget::from_enum(map.target).map(|t| t.slot))
        else {
            continue;
        };
        let p = [s.point[0] as f32, s.point[1] as f32, s.point[2] as f32, s.point[3] as f32];
        vertex.set_attribute(slot, p);
    }
    let s = pos.eval(u, v)?;
    if auto_normal {
        vertex.normal = surface_normal(pos, k, u, v, surface.domain());
    }
    let p = [s.point[0] as f32, s.point[1] as f32, s.point[2] as f32, s.point[3] as f32];
    vertex.set_attribute(if k == 4 { Slot::Vertex4 } else { Slot::Vertex3 }, p);
    Some(vertex)
}
