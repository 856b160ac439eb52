//! Pixel storage modes (`glPixelStore`, GL 1.1 spec §3.6.1 and table 3.1; Mesa `main/pixelstore.c`):
//! how images, bitmaps and textures are laid out in client memory, and the addressing they
//! imply (row length, skipped rows and pixels, row alignment).

use super::consts::*;
use super::state_var::{int_limit, put_flag, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// One direction's storage modes (unpack: memory → GL; pack: GL → memory).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct PixelStore {
    pub swap_bytes: bool,
    pub lsb_first: bool,
    /// Pixels per row in memory; 0 means the image's own width.
    pub row_length: usize,
    pub skip_rows: usize,
    pub skip_pixels: usize,
    /// Rows start at multiples of this many bytes: 1, 2, 4 (GL's initial value) or 8.
    pub alignment: usize,
    /// GL 1.2's rows per image of a 3D texture in memory; 0 means the image's own height.
    pub image_height: usize,
    /// GL 1.2's images of a 3D texture skipped before the first.
    pub skip_images: usize,
}

impl Default for PixelStore {
    fn default() -> Self {
        Self {
            swap_bytes: false,
            lsb_first: false,
            row_length: 0,
            skip_rows: 0,
            skip_pixels: 0,
            alignment: 4,
            image_height: 0,
            skip_images: 0,
        }
    }
}

impl PixelStore {
    /// Bytes from one row's start to the next for rows of `width` pixels of `components`
    /// elements of `element` bytes (GL 1.1 eq. 3.1: `k = n·l` elements when `element` ≥ the
    /// alignment `a`, else `a/s · ⌈s·n·l / a⌉`).
    #[must_use]
    pub fn row_stride(&self, width: usize, components: usize, element: usize) -> usize {
        let pixels = if self.row_length > 0 { self.row_length } else { width };
        let bytes = pixels * components * element;
        if element >= self.alignment {
            bytes
        } else {
            bytes.div_ceil(self.alignment) * self.alignment
        }
    }

    /// Bytes from one bitmap row's start to the next (one bit a pixel, GL 1.1 §3.6.4).
    #[must_use]
    pub fn bitmap_row_stride(&self, width: usize) -> usize {
        let pixels = if self.row_length > 0 { self.row_length } else { width };
        pixels.div_ceil(8).div_ceil(self.alignment) * self.alignment
    }

    /// The byte offset of the first pixel read: skipped rows and pixels.
    #[must_use]
    pub fn first_byte(&self, row_stride: usize, size: usize) -> usize {
        self.skip_rows * row_stride + self.skip_pixels * size
    }

    /// Bytes from one image of a 3D texture to the next, for images `height` rows tall of
    /// rows `row_stride` bytes apart (GL 1.2 §3.8.1: `GL_UNPACK_IMAGE_HEIGHT` rows, or the
    /// image's own height when it is 0).
    #[must_use]
    pub fn image_stride(&self, row_stride: usize, height: usize) -> usize {
        row_stride * if self.image_height > 0 { self.image_height } else { height }
    }
}

/// Mesa's `MAX_CLIENT_ATTRIB_STACK_DEPTH` (`main/config.h`).
pub(crate) const MAX_CLIENT_ATTRIB_STACK_DEPTH: usize = 16;

/// The client's pixel storage state, and `glPushClientAttrib`'s stack (the pixel-store group
/// is the only client group kept: gleval has no vertex arrays).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct PixelStores {
    pub unpack: PixelStore,
    pub pack: PixelStore,
    /// One entry per push: the unpack and pack modes when `GL_CLIENT_PIXEL_STORE_BIT` was set.
    saved: Vec<Option<(PixelStore, PixelStore)>>,
}

impl Gl {
    /// `glPixelStorei`. An unknown name → `GL_INVALID_ENUM`; a negative length or skip, or an
    /// alignment other than 1, 2, 4 or 8 → `GL_INVALID_VALUE` (Mesa's checks). Not compiled
    /// into display lists (GL 1.1 §5.4): it runs at once.
    pub fn pixel_storei(&mut self, pname: GLenum, param: GLint) {
        if self.reject_inside_begin_end() {
            return;
        }
        // Fields 0..=5 are GL 1.1's six in its order, 6 and 7 GL 1.2's skipped images and
        // image height.
        let (store, field) = match pname {
            GL_UNPACK_SWAP_BYTES..=GL_UNPACK_ALIGNMENT => {
                (&mut self.client.pixel_stores.unpack, pname - GL_UNPACK_SWAP_BYTES)
            }
            GL_PACK_SWAP_BYTES..=GL_PACK_ALIGNMENT => (&mut self.client.pixel_stores.pack, pname - GL_PACK_SWAP_BYTES),
            GL_UNPACK_SKIP_IMAGES | GL_UNPACK_IMAGE_HEIGHT => {
                (&mut self.client.pixel_stores.unpack, 6 + pname - GL_UNPACK_SKIP_IMAGES)
            }
            GL_PACK_SKIP_IMAGES | GL_PACK_IMAGE_HEIGHT => {
                (&mut self.client.pixel_stores.pack, 6 + pname - GL_PACK_SKIP_IMAGES)
            }
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        let count = usize::try_from(param).ok();
        let value_ok = match field {
            0 | 1 => true,
            5 => matches!(param, 1 | 2 | 4 | 8),
            _ => count.is_some(),
        };
        if !value_ok {
            return self.set_error(GL_INVALID_VALUE);
        }
        let count = count.unwrap_or(0);
        match field {
            0 => store.swap_bytes = param != 0,
            1 => store.lsb_first = param != 0,
            2 => store.row_length = count,
            3 => store.skip_rows = count,
            4 => store.skip_pixels = count,
            5 => store.alignment = count,
            6 => store.skip_images = count,
            _ => store.image_height = count,
        }
    }

    /// `glPixelStoref`: as [`Gl::pixel_storei`] with the value rounded to the nearest integer
    /// (booleans: non-zero is true), as Mesa converts it.
    pub fn pixel_storef(&mut self, pname: GLenum, param: GLfloat) {
        let boolean =
            matches!(pname, GL_UNPACK_SWAP_BYTES | GL_UNPACK_LSB_FIRST | GL_PACK_SWAP_BYTES | GL_PACK_LSB_FIRST);
        let value = if boolean { GLint::from(param != 0.0) } else { param.round() as GLint };
        self.pixel_storei(pname, value);
    }

    /// `GL_CLIENT_ATTRIB_STACK_DEPTH`.
    pub(crate) fn client_attrib_stack_depth(&self) -> usize {
        self.client.pixel_stores.saved.len()
    }

    /// `glPushClientAttrib(mask)`: saves the pixel-store modes when `mask` has
    /// `GL_CLIENT_PIXEL_STORE_BIT` (other bits are accepted and save nothing). A full stack →
    /// `GL_STACK_OVERFLOW`. Not compiled into display lists.
    pub fn push_client_attrib(&mut self, mask: GLbitfield) {
        if self.reject_inside_begin_end() {
            return;
        }
        let stores = &mut self.client.pixel_stores;
        if stores.saved.len() >= MAX_CLIENT_ATTRIB_STACK_DEPTH {
            return self.set_error(GL_STACK_OVERFLOW);
        }
        let entry = (mask & GL_CLIENT_PIXEL_STORE_BIT != 0).then_some((stores.unpack, stores.pack));
        stores.saved.push(entry);
        self.push_pixel_buffers(mask & GL_CLIENT_PIXEL_STORE_BIT != 0);
        self.push_client_arrays(mask);
    }

    /// `glPopClientAttrib`: restores what the matching push saved. An empty stack →
    /// `GL_STACK_UNDERFLOW`.
    pub fn pop_client_attrib(&mut self) {
        if self.reject_inside_begin_end() {
            return;
        }
        let popped = self.client.pixel_stores.saved.pop();
        if popped.is_some() {
            self.pop_pixel_buffers();
            self.pop_client_arrays();
        }
        match popped {
            None => self.set_error(GL_STACK_UNDERFLOW),
            Some(Some((unpack, pack))) => {
                (self.client.pixel_stores.unpack, self.client.pixel_stores.pack) = (unpack, pack)
            }
            Some(None) => {}
        }
    }

    /// The unpack modes images, bitmaps and textures are read with.
    pub(crate) fn unpack_store(&self) -> PixelStore {
        self.client.pixel_stores.unpack
    }

    /// The pack modes images are written with (GLU's `gluScaleImage` writes with them too).
    pub(crate) fn pack_store(&self) -> PixelStore {
        self.client.pixel_stores.pack
    }

    /// `glGetIntegerv(GL_UNPACK_ALIGNMENT)`, which GLU saves around its own unpacking.
    pub(crate) fn unpack_alignment(&self) -> GLint {
        self.client.pixel_stores.unpack.alignment as GLint
    }
}

impl Gl {
    /// Runs `f` with `store` as the unpack modes, then restores the client's (a display list
    /// replays an image with the modes it was compiled with).
    pub(crate) fn with_unpack_store(&mut self, store: PixelStore, f: impl FnOnce(&mut Gl)) {
        let saved = std::mem::replace(&mut self.client.pixel_stores.unpack, store);
        f(self);
        self.client.pixel_stores.unpack = saved;
    }
}

/// The pixel store's `glGet` rows (GL 1.1 table 6.14 and GL 1.2's two for images), the same
/// eight for each direction.
macro_rules! pixel_store_rows {
    ($($dir:ident: $swap:ident $lsb:ident $length:ident $rows:ident $pixels:ident $alignment:ident
        $images:ident $image_height:ident;)*) => {
        pub(crate) static GET_ROWS: &[StateVar] = &[$(
            row($swap, 1, Kind::Bool, |gl, o| put_flag(o, gl.client.pixel_stores.$dir.swap_bytes)),
            row($lsb, 1, Kind::Bool, |gl, o| put_flag(o, gl.client.pixel_stores.$dir.lsb_first)),
            row($length, 1, Kind::Int, |gl, o| o[0] = gl.client.pixel_stores.$dir.row_length as f64),
            row($rows, 1, Kind::Int, |gl, o| o[0] = gl.client.pixel_stores.$dir.skip_rows as f64),
            row($pixels, 1, Kind::Int, |gl, o| o[0] = gl.client.pixel_stores.$dir.skip_pixels as f64),
            row($alignment, 1, Kind::Int, |gl, o| o[0] = gl.client.pixel_stores.$dir.alignment as f64),
            row($images, 1, Kind::Int, |gl, o| o[0] = gl.client.pixel_stores.$dir.skip_images as f64),
            row($image_height, 1, Kind::Int, |gl, o| o[0] = gl.client.pixel_stores.$dir.image_height as f64),
        )*];
    };
}

pixel_store_rows! {
    unpack: GL_UNPACK_SWAP_BYTES GL_UNPACK_LSB_FIRST GL_UNPACK_ROW_LENGTH GL_UNPACK_SKIP_ROWS GL_UNPACK_SKIP_PIXELS GL_UNPACK_ALIGNMENT
        GL_UNPACK_SKIP_IMAGES GL_UNPACK_IMAGE_HEIGHT;
    pack: GL_PACK_SWAP_BYTES GL_PACK_LSB_FIRST GL_PACK_ROW_LENGTH GL_PACK_SKIP_ROWS GL_PACK_SKIP_PIXELS GL_PACK_ALIGNMENT
        GL_PACK_SKIP_IMAGES GL_PACK_IMAGE_HEIGHT;
}

/// The client attribute stack's `glGet` rows.
pub(crate) static CLIENT_ATTRIB_ROWS: &[StateVar] = &[
    int_limit!(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, MAX_CLIENT_ATTRIB_STACK_DEPTH),
    row(GL_CLIENT_ATTRIB_STACK_DEPTH, 1, Kind::Int, |gl, o| o[0] = gl.client_attrib_stack_depth() as f64),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_are_aligned_as_gl_says() {
        let four = PixelStore::default();
        assert_eq!(four.row_stride(3, 3, 1), 12); // 9 bytes of RGB, padded to 4
        assert_eq!(four.row_stride(3, 4, 1), 12);
        assert_eq!(four.row_stride(3, 3, 4), 36); // floats are aligned already
        let two = PixelStore { alignment: 2, ..four };
        assert_eq!(two.row_stride(3, 3, 1), 10);
        let eight = PixelStore { alignment: 8, ..four };
        assert_eq!(eight.row_stride(3, 3, 4), 40);
        assert_eq!(four.bitmap_row_stride(9), 4); // 2 bytes, padded to 4
        let one = PixelStore { alignment: 1, ..four };
        assert_eq!(one.row_stride(3, 3, 1), 9);
        assert_eq!(one.bitmap_row_stride(9), 2);
        let long = PixelStore { row_length: 10, skip_rows: 2, skip_pixels: 1, ..one };
        assert_eq!(long.row_stride(3, 3, 1), 30);
        assert_eq!(long.first_byte(30, 3), 63);
    }

    #[test]
    fn client_attrib_saves_and_restores_the_pixel_stores() {
        let mut gl = Gl::new(4, 4);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 2);
        gl.push_client_attrib(GL_CLIENT_PIXEL_STORE_BIT);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        gl.pixel_storei(GL_PACK_LSB_FIRST, 1);
        gl.push_client_attrib(GL_CLIENT_VERTEX_ARRAY_BIT);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 8);
        gl.pop_client_attrib();
        assert_eq!(gl.unpack_store().alignment, 8, "the vertex-array group does not hold the pixel stores");
        gl.pop_client_attrib();
        assert_eq!(gl.unpack_store().alignment, 2);
        assert!(!gl.client.pixel_stores.pack.lsb_first);
        gl.pop_client_attrib();
        assert_eq!(gl.get_error(), GL_STACK_UNDERFLOW);
        for _ in 0..=MAX_CLIENT_ATTRIB_STACK_DEPTH {
            gl.push_client_attrib(GL_CLIENT_ALL_ATTRIB_BITS);
        }
        assert_eq!(gl.get_error(), GL_STACK_OVERFLOW);
    }

    #[test]
    fn pixel_store_errors() {
        let mut gl = Gl::new(4, 4);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 3);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.pixel_storei(GL_UNPACK_ROW_LENGTH, -1);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.pixel_storei(0x1234, 1);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        gl.pixel_storef(GL_PACK_ALIGNMENT, 8.0);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        assert_eq!(gl.unpack_store().alignment, 1);
        assert_eq!(gl.client.pixel_stores.pack.alignment, 8);
    }

    #[test]
    fn each_store_reads_back_through_its_own_row() {
        let mut gl = Gl::new(4, 4);
        let names = [
            GL_UNPACK_SWAP_BYTES,
            GL_UNPACK_LSB_FIRST,
            GL_UNPACK_ROW_LENGTH,
            GL_UNPACK_SKIP_ROWS,
            GL_UNPACK_SKIP_PIXELS,
            GL_UNPACK_ALIGNMENT,
            GL_PACK_SWAP_BYTES,
            GL_PACK_LSB_FIRST,
            GL_PACK_ROW_LENGTH,
            GL_PACK_SKIP_ROWS,
            GL_PACK_SKIP_PIXELS,
            GL_PACK_ALIGNMENT,
        ];
        // Flags true; the others distinct (alignments 2 and 8 of the allowed 1, 2, 4, 8).
        let values = [1, 1, 3, 4, 5, 2, 1, 1, 6, 7, 9, 8];
        for (&name, &value) in names.iter().zip(&values) {
            gl.pixel_storei(name, value);
        }
        let read: Vec<GLint> = names
            .iter()
            .map(|&name| {
                let mut v = [0];
                gl.get_integerv(name, &mut v);
                v[0]
            })
            .collect();
        assert_eq!((read, gl.get_error()), (values.to_vec(), GL_NO_ERROR));
    }
}
