//! The one raster-pipeline builder, shared by the frame rasteriser (assembled vertices) and the
//! mesh rasteriser (the evaluator's vertices): what GL's depth test, face culling and topology
//! mean in wgpu is written here once, so a depth or culling fix reaches both.

use crate::gl::consts::*;
use crate::gl::types::GLenum;
use crate::gl::FragmentTests;
use crate::render::assemble::Topology;
use std::collections::HashMap;
use std::hash::Hash;

/// The depth and stencil buffer's format: GL's depth after the viewport transform, in [0, 1],
/// as a 32-bit float, and an 8-bit stencil (the device asks for `DEPTH32FLOAT_STENCIL8`).
pub(crate) const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32FloatStencil8;

/// The per-fragment state a pipeline bakes in (the stencil reference is set per draw): the
/// stencil test's function, masks and operations, depth writes and the colour write mask.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct PipelineTests {
    /// Function, value mask, operations (fail, depth fail, pass), write mask.
    stencil: Option<(GLenum, u32, [GLenum; 3], u32)>,
    depth_write: bool,
    color_write: [bool; 4],
}

impl PipelineTests {
    /// What `tests` asks of the pipeline.
    pub(crate) fn of(tests: &FragmentTests) -> Self {
        Self {
            stencil: tests.stencil.map(|s| (s.func, s.value_mask & 0xFF, s.ops, s.write_mask & 0xFF)),
            depth_write: tests.depth_write,
            color_write: tests.color_write,
        }
    }

    fn color_writes(&self) -> wgpu::ColorWrites {
        let bits =
            [wgpu::ColorWrites::RED, wgpu::ColorWrites::GREEN, wgpu::ColorWrites::BLUE, wgpu::ColorWrites::ALPHA];
        bits.iter().zip(self.color_write).filter(|(_, on)| *on).fold(wgpu::ColorWrites::empty(), |a, (b, _)| a | *b)
    }
}

impl Default for PipelineTests {
    fn default() -> Self {
        Self::of(&FragmentTests::default())
    }
}

/// Everything in which the two rasterisers' pipelines differ.
pub(crate) struct RasterPipeline<'a> {
    /// A label for wgpu's messages.
    pub label: &'a str,
    /// The shader module and its vertex and fragment entry points.
    pub module: &'a wgpu::ShaderModule,
    pub entry_points: (&'a str, &'a str),
    /// The bind groups the shader reads.
    pub layout: &'a wgpu::PipelineLayout,
    /// The vertex buffer's stride and attributes.
    pub vertex: wgpu::VertexBufferLayout<'a>,
    pub topology: Topology,
    /// GL's depth function while `GL_DEPTH_TEST` is on, `None` while it is off.
    pub depth: Option<GLenum>,
    /// GL's front face, and the face culled (only ever for triangles).
    pub faces: (wgpu::FrontFace, Option<wgpu::Face>),
    /// The colour target's format.
    pub format: wgpu::TextureFormat,
    /// GL's blending, when enabled.
    pub blend: Option<wgpu::BlendState>,
    /// The stencil test and the write masks.
    pub tests: PipelineTests,
}

impl RasterPipeline<'_> {
    /// Builds the pipeline. No blending: the GL subset draws opaque colours.
    pub(crate) fn build(self, device: &wgpu::Device) -> wgpu::RenderPipeline {
        let (front_face, cull_mode) = self.faces;
        let primitive =
            wgpu::PrimitiveState { topology: topology(self.topology), front_face, cull_mode, ..Default::default() };
        device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(self.label),
            layout: Some(self.layout),
            vertex: wgpu::VertexState {
                module: self.module,
                entry_point: Some(self.entry_points.0),
                compilation_options: Default::default(),
                buffers: &[Some(self.vertex)],
            },
            primitive,
            depth_stencil: Some(depth_stencil(self.depth, &self.tests)),
            multisample: wgpu::MultisampleState::default(),
            fragment: Some(wgpu::FragmentState {
                module: self.module,
                entry_point: Some(self.entry_points.1),
                compilation_options: Default::default(),
                targets: &[Some(wgpu::ColorTargetState {
                    format: self.format,
                    blend: self.blend,
                    write_mask: self.tests.color_writes(),
                })],
            }),
            multiview_mask: None,
            cache: None,
        })
    }
}

fn topology(topology: Topology) -> wgpu::PrimitiveTopology {
    match topology {
        Topology::Triangles => wgpu::PrimitiveTopology::TriangleList,
        Topology::Lines => wgpu::PrimitiveTopology::LineList,
        Topology::Points => wgpu::PrimitiveTopology::PointList,
    }
}

/// Without `GL_DEPTH_TEST`, GL neither tests nor writes depth (GL 1.1 spec §4.1.5); with it,
/// `glDepthMask` decides the write. The stencil test (§4.1.4) compares the reference (set per
/// draw) with the stored value, both through the value mask, as wgpu does.
fn depth_stencil(depth: Option<GLenum>, tests: &PipelineTests) -> wgpu::DepthStencilState {
    let stencil =
        tests.stencil.map_or_else(wgpu::StencilState::default, |(func, read_mask, [fail, zfail, pass], write_mask)| {
            let face = wgpu::StencilFaceState {
                compare: compare(func),
                fail_op: stencil_op(fail),
                depth_fail_op: stencil_op(zfail),
                pass_op: stencil_op(pass),
            };
            wgpu::StencilState { front: face, back: face, read_mask, write_mask }
        });
    wgpu::DepthStencilState {
        format: DEPTH_FORMAT,
        depth_write_enabled: Some(depth.is_some() && tests.depth_write),
        depth_compare: Some(depth.map_or(wgpu::CompareFunction::Always, compare)),
        stencil,
        bias: wgpu::DepthBiasState::default(),
    }
}

/// GL's stencil operation as wgpu's (8 bits: `GL_INCR`/`GL_DECR` clamp, the `_WRAP` ones wrap).
fn stencil_op(op: GLenum) -> wgpu::StencilOperation {
    use wgpu::StencilOperation as S;
    match op {
        GL_ZERO => S::Zero,
        GL_REPLACE => S::Replace,
        GL_INCR => S::IncrementClamp,
        GL_DECR => S::DecrementClamp,
        GL_INVERT => S::Invert,
        GL_INCR_WRAP => S::IncrementWrap,
        GL_DECR_WRAP => S::DecrementWrap,
        _ => S::Keep,
    }
}

/// GL's depth function as wgpu's comparison.
fn compare(func: GLenum) -> wgpu::CompareFunction {
    match func {
        GL_NEVER => wgpu::CompareFunction::Never,
        GL_EQUAL => wgpu::CompareFunction::Equal,
        GL_LEQUAL => wgpu::CompareFunction::LessEqual,
        GL_GREATER => wgpu::CompareFunction::Greater,
        GL_NOTEQUAL => wgpu::CompareFunction::NotEqual,
        GL_GEQUAL => wgpu::CompareFunction::GreaterEqual,
        GL_ALWAYS => wgpu::CompareFunction::Always,
        _ => wgpu::CompareFunction::Less,
    }
}

/// Makes the pipelines of `keys` that `cache` lacks, several at once: a software driver
/// compiles each pipeline on the thread that asks for it (lavapipe: a few milliseconds each,
/// most of a first frame's time), so a frame needing several pays for the slowest, not the sum.
pub(crate) fn make_missing<K: Copy + Eq + Hash + Send + Sync>(
    cache: &mut HashMap<K, wgpu::RenderPipeline>,
    keys: impl IntoIterator<Item = K>,
    make: impl Fn(K) -> wgpu::RenderPipeline + Sync,
) {
    let mut missing: Vec<K> = Vec::new();
    for key in keys {
        if !cache.contains_key(&key) && !missing.contains(&key) {
            missing.push(key);
        }
    }
    if missing.len() < 2 {
        cache.extend(missing.into_iter().map(|k| (k, make(k))));
        return;
    }
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get()).min(missing.len());
    let chunk = missing.len().div_ceil(threads);
    let made: Vec<(K, wgpu::RenderPipeline)> = std::thread::scope(|scope| {
        let workers: Vec<_> = missing
            .chunks(chunk)
            .map(|keys| scope.spawn(|| keys.iter().map(|&k| (k, make(k))).collect::<Vec<_>>()))
            .collect();
        // A worker that panicked (wgpu reports its errors through the device, not by
        // panicking) loses its pipelines; they are made again below.
        workers.into_iter().filter_map(|w| w.join().ok()).flatten().collect()
    });
    cache.extend(made);
    for key in missing {
        cache.entry(key).or_insert_with(|| make(key));
    }
}
