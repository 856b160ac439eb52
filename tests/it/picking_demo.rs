//! The picking program (`examples/picking.rs`) driven through `App`'s callbacks as a window
//! drives them: a click on a control point selects it through selection mode, a drag moves it
//! (`gluUnProject`) and the curve follows.

use gleval::prelude::*;

use crate::conformance::picking;

/// The highlighted point (the last single point drawn 14 pixels wide), if any.
fn highlighted(gl: &mut Gl) -> Option<[f32; 2]> {
    let frame = gl.frame().expanded();
    let p = frame.primitives.iter().rev().find(|p| p.mode == GL_POINTS && p.count == 1)?;
    (frame.states[p.state].point_size == 14.0).then(|| {
        let v = frame.vertices[p.first].position;
        [v[0], v[1]]
    })
}

/// The control polygon's vertices (the one line strip of 5 vertices).
fn polygon(gl: &mut Gl) -> Vec<[f32; 2]> {
    let frame = gl.frame().expanded();
    let p = frame.primitives.iter().find(|p| p.mode == GL_LINE_STRIP && p.count == 5).expect("control polygon");
    frame.vertices_of(p).iter().map(|v| [v.position[0], v.position[1]]).collect()
}

#[test]
fn a_click_selects_a_point_and_a_drag_moves_it() {
    let mut app = picking::app();
    let mut gl = app.record_frame();
    // The first frame: the click beside control point 2, (0, -1), selected it.
    assert_eq!(highlighted(&mut gl), Some([0.0, -1.0]));
    assert_eq!(gl.get_error(), GL_NO_ERROR);
    // Point 3, (2, 3), is at window (300, 350), GLUT's y 50: press there, drag to (350, 100).
    assert!(app.run_mouse(&mut gl, GLUT_LEFT_BUTTON, GLUT_DOWN, 302, 48));
    assert!(app.run_motion(&mut gl, 350, 100));
    assert!(app.run_mouse(&mut gl, GLUT_LEFT_BUTTON, GLUT_UP, 350, 100));
    let _ = gl.take_frame();
    app.run_display(&mut gl);
    assert_eq!(highlighted(&mut gl), Some([3.0, 2.0]));
    assert_eq!(polygon(&mut gl)[3], [3.0, 2.0], "the vertex array is read when it draws");
    // A click on empty space selects nothing.
    app.run_mouse(&mut gl, GLUT_LEFT_BUTTON, GLUT_DOWN, 10, 10);
    let _ = gl.take_frame();
    app.run_display(&mut gl);
    assert_eq!(highlighted(&mut gl), None);
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}
