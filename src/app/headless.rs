//! Running a program without a window: its pictures as PNG (every top-level window, its
//! subwindows composed in place), timed frames (`--time N`), the `--profile` breakdown, and
//! what a context reads the window with mid-frame.

use super::program::Program;
use super::{compose, App};
use crate::gl::Frame;
use crate::render::{soft, Image, Rasterizer, RenderError, Renderer};

impl App {
    /// Renders the first window headless (the last frame of `--frames N`) with
    /// [`App::rasterizer`], its subwindows composed in place.
    pub fn render_image(&mut self) -> Result<Image, RenderError> {
        let mut renderer = Headless::new(self.rasterizer())?;
        let frames = self.frames.unwrap_or(1);
        let mut program = Program::new(std::mem::replace(self, App::new("", 1, 1)));
        program.run_headless(frames);
        let image = match program.index(1) {
            Some(k) => program.render_tree(k, &mut renderer),
            None => Err(RenderError::Gpu("the program destroyed its first window".into())),
        };
        if let Some(k) = program.index(1) {
            *self = program.slots.swap_remove(k).app;
        }
        image
    }

    /// Runs the program headless and writes each shown top-level window's picture (its
    /// subwindows composed in place): the first to `path`, window N to `path` with `-N` before
    /// the extension. Then the loop ends as freeglut's does (every window's close callback);
    /// true if the program should exit (`GLUT_ACTION_ON_WINDOW_CLOSE` is `GLUT_ACTION_EXIT`).
    pub(super) fn write_pngs(self, path: &str) -> Result<bool, Box<dyn std::error::Error>> {
        let mut renderer = Headless::new(self.rasterizer())?;
        let frames = self.frames.unwrap_or(1);
        let mut program = Program::new(self);
        program.run_headless(frames);
        let pictures = program.render_windows(&mut renderer)?;
        for (n, (id, image)) in pictures.iter().enumerate() {
            crate::render::write_png(compose::png_path(path, *id, n == 0), image)?;
        }
        Ok(program.finish())
    }

    /// Renders `frames` headless frames with one renderer (display callback, assembly,
    /// rasterisation and read-back each time), after one untimed frame (which compiles wgpu's
    /// pipelines), and returns the median frame time.
    pub fn median_frame_time(&mut self, frames: usize) -> Result<std::time::Duration, RenderError> {
        let mut renderer = Headless::new(self.rasterizer())?;
        let mut gl = self.context.take().map_or_else(|| self.new_gl(), |made| *made);
        gl.set_tessellator(self.tessellator);
        self.run_init(&mut gl);
        let mut times = Vec::with_capacity(frames.max(1));
        self.draw_into(&mut gl, self.width, self.height);
        renderer.render_frame(&gl.take_frame(), self.width as u32, self.height as u32)?;
        for _ in 0..frames.max(1) {
            let start = std::time::Instant::now();
            self.draw_into(&mut gl, self.width, self.height);
            let frame = gl.take_frame();
            renderer.render_frame(&frame, self.width as u32, self.height as u32)?;
            gl.recycle_frame(frame);
            times.push(start.elapsed());
        }
        times.sort();
        Ok(times[times.len() / 2])
    }

    pub(super) fn print_frame_time(mut self, frames: usize) -> Result<(), Box<dyn std::error::Error>> {
        let median = self.median_frame_time(frames)?;
        println!("{}: median frame {:.3} ms over {frames} frames", self.title, median.as_secs_f64() * 1e3);
        Ok(())
    }

    /// Renders the program headless and writes it as PNG: the first window to `path`, each
    /// further top-level window to `path` with `-N` (its number) before the extension.
    pub fn write_png(self, path: &str) -> Result<(), Box<dyn std::error::Error>> {
        self.write_pngs(path).map(|_| ())
    }

    /// [`App::write_png`] timing each phase of the run, printed to stderr (`--profile`): the
    /// program's callbacks, the wgpu instance and adapter, the device with the frame
    /// rasteriser's shader, the first frame (assembly, pipelines, rasterisation, read-back), a
    /// second frame of the same picture (what the first cost beyond steady state is pipeline
    /// creation), and the PNG encoding.
    pub(super) fn write_png_profiled(mut self, path: &str) -> Result<(), Box<dyn std::error::Error>> {
        let start = std::time::Instant::now();
        let mut lap = start;
        let mut phase = |name: &str| {
            let now = std::time::Instant::now();
            eprintln!("profile: {name:<34} {:8.2} ms", (now - lap).as_secs_f64() * 1e3);
            lap = now;
        };
        let mut gl = self.record_frames(self.frames.unwrap_or(1));
        phase("program (init, reshape, display)");
        let (w, h) = (self.width as u32, self.height as u32);
        if self.rasterizer() == Rasterizer::Cpu {
            let frame = gl.take_frame();
            let image = soft::render_frame(&frame, w, h);
            phase("CPU rasteriser (assembly, drawing)");
            crate::render::write_png(path, &image)?;
            phase("PNG encoding and write");
            eprintln!("profile: {:<34} {:8.2} ms", "total", start.elapsed().as_secs_f64() * 1e3);
            return Ok(());
        }
        let (instance, adapter) = crate::gpu::first_adapter()?;
        phase("wgpu instance and adapter");
        let mut renderer = Renderer::with_adapter(instance, adapter)?;
        phase("device and shader");
        let frame = gl.take_frame();
        let image = renderer.render_frame(&frame, w, h)?;
        phase("first frame (with pipelines)");
        renderer.render_frame(&frame, w, h)?;
        phase("same frame again (steady state)");
        crate::render::write_png(path, &image)?;
        phase("PNG encoding and write");
        eprintln!(
            "profile: {:<34} {:8.2} ms (the repeated frame included)",
            "total",
            start.elapsed().as_secs_f64() * 1e3
        );
        Ok(())
    }
}

/// A headless frame's rasteriser.
pub(crate) enum Headless {
    Cpu,
    Wgpu(Box<Renderer>),
}

impl Headless {
    pub(super) fn new(rasterizer: Rasterizer) -> Result<Self, RenderError> {
        Ok(match rasterizer {
            Rasterizer::Cpu => Self::Cpu,
            Rasterizer::Wgpu => Self::Wgpu(Box::new(Renderer::new()?)),
        })
    }

    pub(super) fn render_frame(&mut self, frame: &Frame, width: u32, height: u32) -> Result<Image, RenderError> {
        match self {
            Self::Cpu => Ok(soft::render_frame(frame, width, height)),
            Self::Wgpu(renderer) => renderer.render_frame(frame, width, height),
        }
    }
}

/// What a context of this program reads the window with mid-frame (`glCopyTexImage`): its
/// frame so far drawn by the program's headless rasteriser (a wgpu renderer made at the first
/// read and kept).
pub(super) fn window_reader(rasterizer: Rasterizer) -> impl FnMut(&Frame, u32, u32) -> Option<crate::gl::WindowImage> {
    let mut renderer: Option<Renderer> = None;
    move |frame, width, height| match rasterizer {
        Rasterizer::Cpu => Some(soft::render_window(frame, width, height)),
        Rasterizer::Wgpu => {
            if renderer.is_none() {
                renderer = Renderer::new().map_err(|e| eprintln!("gleval: reading the window: {e}")).ok();
            }
            renderer.as_mut()?.render_window(frame, width, height, true).ok()
        }
    }
}
