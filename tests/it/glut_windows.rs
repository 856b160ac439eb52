//! GLUT's windows through the Rust API: numbers in creation order, each window its own context
//! and callbacks, the first frame's callbacks in freeglut's order (seen under Xvfb with
//! `tests/reference/glut/Windows.c`: reshapes in reverse creation order, then window status,
//! then displays), subwindows composed into their parent's picture, and requests made from
//! callbacks (redisplay, hide, destroy, leave the loop) carried out after them.

use gleval::prelude::*;
use std::cell::RefCell;
use std::rc::Rc;

type Log = Rc<RefCell<Vec<String>>>;

fn window(log: &Log, title: &str, w: i32, h: i32, clear: [f32; 3]) -> App {
    let (l1, l2, l3) = (log.clone(), log.clone(), log.clone());
    App::new(title, w, h)
        .reshape(move |gl, w, h| {
            l1.borrow_mut().push(format!("reshape {} {w} {h}", gl.glut_get_window()));
            gl.viewport(0, 0, w, h);
            gl.matrix_mode(GL_PROJECTION);
            gl.load_identity();
            gl.ortho(0.0, f64::from(w), 0.0, f64::from(h), -1.0, 1.0);
            gl.matrix_mode(GL_MODELVIEW);
        })
        .display(move |gl| {
            l2.borrow_mut().push(format!("display {}", gl.glut_get_window()));
            gl.clear_color(clear[0], clear[1], clear[2], 1.0);
            gl.clear(GL_COLOR_BUFFER_BIT);
        })
        .window_status(move |gl, s| l3.borrow_mut().push(format!("status {} {s}", gl.glut_get_window())))
}

#[test]
fn windows_draw_in_freeglut_order_and_subwindows_are_composed_in_place() {
    let log: Log = Rc::default();
    let mut app = window(&log, "first", 40, 30, [0.0, 0.0, 1.0])
        .sub_window(1, 5, 10, window(&log, "", 8, 6, [1.0, 0.0, 0.0]))
        .window(window(&log, "second", 20, 10, [0.0, 1.0, 0.0]));
    let image = app.render_image().unwrap();
    assert_eq!(
        *log.borrow(),
        [
            "reshape 3 20 10",
            "reshape 2 8 6",
            "reshape 1 40 30",
            "status 1 1",
            "status 2 1",
            "status 3 1",
            "display 1",
            "display 2",
            "display 3"
        ]
    );
    let pixel = |x: u32, y: u32| &image.pixels[((y * image.width + x) * 4) as usize..][..3];
    assert_eq!((image.width, image.height), (40, 30));
    assert_eq!(pixel(0, 0), [0, 0, 255]);
    assert_eq!(pixel(5, 10), [255, 0, 0], "the subwindow's top left corner");
    assert_eq!(pixel(12, 15), [255, 0, 0], "its bottom right corner");
    assert_eq!(pixel(13, 16), [0, 0, 255]);
}

#[test]
fn window_queries_answer_for_the_current_window() {
    let seen = Rc::new(RefCell::new(Vec::new()));
    let s = seen.clone();
    let mut app = App::new("a", 50, 40)
        .display(move |gl| {
            s.borrow_mut().push((gl.glut_get(GLUT_WINDOW_NUM_CHILDREN), gl.glut_get(GLUT_WINDOW_WIDTH)));
            gl.glut_set_window(2);
            s.borrow_mut().push((gl.glut_get(GLUT_WINDOW_PARENT), gl.glut_get(GLUT_WINDOW_X)));
            gl.glut_set_window(9);
            s.borrow_mut().push((gl.glut_get_window(), 0));
        })
        .sub_window(1, 7, 3, App::new("", 10, 10));
    let _ = app.record_frame();
    assert_eq!(*seen.borrow(), [(1, 50), (1, 7), (2, 0)]);
}

#[test]
fn requests_from_callbacks_reach_other_windows() {
    let log: Log = Rc::default();
    let (l1, l2) = (log.clone(), log.clone());
    let mut app = App::new("a", 10, 10)
        .display(|gl| gl.glut_post_window_redisplay(2))
        .idle(move |gl| {
            l1.borrow_mut().push("idle".into());
            gl.glut_destroy_window(2);
            gl.glut_idle_func(None);
        })
        .window(App::new("b", 10, 10).display(move |_| l2.borrow_mut().push("display 2".into())).close({
            let l = log.clone();
            move |_| l.borrow_mut().push("close 2".into())
        }));
    let _ = app.record_frames(3);
    // Window 1's display asks window 2 to draw (it draws once, after window 1); the idle
    // callback then destroys it, whose close callback runs; nothing is left to redisplay.
    assert_eq!(*log.borrow(), ["display 2", "idle", "close 2"]);
}

#[test]
fn leaving_the_loop_ends_a_headless_run() {
    let frames = Rc::new(RefCell::new(0));
    let f = frames.clone();
    let mut app = App::new("a", 10, 10).display(move |gl| {
        *f.borrow_mut() += 1;
        if *f.borrow() == 3 {
            gl.glut_leave_main_loop();
        }
        gl.glut_post_redisplay();
    });
    let _ = app.record_frames(10);
    assert_eq!(*frames.borrow(), 3);
}
