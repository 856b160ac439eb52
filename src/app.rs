//! A GLUT-like runner: `App::new(title, w, h).reshape(..).display(..).run()`.
//!
//! `run()` renders one frame headless to a PNG when the program was started with
//! `--png PATH`, and otherwise opens a window (feature `window`) that redraws on resize.
//! Callbacks take the [`Gl`] context, which keeps its state from frame to frame as a GL
//! context does; `gl.glut_get(GLUT_WINDOW_WIDTH)` answers inside them.

use crate::gl::{Gl, Tessellator};
use crate::render::{Image, RenderError, Renderer};

type DisplayFn = Box<dyn FnMut(&mut Gl)>;
type ReshapeFn = Box<dyn FnMut(&mut Gl, i32, i32)>;
type KeyboardFn = Box<dyn FnMut(&mut Gl, char, i32, i32)>;
type MouseFn = Box<dyn FnMut(&mut Gl, i32, i32, i32, i32)>;
type MotionFn = Box<dyn FnMut(&mut Gl, i32, i32)>;

/// What the command line asked for.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Options {
    /// `--png PATH`: render one frame to this file and exit.
    pub png: Option<String>,
    /// `--time N`: render N headless frames and print the median frame time.
    pub time: Option<usize>,
    /// `--gpu`: evaluate `glEvalMesh` grids in the GPU tessellator's compute shader.
    pub gpu: bool,
}

impl Options {
    /// Parses the options [`App::run`] takes out of the program's arguments: `--png PATH` (or
    /// `--png=PATH`), `--time N` and `--gpu`; anything else is left for the program.
    #[must_use]
    pub fn from_args(args: impl IntoIterator<Item = String>) -> Self {
        let mut out = Self::default();
        let mut args = args.into_iter();
        while let Some(a) = args.next() {
            if a == "--png" {
                out.png = args.next();
            } else if let Some(path) = a.strip_prefix("--png=") {
                out.png = Some(path.to_owned());
            } else if a == "--time" {
                out.time = args.next().and_then(|n| n.parse().ok());
            } else if a == "--gpu" {
                out.gpu = true;
            }
        }
        out
    }
}

/// A GLUT-style program: window size, title and callbacks.
pub struct App {
    title: String,
    width: i32,
    height: i32,
    init: Option<DisplayFn>,
    reshape: Option<ReshapeFn>,
    display: Option<DisplayFn>,
    keyboard: Option<KeyboardFn>,
    mouse: Option<MouseFn>,
    motion: Option<MotionFn>,
    tessellator: Tessellator,
}

impl App {
    /// `glutInitWindowSize(width, height)` + `glutCreateWindow(title)`.
    #[must_use]
    pub fn new(title: &str, width: i32, height: i32) -> Self {
        Self {
            title: title.to_owned(),
            width: width.max(1),
            height: height.max(1),
            init: None,
            reshape: None,
            display: None,
            keyboard: None,
            mouse: None,
            motion: None,
            tessellator: Tessellator::from_env(),
        }
    }

    /// Code the C program runs once after `glutCreateWindow` (the textbook's `Hint()`).
    #[must_use]
    pub fn init(mut self, f: impl FnMut(&mut Gl) + 'static) -> Self {
        self.init = Some(Box::new(f));
        self
    }

    /// `glutReshapeFunc`. Without one, GLUT's default sets `glViewport(0, 0, w, h)`.
    #[must_use]
    pub fn reshape(mut self, f: impl FnMut(&mut Gl, i32, i32) + 'static) -> Self {
        self.reshape = Some(Box::new(f));
        self
    }

    /// `glutDisplayFunc`.
    #[must_use]
    pub fn display(mut self, f: impl FnMut(&mut Gl) + 'static) -> Self {
        self.display = Some(Box::new(f));
        self
    }

    /// `glutKeyboardFunc`: called with the character typed and the mouse position in window
    /// pixels (origin top left) when a key is pressed in the window; the window then redraws.
    /// Escape closes the window, as the textbook programs do.
    #[must_use]
    pub fn keyboard(mut self, f: impl FnMut(&mut Gl, char, i32, i32) + 'static) -> Self {
        self.keyboard = Some(Box::new(f));
        self
    }

    /// `glutMouseFunc`: called with the button (`GLUT_LEFT_BUTTON`, `_MIDDLE_`, `_RIGHT_`), the
    /// state (`GLUT_DOWN`, `GLUT_UP`) and the mouse position in window pixels (origin top
    /// left) when a button is pressed or released; the window then redraws.
    #[must_use]
    pub fn mouse(mut self, f: impl FnMut(&mut Gl, i32, i32, i32, i32) + 'static) -> Self {
        self.mouse = Some(Box::new(f));
        self
    }

    /// `glutMotionFunc`: called with the mouse position while a button is held and the mouse
    /// moves; the window then redraws.
    #[must_use]
    pub fn motion(mut self, f: impl FnMut(&mut Gl, i32, i32) + 'static) -> Self {
        self.motion = Some(Box::new(f));
        self
    }

    /// What the window does on a mouse button: the mouse callback; false if there is none.
    pub fn run_mouse(&mut self, gl: &mut Gl, button: i32, state: i32, x: i32, y: i32) -> bool {
        self.mouse.as_mut().map(|mouse| mouse(gl, button, state, x, y)).is_some()
    }

    /// What the window does when the mouse moves with a button held: the motion callback;
    /// false if there is none.
    pub fn run_motion(&mut self, gl: &mut Gl, x: i32, y: i32) -> bool {
        self.motion.as_mut().map(|motion| motion(gl, x, y)).is_some()
    }

    /// The window size asked for.
    #[must_use]
    pub fn size(&self) -> (i32, i32) {
        (self.width, self.height)
    }

    pub(crate) fn run_init(&mut self, gl: &mut Gl) {
        if let Some(init) = &mut self.init {
            init(gl);
        }
    }

    /// What the window does on a key press: the keyboard callback (also for tests and other
    /// event loops).
    pub fn run_keyboard(&mut self, gl: &mut Gl, key: char, x: i32, y: i32) {
        if let Some(keyboard) = &mut self.keyboard {
            keyboard(gl, key, x, y);
        }
    }

    /// The window title.
    #[must_use]
    pub fn title(&self) -> &str {
        &self.title
    }

    /// Where the program's contexts evaluate `glEvalMesh` grids. Initially from the environment
    /// (`GLEVAL_TESSELLATOR`, see [`Tessellator::from_env`]: `App` is where a program meets its
    /// environment, [`Gl::new`] never reads it); `--gpu` on the command line picks the GPU.
    #[must_use]
    pub fn with_tessellator(mut self, tessellator: Tessellator) -> Self {
        self.tessellator = tessellator;
        self
    }

    /// The tessellator this program's contexts use.
    #[must_use]
    pub fn tessellator(&self) -> Tessellator {
        self.tessellator
    }

    /// A fresh context of the window's size on this program's tessellator.
    pub(crate) fn new_gl(&self) -> Gl {
        let mut gl = Gl::new(self.width, self.height);
        gl.set_tessellator(self.tessellator);
        gl
    }

    /// `glutMainLoop`: `--png PATH` renders one frame to PNG and returns; otherwise a window.
    /// `--gpu` selects the GPU tessellator. Errors are printed and the process exits with
    /// status 1, as a C program would fail.
    pub fn run(mut self) {
        let options = Options::from_args(std::env::args().skip(1));
        if options.gpu {
            self.tessellator = Tessellator::Gpu;
        }
        let result = match (options.time, options.png) {
            (Some(frames), _) => self.print_frame_time(frames),
            (None, Some(path)) => self.write_png(&path),
            (None, None) => self.run_window(),
        };
        if let Err(e) = result {
            eprintln!("{e}");
            std::process::exit(1);
        }
    }

    /// Runs init, reshape and display once on a fresh context and returns what was drawn.
    pub fn record_frame(&mut self) -> Gl {
        let mut gl = self.new_gl();
        self.run_init(&mut gl);
        self.draw_into(&mut gl, self.width, self.height);
        gl
    }

    pub(crate) fn draw_into(&mut self, gl: &mut Gl, width: i32, height: i32) {
        self.run_reshape(gl, width, height);
        self.run_display(gl);
    }

    /// The window now has this size: the reshape callback, or GLUT's default viewport.
    pub(crate) fn run_reshape(&mut self, gl: &mut Gl, width: i32, height: i32) {
        gl.set_window_size(width, height);
        match &mut self.reshape {
            Some(reshape) => reshape(gl, width, height),
            None => gl.viewport(0, 0, width, height),
        }
    }

    /// What the window does to redraw: the display callback into `gl`.
    pub fn run_display(&mut self, gl: &mut Gl) {
        if let Some(display) = &mut self.display {
            display(gl);
        }
    }

    /// Renders one frame headless.
    pub fn render_image(&mut self) -> Result<Image, RenderError> {
        let mut gl = self.record_frame();
        let mut renderer = Renderer::new()?;
        renderer.render_frame(&gl.take_frame(), self.width as u32, self.height as u32)
    }

    /// Renders `frames` headless frames with one renderer (display callback, assembly,
    /// rasterisation and read-back each time), after one untimed frame that compiles the
    /// pipelines, and returns the median frame time.
    pub fn median_frame_time(&mut self, frames: usize) -> Result<std::time::Duration, RenderError> {
        let mut renderer = Renderer::new()?;
        let mut gl = self.new_gl();
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

    fn print_frame_time(mut self, frames: usize) -> Result<(), Box<dyn std::error::Error>> {
        let median = self.median_frame_time(frames)?;
        println!("{}: median frame {:.3} ms over {frames} frames", self.title, median.as_secs_f64() * 1e3);
        Ok(())
    }

    /// Renders one frame headless and writes it as PNG.
    pub fn write_png(mut self, path: &str) -> Result<(), Box<dyn std::error::Error>> {
        let image = self.render_image()?;
        crate::render::write_png(path, &image)?;
        Ok(())
    }

    #[cfg(feature = "window")]
    fn run_window(self) -> Result<(), Box<dyn std::error::Error>> {
        crate::window::run(self)
    }

    #[cfg(not(feature = "window"))]
    fn run_window(self) -> Result<(), Box<dyn std::error::Error>> {
        Err("this build has no window support (feature `window`); run with --png PATH".into())
    }
}
