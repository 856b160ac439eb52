//! The CPU rasteriser: draws an assembled [`DrawList`] into an [`Image`] with GL's rules
//! (triangles by their edge functions at pixel centres with the top-left rule, one-pixel lines
//! by GL's diamond-exit rule, points as their pixel; §3.3–3.5 of the GL 1.1 spec), GL's
//! per-fragment operations (`fragment.rs`, the same as `shaders/fragment.wgsl`), the depth test
//! and blending (`framebuffer.rs`). It needs no device and no driver: a headless picture costs
//! its drawing only, where a first wgpu render on a software Vulkan driver pays about 45 ms of
//! instance, adapter and pipeline compilation before drawing anything (docs/benchmarks.md).
//!
//! | file | what |
//! |---|---|
//! | `clip.rs` | the view volume: triangles to polygons, lines to segments |
//! | `primitives.rs` | triangles, lines and points to fragments, attributes interpolated perspective-correctly |
//! | `fragment.rs` | texture environment, fog, stipple, smooth coverage, alpha test |
//! | `sampler.rs` | texture filters, wrap modes, mipmap levels |
//! | `framebuffer.rs` | front, back, depth and stencil buffers; stencil and depth tests, blending, logic op, masks |
//! | `accum.rs` | the accumulation buffer, with Mesa's arithmetic |
//! | `ops.rs` | stencil operations, logic ops |

mod accum;
mod clip;
mod fragment;
mod framebuffer;
mod ops;
mod primitives;
mod sampler;
#[cfg(test)]
mod tests;
mod units;

use super::assemble::{assemble, viewport_in_target, Batch, DrawList, Op, Topology};
use super::Image;
use crate::gl::consts::GL_STENCIL;
use crate::gl::{Accumulation, FragmentTests, Frame, WindowImage};
use fragment::{Fragment, Program, TexSlope};
use framebuffer::{ColorWrite, Framebuffer};
use units::{MultiVertex, SoftVertex, UnitCoords};

/// Renders a recorded frame on the CPU: every mesh evaluated by the CPU tessellator, the
/// frame assembled ([`assemble`]) and rasterised ([`rasterize`]).
#[must_use]
pub fn render_frame(frame: &Frame, width: u32, height: u32) -> Image {
    rasterize(&assemble(frame), width, height)
}

/// [`render_frame`], keeping the depth buffer too: what `glReadPixels` and the copies read.
#[must_use]
pub fn render_window(frame: &Frame, width: u32, height: u32) -> WindowImage {
    let mut canvas = Canvas::new(width, height);
    canvas.draw_frame(frame);
    canvas.fb.window_image()
}

/// Rasterises an assembled list into a `width` × `height` picture that starts as a new
/// OSMesa buffer does (transparent black, depth 1). Ops the CPU cannot draw
/// ([`Op::GpuMesh`], the GPU tessellator's) are skipped: assemble with [`assemble`].
#[must_use]
pub fn rasterize(list: &DrawList, width: u32, height: u32) -> Image {
    let mut canvas = Canvas::new(width, height);
    canvas.draw(list);
    canvas.fb.into_image()
}

/// A colour and depth buffer that keeps what was drawn: frames drawn one after another land on
/// top of each other, as they do in a GL context's framebuffer (an OSMesa buffer, say).
#[derive(Clone)]
pub struct Canvas {
    fb: Framebuffer,
}

impl Canvas {
    /// A `width` × `height` canvas (at least 1 × 1), transparent black, depth 1.
    #[must_use]
    pub fn new(width: u32, height: u32) -> Self {
        Self { fb: Framebuffer::new(width.max(1), height.max(1)) }
    }

    /// Draws an assembled list over what the canvas holds (see [`rasterize`]).
    pub fn draw(&mut self, list: &DrawList) {
        // The query slots are the list's: counted afresh (GL 1.5 §4.1.6).
        (self.fb.samples, self.fb.counting) = (Vec::new(), None);
        for op in &list.ops {
            match op {
                Op::Query { slot, begin } => {
                    self.fb.counting = begin.then_some(*slot);
                    if self.fb.samples.len() <= *slot {
                        self.fb.samples.resize(slot + 1, 0);
                    }
                }
                Op::Clear { color, depth, stencil, accum, tests } => {
                    let Some(rect) = self.scissor_rect(tests) else { continue };
                    self.fb.clear(rect, (*color, *depth, *stencil), tests);
                    if let Some(value) = accum {
                        self.fb.clear_accum(rect, *value);
                    }
                }
                Op::Accum(Accumulation { op, value, tests, read }) => {
                    if let Some(rect) = self.scissor_rect(tests) {
                        self.fb.accumulate(rect, (*op, *value), *read, tests);
                    }
                }
                Op::SwapBuffers => self.fb.swap(),
                Op::Draw(batch) => draw_batch(&mut self.fb, list, batch),
                Op::GpuMesh { .. } => {}
                Op::CopyPixels { copy, batch } => {
                    let Some(copy) = list.pixel_copies.get(*copy) else { continue };
                    if copy.buffer == GL_STENCIL {
                        if let Some(rect) = self.scissor_rect(&batch.tests) {
                            self.fb.copy_stencil(copy, rect, batch.tests.stencil_write_mask);
                        }
                        continue;
                    }
                    let window = self.fb.window_image();
                    let points = super::pixel_copy::copy_vertices(copy, &window);
                    let batch = super::pixel_copy::copy_batch(batch, &window, 0, points.len() as u32);
                    draw_vertices(&mut self.fb, list, (&batch, usize::MAX), &points);
                }
            }
        }
    }

    /// What the canvas holds, colour and depth.
    #[must_use]
    pub fn window_image(&self) -> WindowImage {
        self.fb.window_image()
    }

    /// One colour buffer (the back one for `back`, where there is one) with the depth buffer:
    /// what a read of that buffer sees (`glReadBuffer`).
    #[must_use]
    pub fn buffer_image(&self, back: bool) -> WindowImage {
        self.fb.buffer_image(if back { crate::gl::fragments::BACK_BUFFER } else { crate::gl::fragments::FRONT_BUFFER })
    }

    /// Draws a recorded frame over what the canvas holds, its meshes evaluated on the CPU.
    pub fn draw_frame(&mut self, frame: &Frame) {
        self.draw(&assemble(frame));
    }

    /// What the canvas holds.
    #[must_use]
    pub fn image(&self) -> Image {
        self.fb.image()
    }

    /// The stencil buffer, one byte a pixel, rows top to bottom.
    #[must_use]
    pub fn stencil(&self) -> &[u8] {
        self.fb.stencil()
    }

    /// The whole canvas, or the scissor box of `tests` within it (`None` if empty).
    fn scissor_rect(&self, tests: &FragmentTests) -> Option<[u32; 4]> {
        let size = (self.fb.width, self.fb.height);
        let whole = [0, 0, size.0 as i32, size.1 as i32];
        viewport_in_target(tests.scissor.unwrap_or(whole), size)
    }
}

/// The intersection of two rectangles `[x0, top, x1, bottom]`, `None` if empty.
fn intersect(a: [u32; 4], b: [u32; 4]) -> Option<[u32; 4]> {
    let r = [a[0].max(b[0]), a[1].max(b[1]), a[2].min(b[2]), a[3].min(b[3])];
    (r[0] < r[2] && r[1] < r[3]).then_some(r)
}

fn draw_batch(fb: &mut Framebuffer, list: &DrawList, batch: &Batch) {
    let first = batch.first as usize;
    let Some(vertices) = list.vertices.get(first..first + batch.count as usize) else { return };
    draw_vertices(fb, list, (batch, first), vertices);
}

/// Draws `vertices`, which start at `first` in the list (`usize::MAX`: none of the list's),
/// with `batch`'s topology and state (its own range ignored).
fn draw_vertices(
    fb: &mut Framebuffer,
    list: &DrawList,
    (batch, first): (&Batch, usize),
    vertices: &[super::RasterVertex],
) {
    let size = (fb.width, fb.height);
    let Some(mut scissor) = viewport_in_target(batch.viewport, size) else { return };
    if let Some(b) = batch.tests.scissor {
        let Some(r) = viewport_in_target(b, size).and_then(|b| intersect(scissor, b)) else { return };
        scissor = r;
    }
    if batch.tests.draw_buffers == 0 {
        return;
    }
    let program = batch.fragment.and_then(|f| list.fragments.get(f as usize)).map(Program::new);
    let mut target = Target {
        map: WindowMap::new(batch.viewport, fb.height),
        fb,
        scissor,
        depth_test: batch.depth_test,
        blend: batch.blend,
        tests: batch.tests,
        program,
    };
    if target.program.as_ref().is_some_and(Program::multi_unit) {
        // The units' coordinates beside each vertex (zero where the list has none).
        let units = |k: usize| first.checked_add(k).and_then(|i| list.unit_tex.get(i)).copied().unwrap_or_default();
        let multi: Vec<MultiVertex> =
            vertices.iter().enumerate().map(|(k, &vertex)| MultiVertex { vertex, units: units(k) }).collect();
        return draw_topology(&mut target, batch.topology, &multi);
    }
    draw_topology(&mut target, batch.topology, vertices);
}

/// Draws `vertices` as triangles, lines or points.
fn draw_topology<V: SoftVertex>(target: &mut Target<'_>, topology: Topology, vertices: &[V]) {
    match topology {
        Topology::Triangles => vertices.chunks_exact(3).for_each(|t| primitives::triangle(target, [t[0], t[1], t[2]])),
        Topology::Lines => vertices.chunks_exact(2).for_each(|l| primitives::line(target, &l[0], &l[1])),
        Topology::Points => vertices.iter().for_each(|p| primitives::point(target, p)),
    }
}

/// GL's viewport transform (§2.10.1) into framebuffer coordinates, y down.
#[derive(Clone, Copy, Debug)]
struct WindowMap {
    centre: [f32; 2],
    half: [f32; 2],
}

impl WindowMap {
    fn new([x, y, w, h]: [i32; 4], height: u32) -> Self {
        let (x, y, w, h) = (x as f32, y as f32, w as f32, h as f32);
        Self { centre: [x + w / 2.0, height as f32 - (y + h / 2.0)], half: [w / 2.0, h / 2.0] }
    }

    /// Framebuffer x and y, the depth z/w, and 1/w.
    fn project(&self, clip: [f32; 4]) -> [f32; 4] {
        let inv_w = 1.0 / clip[3];
        [
            self.centre[0] + clip[0] * inv_w * self.half[0],
            self.centre[1] - clip[1] * inv_w * self.half[1],
            clip[2] * inv_w,
            inv_w,
        ]
    }
}

/// Where a batch's fragments go: the buffers, the batch's viewport and scissor, its depth test,
/// blending and fragment operations.
struct Target<'a> {
    fb: &'a mut Framebuffer,
    map: WindowMap,
    scissor: [u32; 4],
    depth_test: Option<crate::gl::types::GLenum>,
    blend: Option<crate::gl::Blend>,
    tests: FragmentTests,
    program: Option<Program<'a>>,
}

impl Target<'_> {
    /// Whether fragments need their texture coordinates' change per pixel.
    fn textured(&self) -> bool {
        self.program.as_ref().is_some_and(Program::textured)
    }

    /// One fragment at framebuffer column `x`, row `y` (inside the scissor), depth `z`.
    /// GL's order: the fragment's colour and the alpha test, the stencil test, the depth test
    /// (stencil operations on each outcome), then the write. Without a stencil test a fragment
    /// failing the depth test is dropped before it is shaded (nothing observable differs).
    fn fragment<U: UnitCoords>(&mut self, (x, y): (u32, u32), z: f32, f: &Fragment<U>, slope: &TexSlope<U>) {
        let index = y as usize * self.fb.width as usize + x as usize;
        let stencil = self.tests.stencil;
        if stencil.is_none() && !self.fb.depth_passes(index, z, self.depth_test) {
            return;
        }
        let row = self.fb.height - 1 - y;
        let color = match &self.program {
            Some(program) => match program.shade(f, slope, (x, row)) {
                Some(c) => c,
                None => return,
            },
            None => fragment::color_sum(f.color, f.secondary),
        };
        if let Some(s) = &stencil {
            if !self.fb.stencil_passes(index, s) {
                return self.fb.stencil_update(index, s, s.ops[0]);
            }
            let depth_passes = self.fb.depth_passes(index, z, self.depth_test);
            self.fb.stencil_update(index, s, s.ops[if depth_passes { 2 } else { 1 }]);
            if !depth_passes {
                return;
            }
        }
        self.fb.count_sample();
        let write_depth = self.depth_test.is_some() && self.tests.depth_write;
        let write = ColorWrite { color, blend: self.blend, tests: self.tests };
        self.fb.write(index, z, write_depth, &write);
    }
}
