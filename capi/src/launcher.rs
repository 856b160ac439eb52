//! gleval's options given to `capi/gleval-run` before the program (`gleval-run --png out.png
//! PROGRAM ARGS`): the launcher hands them over in `GLEVAL_OPTIONS`, one a line, so that a
//! program that never passes its arguments to `glutInit` (or has no GLUT at all, only GLX or
//! EGL) is rendered headless too. GLUT programs take them as if they were among their
//! arguments; a GLX or EGL program's first presented frame goes to `--png`'s file, and the
//! program ends there.

use gleval::app::Options;
use std::sync::OnceLock;

/// The launcher's options, as arguments.
pub fn arguments() -> Vec<String> {
    std::env::var("GLEVAL_OPTIONS").map(|s| s.lines().map(str::to_owned).collect()).unwrap_or_default()
}

/// The launcher's options, parsed.
pub fn options() -> &'static Options {
    static OPTIONS: OnceLock<Options> = OnceLock::new();
    OPTIONS.get_or_init(|| Options::from_args(arguments()))
}

/// With `--png PATH`: writes a presented frame there and ends the program (status 0, or 1
/// with the error if the file cannot be written), as a GLUT program's `--png` run does.
pub fn frame_presented(image: &gleval::render::Image) {
    let Some(path) = &options().png else { return };
    match gleval::render::write_png(path, image) {
        Ok(()) => std::process::exit(0),
        Err(e) => {
            eprintln!("gleval: --png {path}: {e}");
            std::process::exit(1);
        }
    }
}
