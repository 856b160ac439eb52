//! Display lists (GL 1.1 spec §5.4; Mesa `main/dlist.c`): `glNewList`/`glEndList` record the
//! commands made between them, `glCallList`/`glCallLists` replay them.
//!
//! One gate per command: every `Gl` method that GL compiles into a list starts with
//! [`Gl::compiled`], which, while a list is being compiled, appends a [`ListCommand`] (holding
//! copies of whatever GL copies: a map's control points are packed at compile time, as Mesa's
//! `_mesa_copy_map_points1f` does) and tells the method whether to go on and execute it
//! (`GL_COMPILE_AND_EXECUTE`) or stop (`GL_COMPILE`). Replay calls the same methods, so every
//! rule (and every error, which GL raises when a list executes, not when it compiles) is
//! written once. `glEvalMesh` is compiled as the call, not as its vertices; GLU's NURBS calls are
//! compiled as the GL calls GLU makes, with the sampling worked out at compile time, as real
//! GLU's are. One difference: a trimmed surface's vertices are evaluated when the list compiles
//! (real GLU compiles `glEvalCoord2f` calls, evaluated when the list runs), so they differ only
//! if the evaluator state (`GL_AUTO_NORMAL`) changes between compiling and calling the list.
//!
//! Not compiled, executed at once (spec §5.4): `glGenLists`, `glNewList`, `glEndList`,
//! `glDeleteLists`, `glIsList`, `glGet*`, `glIsEnabled`, `glGetError`, `glFlush`, `glFinish`.

use super::bitmap::BitmapCall;
use super::consts::*;
use super::eval::MeshJob;
use super::frame::Call;
use super::state_var::{int_limit, put_enum, row, Kind, StateVar};
use super::types::*;
use super::vertex::Vertex;
use super::Gl;
use std::collections::HashMap;
use std::rc::Rc;

/// Mesa's limit on nested `glCallList` (`MAX_LIST_NESTING`): deeper calls are ignored silently.
pub const MAX_LIST_NESTING: usize = 64;

/// A command as a display list holds it: each variant is one GL call (the `*d`, `*v` and
/// shorter forms stored as the call they reduce to), with its data copied.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum ListCommand {
    /// `glBegin`, `glEnd`, `glVertex`, `glColor`, `glNormal`, `glTexCoord`: the calls a frame logs.
    Immediate(Call),
    /// `glRect*`: `[x1, y1, x2, y2]`.
    Rect([f32; 4]),
    Enable(GLenum),
    Disable(GLenum),
    /// The viewport group's calls (`viewport.rs`).
    Viewport(super::viewport::ViewportCall),
    /// `glPolygonStipple` with its mask unpacked at compile time (`None`: too short).
    PolygonStipple(Option<[u32; 32]>),
    Clear(GLbitfield),
    /// `glHint`.
    Hint(GLenum, GLenum),
    Fog(GLenum, Vec<f32>),
    /// A vertex with all its attributes, as GLU issues a trimmed surface's (its
    /// `glNormal`/`glVertex` pairs; see `Gl::emit_listed_vertex`).
    EmitVertex(Vertex),
    /// Triangles over scattered points evaluated by the GPU tessellator (GLU's trimmed
    /// surfaces there), with the jobs' maps copied.
    ScatteredMesh(Vec<MeshJob>, Vec<u32>),
    RasterPos([f32; 4]),
    /// `glWindowPos*`: x, y, z.
    WindowPos([f32; 3]),
    /// `glBitmap` with its bits unpacked at compile time (`None`: the slice was too short).
    Bitmap(BitmapCall, Option<Vec<bool>>),
    /// `glDrawPixels` with its pixels unpacked to RGBA at compile time.
    DrawPixels((GLsizei, GLsizei), GLenum, GLenum, Option<Vec<[f32; 4]>>),
    CallList(GLuint),
    CallLists(GLsizei, GLenum, Vec<u8>),
    ListBase(GLuint),
    EdgeFlag(GLboolean),
    /// `glBeginQuery(target, id)` (Mesa compiles it: `save_BeginQueryARB`).
    BeginQuery(GLenum, GLuint),
    /// `glEndQuery(target)`.
    EndQuery(GLenum),
    /// An error a draw call raised while it compiled: raised again when the list runs (Mesa's
    /// `_mesa_compile_error`).
    Error(GLenum),
    /// A compressed-image call of GL 1.3 (`texture/compressed.rs`).
    Compressed(super::texture::CompressedCall),
    PassThrough(GLfloat),
    /// `glCopyPixels`: x, y, width, height and the buffer.
    CopyPixels([GLint; 4], GLenum),
    /// The texture copies and `glPrioritizeTextures` (`copy_texture.rs`).
    CopyTexture(super::copy_texture::CopyTextureCall),
    /// The colour-index calls (`color_index.rs`).
    ColorIndex(super::color_index::ColorIndexCall),
    /// The pixel zoom, transfer and maps (`pixel_transfer.rs`).
    PixelTransfer(super::pixel_transfer::PixelTransferCall),
    /// The colour buffer group's calls (`color_buffer.rs`).
    ColorBuffer(super::color_buffer::ColorBufferCall),
    /// The stencil buffer group's calls (`stencil.rs`).
    Stencil(super::stencil::StencilCall),
    /// `glScissor`: x, y, width, height.
    Scissor([GLint; 4]),
    SampleCoverage(GLclampf, GLboolean),
    /// `glAccum` and `glClearAccum` (`accum.rs`).
    Accum(super::accum::AccumCall),
    /// The depth buffer group's calls (`depth.rs`).
    Depth(super::depth::DepthCall),
    /// The point group's calls (`point.rs`).
    Point(super::point::PointCall),
    /// The line group's calls (`line.rs`).
    Line(super::line::LineCall),
    /// The polygon group's calls (`polygon.rs`).
    Polygon(super::polygon::PolygonCall),
    /// The lighting group's calls (`lighting/`).
    Lighting(super::lighting::LightingCall),
    /// The transform group's calls: the matrices, the matrix mode, the clip planes (`matrix.rs`).
    Transform(super::matrix::TransformCall),
    /// The evaluator calls (`eval/`).
    Eval(super::eval::EvalCall),
    /// The texture group's calls (`texture.rs`).
    Texture(super::texture::TextureCall),
    /// The name stack's calls (`select.rs`).
    Names(super::select::NameCall),
    /// `glPushAttrib` and `glPopAttrib` (`attrib.rs`).
    Attrib(super::attrib::AttribCall),
}

/// A list being compiled.
#[derive(Debug)]
struct Compiling {
    name: GLuint,
    execute: bool,
    commands: Vec<ListCommand>,
}

/// The display lists of a context (Mesa keeps them in the shared state; we have one context).
#[derive(Debug, Default)]
pub(crate) struct Lists {
    /// Every list name in use, genned or compiled (a genned name is an empty list, as in Mesa).
    lists: HashMap<GLuint, Rc<[ListCommand]>>,
    compiling: Option<Compiling>,
    base: GLuint,
    /// The largest name ever used (Mesa's hash table `MaxKey`: deleting lists keeps it).
    max_name: GLuint,
    /// How deep `glCallList` is nested now.
    depth: usize,
}

impl Gl {
    /// Whether a display list is being executed (`glCallList`, at any depth).
    pub(crate) fn lists_executing(&self) -> bool {
        self.lists.depth > 0
    }
}

impl Gl {
    /// Runs `f` with no list being compiled: the calls of a command that is recorded whole
    /// (`glCallList`, `glRect`) are not recorded again in `GL_COMPILE_AND_EXECUTE`.
    pub(crate) fn uncompiled(&mut self, f: impl FnOnce(&mut Self)) {
        let compiling = self.lists.compiling.take();
        f(self);
        self.lists.compiling = compiling;
    }

    /// The gate of every compiled command: while a list is compiled, appends `command()` to it
    /// and returns true when the command must not run now (`GL_COMPILE`).
    pub(crate) fn compiled(&mut self, command: impl FnOnce() -> ListCommand) -> bool {
        let Some(list) = self.lists.compiling.as_mut() else { return false };
        list.commands.push(command());
        !list.execute
    }

    /// The gate of a state call: compiled into the list being built (true: the call is done),
    /// or refused inside `begin`/`end` with `GL_INVALID_OPERATION` (true); false: carry on.
    pub(crate) fn compiled_state_call(&mut self, command: impl FnOnce() -> ListCommand) -> bool {
        self.compiled(command) || self.reject_inside_begin_end()
    }

    /// Adds a vertex GLU made (position and attributes evaluated on the surface) to the open
    /// primitive, or to the list being compiled: what GLU's `glNormal3fv`/`glVertex3fv` calls
    /// do for a trimmed surface.
    pub(crate) fn emit_listed_vertex(&mut self, v: Vertex) {
        if !self.compiled(|| ListCommand::EmitVertex(v)) {
            self.emit_vertex(v);
        }
    }

    /// `glGenLists`: `range` consecutive unused names, the first returned (0 for `range` 0).
    /// A negative range → `GL_INVALID_VALUE`, inside `begin`/`end` → `GL_INVALID_OPERATION`.
    pub fn gen_lists(&mut self, range: GLsizei) -> GLuint {
        if self.reject_inside_begin_end() {
            return 0;
        }
        if range < 0 {
            self.set_error(GL_INVALID_VALUE);
            return 0;
        }
        if range == 0 {
            return 0;
        }
        let Some(first) = self.free_list_block(range as u32) else {
            self.set_error(GL_OUT_OF_MEMORY);
            return 0;
        };
        for name in first..first + range as u32 {
            self.insert_list(name, Vec::new());
        }
        first
    }

    /// The first of `n` consecutive unused names (Mesa `_mesa_HashFindFreeKeyBlock`): after the
    /// largest name ever used while there is room above it, else the first gap large enough.
    fn free_list_block(&self, n: u32) -> Option<GLuint> {
        if u32::MAX - 1 - n > self.lists.max_name {
            return Some(self.lists.max_name + 1);
        }
        let mut used: Vec<GLuint> = self.lists.lists.keys().copied().collect();
        used.sort_unstable();
        let mut start: GLuint = 1;
        for name in used {
            if name >= start && name - start >= n {
                return Some(start);
            }
            start = start.max(name.checked_add(1)?);
        }
        start.checked_add(n - 1).map(|_| start)
    }

    fn insert_list(&mut self, name: GLuint, commands: Vec<ListCommand>) {
        self.lists.max_name = self.lists.max_name.max(name);
        self.lists.lists.insert(name, Rc::from(commands));
    }

    /// `glNewList`: starts compiling list `list`. Errors, in Mesa's order: inside
    /// `begin`/`end` (`GL_INVALID_OPERATION`), `list` 0 (`GL_INVALID_VALUE`), a mode other than
    /// `GL_COMPILE`/`GL_COMPILE_AND_EXECUTE` (`GL_INVALID_ENUM`), a list already being compiled
    /// (`GL_INVALID_OPERATION`).
    pub fn new_list(&mut self, list: GLuint, mode: GLenum) {
        if self.reject_inside_begin_end() {
            return;
        }
        self.flush_current();
        if list == 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        if mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE {
            return self.set_error(GL_INVALID_ENUM);
        }
        if self.lists.compiling.is_some() {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let execute = mode == GL_COMPILE_AND_EXECUTE;
        self.lists.compiling = Some(Compiling { name: list, execute, commands: Vec::new() });
    }

    /// `glEndList`: stores the list compiled since `new_list` (replacing any list of that
    /// name); without one → `GL_INVALID_OPERATION`. A primitive that `GL_COMPILE_AND_EXECUTE`
    /// began is ended with it, without an error (as Mesa's `vbo_save_EndList` does).
    pub fn end_list(&mut self) {
        let Some(list) = self.lists.compiling.take() else {
            return self.set_error(GL_INVALID_OPERATION);
        };
        if self.inside_begin_end() {
            self.end();
        }
        self.flush_current();
        self.insert_list(list.name, list.commands);
    }

    /// `glCallList`: executes list `list` (GL allows it inside `begin`/`end`). `list` 0 →
    /// `GL_INVALID_VALUE`; an unknown list does nothing, nor does a call nested deeper than
    /// [`MAX_LIST_NESTING`] (Mesa ignores it silently).
    pub fn call_list(&mut self, list: GLuint) {
        if self.compiled(|| ListCommand::CallList(list)) {
            return;
        }
        if list == 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        self.flush_current();
        // In GL_COMPILE_AND_EXECUTE the call is recorded; what the list does is not again.
        self.uncompiled(|gl| gl.execute_list(list));
    }

    /// `glCallLists`: executes `n` lists whose names (offsets from [`Gl::list_base`]) are read
    /// from `lists` as `type_` says (`GL_BYTE` .. `GL_FLOAT`, or `GL_2_BYTES` .. `GL_4_BYTES`,
    /// big-endian byte groups); the multi-byte types in native byte order, as C's arrays are.
    /// Errors: an unknown type → `GL_INVALID_ENUM`, `n` < 0 → `GL_INVALID_VALUE` (Mesa's order);
    /// `lists` shorter than `n` names → `GL_INVALID_VALUE`.
    pub fn call_lists(&mut self, n: GLsizei, type_: GLenum, lists: &[u8]) {
        if self.compiled(|| ListCommand::CallLists(n, type_, lists.to_vec())) {
            return;
        }
        let Some(size) = list_name_size(type_) else {
            return self.set_error(GL_INVALID_ENUM);
        };
        if n < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let n = n as usize;
        if lists.len() / size < n {
            return self.set_error(GL_INVALID_VALUE);
        }
        let compiling = self.lists.compiling.take();
        for bytes in lists.chunks_exact(size).take(n) {
            let name = self.lists.base.wrapping_add_signed(list_offset(type_, bytes));
            self.execute_list(name);
        }
        self.lists.compiling = compiling;
    }

    /// `glListBase`: the offset `call_lists` adds to every name.
    pub fn list_base(&mut self, base: GLuint) {
        if self.compiled(|| ListCommand::ListBase(base)) || self.reject_inside_begin_end() {
            return;
        }
        self.lists.base = base;
    }

    /// `glDeleteLists`: deletes lists `list .. list + range` (unused names are ignored);
    /// a negative range → `GL_INVALID_VALUE`.
    pub fn delete_lists(&mut self, list: GLuint, range: GLsizei) {
        if self.reject_inside_begin_end() {
            return;
        }
        if range < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        for name in (0..range as u32).filter_map(|i| list.checked_add(i)) {
            self.lists.lists.remove(&name);
        }
    }

    /// `glIsList`: whether `list` names a list (compiled, or reserved by `gen_lists`).
    pub fn is_list(&mut self, list: GLuint) -> GLboolean {
        if self.reject_inside_begin_end() {
            return GL_FALSE;
        }
        if self.lists.lists.contains_key(&list) {
            GL_TRUE
        } else {
            GL_FALSE
        }
    }

    /// `GL_LIST_BASE`, which `GL_LIST_BIT` saves.
    pub(crate) fn list_base_value(&self) -> GLuint {
        self.lists.base
    }

    /// Restores `GL_LIST_BASE` (`glPopAttrib`).
    pub(crate) fn set_list_base_value(&mut self, base: GLuint) {
        self.lists.base = base;
    }

    /// Whether a list is being compiled (`glNewList` without its `glEndList` yet).
    pub(crate) fn compiling_list(&self) -> bool {
        self.lists.compiling.is_some()
    }

    fn execute_list(&mut self, name: GLuint) {
        if self.lists.depth >= MAX_LIST_NESTING {
            return;
        }
        let Some(commands) = self.lists.lists.get(&name).cloned() else { return };
        self.lists.depth += 1;
        // A primitive the list begins, replayed inside `begin`/`end` (the list called there),
        // is `GL_INVALID_OPERATION` and is not drawn, its vertices up to its `glEnd` included
        // (Mesa's `vbo_save_playback_vertex_list`: "draw operation inside glBegin/End");
        // `glDrawArrays` compiled into the list is such a primitive. A `glBegin` inside a
        // primitive the list itself began is only the error, as Mesa compiles it
        // (`_mesa_compile_error`): its `glEnd` then ends the list's primitive.
        let called_inside = self.inside_begin_end();
        let mut commands = commands.iter();
        while let Some(command) = commands.next() {
            if matches!(command, ListCommand::Immediate(Call::Begin(_))) && called_inside {
                self.set_error(GL_INVALID_OPERATION);
                for skipped in commands.by_ref() {
                    if matches!(skipped, ListCommand::Immediate(Call::End)) {
                        break;
                    }
                }
                continue;
            }
            self.execute(command);
        }
        self.lists.depth -= 1;
    }

    /// Replays one command through the method that recorded it.
    fn execute(&mut self, command: &ListCommand) {
        use ListCommand as C;
        match command {
            C::Immediate(Call::Begin(mode)) => self.begin(*mode),
            C::Rect([x1, y1, x2, y2]) => self.rectf(*x1, *y1, *x2, *y2),
            C::Immediate(Call::End) => self.end(),
            C::Immediate(Call::Vertex([x, y, z, w])) => self.vertex4f(*x, *y, *z, *w),
            C::Immediate(Call::Color([r, g, b, a])) => self.color4f(*r, *g, *b, *a),
            C::Immediate(Call::Normal([x, y, z])) => self.normal3f(*x, *y, *z),
            C::Immediate(Call::TexCoord([s, t, r, q])) => self.tex_coord4f(*s, *t, *r, *q),
            C::Immediate(Call::MultiTexCoord(unit, [s, t, r, q])) => {
                self.multi_tex_coord4f(GL_TEXTURE0 + GLenum::from(*unit), *s, *t, *r, *q);
            }
            C::Immediate(Call::SecondaryColor(rgba)) => self.secondary_color(*rgba),
            C::Immediate(Call::FogCoord(c)) => self.fog_coordf(*c),
            C::Enable(cap) => self.enable(*cap),
            C::Disable(cap) => self.disable(*cap),
            C::Lighting(call) => self.replay_lighting_call(call),
            C::Transform(call) => self.replay_transform_call(call),
            C::Viewport(call) => self.replay_viewport_call(*call),
            C::PolygonStipple(rows) => {
                if !self.reject_inside_begin_end() {
                    self.set_polygon_stipple(*rows);
                }
            }
            C::Clear(mask) => self.clear(*mask),
            C::Texture(call) => self.replay_texture_call(call),
            C::Eval(call) => self.replay_eval_call(call),
            C::Hint(target, mode) => self.hint(*target, *mode),
            C::Fog(pname, params) => self.fogfv(*pname, params),
            C::Attrib(call) => self.replay_attrib_call(call),
            C::ColorBuffer(call) => self.replay_color_buffer_call(*call),
            C::Stencil(call) => self.replay_stencil_call(*call),
            C::Scissor([x, y, w, h]) => self.scissor(*x, *y, *w, *h),
            C::SampleCoverage(value, invert) => self.sample_coverage(*value, *invert),
            C::Accum(call) => self.replay_accum_call(*call),
            C::Depth(call) => self.replay_depth_call(*call),
            C::Point(call) => self.replay_point_call(*call),
            C::Line(call) => self.replay_line_call(*call),
            C::Polygon(call) => self.replay_polygon_call(*call),
            C::EmitVertex(v) => self.emit_listed_vertex(*v),
            C::ScatteredMesh(jobs, triangles) => self.record_scattered_mesh(jobs.clone(), triangles.clone()),
            C::RasterPos([x, y, z, w]) => self.raster_pos4f(*x, *y, *z, *w),
            C::WindowPos([x, y, z]) => self.window_pos3f(*x, *y, *z),
            C::Bitmap(call, bits) => self.draw_bitmap(*call, bits.as_deref()),
            C::DrawPixels(size, format, type_, rgba) => self.draw_rgba(*size, *format, *type_, rgba.as_deref()),
            C::CopyPixels([x, y, w, h], type_) => self.copy_pixels(*x, *y, *w, *h, *type_),
            C::CopyTexture(call) => self.replay_copy_texture_call(call),
            C::ColorIndex(call) => self.replay_color_index_call(*call),
            C::PixelTransfer(call) => self.replay_pixel_transfer_call(call),
            C::CallList(list) => self.call_list(*list),
            C::CallLists(n, type_, names) => self.call_lists(*n, *type_, names),
            C::ListBase(base) => self.list_base(*base),
            C::EdgeFlag(flag) => self.edge_flag(*flag),
            C::BeginQuery(target, id) => self.begin_query(*target, *id),
            C::EndQuery(target) => self.end_query(*target),
            C::Error(code) => self.set_error(*code),
            C::Compressed(call) => self.replay_compressed_call(*call),
            C::Names(call) => self.replay_name_call(call),
            C::PassThrough(token) => self.pass_through(*token),
        }
    }
}

/// Bytes per name of a `glCallLists` type, `None` for a type GL does not take.
fn list_name_size(type_: GLenum) -> Option<usize> {
    match type_ {
        GL_BYTE | GL_UNSIGNED_BYTE => Some(1),
        GL_SHORT | GL_UNSIGNED_SHORT | GL_2_BYTES => Some(2),
        GL_3_BYTES => Some(3),
        GL_INT | GL_UNSIGNED_INT | GL_FLOAT | GL_4_BYTES => Some(4),
        _ => None,
    }
}

/// One name of a `glCallLists` array as the offset GL adds to the list base (Mesa
/// `translate_id`: floats are truncated towards zero, byte groups read big-endian).
fn list_offset(type_: GLenum, b: &[u8]) -> i32 {
    let big = |bytes: &[u8]| bytes.iter().fold(0u32, |acc, &x| (acc << 8) | u32::from(x)) as i32;
    match type_ {
        GL_BYTE => i32::from(b[0] as i8),
        GL_UNSIGNED_BYTE => i32::from(b[0]),
        GL_SHORT => i32::from(i16::from_ne_bytes([b[0], b[1]])),
        GL_UNSIGNED_SHORT => i32::from(u16::from_ne_bytes([b[0], b[1]])),
        GL_INT => i32::from_ne_bytes([b[0], b[1], b[2], b[3]]),
        GL_UNSIGNED_INT => u32::from_ne_bytes([b[0], b[1], b[2], b[3]]) as i32,
        GL_FLOAT => f32::from_ne_bytes([b[0], b[1], b[2], b[3]]) as i32,
        _ => big(b),
    }
}

/// The lists' `glGet` rows (GL 1.1 table 6.20): the list being compiled (0 and 0 when none)
/// and the base.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_LIST_BASE, 1, Kind::Int, |gl, o| put_enum(o, gl.lists.base)),
    row(GL_LIST_INDEX, 1, Kind::Int, |gl, o| put_enum(o, gl.lists.compiling.as_ref().map_or(0, |c| c.name))),
    row(GL_LIST_MODE, 1, Kind::Int, |gl, o| {
        let mode = |c: &Compiling| if c.execute { GL_COMPILE_AND_EXECUTE } else { GL_COMPILE };
        put_enum(o, gl.lists.compiling.as_ref().map_or(0, mode))
    }),
    int_limit!(GL_MAX_LIST_NESTING, MAX_LIST_NESTING),
];

#[cfg(test)]
mod tests {
    use super::*;

    fn triangle(gl: &mut Gl) {
        gl.begin(GL_TRIANGLES);
        gl.vertex2f(0.0, 0.0);
        gl.vertex2f(1.0, 0.0);
        gl.vertex2f(0.0, 1.0);
        gl.end();
    }

    #[test]
    fn compile_records_without_drawing_and_call_draws() {
        let mut gl = Gl::new(10, 10);
        let list = gl.gen_lists(1);
        assert_eq!(list, 1);
        gl.new_list(list, GL_COMPILE);
        triangle(&mut gl);
        gl.end_list();
        assert!(gl.frame().vertices.is_empty());
        gl.call_list(list);
        gl.call_list(list);
        assert_eq!(gl.frame().vertices.len(), 6);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn compile_and_execute_draws_once_while_compiling() {
        let mut gl = Gl::new(10, 10);
        gl.new_list(5, GL_COMPILE_AND_EXECUTE);
        triangle(&mut gl);
        gl.end_list();
        assert_eq!(gl.frame().vertices.len(), 3);
        assert_eq!(gl.is_list(5), GL_TRUE);
    }

    #[test]
    fn errors_are_raised_when_the_list_runs() {
        let mut gl = Gl::new(10, 10);
        gl.new_list(1, GL_COMPILE);
        gl.enable(0x1234);
        gl.end_list();
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        gl.call_list(1);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
    }

    #[test]
    fn a_draw_inside_begin_end_is_compiled_as_its_error() {
        // piglit's gl-1.0-beginend-coverage: glDrawArrays between glBegin and glEnd of a
        // GL_COMPILE_AND_EXECUTE list is an error when made and again when the list runs.
        let mut gl = Gl::new(10, 10);
        let v = crate::gl::ClientArray::new(&[0.0f32, 0.0]);
        gl.vertex_pointer(2, GL_FLOAT, 0, &v);
        gl.enable_client_state(GL_VERTEX_ARRAY);
        gl.new_list(1, GL_COMPILE_AND_EXECUTE);
        gl.begin(GL_POINTS);
        gl.draw_arrays(GL_POINTS, 0, 1);
        gl.end();
        gl.end_list();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.call_list(1);
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.begin(GL_POINTS);
        gl.draw_elements(GL_POINTS, 1, GL_UNSIGNED_BYTE, &[0u8]);
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
    }

    #[test]
    fn list_commands_errors_in_mesa_order() {
        let mut gl = Gl::new(10, 10);
        gl.new_list(0, 0x9999);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.new_list(1, 0x9999);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.end_list();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.new_list(1, GL_COMPILE);
        gl.new_list(2, GL_COMPILE);
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.end_list();
        assert_eq!(gl.gen_lists(-1), 0);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.delete_lists(1, -1);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.call_lists(1, GL_DOUBLE, &[0; 8]);
        assert_eq!(gl.get_error(), GL_INVALID_ENUM);
        gl.call_lists(-1, GL_UNSIGNED_BYTE, &[]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.call_list(0);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
    }

    #[test]
    fn maps_are_copied_when_compiled() {
        let mut gl = Gl::new(10, 10);
        let mut pts = [0.0f32, 0.0, 0.0, 9.0, 9.0, 9.0, 1.0, 1.0, 0.0];
        gl.new_list(1, GL_COMPILE);
        // Stride 6: only every other point is part of the map.
        gl.map1f(GL_MAP1_VERTEX_3, 0.0, 1.0, 6, 2, &pts);
        gl.end_list();
        pts.fill(5.0);
        gl.call_list(1);
        let mut coeffs = [0.0f32; 6];
        gl.get_mapfv(GL_MAP1_VERTEX_3, GL_COEFF, &mut coeffs);
        assert_eq!(coeffs, [0.0, 0.0, 0.0, 1.0, 1.0, 0.0]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn nesting_stops_at_mesas_limit() {
        let mut gl = Gl::new(10, 10);
        // List 1 draws a point and calls itself: 64 levels run, then the call is ignored.
        gl.new_list(1, GL_COMPILE);
        gl.begin(GL_POINTS);
        gl.vertex2f(0.0, 0.0);
        gl.end();
        gl.call_list(1);
        gl.end_list();
        gl.call_list(1);
        assert_eq!(gl.frame().vertices.len(), MAX_LIST_NESTING);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn call_lists_adds_the_base_to_each_name() {
        let mut gl = Gl::new(10, 10);
        let base = gl.gen_lists(3);
        assert_eq!(base, 1);
        for (i, n) in [1, 2, 3].into_iter().enumerate() {
            gl.new_list(base + i as u32, GL_COMPILE);
            gl.begin(GL_POINTS);
            for _ in 0..n {
                gl.vertex2f(0.0, 0.0);
            }
            gl.end();
            gl.end_list();
        }
        gl.list_base(base);
        gl.call_lists(3, GL_UNSIGNED_BYTE, &[2, 0, 7]);
        // Lists base+2 (3 points) and base+0 (1 point); base+7 does not exist.
        assert_eq!(gl.frame().vertices.len(), 4);
        gl.call_lists(1, GL_2_BYTES, &[0, 1]);
        assert_eq!(gl.frame().vertices.len(), 6);
        gl.call_lists(1, GL_FLOAT, &0.5f32.to_ne_bytes());
        assert_eq!(gl.frame().vertices.len(), 7);
        // Truncated towards zero, as Mesa does: -1.5 is list base - 1, which does not exist.
        gl.call_lists(1, GL_FLOAT, &(-1.5f32).to_ne_bytes());
        assert_eq!(gl.frame().vertices.len(), 7);
    }

    #[test]
    fn gen_lists_follows_the_largest_name_used() {
        let mut gl = Gl::new(10, 10);
        // Mesa hands out names after the largest ever used, even once it is deleted.
        gl.new_list(2, GL_COMPILE);
        gl.end_list();
        assert_eq!(gl.gen_lists(1), 3);
        assert_eq!(gl.gen_lists(2), 4);
        assert_eq!(gl.is_list(3), GL_TRUE);
        gl.delete_lists(1, 4);
        assert_eq!(gl.is_list(2), GL_FALSE);
        assert_eq!(gl.gen_lists(2), 6);
    }
}
