//! What a [`Gl`](super::Gl) context records: the primitives it assembled between `begin` and
//! `end` (from immediate mode or from the evaluators), and a log of the immediate-mode calls.
//! Tests read it; the renderer draws it.

use super::fog::Fog;
use super::fragments::FragmentTests;
use super::lighting::Lighting;
use super::offset::PolygonOffset;
use super::texture::BoundTexture;
use super::types::{GLbitfield, GLenum};
use super::vertex::Vertex;
use glam::{Mat3, Mat4, Vec3};

/// A `begin`/`end` pair: its mode and its vertices `first..first + count` of [`Frame::vertices`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Primitive {
    /// `GL_POINTS` ... `GL_POLYGON`.
    pub mode: GLenum,
    /// Index of the first vertex.
    pub first: usize,
    /// Number of vertices (may be too few to draw anything, as in GL).
    pub count: usize,
    /// Index in [`Frame::states`] of the GL state the primitive is drawn with.
    pub state: usize,
    /// Drawn from a display list or by `glDrawElements`: llvmpipe's draw module splits such
    /// quads along v1–v3, where it splits those of `glBegin`/`glEnd` and `glDrawArrays`
    /// along v0–v2 (measured on Mesa 22.3; see `render::assemble`).
    pub listed_or_indexed: bool,
}

/// A `glMaterial` call between `begin` and `end`: from vertex `vertex` of primitive
/// `primitive` on, vertices are lit with the lighting of [`Frame::states`]`[state]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MaterialChange {
    /// Index in [`Frame::primitives`].
    pub primitive: usize,
    /// The first vertex (counted in the primitive) the new material applies to.
    pub vertex: usize,
    /// Index in [`Frame::states`] of the state holding the new material.
    pub state: usize,
}

/// The GL state a primitive is drawn with, captured at `begin`.
#[derive(Clone, Debug, PartialEq)]
pub struct DrawState {
    /// The modelview matrix (column-major, GL conventions).
    pub modelview: Mat4,
    /// The projection matrix.
    pub projection: Mat4,
    /// x, y, width, height in pixels, origin bottom-left.
    pub viewport: [i32; 4],
    /// `glDepthRange`.
    pub depth_range: [f32; 2],
    /// Lights and materials when `GL_LIGHTING` is enabled.
    pub lighting: Option<Lighting>,
    /// `GL_COLOR_MATERIAL` enabled.
    pub color_material: bool,
    /// `GL_NORMALIZE` enabled.
    pub normalize: bool,
    /// `GL_RESCALE_NORMAL` enabled.
    pub rescale_normal: bool,
    /// GL 1.4's `GL_COLOR_SUM` enabled: without lighting, the vertices' secondary colour is
    /// added after texturing (with lighting the sum is always made, §3.9).
    pub color_sum: bool,
    /// `GL_FLAT` or `GL_SMOOTH`.
    pub shade_model: GLenum,
    /// `glPointSize`.
    pub point_size: f32,
    /// GL 1.4's point parameters, which derive each point's size from `point_size`
    /// ([`super::PointParameters::derived_size`]).
    pub point_parameters: super::PointParameters,
    /// `glLineWidth`.
    pub line_width: f32,
    /// Front and back `glPolygonMode`.
    pub polygon_mode: [GLenum; 2],
    /// `GL_CW` or `GL_CCW`.
    pub front_face: GLenum,
    /// The culled face when `GL_CULL_FACE` is enabled.
    pub cull_face: Option<GLenum>,
    /// The depth function when `GL_DEPTH_TEST` is enabled.
    pub depth_test: Option<GLenum>,
    /// The texture of unit 0 when a target is enabled and its texture complete.
    pub texture: Option<BoundTexture>,
    /// The textures of units 1 to 7 that draw (a target enabled, the texture complete), in unit
    /// order, with their units (GL 1.3 §3.8.15: each applies its environment to the previous
    /// unit's result); empty for a program of one unit. Their vertices' coordinates are in
    /// [`Frame::unit_tex_coords`].
    pub more_textures: Vec<(usize, BoundTexture)>,
    /// Blending when `GL_BLEND` is enabled.
    pub blend: Option<super::Blend>,
    /// The alpha test's function and reference when `GL_ALPHA_TEST` is enabled.
    pub alpha_test: Option<(GLenum, f32)>,
    /// Fog when `GL_FOG` is enabled.
    pub fog: Option<Fog>,
    /// `glLineStipple`'s (factor, pattern) when `GL_LINE_STIPPLE` is enabled.
    pub line_stipple: Option<(i32, u16)>,
    /// `GL_POINT_SMOOTH` enabled.
    pub point_smooth: bool,
    /// `GL_POINT_SPRITE` enabled (`GL_ARB_point_sprite`): the units whose coordinates a point
    /// replaces (`GL_COORD_REPLACE`, a bit a unit), which draws it as a square whatever
    /// `GL_POINT_SMOOTH` says.
    pub point_sprite: Option<u8>,
    /// `GL_LINE_SMOOTH` enabled.
    pub line_smooth: bool,
    /// `glPolygonOffset` when any of its enables is on.
    pub polygon_offset: Option<PolygonOffset>,
    /// The enabled clip planes in eye coordinates, in plane order.
    pub clip_planes: Vec<[f32; 4]>,
    /// `glPolygonStipple`'s mask when `GL_POLYGON_STIPPLE` is enabled: row y, bit x for window
    /// pixel (x, y) modulo 32.
    pub polygon_stipple: Option<[u32; 32]>,
    /// The scissor and stencil tests, the write masks, the logic op and the colour buffers
    /// drawn (`gl/fragments.rs`).
    pub fragment_tests: FragmentTests,
}

impl DrawState {
    /// What normals are transformed by into eye coordinates: the inverse transpose of the
    /// modelview's upper 3×3 (GL 1.1 §2.10.3), and with `GL_RESCALE_NORMAL` (GL 1.2 §2.10.3)
    /// scaled by 1/√(m₃₁² + m₃₂² + m₃₃²), the length of the inverse's third row (Mesa's
    /// `_NormalScale`): under a uniform scale a unit normal stays unit, under another it does
    /// not (measured on Mesa 22.3, `rescale_normal.calls`). `GL_NORMALIZE` normalises after.
    #[must_use]
    pub fn normal_matrix(&self) -> Mat3 {
        let m = Mat3::from_mat4(self.modelview).inverse().transpose();
        if self.rescale_normal && !self.normalize {
            let row = m.z_axis.length();
            if row > 0.0 {
                return m * (1.0 / row);
            }
        }
        m
    }

    /// A normal in eye coordinates through `normal_matrix` (this state's
    /// [`DrawState::normal_matrix`], computed once per primitive by the caller), made unit length
    /// when `GL_NORMALIZE` asks for it.
    #[must_use]
    pub fn eye_normal(&self, normal_matrix: Mat3, normal: [f32; 3]) -> Vec3 {
        let n = normal_matrix * Vec3::from_array(normal);
        if self.normalize {
            n.normalize_or_zero()
        } else {
            n
        }
    }
}

/// A `glAccum(op, value)` over the scissor box of `tests`, reading the colour buffer `read`
/// (front or back bit) and returning into `tests`' draw buffers through its colour mask.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Accumulation {
    /// `GL_ACCUM`, `GL_LOAD`, `GL_ADD`, `GL_MULT` or `GL_RETURN`.
    pub op: GLenum,
    /// The operation's value.
    pub value: f32,
    /// Scissor, colour mask and draw buffers.
    pub tests: FragmentTests,
    /// The buffer `GL_ACCUM` and `GL_LOAD` read (`FRONT_BUFFER` or `BACK_BUFFER`).
    pub read: u8,
}

/// Framebuffer operations and draws, in program order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Command {
    /// `glClear(mask)` with the clear values current then.
    Clear {
        /// The buffer bits.
        mask: GLbitfield,
        /// The clear colour.
        color: [f32; 4],
        /// The clear depth.
        depth: f32,
        /// The clear stencil value (`glClearStencil`).
        stencil: i32,
        /// The accumulation buffer's clear value (`glClearAccum`).
        accum: [f32; 4],
        /// The scissor box, the write masks and the colour buffers the clear reaches.
        tests: FragmentTests,
    },
    /// `glAccum(op, value)` (see [`Accumulation`]).
    Accum(Accumulation),
    /// `glutSwapBuffers`: the back buffer becomes the front one (a double-buffered context).
    SwapBuffers,
    /// Draw primitive number `n` of [`Frame::primitives`].
    Draw(usize),
    /// Draw mesh number `n` of [`Frame::meshes`].
    Mesh(usize),
    /// Execute copy number `n` of [`Frame::pixel_copies`] (`glCopyPixels`).
    CopyPixels(usize),
    /// An occlusion query's slot of this frame starts (`glBeginQuery`, `begin`) or stops
    /// (`glEndQuery`) counting the samples that pass the depth and stencil tests; a rasteriser
    /// hands the counts back in [`super::WindowImage::samples`].
    Query {
        /// The slot: 0, 1, … in the order the frame's queries began.
        slot: usize,
        /// Whether it starts.
        begin: bool,
    },
}

/// An immediate-mode call, in the order the program made it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Call {
    /// `glBegin(mode)`.
    Begin(GLenum),
    /// `glEnd()`.
    End,
    /// `glVertex*` (x, y, z, w).
    Vertex([f32; 4]),
    /// `glColor*` (r, g, b, a).
    Color([f32; 4]),
    /// `glNormal*`.
    Normal([f32; 3]),
    /// `glTexCoord*` (s, t, r, q).
    TexCoord([f32; 4]),
    /// `glMultiTexCoord*` of unit 1 to 7 (unit 0's is logged as [`Call::TexCoord`]).
    MultiTexCoord(u8, [f32; 4]),
    /// `glSecondaryColor*` (r, g, b, 1; a size-4 array's alpha).
    SecondaryColor([f32; 4]),
    /// `glFogCoord*`.
    FogCoord(f32),
}

/// Everything drawn since the context was made or the frame last taken.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Frame {
    /// All vertices, primitive after primitive.
    pub vertices: Vec<Vertex>,
    /// The primitives, in drawing order.
    pub primitives: Vec<Primitive>,
    /// The immediate-mode calls the program made (evaluator output is not logged here,
    /// only in `primitives`).
    pub calls: Vec<Call>,
    /// The distinct draw states primitives refer to.
    pub states: Vec<DrawState>,
    /// Clears and draws in program order.
    pub commands: Vec<Command>,
    /// The grids `glEvalMesh` drew, each point stored once (see [`Frame::expanded`] for the
    /// primitives GL would have issued).
    pub meshes: Vec<GridMesh>,
    /// Materials changed between `begin` and `end`, in order.
    pub material_changes: Vec<MaterialChange>,
    /// The vertices (indices in `vertices`, ascending) issued with the edge flag false
    /// (`glEdgeFlag`): in line and point polygon modes their edges are not boundary edges.
    pub hidden_edges: Vec<usize>,
    /// The `glCopyPixels` calls, executed by the rasterisers where [`Command::CopyPixels`] says.
    pub pixel_copies: Vec<super::PixelCopy>,
    /// Units 1 to 7's texture coordinates of the vertices (indices in `vertices`, ascending) of
    /// primitives drawn with [`DrawState::more_textures`]: recorded only there, so that a
    /// program of one unit records nothing more.
    pub unit_tex_coords: Vec<(usize, UnitTexCoords)>,
}

/// A vertex's texture coordinates of units 1 to 7.
pub type UnitTexCoords = [[f32; 4]; 7];

/// What a `glEvalMesh` grid draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshMode {
    /// `GL_POINT`: one `GL_POINTS` over the grid, v outer.
    Points,
    /// `GL_LINE` of `glEvalMesh1`: one `GL_LINE_STRIP`.
    CurveLines,
    /// `GL_LINE` of `glEvalMesh2`: a `GL_LINE_STRIP` per row, then one per column.
    SurfaceLines,
    /// `GL_FILL`: a `GL_TRIANGLE_STRIP` per pair of rows.
    Fill,
    /// `GL_TRIANGLES` over [`GridMesh::triangles`] (GLU's trimmed surfaces).
    Triangles,
}

/// A grid's vertices: evaluated on the CPU, or left for the GPU to evaluate at draw time.
#[derive(Clone, Debug, PartialEq)]
pub enum MeshVertices {
    /// `nu · nv` vertices, v outer.
    Evaluated(super::GridVertices),
    /// The maps and parameters, evaluated by the GPU tessellator when the frame is drawn: one
    /// job for a grid, one per Bezier piece for scattered points (outputs concatenated).
    Deferred(Vec<super::MeshJob>),
}

/// One `glEvalMesh1`/`glEvalMesh2` call.
#[derive(Clone, Debug, PartialEq)]
pub struct GridMesh {
    /// What it draws.
    pub mode: MeshMode,
    /// Grid points along u.
    pub nu: usize,
    /// Grid points along v (1 for a curve).
    pub nv: usize,
    /// Index in [`Frame::states`] of its draw state.
    pub state: usize,
    /// Its vertices.
    pub vertices: MeshVertices,
    /// For [`MeshMode::Triangles`]: three vertex indices per triangle (else empty).
    pub triangles: Vec<u32>,
    /// Units 1 to 7's coordinates of every vertex: the current ones when the mesh was recorded
    /// (the evaluators feed unit 0 alone, GL 1.3 §5.1).
    pub unit_tex_coords: UnitTexCoords,
}

impl GridMesh {
    /// The attributes no map evaluates, as they were when the mesh was recorded.
    #[must_use]
    pub fn template(&self) -> Vertex {
        match &self.vertices {
            MeshVertices::Evaluated(grid) => grid.template,
            MeshVertices::Deferred(jobs) => jobs.first().map(|j| j.template).unwrap_or_default(),
        }
    }

    /// The grid's vertices, evaluating a deferred job on the CPU.
    #[must_use]
    pub fn evaluated(&self) -> std::borrow::Cow<'_, super::GridVertices> {
        match &self.vertices {
            MeshVertices::Evaluated(v) => std::borrow::Cow::Borrowed(v),
            MeshVertices::Deferred(jobs) => match jobs.as_slice() {
                [job] => std::borrow::Cow::Owned(job.evaluate()),
                // Scattered points, one job per Bezier piece: outputs concatenated.
                _ => {
                    let all: Vec<Vertex> = jobs.iter().flat_map(|j| j.evaluate().to_vertices()).collect();
                    std::borrow::Cow::Owned(super::GridVertices::from_vertices(&all))
                }
            },
        }
    }

    /// The primitives GL issues for this grid, in Mesa's order: (mode, grid indices).
    #[must_use]
    pub fn primitives(&self) -> Vec<(GLenum, Vec<usize>)> {
        use super::consts::*;
        let (nu, nv) = (self.nu, self.nv);
        match self.mode {
            MeshMode::Points => vec![(GL_POINTS, (0..nu * nv).collect())],
            MeshMode::CurveLines => vec![(GL_LINE_STRIP, (0..nu).collect())],
            MeshMode::SurfaceLines => {
                let rows = (0..nv).map(|j| (GL_LINE_STRIP, (0..nu).map(|i| j * nu + i).collect()));
                let columns = (0..nu).map(|i| (GL_LINE_STRIP, (0..nv).map(|j| j * nu + i).collect()));
                rows.chain(columns).collect()
            }
            MeshMode::Triangles => vec![(GL_TRIANGLES, self.triangles.iter().map(|&i| i as usize).collect())],
            MeshMode::Fill => (0..nv.saturating_sub(1))
                .map(|j| (GL_TRIANGLE_STRIP, (0..nu).flat_map(|i| [j * nu + i, (j + 1) * nu + i]).collect()))
                .collect(),
        }
    }
}

impl Frame {
    /// The vertices of primitive `index`.
    #[must_use]
    pub fn vertices_of(&self, primitive: &Primitive) -> &[Vertex] {
        &self.vertices[primitive.first..primitive.first + primitive.count]
    }

    /// The material changes inside primitive `index`, as (first vertex, state index).
    #[must_use]
    pub fn material_changes_of(&self, index: usize) -> Vec<(usize, usize)> {
        self.material_changes.iter().filter(|c| c.primitive == index).map(|c| (c.vertex, c.state)).collect()
    }

    /// Iterates over (primitive, its vertices).
    pub fn iter(&self) -> impl Iterator<Item = (&Primitive, &[Vertex])> {
        self.primitives.iter().map(move |p| (p, self.vertices_of(p)))
    }

    /// Removes everything recorded.
    pub fn clear(&mut self) {
        self.vertices.clear();
        self.primitives.clear();
        self.calls.clear();
        self.states.clear();
        self.commands.clear();
        self.meshes.clear();
        self.material_changes.clear();
        self.hidden_edges.clear();
        self.pixel_copies.clear();
        self.unit_tex_coords.clear();
    }

    /// Units 1 to 7's coordinates of each vertex of `primitive`; empty when it recorded none
    /// (drawn with one unit).
    #[must_use]
    pub fn unit_tex_coords_of(&self, primitive: &Primitive) -> Vec<UnitTexCoords> {
        let range = primitive.first..primitive.first + primitive.count;
        let start = self.unit_tex_coords.partition_point(|(i, _)| *i < range.start);
        let inside: Vec<_> = self.unit_tex_coords[start..].iter().take_while(|(i, _)| *i < range.end).collect();
        if inside.is_empty() {
            return Vec::new();
        }
        let mut coords = vec![[[0.0, 0.0, 0.0, 1.0]; 7]; primitive.count];
        for (i, c) in inside {
            coords[i - range.start] = *c;
        }
        coords
    }

    /// For each vertex of `primitive`, whether its edge flag is false; empty when none is (the
    /// common case).
    #[must_use]
    pub fn hidden_edges_of(&self, primitive: &Primitive) -> Vec<bool> {
        let range = primitive.first..primitive.first + primitive.count;
        let start = self.hidden_edges.partition_point(|&i| i < range.start);
        let inside = self.hidden_edges[start..].iter().take_while(|&&i| i < range.end);
        let mut flags = Vec::new();
        for &i in inside {
            flags.resize(primitive.count, false);
            flags[i - range.start] = true;
        }
        flags
    }

    /// The frame with every mesh replaced by the primitives GL issues for it (deferred meshes
    /// evaluated on the CPU): what a test comparing against GL's primitive stream reads.
    #[must_use]
    pub fn expanded(&self) -> Frame {
        let mut out = Frame {
            calls: self.calls.clone(),
            states: self.states.clone(),
            pixel_copies: self.pixel_copies.clone(),
            ..Frame::default()
        };
        for command in &self.commands {
            match *command {
                Command::Clear { .. }
                | Command::CopyPixels(_)
                | Command::Accum(_)
                | Command::SwapBuffers
                | Command::Query { .. } => out.commands.push(*command),
                Command::Draw(i) => {
                    let p = self.primitives[i];
                    let first = out.vertices.len();
                    let hidden = self.hidden_edges_of(&p);
                    out.hidden_edges.extend(hidden.iter().enumerate().filter(|(_, h)| **h).map(|(k, _)| first + k));
                    let units = self.unit_tex_coords_of(&p);
                    out.unit_tex_coords.extend(units.into_iter().enumerate().map(|(k, c)| (first + k, c)));
                    out.push_primitive(p.mode, p.state, self.vertices_of(&p).iter().copied());
                    let primitive = out.primitives.len() - 1;
                    for (vertex, state) in self.material_changes_of(i) {
                        out.material_changes.push(MaterialChange { primitive, vertex, state });
                    }
                }
                Command::Mesh(i) => {
                    let mesh = &self.meshes[i];
                    let grid = mesh.evaluated();
                    let units = self.states.get(mesh.state).is_some_and(|s| !s.more_textures.is_empty());
                    for (mode, indices) in mesh.primitives() {
                        if units {
                            let first = out.vertices.len();
                            out.unit_tex_coords.extend((0..indices.len()).map(|k| (first + k, mesh.unit_tex_coords)));
                        }
                        out.push_primitive(mode, mesh.state, indices.iter().map(|&k| grid.vertex(k)));
                    }
                }
            }
        }
        out
    }

    fn push_primitive(&mut self, mode: GLenum, state: usize, vertices: impl Iterator<Item = Vertex>) {
        let first = self.vertices.len();
        self.vertices.extend(vertices);
        let count = self.vertices.len() - first;
        self.primitives.push(Primitive { mode, first, count, state, listed_or_indexed: false });
        self.commands.push(Command::Draw(self.primitives.len() - 1));
    }
}
