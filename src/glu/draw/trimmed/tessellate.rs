//! Trimmed surfaces in tessellator mode: the grid cells wholly inside the loops as
//! `GL_QUAD_STRIP`s, as GLU issues its grid blocks, and the band along the loops as
//! `GL_TRIANGLES`, each point evaluated once.

use super::domain::BY_CELLS;
use super::values::{LatticeValues, PointValues};
use super::Region;
use crate::gl::consts::*;
use crate::gl::Gl;
use crate::glu::consts::*;
use crate::glu::draw::emit::emit_attributes;
use crate::glu::evaluation::surface::Surface;
use crate::glu::model::callbacks::StripSink;
use crate::glu::model::object::NurbsObject;
use crate::tess::trim::{GridStrip, Lattice, TrimPlan};

/// Tessellator mode. The sampling lattice is evaluated on the pool while this thread checks the
/// loops and splits the region ([`TrimPlan`]); then, when only begin, vertex and end callbacks
/// are registered, the pool triangulates the band along the loops (cell by cell) while this
/// thread issues the grid cells wholly inside, a `GL_QUAD_STRIP` per run, as GLU issues its grid
/// blocks; the band follows as `GL_TRIANGLES`. Each point is evaluated once.
pub(super) fn tessellate_trimmed(gl: &mut Gl, obj: &mut NurbsObject, region: &Region) {
    let Region { surface, loops, domain, us, vs } = *region;
    let lattice = Lattice::lines(domain, us, vs);
    let mut values = None;
    let plan = rayon::in_place_scope(|scope| {
        scope.spawn(|_| values = LatticeValues::evaluate(&surface.pos, surface.k, lattice));
        TrimPlan::new(loops, domain, us, vs, &BY_CELLS)
    });
    let plan = match plan {
        Ok(plan) => plan,
        Err(e) => return obj.nurbs_error(e.glu_number()),
    };
    let mut values = values.filter(|v| plan.lattice_lines() == (&v.lattice.u[..], &v.lattice.v[..]));
    let mut band = None;
    if let (Some(lattice), Some(mut sinks)) = (&values, obj.callbacks.sinks()) {
        rayon::in_place_scope(|scope| {
            scope.spawn(|_| band = Some(plan.triangulate_band()));
            let value = |i: u32| lattice.values[plan.grid_index()[i as usize] as usize].as_ref();
            match sinks.plain() {
                Some(mut plain) => issue_strips(gl, &mut plain, plan.strips(), value),
                None => issue_strips(gl, &mut sinks, plan.strips(), value),
            }
        });
        if let Some(Ok(band)) = &band {
            let data = PointValues::new(surface, plan.grid_points(), plan.grid_index(), &band.points, values.take());
            match sinks.plain() {
                Some(mut plain) => issue_band(gl, &mut plain, &band.triangles, |i| data.get(i)),
                None => issue_band(gl, &mut sinks, &band.triangles, |i| data.get(i)),
            }
            return;
        }
    }
    // A band that failed after the strips went out is reported as GLU reports a bad trim.
    let band = match band.unwrap_or_else(|| plan.triangulate_band()) {
        Ok(band) => band,
        Err(e) => return obj.nurbs_error(e.glu_number()),
    };
    let mesh = plan.into_mesh(band);
    let (grid_points, extra) = mesh.points.split_at(mesh.lattice.index.len());
    let data = PointValues::new(surface, grid_points, &mesh.lattice.index, extra, values);
    if let Some(mut sinks) = obj.callbacks.sinks() {
        issue_strips(gl, &mut sinks, &mesh.strips, |i| data.get(i));
        return issue_band(gl, &mut sinks, &mesh.band, |i| data.get(i));
    }
    issue_per_vertex(gl, obj, surface, &mesh.points, (&mesh.strips, &mesh.band), &data);
}

/// The strips and the band when other callbacks are registered: attributes and normals per
/// vertex, before the position.
fn issue_per_vertex(
    gl: &mut Gl,
    obj: &mut NurbsObject,
    surface: &Surface,
    points: &[[f64; 2]],
    (strips, band): (&[GridStrip], &[[u32; 3]]),
    data: &PointValues<'_>,
) {
    let per_vertex = !surface.attributes.is_empty() || obj.callbacks.wants_normals();
    let emit = |gl: &mut Gl, obj: &mut NurbsObject, i: u32| {
        let [u, v] = points[i as usize];
        if per_vertex {
            emit_attributes(gl, obj, surface.view_ref(), u, v);
        }
        if let Some(d) = data.get(i) {
            obj.callbacks.attribute(gl, GLU_NURBS_VERTEX, d);
        }
    };
    for strip in strips {
        obj.callbacks.begin(gl, GL_QUAD_STRIP);
        for (top, bottom) in strip_pairs(*strip) {
            emit(gl, obj, top);
            emit(gl, obj, bottom);
        }
        obj.callbacks.end(gl);
    }
    if !band.is_empty() {
        obj.callbacks.begin(gl, GL_TRIANGLES);
        band.iter().flatten().for_each(|&i| emit(gl, obj, i));
        obj.callbacks.end(gl);
    }
}

/// The grid strips, a `GL_QUAD_STRIP` per run of cells, through the fast callbacks.
fn issue_strips<'v>(
    gl: &mut Gl,
    sinks: &mut impl StripSink,
    strips: &[GridStrip],
    value: impl Fn(u32) -> Option<&'v [f32; 5]>,
) {
    for strip in strips {
        sinks.begin(gl, GL_QUAD_STRIP);
        for (top, bottom) in strip_pairs(*strip) {
            for d in [top, bottom].into_iter().filter_map(&value) {
                sinks.vertex(gl, d);
            }
        }
        sinks.end(gl);
    }
}

/// The band's triangles as `GL_TRIANGLES` through the fast callbacks.
fn issue_band<'v>(
    gl: &mut Gl,
    sinks: &mut impl StripSink,
    triangles: &[[u32; 3]],
    value: impl Fn(u32) -> Option<&'v [f32; 5]>,
) {
    if !triangles.is_empty() {
        sinks.begin(gl, GL_TRIANGLES);
        triangles.iter().flatten().filter_map(|&i| value(i)).for_each(|d| sinks.vertex(gl, d));
        sinks.end(gl);
    }
}

/// A run's (top, bottom) point pairs by increasing u: as a `GL_QUAD_STRIP`, quads
/// top, bottom, next bottom, next top: counter-clockwise in (u, v).
fn strip_pairs(strip: GridStrip) -> impl Iterator<Item = (u32, u32)> {
    (0..=strip.cells).map(move |i| (strip.top + i, strip.bottom + i))
}
