//! Vertex arrays (GL 1.1 §2.8; Mesa 22.3 `main/varray.c`, `vbo/vbo_save_api.c`): the six
//! pointers, `glEnableClientState`, `glArrayElement`, `glDrawArrays`, `glDrawElements`,
//! `glInterleavedArrays`, `glGetPointerv`, and the vertex-array group of the client attribute
//! stack.
//!
//! GL reads the arrays when it draws: the pointers keep a [`ClientPointer`] (shared client
//! memory, see [`super::client_memory`]), and each draw call copies the elements it needs.
//! `glArrayElement(i)` is the immediate-mode calls of element `i` (edge flag, texture
//! coordinate, colour, normal, vertex, in the spec's order); `glDrawArrays` and
//! `glDrawElements` are `glBegin`, those elements and `glEnd`. So a display list compiles them
//! as the vertices they read (§5.4), through the gates of the calls they make; the pointer,
//! client-state and `glInterleavedArrays` calls are not compiled, they run at once.
//!
//! Mesa's rules, measured (`tests/reference/calls/cases/arrays.calls`):
//! - a pointer call checks the stride (negative: `GL_INVALID_VALUE`, but the call goes on and
//!   stores it), then the type (`GL_INVALID_ENUM`), then the size (`GL_INVALID_VALUE`);
//! - `glDrawArrays` checks the count, then the mode; `glDrawElements` the count, the mode, the
//!   type. In a list these errors are compiled and raised when the list runs;
//! - `glDrawArrays` leaves the current colour, normal, texture coordinate and edge flag as
//!   they were (Mesa's vbo draws without touching them); `glArrayElement` sets them;
//! - without the vertex array, `glDrawArrays` and `glDrawElements` draw each element at
//!   (0, 0, 0, 1) (Mesa's current position), while `glArrayElement` issues no vertex;
//! - colour components of a signed type become c / (2ᵇ⁻¹ − 1) (Mesa's vertex fetch), normal
//!   components (2c + 1) / (2ᵇ − 1), as the immediate calls convert them.
//!
//! One difference: where an element lies outside the memory the array was given (a Rust
//! array too short, a negative first index or stride, a NULL pointer), gleval sets
//! `GL_INVALID_VALUE` and draws nothing, where Mesa reads whatever lies there.
//!
//! GL 1.5's buffer objects (`buffers.rs`): a pointer call made while a buffer is bound to
//! `GL_ARRAY_BUFFER` takes its pointer as an offset into that buffer ([`BufferOffset`] in Rust)
//! and keeps the buffer, whatever is bound later (GL 1.5 §2.9.1); an element outside a buffer
//! is zeros in the array's components, as llvmpipe reads it, not an error. The element draws'
//! `_offset` forms take their indices from the buffer bound to `GL_ELEMENT_ARRAY_BUFFER`.

use super::buffers::BufferObject;
use super::client_memory::{to_bytes, ArrayElement, ClientMemory, ClientPointer};
use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{put_flag, row, Kind, StateVar};
use super::types::*;
use super::units::MAX_TEXTURE_UNITS;
use super::variants::GlComponent;
use super::Gl;
use std::any::Any;
use std::rc::Rc;

/// How many arrays there are.
const ARRAYS: usize = 8;

/// Which array, as an index into [`VertexArrays::arrays`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Which {
    Vertex,
    Normal,
    Color,
    Index,
    TexCoord,
    EdgeFlag,
    /// GL 1.4's secondary colour (`GL_EXT_secondary_color`).
    SecondaryColor,
    /// GL 1.4's fog coordinate (`GL_EXT_fog_coord`).
    FogCoord,
}

impl Which {
    const ALL: [Which; ARRAYS] = [
        Which::Vertex,
        Which::Normal,
        Which::Color,
        Which::Index,
        Which::TexCoord,
        Which::EdgeFlag,
        Which::SecondaryColor,
        Which::FogCoord,
    ];

    fn of_capability(cap: GLenum) -> Option<Which> {
        Self::ALL.into_iter().find(|w| w.capability() == cap)
    }

    fn capability(self) -> GLenum {
        match self {
            Which::Vertex => GL_VERTEX_ARRAY,
            Which::Normal => GL_NORMAL_ARRAY,
            Which::Color => GL_COLOR_ARRAY,
            Which::Index => GL_INDEX_ARRAY,
            Which::TexCoord => GL_TEXTURE_COORD_ARRAY,
            Which::EdgeFlag => GL_EDGE_FLAG_ARRAY,
            Which::SecondaryColor => GL_SECONDARY_COLOR_ARRAY,
            Which::FogCoord => GL_FOG_COORD_ARRAY,
        }
    }

    fn pointer_name(self) -> GLenum {
        match self {
            Which::Vertex => GL_VERTEX_ARRAY_POINTER,
            Which::Normal => GL_NORMAL_ARRAY_POINTER,
            Which::Color => GL_COLOR_ARRAY_POINTER,
            Which::Index => GL_INDEX_ARRAY_POINTER,
            Which::TexCoord => GL_TEXTURE_COORD_ARRAY_POINTER,
            Which::EdgeFlag => GL_EDGE_FLAG_ARRAY_POINTER,
            Which::SecondaryColor => GL_SECONDARY_COLOR_ARRAY_POINTER,
            Which::FogCoord => GL_FOG_COORD_ARRAY_POINTER,
        }
    }

    /// The types GL 1.1 (and Mesa's compatibility profile) accepts for the array.
    fn accepts_type(self, type_: GLenum) -> bool {
        let types: &[GLenum] = match self {
            Which::Vertex | Which::TexCoord => &[GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE],
            Which::Normal => &[GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE],
            Which::Color | Which::SecondaryColor => {
                &[GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE]
            }
            Which::Index => &[GL_UNSIGNED_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE],
            Which::EdgeFlag => &[GL_UNSIGNED_BYTE],
            Which::FogCoord => &[GL_FLOAT, GL_DOUBLE],
        };
        types.contains(&type_)
    }

    /// The component counts the array accepts.
    fn accepts_size(self, size: GLint) -> bool {
        match self {
            Which::Vertex => (2..=4).contains(&size),
            Which::TexCoord => (1..=4).contains(&size),
            // Mesa takes 4 for the secondary colour too (measured on Mesa 22.3).
            Which::Color | Which::SecondaryColor => (3..=4).contains(&size),
            Which::Normal => size == 3,
            Which::Index | Which::EdgeFlag | Which::FogCoord => size == 1,
        }
    }
}

/// One array's state (GL 1.1 table 6.6).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ArrayState {
    enabled: bool,
    size: GLint,
    type_: GLenum,
    stride: GLsizei,
    pointer: Option<ClientPointer>,
    /// The buffer object the pointer is an offset into (GL 1.5 §2.9.1), `None` for client
    /// memory: what `GL_*_ARRAY_BUFFER_BINDING` answers.
    buffer: Option<Rc<BufferObject>>,
}

impl ArrayState {
    fn new(size: GLint, type_: GLenum) -> Self {
        Self { enabled: false, size, type_, stride: 0, pointer: None, buffer: None }
    }

    /// The array's buffer's name, 0 for client memory.
    fn buffer_name(&self) -> GLuint {
        self.buffer.as_ref().map_or(0, |b| b.name())
    }

    /// Bytes of one element.
    fn element_size(&self) -> usize {
        type_size(self.type_) * self.size.max(0) as usize
    }

    /// Bytes from one element to the next (the element size for stride 0).
    fn step(&self) -> isize {
        if self.stride == 0 {
            self.element_size() as isize
        } else {
            self.stride as isize
        }
    }

    /// The components of element `i`, converted by `convert`; `None` when they cannot be read.
    fn fetch(&self, i: i64, convert: fn(GLenum, &[u8]) -> f32) -> Option<[f32; 4]> {
        let pointer = self.pointer.as_ref()?;
        let size = type_size(self.type_);
        let mut bytes = [0u8; 32];
        let element = &mut bytes[..self.element_size()];
        let offset = isize::try_from(i).ok().and_then(|i| i.checked_mul(self.step()));
        let mut out = [0.0, 0.0, 0.0, 1.0];
        if !offset.is_some_and(|offset| pointer.read(offset, element)) {
            // A buffer's element outside it is zeros in every component the array has, GL's
            // defaults in the others (measured on llvmpipe: `buffer_objects.calls`).
            let size = usize::try_from(self.size).unwrap_or(0).min(4);
            out[..size].fill(0.0);
            return pointer.memory().bounded().then_some(out);
        }
        for (o, chunk) in out.iter_mut().zip(element.chunks_exact(size)) {
            *o = convert(self.type_, chunk);
        }
        Some(out)
    }
}

/// `sizeof` a GL data type (1 for a type GL does not know, which no array holds).
fn type_size(type_: GLenum) -> usize {
    match type_ {
        GL_SHORT | GL_UNSIGNED_SHORT => 2,
        GL_INT | GL_UNSIGNED_INT | GL_FLOAT => 4,
        GL_DOUBLE => 8,
        _ => 1,
    }
}

/// The index an element buffer's index past its end gives: the draw module's
/// `DRAW_MAX_FETCH_IDX`, a vertex outside every buffer.
const OUTSIDE_INDEX: i64 = u32::MAX as i64;

/// An index of `type_` (`GL_UNSIGNED_BYTE`, `_SHORT` or `_INT`) from its bytes.
fn index_value(type_: GLenum, b: &[u8]) -> i64 {
    match type_ {
        GL_UNSIGNED_BYTE => i64::from(b[0]),
        GL_UNSIGNED_SHORT => i64::from(u16::take(b)),
        _ => i64::from(u32::take(b)),
    }
}

/// A component read as it is (positions, texture coordinates, indices).
fn plain(type_: GLenum, b: &[u8]) -> f32 {
    match type_ {
        GL_BYTE => f32::from(i8::take(b)),
        GL_UNSIGNED_BYTE => f32::from(u8::take(b)),
        GL_SHORT => f32::from(i16::take(b)),
        GL_UNSIGNED_SHORT => f32::from(u16::take(b)),
        GL_INT => i32::take(b) as f32,
        GL_UNSIGNED_INT => u32::take(b) as f32,
        GL_DOUBLE => f64::take(b) as f32,
        _ => f32::take(b),
    }
}

/// A normal component: integers as the immediate `glNormal3*` forms convert them.
fn normal(type_: GLenum, b: &[u8]) -> f32 {
    match type_ {
        GL_BYTE => i8::take(b).normalized(),
        GL_SHORT => i16::take(b).normalized(),
        GL_INT => i32::take(b).normalized(),
        _ => plain(type_, b),
    }
}

/// A colour component: unsigned integers to c / (2ᵇ − 1), signed ones to c / (2ᵇ⁻¹ − 1)
/// (at least −1), as Mesa's vertex fetch converts them.
fn color(type_: GLenum, b: &[u8]) -> f32 {
    match type_ {
        GL_BYTE => (f32::from(i8::take(b)) / 127.0).max(-1.0),
        GL_SHORT => (f32::from(i16::take(b)) / 32767.0).max(-1.0),
        GL_INT => (i32::take(b) as f32 / 2_147_483_647.0).max(-1.0),
        GL_UNSIGNED_BYTE => u8::take(b).normalized(),
        GL_UNSIGNED_SHORT => u16::take(b).normalized(),
        GL_UNSIGNED_INT => u32::take(b).normalized(),
        _ => plain(type_, b),
    }
}

/// A secondary colour component: integers as the immediate `glSecondaryColor3*v` forms
/// convert them, signed c to (2c + 1) / (2ᵇ − 1), which is not what Mesa's colour array does
/// (measured on Mesa 22.3 through `glArrayElement`: `color_sum.calls`).
fn secondary_color(type_: GLenum, b: &[u8]) -> f32 {
    match type_ {
        GL_BYTE => i8::take(b).normalized(),
        GL_SHORT => i16::take(b).normalized(),
        GL_INT => i32::take(b).normalized(),
        _ => color(type_, b),
    }
}

/// What one array element issues.
#[derive(Clone, Copy, Debug, Default)]
struct Element {
    edge_flag: Option<bool>,
    tex_coord: Option<[f32; 4]>,
    /// Units 1 to 7's coordinates (GL 1.3 §2.8: each unit's array).
    unit_tex_coords: [Option<[f32; 4]>; MAX_TEXTURE_UNITS - 1],
    color: Option<[f32; 4]>,
    secondary_color: Option<[f32; 4]>,
    fog_coord: Option<f32>,
    normal: Option<[f32; 4]>,
    vertex: Option<[f32; 4]>,
}

/// What `GL_CLIENT_VERTEX_ARRAY_BIT` saves: the arrays (every unit's texture coordinates), the
/// client active unit and the two buffer bindings (GL 1.5 table 6.8, as Mesa's
/// `copy_array_attrib`).
#[derive(Clone, Debug, PartialEq)]
struct SavedArrays {
    arrays: [ArrayState; ARRAYS],
    unit_tex: UnitArrays,
    client_unit: usize,
    array_buffer: Option<Rc<BufferObject>>,
    element_buffer: Option<Rc<BufferObject>>,
}

/// The client's vertex arrays, the buffer bindings, the current edge flag, and what
/// `glPushClientAttrib` saved of them.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct VertexArrays {
    /// The arrays, the texture coordinates' being the client active unit's.
    arrays: [ArrayState; ARRAYS],
    /// The texture coordinate arrays of the other units, by unit (GL 1.3 §2.8): the client
    /// active unit's entry is unused (its array is in `arrays`).
    unit_tex: UnitArrays,
    /// `glClientActiveTexture`'s unit.
    client_unit: usize,
    /// `glEdgeFlag`'s current value (Mesa keeps it as a float and reports `== 1.0`).
    pub edge_flag: bool,
    /// `GL_ARRAY_BUFFER`'s buffer: the one the pointer calls take offsets into.
    pub(crate) array_buffer: Option<Rc<BufferObject>>,
    /// `GL_ELEMENT_ARRAY_BUFFER`'s buffer: the one the element draws take indices from.
    pub(crate) element_buffer: Option<Rc<BufferObject>>,
    /// One entry per `glPushClientAttrib`: the arrays when `GL_CLIENT_VERTEX_ARRAY_BIT` was set.
    saved: Vec<Option<Box<SavedArrays>>>,
}

/// Each unit's texture coordinate array.
type UnitArrays = Box<[ArrayState; MAX_TEXTURE_UNITS]>;

impl Default for VertexArrays {
    fn default() -> Self {
        Self {
            arrays: [
                ArrayState::new(4, GL_FLOAT),
                ArrayState::new(3, GL_FLOAT),
                ArrayState::new(4, GL_FLOAT),
                ArrayState::new(1, GL_FLOAT),
                ArrayState::new(4, GL_FLOAT),
                ArrayState::new(1, GL_UNSIGNED_BYTE),
                ArrayState::new(3, GL_FLOAT),
                ArrayState::new(1, GL_FLOAT),
            ],
            unit_tex: Box::new(std::array::from_fn(|_| ArrayState::new(4, GL_FLOAT))),
            client_unit: 0,
            edge_flag: true,
            array_buffer: None,
            element_buffer: None,
            saved: Vec::new(),
        }
    }
}

impl VertexArrays {
    fn get(&self, which: Which) -> &ArrayState {
        &self.arrays[which as usize]
    }

    /// Whether `cap` is an array and enabled; `None` when it is no array.
    pub(crate) fn is_enabled(&self, cap: GLenum) -> Option<bool> {
        Which::of_capability(cap).map(|w| self.get(w).enabled)
    }

    /// Enables or disables an array; false when `cap` is no array.
    pub(crate) fn set_enabled(&mut self, cap: GLenum, on: bool) -> bool {
        let Some(w) = Which::of_capability(cap) else { return false };
        self.arrays[w as usize].enabled = on;
        true
    }

    /// Forgets a buffer being deleted: bindings to it become 0, and arrays in it keep their
    /// offset into no memory (Mesa's `unbind` in `_mesa_DeleteBuffers`).
    pub(crate) fn unbind_buffer(&mut self, buffer: &Rc<BufferObject>) {
        let is_it = |b: &Option<Rc<BufferObject>>| b.as_ref().is_some_and(|b| Rc::ptr_eq(b, buffer));
        if is_it(&self.array_buffer) {
            self.array_buffer = None;
        }
        if is_it(&self.element_buffer) {
            self.element_buffer = None;
        }
        for array in self.arrays.iter_mut().chain(self.unit_tex.iter_mut()).filter(|a| is_it(&a.buffer)) {
            array.buffer = None;
            let offset = array.pointer.as_ref().map_or(0, ClientPointer::offset);
            array.pointer = Some(ClientPointer::new(Rc::new(NoMemory), offset));
        }
    }

    /// `glClientActiveTexture`'s unit: its texture coordinate array becomes the one the
    /// pointer, enable and query calls name.
    pub(crate) fn set_client_unit(&mut self, unit: usize) {
        let current = Which::TexCoord as usize;
        std::mem::swap(&mut self.arrays[current], &mut self.unit_tex[self.client_unit]);
        std::mem::swap(&mut self.arrays[current], &mut self.unit_tex[unit]);
        self.client_unit = unit;
    }

    /// The client active unit.
    pub(crate) fn client_unit(&self) -> usize {
        self.client_unit
    }

    /// Unit `unit`'s texture coordinate array.
    fn tex_array(&self, unit: usize) -> &ArrayState {
        if unit == self.client_unit {
            self.get(Which::TexCoord)
        } else {
            &self.unit_tex[unit]
        }
    }

    /// Element `i` of the enabled arrays; `None` when an enabled array cannot be read there.
    fn element(&self, i: i64) -> Option<Element> {
        let on = |w: Which| self.get(w).enabled.then_some(self.get(w));
        let mut e = Element::default();
        if let Some(a) = on(Which::EdgeFlag) {
            e.edge_flag = Some(a.fetch(i, plain)?[0] == 1.0);
        }
        for unit in 0..MAX_TEXTURE_UNITS {
            let a = self.tex_array(unit);
            if a.enabled {
                let coords = Some(a.fetch(i, plain)?);
                match unit {
                    0 => e.tex_coord = coords,
                    _ => e.unit_tex_coords[unit - 1] = coords,
                }
            }
        }
        if let Some(a) = on(Which::Color) {
            e.color = Some(a.fetch(i, color)?);
        }
        if let Some(a) = on(Which::SecondaryColor) {
            e.secondary_color = Some(a.fetch(i, secondary_color)?);
        }
        if let Some(a) = on(Which::FogCoord) {
            e.fog_coord = Some(a.fetch(i, plain)?[0]);
        }
        if let Some(a) = on(Which::Index) {
            a.fetch(i, plain)?; // read (as GL does); colour index has no effect in RGBA
        }
        if let Some(a) = on(Which::Normal) {
            e.normal = Some(a.fetch(i, normal)?);
        }
        if let Some(a) = on(Which::Vertex) {
            e.vertex = Some(a.fetch(i, plain)?);
        }
        Some(e)
    }
}

/// The memory an array points into once its buffer is deleted: none (Mesa would read the
/// address its offset makes; gleval reads nothing).
#[derive(Debug)]
struct NoMemory;

impl ClientMemory for NoMemory {
    fn read(&self, _: usize, _: &mut [u8]) -> bool {
        false
    }

    fn as_any(&self) -> &dyn Any {
        self
    }
}

/// What a pointer call accepts for its memory: a [`ClientArray`](super::ClientArray) (`&v`), a
/// [`ClientPointer`] (`&v[3]` is `v.at(3)`), `None` (C's NULL), or a [`BufferOffset`].
///
/// While a buffer is bound to `GL_ARRAY_BUFFER`, GL takes the pointer as an offset into it
/// (GL 1.5 §2.9.1): [`PointerArg::buffer_offset`] is that offset. C's pointers are both (the
/// C ABI's kind answers its address); a Rust client pointer is offset 0 there, as NULL is.
pub trait PointerArg {
    /// The pointer as client memory, `None` for NULL (no buffer bound).
    fn into_pointer(self) -> Option<ClientPointer>;
    /// The pointer as an offset into the buffer bound to `GL_ARRAY_BUFFER`.
    fn buffer_offset(&self) -> usize {
        0
    }
}

/// An offset into a buffer object where C passes one as a pointer (`(void *)12`, the
/// `BUFFER_OFFSET(12)` idiom): `gl.vertex_pointer(3, GL_FLOAT, 0, BufferOffset(12))`. With no
/// buffer bound it points at no memory (a draw reading it is `GL_INVALID_VALUE`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BufferOffset(pub usize);

impl PointerArg for BufferOffset {
    fn into_pointer(self) -> Option<ClientPointer> {
        (self.0 != 0).then(|| ClientPointer::new(Rc::new(NoMemory), self.0))
    }

    fn buffer_offset(&self) -> usize {
        self.0
    }
}

impl PointerArg for &super::ClientArray {
    fn into_pointer(self) -> Option<ClientPointer> {
        Some(self.into())
    }
}

impl PointerArg for ClientPointer {
    fn into_pointer(self) -> Option<ClientPointer> {
        Some(self)
    }
}

impl PointerArg for &ClientPointer {
    fn into_pointer(self) -> Option<ClientPointer> {
        Some(self.clone())
    }
}

impl PointerArg for Option<ClientPointer> {
    fn into_pointer(self) -> Option<ClientPointer> {
        self
    }
}

/// `glInterleavedArrays`' formats (GL 1.1 table 2.5): texture coordinate size, colour (size,
/// type), normal, vertex size, and the default stride in bytes.
struct Layout {
    tex: GLint,
    color: Option<(GLint, GLenum)>,
    normal: bool,
    vertex: GLint,
}

fn interleaved_layout(format: GLenum) -> Option<Layout> {
    let l = |tex, color, normal, vertex| Some(Layout { tex, color, normal, vertex });
    let (ub, f) = (GL_UNSIGNED_BYTE, GL_FLOAT);
    match format {
        GL_V2F => l(0, None, false, 2),
        GL_V3F => l(0, None, false, 3),
        GL_C4UB_V2F => l(0, Some((4, ub)), false, 2),
        GL_C4UB_V3F => l(0, Some((4, ub)), false, 3),
        GL_C3F_V3F => l(0, Some((3, f)), false, 3),
        GL_N3F_V3F => l(0, None, true, 3),
        GL_C4F_N3F_V3F => l(0, Some((4, f)), true, 3),
        GL_T2F_V3F => l(2, None, false, 3),
        GL_T4F_V4F => l(4, None, false, 4),
        GL_T2F_C4UB_V3F => l(2, Some((4, ub)), false, 3),
        GL_T2F_C3F_V3F => l(2, Some((3, f)), false, 3),
        GL_T2F_N3F_V3F => l(2, None, true, 3),
        GL_T2F_C4F_N3F_V3F => l(2, Some((4, f)), true, 3),
        GL_T4F_C4F_N3F_V4F => l(4, Some((4, f)), true, 4),
        _ => None,
    }
}

impl Gl {
    /// `glVertexPointer(size, type, stride, pointer)`: sizes 2–4 of `GL_SHORT`, `GL_INT`,
    /// `GL_FLOAT` or `GL_DOUBLE`. Errors in Mesa's order (module docs). Not compiled.
    pub fn vertex_pointer(&mut self, size: GLint, type_: GLenum, stride: GLsizei, pointer: impl PointerArg) {
        self.array_pointer(Which::Vertex, size, type_, stride, pointer);
    }

    /// `glNormalPointer(type, stride, pointer)`: three of `GL_BYTE`, `GL_SHORT`, `GL_INT`,
    /// `GL_FLOAT` or `GL_DOUBLE`.
    pub fn normal_pointer(&mut self, type_: GLenum, stride: GLsizei, pointer: impl PointerArg) {
        self.array_pointer(Which::Normal, 3, type_, stride, pointer);
    }

    /// `glColorPointer(size, type, stride, pointer)`: 3 or 4 of any integer type, `GL_FLOAT`
    /// or `GL_DOUBLE`.
    pub fn color_pointer(&mut self, size: GLint, type_: GLenum, stride: GLsizei, pointer: impl PointerArg) {
        self.array_pointer(Which::Color, size, type_, stride, pointer);
    }

    /// `glIndexPointer(type, stride, pointer)`: `GL_UNSIGNED_BYTE`, `GL_SHORT`, `GL_INT`,
    /// `GL_FLOAT` or `GL_DOUBLE` (kept as state: colour indices do not draw in RGBA).
    pub fn index_pointer(&mut self, type_: GLenum, stride: GLsizei, pointer: impl PointerArg) {
        self.array_pointer(Which::Index, 1, type_, stride, pointer);
    }

    /// `glTexCoordPointer(size, type, stride, pointer)`: sizes 1–4 of `GL_SHORT`, `GL_INT`,
    /// `GL_FLOAT` or `GL_DOUBLE`.
    pub fn tex_coord_pointer(&mut self, size: GLint, type_: GLenum, stride: GLsizei, pointer: impl PointerArg) {
        self.array_pointer(Which::TexCoord, size, type_, stride, pointer);
    }

    /// `glSecondaryColorPointer(size, type, stride, pointer)` (GL 1.4): 3 (or 4, as Mesa
    /// takes) of any integer type, `GL_FLOAT` or `GL_DOUBLE`; alpha is not read into the
    /// secondary colour.
    pub fn secondary_color_pointer(&mut self, size: GLint, type_: GLenum, stride: GLsizei, pointer: impl PointerArg) {
        self.array_pointer(Which::SecondaryColor, size, type_, stride, pointer);
    }

    /// `glFogCoordPointer(type, stride, pointer)` (GL 1.4): one `GL_FLOAT` or `GL_DOUBLE` per
    /// element.
    pub fn fog_coord_pointer(&mut self, type_: GLenum, stride: GLsizei, pointer: impl PointerArg) {
        self.array_pointer(Which::FogCoord, 1, type_, stride, pointer.into_pointer());
    }

    /// `glEdgeFlagPointer(stride, pointer)`: one `GLboolean` per element.
    pub fn edge_flag_pointer(&mut self, stride: GLsizei, pointer: impl PointerArg) {
        self.array_pointer(Which::EdgeFlag, 1, GL_UNSIGNED_BYTE, stride, pointer);
    }

    fn array_pointer(&mut self, which: Which, size: GLint, type_: GLenum, stride: GLsizei, pointer: impl PointerArg) {
        if self.reject_inside_begin_end() {
            return;
        }
        // Mesa's validate_array reports a negative stride and goes on.
        if stride < 0 {
            self.set_error(GL_INVALID_VALUE);
        }
        if !which.accepts_type(type_) {
            return self.set_error(GL_INVALID_ENUM);
        }
        if !which.accepts_size(size) {
            return self.set_error(GL_INVALID_VALUE);
        }
        let (pointer, buffer) = self.array_memory(pointer);
        let array = &mut self.client.arrays.arrays[which as usize];
        (array.size, array.type_, array.stride, array.pointer, array.buffer) = (size, type_, stride, pointer, buffer);
    }

    /// Where a pointer argument points: an offset into the buffer bound to `GL_ARRAY_BUFFER`
    /// (and that buffer), or client memory when none is.
    fn array_memory(&self, pointer: impl PointerArg) -> (Option<ClientPointer>, Option<Rc<BufferObject>>) {
        match &self.client.arrays.array_buffer {
            Some(buffer) => {
                let memory: Rc<dyn ClientMemory> = buffer.clone();
                (Some(ClientPointer::new(memory, pointer.buffer_offset())), Some(buffer.clone()))
            }
            None => (pointer.into_pointer(), None),
        }
    }

    /// `glEnableClientState(array)`: `GL_VERTEX_ARRAY` … `GL_EDGE_FLAG_ARRAY`; another name →
    /// `GL_INVALID_ENUM`. Not compiled. (`glEnable` takes the same names, as in Mesa.)
    pub fn enable_client_state(&mut self, array: GLenum) {
        self.client_state(array, true);
    }

    /// `glDisableClientState(array)`.
    pub fn disable_client_state(&mut self, array: GLenum) {
        self.client_state(array, false);
    }

    fn client_state(&mut self, array: GLenum, on: bool) {
        if self.reject_inside_begin_end() {
            return;
        }
        if !self.client.arrays.set_enabled(array, on) {
            self.set_error(GL_INVALID_ENUM);
        }
    }

    /// `glEdgeFlag(flag)`: whether the following polygon vertices start boundary edges (GL 1.1
    /// §2.6.2); only 1 (`GL_TRUE`) counts as true, as in Mesa, which keeps the flag as a float.
    pub fn edge_flag(&mut self, flag: GLboolean) {
        if self.compiled(|| ListCommand::EdgeFlag(flag)) {
            return;
        }
        self.client.arrays.edge_flag = flag == GL_TRUE;
    }

    /// The current edge flag, which each vertex issued takes.
    pub(crate) fn edge_flag_value(&self) -> bool {
        self.client.arrays.edge_flag
    }

    /// `glEdgeFlagv(flag)`: `flag` needs one value.
    pub fn edge_flagv(&mut self, flag: &[GLboolean]) {
        if let Some([f]) = self.first::<1, GLboolean>(flag) {
            self.edge_flag(f);
        }
    }

    /// `glArrayElement(i)`: element `i` of every enabled array, as the immediate calls (allowed
    /// inside `begin`/`end`; compiled into lists as those calls).
    pub fn array_element(&mut self, i: GLint) {
        match self.client.arrays.element(i64::from(i)) {
            Some(e) => self.issue(&e, false),
            None => self.set_error(GL_INVALID_VALUE),
        }
    }

    /// The immediate calls of one element; `position_fallback`: without the vertex array, a
    /// vertex at (0, 0, 0, 1) (what Mesa's draws do).
    fn issue(&mut self, e: &Element, position_fallback: bool) {
        if let Some(flag) = e.edge_flag {
            self.edge_flag(GLboolean::from(flag));
        }
        if let Some([s, t, r, q]) = e.tex_coord {
            self.tex_coord4f(s, t, r, q);
        }
        for (unit, coords) in (1..).zip(e.unit_tex_coords) {
            if let Some([s, t, r, q]) = coords {
                self.multi_tex_coord4f(GL_TEXTURE0 + unit, s, t, r, q);
            }
        }
        if let Some([r, g, b, a]) = e.color {
            self.color4f(r, g, b, a);
        }
        if let Some(c) = e.secondary_color {
            // A size-4 array gives the alpha too, as Mesa reads it (a size-3 one 1).
            self.secondary_color(c);
        }
        if let Some(c) = e.fog_coord {
            self.fog_coordf(c);
        }
        if let Some([x, y, z, _]) = e.normal {
            self.normal3f(x, y, z);
        }
        match e.vertex {
            Some([x, y, z, w]) => self.vertex4f(x, y, z, w),
            None if position_fallback => self.vertex4f(0.0, 0.0, 0.0, 1.0),
            None => {}
        }
    }

    /// A draw call's error: raised now, and compiled into the list being made so that it is
    /// raised again when the list runs (Mesa's `_mesa_compile_error`).
    pub(super) fn draw_error(&mut self, code: GLenum) {
        if !self.compiled(|| ListCommand::Error(code)) {
            self.set_error(code);
        }
    }

    /// `glDrawArrays(mode, first, count)`: `glBegin(mode)`, elements `first .. first + count`,
    /// `glEnd`, leaving the current values as they were. Errors: inside `begin`/`end`
    /// (`GL_INVALID_OPERATION`), `count` < 0 (`GL_INVALID_VALUE`), an unknown mode
    /// (`GL_INVALID_ENUM`); an element outside the arrays' memory (`GL_INVALID_VALUE`).
    pub fn draw_arrays(&mut self, mode: GLenum, first: GLint, count: GLsizei) {
        // Inside begin/end: raised, and compiled too (Mesa's `save_DrawArrays` and
        // `save_DrawElements`: "glDraw*(recursive)"), so a list made in
        // `GL_COMPILE_AND_EXECUTE` mode raises it again when called.
        if self.inside_begin_end() {
            return self.draw_error(GL_INVALID_OPERATION);
        }
        if count < 0 {
            return self.draw_error(GL_INVALID_VALUE);
        }
        if mode > GL_POLYGON {
            return self.draw_error(GL_INVALID_ENUM);
        }
        let first = i64::from(first);
        self.draw_indexed(mode, (first..first + i64::from(count)).collect());
    }

    /// `glDrawElements(mode, count, type, indices)`: as [`Gl::draw_arrays`] over the `count`
    /// indices read from `indices` as `type` says (`GL_UNSIGNED_BYTE`, `GL_UNSIGNED_SHORT` or
    /// `GL_UNSIGNED_INT`, in native byte order: any slice type holds them as C's array does).
    /// Errors: `count` < 0 (`GL_INVALID_VALUE`), then the mode and the type
    /// (`GL_INVALID_ENUM`), then `indices` shorter than `count` indices (`GL_INVALID_VALUE`).
    ///
    /// The indices are client memory, whatever is bound to `GL_ELEMENT_ARRAY_BUFFER`: indices
    /// in a buffer are [`Gl::draw_elements_offset`]'s.
    pub fn draw_elements<T: ArrayElement>(&mut self, mode: GLenum, count: GLsizei, type_: GLenum, indices: &[T]) {
        if !self.element_draw_checks(mode, count, type_) {
            return;
        }
        let size = type_size(type_);
        let bytes = to_bytes(indices);
        let Some(bytes) = bytes.get(..count as usize * size) else { return self.set_error(GL_INVALID_VALUE) };
        self.draw_index_list(mode, bytes.chunks_exact(size).map(|b| index_value(type_, b)).collect());
    }

    /// `glDrawElements(mode, count, type, (void *)offset)` with a buffer bound to
    /// `GL_ELEMENT_ARRAY_BUFFER` (GL 1.5 §2.9.2): the `count` indices from byte `offset` of
    /// that buffer, read now (a display list keeps the vertices they name). Errors as
    /// [`Gl::draw_elements`]; no element buffer bound → `GL_INVALID_VALUE` (no memory to read).
    /// As Mesa 22.3 on llvmpipe does (measured): an offset that is no multiple of the index
    /// size, or past the buffer's end, draws nothing; an index past the end names a vertex
    /// outside every buffer (zeros, see `fetch`).
    pub fn draw_elements_offset(&mut self, mode: GLenum, count: GLsizei, type_: GLenum, offset: usize) {
        if !self.element_draw_checks(mode, count, type_) {
            return;
        }
        let Some(buffer) = self.client.arrays.element_buffer.clone() else { return self.set_error(GL_INVALID_VALUE) };
        let size = type_size(type_);
        if offset % size != 0 || offset > buffer.len() {
            return;
        }
        let index = |i: usize| {
            let mut b = [0u8; 4];
            let at = i.checked_mul(size).and_then(|d| d.checked_add(offset));
            let read = at.is_some_and(|at| buffer.read(at, &mut b[..size]));
            if read {
                index_value(type_, &b)
            } else {
                OUTSIDE_INDEX
            }
        };
        let indices = (0..count as usize).map(index).collect();
        self.draw_index_list(mode, indices);
    }

    /// `glDrawElements`' checks in Mesa's order (inside `begin`/`end`, the count, the mode and
    /// the type), each error compiled too; true when they pass.
    pub(super) fn element_draw_checks(&mut self, mode: GLenum, count: GLsizei, type_: GLenum) -> bool {
        let error = if self.inside_begin_end() {
            GL_INVALID_OPERATION
        } else if count < 0 {
            GL_INVALID_VALUE
        } else if mode > GL_POLYGON || !matches!(type_, GL_UNSIGNED_BYTE | GL_UNSIGNED_SHORT | GL_UNSIGNED_INT) {
            GL_INVALID_ENUM
        } else {
            return true;
        };
        self.draw_error(error);
        false
    }

    /// An indexed draw of `indices` (quads split as lists split them, `recorder.indexed_draw`).
    fn draw_index_list(&mut self, mode: GLenum, indices: Vec<i64>) {
        self.recorder.indexed_draw = true;
        self.draw_indexed(mode, indices);
        self.recorder.indexed_draw = false;
    }

    /// Begin, the elements, end; the current values are restored after.
    fn draw_indexed(&mut self, mode: GLenum, indices: Vec<i64>) {
        let elements: Option<Vec<Element>> = indices.into_iter().map(|i| self.client.arrays.element(i)).collect();
        let Some(elements) = elements else { return self.set_error(GL_INVALID_VALUE) };
        let (current, edge_flag) = (self.server.current, self.client.arrays.edge_flag);
        self.begin(mode);
        for e in &elements {
            self.issue(e, true);
        }
        self.end();
        (self.server.current, self.client.arrays.edge_flag) = (current, edge_flag);
    }

    /// `glInterleavedArrays(format, stride, pointer)`: sets the vertex, and as the format says
    /// the colour, normal and texture-coordinate arrays into one block of memory, enables them,
    /// disables the others (GL 1.1 §2.8). Errors: a negative stride (`GL_INVALID_VALUE`), then
    /// an unknown format (`GL_INVALID_ENUM`). Not compiled.
    pub fn interleaved_arrays(&mut self, format: GLenum, stride: GLsizei, pointer: impl PointerArg) {
        if self.reject_inside_begin_end() {
            return;
        }
        if stride < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let Some(layout) = interleaved_layout(format) else { return self.set_error(GL_INVALID_ENUM) };
        let (pointer, buffer) = self.array_memory(pointer);
        let color_bytes = layout.color.map_or(0, |(n, t)| n as usize * type_size(t));
        let (pc, pn) = (layout.tex as usize * 4, layout.tex as usize * 4 + color_bytes);
        let pv = pn + if layout.normal { 12 } else { 0 };
        let default_stride = pv + layout.vertex as usize * 4;
        let stride = if stride == 0 { default_stride as GLsizei } else { stride };
        let at = |offset: usize| pointer.as_ref().map(|p| ClientPointer::new(p.memory().clone(), p.offset() + offset));
        let set = |a: &mut ArrayState, on: bool, size: GLint, type_: GLenum, offset: usize| {
            a.enabled = on;
            if on {
                (a.size, a.type_, a.stride, a.pointer) = (size, type_, stride, at(offset));
                a.buffer.clone_from(&buffer);
            }
        };
        // Mesa leaves the secondary colour array as it was (measured on Mesa 22.3), and the
        // fog coordinate array.
        let [vertex, normal, color, index, tex, edge, _, _] = &mut self.client.arrays.arrays;
        edge.enabled = false;
        index.enabled = false;
        set(tex, layout.tex > 0, layout.tex, GL_FLOAT, 0);
        let (csize, ctype) = layout.color.unwrap_or((4, GL_FLOAT));
        set(color, layout.color.is_some(), csize, ctype, pc);
        set(normal, layout.normal, 3, GL_FLOAT, pn);
        set(vertex, true, layout.vertex, GL_FLOAT, pv);
    }

    /// `glGetPointerv(pname)`: an array's pointer (`None` for NULL). `GL_FEEDBACK_BUFFER_POINTER`
    /// and `GL_SELECTION_BUFFER_POINTER` are known names with `None` here (the buffers are the
    /// context's; the C ABI answers them with the caller's). Another name → `GL_INVALID_ENUM`;
    /// inside `begin`/`end` → `GL_INVALID_OPERATION`.
    pub fn get_pointerv(&mut self, pname: GLenum) -> Option<ClientPointer> {
        if let Some(error) = self.get_pointerv_error(pname) {
            self.set_error(error);
            return None;
        }
        let which = Which::ALL.into_iter().find(|w| w.pointer_name() == pname)?;
        self.client.arrays.get(which).pointer.clone()
    }

    /// The error `glGetPointerv(pname)` raises now (inside `begin`/`end`, then an unknown
    /// name), `None` when it writes its answer: what a binding writing the caller's pointer
    /// asks before it does.
    #[must_use]
    pub fn get_pointerv_error(&self, pname: GLenum) -> Option<GLenum> {
        let known = Which::ALL.into_iter().any(|w| w.pointer_name() == pname)
            || matches!(pname, GL_FEEDBACK_BUFFER_POINTER | GL_SELECTION_BUFFER_POINTER);
        if self.inside_begin_end() {
            Some(GL_INVALID_OPERATION)
        } else if !known {
            Some(GL_INVALID_ENUM)
        } else {
            None
        }
    }

    /// Bytes `glDrawElements` reads for `count` indices of `type_`; `None` where it reads none
    /// (a negative count, a type other than `GL_UNSIGNED_BYTE`, `_SHORT`, `_INT`).
    #[must_use]
    pub fn draw_elements_len(count: GLsizei, type_: GLenum) -> Option<usize> {
        if !matches!(type_, GL_UNSIGNED_BYTE | GL_UNSIGNED_SHORT | GL_UNSIGNED_INT) {
            return None;
        }
        usize::try_from(count).ok()?.checked_mul(type_size(type_))
    }

    /// `glPushClientAttrib`'s vertex-array half: saves the arrays when `mask` asks.
    pub(crate) fn push_client_arrays(&mut self, mask: GLbitfield) {
        let a = &self.client.arrays;
        let saved = (mask & GL_CLIENT_VERTEX_ARRAY_BIT != 0).then(|| {
            Box::new(SavedArrays {
                arrays: a.arrays.clone(),
                unit_tex: a.unit_tex.clone(),
                client_unit: a.client_unit,
                array_buffer: a.array_buffer.clone(),
                element_buffer: a.element_buffer.clone(),
            })
        });
        self.client.arrays.saved.push(saved);
    }

    /// `glPopClientAttrib`'s vertex-array half: every unit's array and the client active unit.
    pub(crate) fn pop_client_arrays(&mut self) {
        if let Some(Some(saved)) = self.client.arrays.saved.pop() {
            let a = &mut self.client.arrays;
            (a.arrays, a.unit_tex, a.client_unit) = (saved.arrays, saved.unit_tex, saved.client_unit);
            (a.array_buffer, a.element_buffer) = (saved.array_buffer, saved.element_buffer);
        }
    }
}

/// `glGet` of an array's size, type or stride (GL 1.1 table 6.6; the enables are capabilities).
macro_rules! array_row {
    ($name:expr, $which:ident . $field:ident) => {
        row($name, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.client.arrays.get(Which::$which).$field))
    };
}

/// `glGet` of an array's buffer binding (GL 1.5 table 6.7).
macro_rules! binding_row {
    ($name:expr, $which:ident) => {
        row($name, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.client.arrays.get(Which::$which).buffer_name()))
    };
}

/// The arrays' `glGet` rows, the buffer bindings' (GL 1.5 table 6.7), and the current edge
/// flag's (table 6.3), which lives here.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_ARRAY_BUFFER_BINDING, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.array_buffer_binding())),
    row(GL_ELEMENT_ARRAY_BUFFER_BINDING, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.element_array_buffer_binding())),
    row(GL_PIXEL_PACK_BUFFER_BINDING, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.pixel_pack_buffer_binding())),
    row(GL_PIXEL_UNPACK_BUFFER_BINDING, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.pixel_unpack_buffer_binding())),
    binding_row!(GL_VERTEX_ARRAY_BUFFER_BINDING, Vertex),
    binding_row!(GL_NORMAL_ARRAY_BUFFER_BINDING, Normal),
    binding_row!(GL_COLOR_ARRAY_BUFFER_BINDING, Color),
    binding_row!(GL_INDEX_ARRAY_BUFFER_BINDING, Index),
    binding_row!(GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, TexCoord),
    binding_row!(GL_EDGE_FLAG_ARRAY_BUFFER_BINDING, EdgeFlag),
    binding_row!(GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING, SecondaryColor),
    binding_row!(GL_FOG_COORD_ARRAY_BUFFER_BINDING, FogCoord),
    row(GL_EDGE_FLAG, 1, Kind::Bool, |gl, o| put_flag(o, gl.client.arrays.edge_flag)),
    array_row!(GL_VERTEX_ARRAY_SIZE, Vertex.size),
    array_row!(GL_VERTEX_ARRAY_TYPE, Vertex.type_),
    array_row!(GL_VERTEX_ARRAY_STRIDE, Vertex.stride),
    array_row!(GL_NORMAL_ARRAY_TYPE, Normal.type_),
    array_row!(GL_NORMAL_ARRAY_STRIDE, Normal.stride),
    array_row!(GL_COLOR_ARRAY_SIZE, Color.size),
    array_row!(GL_COLOR_ARRAY_TYPE, Color.type_),
    array_row!(GL_COLOR_ARRAY_STRIDE, Color.stride),
    array_row!(GL_INDEX_ARRAY_TYPE, Index.type_),
    array_row!(GL_INDEX_ARRAY_STRIDE, Index.stride),
    array_row!(GL_TEXTURE_COORD_ARRAY_SIZE, TexCoord.size),
    array_row!(GL_TEXTURE_COORD_ARRAY_TYPE, TexCoord.type_),
    array_row!(GL_TEXTURE_COORD_ARRAY_STRIDE, TexCoord.stride),
    array_row!(GL_EDGE_FLAG_ARRAY_STRIDE, EdgeFlag.stride),
    array_row!(GL_SECONDARY_COLOR_ARRAY_SIZE, SecondaryColor.size),
    array_row!(GL_SECONDARY_COLOR_ARRAY_TYPE, SecondaryColor.type_),
    array_row!(GL_SECONDARY_COLOR_ARRAY_STRIDE, SecondaryColor.stride),
    array_row!(GL_FOG_COORD_ARRAY_TYPE, FogCoord.type_),
    array_row!(GL_FOG_COORD_ARRAY_STRIDE, FogCoord.stride),
];

#[cfg(test)]
mod tests {
    use super::super::ClientArray;
    use super::*;

    #[test]
    fn draw_arrays_reads_the_array_when_it_draws() {
        let mut gl = Gl::new(4, 4);
        let v = ClientArray::new(&[0.0f32, 0.0, 1.0, 1.0]);
        gl.vertex_pointer(2, GL_FLOAT, 0, &v);
        gl.enable_client_state(GL_VERTEX_ARRAY);
        v.write(2, &[0.5f32, 0.25]);
        gl.draw_arrays(GL_LINES, 0, 2);
        let frame = gl.frame();
        assert_eq!(frame.primitives[0].mode, GL_LINES);
        assert_eq!(frame.vertices[1].position, [0.5, 0.25, 0.0, 1.0]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn reading_past_the_array_is_an_error_not_a_panic() {
        let mut gl = Gl::new(4, 4);
        let v = ClientArray::new(&[0.0f32; 5]);
        gl.vertex_pointer(3, GL_FLOAT, 0, &v);
        gl.enable_client_state(GL_VERTEX_ARRAY);
        gl.draw_arrays(GL_POINTS, 0, 2);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.draw_elements(GL_POINTS, 3, GL_UNSIGNED_BYTE, &[0u8, 0]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.draw_arrays(GL_POINTS, -1, 1);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        assert!(gl.frame().vertices.is_empty());
    }

    #[test]
    fn interleaved_sets_every_array_into_one_block() {
        let mut gl = Gl::new(4, 4);
        let mut block = vec![255u8, 0, 0, 255];
        block.extend(to_bytes(&[0.5f32, 0.25, 0.0]));
        let data = ClientArray::from_bytes(block);
        gl.interleaved_arrays(GL_C4UB_V3F, 0, &data);
        gl.draw_arrays(GL_POINTS, 0, 1);
        let v = gl.frame().vertices[0];
        assert_eq!((v.position, v.color), ([0.5, 0.25, 0.0, 1.0], [1.0, 0.0, 0.0, 1.0]));
        let mut stride = [0];
        gl.get_integerv(GL_VERTEX_ARRAY_STRIDE, &mut stride);
        assert_eq!(stride[0], 16);
        assert!(gl.get_pointerv(GL_COLOR_ARRAY_POINTER).is_some_and(|p| p.points_into(&data)));
    }
}
