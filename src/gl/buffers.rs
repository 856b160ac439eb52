//! GL 1.5's buffer objects (GL 1.5 §2.9, `GL_ARB_vertex_buffer_object`; Mesa 22.3
//! `main/bufferobj.c`): names, the `GL_ARRAY_BUFFER` and `GL_ELEMENT_ARRAY_BUFFER` bindings,
//! the data store, and mapping it into the client's address space.
//!
//! A buffer object is an [`Rc<BufferObject>`] that the bindings, the vertex arrays set while
//! it was bound (see `arrays.rs`) and a mapping share: a deleted buffer lives on in whatever
//! still holds it, as GL says (§2.9: "the data store is not deleted until no bindings refer to
//! it"). Its bytes are `Cell`s, so that a pointer [`BufferMap::as_ptr`] hands the C ABI may be
//! written through while the context holds the buffer too (the storage does not move until
//! `glBufferData` replaces it, which unmaps it first, as Mesa does).
//!
//! Mesa's rules, measured (`tests/reference/calls/cases/buffer_objects.calls`):
//! - every call here inside `begin`/`end` is `GL_INVALID_OPERATION` and does nothing;
//! - a target other than the two is `GL_INVALID_ENUM`; a target with buffer 0 bound,
//!   `GL_INVALID_OPERATION`; these come first, except in `glMapBuffer` (the access first) and
//!   `glGetBufferPointerv` (the name first);
//! - `glBindBuffer` of a name never generated makes the buffer (a compatibility context);
//!   `glIsBuffer` is false for a name generated but never bound; names are not reused: the next
//!   is one past the largest ever made;
//! - `glBufferData` checks the size (`GL_INVALID_VALUE`) before the usage (`GL_INVALID_ENUM`),
//!   and unmaps a mapped buffer with no error; the sub-data calls check the size, the offset
//!   and the range (`GL_INVALID_VALUE`) before the mapping (`GL_INVALID_OPERATION`);
//! - mapping a buffer of no bytes or a mapped one is `GL_INVALID_OPERATION`;
//!   `GL_BUFFER_ACCESS` is the mapping's access while mapped, `GL_READ_WRITE` otherwise;
//! - deleting a bound buffer unbinds it from the two targets and from every array (whose
//!   offset stays, `glGetPointerv` answers it); deleting a mapped one unmaps it;
//! - drawing from a mapped buffer is no error in Mesa 22.3: it draws what the buffer holds.

use super::client_memory::{to_bytes, ArrayElement, ClientMemory};
use super::consts::*;
use super::types::*;
use super::Gl;
use std::any::Any;
use std::cell::{Cell, RefCell};
use std::collections::HashMap;
use std::rc::Rc;

/// A buffer object: its name, data store, usage, and mapping.
#[derive(Debug)]
pub struct BufferObject {
    name: GLuint,
    store: RefCell<Vec<Cell<u8>>>,
    usage: Cell<GLenum>,
    /// The mapping in place.
    mapping: Cell<Option<Mapping>>,
}

/// A buffer's mapping: `glMapBuffer`'s access (GL 3.0's range maps have the access their read
/// and write bits make), a number no other mapping has, the byte range mapped and GL 3.0's
/// access flags (`GL_MAP_READ_BIT` ...; `glMapBuffer`'s are the read and write bits its access
/// names, as Mesa sets them).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Mapping {
    access: GLenum,
    id: u64,
    offset: usize,
    length: usize,
    flags: GLbitfield,
}

impl PartialEq for BufferObject {
    /// The same object (a binding names one object, whatever it holds).
    fn eq(&self, other: &Self) -> bool {
        std::ptr::eq(self, other)
    }
}

impl BufferObject {
    fn new(name: GLuint) -> Self {
        Self { name, store: RefCell::default(), usage: Cell::new(GL_STATIC_DRAW), mapping: Cell::new(None) }
    }

    /// Its name.
    #[must_use]
    pub fn name(&self) -> GLuint {
        self.name
    }

    /// Its size in bytes.
    #[must_use]
    pub fn len(&self) -> usize {
        self.store.borrow().len()
    }

    /// Whether it holds no bytes.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Whether it is mapped.
    #[must_use]
    pub fn is_mapped(&self) -> bool {
        self.mapping.get().is_some()
    }

    /// Stores `bytes` from `offset` on (a pixel pack buffer's writes); false where they do not
    /// fit.
    pub(super) fn store_bytes(&self, offset: usize, bytes: &[u8]) -> bool {
        self.write_bytes(offset, bytes)
    }

    fn write_bytes(&self, offset: usize, bytes: &[u8]) -> bool {
        let store = self.store.borrow();
        let Some(cells) = offset.checked_add(bytes.len()).and_then(|end| store.get(offset..end)) else {
            return false;
        };
        cells.iter().zip(bytes).for_each(|(c, &b)| c.set(b));
        true
    }
}

impl ClientMemory for BufferObject {
    fn read(&self, offset: usize, out: &mut [u8]) -> bool {
        let store = self.store.borrow();
        let Some(cells) = offset.checked_add(out.len()).and_then(|end| store.get(offset..end)) else {
            return false;
        };
        out.iter_mut().zip(cells).for_each(|(o, c)| *o = c.get());
        true
    }

    /// llvmpipe's vertex fetch is bounded by the buffer: an element outside it reads as zeros.
    fn bounded(&self) -> bool {
        true
    }

    fn as_any(&self) -> &dyn Any {
        self
    }
}

/// `glMapBuffer`'s answer: the mapped data store, readable and writable (as the access allows)
/// until `glUnmapBuffer`, `glBufferData` or `glDeleteBuffers` ends the mapping; after that
/// every access answers false or `None`.
///
/// ```
/// use gleval::prelude::*;
/// let mut gl = Gl::new(4, 4);
/// let mut name = [0];
/// gl.gen_buffers(1, &mut name);
/// gl.bind_buffer(GL_ARRAY_BUFFER, name[0]);
/// gl.buffer_data(GL_ARRAY_BUFFER, 8, None::<&[u8]>, GL_DYNAMIC_DRAW);
/// let map = gl.map_buffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY).unwrap();
/// assert!(map.write(0, &[0.5f32, 0.25]));
/// assert_eq!(gl.unmap_buffer(GL_ARRAY_BUFFER), GL_TRUE);
/// assert!(!map.write(0, &[1.0f32]));
/// let mut back = [0.0f32; 2];
/// gl.get_buffer_sub_data(GL_ARRAY_BUFFER, 0, 8, &mut back);
/// assert_eq!(back, [0.5, 0.25]);
/// ```
#[derive(Clone, Debug)]
pub struct BufferMap {
    buffer: Rc<BufferObject>,
    id: u64,
}

impl PartialEq for BufferMap {
    fn eq(&self, other: &Self) -> bool {
        Rc::ptr_eq(&self.buffer, &other.buffer) && self.id == other.id
    }
}

impl BufferMap {
    /// The access it was mapped with, while it is the buffer's mapping.
    fn access(&self) -> Option<GLenum> {
        self.mapping().map(|m| m.access)
    }

    /// The buffer's mapping, while it is this one.
    fn mapping(&self) -> Option<Mapping> {
        self.buffer.mapping.get().filter(|m| m.id == self.id)
    }

    /// Where the mapped range starts in the data store (0 but for GL 3.0's range maps).
    fn start(&self) -> usize {
        self.mapping().map_or(0, |m| m.offset)
    }

    /// Whether the mapping is still in place.
    #[must_use]
    pub fn is_mapped(&self) -> bool {
        self.access().is_some()
    }

    /// Its size in bytes: the range mapped (the whole buffer but for GL 3.0's range maps).
    #[must_use]
    pub fn len(&self) -> usize {
        self.mapping().map_or(0, |m| m.length)
    }

    /// Whether it maps no bytes (GL maps no empty range: never true while mapped).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The address of the data store (C's `glMapBuffer` result). It stays valid until the
    /// mapping ends; the C ABI hands it out, Rust reads and writes through
    /// [`BufferMap::write`] and [`BufferMap::read`].
    #[must_use]
    pub fn as_ptr(&self) -> *mut u8 {
        self.buffer.store.borrow().as_ptr().cast::<u8>().cast_mut().wrapping_add(self.start())
    }

    /// Writes `values` from byte `offset` on; false (nothing written) when the mapping has
    /// ended, is `GL_READ_ONLY`, or the values do not fit.
    pub fn write<T: ArrayElement>(&self, offset: usize, values: &[T]) -> bool {
        let bytes = to_bytes(values);
        matches!(self.access(), Some(GL_WRITE_ONLY | GL_READ_WRITE))
            && offset.checked_add(bytes.len()).is_some_and(|end| end <= self.len())
            && self.buffer.write_bytes(self.start() + offset, &bytes)
    }

    /// Reads `out.len()` values from byte `offset` on; false when the mapping has ended, is
    /// `GL_WRITE_ONLY`, or the values are not all there.
    pub fn read<T: ArrayElement>(&self, offset: usize, out: &mut [T]) -> bool {
        if !matches!(self.access(), Some(GL_READ_ONLY | GL_READ_WRITE)) {
            return false;
        }
        let mut bytes = vec![0u8; out.len() * T::SIZE];
        if offset.checked_add(bytes.len()).is_none_or(|end| end > self.len())
            || !self.buffer.read(self.start() + offset, &mut bytes)
        {
            return false;
        }
        out.iter_mut().zip(bytes.chunks_exact(T::SIZE)).for_each(|(o, b)| *o = T::take(b));
        true
    }
}

/// The buffer objects by name (`None`: generated, not yet bound, so not yet a buffer) and the
/// mappings' numbering.
#[derive(Debug, Default)]
pub(crate) struct BufferObjects {
    objects: HashMap<GLuint, Option<Rc<BufferObject>>>,
    /// The largest name ever made (Mesa's hash table's `MaxKey`: names are not reused).
    max_name: GLuint,
    /// GL 2.1's `GL_PIXEL_PACK_BUFFER` binding (see `pixel_buffers.rs`).
    pub(super) pack: Option<Rc<BufferObject>>,
    /// GL 2.1's `GL_PIXEL_UNPACK_BUFFER` binding.
    pub(super) unpack: Option<Rc<BufferObject>>,
    /// One entry a `glPushClientAttrib`: the pack and unpack bindings when it saved the
    /// pixel-store group, which holds them (GL 2.1 table 6.39; Mesa's `copy_pixelstore`).
    pub(super) saved_pixel_buffers: Vec<Option<PixelBuffers>>,
    mappings: u64,
}

/// Whether `target` is a buffer target gleval has (GL 1.5's two, GL 2.1's pixel buffers).
fn known_target(target: GLenum) -> bool {
    matches!(target, GL_ARRAY_BUFFER | GL_ELEMENT_ARRAY_BUFFER | GL_PIXEL_PACK_BUFFER | GL_PIXEL_UNPACK_BUFFER)
}

/// The pack and unpack buffer bindings.
pub(super) type PixelBuffers = (Option<Rc<BufferObject>>, Option<Rc<BufferObject>>);

/// GL 1.5 table 2.8's usages.
fn known_usage(usage: GLenum) -> bool {
    matches!(
        usage,
        GL_STREAM_DRAW
            | GL_STREAM_READ
            | GL_STREAM_COPY
            | GL_STATIC_DRAW
            | GL_STATIC_READ
            | GL_STATIC_COPY
            | GL_DYNAMIC_DRAW
            | GL_DYNAMIC_READ
            | GL_DYNAMIC_COPY
    )
}

/// `count` zero bytes, `None` when memory cannot be had.
fn zeroed(count: usize) -> Option<Vec<Cell<u8>>> {
    let mut store = Vec::new();
    store.try_reserve_exact(count).ok()?;
    store.resize_with(count, Cell::default);
    Some(store)
}

impl Gl {
    /// The buffer bound to `target` (either of the two).
    fn bound_buffer(&self, target: GLenum) -> Option<&Rc<BufferObject>> {
        match target {
            GL_ARRAY_BUFFER => self.client.arrays.array_buffer.as_ref(),
            GL_PIXEL_PACK_BUFFER => self.client.buffers.pack.as_ref(),
            GL_PIXEL_UNPACK_BUFFER => self.client.buffers.unpack.as_ref(),
            _ => self.client.arrays.element_buffer.as_ref(),
        }
    }

    /// The checks every call on a target's buffer makes first, in Mesa's order (inside
    /// `begin`/`end`, the target, buffer 0 bound); the buffer when they pass.
    fn target_buffer(&mut self, target: GLenum) -> Option<Rc<BufferObject>> {
        if self.reject_inside_begin_end() {
            return None;
        }
        if !known_target(target) {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        let buffer = self.bound_buffer(target).cloned();
        if buffer.is_none() {
            self.set_error(GL_INVALID_OPERATION);
        }
        buffer
    }

    /// `glGenBuffers(n, buffers)`: `n` names never used before, written to `buffers`. `n` < 0
    /// or `buffers` shorter than `n` → `GL_INVALID_VALUE`.
    pub fn gen_buffers(&mut self, n: GLsizei, buffers: &mut [GLuint]) {
        if self.reject_inside_begin_end() {
            return;
        }
        let Some(names) = usize::try_from(n).ok().and_then(|n| buffers.get_mut(..n)) else {
            return self.set_error(GL_INVALID_VALUE);
        };
        let table = &mut self.client.buffers;
        for name in names {
            table.max_name += 1;
            *name = table.max_name;
            table.objects.insert(*name, None);
        }
    }

    /// `glDeleteBuffers(n, buffers)`: deletes the first `n` names (0 and unknown names are
    /// ignored), unbinding and unmapping each as the module docs say. `n` < 0 or `buffers`
    /// shorter than `n` → `GL_INVALID_VALUE`.
    pub fn delete_buffers(&mut self, n: GLsizei, buffers: &[GLuint]) {
        if self.reject_inside_begin_end() {
            return;
        }
        let Some(names) = usize::try_from(n).ok().and_then(|n| buffers.get(..n)) else {
            return self.set_error(GL_INVALID_VALUE);
        };
        for name in names {
            if let Some(buffer) = self.client.buffers.objects.remove(name).flatten() {
                buffer.mapping.set(None);
                self.client.arrays.unbind_buffer(&buffer);
                let table = &mut self.client.buffers;
                for binding in [&mut table.pack, &mut table.unpack] {
                    if binding.as_ref().is_some_and(|b| Rc::ptr_eq(b, &buffer)) {
                        *binding = None;
                    }
                }
            }
        }
    }

    /// `glIsBuffer(buffer)`: whether `buffer` names a buffer object (one bound at least once).
    pub fn is_buffer(&mut self, buffer: GLuint) -> GLboolean {
        if self.reject_inside_begin_end() {
            return GL_FALSE;
        }
        GLboolean::from(matches!(self.client.buffers.objects.get(&buffer), Some(Some(_))))
    }

    /// `glBindBuffer(target, buffer)`: binds `buffer` (0: none) to `GL_ARRAY_BUFFER` or
    /// `GL_ELEMENT_ARRAY_BUFFER`, making the object on its first bind. Another target →
    /// `GL_INVALID_ENUM`.
    pub fn bind_buffer(&mut self, target: GLenum, buffer: GLuint) {
        if self.reject_inside_begin_end() {
            return;
        }
        if !known_target(target) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let object = (buffer != 0).then(|| {
            let table = &mut self.client.buffers;
            table.max_name = table.max_name.max(buffer);
            table.objects.entry(buffer).or_default().get_or_insert_with(|| Rc::new(BufferObject::new(buffer))).clone()
        });
        match target {
            GL_ARRAY_BUFFER => self.client.arrays.array_buffer = object,
            GL_PIXEL_PACK_BUFFER => self.client.buffers.pack = object,
            GL_PIXEL_UNPACK_BUFFER => self.client.buffers.unpack = object,
            _ => self.client.arrays.element_buffer = object,
        }
    }

    /// `glBufferData(target, size, data, usage)`: a new data store of `size` bytes, a copy of
    /// `data`'s first `size` bytes (`None`, C's NULL: zeros), for `usage`. Errors in Mesa's
    /// order (module docs); `data` shorter than `size` → `GL_INVALID_VALUE`; a size memory
    /// cannot hold → `GL_OUT_OF_MEMORY`. Not compiled into display lists (run at once).
    pub fn buffer_data<T: ArrayElement>(
        &mut self,
        target: GLenum,
        size: GLsizeiptr,
        data: Option<&[T]>,
        usage: GLenum,
    ) {
        let Some(buffer) = self.target_buffer(target) else { return };
        let Ok(size) = usize::try_from(size) else { return self.set_error(GL_INVALID_VALUE) };
        if !known_usage(usage) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let bytes = data.map(to_bytes);
        if bytes.as_ref().is_some_and(|b| b.len() < size) {
            return self.set_error(GL_INVALID_VALUE);
        }
        let Some(store) = zeroed(size) else { return self.set_error(GL_OUT_OF_MEMORY) };
        buffer.mapping.set(None);
        *buffer.store.borrow_mut() = store;
        buffer.usage.set(usage);
        if let Some(bytes) = bytes {
            buffer.write_bytes(0, &bytes[..size]);
        }
    }

    /// The sub-data calls' checks after the target's: the size, the offset, the range
    /// (`GL_INVALID_VALUE`), then the mapping (`GL_INVALID_OPERATION`); the byte range.
    fn buffer_range(
        &mut self,
        target: GLenum,
        offset: GLintptr,
        size: GLsizeiptr,
    ) -> Option<(Rc<BufferObject>, std::ops::Range<usize>)> {
        let buffer = self.target_buffer(target)?;
        let (Ok(size), Ok(offset)) = (usize::try_from(size), usize::try_from(offset)) else {
            self.set_error(GL_INVALID_VALUE);
            return None;
        };
        let Some(end) = offset.checked_add(size).filter(|&end| end <= buffer.len()) else {
            self.set_error(GL_INVALID_VALUE);
            return None;
        };
        if buffer.is_mapped() {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        Some((buffer, offset..end))
    }

    /// `glBufferSubData(target, offset, size, data)`: replaces bytes `offset .. offset + size`
    /// with `data`'s first `size` bytes. Errors in Mesa's order (module docs); `data` shorter
    /// than `size` → `GL_INVALID_VALUE`. Not compiled.
    pub fn buffer_sub_data<T: ArrayElement>(&mut self, target: GLenum, offset: GLintptr, size: GLsizeiptr, data: &[T]) {
        let Some((buffer, range)) = self.buffer_range(target, offset, size) else { return };
        let bytes = to_bytes(data);
        let Some(bytes) = bytes.get(..range.len()) else { return self.set_error(GL_INVALID_VALUE) };
        buffer.write_bytes(range.start, bytes);
    }

    /// `glGetBufferSubData(target, offset, size, data)`: bytes `offset .. offset + size` into
    /// `data` (values of any type, in native byte order; a last value partly written keeps its
    /// other bytes). Errors as [`Gl::buffer_sub_data`].
    pub fn get_buffer_sub_data<T: ArrayElement>(
        &mut self,
        target: GLenum,
        offset: GLintptr,
        size: GLsizeiptr,
        data: &mut [T],
    ) {
        let Some((buffer, range)) = self.buffer_range(target, offset, size) else { return };
        let mut bytes = to_bytes(data);
        let Some(out) = bytes.get_mut(..range.len()) else { return self.set_error(GL_INVALID_VALUE) };
        buffer.read(range.start, out);
        data.iter_mut().zip(bytes.chunks_exact(T::SIZE)).for_each(|(d, b)| *d = T::take(b));
    }

    /// `glMapBuffer(target, access)`: maps the data store for `GL_READ_ONLY`, `GL_WRITE_ONLY`
    /// or `GL_READ_WRITE`; `None` (C's NULL) on an error: another access (`GL_INVALID_ENUM`,
    /// checked first), the target's errors, a buffer mapped already or of no bytes
    /// (`GL_INVALID_OPERATION`). Not compiled.
    pub fn map_buffer(&mut self, target: GLenum, access: GLenum) -> Option<BufferMap> {
        if self.reject_inside_begin_end() {
            return None;
        }
        if !matches!(access, GL_READ_ONLY | GL_WRITE_ONLY | GL_READ_WRITE) {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        let buffer = self.target_buffer(target)?;
        if buffer.is_mapped() || buffer.is_empty() {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        let flags = match access {
            GL_READ_ONLY => GL_MAP_READ_BIT,
            GL_WRITE_ONLY => GL_MAP_WRITE_BIT,
            _ => GL_MAP_READ_BIT | GL_MAP_WRITE_BIT,
        };
        let length = buffer.len();
        Some(self.map(buffer, access, (0, length), flags))
    }

    /// Maps `range` (offset, length) of `buffer` with `access` and `flags`.
    fn map(&mut self, buffer: Rc<BufferObject>, access: GLenum, range: (usize, usize), flags: GLbitfield) -> BufferMap {
        self.client.buffers.mappings += 1;
        let id = self.client.buffers.mappings;
        buffer.mapping.set(Some(Mapping { access, id, offset: range.0, length: range.1, flags }));
        BufferMap { buffer, id }
    }

    /// `glMapBufferRange(target, offset, length, access)` (GL 3.0 §2.9.3,
    /// `GL_ARB_map_buffer_range`): maps bytes `offset .. offset + length` for the `access`
    /// bits (`GL_MAP_READ_BIT`, `GL_MAP_WRITE_BIT`, the invalidate, flush-explicit and
    /// unsynchronized bits, which change nothing here: the store is the client's own memory).
    /// `None` (C's NULL) on an error, in Mesa 22.3's order (measured,
    /// `capi/tests/pixel_buffers.c`): inside `begin`/`end` (`GL_INVALID_OPERATION`), the
    /// target's errors, a negative offset or length or an unknown bit (`GL_INVALID_VALUE`),
    /// neither read nor write, read with an invalidate or the unsynchronized bit, flush-explicit
    /// without write (`GL_INVALID_OPERATION`), a length of 0 or a mapped buffer
    /// (`GL_INVALID_OPERATION`), a range past the end (`GL_INVALID_VALUE`). Not compiled.
    pub fn map_buffer_range(
        &mut self,
        target: GLenum,
        offset: GLintptr,
        length: GLsizeiptr,
        access: GLbitfield,
    ) -> Option<BufferMap> {
        let buffer = self.target_buffer(target)?;
        let known = GL_MAP_READ_BIT
            | GL_MAP_WRITE_BIT
            | GL_MAP_INVALIDATE_RANGE_BIT
            | GL_MAP_INVALIDATE_BUFFER_BIT
            | GL_MAP_FLUSH_EXPLICIT_BIT
            | GL_MAP_UNSYNCHRONIZED_BIT;
        let (Ok(start), Ok(len)) = (usize::try_from(offset), usize::try_from(length)) else {
            self.set_error(GL_INVALID_VALUE);
            return None;
        };
        if access & !known != 0 {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let (read, write) = (access & GL_MAP_READ_BIT != 0, access & GL_MAP_WRITE_BIT != 0);
        let read_forbidden = GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT | GL_MAP_UNSYNCHRONIZED_BIT;
        let explicit_without_write = access & GL_MAP_FLUSH_EXPLICIT_BIT != 0 && !write;
        if !(read || write) || (read && access & read_forbidden != 0) || explicit_without_write {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        if len == 0 || buffer.is_mapped() {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        if start.checked_add(len).is_none_or(|end| end > buffer.len()) {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let mode = match (read, write) {
            (true, false) => GL_READ_ONLY,
            (false, true) => GL_WRITE_ONLY,
            _ => GL_READ_WRITE,
        };
        Some(self.map(buffer, mode, (start, len), access))
    }

    /// `glFlushMappedBufferRange(target, offset, length)` (GL 3.0): says bytes `offset ..
    /// offset + length` of the mapped range were written. Nothing needs doing (the store is
    /// the client's memory); the errors are Mesa's (measured): the target's, a negative offset
    /// or length or a range past the mapping (`GL_INVALID_VALUE`), a buffer not mapped or
    /// mapped without `GL_MAP_FLUSH_EXPLICIT_BIT` (`GL_INVALID_OPERATION`).
    pub fn flush_mapped_buffer_range(&mut self, target: GLenum, offset: GLintptr, length: GLsizeiptr) {
        let Some(buffer) = self.target_buffer(target) else { return };
        let (Ok(start), Ok(len)) = (usize::try_from(offset), usize::try_from(length)) else {
            return self.set_error(GL_INVALID_VALUE);
        };
        let Some(mapping) = buffer.mapping.get() else { return self.set_error(GL_INVALID_OPERATION) };
        if mapping.flags & GL_MAP_FLUSH_EXPLICIT_BIT == 0 {
            return self.set_error(GL_INVALID_OPERATION);
        }
        if start.checked_add(len).is_none_or(|end| end > mapping.length) {
            self.set_error(GL_INVALID_VALUE);
        }
    }

    /// `glUnmapBuffer(target)`: ends the mapping; `GL_TRUE` (the data store is intact), or
    /// `GL_FALSE` with the target's errors or when it is not mapped (`GL_INVALID_OPERATION`).
    pub fn unmap_buffer(&mut self, target: GLenum) -> GLboolean {
        let Some(buffer) = self.target_buffer(target) else { return GL_FALSE };
        if buffer.mapping.take().is_none() {
            self.set_error(GL_INVALID_OPERATION);
            return GL_FALSE;
        }
        GL_TRUE
    }

    /// `glGetBufferParameteriv(target, pname, params)`: `GL_BUFFER_SIZE`, `GL_BUFFER_USAGE`,
    /// `GL_BUFFER_ACCESS` or `GL_BUFFER_MAPPED` of the target's buffer into `params[0]`. The
    /// target's errors, then another name → `GL_INVALID_ENUM`; an empty `params` →
    /// `GL_INVALID_VALUE`.
    pub fn get_buffer_parameteriv(&mut self, target: GLenum, pname: GLenum, params: &mut [GLint]) {
        let Some(buffer) = self.target_buffer(target) else { return };
        let value = match pname {
            GL_BUFFER_SIZE => GLint::try_from(buffer.len()).unwrap_or(GLint::MAX),
            GL_BUFFER_USAGE => buffer.usage.get() as GLint,
            GL_BUFFER_ACCESS => buffer.mapping.get().map_or(GL_READ_WRITE, |m| m.access) as GLint,
            GL_BUFFER_MAPPED => GLint::from(buffer.is_mapped()),
            GL_BUFFER_ACCESS_FLAGS => buffer.mapping.get().map_or(0, |m| m.flags) as GLint,
            GL_BUFFER_MAP_OFFSET => buffer.mapping.get().map_or(0, |m| m.offset) as GLint,
            GL_BUFFER_MAP_LENGTH => buffer.mapping.get().map_or(0, |m| m.length) as GLint,
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        match params.first_mut() {
            Some(p) => *p = value,
            None => self.set_error(GL_INVALID_VALUE),
        }
    }

    /// `glGetBufferPointerv(target, pname, params)`: the target's mapping (`None`: not
    /// mapped) into `params[0]` for `GL_BUFFER_MAP_POINTER`. Errors as
    /// [`Gl::get_buffer_pointerv_error`] says (nothing is written then); an empty `params` →
    /// `GL_INVALID_VALUE`.
    pub fn get_buffer_pointerv(&mut self, target: GLenum, pname: GLenum, params: &mut [Option<BufferMap>]) {
        if let Some(error) = self.get_buffer_pointerv_error(target, pname) {
            return self.set_error(error);
        }
        let Some(buffer) = self.bound_buffer(target).cloned() else { return };
        let map = buffer.mapping.get().map(|m| BufferMap { buffer, id: m.id });
        match params.first_mut() {
            Some(p) => *p = map,
            None => self.set_error(GL_INVALID_VALUE),
        }
    }

    /// The error `glGetBufferPointerv(target, pname)` raises, in Mesa's order: inside
    /// `begin`/`end` (`GL_INVALID_OPERATION`), a name other than `GL_BUFFER_MAP_POINTER`
    /// (`GL_INVALID_ENUM`), then the target's errors; `None` when it writes its answer (what a
    /// binding writing the caller's pointer asks first).
    #[must_use]
    pub fn get_buffer_pointerv_error(&self, target: GLenum, pname: GLenum) -> Option<GLenum> {
        if self.inside_begin_end() {
            Some(GL_INVALID_OPERATION)
        } else if pname != GL_BUFFER_MAP_POINTER || !known_target(target) {
            Some(GL_INVALID_ENUM)
        } else if self.bound_buffer(target).is_none() {
            Some(GL_INVALID_OPERATION)
        } else {
            None
        }
    }

    /// The name bound to `GL_ELEMENT_ARRAY_BUFFER` (0: none): whether `glDrawElements`' index
    /// pointer is an offset into it (the C ABI asks).
    #[must_use]
    pub fn element_array_buffer_binding(&self) -> GLuint {
        self.client.arrays.element_buffer.as_ref().map_or(0, |b| b.name)
    }

    /// The name bound to `GL_ARRAY_BUFFER` (0: none).
    #[must_use]
    pub fn array_buffer_binding(&self) -> GLuint {
        self.client.arrays.array_buffer.as_ref().map_or(0, |b| b.name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_mapping_ends_with_unmap_data_and_delete() {
        let mut gl = Gl::new(4, 4);
        gl.bind_buffer(GL_ARRAY_BUFFER, 5);
        gl.buffer_data(GL_ARRAY_BUFFER, 4, Some(&[1u8, 2, 3, 4]), GL_STATIC_DRAW);
        let map = gl.map_buffer(GL_ARRAY_BUFFER, GL_READ_ONLY).unwrap();
        let mut out = [0u8; 4];
        assert!(map.read(0, &mut out) && out == [1, 2, 3, 4]);
        assert!(!map.write(0, &[9u8]), "read only");
        gl.buffer_data(GL_ARRAY_BUFFER, 2, None::<&[u8]>, GL_STATIC_DRAW);
        assert!(!map.is_mapped());
        let map = gl.map_buffer(GL_ARRAY_BUFFER, GL_READ_WRITE).unwrap();
        assert!(!map.write(1, &[1u16]), "past the end");
        gl.delete_buffers(1, &[5]);
        assert!(!map.is_mapped());
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        assert_eq!(gl.array_buffer_binding(), 0);
    }

    #[test]
    fn sizes_memory_cannot_hold_are_out_of_memory() {
        let mut gl = Gl::new(4, 4);
        gl.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, 1);
        gl.buffer_data(GL_ELEMENT_ARRAY_BUFFER, isize::MAX, None::<&[u8]>, GL_STATIC_DRAW);
        assert_eq!(gl.get_error(), GL_OUT_OF_MEMORY);
        gl.buffer_data(GL_ELEMENT_ARRAY_BUFFER, 8, Some(&[0u8; 4]), GL_STATIC_DRAW);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.get_buffer_sub_data(GL_ELEMENT_ARRAY_BUFFER, 0, 0, &mut [0u8; 0]);
        gl.get_buffer_sub_data(GL_ELEMENT_ARRAY_BUFFER, isize::MAX, isize::MAX, &mut [0u8; 0]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    }
}
