//! The callbacks a C program registers, per window as GLUT keeps them, and `App` closures that
//! call them.
//!
//! The C function pointers live in a thread-local table by window number, read when an event
//! comes, so a program that changes a callback from a callback (`glutDisplayFunc` inside
//! `keyboard`) is obeyed. When the main loop starts, every window's `App` gets a closure for
//! each event that looks its C function up; the closure makes the window's context current
//! while the C function runs. The idle callback, the timers and the menu status callbacks are
//! the program's, not a window's.

use crate::context::{enter, with_gl};
use gleval::app::App;
use gleval::gl::Gl;
use gleval::glut::consts::{GLUT_DOWN, GLUT_UP};
use std::cell::{Cell, RefCell};
use std::collections::HashMap;
use std::ffi::{c_int, c_uchar, c_uint};

type VoidFn = extern "C" fn();
type SizeFn = extern "C" fn(c_int, c_int);
type KeyFn = extern "C" fn(c_uchar, c_int, c_int);
type Int3Fn = extern "C" fn(c_int, c_int, c_int);
type Int4Fn = extern "C" fn(c_int, c_int, c_int, c_int);
type Int5Fn = extern "C" fn(c_int, c_int, c_int, c_int, c_int);
type StateFn = extern "C" fn(c_int);
type JoystickFn = extern "C" fn(c_uint, c_int, c_int, c_int);

/// One window's C callbacks.
#[derive(Clone, Copy, Default)]
struct Table {
    display: Option<VoidFn>,
    reshape: Option<SizeFn>,
    keyboard: Option<KeyFn>,
    keyboard_up: Option<KeyFn>,
    special: Option<Int3Fn>,
    special_up: Option<Int3Fn>,
    mouse: Option<Int4Fn>,
    motion: Option<SizeFn>,
    passive_motion: Option<SizeFn>,
    entry: Option<StateFn>,
    visibility: Option<StateFn>,
    window_status: Option<StateFn>,
    close: Option<VoidFn>,
    mouse_wheel: Option<Int4Fn>,
    position: Option<SizeFn>,
    overlay_display: Option<VoidFn>,
    init_context: Option<VoidFn>,
    app_status: Option<StateFn>,
    joystick: Option<(JoystickFn, c_int)>,
    spaceball_motion: Option<Int3Fn>,
    spaceball_rotate: Option<Int3Fn>,
    spaceball_button: Option<SizeFn>,
    button_box: Option<SizeFn>,
    dials: Option<SizeFn>,
    tablet_motion: Option<SizeFn>,
    tablet_button: Option<Int4Fn>,
    multi_entry: Option<SizeFn>,
    multi_button: Option<Int5Fn>,
    multi_motion: Option<Int3Fn>,
    multi_passive: Option<Int3Fn>,
}

/// The program's own callbacks.
#[derive(Clone, Copy, Default)]
struct Global {
    idle: Option<VoidFn>,
    menu_status: Option<Int3Fn>,
    menu_state: Option<StateFn>,
}

thread_local! {
    static TABLES: RefCell<HashMap<i32, Table>> = RefCell::new(HashMap::new());
    static GLOBAL: Cell<Global> = Cell::new(Global::default());
    static IN_LOOP: Cell<bool> = const { Cell::new(false) };
    static TIMERS: Cell<Vec<(u32, StateFn, i32)>> = const { Cell::new(Vec::new()) };
}

fn table(window: i32) -> Table {
    TABLES.with(|t| t.borrow().get(&window).copied().unwrap_or_default())
}

/// Changes the current window's table (GLUT: callbacks are set on the current window);
/// without a current window, freeglut's complaint.
fn update(call: &str, f: impl FnOnce(&mut Table)) {
    let window = with_gl(|gl| gl.glut_get_window());
    if window == 0 {
        return eprintln!("gleval: {call} called with no current window; the call is ignored");
    }
    TABLES.with(|t| f(t.borrow_mut().entry(window).or_default()));
}

fn global(f: impl FnOnce(&mut Global)) {
    GLOBAL.with(|g| {
        let mut v = g.get();
        f(&mut v);
        g.set(v);
    });
}

fn in_loop() -> bool {
    IN_LOOP.with(Cell::get)
}

/// A key as GLUT reports it: the character's byte (Latin-1), `None` beyond.
fn key_byte(c: char) -> Option<c_uchar> {
    u8::try_from(u32::from(c)).ok()
}

/// Calls window `id`'s C callback that `pick` finds (if set now) with `gl` current.
fn call<F: Copy>(gl: &mut Gl, id: i32, pick: impl Fn(&Table) -> Option<F>, run: impl FnOnce(F)) -> bool {
    match pick(&table(id)) {
        Some(f) => {
            enter(gl, || run(f));
            true
        }
        None => false,
    }
}

/// Every window of `root` with closures for its events, and the program's idle callback and
/// timers on the first window; the loop starts after this.
pub(super) fn register(mut root: App) -> App {
    IN_LOOP.with(|l| l.set(true));
    let mut id = 1;
    while let Some(window) = root.window_mut(id) {
        let app = std::mem::replace(window, App::new("", 1, 1));
        *root.window_mut(id).expect("present") = register_window(app, id);
        id += 1;
    }
    if let Some(idle) = GLOBAL.with(Cell::get).idle {
        root = root.idle(move |gl| enter(gl, || idle()));
    }
    for (msecs, f, value) in TIMERS.with(Cell::take) {
        root = root.timer(msecs, move |gl, v| enter(gl, || f(v)), value);
    }
    root
}

/// Window `id`'s closures: each looks up the C function when its event comes.
fn register_window(app: App, id: i32) -> App {
    let gl_debug = super::init::gl_debug();
    let app = app
        .display(move |gl| {
            call(gl, id, |t| t.display, |f| f());
            if gl_debug {
                gl.glut_report_errors();
            }
        })
        .reshape(move |gl, w, h| {
            if !call(gl, id, |t| t.reshape, |f| f(w, h)) {
                gl.viewport(0, 0, w, h);
            }
        })
        .keyboard(move |gl, c, x, y| {
            call(gl, id, |t| t.keyboard, |f| key_byte(c).map_or((), |k| f(k, x, y)));
        })
        .keyboard_up(move |gl, c, x, y| {
            call(gl, id, |t| t.keyboard_up, |f| key_byte(c).map_or((), |k| f(k, x, y)));
        })
        .special(move |gl, k, x, y| {
            call(gl, id, |t| t.special, |f| f(k, x, y));
        })
        .special_up(move |gl, k, x, y| {
            call(gl, id, |t| t.special_up, |f| f(k, x, y));
        });
    register_pointer(app, id)
}

fn register_pointer(app: App, id: i32) -> App {
    let app = app
        .mouse(move |gl, b, s, x, y| {
            call(gl, id, |t| t.mouse, |f| f(b, s, x, y));
        })
        .motion(move |gl, x, y| {
            call(gl, id, |t| t.motion, |f| f(x, y));
        })
        .passive_motion(move |gl, x, y| {
            call(gl, id, |t| t.passive_motion, |f| f(x, y));
        })
        .entry(move |gl, s| {
            call(gl, id, |t| t.entry, |f| f(s));
        })
        // Without a wheel callback freeglut reports the wheel's notches as buttons 3 and 4.
        .mouse_wheel(move |gl, wheel, direction, x, y| {
            if !call(gl, id, |t| t.mouse_wheel, |f| f(wheel, direction, x, y)) {
                let button = if direction > 0 { 3 } else { 4 };
                call(gl, id, |t| t.mouse, |f| f(button, GLUT_DOWN, x, y));
                call(gl, id, |t| t.mouse, |f| f(button, GLUT_UP, x, y));
            }
        });
    register_window_state(app, id)
}

fn register_window_state(mut app: App, id: i32) -> App {
    // freeglut keeps one of the two (the one set last); so does `App`.
    let t = table(id);
    if t.visibility.is_some() {
        app = app.visibility(move |gl, s| {
            call(gl, id, |t| t.visibility, |f| f(s));
        });
    } else {
        app = app.window_status(move |gl, s| {
            call(gl, id, |t| t.window_status, |f| f(s));
        });
    }
    let app = app
        .close(move |gl| {
            call(gl, id, |t| t.close, |f| f());
        })
        .position_func(move |gl, x, y| {
            call(gl, id, |t| t.position, |f| f(x, y));
        })
        .init_context(move |gl| {
            call(gl, id, |t| t.init_context, |f| f());
        })
        .menu_status(move |gl, status, x, y| {
            let g = GLOBAL.with(Cell::get);
            if let Some(f) = g.menu_status {
                enter(gl, || f(status, x, y));
            }
            if let Some(f) = g.menu_state {
                enter(gl, || f(status));
            }
        });
    register_devices(app, id)
}

/// The device callbacks the program set: kept (as freeglut keeps them) and never called, as
/// there is no joystick, spaceball, tablet, dial box or multi-pointer device.
fn register_devices(mut app: App, id: i32) -> App {
    let t = table(id);
    if let Some((f, interval)) = t.joystick {
        app = app.joystick(move |gl, b, x, y, z| enter(gl, || f(b, x, y, z)), interval);
    }
    if let Some(f) = t.overlay_display {
        app = app.overlay_display(move |gl| enter(gl, || f()));
    }
    if let Some(f) = t.app_status {
        app = app.app_status(move |gl, s| enter(gl, || f(s)));
    }
    if let Some(f) = t.spaceball_motion {
        app = app.spaceball_motion(move |gl, x, y, z| enter(gl, || f(x, y, z)));
    }
    if let Some(f) = t.spaceball_rotate {
        app = app.spaceball_rotate(move |gl, x, y, z| enter(gl, || f(x, y, z)));
    }
    if let Some(f) = t.spaceball_button {
        app = app.spaceball_button(move |gl, b, s| enter(gl, || f(b, s)));
    }
    if let Some(f) = t.button_box {
        app = app.button_box(move |gl, b, s| enter(gl, || f(b, s)));
    }
    if let Some(f) = t.dials {
        app = app.dials(move |gl, d, v| enter(gl, || f(d, v)));
    }
    if let Some(f) = t.tablet_motion {
        app = app.tablet_motion(move |gl, x, y| enter(gl, || f(x, y)));
    }
    if let Some(f) = t.tablet_button {
        app = app.tablet_button(move |gl, b, s, x, y| enter(gl, || f(b, s, x, y)));
    }
    if let Some(f) = t.multi_entry {
        app = app.multi_entry(move |gl, d, s| enter(gl, || f(d, s)));
    }
    if let Some(f) = t.multi_button {
        app = app.multi_button(move |gl, d, x, y, b, s| enter(gl, || f(d, x, y, b, s)));
    }
    if let Some(f) = t.multi_motion {
        app = app.multi_motion(move |gl, d, x, y| enter(gl, || f(d, x, y)));
    }
    if let Some(f) = t.multi_passive {
        app = app.multi_passive(move |gl, d, x, y| enter(gl, || f(d, x, y)));
    }
    app
}

/// Registration entry points: `glutDisplayFunc(f)` stores `f` for the current window (NULL
/// clears it).
macro_rules! registrations {
    ($($name:ident($t:ty) => $field:ident;)*) => {
        $(entry! {
            #[doc = concat!("`", stringify!($name), "`: for the current window.")]
            fn $name(f: Option<$t>) { update(stringify!($name), |t| t.$field = f) }
        })*
    };
}

registrations! {
    glutDisplayFunc(VoidFn) => display;
    glutReshapeFunc(SizeFn) => reshape;
    glutKeyboardFunc(KeyFn) => keyboard;
    glutKeyboardUpFunc(KeyFn) => keyboard_up;
    glutSpecialFunc(Int3Fn) => special;
    glutSpecialUpFunc(Int3Fn) => special_up;
    glutMouseFunc(Int4Fn) => mouse;
    glutMotionFunc(SizeFn) => motion;
    glutPassiveMotionFunc(SizeFn) => passive_motion;
    glutEntryFunc(StateFn) => entry;
    glutCloseFunc(VoidFn) => close;
    glutWMCloseFunc(VoidFn) => close;
    glutMouseWheelFunc(Int4Fn) => mouse_wheel;
    glutPositionFunc(SizeFn) => position;
    glutOverlayDisplayFunc(VoidFn) => overlay_display;
    glutInitContextFunc(VoidFn) => init_context;
    glutAppStatusFunc(StateFn) => app_status;
    glutSpaceballMotionFunc(Int3Fn) => spaceball_motion;
    glutSpaceballRotateFunc(Int3Fn) => spaceball_rotate;
    glutSpaceballButtonFunc(SizeFn) => spaceball_button;
    glutButtonBoxFunc(SizeFn) => button_box;
    glutDialsFunc(SizeFn) => dials;
    glutTabletMotionFunc(SizeFn) => tablet_motion;
    glutTabletButtonFunc(Int4Fn) => tablet_button;
    glutMultiEntryFunc(SizeFn) => multi_entry;
    glutMultiButtonFunc(Int5Fn) => multi_button;
    glutMultiMotionFunc(Int3Fn) => multi_motion;
    glutMultiPassiveFunc(Int3Fn) => multi_passive;
}

entry! {
    /// `glutVisibilityFunc`: freeglut makes it of the window status, so it replaces a window
    /// status callback.
    fn glutVisibilityFunc(f: Option<StateFn>) {
        update("glutVisibilityFunc", |t| (t.visibility, t.window_status) = (f, None))
    }
}

entry! {
    /// `glutWindowStatusFunc`: replaces a visibility callback.
    fn glutWindowStatusFunc(f: Option<StateFn>) {
        update("glutWindowStatusFunc", |t| (t.window_status, t.visibility) = (f, None))
    }
}

entry! {
    /// `glutJoystickFunc(f, interval)`: kept; there is no joystick, so it is never called.
    fn glutJoystickFunc(f: Option<JoystickFn>, interval: c_int) {
        update("glutJoystickFunc", |t| t.joystick = f.map(|f| (f, interval)))
    }
}

entry! {
    /// `glutMenuStatusFunc`: the program's (status, x, y) when a menu opens or closes.
    fn glutMenuStatusFunc(f: Option<Int3Fn>) {
        global(|g| g.menu_status = f)
    }
}

entry! {
    /// `glutMenuStateFunc`: the program's (status) when a menu opens or closes.
    fn glutMenuStateFunc(f: Option<StateFn>) {
        global(|g| g.menu_state = f)
    }
}

entry! {
    /// `glutIdleFunc`: before the main loop, the program's idle callback; inside it, a
    /// request the loop carries out after the current callback (NULL stops idling).
    fn glutIdleFunc(f: Option<VoidFn>) {
        if !in_loop() {
            return global(|g| g.idle = f);
        }
        let idle = f.map(|f| Box::new(move |gl: &mut Gl| enter(gl, || f())) as gleval::glut::IdleFn);
        with_gl(|gl| gl.glut_idle_func(idle))
    }
}

entry! {
    /// `glutTimerFunc(msecs, f, value)`: `f(value)` once, `msecs` from now.
    fn glutTimerFunc(msecs: c_uint, f: Option<StateFn>, value: c_int) {
        let Some(f) = f else { return };
        if !in_loop() {
            return TIMERS.with(|t| {
                let mut timers = t.take();
                timers.push((msecs, f, value));
                t.set(timers);
            });
        }
        with_gl(|gl| gl.glut_timer_func(msecs, move |gl, v| enter(gl, || f(v)), value))
    }
}

entry! {
    /// `glutMenuDestroyFunc(f)` (freeglut): `f` runs when the current menu is destroyed.
    fn glutMenuDestroyFunc(f: Option<VoidFn>) {
        let handler = f.map(|f| Box::new(move |gl: &mut Gl| enter(gl, || f())) as Box<dyn FnMut(&mut Gl)>);
        with_gl(|gl| gl.glut_menu_destroy_func(handler))
    }
}
