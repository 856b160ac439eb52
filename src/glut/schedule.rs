//! GLUT's main-loop scheduling, shared by the window and the headless runner: the idle callback
//! and the pending timers, on a clock the runner supplies (real milliseconds in a window; a
//! virtual 60 Hz clock headless, so that an animation renders the same frames on every run).

use super::state::TimerRequest;
use super::{IdleFn, TimerFn};
use crate::gl::Gl;

/// A timer waiting for its time.
struct Pending {
    due_ms: f64,
    /// Registration order: timers due at the same time run in the order they were asked for.
    seq: u64,
    callback: TimerFn,
    value: i32,
}

/// The idle callback and the timers of a running program.
#[derive(Default)]
pub(crate) struct Schedule {
    idle: Option<IdleFn>,
    timers: Vec<Pending>,
    seq: u64,
}

impl Schedule {
    /// A schedule that starts with the program's registrations (`App::idle`, `App::timer`).
    pub fn new(idle: Option<IdleFn>, timers: Vec<TimerRequest>, now_ms: f64) -> Self {
        let mut schedule = Self { idle, timers: Vec::new(), seq: 0 };
        for request in timers {
            schedule.add_timer(request, now_ms);
        }
        schedule
    }

    fn add_timer(&mut self, (msecs, callback, value): TimerRequest, now_ms: f64) {
        self.seq += 1;
        self.timers.push(Pending { due_ms: now_ms + f64::from(msecs), seq: self.seq, callback, value });
    }

    /// Takes the `glutIdleFunc` and `glutTimerFunc` calls the last callback made.
    pub fn absorb(&mut self, gl: &mut Gl, now_ms: f64) {
        if let Some(change) = gl.glut.idle.take() {
            self.idle = change;
        }
        for request in std::mem::take(&mut gl.glut.timers) {
            self.add_timer(request, now_ms);
        }
    }

    /// Runs every timer due by `now_ms`, earliest first (ties in registration order); timers
    /// they register wait for a later call. True if any ran.
    pub fn fire_due(&mut self, gl: &mut Gl, now_ms: f64) -> bool {
        let mut due: Vec<Pending> = Vec::new();
        let mut k = 0;
        while k < self.timers.len() {
            if self.timers[k].due_ms <= now_ms {
                due.push(self.timers.swap_remove(k));
            } else {
                k += 1;
            }
        }
        due.sort_by(|a, b| a.due_ms.total_cmp(&b.due_ms).then(a.seq.cmp(&b.seq)));
        let ran = !due.is_empty();
        for mut timer in due {
            (timer.callback)(gl, timer.value);
            self.absorb(gl, now_ms);
        }
        ran
    }

    /// Runs the idle callback once, if there is one. True if it ran.
    pub fn run_idle(&mut self, gl: &mut Gl, now_ms: f64) -> bool {
        let Some(idle) = self.idle.as_mut() else { return false };
        idle(gl);
        self.absorb(gl, now_ms);
        true
    }

    /// When the earliest timer is due.
    pub fn next_due_ms(&self) -> Option<f64> {
        self.timers.iter().map(|t| t.due_ms).min_by(f64::total_cmp)
    }

    /// An idle callback is set.
    pub fn has_idle(&self) -> bool {
        self.idle.is_some()
    }

    /// Nothing left that could run: no idle callback and no timer.
    pub fn is_empty(&self) -> bool {
        self.idle.is_none() && self.timers.is_empty()
    }
}
