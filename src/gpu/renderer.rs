//! The [`Renderer`]: draws a recorded [`Frame`] into an RGBA8 target, headless (read back as an
//! [`Image`]) or into a window's surface. It assembles the frame on the CPU, leaves the meshes
//! the GPU can take to the mesh rasteriser (one evaluator dispatch), and draws everything in
//! program order, one render pass per GL clear.
//!
//! GL conventions kept in one place: viewports (origin bottom-left, allowed outside the
//! drawable) become a full-target transform of the clip coordinates plus a scissor rectangle,
//! which is what clipping to GL's view volume amounts to; depth was already mapped to [0, 1]
//! during assembly; the depth test and depth writes exist only while `GL_DEPTH_TEST` is on.

use super::device::{first_adapter, request_device, ErrorSlot, Gpu, RenderError};
use super::evaluate;
use super::frame_raster::{vertex_buffer, FrameRaster, PipelineKey};
use super::mesh_raster::{gpu_mesh_indices, MeshRaster, PreparedMeshes};
use super::passes::{begin_pass, draw_rect, split_passes, stencil_reference, PassItem};
use super::raster::PipelineTests;
use super::target::Target;
use crate::gl::consts::GL_DEPTH;
use crate::gl::{Frame, WindowImage};
use crate::math::BezierPatch;
use crate::render::assemble::{assemble_frame, Batch, DrawList, Op};
use crate::render::pixel_copy::{copy_batch, copy_vertices};
use crate::render::Image;
use crate::tess::Mesh;

const COLOR_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// A wgpu device with the pipelines that draw assembled GL frames.
pub struct Renderer {
    /// The instance the adapter came from (a window surface must be made from it).
    pub instance: wgpu::Instance,
    /// The adapter in use.
    pub adapter: wgpu::Adapter,
    /// The device.
    pub device: wgpu::Device,
    /// Its queue.
    pub queue: wgpu::Queue,
    frames: FrameRaster,
    meshes: Option<MeshRaster>,
    errors: ErrorSlot,
}

/// Where a render goes: colour and depth views of a `size` target whose colour is `format`,
/// drawn upside down with `flip` (see [`Renderer::render_frame`]).
pub(crate) struct Attachments<'a> {
    color: &'a wgpu::TextureView,
    depth: &'a wgpu::TextureView,
    size: (u32, u32),
    format: wgpu::TextureFormat,
    flip: bool,
}

impl<'a> Attachments<'a> {
    /// A window's surface views, drawn the right way up: what [`Renderer::encode`] draws
    /// onto, and the GLUT menu pass after it ([`Renderer::encode_over`]).
    pub(crate) fn window(
        color: &'a wgpu::TextureView,
        depth: &'a wgpu::TextureView,
        size: (u32, u32),
        format: wgpu::TextureFormat,
    ) -> Self {
        Attachments { color, depth, size, format, flip: false }
    }
}

impl Renderer {
    /// A headless renderer on the first adapter that works (see [`RenderError::NoAdapter`]).
    pub fn new() -> Result<Self, RenderError> {
        let (instance, adapter) = first_adapter()?;
        Self::with_adapter(instance, adapter)
    }

    /// A renderer on a given instance and adapter (a window's).
    pub fn with_adapter(instance: wgpu::Instance, adapter: wgpu::Adapter) -> Result<Self, RenderError> {
        let (device, queue) = request_device(&adapter)?;
        let errors = ErrorSlot::catching(&device);
        let frames = FrameRaster::new(&device);
        Ok(Self { instance, adapter, device, queue, frames, meshes: None, errors })
    }

    /// Whether flat shading takes a primitive's last vertex (GL's convention, kept by wgpu's GL
    /// backend) rather than its first (Vulkan, Metal, DX12).
    pub fn provoking_vertex_is_last(&self) -> bool {
        self.adapter.get_info().backend == wgpu::Backend::Gl
    }

    /// A one-line description of the adapter (name and backend).
    #[must_use]
    pub fn adapter_name(&self) -> String {
        let info = self.adapter.get_info();
        format!("{} ({:?})", info.name, info.backend)
    }

    /// What the evaluator needs of this renderer (for the tests and benchmarks that drive it
    /// directly).
    #[doc(hidden)]
    pub fn gpu(&self) -> Gpu<'_> {
        Gpu {
            device: &self.device,
            queue: &self.queue,
            errors: &self.errors,
            provoking_last: self.provoking_vertex_is_last(),
        }
    }

    /// Renders a recorded frame headless and reads it back. The target is drawn upside down
    /// (GL's bottom row first) and read back the right way up: Vulkan's top-left fill rule then
    /// includes the pixels on a triangle's left and bottom edges in GL's window, llvmpipe's rule
    /// for GL (measured on Mesa 22.3; the CPU rasteriser's too).
    pub fn render_frame(&mut self, frame: &Frame, width: u32, height: u32) -> Result<Image, RenderError> {
        let window = self.render_window(frame, width, height, false)?;
        Ok(Image { width: window.width, height: window.height, pixels: window.color })
    }

    /// Renders a recorded frame headless and reads its colour back, and its depth with `depth`.
    /// A `glCopyPixels` reads the target as drawn so far: the frame is drawn up to it, read back,
    /// and its points join the draws that follow (`render::pixel_copy`).
    pub fn render_window(
        &mut self,
        frame: &Frame,
        width: u32,
        height: u32,
        depth: bool,
    ) -> Result<WindowImage, RenderError> {
        let gl_backend = self.adapter.get_info().backend == wgpu::Backend::Gl;
        if super::fallback::needs_cpu(frame) || (gl_backend && super::fallback::reads_depth(frame, depth)) {
            return Ok(crate::render::soft::render_window(frame, width.max(1), height.max(1)));
        }
        let target = Target::new(&self.device, width.max(1), height.max(1), COLOR_FORMAT);
        let attachments = Attachments {
            color: &target.color_view,
            depth: &target.depth_view,
            size: (target.width, target.height),
            format: COLOR_FORMAT,
            flip: true,
        };
        let (list, prepared, mut encoder, start, keep) = self.draw_copies(frame, &target, &attachments)?;
        self.encode_list(&list, start..list.ops.len(), frame, prepared.as_ref(), &mut encoder, &attachments, keep);
        self.read_target(&target, encoder, depth)
    }

    /// Draws `frame` into the headless `target` up to its last `glCopyPixels`, each copy
    /// reading the target as drawn so far and becoming a batch of points: the assembled list
    /// with every copy so replaced, its prepared GPU meshes, the encoder for what follows, the
    /// index of the first op not drawn yet, and whether the target already holds a picture.
    #[allow(clippy::type_complexity)]
    fn draw_copies(
        &mut self,
        frame: &Frame,
        target: &Target,
        attachments: &Attachments<'_>,
    ) -> Result<(DrawList, Option<PreparedMeshes>, wgpu::CommandEncoder, usize, bool), RenderError> {
        let mut encoder = self.device.create_command_encoder(&Default::default());
        let (mut list, prepared) = self.prepare(frame, &mut encoder, attachments);
        let (mut start, mut keep) = (0, false);
        let is_copy = |op: &Op| matches!(op, Op::CopyPixels { .. });
        while let Some(at) = list.ops[start..].iter().position(is_copy).map(|k| start + k) {
            self.encode_list(&list, start..at, frame, prepared.as_ref(), &mut encoder, attachments, keep);
            let Op::CopyPixels { copy, batch } = list.ops[at] else { unreachable!("found above") };
            let depth = list.pixel_copies.get(copy).is_some_and(|c| c.buffer == GL_DEPTH);
            let window = self.read_target(target, encoder, depth)?;
            let points = list.pixel_copies.get(copy).map(|c| copy_vertices(c, &window)).unwrap_or_default();
            let first = list.vertices.len() as u32;
            list.vertices.extend(points);
            list.ops[at] = Op::Draw(copy_batch(&batch, &window, first, list.vertices.len() as u32 - first));
            encoder = self.device.create_command_encoder(&Default::default());
            (start, keep) = (at, true);
        }
        Ok((list, prepared, encoder, start, keep))
    }

    /// Submits `encoder` and reads `target` back (its depth too with `depth`).
    fn read_target(
        &self,
        target: &Target,
        encoder: wgpu::CommandEncoder,
        depth: bool,
    ) -> Result<WindowImage, RenderError> {
        let color = target.read(&self.device, &self.queue, encoder, true);
        // A validation error makes the submission fail; report the error itself.
        self.take_error()?;
        let color = color?;
        let depth = if depth {
            let encoder = self.device.create_command_encoder(&Default::default());
            target.read_depth(&self.device, &self.queue, encoder, true)?
        } else {
            Vec::new()
        };
        // No query slot: frames with occlusion queries are the CPU rasteriser's (fallback.rs).
        Ok(WindowImage { width: target.width, height: target.height, color, depth, samples: Vec::new() })
    }

    /// The first wgpu validation or device error since the last call, if any.
    pub fn take_error(&self) -> Result<(), RenderError> {
        self.errors.take()
    }

    /// Records a frame into `encoder`, rendering to `color` (of `format`) and `depth`: meshes
    /// left to the GPU tessellator are evaluated by one compute dispatch first, then everything
    /// is drawn in program order.
    pub fn encode(
        &mut self,
        frame: &Frame,
        encoder: &mut wgpu::CommandEncoder,
        color: &wgpu::TextureView,
        depth: &wgpu::TextureView,
        size: (u32, u32),
        format: wgpu::TextureFormat,
    ) {
        self.encode_onto(frame, encoder, &Attachments::window(color, depth, size, format), false);
    }

    /// [`Renderer::encode`] over what `target` already holds: no clear unless the frame asks
    /// for one (a GLUT menu drawn over the program's picture).
    pub(crate) fn encode_over(&mut self, frame: &Frame, encoder: &mut wgpu::CommandEncoder, target: &Attachments<'_>) {
        self.encode_onto(frame, encoder, target, true);
    }

    fn encode_onto(&mut self, frame: &Frame, encoder: &mut wgpu::CommandEncoder, target: &Attachments<'_>, keep: bool) {
        let (mut list, prepared) = self.prepare(frame, encoder, target);
        if !frame.pixel_copies.is_empty() {
            // A window's surface cannot be read back: the copies read a headless target of the
            // same size drawn the same way, and the window draws their points.
            let headless = Target::new(&self.device, target.size.0, target.size.1, COLOR_FORMAT);
            let attachments = Attachments {
                color: &headless.color_view,
                depth: &headless.depth_view,
                size: target.size,
                format: COLOR_FORMAT,
                flip: true,
            };
            match self.draw_copies(frame, &headless, &attachments) {
                Ok((resolved, ..)) => list = resolved,
                Err(e) => eprintln!("gleval: glCopyPixels in a window: {e}"),
            }
        }
        self.encode_list(&list, 0..list.ops.len(), frame, prepared.as_ref(), encoder, target, keep);
    }

    /// Assembles a frame, and records the evaluation of the meshes left to the GPU.
    fn prepare(
        &mut self,
        frame: &Frame,
        encoder: &mut wgpu::CommandEncoder,
        target: &Attachments<'_>,
    ) -> (DrawList, Option<PreparedMeshes>) {
        let size = target.size;
        let on_gpu = gpu_mesh_indices(&self.device, frame);
        let list = assemble_frame(frame, &on_gpu);
        let prepared = (!on_gpu.is_empty()).then(|| {
            let provoking_last = self.provoking_vertex_is_last();
            let texture_layout = self.frames.texture_layout();
            let meshes =
                self.meshes.get_or_insert_with(|| MeshRaster::new(&self.device, texture_layout, provoking_last));
            let prepared = meshes.prepare(&self.device, &self.queue, encoder, frame, &on_gpu, (size, target.flip));
            meshes.ensure_pipelines(&self.device, frame, &prepared, target.format);
            prepared
        });
        (list, prepared)
    }

    /// Records the ops in range `ops` of an assembled list (with its frame's GPU meshes already prepared).
    #[allow(clippy::too_many_arguments)]
    fn encode_list(
        &mut self,
        list: &DrawList,
        ops: std::ops::Range<usize>,
        frame: &Frame,
        prepared: Option<&PreparedMeshes>,
        encoder: &mut wgpu::CommandEncoder,
        target: &Attachments<'_>,
        keep: bool,
    ) {
        let list = super::clear_quads::clears_as_quads(list, target.size);
        let list = list.as_ref();
        let buffer = vertex_buffer(&self.device, list, target.size, target.flip);
        // A height of 0 tells the polygon stipple that rows are GL's (`fragment.wgsl`).
        let height = if target.flip { 0 } else { target.size.1 };
        let bind_groups = self.frames.texture_bind_groups(&self.device, &self.queue, list, height);
        let passes = split_passes(&list.ops[ops], keep);
        let batches = passes.iter().flat_map(|p| &p.draws).filter_map(|item| match item {
            PassItem::Batch(batch) => Some(pipeline_key(batch, target)),
            PassItem::Mesh { .. } => None,
        });
        self.frames.ensure_pipelines(&self.device, batches);
        for pass in passes {
            let clears = (pass.clear_depth, pass.clear_stencil);
            let mut rp = begin_pass(encoder, target.color, target.depth, pass.clear_color, clears);
            for item in &pass.draws {
                self.draw_item(&mut rp, item, (buffer.as_ref(), &bind_groups), frame, prepared, target);
            }
        }
    }

    /// Draws a batch of the assembled vertices, or a prepared mesh, scissored to its viewport.
    fn draw_item(
        &self,
        rp: &mut wgpu::RenderPass<'_>,
        item: &PassItem,
        (buffer, bind_groups): (Option<&wgpu::Buffer>, &[wgpu::BindGroup]),
        frame: &Frame,
        prepared: Option<&PreparedMeshes>,
        target: &Attachments<'_>,
    ) {
        match item {
            PassItem::Batch(batch) => {
                let Some(buffer) = buffer else { return };
                let Some(scissor) = draw_rect(batch.viewport, &batch.tests, target.size, target.flip) else { return };
                rp.set_scissor_rect(scissor[0], scissor[1], scissor[2], scissor[3]);
                rp.set_stencil_reference(stencil_reference(&batch.tests));
                rp.set_pipeline(self.frames.pipeline(pipeline_key(batch, target)));
                set_blend_constant(rp, batch.blend.as_ref());
                rp.set_bind_group(0, fragment_group(bind_groups, batch.fragment), &[]);
                rp.set_vertex_buffer(0, buffer.slice(..));
                rp.draw(batch.first..batch.first + batch.count, 0..1);
            }
            PassItem::Mesh { mesh, fragment } => {
                let (Some(prepared), Some(meshes)) = (prepared, &self.meshes) else { return };
                let Some(state) = prepared.state(frame, *mesh) else { return };
                let tests = &state.fragment_tests;
                let Some(scissor) = draw_rect(state.viewport, tests, target.size, target.flip) else { return };
                rp.set_scissor_rect(scissor[0], scissor[1], scissor[2], scissor[3]);
                rp.set_stencil_reference(stencil_reference(tests));
                set_blend_constant(rp, state.blend.as_ref());
                let fragment = fragment_group(bind_groups, *fragment);
                meshes.draw(rp, frame, prepared, (*mesh, fragment), target.format);
            }
        }
    }
}

/// The render pass's blend constant for `blend` (see `blend.rs`).
fn set_blend_constant(rp: &mut wgpu::RenderPass<'_>, blend: Option<&crate::gl::Blend>) {
    if let Some((_, constant)) = blend.and_then(super::blend::wgpu_blend) {
        rp.set_blend_constant(constant);
    }
}

/// The bind group of a fragment state; the last one is the one without fragment operations.
fn fragment_group(bind_groups: &[wgpu::BindGroup], fragment: Option<u32>) -> &wgpu::BindGroup {
    &bind_groups[fragment.map_or(bind_groups.len() - 1, |f| f as usize)]
}

/// The frame rasteriser's pipeline for a batch drawn into `target`.
fn pipeline_key(batch: &Batch, target: &Attachments<'_>) -> PipelineKey {
    let blend = batch.blend.as_ref().and_then(super::blend::wgpu_blend).map(|(state, _)| state);
    (batch.topology, batch.depth_test, target.format, blend, PipelineTests::of(&batch.tests))
}

/// The typed API on the GPU tessellator: each patch over a uniform `segments_u` × `segments_v`
/// grid of its unit domain, all patches in one dispatch, read back as one [`Mesh`] with the
/// layout of [`BezierPatch::tessellate`] (the CPU back end): positions divided by w, unit
/// normals (zero where degenerate), (u, v) texture coordinates, counter-clockwise triangles.
///
/// Errors: [`RenderError::Gpu`] for an empty grid (a segment count of 0), a patch of other
/// than 3 or 4 components, a batch beyond the device's storage-buffer limit, or a wgpu error.
pub fn tessellate_patches(
    renderer: &Renderer,
    patches: &[BezierPatch<f64>],
    segments_u: usize,
    segments_v: usize,
) -> Result<Mesh, RenderError> {
    evaluate::tessellate_patches(renderer.gpu(), patches, segments_u, segments_v)
}
