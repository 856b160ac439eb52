//! A loop the program drives itself (freeglut's `glutMainLoopEvent`), headless: each call is
//! one pass of GLUT's main loop on the virtual 60 Hz clock of `--frames`. The first call draws
//! every window's first frame; after `--frames N` calls (1 by default) the pictures are
//! written to the `--png` path as `glutMainLoop` writes them, and the loop is over.

use super::program::Program;
use super::{compose, App, Headless, Options};
use crate::render::RenderError;

/// The virtual refresh period of a pass.
const PASS_MS: f64 = 1000.0 / 60.0;

/// A program whose loop runs one pass at a time.
pub struct Running {
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
    /// The program's loop, to be run one pass at a time ([`Running::pass`]).
    pub fn start_passes(self, options: &Options) -> Result<Running, RenderError> {
        let renderer = Headless::new(if options.wgpu { crate::render::Rasterizer::Wgpu } else { self.rasterizer() })?;
        Ok(Running {
            program: Program::new(self),
            renderer,
            png: options.png.clone(),
            frames: options.frames.unwrap_or(1).max(1),
            passes: 0,
        })
    }
}

impl Running {
    /// One pass of the main loop: the first draws every window's first frame; later ones
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
                crate::render::write_png(&compose::png_path(path, *id, n == 0), image)?;
            }
        }
        Ok(Pass::Over { exit: self.program.finish() })
    }

    /// The loop was left (`glutLeaveMainLoop`, the last window closed).
    #[must_use]
    pub fn left(&self) -> bool {
        self.program.leave
    }
}
