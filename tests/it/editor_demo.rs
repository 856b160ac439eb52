//! The control-point editor (`examples/editor.rs`) driven through `App`'s callbacks as a window
//! drives them, its frames drawn by the CPU rasteriser: the first frame's selected ball wears
//! the ring; a click on another ball selects it (selection mode around gluSphere's triangles),
//! a drag moves it (gluProject/gluUnProject) and the ring follows.

use gleval::prelude::*;
use gleval::render::soft::render_frame;

use crate::conformance::editor;

/// The pixel at (x, y), y from the top as GLUT's, as RGB.
fn pixel(gl: &mut Gl, x: u32, y: u32) -> [u8; 3] {
    let image = render_frame(gl.frame(), 400, 400);
    let i = 4 * (y * image.width + x) as usize;
    [image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]]
}

/// The ring's yellow (1, 0.9, 0.1).
fn yellow(p: [u8; 3]) -> bool {
    p[0] > 240 && (220..=240).contains(&p[1]) && p[2] < 40
}

fn redisplay(app: &mut App, gl: &mut Gl) {
    let _ = gl.take_frame();
    app.run_display(gl);
}

#[test]
fn a_click_selects_a_ball_and_a_drag_moves_it() {
    let mut app = editor::app();
    let mut gl = app.record_frame();
    // The first frame: point 2, (-0.8, -2.6) at window (160, 330), picked, heavier (radius 0.26,
    // its ring 16 to 20 pixels out) and green.
    assert!(yellow(pixel(&mut gl, 178, 330)), "{:?}", pixel(&mut gl, 178, 330));
    let [r, g, b] = pixel(&mut gl, 160, 330);
    assert!(g > 150 && g > r && g > b, "point 2 is green: {:?}", [r, g, b]);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    // Point 3, (0.8, 2.6), is at window (240, 70): press beside its centre, drag to (300, 120),
    // world (2, 1.6), release.
    assert!(app.run_mouse(&mut gl, GLUT_LEFT_BUTTON, GLUT_DOWN, 242, 68));
    assert!(app.run_motion(&mut gl, 300, 120));
    assert!(app.run_mouse(&mut gl, GLUT_LEFT_BUTTON, GLUT_UP, 300, 120));
    redisplay(&mut app, &mut gl);
    // Its ring (radius 0.18: 12 to 16 pixels out) around the new place, none at the old ones.
    assert!(yellow(pixel(&mut gl, 314, 120)), "{:?}", pixel(&mut gl, 314, 120));
    assert!(!yellow(pixel(&mut gl, 254, 70)), "{:?}", pixel(&mut gl, 254, 70));
    assert!(!yellow(pixel(&mut gl, 178, 330)), "{:?}", pixel(&mut gl, 178, 330));
    let [r, g, b] = pixel(&mut gl, 300, 120);
    assert!(r > 200 && r > g && g > b, "point 3 is orange: {:?}", [r, g, b]);
    assert_eq!(pixel(&mut gl, 240, 70), pixel(&mut gl, 20, 200), "nothing left where point 3 was");
    // A click on empty space selects nothing: no ring.
    assert!(app.run_mouse(&mut gl, GLUT_LEFT_BUTTON, GLUT_DOWN, 20, 200));
    redisplay(&mut app, &mut gl);
    assert!(!yellow(pixel(&mut gl, 314, 120)), "{:?}", pixel(&mut gl, 314, 120));
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}
