//! GLU's objects (NURBS renderers, tessellators, quadrics), held by the context as C programs
//! hold their pointers: a handle is an index into one table per kind, and a deleted object
//! leaves its slot empty, so a stale handle finds nothing (GLU would read freed memory).

use super::quadric::QuadricObject;
use super::{NurbsObject, TessObject};

/// The objects of one kind, indexed by their handles.
#[derive(Debug)]
pub(crate) struct Handles<T>(Vec<Option<T>>);

impl<T> Default for Handles<T> {
    fn default() -> Self {
        Self(Vec::new())
    }
}

impl<T> Handles<T> {
    /// Keeps `object` and gives its handle (never one handed out before).
    pub fn insert(&mut self, object: T) -> usize {
        self.0.push(Some(object));
        self.0.len() - 1
    }

    /// The object behind `handle`; `None` once deleted, or while taken.
    pub fn get_mut(&mut self, handle: usize) -> Option<&mut T> {
        self.0.get_mut(handle).and_then(Option::as_mut)
    }

    /// Takes the object out (its slot empty until [`Handles::put_back`]), so that a call may
    /// run its callbacks with the context in hand.
    pub fn take(&mut self, handle: usize) -> Option<T> {
        self.0.get_mut(handle).and_then(Option::take)
    }

    /// Returns a taken object to its slot.
    pub fn put_back(&mut self, handle: usize, object: T) {
        if let Some(slot) = self.0.get_mut(handle) {
            *slot = Some(object);
        }
    }

    /// Deletes the object: later calls with the handle find nothing.
    pub fn remove(&mut self, handle: usize) {
        if let Some(slot) = self.0.get_mut(handle) {
            *slot = None;
        }
    }
}

/// Every GLU object of a context.
#[derive(Debug, Default)]
pub(crate) struct GluObjects {
    pub nurbs: Handles<NurbsObject>,
    pub tessellators: Handles<TessObject>,
    pub quadrics: Handles<QuadricObject>,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn handles_are_never_reused_and_stale_ones_find_nothing() {
        let mut h = Handles::default();
        let (a, b) = (h.insert(1), h.insert(2));
        h.remove(a);
        assert_eq!(h.get_mut(a), None);
        assert_eq!(h.get_mut(b), Some(&mut 2));
        assert_eq!(h.insert(3), 2);
        let taken = h.take(b).unwrap();
        assert_eq!(h.get_mut(b), None);
        h.put_back(b, taken + 10);
        assert_eq!(h.get_mut(b), Some(&mut 12));
        h.remove(7);
        assert_eq!(h.take(7), None);
    }
}
