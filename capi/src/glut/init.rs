//! `glutInit` (gleval's options and GLUT's X options out of `argv`), the initial window
//! attributes, and the main loop: `glutMainLoop`, `glutMainLoopEvent`, `glutLeaveMainLoop`,
//! `glutExit`.

use super::{callbacks, windows};
use crate::context::{has_current, with_gl};
use gleval::app::{App, Options, Pass, Running};
use gleval::gl::Gl;
use gleval::glut::consts::*;
use gleval::glut::{split_init_args, InitArgs, XOptions};
use std::cell::RefCell;
use std::ffi::{c_char, c_int, c_uint, CStr};

/// What the program asked for before its windows.
struct Setup {
    options: Options,
    size: (i32, i32),
    position: Option<(i32, i32)>,
    display_mode: u32,
    /// `-gldebug`: GL errors are reported after each display callback.
    gl_debug: bool,
    /// The program-wide settings made before any window (`glutSetOption` after `glutInit`),
    /// which each window takes.
    settings: Gl,
}

thread_local! {
    static SETUP: RefCell<Setup> = RefCell::new(Setup {
        options: Options::from_args(crate::launcher::arguments()),
        // GLUT's default window size and display mode (GLUT_RGBA | GLUT_SINGLE | GLUT_DEPTH
        // is freeglut's; gleval's windows have colour and depth whatever is asked).
        size: (300, 300),
        position: None,
        display_mode: 0,
        gl_debug: false,
        settings: Gl::new(300, 300),
    });
    /// A loop the program drives with `glutMainLoopEvent`. Leaked rather than owned: a program
    /// may exit with its loop running, and a thread-local dropped at exit must not drop GPU
    /// devices (their library's thread-locals are gone by then); `Running::close` frees what
    /// it holds when the loop ends.
    static RUNNING: RefCell<Option<&'static mut Running>> = const { RefCell::new(None) };
    /// That loop is over (later passes do nothing).
    static ENDED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Runs `f` on the current context, or before any window on the settings' context (GLUT's
/// settings and queries answer before `glutCreateWindow`).
pub(super) fn with_glut<R: crate::boundary::Fallback>(f: impl FnOnce(&mut Gl) -> R) -> R {
    if has_current() {
        with_gl(f)
    } else {
        SETUP.with(|s| f(&mut s.borrow_mut().settings))
    }
}

/// A program-wide setting: on the current context, and on the settings' context that windows
/// made later take it from.
pub(super) fn set_glut(f: impl Fn(&mut Gl)) {
    if has_current() {
        with_gl(&f);
    }
    SETUP.with(|s| f(&mut s.borrow_mut().settings));
}

/// A new window's `App` with the program's size, place and display mode (`sub`: a
/// subwindow's own place and size); its context takes the settings made so far.
pub(super) fn new_window(title: &str, sub: Option<(i32, i32, i32, i32)>) -> App {
    SETUP.with(|s| {
        let s = s.borrow();
        // freeglut on Mesa has no colour-index window to give: its fatal error, status 1.
        gleval::glut::display_mode::exit_unless_possible(s.display_mode);
        let (w, h) = sub.map_or(s.size, |(_, _, w, h)| (w, h));
        let mut app = App::new(title, w, h).init_display_mode(s.display_mode);
        if let Some((x, y)) = sub.map(|(x, y, _, _)| (x, y)).or(s.position) {
            app = app.position(x, y);
        }
        app.context_mut().glut_inherit_settings(&s.settings);
        match crate::x11::default_screen_size() {
            Some((w, h)) => {
                app.context_mut().glut_set_screen_size(w, h);
                app.screen_size(w, h)
            }
            None => app,
        }
    })
}

/// Applies GLUT's X options as freeglut does: before any window, on the settings the windows
/// take (`App::run` applies the same options to a Rust program's window).
fn apply_x_options(x: &XOptions) {
    SETUP.with(|s| {
        let mut s = s.borrow_mut();
        if let Some(size) = x.size {
            s.size = size;
            s.settings.glut_set_option(GLUT_INIT_WINDOW_WIDTH, size.0);
            s.settings.glut_set_option(GLUT_INIT_WINDOW_HEIGHT, size.1);
        }
        if let Some((px, py)) = x.position {
            s.position = Some((px, py));
            s.settings.glut_set_option(GLUT_INIT_WINDOW_X, px);
            s.settings.glut_set_option(GLUT_INIT_WINDOW_Y, py);
        }
        s.gl_debug |= x.gl_debug;
    });
    // The X display the windows open on (winit reads it from the environment).
    if let Some(display) = &x.display {
        std::env::set_var("DISPLAY", display);
    }
    set_glut(|gl| gl.glut_take_x_settings(x));
}

/// Whether `-gldebug` was given.
pub(super) fn gl_debug() -> bool {
    SETUP.with(|s| s.borrow().gl_debug)
}

entry! {
    /// `glutInit(&argc, argv)`: takes gleval's options (`--png PATH`, `--time N`, `--frames N`,
    /// `--gpu`, `--wgpu`, `--profile`) and GLUT's X options (`-geometry WxH+X+Y`, `-display`,
    /// `-iconic`, `-direct`, `-indirect`, `-sync`, `-gldebug`) out of `argv`, as GLUT does.
    unsafe fn glutInit(argcp: *mut c_int, argv: *mut *mut c_char) {
        let (Some(argc), false) = (unsafe { argcp.as_mut() }, argv.is_null()) else { return };
        let n = usize::try_from(*argc).unwrap_or(0);
        // SAFETY: `argv` holds `argc` strings (C's promise for main's arguments).
        let strings: Vec<String> = (0..n)
            .map(|i| unsafe { *argv.add(i) })
            .map(|p| if p.is_null() { String::new() } else { unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned() })
            .collect();
        let InitArgs { gleval: ours, x, kept: keep } = split_init_args(&strings);
        let mut kept = 0;
        for (i, keep) in keep.into_iter().enumerate() {
            if keep {
                unsafe { *argv.add(kept) = *argv.add(i) };
                kept += 1;
            }
        }
        if kept < n {
            unsafe { *argv.add(kept) = std::ptr::null_mut() };
        }
        *argc = kept as c_int;
        let all = crate::launcher::arguments().into_iter().chain(ours);
        SETUP.with(|s| s.borrow_mut().options = Options::from_args(all));
        apply_x_options(&x);
        // freeglut answers the X screen's size (after `-display`, which picks the server).
        if let Some((w, h)) = crate::x11::default_screen_size() {
            SETUP.with(|s| s.borrow_mut().settings.glut_set_screen_size(w, h));
        }
    }
}

entry! {
    /// `glutInitWindowSize`.
    fn glutInitWindowSize(width: c_int, height: c_int) {
        SETUP.with(|s| {
            let mut s = s.borrow_mut();
            s.size = (width, height);
            s.settings.glut_set_option(GLUT_INIT_WINDOW_WIDTH, width);
            s.settings.glut_set_option(GLUT_INIT_WINDOW_HEIGHT, height);
        })
    }
}

entry! {
    /// `glutInitWindowPosition`: where later windows open (the window system may place them
    /// elsewhere); `glutGet(GLUT_INIT_WINDOW_X)` reads it back.
    fn glutInitWindowPosition(x: c_int, y: c_int) {
        SETUP.with(|s| s.borrow_mut().position = Some((x, y)));
        set_glut(|gl| {
            gl.glut_set_option(GLUT_INIT_WINDOW_X, x);
            gl.glut_set_option(GLUT_INIT_WINDOW_Y, y);
        });
    }
}

entry! {
    /// `glutInitDisplayMode`: kept for `glutGet`; the window always has colour and depth.
    fn glutInitDisplayMode(mode: c_uint) {
        SETUP.with(|s| s.borrow_mut().display_mode = mode);
        set_glut(|gl| gl.glut_set_option(GLUT_INIT_DISPLAY_MODE, mode as i32));
    }
}

entry! {
    /// `glutInitDisplayString`: the display mode freeglut makes of the string's words.
    unsafe fn glutInitDisplayString(string: *const c_char) {
        if string.is_null() {
            return;
        }
        let s = unsafe { CStr::from_ptr(string) }.to_string_lossy().into_owned();
        let (mode, unknown) = gleval::glut::display_mode_from_string(&s);
        for word in unknown {
            with_glut(|gl| gl.glut_warning(&format!("WARNING - Display string token not recognized:  {word}")));
        }
        SETUP.with(|s| s.borrow_mut().display_mode = mode);
        set_glut(|gl| gl.glut_set_option(GLUT_INIT_DISPLAY_MODE, mode as i32));
    }
}

/// The windows made so far with their callbacks, ready to run; `None` (with GLUT's complaint)
/// before any window.
fn program(call: &str) -> Option<App> {
    let current = with_gl(|gl| gl.glut_get_window()).max(1);
    let Some(mut root) = windows::take_root() else {
        eprintln!("gleval: {call} called before glutCreateWindow");
        return None;
    };
    root.sync_contexts(current);
    Some(callbacks::register(root))
}

/// The loop is over: no window's context is reachable any more; exit unless the program asked
/// for `glutMainLoop` to return.
fn loop_over(exit: bool) {
    windows::forget_all();
    crate::context::clear_current();
    if exit {
        std::process::exit(0);
    }
}

entry! {
    /// `glutMainLoop`: runs the program (windows, or headless with `--png PATH`, `--time N`)
    /// until the loop ends; then, as freeglut, exits the process unless
    /// `GLUT_ACTION_ON_WINDOW_CLOSE` is `GLUT_ACTION_GLUTMAINLOOP_RETURNS` or
    /// `GLUT_ACTION_CONTINUE_EXECUTION`, in which case it returns.
    fn glutMainLoop() {
        let Some(app) = program("glutMainLoop") else { std::process::exit(1) };
        let options = SETUP.with(|s| s.borrow().options.clone());
        // A panic inside the loop (a bug) ends the program with status 1 after its message,
        // as a failed run does.
        let ran = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| app.run_loop(options)));
        match ran {
            Ok(exit) => loop_over(exit),
            Err(_) => std::process::exit(1),
        }
    }
}

entry! {
    /// `glutMainLoopEvent` (freeglut): one pass of the main loop, for programs that run their
    /// own loop: the events waiting and the callbacks they call for. Headless (`--png PATH`
    /// with `--frames N`), the pictures are written after the Nth pass and the program ends.
    fn glutMainLoopEvent() {
        if ENDED.with(std::cell::Cell::get) {
            return;
        }
        let started = RUNNING.with(|r| r.borrow().is_some());
        if !started {
            let Some(app) = program("glutMainLoopEvent") else { return };
            let options = SETUP.with(|s| s.borrow().options.clone());
            match app.start_passes(&options) {
                Ok(running) => RUNNING.with(|r| *r.borrow_mut() = Some(Box::leak(Box::new(running)))),
                Err(e) => {
                    eprintln!("{e}");
                    std::process::exit(1);
                }
            }
        }
        let pass = RUNNING.with(|r| r.borrow_mut().as_mut().map(|running| running.pass()));
        match pass {
            Some(Ok(Pass::Running)) | None => {}
            // Headless, the pictures are written: the program ends here whatever the close
            // action, as its own loop would otherwise call for passes that never come.
            Some(Ok(Pass::Over { exit })) => {
                let headless = RUNNING.with(|r| {
                    r.borrow_mut().take().is_some_and(|running| {
                        running.close();
                        running.headless()
                    })
                });
                ENDED.with(|e| e.set(true));
                loop_over(exit || headless);
            }
            Some(Err(e)) => {
                eprintln!("{e}");
                std::process::exit(1);
            }
        }
    }
}

entry! {
    /// `glutLeaveMainLoop` (freeglut): the loop ends after the current callback.
    fn glutLeaveMainLoop() {
        with_gl(|gl| gl.glut_leave_main_loop())
    }
}

entry! {
    /// `glutExit` (freeglut): the loop ends; a program driving its own loop with
    /// `glutMainLoopEvent` has its windows closed now (their close callbacks run).
    fn glutExit() {
        with_gl(|gl| gl.glut_leave_main_loop());
        if let Some(running) = RUNNING.with(|r| r.borrow_mut().take()) {
            running.close();
            windows::forget_all();
            crate::context::clear_current();
        }
    }
}
