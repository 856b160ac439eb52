//! A surface ready to draw: its position map and attribute maps as Bezier patches, and each
//! patch with the grid GLU samples it with ([`PatchGrid`]).

use super::pieces::SurfacePatches;
use super::sampling::Sampler;
use crate::glu::model::maps::SurfaceDef;
use crate::glu::model::object::NurbsObject;
use crate::glu::model::targets::{attribute_rank, is_position};

/// One Bezier patch of the position map and its sampling grid: `nu` × `nv` segments over
/// [u0, u1] × [v0, v1].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct PatchGrid {
    /// (u0, u1).
    pub u: (f64, f64),
    /// (v0, v1).
    pub v: (f64, f64),
    /// Segments along u.
    pub nu: usize,
    /// Segments along v.
    pub nv: usize,
}

impl PatchGrid {
    /// Grid points, (nu + 1)(nv + 1), saturating.
    pub fn points(&self) -> usize {
        (self.nu + 1).saturating_mul(self.nv + 1)
    }
}

/// Everything needed to draw a surface: the position map's patches and the other maps'.
pub(crate) struct Surface {
    pub pos: SurfacePatches,
    /// The other maps, in GLU's callback order ([`attribute_rank`]).
    pub attributes: Vec<SurfacePatches>,
    /// The position map's components: 3, or 4 (rational).
    pub k: usize,
}

impl Surface {
    /// The surface of `def`; `None` (after GLU's error 8 when there is no position map) if it
    /// has nothing to draw.
    pub fn new(obj: &mut NurbsObject, def: &SurfaceDef) -> Option<Self> {
        let Some(position) = def.maps.iter().rev().find(|m| is_position(m.target)) else {
            obj.nurbs_error(8);
            return None;
        };
        let pos = SurfacePatches::new(position)?;
        let mut attributes: Vec<SurfacePatches> =
            def.maps.iter().filter(|m| !is_position(m.target)).filter_map(SurfacePatches::new).collect();
        attributes.sort_by_key(|p| attribute_rank(p.target));
        Some(Self { pos, attributes, k: position.k })
    }

    /// The parameter domain [u0, u1, v0, v1] of the position map.
    pub fn domain(&self) -> [f64; 4] {
        let p = &self.pos.patches;
        let (u, v) = (&p.uintervals, &p.vintervals);
        [u[0].0, u[u.len() - 1].1, v[0].0, v[v.len() - 1].1]
    }

    /// Every patch with its grid, u outer.
    pub fn patches(&self, sampler: &Sampler) -> Vec<PatchGrid> {
        let p = &self.pos.patches;
        let mut out = Vec::new();
        for (a, &u) in p.uintervals.iter().enumerate() {
            for (b, &v) in p.vintervals.iter().enumerate() {
                let Some(points) = p.patch(a, b) else { continue };
                let (nu, nv) = sampler.patch_segments(points, self.k, (p.uorder, p.vorder), (u.1 - u.0, v.1 - v.0));
                out.push(PatchGrid { u, v, nu, nv });
            }
        }
        out
    }

    /// The position map, the attribute maps and k, as the per-vertex evaluations take them.
    pub fn view_ref(&self) -> (&SurfacePatches, &[SurfacePatches], usize) {
        (&self.pos, &self.attributes, self.k)
    }
}
