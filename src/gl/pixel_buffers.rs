//! GL 2.1's pixel buffer objects (GL 2.1 §3.7.4, §4.3.2, §6.1.13; `GL_ARB_pixel_buffer_object`;
//! Mesa `main/pbo.c`): while a buffer is bound to `GL_PIXEL_UNPACK_BUFFER`, a call that reads
//! an image (`glTexImage`, `glDrawPixels`, `glBitmap`, `glPolygonStipple`, `glPixelMap`...)
//! reads it from that buffer, its pointer argument an offset; while one is bound to
//! `GL_PIXEL_PACK_BUFFER`, a call that writes one (`glReadPixels`, `glGetTexImage`...) writes
//! it there. A range outside the buffer, or a mapped buffer, is `GL_INVALID_OPERATION` and the
//! call does nothing (Mesa's `_mesa_validate_pbo_access`, measured:
//! `capi/tests/pixel_buffers.c`).
//!
//! The calls themselves take the image as bytes: the C ABI asks here for the buffer's bytes
//! (or a place to write them) where it would take the client's memory.

use super::consts::*;
use super::types::*;
use super::Gl;

impl Gl {
    /// The name bound to `GL_PIXEL_PACK_BUFFER` (0: none).
    #[must_use]
    pub fn pixel_pack_buffer_binding(&self) -> GLuint {
        self.client.buffers.pack.as_ref().map_or(0, |b| b.name())
    }

    /// The name bound to `GL_PIXEL_UNPACK_BUFFER` (0: none).
    #[must_use]
    pub fn pixel_unpack_buffer_binding(&self) -> GLuint {
        self.client.buffers.unpack.as_ref().map_or(0, |b| b.name())
    }

    /// `glPushClientAttrib`'s part: the two bindings, when the pixel-store group is saved.
    pub(super) fn push_pixel_buffers(&mut self, save: bool) {
        let table = &mut self.client.buffers;
        let entry = save.then(|| (table.pack.clone(), table.unpack.clone()));
        table.saved_pixel_buffers.push(entry);
    }

    /// `glPopClientAttrib`'s part: the bindings the matching push saved, if it saved them.
    pub(super) fn pop_pixel_buffers(&mut self) {
        let table = &mut self.client.buffers;
        if let Some(Some((pack, unpack))) = table.saved_pixel_buffers.pop() {
            (table.pack, table.unpack) = (pack, unpack);
        }
    }

    /// The `len` bytes from `offset` of the buffer bound to `GL_PIXEL_UNPACK_BUFFER`, what an
    /// unpacking call reads; `None` with `GL_INVALID_OPERATION` when the range is outside the
    /// buffer or the buffer is mapped, or with no buffer bound (no error: the caller reads the
    /// client's memory then).
    pub fn read_unpack_buffer(&mut self, offset: usize, len: usize) -> Option<Vec<u8>> {
        let buffer = self.client.buffers.unpack.clone()?;
        let mut bytes = vec![0u8; len];
        let inside = offset.checked_add(len).is_some_and(|end| end <= buffer.len());
        if buffer.is_mapped() || !inside {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        super::client_memory::ClientMemory::read(&*buffer, offset, &mut bytes);
        Some(bytes)
    }

    /// Runs `write` on bytes `offset .. offset + len` of the buffer bound to
    /// `GL_PIXEL_PACK_BUFFER` (as the buffer holds them: what the call leaves unwritten stays),
    /// then stores them back. With no buffer bound, nothing runs and the answer is false (the
    /// caller writes the client's memory then); a range outside the buffer or a mapped buffer
    /// is `GL_INVALID_OPERATION` and nothing runs (true: handled).
    pub fn write_pack_buffer(&mut self, offset: usize, len: usize, write: impl FnOnce(&mut Gl, &mut [u8])) -> bool {
        let Some(buffer) = self.client.buffers.pack.clone() else { return false };
        let inside = offset.checked_add(len).is_some_and(|end| end <= buffer.len());
        if buffer.is_mapped() || !inside {
            self.set_error(GL_INVALID_OPERATION);
            return true;
        }
        let mut bytes = vec![0u8; len];
        super::client_memory::ClientMemory::read(&*buffer, offset, &mut bytes);
        write(self, &mut bytes);
        buffer.store_bytes(offset, &bytes);
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unpack_reads_the_buffer_and_rejects_ranges_outside_it() {
        let mut gl = Gl::new(2, 2);
        assert_eq!(gl.read_unpack_buffer(0, 4), None);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        gl.bind_buffer(GL_PIXEL_UNPACK_BUFFER, 3);
        gl.buffer_data(GL_PIXEL_UNPACK_BUFFER, 6, Some(&[1u8, 2, 3, 4, 5, 6]), GL_STATIC_DRAW);
        assert_eq!(gl.pixel_unpack_buffer_binding(), 3);
        assert_eq!(gl.read_unpack_buffer(2, 4), Some(vec![3, 4, 5, 6]));
        assert_eq!(gl.read_unpack_buffer(3, 4), None);
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        let _map = gl.map_buffer(GL_PIXEL_UNPACK_BUFFER, GL_READ_ONLY);
        assert_eq!(gl.read_unpack_buffer(0, 1), None);
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    }

    #[test]
    fn pack_writes_into_the_buffer_keeping_what_is_not_written() {
        let mut gl = Gl::new(2, 2);
        assert!(!gl.write_pack_buffer(0, 2, |_, _| panic!("no buffer bound")));
        gl.bind_buffer(GL_PIXEL_PACK_BUFFER, 4);
        gl.buffer_data(GL_PIXEL_PACK_BUFFER, 4, Some(&[9u8, 9, 9, 9]), GL_STREAM_READ);
        assert!(gl.write_pack_buffer(1, 2, |_, out| out[0] = 7));
        let mut back = [0u8; 4];
        gl.get_buffer_sub_data(GL_PIXEL_PACK_BUFFER, 0, 4, &mut back);
        assert_eq!(back, [9, 7, 9, 9]);
        assert!(gl.write_pack_buffer(3, 2, |_, _| panic!("out of range")));
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.delete_buffers(1, &[4]);
        assert_eq!(gl.pixel_pack_buffer_binding(), 0);
    }

    #[test]
    fn map_buffer_range_maps_a_range_in_mesas_error_order() {
        let mut gl = Gl::new(2, 2);
        gl.bind_buffer(GL_PIXEL_PACK_BUFFER, 1);
        gl.buffer_data(GL_PIXEL_PACK_BUFFER, 8, Some(&[0u8, 1, 2, 3, 4, 5, 6, 7]), GL_STREAM_READ);
        // Mesa's answers (capi/tests/pixel_buffers.c).
        for (offset, length, access, error) in [
            (-1, 4, 0, GL_INVALID_VALUE),
            (0, 4, 0x1000 | GL_MAP_READ_BIT, GL_INVALID_VALUE),
            (0, 4, 0, GL_INVALID_OPERATION),
            (0, 4, GL_MAP_READ_BIT | GL_MAP_INVALIDATE_RANGE_BIT, GL_INVALID_OPERATION),
            (0, 4, GL_MAP_READ_BIT | GL_MAP_FLUSH_EXPLICIT_BIT, GL_INVALID_OPERATION),
            (0, 0, GL_MAP_READ_BIT, GL_INVALID_OPERATION),
            (6, 4, 0, GL_INVALID_OPERATION),
            (6, 4, GL_MAP_READ_BIT, GL_INVALID_VALUE),
        ] {
            assert!(gl.map_buffer_range(GL_PIXEL_PACK_BUFFER, offset, length, access).is_none());
            assert_eq!(gl.get_error(), error, "{offset} {length} {access:#x}");
        }
        let map = gl.map_buffer_range(GL_PIXEL_PACK_BUFFER, 2, 4, GL_MAP_READ_BIT).unwrap();
        let mut out = [0u8; 4];
        assert!(map.read(0, &mut out) && out == [2, 3, 4, 5]);
        assert!(!map.read(1, &mut out), "past the mapped range");
        let mut p = [0; 1];
        gl.get_buffer_parameteriv(GL_PIXEL_PACK_BUFFER, GL_BUFFER_MAP_OFFSET, &mut p);
        assert_eq!(p, [2]);
        gl.get_buffer_parameteriv(GL_PIXEL_PACK_BUFFER, GL_BUFFER_ACCESS, &mut p);
        assert_eq!(p, [GL_READ_ONLY as GLint]);
        gl.flush_mapped_buffer_range(GL_PIXEL_PACK_BUFFER, 0, 2);
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION, "mapped without the flush-explicit bit");
    }
}
