//! The registry of live contexts that EGL and GLX keep alike, one per API: a context is
//! current in at most one thread, and one destroyed while current lives until it is released
//! (GLX 1.4 §3.3.7; EGL 1.5 §3.7.3, `eglDestroyContext`). The registry tells a handle that is
//! a context from one that is not, so a bad handle is an error, never a crash.

use crate::surface;
use gleval::gl::Gl;
use std::cell::Cell;
use std::collections::HashMap;
use std::sync::{Mutex, PoisonError};
use std::thread::{LocalKey, ThreadId};

/// A context of an API: a boxed value holding its GL context.
pub(crate) trait ApiContext: 'static {
    fn gl(&mut self) -> &mut Gl;
}

/// What the registry knows of a live context.
#[derive(Clone, Copy, Default)]
pub(crate) struct Life {
    /// The thread it is current in.
    pub current_in: Option<ThreadId>,
    /// Destroyed while current: freed when released.
    pub destroyed: bool,
}

/// One API's live contexts, by address, and the thread-local slot of the one current in each
/// thread.
pub(crate) struct Registry<C: ApiContext> {
    live: Mutex<Option<HashMap<usize, Life>>>,
    current: &'static LocalKey<Cell<*mut C>>,
}

impl<C: ApiContext> Registry<C> {
    pub(crate) const fn new(current: &'static LocalKey<Cell<*mut C>>) -> Self {
        Registry { live: Mutex::new(None), current }
    }

    fn with<R>(&self, f: impl FnOnce(&mut HashMap<usize, Life>) -> R) -> R {
        let mut guard = self.live.lock().unwrap_or_else(PoisonError::into_inner);
        f(guard.get_or_insert_with(HashMap::new))
    }

    /// Boxes a new context and registers it, current nowhere.
    pub(crate) fn register(&self, context: C) -> *mut C {
        let ctx = Box::into_raw(Box::new(context));
        self.with(|r| r.insert(ctx as usize, Life::default()));
        ctx
    }

    /// The live context a handle names.
    pub(crate) fn life(&self, handle: *mut C) -> Option<Life> {
        self.with(|r| r.get(&(handle as usize)).copied())
    }

    /// The context current in this thread (NULL if none of this API's is).
    pub(crate) fn current(&self) -> *mut C {
        self.current.with(Cell::get)
    }

    /// Makes `context`, a registered one, current in this thread: in the registry, for GL's
    /// calls and in this API's slot. What was current before is the caller's to release.
    pub(crate) fn make_current(&self, context: &mut C) {
        let ctx: *mut C = context;
        let me = std::thread::current().id();
        self.with(|r| r.entry(ctx as usize).or_default().current_in = Some(me));
        crate::context::make_current(context.gl());
        self.current.with(|c| c.set(ctx));
    }

    /// Destroys a live context: freed now if it is current nowhere, else when released.
    pub(crate) fn destroy(&self, ctx: *mut C, life: Life) {
        if life.current_in.is_some() {
            self.with(|r| r.entry(ctx as usize).or_default().destroyed = true);
        } else {
            self.free(ctx);
        }
    }

    /// Frees a context that is current nowhere.
    fn free(&self, ctx: *mut C) {
        self.with(|r| r.remove(&(ctx as usize)));
        // SAFETY: made by `register` and registered until now; current nowhere.
        let mut owned = unsafe { Box::from_raw(ctx) };
        crate::context::release_if_current(owned.gl());
    }

    /// Releases this thread's current context: its frame lands on its drawable, it is current
    /// nowhere, and freed if it was destroyed meanwhile.
    pub(crate) fn release_current(&self) {
        let ctx = self.current.with(|c| c.replace(std::ptr::null_mut()));
        if ctx.is_null() {
            return;
        }
        surface::unbind();
        // SAFETY: current, hence live.
        crate::context::release_if_current(unsafe { (*ctx).gl() });
        let destroyed = self.with(|r| {
            let life = r.get_mut(&(ctx as usize))?;
            life.current_in = None;
            Some(life.destroyed)
        });
        if destroyed == Some(true) {
            self.free(ctx);
        }
    }
}
