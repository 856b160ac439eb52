//! Trimmed surfaces on the GPU tessellator: the triangulation's points evaluated on the GPU,
//! one scattered job per Bezier piece.

use crate::gl::{Gl, MapSample, MapTarget, MeshJob};
use crate::glu::evaluation::pieces::locate;
use crate::glu::evaluation::surface::Surface;
use std::collections::BTreeMap;

/// The GPU tessellator's trimmed surface: the triangulation's (u, v) points grouped by the
/// Bezier piece they lie on, one scattered job per piece (its control points and the points'
/// parameters normalised to it), drawn as GL_TRIANGLES over the triangulation.
pub(super) fn record_on_gpu(
    gl: &mut Gl,
    surface: &Surface,
    points: &[[f64; 2]],
    triangles: impl Iterator<Item = [u32; 3]>,
    auto_normal: bool,
) {
    let p = &surface.pos.patches;
    let mut pieces: BTreeMap<(usize, usize), Vec<usize>> = BTreeMap::new();
    for (k, &[u, v]) in points.iter().enumerate() {
        let (Some(a), Some(b)) = (locate(&p.uintervals, u), locate(&p.vintervals, v)) else { return };
        pieces.entry((a, b)).or_default().push(k);
    }
    let template = gl.current_vertex([0.0, 0.0, 0.0, 1.0]);
    let mut renumbered = vec![0u32; points.len()];
    let mut jobs = Vec::with_capacity(pieces.len());
    for ((a, b), members) in pieces {
        let maps = piece_maps(surface, (p.uintervals[a], p.vintervals[b]), points, &members);
        let first: usize = jobs.iter().map(MeshJob::len).sum();
        for (n, &k) in members.iter().enumerate() {
            renumbered[k] = (first + n) as u32;
        }
        let nu = members.len();
        jobs.push(MeshJob { maps, auto_normal, template, nu, nv: 1, scattered: true });
    }
    let triangles = triangles.flat_map(|t| t.map(|i| renumbered[i as usize])).collect();
    gl.record_scattered_mesh(jobs, triangles);
}

/// Every map restricted to the piece over `(u, v)`, with the parameters of the piece's
/// `members` among `points`, normalised to it.
fn piece_maps(
    surface: &Surface,
    (u, v): ((f64, f64), (f64, f64)),
    points: &[[f64; 2]],
    members: &[usize],
) -> Vec<MapSample> {
    let mut maps = Vec::new();
    for map in surface.attributes.iter().chain([&surface.pos]) {
        let (Some(target), Some(control)) = (MapTarget::from_enum(map.target), map.on(u, v)) else { continue };
        let slot = target.slot;
        let norm = |x: f64, (x0, x1): (f64, f64)| ((x - x0) / (x1 - x0)) as f32;
        maps.push(MapSample {
            slot,
            uorder: map.patches.uorder,
            vorder: map.patches.vorder,
            points: control.iter().map(|&c| c as f32).collect(),
            us: members.iter().map(|&k| norm(points[k][0], u)).collect(),
            vs: members.iter().map(|&k| norm(points[k][1], v)).collect(),
        });
    }
    maps
}
