//! What the command line asks of a program: gleval's options and GLUT's X options, parsed
//! once (`Options::from_args`) and applied when the program runs.

use super::App;

/// What the command line asked for.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Options {
    /// `--png PATH`: render one frame to this file and exit.
    pub png: Option<String>,
    /// `--time N`: render N headless frames and print the median frame time.
    pub time: Option<usize>,
    /// `--gpu`: evaluate `glEvalMesh` grids in the GPU tessellator's compute shader.
    pub gpu: bool,
    /// `--frames N`: headless, run the program for N frames (idle and timer callbacks on a
    /// virtual 60 Hz clock) and render the last.
    pub frames: Option<usize>,
    /// `--profile`: with `--png`, print to stderr where the run's time went.
    pub profile: bool,
    /// `--wgpu`: draw headless frames through wgpu rather than the CPU rasteriser.
    pub wgpu: bool,
    /// GLUT's X options (`-geometry`, `-display`, `-iconic`, `-direct`, `-indirect`, `-sync`,
    /// `-gldebug`), as `glutInit` takes them.
    pub glut: crate::glut::XOptions,
}

impl Options {
    /// Parses the options [`App::run`] takes out of the program's arguments (its name not
    /// among them): `--png PATH` (or `--png=PATH`), `--time N`, `--frames N`, `--gpu`, `--wgpu`
    /// and `--profile`, and GLUT's X options ([`crate::glut::split_init_args`]); anything else
    /// is left for the program.
    #[must_use]
    pub fn from_args(args: impl IntoIterator<Item = String>) -> Self {
        let all: Vec<String> = std::iter::once(String::new()).chain(args).collect();
        let split = crate::glut::split_init_args(&all);
        let mut out = Self { glut: split.x, ..Self::default() };
        let mut args = split.gleval.into_iter();
        while let Some(a) = args.next() {
            if a == "--png" {
                out.png = args.next();
            } else if let Some(path) = a.strip_prefix("--png=") {
                out.png = Some(path.to_owned());
            } else if a == "--time" {
                out.time = args.next().and_then(|n| n.parse().ok());
            } else if a == "--gpu" {
                out.gpu = true;
            } else if a == "--frames" {
                out.frames = args.next().and_then(|n| n.parse().ok());
            } else if a == "--profile" {
                out.profile = true;
            } else if a == "--wgpu" {
                out.wgpu = true;
            }
        }
        out
    }
}

impl App {
    /// GLUT's X options, as freeglut's `glutInit` applies them: `-display` picks the X server
    /// the window opens on, `-geometry`'s place is where it opens unless the program placed it
    /// (its size is the program's: `App::new` is `glutInitWindowSize` after `glutInit`, which
    /// overrides it in freeglut too), `-iconic` and `-direct`/`-indirect` are settings
    /// `glutGet` reads back, and `-gldebug` reports GL errors after each display callback.
    pub(super) fn take_x_options(&mut self, x: &crate::glut::XOptions) {
        if let Some(display) = &x.display {
            std::env::set_var("DISPLAY", display);
        }
        if self.position.is_none() {
            self.position = x.position;
        }
        if x.sets_settings() {
            self.context_mut().glut_take_x_settings(x);
        }
        if x.gl_debug {
            self.gl_debug = true;
        }
    }
}
