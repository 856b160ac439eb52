//! One surface vertex through the callbacks as GLU's tessellator mode hands it out
//! (`inDoEvalCoord2EM`, `interface/insurfeval.cc`): the texture coordinate, colour and normal
//! maps' values in that order, else the automatic normal when a normal callback is set, then the
//! position (x, y, z divided by w) with (u, v). Every map is evaluated on the current patch by
//! GLU's `f32` evaluator ([`PatchMachine`]).

use crate::gl::Gl;
use crate::glu::consts::*;
use crate::glu::evaluation::machine::{MachineSample, PatchMachine};
use crate::glu::evaluation::surface::Surface;
use crate::glu::model::object::NurbsObject;
use crate::glu::model::targets::callback_kind;

/// The maps of one patch, ready to evaluate.
pub(crate) struct PatchVertices {
    position: PatchMachine,
    /// Attribute maps with their callback and component count, in callback order.
    attributes: Vec<(PatchMachine, u32, usize)>,
    has_normal_map: bool,
    auto_normal: bool,
}

impl PatchVertices {
    /// The machines of the patch [u0, u1] × [v0, v1]; `None` if the position map has none.
    pub fn new(obj: &NurbsObject, surface: &Surface, u: (f64, f64), v: (f64, f64)) -> Option<Self> {
        let machine = |map: &crate::glu::evaluation::pieces::SurfacePatches| {
            let p = &map.patches;
            let points = map.on(u, v)?;
            PatchMachine::new(&points, p.dim, (p.uorder, p.vorder), (u.0 as f32, u.1 as f32), (v.0 as f32, v.1 as f32))
        };
        // Only the automatic normal reads a map's partials.
        let attributes: Vec<(PatchMachine, u32, usize)> = surface
            .attributes
            .iter()
            .filter_map(|map| Some((machine(map)?.without_partials(), callback_kind(map.target)?, map.patches.dim)))
            .collect();
        let has_normal_map = attributes.iter().any(|a| a.1 == GLU_NURBS_NORMAL);
        let auto_normal = obj.callbacks.wants_normals();
        let position = machine(&surface.pos)?;
        let position = if auto_normal && !has_normal_map { position } else { position.without_partials() };
        Some(Self { position, attributes, has_normal_map, auto_normal })
    }

    /// The position map's machine, shareable between threads (the only map whose values reach
    /// the callbacks when only begin, vertex and end callbacks are set).
    pub fn positions(&self) -> crate::glu::evaluation::machine::Positions<'_> {
        self.position.positions()
    }

    /// The callbacks of the vertex at (u, v).
    pub fn emit(&self, gl: &mut Gl, obj: &mut NurbsObject, u: f32, v: f32) {
        self.emit_with(gl, obj, (u, v), |machine| machine.sample(u, v));
    }

    /// Every map sampled over the grid `us` × `vs` (v outer), for [`Self::emit_sampled`]; a map
    /// on an empty patch has no samples.
    pub fn sample_grid(&self, us: &[f32], vs: &[f32]) -> GridSamples {
        let maps = self.attributes.iter().map(|a| &a.0).chain([&self.position]);
        GridSamples { maps: maps.map(|m| m.sample_grid(us, vs)).collect() }
    }

    /// [`Self::emit`] for sample `index` of `samples` (at (u, v)): the same callbacks.
    pub fn emit_sampled(
        &self,
        gl: &mut Gl,
        obj: &mut NurbsObject,
        samples: &GridSamples,
        index: usize,
        u: f32,
        v: f32,
    ) {
        let mut maps = samples.maps.iter();
        self.emit_with(gl, obj, (u, v), |_| maps.next()?.as_ref()?.get(index).copied());
    }

    /// The callbacks of the vertex at (u, v), `sample` giving each map's sample there in turn
    /// (the attribute maps in callback order, then the position map).
    fn emit_with(
        &self,
        gl: &mut Gl,
        obj: &mut NurbsObject,
        (u, v): (f32, f32),
        mut sample: impl FnMut(&PatchMachine) -> Option<MachineSample>,
    ) {
        for (machine, kind, dim) in &self.attributes {
            if let Some(values) = sample(machine) {
                obj.callbacks.attribute(gl, *kind, &values.point[..*dim]);
            }
        }
        let Some(at) = sample(&self.position) else { return };
        let point = if !self.has_normal_map && self.auto_normal {
            let Some((point, normal)) = self.position.point_and_normal_of(at, u, v) else { return };
            obj.callbacks.attribute(gl, GLU_NURBS_NORMAL, &normal);
            point
        } else {
            self.position.position_of(&at)
        };
        obj.callbacks.attribute(gl, GLU_NURBS_VERTEX, &[point[0], point[1], point[2], u, v]);
    }
}

/// Every map's samples over a grid (see [`PatchVertices::sample_grid`]).
pub(crate) struct GridSamples {
    maps: Vec<Option<Vec<MachineSample>>>,
}
