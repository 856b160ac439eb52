//! The GL façade: a context that keeps the GL 1.x state the evaluators need, sets GL's error
//! flag exactly as Mesa does, and records what it draws into a [`Frame`].
//!
//! Method names follow the porting convention: the C function without `gl`, in snake_case,
//! with the same arguments in the same order (`glMap2f` → [`Gl::map2f`]). Pointers become
//! slices; a slice shorter than the call needs sets `GL_INVALID_VALUE` instead of reading out of
//! bounds. Nothing here panics on bad input.

mod accum;
mod array_draws;
mod arrays;
mod attrib;
mod binding;
mod bitmap;
mod blend;
mod buffers;
mod clear;
mod client_memory;
pub(crate) mod clip;
mod color_buffer;
mod color_index;
pub mod consts;
mod copy_pixels;
mod copy_texture;
mod current;
mod depth;
mod depth_stencil_pixels;
mod draw_buffer;
mod enable;
mod eval;
pub mod feedback;
mod feedback_prims;
mod fog;
pub mod fragments;
mod frame;
mod get;
mod grid_vertices;
mod hint;
mod imaging;
mod immediate;
mod lighting;
mod line;
pub(crate) mod lists;
mod matrix;
mod multisample;
mod multitexture;
mod occlusion;
mod offset;
mod param_variants;
mod pixel_buffers;
mod pixel_pack;
mod pixel_packed;
mod pixel_transfer;
mod pixel_unpack;
pub mod pixel_zoom;
mod pixels;
/// The pixel store modes, which GLU reads as it unpacks images itself.
pub(crate) use pixels::PixelStore;
mod point;
mod polygon;
mod raster_pos;
mod read_pixels;
mod read_stencil;
mod scissor;
mod select;
pub(crate) mod shade;
mod state_var;
mod stencil;
mod stipple;
mod stipple_query;
mod texture;
pub mod types;
mod units;
mod variants;
mod vertex;
mod viewport;
mod window_read;

pub use arrays::{BufferOffset, PointerArg};
pub use blend::Blend;
pub use buffers::{BufferMap, BufferObject};
pub use client_memory::{ArrayElement, ClientArray, ClientMemory, ClientPointer};
pub use copy_pixels::{CopyFragment, PixelCopy};
pub use eval::{MapSample, MeshJob};
pub use eval::{MapTarget, Slot};
pub use fog::Fog;
pub use fragments::{BufferConfig, FragmentTests, Stencil};
pub use frame::{
    Accumulation, Call, Command, DrawState, Frame, GridMesh, MaterialChange, MeshMode, MeshVertices, Primitive,
    UnitTexCoords,
};
pub use grid_vertices::GridVertices;
pub use lighting::{Light, Lighting, Material};
pub use lists::MAX_LIST_NESTING;
pub use offset::PolygonOffset;
pub use pixel_transfer::{ColorTransfer, DepthTransfer, MAX_PIXEL_MAP_TABLE};
pub use point::PointParameters;
pub use select::SelectHit;
pub use texture::{copied_depth_texel, depth_texel, texel_depth, DepthParams, DepthSampling};
pub use texture::{
    cube_face, cube_face_coords, texture_source, BoundTexture, Combine, Combiner, TexLevel, TexParams,
    MAX_3D_TEXTURE_SIZE, MAX_TEXTURE_SIZE,
};
pub use texture::{TexGen, TexGenCoord, TexGenState, MAX_COMBINED_TEXTURE_IMAGE_UNITS, MAX_TEXTURE_UNITS};
pub use variants::GlComponent;
pub use vertex::Vertex;
pub use window_read::{WindowImage, WindowReader};

use consts::*;
pub(crate) use current::Current;
use types::*;

/// Where `glEvalMesh` grids are evaluated: chosen with [`Gl::set_tessellator`] (a new [`Gl`]
/// starts on the CPU; `App` picks the GPU for `--gpu` or `GLEVAL_TESSELLATOR=gpu`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Tessellator {
    /// On the CPU: the frame holds the vertices (the default; tests read them). A large grid is
    /// evaluated when the call is made; small ones in batches, by the time the frame is looked
    /// at ([`Gl::frame`], [`Gl::take_frame`]), each with the maps and state of its own call.
    #[default]
    Cpu,
    /// In a WGSL compute shader when the frame is drawn: the frame holds the maps, and the
    /// renderer evaluates every mesh of the frame in one dispatch straight into the vertex and
    /// index buffers it draws. [`Frame::expanded`] still gives the vertices (evaluated on the CPU).
    Gpu,
}

impl Tessellator {
    /// The environment variable that `App` reads to pick the tessellator of the
    /// context it hands its callbacks: `gpu` or `cpu`. [`Gl::new`] never reads it.
    pub const ENV: &'static str = "GLEVAL_TESSELLATOR";

    /// `Gpu` when `GLEVAL_TESSELLATOR=gpu`, else `Cpu`.
    #[must_use]
    pub fn from_env() -> Self {
        match std::env::var(Self::ENV) {
            Ok(v) if v.eq_ignore_ascii_case("gpu") => Self::Gpu,
            _ => Self::Cpu,
        }
    }
}

/// The OpenGL version gleval implements, whole (`GL_VERSION` begins with it): the most a
/// GLX or EGL context may ask for.
pub const VERSION: (i32, i32) = (1, 5);

/// The name of a GL error code (`GL_INVALID_ENUM` ...), "an unknown error" for anything else.
#[must_use]
pub fn error_name(code: GLenum) -> &'static str {
    match code {
        GL_NO_ERROR => "GL_NO_ERROR",
        GL_INVALID_ENUM => "GL_INVALID_ENUM",
        GL_INVALID_VALUE => "GL_INVALID_VALUE",
        GL_INVALID_OPERATION => "GL_INVALID_OPERATION",
        GL_STACK_OVERFLOW => "GL_STACK_OVERFLOW",
        GL_STACK_UNDERFLOW => "GL_STACK_UNDERFLOW",
        GL_OUT_OF_MEMORY => "GL_OUT_OF_MEMORY",
        _ => "an unknown error",
    }
}

/// What gleval implements beyond GL 1.1, each extension once it is whole, and nothing more:
/// `glWindowPos` (`raster_pos.rs`), blending's constant colour, equations and separate factors
/// (`blend.rs`), `glDrawRangeElements` and the multi-draws (`array_draws.rs`), the wrapping
/// stencil operations (`stencil.rs`), `GL_RESCALE_NORMAL` (`frame.rs`), `GL_CLAMP_TO_EDGE`
/// and the texture level and LOD range (`texture/params.rs`), 3D textures (`texture/image.rs`),
/// BGRA and the packed pixel types (`pixel_packed.rs`), `GL_ADD` and the combiner with DOT3
/// (`texture/combine.rs`), `GL_CLAMP_TO_BORDER` and `GL_MIRRORED_REPEAT`
/// (`render/soft/sampler.rs`, `shaders/fragment.wgsl`), `GL_GENERATE_MIPMAP`
/// (`texture/generate.rs`), buffer objects (`buffers.rs`), occlusion queries (`occlusion.rs`),
/// GL 1.3's texture units and GL 1.4's crossbar (`multitexture.rs`, `units.rs`,
/// `render/soft/units.rs`; wgpu hands frames drawing with more than unit 0 to the CPU
/// rasteriser, `gpu/fallback.rs`), GL 1.3's cube maps (`texture.rs`, `render/soft/fragment.rs`;
/// drawn by the CPU rasteriser for wgpu too), transpose matrices (`matrix.rs`), and GL 1.4's
/// depth textures with GL 1.4's and 1.5's shadow comparisons (`texture/depth.rs`; the CPU
/// rasteriser draws them for wgpu too), and point sprites (`point.rs`, `render/assemble.rs`:
/// a sprite is the wide point's square with its coordinates, drawn by both rasterisers).
const EXTENSIONS: &str =
    "GL_ARB_depth_buffer_float GL_ARB_depth_texture GL_ARB_map_buffer_range GL_ARB_multisample GL_ARB_multitexture GL_ARB_occlusion_query GL_ARB_pixel_buffer_object GL_ARB_point_parameters GL_ARB_point_sprite GL_ARB_shadow GL_ARB_texture_border_clamp GL_ARB_texture_compression GL_ARB_texture_cube_map GL_ARB_texture_env_add GL_ARB_texture_env_combine GL_ARB_texture_env_crossbar GL_ARB_texture_env_dot3 GL_ARB_texture_mirrored_repeat GL_ARB_texture_non_power_of_two GL_ARB_texture_rectangle GL_ARB_transpose_matrix GL_ARB_vertex_buffer_object GL_ARB_window_pos GL_EXT_bgra GL_EXT_blend_color GL_EXT_blend_equation_separate GL_EXT_blend_func_separate GL_EXT_blend_minmax GL_EXT_blend_subtract GL_EXT_draw_range_elements GL_EXT_fog_coord GL_EXT_multi_draw_arrays GL_EXT_packed_depth_stencil GL_EXT_packed_pixels GL_EXT_pixel_buffer_object GL_EXT_point_parameters GL_EXT_rescale_normal GL_EXT_shadow_funcs GL_EXT_stencil_wrap GL_EXT_texture3D GL_EXT_texture_cube_map GL_EXT_texture_edge_clamp GL_EXT_texture_env_add GL_EXT_texture_env_combine GL_EXT_texture_lod_bias GL_EXT_texture_rectangle GL_EXT_vertex_array GL_IBM_texture_mirrored_repeat GL_NV_blend_square GL_NV_texture_rectangle GL_SGIS_generate_mipmap GL_SGIS_texture_border_clamp GL_SGIS_texture_edge_clamp GL_SGIS_texture_lod";

/// A GL context without a GPU: GL state plus the recording of what is drawn.
///
/// ```
/// use gleval::prelude::*;
/// let mut gl = Gl::new(400, 200);
/// let pts = [-2.0f32, 0.0, 0.0, 0.0, 2.0, 0.0, 2.0, 0.0, 0.0];
/// gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 3, 3, &pts);
/// gl.enable(GL_MAP1_VERTEX_3);
/// gl.map_grid1f(4, 0.0, 1.0);
/// gl.eval_mesh1(GL_LINE, 0, 4);
/// assert_eq!(gl.get_error(), GL_NO_ERROR);
/// // The frame keeps the grid once; `expanded` gives the primitives GL issues.
/// let frame = gl.frame().expanded();
/// let strip = frame.primitives[0];
/// assert_eq!((strip.mode, strip.count), (GL_LINE_STRIP, 5));
/// assert_eq!(frame.vertices[2].position, [0.0, 1.0, 0.0, 1.0]);
/// ```
#[derive(Debug)]
pub struct Gl {
    /// GL's server state, one struct per attribute group (GL 1.1 spec §6.2).
    pub(crate) server: ServerState,
    /// The client's state: arrays, pixel store, and the feedback and selection buffers.
    client: ClientState,
    /// The frame being recorded and what builds it.
    pub(crate) recorder: Recorder,
    /// Display lists, and the one being compiled.
    lists: lists::Lists,
    /// GLU's objects, one handle table per kind: the one import from `gl` into `glu`, since
    /// GLU's calls are methods of `Gl` (the porting rule).
    pub(crate) glu: crate::glu::GluObjects,
    /// What GLUT's calls made inside callbacks ask of the window (redisplay, timers, idle, title).
    pub(crate) glut: crate::glut::GlutState,
    /// GL's error flag: the first error since the last `glGetError`.
    error: GLenum,
}

/// GL's server state (GL 1.1 spec §6.2, tables 6.3–6.20): what `glPushAttrib` saves.
#[derive(Debug)]
pub(crate) struct ServerState {
    pub(crate) current: Current,
    pub(super) caps: enable::Caps,
    /// The depth buffer group: the test's function, the write mask, the clear value.
    pub(super) depth: depth::Depth,
    /// The point group: the point size.
    pub(super) point: point::Point,
    /// The line group: the width and the stipple.
    pub(super) line: line::Line,
    /// The polygon group: modes, facing, culling, offset.
    pub(super) polygon: polygon::Polygon,
    pub(crate) eval: eval::EvalState,
    /// `glPushAttrib`'s stack.
    pub(super) attrib_stack: attrib::AttribStack,
    pub(super) active_texture: GLenum,
    pub(crate) matrices: matrix::MatrixStacks,
    pub(super) lighting: lighting::Lighting,
    /// The viewport group: the rectangle and the depth range.
    pub(super) viewport: viewport::Viewport,
    /// `glShadeModel` (the lighting group's; `Lighting` is what a lit draw carries).
    pub(super) shade_model: GLenum,
    /// `glClipPlane`'s planes in eye coordinates, as transformed at the call (the transform
    /// group's, with the matrix mode).
    pub(super) clip_planes: [[f32; 4]; clip::MAX_CLIP_PLANES],
    /// `glPolygonStipple`, the polygon stipple group: row y, bit x for window pixel (x, y)
    /// modulo 32.
    pub(super) polygon_stipple: [u32; 32],
    /// The current raster position, where bitmaps and pixels are drawn.
    pub(super) raster_pos: raster_pos::RasterPos,
    /// Texture objects, and each unit's bindings and environment.
    pub(super) textures: texture::Textures,
    /// Each unit's `glTexGen` modes and planes.
    pub(super) tex_gen: [texture::TexGen; units::MAX_TEXTURE_UNITS],
    /// What Mesa's deferred `glMaterial` leaves of `GL_COLOR_MATERIAL`'s tracking.
    pub(super) color_material_sync: lighting::ColorMaterialSync,
    /// `glHint`'s requests.
    pub(super) hints: hint::Hints,
    /// The colour buffer group: alpha test, blending, logic op, colour mask, draw buffer,
    /// clear colour.
    pub(super) color_buffer: color_buffer::ColorBuffer,
    /// The fog group.
    pub(super) fog: fog::FogState,
    /// The stencil buffer group: the test, its masks and operations, the clear value.
    pub(super) stencil: stencil::StencilBuffer,
    /// The scissor group: the box (x, y, width, height).
    pub(super) scissor: [GLint; 4],
    /// The accumulation buffer group: the clear value.
    pub(super) clear_accum: [f32; 4],
    /// The multisample group: `glSampleCoverage`.
    pub(super) multisample: multisample::Multisample,
    /// The drawable's buffers (not an attribute group: no push saves them).
    pub(super) framebuffer: fragments::BufferConfig,
    /// `glPixelTransfer`, `glPixelMap` and `glPixelZoom`.
    pub(super) pixel_state: pixel_transfer::PixelState,
    /// The colour-index calls' state (an RGBA context keeps it and draws nothing with it).
    pub(super) color_index: color_index::ColorIndex,
    /// GL 1.5's occlusion queries (no attribute group).
    pub(super) queries: occlusion::Queries,
}

impl ServerState {
    /// GL's initial state for a `width` × `height` drawable.
    fn new(width: i32, height: i32) -> Self {
        Self {
            current: Current::default(),
            caps: enable::Caps::default(),
            depth: depth::Depth::default(),
            point: point::Point::default(),
            line: line::Line::default(),
            polygon: polygon::Polygon::default(),
            eval: eval::EvalState::default(),
            attrib_stack: attrib::AttribStack::default(),
            active_texture: GL_TEXTURE0,
            matrices: matrix::MatrixStacks::default(),
            lighting: lighting::Lighting::default(),
            viewport: viewport::Viewport::new(width, height),
            shade_model: GL_SMOOTH,
            clip_planes: [[0.0; 4]; clip::MAX_CLIP_PLANES],
            polygon_stipple: [u32::MAX; 32],
            raster_pos: raster_pos::RasterPos::default(),
            textures: texture::Textures::default(),
            tex_gen: [texture::TexGen::default(); units::MAX_TEXTURE_UNITS],
            color_material_sync: lighting::ColorMaterialSync::default(),
            hints: hint::Hints::default(),
            color_buffer: color_buffer::ColorBuffer::default(),
            fog: fog::FogState::default(),
            stencil: stencil::StencilBuffer::default(),
            scissor: [0, 0, width, height],
            clear_accum: [0.0; 4],
            multisample: multisample::Multisample::default(),
            framebuffer: fragments::BufferConfig::default(),
            pixel_state: pixel_transfer::PixelState::default(),
            color_index: color_index::ColorIndex::default(),
            queries: occlusion::Queries::default(),
        }
    }
}

/// The client's state (GL 1.1 spec §6.1.13, what `glPushClientAttrib` saves, with the feedback
/// and selection buffers, which GL keeps on the client side too).
#[derive(Debug, Default)]
struct ClientState {
    /// How client memory is laid out for images and bitmaps (`glPixelStore`).
    pixel_stores: pixels::PixelStores,
    /// The client's vertex arrays and the current edge flag.
    arrays: arrays::VertexArrays,
    /// `glRenderMode(GL_FEEDBACK)` and its buffer.
    feedback: feedback::Feedback,
    /// Selection mode: its buffer, the name stack and the hit being gathered.
    select: select::Selection,
    /// GL 1.5's buffer objects by name (their bindings are the vertex arrays').
    buffers: buffers::BufferObjects,
}

/// The recording: the frame, the primitive open between `begin` and `end`, and what the
/// frame's meshes are evaluated with.
#[derive(Debug)]
pub(crate) struct Recorder {
    pub(super) width: i32,
    pub(super) height: i32,
    /// Index in `frame.primitives` of the primitive being built between begin and end.
    pub(super) open_primitive: Option<usize>,
    /// Index in `frame.states` of a snapshot of the current state, if still valid.
    pub(super) state_index: Option<usize>,
    pub(super) frame: Frame,
    /// Vertex buffers of a recycled frame's meshes, reused by the next meshes (no page faults).
    pub(super) vertex_pool: Vec<GridVertices>,
    /// Small CPU meshes recorded but not yet evaluated (see `Gl::record_mesh`).
    pub(super) pending_meshes: eval::PendingMeshes,
    pub(super) tessellator: Tessellator,
    /// What reads the window mid-frame (`glCopyTexImage`).
    pub(super) window_reader: window_read::Reader,
    /// A `glDrawElements` is issuing its elements (see [`Primitive::listed_or_indexed`]).
    pub(super) indexed_draw: bool,
    /// The open primitive draws with units beyond unit 0: its vertices record those units'
    /// coordinates ([`Frame::unit_tex_coords`]).
    pub(super) multi_unit: bool,
    /// Buffer swaps recorded since the context was made ([`Gl::buffer_swaps`]).
    pub(super) swaps: u64,
}

impl Recorder {
    fn new(width: i32, height: i32) -> Self {
        Self {
            width,
            height,
            open_primitive: None,
            state_index: None,
            frame: Frame::default(),
            vertex_pool: Vec::new(),
            pending_meshes: eval::PendingMeshes::default(),
            tessellator: Tessellator::Cpu,
            window_reader: window_read::Reader::default(),
            indexed_draw: false,
            multi_unit: false,
            swaps: 0,
        }
    }
}

impl Gl {
    /// A context for a drawable of `width` × `height` pixels, in GL's initial state.
    #[must_use]
    pub fn new(width: i32, height: i32) -> Self {
        Self {
            server: ServerState::new(width, height),
            client: ClientState::default(),
            recorder: Recorder::new(width, height),
            lists: lists::Lists::default(),
            glu: crate::glu::GluObjects::default(),
            glut: crate::glut::GlutState::default(),
            error: GL_NO_ERROR,
        }
    }

    /// The drawable's width in pixels.
    #[must_use]
    pub fn width(&self) -> i32 {
        self.recorder.width
    }

    /// The drawable's height in pixels.
    #[must_use]
    pub fn height(&self) -> i32 {
        self.recorder.height
    }

    /// Sets the drawable size that `glutGet` reports (the window was resized).
    pub fn set_window_size(&mut self, width: i32, height: i32) {
        self.recorder.width = width;
        self.recorder.height = height;
    }

    /// What has been drawn so far (small meshes still pending are evaluated first, hence
    /// `&mut self`).
    #[must_use]
    pub fn frame(&mut self) -> &Frame {
        self.evaluate_pending_meshes();
        &self.recorder.frame
    }

    /// Where `glEvalMesh` grids are evaluated from now on.
    pub fn set_tessellator(&mut self, tessellator: Tessellator) {
        self.recorder.tessellator = tessellator;
    }

    /// The tessellator in use.
    #[must_use]
    pub fn tessellator(&self) -> Tessellator {
        self.recorder.tessellator
    }

    /// Takes the recorded frame, leaving an empty one (the GL state is kept).
    pub fn take_frame(&mut self) -> Frame {
        self.evaluate_pending_meshes();
        // The occlusion queries' counts come from the frame before it goes.
        self.queries_leave_frame();
        self.recorder.state_index = None;
        let frame = std::mem::take(&mut self.recorder.frame);
        self.queries_enter_frame();
        frame
    }

    /// Gives a frame taken with [`Gl::take_frame`] back once it is drawn: its buffers are reused
    /// by the frames recorded next, so a render loop does not allocate (and fault in) fresh
    /// memory for every frame.
    pub fn recycle_frame(&mut self, mut frame: Frame) {
        self.recorder.vertex_pool.clear();
        for mesh in frame.meshes.drain(..) {
            if let MeshVertices::Evaluated(vertices) = mesh.vertices {
                self.recorder.vertex_pool.push(vertices);
            }
        }
        if self.recorder.frame.commands.is_empty() && self.recorder.frame.states.is_empty() {
            frame.vertices.clear();
            frame.primitives.clear();
            frame.calls.clear();
            frame.states.clear();
            frame.commands.clear();
            frame.material_changes.clear();
            frame.hidden_edges.clear();
            frame.pixel_copies.clear();
            self.recorder.frame = frame;
        }
    }

    /// A vertex buffer from the recycled pool (empty if none is left).
    pub(crate) fn pooled_vertices(&mut self) -> GridVertices {
        self.recorder.vertex_pool.pop().unwrap_or_default()
    }

    /// Marks the draw state as changed: the next primitive records a new snapshot.
    pub(crate) fn touch_state(&mut self) {
        self.recorder.state_index = None;
    }

    /// The index of the current draw state in the frame, recording it if needed.
    pub(crate) fn current_state_index(&mut self) -> usize {
        if let Some(i) = self.recorder.state_index {
            return i;
        }
        let texture = self.bound_texture();
        let mut state = self.snapshot(texture);
        state.more_textures = self.more_textures();
        self.recorder.frame.states.push(state);
        let i = self.recorder.frame.states.len() - 1;
        self.recorder.state_index = Some(i);
        i
    }

    fn snapshot(&self, texture: Option<texture::BoundTexture>) -> DrawState {
        let lighting = self.server.caps.is_on(GL_LIGHTING).then(|| {
            let mut l = self.server.lighting.clone();
            for (i, light) in l.lights.iter_mut().enumerate() {
                light.enabled = self.server.caps.is_on(GL_LIGHT0 + i as GLenum);
            }
            l
        });
        DrawState {
            modelview: self.server.matrices.modelview(),
            projection: self.server.matrices.projection(),
            viewport: self.server.viewport.rect,
            depth_range: self.server.viewport.depth_range,
            lighting,
            color_material: self.color_material_tracks(),
            normalize: self.server.caps.is_on(GL_NORMALIZE),
            rescale_normal: self.server.caps.is_on(GL_RESCALE_NORMAL),
            color_sum: self.server.caps.is_on(GL_COLOR_SUM),
            shade_model: self.server.shade_model,
            point_size: self.server.point.size,
            point_parameters: self.server.point.parameters,
            line_width: self.server.line.width,
            polygon_mode: self.server.polygon.mode,
            front_face: self.server.polygon.front_face,
            cull_face: self.server.caps.is_on(GL_CULL_FACE).then_some(self.server.polygon.cull_face),
            depth_test: self.server.caps.is_on(GL_DEPTH_TEST).then_some(self.server.depth.func),
            texture,
            more_textures: Vec::new(),
            blend: self.enabled_blend(),
            alpha_test: self.enabled_alpha_test(),
            fog: self.enabled_fog(),
            line_stipple: self.enabled_line_stipple(),
            point_smooth: self.server.caps.is_on(GL_POINT_SMOOTH),
            point_sprite: self.server.caps.is_on(GL_POINT_SPRITE).then_some(self.server.point.coord_replace),
            line_smooth: self.server.caps.is_on(GL_LINE_SMOOTH),
            polygon_offset: self.enabled_polygon_offset(),
            clip_planes: self.enabled_clip_planes(),
            polygon_stipple: self.enabled_polygon_stipple(),
            fragment_tests: self.fragment_tests(),
        }
    }

    /// `glGetError`: returns the first error recorded since the last call and clears it.
    /// Inside `begin`/`end` it returns `GL_NO_ERROR` and records `GL_INVALID_OPERATION`, as Mesa does.
    pub fn get_error(&mut self) -> GLenum {
        if self.inside_begin_end() {
            self.set_error(GL_INVALID_OPERATION);
            return GL_NO_ERROR;
        }
        std::mem::replace(&mut self.error, GL_NO_ERROR)
    }

    /// `glGetString`: who implements this GL (`GL_VENDOR` "gleval"), on what (`GL_RENDERER`:
    /// the tessellator in use; wgpu draws what is recorded), the version (`GL_VERSION`: "1.5"
    /// and ours: GL 1.5 is whole, GL 1.2's imaging subset aside, as GL allows) and the extensions
    /// complete beyond it
    /// (`GL_EXTENSIONS`: each extension that is whole, in `EXTENSIONS`).
    /// Another name → `GL_INVALID_ENUM` and `None` (C's NULL), as inside `begin`/`end`
    /// (`GL_INVALID_OPERATION`).
    pub fn get_string(&mut self, name: GLenum) -> Option<&'static str> {
        if self.reject_inside_begin_end() {
            return None;
        }
        match name {
            GL_VENDOR => Some("gleval"),
            GL_RENDERER => Some(match self.recorder.tessellator {
                Tessellator::Cpu => "gleval (CPU tessellator, wgpu rasteriser)",
                Tessellator::Gpu => "gleval (WGSL tessellator, wgpu rasteriser)",
            }),
            GL_VERSION => Some(concat!("1.5 gleval ", env!("CARGO_PKG_VERSION"))),
            GL_EXTENSIONS => Some(EXTENSIONS),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// Records `code` unless an earlier error is still pending (GL's sticky flag; Mesa's `_mesa_error`).
    /// The error flag as it stands, without clearing it (the C library's `GLEVAL_DEBUG`
    /// names each error a call raised).
    #[must_use]
    pub fn pending_error(&self) -> GLenum {
        self.error
    }

    pub(crate) fn set_error(&mut self, code: GLenum) {
        if self.error == GL_NO_ERROR {
            self.error = code;
        }
    }

    /// Whether a `begin` is open (no `end` yet): where GL forbids most calls.
    #[must_use]
    pub fn inside_begin_end(&self) -> bool {
        self.recorder.open_primitive.is_some()
    }

    /// For calls GL forbids between `begin` and `end`: records `GL_INVALID_OPERATION` and
    /// returns true when inside.
    pub(crate) fn reject_inside_begin_end(&mut self) -> bool {
        let inside = self.inside_begin_end();
        if inside {
            self.set_error(GL_INVALID_OPERATION);
        }
        inside
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn get_string_names_and_errors() {
        let mut gl = Gl::new(4, 4);
        assert_eq!(gl.get_string(GL_VENDOR), Some("gleval"));
        let version = format!("{}.{} ", VERSION.0, VERSION.1);
        assert!(gl.get_string(GL_VERSION).is_some_and(|v| v.starts_with(&version)));
        // The claims, spelled out: a new one is a decision, made here as well.
        let claimed = [
            "GL_ARB_depth_buffer_float",
            "GL_ARB_depth_texture",
            "GL_ARB_map_buffer_range",
            "GL_ARB_multisample",
            "GL_ARB_multitexture",
            "GL_ARB_occlusion_query",
            "GL_ARB_pixel_buffer_object",
            "GL_ARB_point_parameters",
            "GL_ARB_point_sprite",
            "GL_ARB_shadow",
            "GL_ARB_texture_border_clamp",
            "GL_ARB_texture_compression",
            "GL_ARB_texture_cube_map",
            "GL_ARB_texture_env_add",
            "GL_ARB_texture_env_combine",
            "GL_ARB_texture_env_crossbar",
            "GL_ARB_texture_env_dot3",
            "GL_ARB_texture_mirrored_repeat",
            "GL_ARB_texture_non_power_of_two",
            "GL_ARB_texture_rectangle",
            "GL_ARB_transpose_matrix",
            "GL_ARB_vertex_buffer_object",
            "GL_ARB_window_pos",
            "GL_EXT_bgra",
            "GL_EXT_blend_color",
            "GL_EXT_blend_equation_separate",
            "GL_EXT_blend_func_separate",
            "GL_EXT_blend_minmax",
            "GL_EXT_blend_subtract",
            "GL_EXT_draw_range_elements",
            "GL_EXT_fog_coord",
            "GL_EXT_multi_draw_arrays",
            "GL_EXT_packed_depth_stencil",
            "GL_EXT_packed_pixels",
            "GL_EXT_pixel_buffer_object",
            "GL_EXT_point_parameters",
            "GL_EXT_rescale_normal",
            "GL_EXT_shadow_funcs",
            "GL_EXT_stencil_wrap",
            "GL_EXT_texture3D",
            "GL_EXT_texture_cube_map",
            "GL_EXT_texture_edge_clamp",
            "GL_EXT_texture_env_add",
            "GL_EXT_texture_env_combine",
            "GL_EXT_texture_lod_bias",
            "GL_EXT_texture_rectangle",
            "GL_EXT_vertex_array",
            "GL_IBM_texture_mirrored_repeat",
            "GL_NV_blend_square",
            "GL_NV_texture_rectangle",
            "GL_SGIS_generate_mipmap",
            "GL_SGIS_texture_border_clamp",
            "GL_SGIS_texture_edge_clamp",
            "GL_SGIS_texture_lod",
        ];
        assert_eq!(gl.get_string(GL_EXTENSIONS), Some(claimed.join(" ").as_str()));
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        assert_eq!(gl.get_string(0x1234), None);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.begin(GL_POINTS);
        assert_eq!(gl.get_string(GL_VENDOR), None);
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    }
}
