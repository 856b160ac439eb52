//! Client memory that GL reads when it draws, not when it is handed over (GL 1.1 §2.8).
//!
//! `glVertexPointer(3, GL_FLOAT, 0, v)` keeps the address `v`; `glDrawArrays` reads the array
//! then, so a C program that changes `v` between the two calls draws the change. A Rust port
//! reads the same way with a [`ClientArray`]: a shared, growable buffer whose handle the
//! pointer calls keep (a clone of an `Rc`), and which the program goes on writing through its
//! own handle:
//!
//! ```
//! use gleval::prelude::*;
//! use gleval::gl::ClientArray;
//! let mut gl = Gl::new(4, 4);
//! let vertices = ClientArray::new(&[0.0f32, 0.0, 0.5, 0.5]);
//! gl.vertex_pointer(2, GL_FLOAT, 0, &vertices);
//! gl.enable_client_state(GL_VERTEX_ARRAY);
//! vertices.set(0, -0.5f32); // after the pointer call: drawn all the same
//! gl.draw_arrays(GL_POINTS, 0, 2);
//! assert_eq!(gl.frame().vertices[0].position, [-0.5, 0.0, 0.0, 1.0]);
//! ```
//!
//! An array element of a C pointer (`&v[3]`) is [`ClientArray::at`]`(3)`. Other memory (the C
//! ABI's raw pointers) implements [`ClientMemory`]; `Gl` only ever copies out of it the bytes a
//! draw call's own arguments say it reads.

use std::any::Any;
use std::cell::RefCell;
use std::fmt::Debug;
use std::rc::Rc;

/// Memory GL reads vertex arrays from at draw time.
pub trait ClientMemory: Debug {
    /// Copies `out.len()` bytes starting `offset` bytes in; false (and `out` unspecified) when
    /// the memory does not hold them all.
    fn read(&self, offset: usize, out: &mut [u8]) -> bool;
    /// Whether an element outside the memory reads as zeros instead of failing the draw: a
    /// buffer object's (GL 1.5), whose size GL knows, as llvmpipe's bounded vertex fetch reads
    /// it. Client memory has no size GL knows: gleval refuses to read past it.
    fn bounded(&self) -> bool {
        false
    }
    /// The memory as `Any`, so that a binding can recognise its own kind (the C ABI answers
    /// `glGetPointerv` with the address it was given).
    fn as_any(&self) -> &dyn Any;
}

impl ClientMemory for RefCell<Vec<u8>> {
    fn read(&self, offset: usize, out: &mut [u8]) -> bool {
        let bytes = self.borrow();
        let Some(src) = offset.checked_add(out.len()).and_then(|end| bytes.get(offset..end)) else { return false };
        out.copy_from_slice(src);
        true
    }

    fn as_any(&self) -> &dyn Any {
        self
    }
}

/// A value type client arrays hold, stored in native byte order as C lays it out.
pub trait ArrayElement: Copy + 'static {
    /// `sizeof` the type.
    const SIZE: usize;
    /// Writes the value's bytes into `out` (`SIZE` bytes).
    fn put(self, out: &mut [u8]);
    /// Reads a value from `SIZE` bytes.
    fn take(bytes: &[u8]) -> Self;
}

macro_rules! array_element {
    ($($t:ty),*) => {$(
        impl ArrayElement for $t {
            const SIZE: usize = std::mem::size_of::<$t>();
            fn put(self, out: &mut [u8]) {
                out.copy_from_slice(&self.to_ne_bytes());
            }
            fn take(bytes: &[u8]) -> Self {
                let mut b = [0u8; std::mem::size_of::<$t>()];
                b.copy_from_slice(&bytes[..Self::SIZE]);
                <$t>::from_ne_bytes(b)
            }
        }
    )*};
}
array_element!(i8, u8, i16, u16, i32, u32, f32, f64);

/// The bytes of `values` as C's array of them holds them.
pub(crate) fn to_bytes<T: ArrayElement>(values: &[T]) -> Vec<u8> {
    let mut out = vec![0u8; values.len() * T::SIZE];
    for (v, chunk) in values.iter().zip(out.chunks_exact_mut(T::SIZE)) {
        v.put(chunk);
    }
    out
}

/// A client array shared between the program and the context: the Rust form of the C array a
/// `gl*Pointer` call points into. Cloning gives another handle to the same memory.
#[derive(Clone, Debug)]
pub struct ClientArray {
    bytes: Rc<RefCell<Vec<u8>>>,
    /// Bytes per element of the type it was made of (what [`ClientArray::at`] counts in).
    element: usize,
}

impl ClientArray {
    /// An array holding `values` (`GLfloat v[] = {...}`).
    #[must_use]
    pub fn new<T: ArrayElement>(values: &[T]) -> Self {
        Self { bytes: Rc::new(RefCell::new(to_bytes(values))), element: T::SIZE }
    }

    /// An array of raw bytes, for layouts that mix types (`GL_C4UB_V3F`'s colour bytes and
    /// float coordinates).
    #[must_use]
    pub fn from_bytes(bytes: Vec<u8>) -> Self {
        Self { bytes: Rc::new(RefCell::new(bytes)), element: 1 }
    }

    /// Its size in bytes.
    #[must_use]
    pub fn byte_len(&self) -> usize {
        self.bytes.borrow().len()
    }

    /// `v[index] = value`, counting in elements of `T`; false (nothing written) past the end.
    pub fn set<T: ArrayElement>(&self, index: usize, value: T) -> bool {
        self.write(index, &[value])
    }

    /// Writes `values` from element `first` on (elements of `T`); false (nothing written)
    /// when they do not fit.
    pub fn write<T: ArrayElement>(&self, first: usize, values: &[T]) -> bool {
        let mut bytes = self.bytes.borrow_mut();
        let start = first.checked_mul(T::SIZE);
        let range = start.and_then(|s| Some(s..s.checked_add(values.len() * T::SIZE)?));
        let Some(target) = range.and_then(|r| bytes.get_mut(r)) else { return false };
        target.copy_from_slice(&to_bytes(values));
        true
    }

    /// `v[index]` as a `T`; `None` past the end.
    #[must_use]
    pub fn get<T: ArrayElement>(&self, index: usize) -> Option<T> {
        let mut b = vec![0u8; T::SIZE];
        self.bytes.read(index.checked_mul(T::SIZE)?, &mut b).then(|| T::take(&b))
    }

    /// The whole array as values of `T` (a trailing partial value is left out).
    #[must_use]
    pub fn to_vec<T: ArrayElement>(&self) -> Vec<T> {
        self.bytes.borrow().chunks_exact(T::SIZE).map(T::take).collect()
    }

    /// `&v[index]`: a pointer `index` elements (of the type the array was made of) in.
    #[must_use]
    pub fn at(&self, index: usize) -> ClientPointer {
        self.at_byte(index.saturating_mul(self.element))
    }

    /// `(char *)v + offset`: a pointer `offset` bytes in.
    #[must_use]
    pub fn at_byte(&self, offset: usize) -> ClientPointer {
        ClientPointer { memory: self.bytes.clone(), offset }
    }
}

/// Where a vertex array starts: client memory and a byte offset into it, what a C pointer
/// names. Made from a [`ClientArray`] (`&array`, [`ClientArray::at`]) or any [`ClientMemory`].
#[derive(Clone, Debug)]
pub struct ClientPointer {
    memory: Rc<dyn ClientMemory>,
    offset: usize,
}

impl ClientPointer {
    /// A pointer `offset` bytes into `memory`.
    #[must_use]
    pub fn new(memory: Rc<dyn ClientMemory>, offset: usize) -> Self {
        Self { memory, offset }
    }

    /// The memory it points into.
    #[must_use]
    pub fn memory(&self) -> &Rc<dyn ClientMemory> {
        &self.memory
    }

    /// The byte offset into the memory.
    #[must_use]
    pub fn offset(&self) -> usize {
        self.offset
    }

    /// Whether this pointer is the start of `array` (`glGetPointerv` answers in tests).
    #[must_use]
    pub fn points_into(&self, array: &ClientArray) -> bool {
        std::ptr::addr_eq(Rc::as_ptr(&self.memory), Rc::as_ptr(&array.bytes))
    }

    /// Copies `out.len()` bytes from `offset` bytes past the pointer; false when they are not
    /// all there (or `offset` is negative: before the pointer).
    pub(crate) fn read(&self, offset: isize, out: &mut [u8]) -> bool {
        let at = usize::try_from(offset).ok().and_then(|o| o.checked_add(self.offset));
        at.is_some_and(|at| self.memory.read(at, out))
    }
}

impl PartialEq for ClientPointer {
    fn eq(&self, other: &Self) -> bool {
        std::ptr::addr_eq(Rc::as_ptr(&self.memory), Rc::as_ptr(&other.memory)) && self.offset == other.offset
    }
}

impl From<&ClientArray> for ClientPointer {
    fn from(array: &ClientArray) -> Self {
        array.at_byte(0)
    }
}

impl From<&ClientPointer> for ClientPointer {
    fn from(pointer: &ClientPointer) -> Self {
        pointer.clone()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrays_read_and_write_in_elements() {
        let a = ClientArray::new(&[1.0f32, 2.0, 3.0]);
        assert_eq!(a.byte_len(), 12);
        assert!(a.set(1, 5.0f32));
        assert!(!a.set(3, 5.0f32));
        assert_eq!(a.to_vec::<f32>(), vec![1.0, 5.0, 3.0]);
        assert_eq!(a.get::<f32>(2), Some(3.0));
        assert_eq!(a.get::<f32>(3), None);
        let p = a.at(1);
        assert_eq!(p.offset(), 4);
        let mut out = [0u8; 8];
        assert!(p.read(0, &mut out));
        assert!(!p.read(4, &mut out));
        assert!(!p.read(-4, &mut out));
        assert!(p.points_into(&a));
    }
}
