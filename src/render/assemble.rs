//! Primitive assembly: turns a recorded [`Frame`] into a [`DrawList`] of clip-space triangles,
//! lines and points that any rasteriser (wgpu here) draws without further GL knowledge.
//!
//! Done on the CPU, as GL's fixed-function stages define them (GL 1.1 spec §2.6, §3.3–3.5):
//! per-vertex transform and lighting, polygon orientation in window space, face culling,
//! two-sided colour selection, flat shading with GL's provoking vertices, polygon modes with
//! polygon edges (no interior diagonals of quads and polygons), and GL's aliased wide lines
//! (widened along the minor axis) and square points, which wgpu does not have, as quads.

use super::corner::Corner;
use super::stipple::Stipple;
use super::{clip, offset, smooth};
use crate::gl::consts::*;
use crate::gl::shade::{ShadedVertex, Shader};
use crate::gl::types::GLenum;
use crate::gl::{
    Accumulation, BoundTexture, Command, DrawState, Fog, FragmentTests, Frame, MeshVertices, UnitTexCoords, Vertex,
};
use glam::Vec4;

/// A vertex ready for the rasteriser: clip position (depth already mapped to [0, 1] through
/// `glDepthRange`), the final colour and the secondary colour the colour sum adds after
/// texturing (GL 1.4 §3.9; zero without a sum), and the texture coordinates (s, t, r, q)
/// after the texture matrix (the rasteriser divides by q per fragment).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
#[cfg_attr(feature = "gpu", derive(bytemuck::Pod, bytemuck::Zeroable))]
pub struct RasterVertex {
    /// Clip-space x, y, z, w with z in wgpu's [0, w] convention.
    pub clip: [f32; 4],
    /// RGBA in [0, 1].
    pub color: [f32; 4],
    /// The secondary colour's RGB in [0, 1] (alpha unused), added after texturing.
    pub secondary: [f32; 4],
    /// (s, t, r, q); zero when the batch has no texture.
    pub tex: [f32; 4],
    /// The fog coordinate: eye-space distance.
    pub fog: f32,
    /// A smooth point's or line's coverage coordinates (zero otherwise; see [`Smooth`]).
    pub aa: [f32; 4],
}

/// Which coverage a batch's fragments compute from [`RasterVertex::aa`] (Mesa's smooth
/// points and lines, `render::smooth`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Smooth {
    /// None: the fragments keep their alpha.
    #[default]
    None,
    /// A smooth point's square: (u, v, k, 1).
    Point,
    /// A smooth line's rectangle: (across, half width, along, half length).
    Line,
}

/// What a batch draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Topology {
    /// Triangle list.
    Triangles,
    /// Line list of one-pixel lines.
    Lines,
    /// Point list of one-pixel points.
    Points,
}

/// A run of vertices drawn with one viewport and depth state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Batch {
    /// GL viewport: x, y, width, height, origin bottom-left.
    pub viewport: [i32; 4],
    /// The depth function, or `None` with the depth test disabled.
    pub depth_test: Option<GLenum>,
    /// Triangles, lines or points.
    pub topology: Topology,
    /// First vertex in [`DrawList::vertices`].
    pub first: u32,
    /// Number of vertices.
    pub count: u32,
    /// The texture, fog and alpha test, as an index into [`DrawList::fragments`]; `None`
    /// when the batch has none of them.
    pub fragment: Option<u32>,
    /// Blending's factors, equations and colour, when blending.
    pub blend: Option<crate::gl::Blend>,
    /// Scissor, stencil, write masks, logic op and draw buffers.
    pub tests: FragmentTests,
}

/// The GL viewport `[x, y, width, height]` (origin bottom-left) within a `width` × `height`
/// target, as target columns and rows (rows top to bottom), ends exclusive:
/// `[x0, top, x1, bottom]`; `None` when nothing of it is inside. Both rasterisers draw a batch
/// inside this rectangle only (GL's viewport clips; wgpu's scissor).
#[must_use]
pub(crate) fn viewport_in_target([x, y, w, h]: [i32; 4], (width, height): (u32, u32)) -> Option<[u32; 4]> {
    let (fw, fh) = (i64::from(width), i64::from(height));
    let x0 = i64::from(x).clamp(0, fw);
    let x1 = (i64::from(x) + i64::from(w)).clamp(0, fw);
    let top = (fh - i64::from(y) - i64::from(h)).clamp(0, fh);
    let bottom = (fh - i64::from(y)).clamp(0, fh);
    (x1 > x0 && bottom > top).then_some([x0 as u32, top as u32, x1 as u32, bottom as u32])
}

/// How many of a bucket's latest fragment states a new primitive's is compared with.
const RECENT_FRAGMENT_STATES: usize = 16;

/// What a batch's fragments go through before blending: texturing, fog, the alpha test.
#[derive(Clone, Debug, PartialEq)]
pub struct FragmentState {
    /// The texture and its environment.
    pub texture: Option<BoundTexture>,
    /// Units 1 to 7's textures that draw, with their units ([`DrawState::more_textures`]).
    pub more_textures: Vec<(usize, BoundTexture)>,
    /// Fog.
    pub fog: Option<Fog>,
    /// The alpha test's function and reference.
    pub alpha_test: Option<(GLenum, f32)>,
    /// The coverage of smooth points or lines.
    pub smooth: Smooth,
    /// The polygon stipple of filled polygons: row y, bit x for window pixel (x, y) mod 32.
    pub polygon_stipple: Option<[u32; 32]>,
}

/// A framebuffer operation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Op {
    /// Clear colour and/or depth.
    Clear {
        /// Colour to clear to, if the colour bit was set.
        color: Option<[f32; 4]>,
        /// Depth to clear to, if the depth bit was set.
        depth: Option<f32>,
        /// Stencil value to clear to, if the stencil bit was set.
        stencil: Option<i32>,
        /// Accumulation value to clear to, if the accumulation bit was set.
        accum: Option<[f32; 4]>,
        /// The scissor box, write masks and colour buffers of the clear.
        tests: FragmentTests,
    },
    /// `glAccum`.
    Accum(Accumulation),
    /// The back buffer becomes the front one.
    SwapBuffers,
    /// An occlusion query's slot starts (`begin`) or stops counting (see [`Command::Query`]).
    Query {
        /// The slot.
        slot: usize,
        /// Whether it starts.
        begin: bool,
    },
    /// Draw a batch.
    Draw(Batch),
    /// Draw a mesh of the frame whose vertices the GPU tessellator evaluates.
    GpuMesh {
        /// The mesh's index in the frame.
        mesh: usize,
        /// Its texture, fog and alpha test, as for [`Batch::fragment`].
        fragment: Option<u32>,
    },
    /// Execute copy `copy` of [`DrawList::pixel_copies`] (`glCopyPixels`): read the buffers as
    /// drawn so far and draw the copy's points ([`super::pixel_copy`]) with `batch`'s depth test,
    /// blending and fragment operations (its vertex range is empty until then).
    CopyPixels {
        /// Index in [`DrawList::pixel_copies`].
        copy: usize,
        /// The state its points are drawn with.
        batch: Batch,
    },
}

/// Everything to rasterise for one frame, in order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DrawList {
    /// All vertices.
    pub vertices: Vec<RasterVertex>,
    /// Clears and draws in program order.
    pub ops: Vec<Op>,
    /// The fragment states the batches are drawn with.
    pub fragments: Vec<FragmentState>,
    /// The `glCopyPixels` calls the ops execute.
    pub pixel_copies: Vec<crate::gl::PixelCopy>,
    /// Units 1 to 7's texture coordinates of `vertices[i]` (after their matrices), for the
    /// vertices of batches drawn with more units than unit 0: shorter than `vertices` where the
    /// rest draw with unit 0 alone (the single-unit lists keep it empty).
    pub unit_tex: Vec<UnitTexCoords>,
}

/// Assembles a frame, evaluating deferred (GPU) meshes on the CPU.
#[must_use]
pub fn assemble(frame: &Frame) -> DrawList {
    assemble_frame(frame, &[])
}

/// Assembles a frame; the meshes listed in `gpu_meshes` (sorted) stay [`Op::GpuMesh`] for the
/// GPU tessellator to evaluate and draw, every other mesh is assembled here.
#[must_use]
pub fn assemble_frame(frame: &Frame, gpu_meshes: &[usize]) -> DrawList {
    let mut out = Assembler::default();
    for command in &frame.commands {
        match *command {
            Command::Clear { mask, color, depth, stencil, accum, tests } => {
                out.clear(mask, (color, depth, stencil, accum), tests)
            }
            Command::Accum(accumulation) => out.list.ops.push(Op::Accum(accumulation)),
            Command::SwapBuffers => out.list.ops.push(Op::SwapBuffers),
            Command::Query { slot, begin } => out.list.ops.push(Op::Query { slot, begin }),
            Command::Draw(index) => {
                if let Some(p) = frame.primitives.get(index) {
                    if let Some(state) = frame.states.get(p.state) {
                        let materials: Vec<(usize, &DrawState)> = frame
                            .material_changes_of(index)
                            .into_iter()
                            .filter_map(|(vertex, s)| Some((vertex, frame.states.get(s)?)))
                            .collect();
                        let hidden = frame.hidden_edges_of(p);
                        let shape = (p.mode, p.listed_or_indexed);
                        let units = frame.unit_tex_coords_of(p);
                        out.lit_primitive(shape, (frame.vertices_of(p), &units), state, &materials, &hidden);
                    }
                }
            }
            Command::Mesh(index) => {
                let Some(mesh) = frame.meshes.get(index) else { continue };
                let Some(state) = frame.states.get(mesh.state) else { continue };
                if gpu_meshes.binary_search(&index).is_ok() && matches!(mesh.vertices, MeshVertices::Deferred(_)) {
                    // A mesh with smoothing or a polygon stipple is never left to the GPU.
                    let fragment = out.fragment_index(state, (Smooth::None, None));
                    out.list.ops.push(Op::GpuMesh { mesh: index, fragment });
                    continue;
                }
                let grid = mesh.evaluated();
                for (mode, indices) in mesh.primitives() {
                    let vertices: Vec<Vertex> = indices.iter().map(|&k| grid.vertex(k)).collect();
                    let units = if state.more_textures.is_empty() {
                        Vec::new()
                    } else {
                        vec![mesh.unit_tex_coords; vertices.len()]
                    };
                    out.lit_primitive((mode, false), (&vertices, &units), state, &[], &[]);
                }
            }
            Command::CopyPixels(index) => {
                let Some(copy) = frame.pixel_copies.get(index) else { continue };
                let Some(state) = frame.states.get(copy.state) else { continue };
                out.pixel_copy(copy, state);
            }
        }
    }
    out.list
}

#[derive(Default)]
struct Assembler {
    list: DrawList,
    /// `list.fragments`' indices by [`fragment_bucket`]: a frame may hold thousands of
    /// fragment states, and a linear search per primitive made assembling it quadratic.
    fragment_buckets: std::collections::HashMap<u64, Vec<u32>>,
}

/// A hash of the fragment state a primitive is drawn with: equal states (by `FragmentState`'s
/// `==`) share it, unequal ones rarely do. The texture is named by its key (object and image
/// version) and environment, its images are not read.
fn fragment_bucket(state: &DrawState, smooth: Smooth, polygon_stipple: Option<[u32; 32]>) -> u64 {
    use std::hash::{Hash, Hasher};
    let mut h = std::collections::hash_map::DefaultHasher::new();
    let bits = |values: &[f32], h: &mut std::collections::hash_map::DefaultHasher| {
        values.iter().for_each(|v| v.to_bits().hash(h))
    };
    for t in state.texture.iter().chain(state.more_textures.iter().map(|(_, t)| t)) {
        (t.key, t.base_format, t.env_mode, t.dims).hash(&mut h);
        bits(&t.env_color, &mut h);
        bits(&t.border_color, &mut h);
    }
    if let Some(f) = &state.fog {
        f.mode.hash(&mut h);
        bits(&[f.density, f.start, f.end], &mut h);
        bits(&f.color, &mut h);
    }
    if let Some((func, reference)) = state.alpha_test {
        func.hash(&mut h);
        bits(&[reference], &mut h);
    }
    (smooth, polygon_stipple).hash(&mut h);
    h.finish()
}

impl Assembler {
    /// A clear of the buffers `mask` names, to their clear values.
    fn clear(&mut self, mask: u32, values: ([f32; 4], f32, i32, [f32; 4]), tests: FragmentTests) {
        let has = |bit: u32| mask & bit != 0;
        let color = has(GL_COLOR_BUFFER_BIT).then_some(values.0);
        let depth = has(GL_DEPTH_BUFFER_BIT).then_some(values.1);
        let stencil = has(GL_STENCIL_BUFFER_BIT).then_some(values.2);
        let accum = has(GL_ACCUM_BUFFER_BIT).then_some(values.3);
        if color.is_some() || depth.is_some() || stencil.is_some() || accum.is_some() {
            self.list.ops.push(Op::Clear { color, depth, stencil, accum, tests });
        }
    }

    /// A `glCopyPixels`: its copy and the batch state its points will be drawn with.
    fn pixel_copy(&mut self, copy: &crate::gl::PixelCopy, state: &DrawState) {
        let fragment = self.fragment_index(state, (Smooth::None, None));
        let (viewport, depth_test, blend, tests) =
            (state.viewport, state.depth_test, state.blend, state.fragment_tests);
        let topology = Topology::Points;
        let batch = Batch { viewport, depth_test, topology, first: 0, count: 0, fragment, blend, tests };
        self.list.pixel_copies.push(copy.clone());
        self.list.ops.push(Op::CopyPixels { copy: self.list.pixel_copies.len() - 1, batch });
    }

    /// A primitive whose vertices from `materials[k].0` on are lit with the lighting of
    /// `materials[k].1` (`glMaterial` between `begin` and `end`); everything else is `state`'s.
    /// `hidden[i]`: vertex `i`'s edge flag is false (empty: none is); `unit_coords[i]`: vertex
    /// `i`'s coordinates of units 1 to 7 (empty: drawn with unit 0 alone).
    fn lit_primitive(
        &mut self,
        (mode, listed_or_indexed): (GLenum, bool),
        (vertices, unit_coords): (&[crate::gl::Vertex], &[UnitTexCoords]),
        state: &DrawState,
        materials: &[(usize, &DrawState)],
        hidden: &[bool],
    ) {
        let shaders: Vec<Shader> =
            std::iter::once(Shader::new(state)).chain(materials.iter().map(|(_, s)| Shader::new(s))).collect();
        let shader_of = |i: usize| materials.iter().rposition(|&(first, _)| first <= i).map_or(0, |k| k + 1);
        let mut v: Vec<ShadedVertex> =
            vertices.iter().enumerate().map(|(i, v)| shaders[shader_of(i)].shade(v)).collect();
        if !state.more_textures.is_empty() {
            for ((shaded, vertex), coords) in v.iter_mut().zip(vertices).zip(unit_coords) {
                shaded.units = shaders[0].unit_tex(vertex, coords);
            }
        }
        let n = v.len();
        let closing_edge_first = mode != GL_POLYGON;
        // Mesa 22.3 hands llvmpipe's draw module the quads of a display list or of
        // glDrawElements, and those of any source while a pipeline stage is on (a polygon
        // stipple, an unfilled face), and it splits them along v1–v3; the quads of
        // glBegin/glEnd and glDrawArrays reach it as triangles split along v0–v2 (measured:
        // the diagonal of a quad of four colours, tests/reference/pixels/quads.c).
        let pipeline = state.polygon_stipple.is_some() || state.polygon_mode != [GL_FILL, GL_FILL];
        let quads = mode == GL_QUADS && (pipeline || listed_or_indexed);
        let mut ctx = PrimitiveContext {
            out: self,
            state,
            v: &v,
            stipple: Stipple::default(),
            closing_edge_first,
            hidden,
            quads,
        };
        match mode {
            GL_POINTS => (0..n).for_each(|i| ctx.point(i)),
            GL_LINES => (0..n / 2).for_each(|i| {
                // Each separate segment restarts the stipple (GL 1.1 §3.4.2).
                ctx.stipple.reset();
                ctx.segment(2 * i, 2 * i + 1, 2 * i + 1);
            }),
            GL_LINE_STRIP => (1..n).for_each(|i| ctx.segment(i - 1, i, i)),
            GL_LINE_LOOP if n >= 2 => {
                (1..n).for_each(|i| ctx.segment(i - 1, i, i));
                ctx.segment(n - 1, 0, 0);
            }
            GL_TRIANGLES => (0..n / 3).for_each(|i| ctx.polygon(&[3 * i, 3 * i + 1, 3 * i + 2], 3 * i + 2)),
            GL_TRIANGLE_STRIP => (2..n).for_each(|i| {
                // Odd triangles swap their first two vertices to keep the strip's orientation.
                let tri = if i % 2 == 0 { [i - 2, i - 1, i] } else { [i - 1, i - 2, i] };
                ctx.polygon(&tri, i);
            }),
            GL_TRIANGLE_FAN => (2..n).for_each(|i| ctx.polygon(&[0, i - 1, i], i)),
            GL_QUADS => (0..n / 4).for_each(|q| ctx.polygon(&[4 * q, 4 * q + 1, 4 * q + 2, 4 * q + 3], 4 * q + 3)),
            GL_QUAD_STRIP => (1..n / 2).for_each(|q| {
                let (a, b) = (2 * q - 2, 2 * q);
                ctx.polygon(&[a, a + 1, b + 1, b], b + 1);
            }),
            GL_POLYGON if n >= 3 => {
                let all: Vec<usize> = (0..n).collect();
                ctx.polygon(&all, 0);
            }
            _ => {}
        }
    }

    /// Appends vertices to the last batch if it has the same state, else starts a batch.
    fn push(&mut self, state: &DrawState, topology: Topology, corners: &[Corner]) {
        self.push_as(state, topology, (Smooth::None, None), corners);
    }

    /// As [`Assembler::push`], with a smooth coverage or a polygon stipple for the fragments.
    fn push_as(
        &mut self,
        state: &DrawState,
        topology: Topology,
        extra: (Smooth, Option<[u32; 32]>),
        corners: &[Corner],
    ) {
        let depth_range = state.depth_range;
        let fragment = self.fragment_index(state, extra);
        let tests = state.fragment_tests;
        let batch_key = (state.viewport, state.depth_test, topology, fragment, state.blend, tests);
        let first = self.list.vertices.len() as u32;
        if !state.more_textures.is_empty() {
            self.list.unit_tex.resize(first as usize, [[0.0; 4]; 7]);
            self.list.unit_tex.extend(corners.iter().map(|c| c.units.map(|u| u.to_array())));
        }
        self.list.vertices.extend(corners.iter().map(|c| RasterVertex {
            clip: offset_depth(depth_mapped(c.clip, depth_range), c.depth_offset),
            color: c.color.to_array(),
            secondary: c.secondary.to_array(),
            tex: c.tex.to_array(),
            fog: c.fog,
            aa: c.aa.to_array(),
        }));
        let added = corners.len() as u32;
        if let Some(Op::Draw(last)) = self.list.ops.last_mut() {
            let last_key = (last.viewport, last.depth_test, last.topology, last.fragment, last.blend, last.tests);
            if last_key == batch_key && last.first + last.count == first {
                last.count += added;
                return;
            }
        }
        let (viewport, depth_test, topology, fragment, blend, tests) = batch_key;
        let batch = Batch { viewport, depth_test, topology, first, count: added, fragment, blend, tests };
        self.list.ops.push(Op::Draw(batch));
    }

    /// The index of the state's fragment operations in the list, adding them if they are new
    /// (looked up by [`fragment_bucket`]); `None` without any.
    fn fragment_index(
        &mut self,
        state: &DrawState,
        (smooth, polygon_stipple): (Smooth, Option<[u32; 32]>),
    ) -> Option<u32> {
        let plain = smooth == Smooth::None && polygon_stipple.is_none();
        let untextured = state.texture.is_none() && state.more_textures.is_empty();
        if untextured && state.fog.is_none() && state.alpha_test.is_none() && plain {
            return None;
        }
        let fragments = &mut self.list.fragments;
        let same = |f: &FragmentState| {
            f.texture.as_ref() == state.texture.as_ref()
                && f.more_textures == state.more_textures
                && f.fog == state.fog
                && f.alpha_test == state.alpha_test
                && f.smooth == smooth
                && f.polygon_stipple == polygon_stipple
        };
        let bucket = self.fragment_buckets.entry(fragment_bucket(state, smooth, polygon_stipple)).or_default();
        // The latest few of the bucket only: a state that never equals itself (a NaN fog or
        // alpha reference: the fuzz driver makes them) would otherwise make every primitive
        // search the whole bucket, quadratic in the frame.
        if let Some(&found) = bucket.iter().rev().take(RECENT_FRAGMENT_STATES).find(|&&i| same(&fragments[i as usize]))
        {
            return Some(found);
        }
        let (texture, fog, alpha_test) = (state.texture.clone(), state.fog, state.alpha_test);
        let more_textures = state.more_textures.clone();
        fragments.push(FragmentState { texture, more_textures, fog, alpha_test, smooth, polygon_stipple });
        let index = (fragments.len() - 1) as u32;
        bucket.push(index);
        Some(index)
    }
}

/// Maps GL clip z (NDC z in [−1, 1]) through the depth range into wgpu's [0, 1].
fn depth_mapped(clip: Vec4, [near, far]: [f32; 2]) -> [f32; 4] {
    let z = (clip.z + clip.w) * 0.5 * (far - near) + near * clip.w;
    [clip.x, clip.y, z, clip.w]
}

/// Adds a polygon offset (window depth units) to a clip position already in wgpu's depth.
fn offset_depth(mut clip: [f32; 4], offset: f32) -> [f32; 4] {
    clip[2] += offset * clip[3];
    clip
}

struct PrimitiveContext<'a, 'b> {
    out: &'a mut Assembler,
    state: &'b DrawState,
    v: &'b [ShadedVertex],
    stipple: Stipple,
    /// Polygon edges in line mode start with the closing edge (triangles and quads), not the
    /// first (`GL_POLYGON`): see [`PrimitiveContext::edges`].
    closing_edge_first: bool,
    /// Vertices whose edge flag is false (`glEdgeFlag`); empty when none is.
    hidden: &'b [bool],
    /// `GL_QUADS` as Mesa's draw module takes them (see `lit_primitive`): a quad is filled as
    /// (v0, v1, v3), (v1, v2, v3), its diagonal v1–v3 (`draw_pt_decompose.h`); other quads as
    /// a fan from v0. The diagonal shows where attributes
    /// are interpolated across a quad that is no parallelogram.
    quads: bool,
}

impl PrimitiveContext<'_, '_> {
    fn flat(&self) -> bool {
        self.state.shade_model == GL_FLAT
    }

    /// A point of the point size: one pixel natively, else a square in window space.
    fn point(&mut self, i: usize) {
        let c = self.corner(i, i, true);
        self.point_at(c);
    }

    /// Vertex `i` as a corner with the colours of vertex `colours` (itself, or the provoking
    /// vertex under flat shading), of the front face or the back one.
    fn corner(&self, i: usize, colours: usize, front: bool) -> Corner {
        let (v, c) = (&self.v[i], &self.v[colours]);
        let (color, secondary) = if front { (c.front, c.front_secondary) } else { (c.back, c.back_secondary) };
        let (tex, units, fog) = (v.tex, v.units, v.fog);
        Corner { clip: v.clip, eye: v.eye, color, secondary, tex, units, fog, depth_offset: 0.0, aa: Vec4::ZERO }
    }

    /// A point is clipped whole when its vertex is outside a clip plane (GL 1.1 §2.11).
    fn point_at(&mut self, c: Corner) {
        if !clip::point_inside(&c, &self.state.clip_planes) {
            return;
        }
        let size = self.state.point_parameters.derived_size(self.state.point_size, c.eye.z);
        // A point sprite is a square whatever GL_POINT_SMOOTH says (GL 2.0 §3.3.1).
        if self.state.point_smooth && self.state.point_sprite.is_none() {
            if let Some(quad) = smooth::point_quad(c, size, self.state.viewport) {
                self.out.push_as(self.state, Topology::Triangles, (Smooth::Point, None), &quad);
            }
            return;
        }
        let size = size.round().max(1.0);
        let replace = self.state.point_sprite.unwrap_or(0);
        if size <= 1.0 {
            // The one fragment sits at the sprite's centre.
            return self.out.push(self.state, Topology::Points, &[sprite_corner(c, replace, [0.5, 0.5])]);
        }
        let p = c.clip;
        // GL discards a point whose centre is outside the view volume, whatever its size.
        if p.w <= 0.0 || p.x.abs() > p.w || p.y.abs() > p.w || p.z.abs() > p.w {
            return;
        }
        let [_, _, vw, vh] = self.state.viewport;
        let (hx, hy) = (size / vw.max(1) as f32 * p.w, size / vh.max(1) as f32 * p.w);
        // llvmpipe's wide points break ties the other way from its triangles: a square edge
        // through a row of pixel centres takes the row above it in GL's window, not the one
        // below (measured on Mesa 22.3: a 5-pixel point at window y = 100 fills rows 98..102),
        // and a column through pixel centres takes the column to its right (a 5-pixel point at
        // window x = 16 fills columns 14..18: `tests/reference/pixels/point_parameters.c`).
        // Moving the square up and right by one sub-pixel step (1/256, the rasterisers'
        // precision) makes both rasterisers do the same.
        let up = 2.0 / 256.0 / vh.max(1) as f32 * p.w;
        let right = 2.0 / 256.0 / vw.max(1) as f32 * p.w;
        // A sprite's coordinates run from (0, 0) at its upper left to (1, 1) at its lower
        // right (GL 2.0 eq. 3.4 with GL_ARB_point_sprite's upper-left origin).
        let corner = |dx: f32, dy: f32| {
            let c = Corner { clip: p + Vec4::new(dx * hx + right, dy * hy + up, 0.0, 0.0), ..c };
            sprite_corner(c, replace, [(dx + 1.0) / 2.0, (1.0 - dy) / 2.0])
        };
        let (a, b, cc, d) = (corner(-1.0, -1.0), corner(1.0, -1.0), corner(1.0, 1.0), corner(-1.0, 1.0));
        self.out.push(self.state, Topology::Triangles, &[a, b, cc, a, cc, d]);
    }

    /// A segment of a line primitive; `provoking` gives its colour under flat shading.
    fn segment(&mut self, a: usize, b: usize, provoking: usize) {
        let colours = |i: usize| if self.flat() { provoking } else { i };
        let (ca, cb) = (self.corner(a, colours(a), true), self.corner(b, colours(b), true));
        self.line(ca, cb);
    }

    /// One line: clipped by the clip planes, then cut into its stippled pieces (Mesa's order:
    /// the stipple counts the clipped line's length).
    fn line(&mut self, a: Corner, b: Corner) {
        let Some((a, b)) = clip::segment(a, b, &self.state.clip_planes) else { return };
        let Some(stipple) = self.state.line_stipple else { return self.raster_line(a, b) };
        let Some((a, b)) = clip::view_volume(a, b) else { return };
        let euclidean = self.state.line_smooth;
        for (p, q) in self.stipple.pieces(a, b, self.state.viewport, stipple, euclidean) {
            self.raster_line(p, q);
        }
    }

    /// A line of the line width: one pixel natively, else GL's aliased wide line, a
    /// parallelogram widened along the minor axis by the width in pixels.
    fn raster_line(&mut self, a: Corner, b: Corner) {
        if self.state.line_smooth {
            if let Some(quad) = smooth::line_quad(a, b, self.state.line_width, self.state.viewport) {
                self.out.push_as(self.state, Topology::Triangles, (Smooth::Line, None), &quad);
            }
            return;
        }
        let width = self.state.line_width.round().max(1.0);
        if width <= 1.0 {
            return self.out.push(self.state, Topology::Lines, &[a, b]);
        }
        if a.clip.w <= 0.0 || b.clip.w <= 0.0 {
            return;
        }
        let [_, _, vw, vh] = self.state.viewport;
        let (vw, vh) = (vw.max(1) as f32, vh.max(1) as f32);
        let (pa, pb) = (a.clip / a.clip.w, b.clip / b.clip.w);
        let (dx, dy) = ((pb.x - pa.x) * vw, (pb.y - pa.y) * vh);
        let offset = if dx.abs() >= dy.abs() {
            Vec4::new(0.0, width / vh, 0.0, 0.0)
        } else {
            Vec4::new(width / vw, 0.0, 0.0, 0.0)
        };
        let shift = |c: Corner, s: f32| Corner { clip: c.clip + offset * (s * c.clip.w), ..c };
        let (a0, a1, b0, b1) = (shift(a, -1.0), shift(a, 1.0), shift(b, -1.0), shift(b, 1.0));
        self.out.push(self.state, Topology::Triangles, &[a0, a1, b1, a0, b1, b0]);
    }

    /// A polygon's edges in line mode, in the order Mesa's draw module strokes them, which the
    /// line stipple shows: it splits triangles and quads into triangles and strokes each
    /// triangle's edges from its last vertex (v2 → v0, v0 → v1, v1 → v2), restarting the
    /// stipple at each triangle and quad; `GL_POLYGON` is stroked v0 → v1 → … → v0 with one
    /// restart (`draw_pipe_unfilled.c`, `draw_pt_decompose.h`; measured on llvmpipe).
    fn edges(&mut self, corners: &[Corner]) {
        let n = corners.len();
        self.stipple.reset();
        let first = if self.closing_edge_first { n - 1 } else { 0 };
        for j in 0..n {
            let k = (first + j) % n;
            self.line(corners[k], corners[(k + 1) % n]);
        }
    }

    /// A polygon some of whose edge flags are false, in point or line mode: only the vertices
    /// and edges that start at a flagged vertex (GL 1.1 §2.6.2, §3.5.4), each clipped on its
    /// own by the clip planes.
    fn flagged(&mut self, mode: GLenum, corners: &[Corner], flags: &[bool]) {
        let n = corners.len();
        if mode == GL_POINT {
            (0..n).filter(|&k| flags[k]).for_each(|k| self.point_at(corners[k]));
            return;
        }
        self.stipple.reset();
        let first = if self.closing_edge_first { n - 1 } else { 0 };
        for j in 0..n {
            let k = (first + j) % n;
            if flags[k] {
                self.line(corners[k], corners[(k + 1) % n]);
            }
        }
    }

    /// A polygon (triangle, quad or `GL_POLYGON`): orientation, culling, face colour, flat
    /// shading, then the polygon mode of its face. In line mode only the polygon's own edges
    /// are drawn, never the diagonals used to fill it.
    fn polygon(&mut self, idx: &[usize], provoking: usize) {
        let area = signed_area(idx.iter().map(|&i| self.v[i].clip));
        let ccw_front = self.state.front_face == GL_CCW;
        let front = (area > 0.0) == ccw_front;
        if let Some(cull) = self.state.cull_face {
            if cull == GL_FRONT_AND_BACK || (cull == GL_FRONT) == front {
                return;
            }
        }
        let colours = |i: usize| if self.flat() { provoking } else { i };
        let corners: Vec<Corner> = idx.iter().map(|&i| self.corner(i, colours(i), front)).collect();
        let mut corners = clip::polygon(corners, &self.state.clip_planes);
        if corners.len() < 3 {
            return;
        }
        let mode = self.state.polygon_mode[usize::from(!front)];
        let depth = self.state.polygon_offset.filter(|o| o.applies_to(mode)).map(|o| {
            let depth = offset::polygon_offset(&corners, self.state.viewport, self.state.depth_range, &o);
            corners.iter_mut().for_each(|c| c.depth_offset = depth);
            depth
        });
        let is_hidden = |i: &usize| self.hidden.get(*i).copied().unwrap_or(false);
        if mode != GL_FILL && idx.iter().any(is_hidden) {
            let flags: Vec<bool> = idx.iter().map(|i| !is_hidden(i)).collect();
            let mut whole: Vec<Corner> = idx.iter().map(|&i| self.corner(i, colours(i), front)).collect();
            whole.iter_mut().for_each(|c| c.depth_offset = depth.unwrap_or(0.0));
            return self.flagged(mode, &whole, &flags);
        }
        match mode {
            GL_POINT => corners.iter().for_each(|&c| self.point_at(c)),
            GL_LINE => self.edges(&corners),
            _ => {
                if self.quads && corners.len() == 4 && idx.len() == 4 {
                    corners.rotate_left(1);
                }
                let tris: Vec<Corner> =
                    (1..corners.len() - 1).flat_map(|k| [corners[0], corners[k], corners[k + 1]]).collect();
                // The polygon stipple applies to filled polygons only (GL 1.1 §3.5.6).
                let extra = (Smooth::None, self.state.polygon_stipple);
                self.out.push_as(self.state, Topology::Triangles, extra, &tris);
            }
        }
    }
}

/// `c` with the texture coordinates of the units in `replace` (a bit a unit, unit 0 the lowest)
/// replaced by the point sprite's (s, t) there (`GL_COORD_REPLACE`).
fn sprite_corner(mut c: Corner, replace: u8, [s, t]: [f32; 2]) -> Corner {
    let sprite = Vec4::new(s, t, 0.0, 1.0);
    if replace & 1 != 0 {
        c.tex = sprite;
    }
    for (k, unit) in c.units.iter_mut().enumerate() {
        if replace & (2 << k) != 0 {
            *unit = sprite;
        }
    }
    c
}

/// Twice the signed area of the projected polygon (positive when counter-clockwise in window
/// coordinates, y up). With a vertex behind the eye (w ≤ 0) the homogeneous determinant of the
/// first three vertices gives the orientation instead.
fn signed_area(points: impl Iterator<Item = Vec4>) -> f32 {
    let p: Vec<Vec4> = points.collect();
    if p.iter().all(|c| c.w > 0.0) {
        let ndc: Vec<(f32, f32)> = p.iter().map(|c| (c.x / c.w, c.y / c.w)).collect();
        (0..ndc.len())
            .map(|k| {
                let (a, b) = (ndc[k], ndc[(k + 1) % ndc.len()]);
                a.0 * b.1 - b.0 * a.1
            })
            .sum()
    } else {
        let (a, b, c) = (p[0], p[1], p[2]);
        let det = a.x * (b.y * c.w - c.y * b.w) - b.x * (a.y * c.w - c.y * a.w) + c.x * (a.y * b.w - b.y * a.w);
        det * (a.w * b.w * c.w).signum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::Gl;

    fn triangle_list(list: &DrawList) -> Vec<[f32; 2]> {
        list.vertices.iter().map(|v| [v.clip[0], v.clip[1]]).collect()
    }

    #[test]
    fn quad_strip_fills_two_triangles_per_quad_and_culls_by_winding() {
        let mut gl = Gl::new(10, 10);
        gl.begin(GL_QUAD_STRIP);
        for (x, y) in [(0.0, 0.0), (0.0, 0.5), (0.5, 0.0), (0.5, 0.5)] {
            gl.vertex2f(x, y);
        }
        gl.end();
        let list = assemble(&gl.take_frame());
        assert_eq!(list.vertices.len(), 6);
        // Quad (0,0) (0,.5) (.5,.5) (.5,0) is clockwise: culled as a back face.
        gl.enable(GL_CULL_FACE);
        gl.begin(GL_QUAD_STRIP);
        for (x, y) in [(0.0, 0.0), (0.0, 0.5), (0.5, 0.0), (0.5, 0.5)] {
            gl.vertex2f(x, y);
        }
        gl.end();
        assert!(assemble(&gl.take_frame()).vertices.is_empty());
    }

    #[test]
    fn polygon_line_mode_draws_only_the_boundary() {
        let mut gl = Gl::new(10, 10);
        gl.polygon_mode(GL_FRONT_AND_BACK, GL_LINE);
        gl.begin(GL_QUADS);
        for (x, y) in [(0.0, 0.0), (0.5, 0.0), (0.5, 0.5), (0.0, 0.5)] {
            gl.vertex2f(x, y);
        }
        gl.end();
        let list = assemble(&gl.take_frame());
        assert_eq!(list.vertices.len(), 8, "4 edges, no diagonal");
        assert!(matches!(list.ops[0], Op::Draw(Batch { topology: Topology::Lines, .. })));
    }

    #[test]
    fn wide_points_are_squares_of_the_point_size() {
        let mut gl = Gl::new(100, 50);
        gl.point_size(4.0);
        gl.begin(GL_POINTS);
        gl.vertex2f(0.0, 0.0);
        gl.end();
        let pts = triangle_list(&assemble(&gl.take_frame()));
        let xs: Vec<f32> = pts.iter().map(|p| p[0]).collect();
        let ys: Vec<f32> = pts.iter().map(|p| p[1]).collect();
        // 4 px = 0.08 NDC wide at 100 px, 0.16 NDC tall at 50 px.
        let span = |v: &[f32]| v.iter().cloned().fold(f32::MIN, f32::max) - v.iter().cloned().fold(f32::MAX, f32::min);
        assert!((span(&xs) - 0.08).abs() < 1e-6 && (span(&ys) - 0.16).abs() < 1e-6);
    }

    #[test]
    fn flat_shading_uses_the_provoking_vertex() {
        let mut gl = Gl::new(10, 10);
        gl.shade_model(GL_FLAT);
        gl.begin(GL_TRIANGLES);
        gl.color3f(1.0, 0.0, 0.0);
        gl.vertex2f(0.0, 0.0);
        gl.color3f(0.0, 1.0, 0.0);
        gl.vertex2f(0.5, 0.0);
        gl.color3f(0.0, 0.0, 1.0);
        gl.vertex2f(0.0, 0.5);
        gl.end();
        let list = assemble(&gl.take_frame());
        assert!(list.vertices.iter().all(|v| v.color == [0.0, 0.0, 1.0, 1.0]), "last vertex of a triangle");
    }

    /// GL 1.1 §2.13: with light 0's defaults and the normal towards it, a vertex's colour is
    /// 0.2 · 0.2 ambient + its diffuse material (alpha: the diffuse alpha). Real Mesa gives the
    /// same in feedback mode: (1, .04, .04, 1), (.04, 1, .04, 1), (.04, .04, 1, .5), and the
    /// point drawn after `end` keeps the last material.
    #[test]
    fn materials_changed_between_begin_and_end_light_the_vertices_after_them() {
        let mut gl = Gl::new(16, 16);
        gl.enable(GL_LIGHTING);
        gl.enable(GL_LIGHT0);
        gl.normal3f(0.0, 0.0, 1.0);
        gl.begin(GL_TRIANGLES);
        gl.material_fv(GL_FRONT, GL_DIFFUSE, &[1.0, 0.0, 0.0, 1.0]);
        gl.vertex2f(0.0, 0.0);
        gl.material_fv(GL_FRONT, GL_DIFFUSE, &[0.0, 1.0, 0.0, 1.0]);
        gl.vertex2f(0.5, 0.0);
        gl.material_fv(GL_FRONT, GL_DIFFUSE, &[0.0, 0.0, 1.0, 0.5]);
        gl.vertex2f(0.0, 0.5);
        gl.end();
        gl.begin(GL_POINTS);
        gl.vertex2f(0.2, 0.2);
        gl.end();
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        let list = assemble(&gl.take_frame());
        let expected = [[1.0, 0.04, 0.04, 1.0], [0.04, 1.0, 0.04, 1.0], [0.04, 0.04, 1.0, 0.5], [0.04, 0.04, 1.0, 0.5]];
        assert_eq!(list.vertices.len(), 4);
        for (v, e) in list.vertices.iter().zip(expected) {
            assert!(v.color.iter().zip(e).all(|(a, b)| (a - b).abs() < 1e-6), "{:?} vs {e:?}", v.color);
        }
    }

    /// GL 1.1 §2.13.3: the tracked material keeps the last colour when tracking stops. Real
    /// Mesa's feedback: red, green, then blue (diffuse 0, 0, 1 after glDisable).
    #[test]
    fn the_tracked_material_keeps_the_last_colour() {
        let mut gl = Gl::new(16, 16);
        gl.enable(GL_LIGHTING);
        gl.enable(GL_LIGHT0);
        gl.normal3f(0.0, 0.0, 1.0);
        gl.enable(GL_COLOR_MATERIAL);
        gl.begin(GL_POINTS);
        gl.color3f(1.0, 0.0, 0.0);
        gl.vertex2f(0.0, 0.0);
        gl.color3f(0.0, 1.0, 0.0);
        gl.vertex2f(0.1, 0.0);
        gl.end();
        gl.color3f(0.0, 0.0, 1.0);
        gl.disable(GL_COLOR_MATERIAL);
        gl.color3f(1.0, 1.0, 0.0);
        gl.begin(GL_POINTS);
        gl.vertex2f(0.2, 0.0);
        gl.end();
        let list = assemble(&gl.take_frame());
        let colours: Vec<[f32; 4]> = list.vertices.iter().map(|v| v.color).collect();
        // Ambient 0.2 · tracked colour + diffuse tracked colour, clamped to 1.
        assert_eq!(colours, [[1.0, 0.0, 0.0, 1.0], [0.0, 1.0, 0.0, 1.0], [0.0, 0.0, 1.0, 1.0]]);
    }

    #[test]
    fn depth_range_maps_to_zero_one() {
        assert_eq!(depth_mapped(Vec4::new(0.0, 0.0, -1.0, 1.0), [0.0, 1.0])[2], 0.0);
        assert_eq!(depth_mapped(Vec4::new(0.0, 0.0, 2.0, 2.0), [0.0, 1.0])[2], 2.0);
    }
}
