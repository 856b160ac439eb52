//! The frame rasteriser: draws the CPU's assembled vertices ([`RasterVertex`]: clip position
//! and final colour, `shaders/raster.wgsl`). GL's vertex stage already ran on the CPU, so all
//! that is left is GL's viewport, which wgpu cannot take as GL gives it (see
//! [`to_target_space`]).

use super::device::shader_module;
use super::layout::RASTER_WGSL;
use super::raster::{PipelineTests, RasterPipeline};
use super::textures::{self, TextureCache};
use crate::gl::types::GLenum;
use crate::render::assemble::{DrawList, Op, RasterVertex, Topology};
use std::collections::HashMap;
use wgpu::util::DeviceExt;

/// Pipeline key: topology, depth function, target format, blend factors, stencil and masks.
pub(crate) type PipelineKey = (Topology, Option<GLenum>, wgpu::TextureFormat, Option<wgpu::BlendState>, PipelineTests);

/// The frame rasteriser's shader and its pipelines, made on first use, and the textures it
/// samples.
pub(crate) struct FrameRaster {
    module: wgpu::ShaderModule,
    layout: wgpu::PipelineLayout,
    texture_layout: wgpu::BindGroupLayout,
    pipelines: HashMap<PipelineKey, wgpu::RenderPipeline>,
    textures: TextureCache,
}

impl FrameRaster {
    /// Compiles `shaders/raster.wgsl` on `device`.
    pub(crate) fn new(device: &wgpu::Device) -> Self {
        let module = shader_module(device, "raster.wgsl", RASTER_WGSL);
        let texture_layout = textures::bind_group_layout(device);
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("raster"),
            bind_group_layouts: &[Some(&texture_layout)],
            immediate_size: 0,
        });
        Self { module, layout, texture_layout, pipelines: HashMap::new(), textures: TextureCache::default() }
    }

    /// The bind groups of a list's batches: one per fragment state of the list, in its order,
    /// then the one for batches without any (see [`TextureCache::bind_groups`]).
    pub(crate) fn texture_bind_groups(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        list: &DrawList,
        height: u32,
    ) -> Vec<wgpu::BindGroup> {
        self.textures.bind_groups(device, queue, &self.texture_layout, &list.fragments, height)
    }

    /// The layout of the texture bind groups (the mesh rasteriser's group 1 too).
    pub(crate) fn texture_layout(&self) -> &wgpu::BindGroupLayout {
        &self.texture_layout
    }

    /// Makes sure the pipelines for `keys` exist (before a render pass borrows them all).
    pub(crate) fn ensure_pipelines(&mut self, device: &wgpu::Device, keys: impl IntoIterator<Item = PipelineKey>) {
        let (module, layout) = (&self.module, &self.layout);
        super::raster::make_missing(&mut self.pipelines, keys, |key| make_pipeline(device, module, layout, key));
    }

    /// The pipeline for `key`, made by [`FrameRaster::ensure_pipelines`].
    pub(crate) fn pipeline(&self, key: PipelineKey) -> &wgpu::RenderPipeline {
        &self.pipelines[&key]
    }
}

fn make_pipeline(
    device: &wgpu::Device,
    module: &wgpu::ShaderModule,
    layout: &wgpu::PipelineLayout,
    (topology, depth, format, blend, tests): PipelineKey,
) -> wgpu::RenderPipeline {
    let attributes = wgpu::vertex_attr_array![0 => Float32x4, 1 => Float32x4, 2 => Float32x4, 3 => Float32x4, 4 => Float32, 5 => Float32x4];
    let vertex = wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<RasterVertex>() as wgpu::BufferAddress,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &attributes,
    };
    RasterPipeline {
        label: "gl raster",
        module,
        entry_points: ("vs_main", "fs_main"),
        layout,
        vertex,
        topology,
        depth,
        // The CPU culled already; wgpu's defaults, no culling.
        faces: (wgpu::FrontFace::Ccw, None),
        format,
        blend,
        tests,
    }
    .build(device)
}

/// The list's vertices in one vertex buffer (in the target's clip space, upside down with
/// `flip`), if there are any.
pub(crate) fn vertex_buffer(
    device: &wgpu::Device,
    list: &DrawList,
    size: (u32, u32),
    flip: bool,
) -> Option<wgpu::Buffer> {
    let mut vertices = to_target_space(list, size);
    if flip {
        vertices.iter_mut().for_each(|v| v.clip[1] = -v.clip[1]);
    }
    (!vertices.is_empty()).then(|| {
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("frame vertices"),
            contents: bytemuck::cast_slice(&vertices),
            usage: wgpu::BufferUsages::VERTEX,
        })
    })
}

/// Moves each batch's vertices from its GL viewport's clip space into the whole target's:
/// x' = x·(vw/W) + w·((2·vx + vw)/W − 1), likewise y. wgpu needs viewports inside the target;
/// GL allows them anywhere, so the viewport transform is applied here instead.
fn to_target_space(list: &DrawList, (width, height): (u32, u32)) -> Vec<RasterVertex> {
    let mut out = list.vertices.clone();
    let (fw, fh) = (width as f32, height as f32);
    for op in &list.ops {
        let Op::Draw(b) = op else { continue };
        let [vx, vy, vw, vh] = b.viewport.map(|c| c as f32);
        let (sx, ox) = (vw / fw, (2.0 * vx + vw) / fw - 1.0);
        let (sy, oy) = (vh / fh, (2.0 * vy + vh) / fh - 1.0);
        for v in &mut out[b.first as usize..(b.first + b.count) as usize] {
            let w = v.clip[3];
            v.clip[0] = v.clip[0] * sx + w * ox;
            v.clip[1] = v.clip[1] * sy + w * oy;
        }
    }
    out
}
