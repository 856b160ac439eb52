//! A loop the program drives itself (freeglut's `glutMainLoopEvent`). In windows (feature
//! `window`, no `--png`), each call handles the events waiting and returns. Headless (`--png`),
//! each call is one pass of GLUT's main loop on the virtual 60 Hz clock of `--frames`: the
//! first draws every window's first frame; after `--frames N` calls (1 by default) the
//! pictures are written to the `--png` path as `glutMainLoop` writes them, and the loop is over.

use super::program::Program;
use super::{compose, App, Headless, Options};

/// The virtual refresh period of a pass.
const PASS_MS: f64 = 1000.0 / 60.0;

/// A program whose loop runs one pass at a time.
pub struct Running {
    inner: Inner,
}

enum Inner {
    /// The loop is over and what it held is gone.
    Closed,
    Headless(Box<Passes>),
    #[cfg(all(
        feature = "window",
        any(target_os = "linux", target_os = "windows", target_os = "macos", target_os = "freebsd")
    ))]
    Window(Box<crate::window::Pumped>),
}

/// The headless passes.
struct Passes {
    program: Program,
    renderer: Headless,
    png: Option<String>,
    frames: usize,
    passes: usize,
}

/// What a pass leaves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pass {
    /// The loop goes on.
    Running,
    /// The loop is over (the pictures written, the windows closed); `exit`: the program
    /// should exit now (`GLUT_ACTION_ON_WINDOW_CLOSE` is `GLUT_ACTION_EXIT`).
    Over {
        /// Exit rather than go on after the loop.
        exit: bool,
    },
}

impl App {
    /// The program's loop, to be run one pass at a time ([`Running::pass`]): in its windows,
    /// or headless with `--png`.
    pub fn start_passes(self, options: &Options) -> Result<Running, Box<dyn std::error::Error>> {
        #[cfg(all(
            feature = "window",
            any(target_os = "linux", target_os = "windows", target_os = "macos", target_os = "freebsd")
        ))]
        if options.png.is_none() {
            let pumped = crate::window::Pumped::new(self)?;
            return Ok(Running { inner: Inner::Window(Box::new(pumped)) });
        }
        let renderer = Headless::new(if options.wgpu { crate::render::Rasterizer::Wgpu } else { self.rasterizer() })?;
        let passes = Passes {
            program: Program::new(self),
            renderer,
            png: options.png.clone(),
            frames: options.frames.unwrap_or(1).max(1),
            passes: 0,
        };
        Ok(Running { inner: Inner::Headless(Box::new(passes)) })
    }
}

impl Running {
    /// One pass of the main loop (headless: as the module documentation says); in windows, the
    /// events waiting and what they call for. `Pass::Over` once the loop has ended (the last
    /// window closed, `glutLeaveMainLoop`), its windows closed.
    pub fn pass(&mut self) -> Result<Pass, Box<dyn std::error::Error>> {
        match &mut self.inner {
            Inner::Closed => Ok(Pass::Over { exit: false }),
            Inner::Headless(passes) => passes.pass(),
            #[cfg(all(
                feature = "window",
                any(target_os = "linux", target_os = "windows", target_os = "macos", target_os = "freebsd")
            ))]
            Inner::Window(pumped) => Ok(match pumped.pass()? {
                None => Pass::Running,
                Some(exit) => Pass::Over { exit },
            }),
        }
    }

    /// Drops what the loop held (windows, GPU devices) now, rather than whenever the `Running`
    /// is dropped: a `Running` kept in a thread-local would otherwise be dropped while the
    /// thread exits, when the GPU library's own thread-locals are already gone.
    pub fn close(&mut self) {
        self.inner = Inner::Closed;
    }

    /// Whether the passes are headless (the pictures are written when the loop is over).
    #[must_use]
    pub fn headless(&self) -> bool {
        matches!(self.inner, Inner::Headless(_))
    }
}

impl Passes {
    /// One headless pass of the main loop: the first draws every window's first frame; later ones
    /// advance the clock a refresh (due timers, the idle callback) and redraw the windows that
    /// asked. After the last of `--frames` (or when the program left the loop) the pictures are
    /// written and the loop ends.
    pub fn pass(&mut self) -> Result<Pass, Box<dyn std::error::Error>> {
        if self.passes == 0 {
            self.program.start();
        } else {
            self.program.step(PASS_MS);
            self.program.display_pending();
        }
        self.passes += 1;
        if self.passes < self.frames && !self.program.leave {
            return Ok(Pass::Running);
        }
        if let Some(path) = &self.png {
            let pictures = self.program.render_windows(&mut self.renderer)?;
            for (n, (id, image)) in pictures.iter().enumerate() {
                crate::render::write_png(compose::png_path(path, *id, n == 0), image)?;
            }
        }
        Ok(Pass::Over { exit: self.program.finish() })
    }
}
