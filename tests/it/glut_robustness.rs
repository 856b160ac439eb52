//! GLUT's calls with bad arguments never panic and change nothing they should not: windows
//! that do not exist, unknown query names, absurd shape sizes, joystick identifiers and axes
//! beyond freeglut's, options freeglut does not know. (The tea set keeps the normals of the
//! first size it is drawn at, program-wide as freeglut does, so this binary draws it only in
//! `glut_shapes.rs`; its odd sizes are tried in `src/glut/teaset.rs`'s own tests.)

use gleval::prelude::*;
use proptest::prelude::*;

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn any_arguments_are_safe(window in -3i32..9, name in 0u32..0x400, value in -5i32..5,
                              slices in -3i32..40, stacks in -3i32..40, levels in -2i32..4,
                              size in prop::num::f64::ANY) {
        let mut app = App::new("a", 16, 16).display(move |gl| {
            gl.glut_set_window(window);
            gl.glut_post_window_redisplay(window);
            let _ = (gl.glut_get(name), gl.glut_device_get(name), gl.glut_layer_get(name), gl.glut_game_mode_get(name));
            gl.glut_set_option(name, value);
            gl.glut_set_key_repeat(value);
            gl.glut_solid_cylinder(size, size, slices, stacks);
            gl.glut_wire_cylinder(size, 1.0, slices, stacks);
            gl.glut_solid_sierpinski_sponge(levels, &[size, 0.0, -size], size);
            gl.glut_joystick_set_dead_band(value, value, size as f32);
            let _ = gl.glut_joystick_get_saturation(value, value);
            if window > 1 {
                gl.glut_destroy_window(window);
            }
        });
        let gl = app.record_frames(2);
        prop_assert!(gl.width() == 16);
    }
}

#[test]
fn absurd_shapes_draw_nothing_rather_than_exhaust_memory() {
    let mut gl = Gl::new(8, 8);
    gl.glut_solid_cylinder(1.0, 1.0, 1 << 20, 1 << 20);
    gl.glut_wire_cylinder(1.0, 1.0, i32::MAX, i32::MAX);
    gl.glut_solid_sierpinski_sponge(40, &[0.0; 3], 1.0);
    assert!(gl.frame().primitives.is_empty());
    assert_eq!(gl.get_error(), GL_NO_ERROR);
}

#[test]
fn shapes_inside_begin_end_are_an_invalid_operation_and_draw_nothing() {
    let mut gl = Gl::new(8, 8);
    gl.begin(GL_POINTS);
    gl.glut_solid_teacup(1.0);
    gl.glut_wire_rhombic_dodecahedron();
    gl.end();
    assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    assert!(gl.frame().primitives.iter().all(|p| p.count == 0));
}
