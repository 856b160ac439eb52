//! GLUT's main loop as `App` runs it headless (`--frames N`): idle and timer callbacks on a
//! virtual 60 Hz clock, `glutPostRedisplay`, `glutReshapeWindow`, `glutGet`. What is checked is
//! GLUT's documented behaviour (GLUT 3 spec §7.19 glutIdleFunc, §7.20 glutTimerFunc, §2.1
//! glutPostRedisplay): the display callback runs only after a redisplay is posted, a timer
//! runs once, timers due together run in the order they were registered.

use gleval::prelude::*;
use std::cell::RefCell;
use std::rc::Rc;

type Log = Rc<RefCell<Vec<String>>>;

fn log() -> Log {
    Rc::new(RefCell::new(Vec::new()))
}

/// An app whose display callback logs its call and the elapsed time.
fn logging_app(log: &Log) -> App {
    let l = Rc::clone(log);
    App::new("loop", 64, 48).display(move |gl| {
        l.borrow_mut().push(format!("display {}", gl.glut_get(GLUT_ELAPSED_TIME)));
    })
}

#[test]
fn without_idle_or_timers_one_frame_is_all_there_is() {
    let log = log();
    let mut app = logging_app(&log);
    let _ = app.record_frames(30);
    assert_eq!(*log.borrow(), ["display 0"]);
}

#[test]
fn an_idle_callback_that_posts_redisplay_animates_one_step_per_frame() {
    let log = log();
    let steps = Rc::new(RefCell::new(0));
    let s = Rc::clone(&steps);
    let mut app = logging_app(&log).idle(move |gl| {
        *s.borrow_mut() += 1;
        gl.glut_post_redisplay();
    });
    let _ = app.record_frames(4);
    assert_eq!(*steps.borrow(), 3, "idle runs between frames, once per refresh");
    // 1000/60 ms per refresh, truncated as GLUT's integer milliseconds.
    assert_eq!(*log.borrow(), ["display 0", "display 16", "display 33", "display 50"]);
}

#[test]
fn an_idle_callback_that_never_posts_draws_nothing_new() {
    let log = log();
    let mut app = logging_app(&log).idle(|_| {});
    let _ = app.record_frames(5);
    assert_eq!(log.borrow().len(), 1);
}

/// An idle callback that draws and swaps but never posts a redisplay (a common animation loop)
/// presents a frame each refresh: `--frames N` counts those frames, N - 1 idle calls after the
/// first display, instead of waiting for a redisplay that never comes.
#[test]
fn an_idle_callback_that_swaps_presents_one_frame_per_refresh() {
    let log = log();
    let steps = Rc::new(RefCell::new(0));
    let s = Rc::clone(&steps);
    let mut app = logging_app(&log).init_display_mode(GLUT_DOUBLE | GLUT_RGB).idle(move |gl| {
        *s.borrow_mut() += 1;
        gl.clear(GL_COLOR_BUFFER_BIT);
        gl.glut_swap_buffers();
    });
    let gl = app.record_frames(5);
    assert_eq!(*steps.borrow(), 4, "one idle call a presented frame");
    assert_eq!(gl.buffer_swaps(), 4);
    assert_eq!(*log.borrow(), ["display 0"], "no redisplay was posted");
}

#[test]
fn the_idle_callback_can_be_removed_from_a_callback() {
    let log = log();
    let count = Rc::new(RefCell::new(0));
    let c = Rc::clone(&count);
    let mut app = logging_app(&log).idle(move |gl| {
        *c.borrow_mut() += 1;
        gl.glut_post_redisplay();
        if *c.borrow() == 2 {
            gl.glut_idle_func(None); // glutIdleFunc(NULL)
        }
    });
    let _ = app.record_frames(10);
    assert_eq!(*count.borrow(), 2);
    assert_eq!(log.borrow().len(), 3);
}

#[test]
fn timers_run_once_when_due_and_in_registration_order() {
    let log = log();
    let l = Rc::clone(&log);
    let l2 = Rc::clone(&log);
    let mut app = logging_app(&log)
        .timer(
            100,
            move |gl, value| {
                l.borrow_mut().push(format!("timer {value} {}", gl.glut_get(GLUT_ELAPSED_TIME)));
                gl.glut_post_redisplay();
            },
            7,
        )
        .timer(100, move |_, value| l2.borrow_mut().push(format!("timer {value}")), 8);
    let _ = app.record_frames(10);
    // Due at 100 ms: the first refresh at or after it is the 6th (100.0 ms).
    assert_eq!(*log.borrow(), ["display 0", "timer 7 100", "timer 8", "display 100"]);
}

#[test]
fn a_timer_that_rearms_itself_drives_an_animation() {
    let log = log();
    let l = Rc::clone(&log);
    fn tick(gl: &mut Gl, value: i32, l: Log) {
        l.borrow_mut().push(format!("tick {value}"));
        gl.glut_post_redisplay();
        let l2 = Rc::clone(&l);
        gl.glut_timer_func(50, move |gl, v| tick(gl, v, Rc::clone(&l2)), value + 1);
    }
    let mut app = logging_app(&log).timer(50, move |gl, v| tick(gl, v, Rc::clone(&l)), 0);
    let _ = app.record_frames(3);
    let log = log.borrow();
    assert_eq!(log.as_slice(), ["display 0", "tick 0", "display 50", "tick 1", "display 100"]);
}

#[test]
fn reshape_window_resizes_the_next_frame() {
    let sizes = log();
    let s = Rc::clone(&sizes);
    let mut app = App::new("reshape", 64, 48)
        .reshape(move |gl, w, h| {
            s.borrow_mut().push(format!("{w}x{h}"));
            gl.viewport(0, 0, w, h);
        })
        .display(|_| {})
        .idle(|gl| {
            gl.glut_reshape_window(100, 80);
            gl.glut_post_redisplay();
        });
    let gl = app.record_frames(2);
    assert_eq!(*sizes.borrow(), ["64x48", "100x80"]);
    assert_eq!((gl.glut_get(GLUT_WINDOW_WIDTH), gl.glut_get(GLUT_WINDOW_HEIGHT)), (100, 80));
    assert_eq!(gl.glut_get(GLUT_INIT_WINDOW_WIDTH), 64);
}

#[test]
fn glut_get_answers_what_glut_does() {
    let mut app = App::new("get", 64, 48).init_display_mode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH).display(|_| {});
    let gl = app.record_frame();
    assert_eq!(gl.glut_get(GLUT_INIT_DISPLAY_MODE), (GLUT_DOUBLE | GLUT_DEPTH) as i32);
    assert_eq!(gl.glut_get(GLUT_WINDOW_DOUBLEBUFFER), 1);
    assert_eq!(gl.glut_get(GLUT_WINDOW_RGBA), 1);
    assert_eq!(gl.glut_get(0xdead), -1, "unknown names give -1, as freeglut");
    assert_eq!(gl.glut_get_modifiers(), 0, "no modifiers outside input callbacks");
}

#[test]
fn frames_are_deterministic_and_only_the_last_is_kept() {
    let draw = |frames| {
        let angle = Rc::new(RefCell::new(0.0f32));
        let (a1, a2) = (Rc::clone(&angle), Rc::clone(&angle));
        let mut app = App::new("spin", 64, 48)
            .display(move |gl| {
                gl.clear(GL_COLOR_BUFFER_BIT);
                gl.begin(GL_POINTS);
                gl.vertex2f(*a1.borrow(), 0.0);
                gl.end();
            })
            .idle(move |gl| {
                *a2.borrow_mut() += 0.1;
                gl.glut_post_redisplay();
            });
        let mut gl = app.record_frames(frames);
        let frame = gl.take_frame();
        assert_eq!(frame.vertices.len(), 1, "earlier frames are not kept");
        frame.vertices[0].position[0]
    };
    assert_eq!(draw(1), 0.0);
    assert!((draw(11) - 1.0).abs() < 1e-5);
    assert_eq!(draw(11), draw(11));
}
