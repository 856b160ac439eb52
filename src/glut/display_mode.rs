//! What `glutInitDisplayMode` can get on Mesa: colour-index windows (`GLUT_INDEX`) cannot be
//! had. Mesa has no colour-index visuals (Mesa 22 under Xvfb offers RGBA GLX configs only), so
//! freeglut's `glutCreateWindow` finds no config, prints its fatal error and exits with status
//! 1, before any callback runs (measured: freeglut 3.4 on Mesa 22.3, `GLUT_INDEX | GLUT_SINGLE`
//! and `GLUT_INDEX | GLUT_DOUBLE | GLUT_DEPTH`: `freeglut (./prog):  ERROR:  Internal error
//! <FBConfig with necessary capabilities not found> in function fgOpenWindow`, status 1). A
//! program asking for it gets the same here, from `App` and from the C ABI's
//! `glutCreateWindow`.

use super::consts::GLUT_INDEX;

/// Whether a window of display `mode` can be made: not a colour-index one.
#[must_use]
pub fn display_mode_possible(mode: u32) -> bool {
    mode & GLUT_INDEX == 0
}

/// freeglut's fatal error line for a display mode no config has, as `program` (its `argv[0]`)
/// prints it; `None` when the mode is possible.
#[must_use]
pub fn display_mode_error(program: &str, mode: u32) -> Option<String> {
    (!display_mode_possible(mode)).then(|| {
        format!(
            "freeglut ({program}):  ERROR:  Internal error <FBConfig with necessary capabilities not found> in \
             function fgOpenWindow"
        )
    })
}

/// Ends the process as freeglut does when the display `mode` cannot be had (see the module
/// docs); returns otherwise.
pub fn exit_unless_possible(mode: u32) {
    let program = std::env::args().next().unwrap_or_default();
    if let Some(message) = display_mode_error(&program, mode) {
        eprintln!("{message}");
        std::process::exit(1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::glut::consts::{GLUT_DEPTH, GLUT_DOUBLE, GLUT_RGB};

    #[test]
    fn colour_index_windows_cannot_be_had() {
        assert!(display_mode_possible(GLUT_RGB | GLUT_DOUBLE | GLUT_DEPTH));
        assert!(!display_mode_possible(GLUT_INDEX | GLUT_DOUBLE));
        let line = display_mode_error("./prog", GLUT_INDEX).expect("an error");
        assert!(line.starts_with("freeglut (./prog):  ERROR:  Internal error <FBConfig"));
        assert_eq!(display_mode_error("./prog", GLUT_RGB), None);
    }
}
