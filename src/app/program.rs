//! A running GLUT program: its windows, each with its own context and callbacks, the
//! program-wide idle callback and timers, and what callbacks ask of windows, carried out after
//! each callback as freeglut's main loop carries them out. Shared by the headless runner and
//! the window runner; neither knows GLUT's rules beyond what this file gives them.

use super::App;
use crate::gl::Gl;
use crate::glut::consts::*;
use crate::glut::options::GlutOptions;
use crate::glut::state::SharedProgram;
use crate::glut::windows::{WindowFacts, WindowRequest};
use crate::glut::Schedule;
use std::rc::Rc;

/// The virtual refresh period of headless runs: a 60 Hz display.
const HEADLESS_FRAME_MS: f64 = 1000.0 / 60.0;

/// How many refreshes a headless run waits for a redisplay (an idle callback that never posts
/// one, a timer an hour away) before it decides the picture will not change.
const MAX_QUIET_REFRESHES: usize = 100_000;

/// One window: what it is, its callbacks and its context.
pub(crate) struct Slot {
    pub facts: WindowFacts,
    pub app: App,
    /// Boxed so that its address stays put while windows come and go (the C ABI makes a
    /// window's context current by that address).
    pub gl: Box<Gl>,
    /// Its display callback must run.
    pub redisplay: bool,
    /// Its reshape callback must run with this size.
    pub reshape: Option<(i32, i32)>,
    /// Stacking among its siblings (`glutPopWindow` raises, `glutPushWindow` lowers).
    pub z: i32,
    /// Iconified: not shown, and not drawn headless.
    pub iconic: bool,
}

/// The windows of a running program.
pub(crate) struct Program {
    pub slots: Vec<Slot>,
    /// GLUT's program-wide state, the one every window's context holds: the settings, the
    /// message handlers, the window table, the current window, the clock and the screen.
    glut: SharedProgram,
    pub schedule: Schedule,
    /// The loop ends: `glutLeaveMainLoop`, or the last window closed.
    pub leave: bool,
    /// What a window system must carry out (move, retitle, cursor, ...) after the last
    /// callback; the headless runner drops them.
    pub effects: Vec<(i32, WindowRequest)>,
    /// Milliseconds since the loop started (`GLUT_ELAPSED_TIME`; headless, virtual).
    pub now_ms: f64,
}

impl Program {
    /// The program's windows from `root` and the windows added to it, each with the context
    /// made for it before the loop (the C ABI's) or a fresh one.
    pub fn new(mut root: App) -> Self {
        let tessellator = root.tessellator();
        let schedule = root.take_schedule(0.0);
        let screen = root.screen.unwrap_or((0, 0));
        let mut slots = Vec::new();
        for (index, (parent, mut app)) in root.flatten().into_iter().enumerate() {
            let id = index as i32 + 1;
            let mut gl = app.context.take().unwrap_or_else(|| Box::new(app.new_gl()));
            gl.set_tessellator(tessellator);
            gl.glut.window = id;
            let (x, y) = app.position.unwrap_or((0, 0));
            let facts = WindowFacts {
                id,
                parent,
                x,
                y,
                width: app.width,
                height: app.height,
                shown: true,
                cursor: GLUT_CURSOR_INHERIT,
                ..WindowFacts::default()
            };
            slots.push(Slot { facts, app, gl, redisplay: true, reshape: None, z: id, iconic: false });
        }
        // One program: the first window's (the C ABI's windows share it already; a Rust
        // program's windows made apart take the first's settings).
        let glut: SharedProgram = slots.first().map(|s| Rc::clone(&s.gl.glut.program)).unwrap_or_default();
        for slot in &mut slots {
            slot.gl.glut.program = Rc::clone(&glut);
        }
        {
            let mut p = glut.borrow_mut();
            (p.current, p.screen) = (1, screen);
        }
        let mut program = Self { slots, glut, schedule, leave: false, effects: Vec::new(), now_ms: 0.0 };
        let iconic = program.options().iconic;
        for slot in &mut program.slots {
            slot.iconic = iconic && slot.facts.parent == 0;
            slot.facts.shown = !slot.iconic;
        }
        program.refresh();
        program
    }

    /// The index of window `id`, if it is open.
    pub fn index(&self, id: i32) -> Option<usize> {
        self.slots.iter().position(|s| s.facts.id == id)
    }

    /// The program's window table and clock as they are now, for `glutGet` in every window.
    pub fn refresh(&mut self) {
        let mut facts: Vec<WindowFacts> = self.slots.iter().map(|s| s.facts).collect();
        for f in &mut facts {
            f.children = self.slots.iter().filter(|s| s.facts.parent == f.id).count() as i32;
        }
        for slot in &mut self.slots {
            slot.facts.children = facts.iter().find(|f| f.id == slot.facts.id).map_or(0, |f| f.children);
        }
        let mut p = self.glut.borrow_mut();
        p.windows = facts;
        p.elapsed_ms = self.now_ms as i32;
    }

    /// The window GLUT calls go to (`glutSetWindow`; the last window whose callback ran).
    pub fn current(&self) -> i32 {
        self.glut.borrow().current
    }

    fn set_current(&self, id: i32) {
        self.glut.borrow_mut().current = id;
    }

    /// The program-wide settings.
    pub fn options(&self) -> GlutOptions {
        self.glut.borrow().options
    }

    /// Runs a callback of window `k` with that window current, then carries out what it asked.
    pub fn callback<R>(&mut self, k: usize, run: impl FnOnce(&mut App, &mut Gl) -> R) -> R {
        self.set_current(self.slots[k].facts.id);
        let slot = &mut self.slots[k];
        let result = run(&mut slot.app, &mut slot.gl);
        self.absorb(k);
        result
    }

    /// Runs the program-wide callbacks (idle, timers) with the current window's context.
    pub fn run_global(&mut self, run: impl FnOnce(&mut Schedule, &mut Gl, f64) -> bool) -> bool {
        let Some(k) = self.index(self.current()).or(if self.slots.is_empty() { None } else { Some(0) }) else {
            return false;
        };
        let now = self.now_ms;
        let ran = run(&mut self.schedule, &mut self.slots[k].gl, now);
        self.absorb(k);
        ran
    }

    /// What the callback that just ran in window `k` changed: the idle callback and timers,
    /// and the requests every context holds (the settings and the current window are the
    /// program's already).
    fn absorb(&mut self, k: usize) {
        if let Some(slot) = self.slots.get_mut(k) {
            self.leave |= std::mem::take(&mut slot.gl.glut.leave_main_loop);
            self.schedule.absorb(&mut slot.gl, self.now_ms);
        }
        let mut requests = Vec::new();
        for slot in &mut self.slots {
            let id = slot.facts.id;
            let glut = &mut slot.gl.glut;
            requests.append(&mut glut.requests);
            if std::mem::take(&mut glut.redisplay) {
                requests.push((id, WindowRequest::Redisplay));
            }
            if let Some(title) = glut.title.take() {
                requests.push((id, WindowRequest::Title(title)));
            }
            if let Some((w, h)) = glut.reshape.take() {
                requests.push((id, WindowRequest::Reshape(w, h)));
            }
            if std::mem::take(&mut glut.full_screen) {
                requests.push((id, WindowRequest::FullScreen));
            }
        }
        for (id, request) in requests {
            self.apply(id, request);
        }
        self.refresh();
    }

    fn apply(&mut self, id: i32, request: WindowRequest) {
        if request == WindowRequest::Destroy {
            return self.destroy(id);
        }
        let Some(k) = self.index(id) else { return };
        let top = self.slots[k].facts.parent == 0;
        let far = self.slots.len() as i32 * 2;
        let slot = &mut self.slots[k];
        let mut shown_changed = None;
        match &request {
            WindowRequest::Redisplay => slot.redisplay = true,
            WindowRequest::Position(x, y) => (slot.facts.x, slot.facts.y) = (*x, *y),
            WindowRequest::Reshape(w, h) => {
                slot.reshape = Some((*w, *h));
                slot.redisplay = true;
            }
            WindowRequest::Show | WindowRequest::Hide | WindowRequest::Iconify => {
                let shown = request == WindowRequest::Show;
                slot.iconic = request == WindowRequest::Iconify && top;
                if slot.facts.shown != shown {
                    slot.facts.shown = shown;
                    slot.redisplay |= shown;
                    shown_changed = Some(shown);
                }
            }
            WindowRequest::Push => slot.z = -slot.facts.id - far,
            WindowRequest::Pop => slot.z = slot.facts.id + far,
            WindowRequest::FullScreen => slot.facts.full_screen = top,
            WindowRequest::LeaveFullScreen => slot.facts.full_screen = false,
            WindowRequest::FullScreenToggle => slot.facts.full_screen = top && !slot.facts.full_screen,
            WindowRequest::Cursor(c) => slot.facts.cursor = *c,
            WindowRequest::IgnoreKeyRepeat(on) => slot.facts.ignore_key_repeat = *on,
            WindowRequest::Data(d) => slot.facts.data = *d,
            WindowRequest::Title(_) | WindowRequest::IconTitle(_) | WindowRequest::WarpPointer(..) => {}
            WindowRequest::Destroy => {}
        }
        self.effects.push((id, request));
        if let Some(shown) = shown_changed {
            self.callback(k, |app, gl| app.run_shown(gl, shown));
        }
    }

    /// `glutDestroyWindow`: its subwindows first, then the window's close callback, then it
    /// goes, as freeglut's `fgDestroyWindow`. When no top-level window is left the loop ends.
    pub fn destroy(&mut self, id: i32) {
        let children: Vec<i32> = self.slots.iter().filter(|s| s.facts.parent == id).map(|s| s.facts.id).collect();
        for child in children {
            self.destroy(child);
        }
        let Some(k) = self.index(id) else { return };
        self.callback(k, |app, gl| app.run_close(gl));
        if let Some(k) = self.index(id) {
            self.slots.remove(k);
            self.effects.push((id, WindowRequest::Destroy));
        }
        if self.current() == id {
            self.set_current(0);
        }
        if !self.slots.iter().any(|s| s.facts.parent == 0) {
            self.leave = true;
        }
        self.refresh();
    }

    /// The user closed top-level window `id` (the window manager's close button), as freeglut
    /// answers it by `GLUT_ACTION_ON_WINDOW_CLOSE`: the window is destroyed; `GLUT_ACTION_EXIT`
    /// then ends the program (true), `..._GLUTMAINLOOP_RETURNS` ends the loop.
    pub fn close_by_user(&mut self, id: i32) -> bool {
        self.destroy(id);
        match self.options().action_on_close {
            GLUT_ACTION_EXIT => true,
            GLUT_ACTION_GLUTMAINLOOP_RETURNS => {
                self.leave = true;
                false
            }
            _ => false,
        }
    }

    /// The end of the loop (freeglut's `fgDeinitialize`): every window left is destroyed, its
    /// close callback run. True if the program should exit (`GLUT_ACTION_EXIT`) rather than
    /// return from `glutMainLoop`.
    pub fn finish(&mut self) -> bool {
        while let Some(top) = self.slots.iter().find(|s| s.facts.parent == 0).map(|s| s.facts.id) {
            self.destroy(top);
        }
        self.options().action_on_close == GLUT_ACTION_EXIT
    }

    /// The first frame of every window, in the order freeglut 3.4's first pass through its
    /// loop runs the callbacks (seen under Xvfb): the init-context callbacks in creation order,
    /// the reshapes in reverse creation order, the window status (or visibility) callbacks in
    /// creation order, then the display callbacks of the shown windows in creation order.
    pub fn start(&mut self) {
        for k in 0..self.slots.len() {
            self.callback(k, |app, gl| app.run_init(gl));
        }
        let ids: Vec<i32> = self.slots.iter().map(|s| s.facts.id).collect();
        for &id in &ids {
            if let Some(k) = self.index(id) {
                self.callback(k, |app, gl| app.run_init_context(gl));
            }
        }
        for &id in ids.iter().rev() {
            if let Some(k) = self.index(id) {
                self.reshape(k);
            }
        }
        for &id in &ids {
            if let Some(k) = self.index(id) {
                let shown = self.slots[k].facts.shown;
                self.callback(k, |app, gl| app.run_shown(gl, shown));
            }
        }
        self.display_pending();
    }

    /// Window `k`'s reshape callback at its (new) size.
    pub fn reshape(&mut self, k: usize) {
        let slot = &mut self.slots[k];
        let (w, h) = slot.reshape.take().unwrap_or((slot.facts.width, slot.facts.height));
        (slot.facts.width, slot.facts.height) = (w, h);
        (slot.app.width, slot.app.height) = (w, h);
        self.refresh();
        self.callback(k, |app, gl| app.run_reshape(gl, w, h));
    }

    /// The reshape and display callbacks of every window that asked for them (shown windows
    /// only); true if any drew. What a window drew before is dropped first.
    pub fn display_pending(&mut self) -> bool {
        let mut drew = false;
        let ids: Vec<i32> = self.slots.iter().map(|s| s.facts.id).collect();
        for id in ids {
            let Some(k) = self.index(id) else { continue };
            if self.slots[k].reshape.is_some() {
                self.reshape(k);
            }
            let slot = &mut self.slots[k];
            if !slot.redisplay || !slot.facts.shown {
                continue;
            }
            slot.redisplay = false;
            let previous = slot.gl.take_frame();
            slot.gl.recycle_frame(previous);
            self.callback(k, |app, gl| app.run_display(gl));
            drew = true;
        }
        drew
    }

    /// The windows drawn inside window `id`, bottom to top.
    pub fn children(&self, id: i32) -> Vec<usize> {
        let mut children: Vec<usize> = (0..self.slots.len()).filter(|&k| self.slots[k].facts.parent == id).collect();
        children.sort_by_key(|&k| self.slots[k].z);
        children
    }

    /// The top-level windows, in creation order.
    pub fn top_level(&self) -> Vec<usize> {
        (0..self.slots.len()).filter(|&k| self.slots[k].facts.parent == 0).collect()
    }

    /// Runs the program headless for `frames` frames: the first frame of every window, then,
    /// between frames, what GLUT's main loop does in one refresh of a 60 Hz display (the timers
    /// due, the idle callback once) until a callback posts a redisplay or presents a frame
    /// itself (swaps the buffers); the windows that asked draw again. It stops early when
    /// nothing is left that could redisplay, or the loop was
    /// left (`glutLeaveMainLoop`, the last window destroyed).
    pub fn run_headless(&mut self, frames: usize) {
        self.start();
        for _ in 1..frames.max(1) {
            if self.leave || !self.advance() {
                break;
            }
            self.display_pending();
        }
    }

    /// One refresh of the main loop: the clock advances, the due timers and the idle callback
    /// run (`glutMainLoopEvent` headless).
    pub fn step(&mut self, ms: f64) {
        self.now_ms += ms;
        self.refresh();
        self.run_global(|schedule, gl, now| schedule.fire_due(gl, now));
        self.run_global(|schedule, gl, now| schedule.run_idle(gl, now));
    }

    /// Each window's buffer swaps so far ([`Gl::buffer_swaps`]), by window.
    pub fn buffer_swaps(&self) -> Vec<(i32, u64)> {
        self.slots.iter().map(|s| (s.facts.id, s.gl.buffer_swaps())).collect()
    }

    /// Steps the virtual clock until a window must redraw (true) or nothing is left that could
    /// make one (false).
    fn advance(&mut self) -> bool {
        for _ in 0..MAX_QUIET_REFRESHES {
            let swaps = self.buffer_swaps();
            self.step(HEADLESS_FRAME_MS);
            if self.leave {
                return false;
            }
            // A frame presented by the idle callback or a timer counts as one of `--frames`,
            // whether or not a redisplay was posted.
            if self.slots.iter().any(|s| s.redisplay || s.reshape.is_some()) || self.buffer_swaps() != swaps {
                return true;
            }
            if self.schedule.is_empty() {
                return false;
            }
        }
        false
    }
}

impl App {
    /// Before the main loop (the C ABI, between `glutCreateWindow` and `glutMainLoop`): every
    /// window gets its context if it has none, and every context holds the program's state
    /// (`current`'s), which learns the program's windows and that `current` is the current
    /// window, so that `glutGet`, `glutSetWindow` and the settings answer as they will in the
    /// loop.
    pub fn sync_contexts(&mut self, current: i32) {
        let mut facts = Vec::new();
        let count = self.extra.len() as i32 + 1;
        for id in 1..=count {
            let parent = if id == 1 { 0 } else { self.extra[id as usize - 2].0 };
            let app = self.window_mut(id).expect("numbered above");
            let (x, y) = app.position.unwrap_or((0, 0));
            let (width, height) = (app.width, app.height);
            let gl = app.context_mut();
            gl.glut.window = id;
            let shown = !gl.glut.requests.iter().any(|(w, r)| *w == id && *r == WindowRequest::Destroy);
            let f = WindowFacts {
                id,
                parent,
                x,
                y,
                width,
                height,
                shown,
                cursor: GLUT_CURSOR_INHERIT,
                ..WindowFacts::default()
            };
            facts.push(f);
        }
        for f in &mut facts {
            f.children = (2..=count).filter(|&c| self.extra[c as usize - 2].0 == f.id).count() as i32;
        }
        // One program for them all: `current`'s (the C ABI's windows share one already).
        let Some(program) = self.window_mut(current).map(|w| Rc::clone(&w.context_mut().glut.program)) else { return };
        for id in 1..=count {
            let gl = self.window_mut(id).expect("numbered above").context_mut();
            gl.glut.program = Rc::clone(&program);
        }
        let mut p = program.borrow_mut();
        (p.windows, p.current) = (facts, current);
    }
}
