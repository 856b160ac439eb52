//! The interactive demo driven through `App`'s callbacks as the window drives them: dragging a
//! control point moves the curve's end, keys switch the curve kind and the window title says
//! so. (The winit event plumbing itself needs a display and is not exercised here.)

use gleval::prelude::*;

#[path = "../../examples/demo.rs"]
pub(crate) mod demo;

/// The first vertex of the first recorded curve, in world coordinates.
fn curve_start(gl: &mut Gl) -> [f32; 2] {
    let frame = gl.frame().expanded();
    let strip = frame.primitives.iter().find(|p| p.mode == GL_LINE_STRIP && p.count > 20).expect("a curve");
    let v = frame.vertices[strip.first].position;
    [v[0], v[1]]
}

#[test]
fn dragging_a_point_moves_the_curve_and_keys_switch_the_kind() {
    let mut app = demo::app();
    let mut gl = app.record_frame();
    // The Bezier curve starts at P0 = (1, 1): 800 × 480 pixels show [0, 10] × [0, 6].
    assert_eq!(curve_start(&mut gl), [1.0, 1.0]);
    assert!(gl.take_window_title().is_some_and(|t| t.starts_with("Bezier")));
    // Press on P0 (pixel (80, 400)), drag to world (2, 3) (pixel (160, 240)), release.
    assert!(app.run_mouse(&mut gl, GLUT_LEFT_BUTTON, GLUT_DOWN, 80, 400));
    assert!(app.run_motion(&mut gl, 160, 240));
    assert!(app.run_mouse(&mut gl, GLUT_LEFT_BUTTON, GLUT_UP, 160, 240));
    let _ = gl.take_frame();
    app.run_display(&mut gl);
    assert_eq!(curve_start(&mut gl), [2.0, 3.0]);
    // Moving after the release drags nothing.
    app.run_motion(&mut gl, 400, 100);
    let _ = gl.take_frame();
    app.run_display(&mut gl);
    assert_eq!(curve_start(&mut gl), [2.0, 3.0]);
    // 'n' draws a NURBS curve (GLU: an open uniform curve starts at its first point too).
    app.run_keyboard(&mut gl, 'n', 0, 0);
    let _ = gl.take_frame();
    app.run_display(&mut gl);
    assert!(gl.take_window_title().is_some_and(|t| t.starts_with("NURBS")));
    let start = curve_start(&mut gl);
    assert!((start[0] - 2.0).abs() < 1e-5 && (start[1] - 3.0).abs() < 1e-5, "{start:?}");
}
