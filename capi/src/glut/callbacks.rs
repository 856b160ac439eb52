//! The callbacks a C program registers, and `App` closures that call them.
//!
//! The C function pointers live in a thread-local table read when an event comes, so a program
//! that changes its display function from a callback (`glutDisplayFunc` inside `keyboard`) is
//! obeyed. `App` gets a closure for each callback set when the main loop starts; the closure
//! makes the context it is handed current while the C function runs.

use crate::context::{enter, with_gl};
use gleval::app::App;
use gleval::gl::Gl;
use std::cell::Cell;
use std::ffi::{c_int, c_uchar, c_uint};

type VoidFn = extern "C" fn();
type SizeFn = extern "C" fn(c_int, c_int);
type KeyFn = extern "C" fn(c_uchar, c_int, c_int);
type SpecialFn = extern "C" fn(c_int, c_int, c_int);
type MouseFn = extern "C" fn(c_int, c_int, c_int, c_int);
type StateFn = extern "C" fn(c_int);

/// The table of C callbacks.
#[derive(Clone, Copy, Default)]
struct Table {
    display: Option<VoidFn>,
    reshape: Option<SizeFn>,
    keyboard: Option<KeyFn>,
    keyboard_up: Option<KeyFn>,
    special: Option<SpecialFn>,
    special_up: Option<SpecialFn>,
    mouse: Option<MouseFn>,
    motion: Option<SizeFn>,
    passive_motion: Option<SizeFn>,
    entry: Option<StateFn>,
    idle: Option<VoidFn>,
}

thread_local! {
    static TABLE: Cell<Table> = Cell::new(Table::default());
    static IN_LOOP: Cell<bool> = const { Cell::new(false) };
    static TIMERS: Cell<Vec<(u32, StateFn, i32)>> = const { Cell::new(Vec::new()) };
}

fn table() -> Table {
    TABLE.with(Cell::get)
}

fn update(f: impl FnOnce(&mut Table)) {
    TABLE.with(|t| {
        let mut table = t.get();
        f(&mut table);
        t.set(table);
    });
}

pub(super) fn set_in_loop(on: bool) {
    IN_LOOP.with(|l| l.set(on));
}

fn in_loop() -> bool {
    IN_LOOP.with(Cell::get)
}

/// A key as GLUT reports it: the character's byte (Latin-1), `None` beyond.
fn key_byte(c: char) -> Option<c_uchar> {
    u8::try_from(u32::from(c)).ok()
}

/// `App` with a closure for each callback set now.
pub(super) fn register(mut app: App) -> App {
    let t = table();
    if t.display.is_some() {
        app = app.display(|gl| call(gl, |t| t.display, |f| f()));
    }
    if t.reshape.is_some() {
        app = app.reshape(|gl, w, h| call(gl, |t| t.reshape, |f| f(w, h)));
    }
    if t.keyboard.is_some() {
        app = app.keyboard(|gl, c, x, y| call(gl, |t| t.keyboard, |f| key_byte(c).map_or((), |k| f(k, x, y))));
    }
    if t.keyboard_up.is_some() {
        app = app.keyboard_up(|gl, c, x, y| call(gl, |t| t.keyboard_up, |f| key_byte(c).map_or((), |k| f(k, x, y))));
    }
    if t.special.is_some() {
        app = app.special(|gl, k, x, y| call(gl, |t| t.special, |f| f(k, x, y)));
    }
    if t.special_up.is_some() {
        app = app.special_up(|gl, k, x, y| call(gl, |t| t.special_up, |f| f(k, x, y)));
    }
    register_pointer(app, t)
}

fn register_pointer(mut app: App, t: Table) -> App {
    if t.mouse.is_some() {
        app = app.mouse(|gl, b, s, x, y| call(gl, |t| t.mouse, |f| f(b, s, x, y)));
    }
    if t.motion.is_some() {
        app = app.motion(|gl, x, y| call(gl, |t| t.motion, |f| f(x, y)));
    }
    if t.passive_motion.is_some() {
        app = app.passive_motion(|gl, x, y| call(gl, |t| t.passive_motion, |f| f(x, y)));
    }
    if t.entry.is_some() {
        app = app.entry(|gl, s| call(gl, |t| t.entry, |f| f(s)));
    }
    if let Some(idle) = t.idle {
        app = app.idle(move |gl| enter(gl, || idle()));
    }
    for (msecs, f, value) in TIMERS.with(Cell::take) {
        app = app.timer(msecs, move |gl, v| enter(gl, || f(v)), value);
    }
    app
}

/// Calls the C callback `pick` finds in the table (if still set) with `gl` current.
fn call<F: Copy>(gl: &mut Gl, pick: impl Fn(&Table) -> Option<F>, run: impl FnOnce(F)) {
    if let Some(f) = pick(&table()) {
        enter(gl, || run(f));
    }
}

/// Registration entry points: `glutDisplayFunc(f)` stores `f` (NULL clears it).
macro_rules! registrations {
    ($($name:ident($t:ty) => $field:ident;)*) => {
        $(entry! {
            #[doc = concat!("`", stringify!($name), "`.")]
            fn $name(f: Option<$t>) { update(|t| t.$field = f) }
        })*
    };
}

registrations! {
    glutDisplayFunc(VoidFn) => display;
    glutReshapeFunc(SizeFn) => reshape;
    glutKeyboardFunc(KeyFn) => keyboard;
    glutKeyboardUpFunc(KeyFn) => keyboard_up;
    glutSpecialFunc(SpecialFn) => special;
    glutSpecialUpFunc(SpecialFn) => special_up;
    glutMouseFunc(MouseFn) => mouse;
    glutMotionFunc(SizeFn) => motion;
    glutPassiveMotionFunc(SizeFn) => passive_motion;
    glutEntryFunc(StateFn) => entry;
}

entry! {
    /// `glutIdleFunc`: before the main loop, `App`'s idle callback; inside it, a request the
    /// loop carries out after the current callback (NULL stops idling).
    fn glutIdleFunc(f: Option<VoidFn>) {
        if !in_loop() {
            return update(|t| t.idle = f);
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
