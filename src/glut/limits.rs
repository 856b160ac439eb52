//! The parts of GLUT that freeglut 3.4 answers on X11 without the feature behind them, answered
//! the same way (each found by a probe program against freeglut under Xvfb):
//! - overlays: none possible (`glutLayerGet(GLUT_OVERLAY_POSSIBLE)` is 0), so establishing,
//!   showing, hiding, using and redisplaying one change nothing;
//! - game mode: `glutGameModeString` is parsed and read back by `glutGameModeGet`, but the
//!   screen's mode cannot change, so `glutEnterGameMode` warns "failed to change screen
//!   settings" and returns 0, and game mode is never active;
//! - video resizing: not possible (`glutVideoResizeGet` answers 0);
//! - colour-index maps in an RGBA window: `glutSetColor` changes nothing, `glutGetColor`
//!   answers -1, `glutCopyColormap` copies nothing;
//! - `glutGetModeValues`: gleval's windows have no multisampled or auxiliary buffers, so no
//!   values (freeglut lists what the X server's visuals offer).

use super::consts::*;
use crate::gl::types::{GLenum, GLfloat};
use crate::gl::Gl;

/// `glutGameModeString`'s fields: width, height, bits per pixel, refresh rate (-1 unset).
pub(crate) type GameMode = [i32; 4];

/// Parses freeglut's game-mode string, `[W x H][:BPP][@HZ]`: the fields given, -1 for the rest.
fn parse_game_mode(s: &str) -> GameMode {
    let mut out = [-1; 4];
    let (rest, hz) = s.split_once('@').map_or((s, None), |(a, b)| (a, Some(b)));
    let (size, bpp) = rest.split_once(':').map_or((rest, None), |(a, b)| (a, Some(b)));
    let number = |t: &str| t.trim().parse::<i32>().ok();
    if let Some((w, h)) = size.split_once('x') {
        out[0] = number(w).unwrap_or(-1);
        out[1] = number(h).unwrap_or(-1);
    }
    out[2] = bpp.and_then(number).unwrap_or(-1);
    out[3] = hz.and_then(number).unwrap_or(-1);
    out
}

/// `glutInitDisplayString`'s display mode, as freeglut 3.4 maps the tokens (a comparison such
/// as `depth>=16` counts as its name; `acc` and `acca` set nothing in freeglut, nor here);
/// the tokens it does not know, for its warning.
#[must_use]
pub fn display_mode_from_string(s: &str) -> (u32, Vec<String>) {
    let mut mode = 0;
    let mut unknown = Vec::new();
    for token in s.split([' ', '\t']).filter(|t| !t.is_empty()) {
        let name = token.split(['=', '<', '>', '!', '~']).next().unwrap_or("");
        mode |= match name {
            "alpha" => GLUT_ALPHA,
            "depth" => GLUT_DEPTH,
            "double" => GLUT_DOUBLE,
            "index" => GLUT_INDEX,
            "stencil" => GLUT_STENCIL,
            "samples" => GLUT_MULTISAMPLE,
            "stereo" => GLUT_STEREO,
            "luminance" => GLUT_LUMINANCE,
            "borderless" => GLUT_BORDERLESS,
            "aux" => GLUT_AUX,
            "acc" | "acca" | "rgba" | "rgb" | "single" | "red" | "green" | "blue" | "buffer" | "conformant" | "num"
            | "slow" | "win32pfd" | "xvisual" | "xstaticgray" | "xgrayscale" | "xstaticcolor" | "xpseudocolor"
            | "xtruecolor" | "xdirectcolor" | "xstaticgrey" | "xgreyscale" | "xstaticcolour" | "xpseudocolour"
            | "xtruecolour" | "xdirectcolour" => 0,
            _ => {
                unknown.push(name.to_owned());
                0
            }
        };
    }
    (mode, unknown)
}

impl Gl {
    /// `glutGameModeString(s)`: the mode `glutGameModeGet` reads back.
    pub fn glut_game_mode_string(&mut self, s: &str) {
        self.glut.program_mut().options.game_mode = parse_game_mode(s);
    }

    /// `glutEnterGameMode`: the screen's mode cannot change (freeglut on a server without
    /// mode switching warns and gives up): 0, no window.
    pub fn glut_enter_game_mode(&mut self) -> i32 {
        self.glut_warning("failed to change screen settings");
        0
    }

    /// `glutLeaveGameMode`: game mode never started, so there is nothing to leave.
    pub fn glut_leave_game_mode(&mut self) {}

    /// `glutGameModeGet(what)`: not possible, not active, no display change; the width,
    /// height, depth and rate `glutGameModeString` gave (-1 before); -1 for other names.
    #[must_use]
    pub fn glut_game_mode_get(&self, what: GLenum) -> i32 {
        let mode = self.glut.program().options.game_mode;
        match what {
            GLUT_GAME_MODE_ACTIVE | GLUT_GAME_MODE_POSSIBLE | GLUT_GAME_MODE_DISPLAY_CHANGED => 0,
            GLUT_GAME_MODE_WIDTH => mode[0],
            GLUT_GAME_MODE_HEIGHT => mode[1],
            GLUT_GAME_MODE_PIXEL_DEPTH => mode[2],
            GLUT_GAME_MODE_REFRESH_RATE => mode[3],
            _ => -1,
        }
    }

    /// `glutEstablishOverlay`: no overlay is possible (freeglut on X11 does nothing).
    pub fn glut_establish_overlay(&mut self) {}
    /// `glutRemoveOverlay`: there is none.
    pub fn glut_remove_overlay(&mut self) {}
    /// `glutUseLayer(layer)`: the normal plane stays in use.
    pub fn glut_use_layer(&mut self, _layer: GLenum) {}
    /// `glutPostOverlayRedisplay`: there is no overlay to redisplay.
    pub fn glut_post_overlay_redisplay(&mut self) {}
    /// `glutPostWindowOverlayRedisplay(window)`: there is no overlay to redisplay.
    pub fn glut_post_window_overlay_redisplay(&mut self, _window: i32) {}
    /// `glutShowOverlay`: there is none.
    pub fn glut_show_overlay(&mut self) {}
    /// `glutHideOverlay`: there is none.
    pub fn glut_hide_overlay(&mut self) {}

    /// `glutVideoResizeGet(what)`: video resizing is not possible: 0.
    #[must_use]
    pub fn glut_video_resize_get(&self, _what: GLenum) -> i32 {
        0
    }
    /// `glutSetupVideoResizing`: not possible, nothing to set up.
    pub fn glut_setup_video_resizing(&mut self) {}
    /// `glutStopVideoResizing`: never started.
    pub fn glut_stop_video_resizing(&mut self) {}
    /// `glutVideoResize(x, y, width, height)`: not possible.
    pub fn glut_video_resize(&mut self, _x: i32, _y: i32, _width: i32, _height: i32) {}
    /// `glutVideoPan(x, y, width, height)`: not possible.
    pub fn glut_video_pan(&mut self, _x: i32, _y: i32, _width: i32, _height: i32) {}

    /// `glutSetColor(index, r, g, b)`: the window is RGBA, it has no colour map to change.
    pub fn glut_set_color(&mut self, _index: i32, _red: GLfloat, _green: GLfloat, _blue: GLfloat) {}
    /// `glutGetColor(index, component)`: an RGBA window has no colour map: -1.
    #[must_use]
    pub fn glut_get_color(&self, _index: i32, _component: i32) -> GLfloat {
        -1.0
    }
    /// `glutCopyColormap(window)`: an RGBA window has no colour map to copy.
    pub fn glut_copy_colormap(&mut self, _window: i32) {}

    /// `glutGetModeValues(mode)`: the sample counts (`GLUT_MULTISAMPLE`) or auxiliary buffer
    /// counts (`GLUT_AUX`) a window could have: none here.
    #[must_use]
    pub fn glut_get_mode_values(&self, _mode: GLenum) -> Vec<i32> {
        Vec::new()
    }

    /// `glutForceJoystickFunc`: calls the joystick callback now if a joystick is plugged in;
    /// there is none.
    pub fn glut_force_joystick_func(&mut self) {}

    /// `glutSetVertexAttribCoord3(attrib)` (freeglut, for shaders of GL 2+): recorded; gleval's
    /// shapes feed GL 1.1's fixed pipeline, which has no generic attributes.
    pub fn glut_set_vertex_attrib_coord3(&mut self, attrib: i32) {
        self.glut.program_mut().options.vertex_attribs[0] = attrib;
    }
    /// `glutSetVertexAttribNormal(attrib)`: recorded, as [`Gl::glut_set_vertex_attrib_coord3`].
    pub fn glut_set_vertex_attrib_normal(&mut self, attrib: i32) {
        self.glut.program_mut().options.vertex_attribs[1] = attrib;
    }
    /// `glutSetVertexAttribTexCoord2(attrib)`: recorded, as [`Gl::glut_set_vertex_attrib_coord3`].
    pub fn glut_set_vertex_attrib_tex_coord2(&mut self, attrib: i32) {
        self.glut.program_mut().options.vertex_attribs[2] = attrib;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display_strings_as_freeglut_maps_them() {
        // Figures from freeglut 3.4 under Xvfb (glutGet(GLUT_INIT_DISPLAY_MODE) after the call).
        let cases = [
            ("rgba double depth>=16", 18),
            ("rgb single", 0),
            ("index", 1),
            ("alpha acc stencil samples stereo", 424),
            ("depth=24 double borderless", 2066),
            ("luminance", 512),
            ("foo double", 2),
            ("acca", 0),
            ("aux", 4096),
            ("num xvisual conformant slow buffer red green blue", 0),
        ];
        for (s, mode) in cases {
            assert_eq!(display_mode_from_string(s).0, mode, "{s}");
        }
        assert_eq!(display_mode_from_string("foo double").1, ["foo"]);
    }

    #[test]
    fn game_mode_strings() {
        assert_eq!(parse_game_mode("640x480:24@60"), [640, 480, 24, 60]);
        assert_eq!(parse_game_mode("800x600"), [800, 600, -1, -1]);
        assert_eq!(parse_game_mode(":16"), [-1, -1, 16, -1]);
    }
}
