//! The call-script commands of `interp_arrays.c` (vertex arrays, the client attribute stack,
//! edge flags, selection, `glPassThrough`, the states feedback depends on) on `Gl`, and the
//! `gl_feedback` mode in which the runner prints gleval's own feedback buffer (FORMAT.md).

use super::Args;
use gleval::gl::{BufferMap, BufferOffset, ClientArray, ClientPointer, PointerArg};
use gleval::prelude::*;

/// The names these commands use, beyond the runner's table.
pub fn enum_value(token: &str) -> Option<u32> {
    let named = [
        ("GL_VERTEX_ARRAY", GL_VERTEX_ARRAY),
        ("GL_NORMAL_ARRAY", GL_NORMAL_ARRAY),
        ("GL_COLOR_ARRAY", GL_COLOR_ARRAY),
        ("GL_INDEX_ARRAY", GL_INDEX_ARRAY),
        ("GL_TEXTURE_COORD_ARRAY", GL_TEXTURE_COORD_ARRAY),
        ("GL_EDGE_FLAG_ARRAY", GL_EDGE_FLAG_ARRAY),
        ("GL_VERTEX_ARRAY_POINTER", GL_VERTEX_ARRAY_POINTER),
        ("GL_NORMAL_ARRAY_POINTER", GL_NORMAL_ARRAY_POINTER),
        ("GL_COLOR_ARRAY_POINTER", GL_COLOR_ARRAY_POINTER),
        ("GL_INDEX_ARRAY_POINTER", GL_INDEX_ARRAY_POINTER),
        ("GL_TEXTURE_COORD_ARRAY_POINTER", GL_TEXTURE_COORD_ARRAY_POINTER),
        ("GL_EDGE_FLAG_ARRAY_POINTER", GL_EDGE_FLAG_ARRAY_POINTER),
        ("GL_VERTEX_ARRAY_SIZE", GL_VERTEX_ARRAY_SIZE),
        ("GL_VERTEX_ARRAY_TYPE", GL_VERTEX_ARRAY_TYPE),
        ("GL_VERTEX_ARRAY_STRIDE", GL_VERTEX_ARRAY_STRIDE),
        ("GL_NORMAL_ARRAY_TYPE", GL_NORMAL_ARRAY_TYPE),
        ("GL_NORMAL_ARRAY_STRIDE", GL_NORMAL_ARRAY_STRIDE),
        ("GL_COLOR_ARRAY_SIZE", GL_COLOR_ARRAY_SIZE),
        ("GL_COLOR_ARRAY_TYPE", GL_COLOR_ARRAY_TYPE),
        ("GL_COLOR_ARRAY_STRIDE", GL_COLOR_ARRAY_STRIDE),
        ("GL_INDEX_ARRAY_TYPE", GL_INDEX_ARRAY_TYPE),
        ("GL_INDEX_ARRAY_STRIDE", GL_INDEX_ARRAY_STRIDE),
        ("GL_TEXTURE_COORD_ARRAY_SIZE", GL_TEXTURE_COORD_ARRAY_SIZE),
        ("GL_TEXTURE_COORD_ARRAY_TYPE", GL_TEXTURE_COORD_ARRAY_TYPE),
        ("GL_TEXTURE_COORD_ARRAY_STRIDE", GL_TEXTURE_COORD_ARRAY_STRIDE),
        ("GL_EDGE_FLAG_ARRAY_STRIDE", GL_EDGE_FLAG_ARRAY_STRIDE),
        ("GL_EDGE_FLAG", GL_EDGE_FLAG),
        ("GL_V2F", GL_V2F),
        ("GL_V3F", GL_V3F),
        ("GL_C4UB_V2F", GL_C4UB_V2F),
        ("GL_C4UB_V3F", GL_C4UB_V3F),
        ("GL_C3F_V3F", GL_C3F_V3F),
        ("GL_N3F_V3F", GL_N3F_V3F),
        ("GL_C4F_N3F_V3F", GL_C4F_N3F_V3F),
        ("GL_T2F_V3F", GL_T2F_V3F),
        ("GL_T4F_V4F", GL_T4F_V4F),
        ("GL_T2F_C4UB_V3F", GL_T2F_C4UB_V3F),
        ("GL_T2F_C3F_V3F", GL_T2F_C3F_V3F),
        ("GL_T2F_N3F_V3F", GL_T2F_N3F_V3F),
        ("GL_T2F_C4F_N3F_V3F", GL_T2F_C4F_N3F_V3F),
        ("GL_T4F_C4F_N3F_V4F", GL_T4F_C4F_N3F_V4F),
        ("GL_CLIENT_VERTEX_ARRAY_BIT", GL_CLIENT_VERTEX_ARRAY_BIT),
        ("GL_CLIENT_PIXEL_STORE_BIT", GL_CLIENT_PIXEL_STORE_BIT),
        ("GL_CLIENT_ALL_ATTRIB_BITS", GL_CLIENT_ALL_ATTRIB_BITS),
        ("GL_CLIENT_ATTRIB_STACK_DEPTH", GL_CLIENT_ATTRIB_STACK_DEPTH),
        ("GL_MAX_CLIENT_ATTRIB_STACK_DEPTH", GL_MAX_CLIENT_ATTRIB_STACK_DEPTH),
        ("GL_RENDER", GL_RENDER),
        ("GL_SELECT", GL_SELECT),
        ("GL_FEEDBACK", GL_FEEDBACK),
        ("GL_RENDER_MODE", GL_RENDER_MODE),
        ("GL_SELECTION_BUFFER_SIZE", GL_SELECTION_BUFFER_SIZE),
        ("GL_NAME_STACK_DEPTH", GL_NAME_STACK_DEPTH),
        ("GL_MAX_NAME_STACK_DEPTH", GL_MAX_NAME_STACK_DEPTH),
        ("GL_FEEDBACK_BUFFER_SIZE", GL_FEEDBACK_BUFFER_SIZE),
        ("GL_FEEDBACK_BUFFER_TYPE", GL_FEEDBACK_BUFFER_TYPE),
        ("GL_SELECTION_BUFFER_POINTER", GL_SELECTION_BUFFER_POINTER),
        ("GL_FEEDBACK_BUFFER_POINTER", GL_FEEDBACK_BUFFER_POINTER),
        ("GL_2D", GL_2D),
        ("GL_3D", GL_3D),
        ("GL_3D_COLOR", GL_3D_COLOR),
        ("GL_3D_COLOR_TEXTURE", GL_3D_COLOR_TEXTURE),
        ("GL_4D_COLOR_TEXTURE", GL_4D_COLOR_TEXTURE),
        ("GL_LIGHT0", GL_LIGHT0),
        ("GL_AMBIENT", GL_AMBIENT),
        ("GL_SPECULAR", GL_SPECULAR),
        ("GL_POSITION", GL_POSITION),
        ("GL_EMISSION", GL_EMISSION),
        ("GL_BACK", GL_BACK),
        ("GL_FRONT_AND_BACK", GL_FRONT_AND_BACK),
        ("GL_CW", GL_CW),
        ("GL_CCW", GL_CCW),
        ("GL_POLYGON_MODE", GL_POLYGON_MODE),
        ("GL_LIGHT_MODEL_TWO_SIDE", GL_LIGHT_MODEL_TWO_SIDE),
        ("GL_FLAT", GL_FLAT),
        ("GL_SMOOTH", GL_SMOOTH),
        ("GL_MODELVIEW", GL_MODELVIEW),
        ("GL_PROJECTION", GL_PROJECTION),
    ];
    named.iter().find(|(n, _)| *n == token).map(|(_, v)| *v)
}

/// interp.c's buffers: the client memory (64 KiB), the selection buffer (pre-filled with 7777).
pub struct Harness {
    pub mem: ClientArray,
    /// `buffer_offsets on`: pointer arguments are offsets into the bound buffers.
    pub buffer_offsets: bool,
    /// The last `map_buffer`'s mapping.
    pub mapped: Option<BufferMap>,
    select: Vec<u32>,
    select_size: usize,
    select_null: bool,
    select_set: bool,
    /// `gl_feedback`: read gleval's feedback buffer instead of emulating it.
    pub real_feedback: bool,
}

impl Default for Harness {
    fn default() -> Self {
        Self {
            mem: ClientArray::from_bytes(vec![0; 1 << 16]),
            buffer_offsets: false,
            mapped: None,
            select: vec![7777; 1024],
            select_size: 0,
            select_null: false,
            select_set: false,
            real_feedback: false,
        }
    }
}

const FEEDBACK_SIZE: i32 = 1 << 22;

impl Harness {
    /// `n` GLints of client memory from byte `offset` (C's `const GLint *`).
    fn ints(&self, offset: i32, n: usize) -> Vec<i32> {
        let bytes = self.mem.to_vec::<u8>();
        let from = usize::try_from(offset).unwrap_or(0);
        bytes[from..].chunks_exact(4).take(n).map(|b| i32::from_ne_bytes([b[0], b[1], b[2], b[3]])).collect()
    }

    /// A pointer argument as interp.c's `ptr_at` makes it.
    fn at(&self, offset: i32) -> Pointer {
        let offset = usize::try_from(offset).ok();
        if self.buffer_offsets {
            Pointer::Offset(BufferOffset(offset.unwrap_or(0)))
        } else {
            Pointer::Client(offset.map(|o| self.mem.at_byte(o)))
        }
    }

    /// An element draw's index pointer: an offset (`buffer_offsets on`) or client bytes.
    fn indices(&self, offset: i32) -> Result<usize, Vec<u8>> {
        if self.buffer_offsets {
            return Ok(usize::try_from(offset).unwrap_or(0));
        }
        let bytes = self.mem.to_vec::<u8>();
        Err(usize::try_from(offset).map_or(Vec::new(), |o| bytes[o..].to_vec()))
    }

    fn write_mem(&self, offset: usize, type_: u32, values: &[f64]) {
        for (i, &x) in values.iter().enumerate() {
            let ok = match type_ {
                GL_BYTE => self.mem.write(offset + i, &[x as i8]),
                GL_UNSIGNED_BYTE => self.mem.write(offset + i, &[x as u8]),
                GL_SHORT => write_at(&self.mem, offset + 2 * i, &(x as i16).to_ne_bytes()),
                GL_UNSIGNED_SHORT => write_at(&self.mem, offset + 2 * i, &(x as u16).to_ne_bytes()),
                GL_INT => write_at(&self.mem, offset + 4 * i, &(x as i32).to_ne_bytes()),
                GL_UNSIGNED_INT => write_at(&self.mem, offset + 4 * i, &(x as u32).to_ne_bytes()),
                GL_FLOAT => write_at(&self.mem, offset + 4 * i, &(x as f32).to_ne_bytes()),
                _ => write_at(&self.mem, offset + 8 * i, &x.to_ne_bytes()),
            };
            assert!(ok, "client_mem out of range");
        }
    }

    /// Names a pointer as interp.c prints it.
    fn pointer_name(&self, pname: u32, p: Option<&ClientPointer>) -> String {
        match (pname, p) {
            (GL_FEEDBACK_BUFFER_POINTER, _) => "feedback+0".into(),
            (GL_SELECTION_BUFFER_POINTER, _) if self.select_set && !self.select_null => "select+0".into(),
            (_, Some(p)) if p.points_into(&self.mem) => format!("mem+{}", p.offset()),
            // An offset into a buffer, printed as the C ABI's pointer of that value is.
            (_, Some(p)) if p.offset() != 0 => format!("offset+{}", p.offset()),
            (_, _) => "null".into(),
        }
    }

    /// Runs one of this file's commands; false when `cmd` is not one.
    pub fn run(&mut self, gl: &mut Gl, cmd: &str, a: &mut Args, values: &mut Vec<String>) -> bool {
        match cmd {
            "client_mem" => {
                let (offset, type_) = (a.int() as usize, a.e());
                self.write_mem(offset, type_, &a.array());
            }
            "vertex_pointer" => {
                let (size, type_, stride, offset) = (a.int(), a.e(), a.int(), a.int());
                gl.vertex_pointer(size, type_, stride, self.at(offset));
            }
            "color_pointer" => {
                let (size, type_, stride, offset) = (a.int(), a.e(), a.int(), a.int());
                gl.color_pointer(size, type_, stride, self.at(offset));
            }
            "secondary_color_pointer" => {
                let (size, type_, stride, offset) = (a.int(), a.e(), a.int(), a.int());
                gl.secondary_color_pointer(size, type_, stride, self.at(offset));
            }
            "tex_coord_pointer" => {
                let (size, type_, stride, offset) = (a.int(), a.e(), a.int(), a.int());
                gl.tex_coord_pointer(size, type_, stride, self.at(offset));
            }
            "normal_pointer" => {
                let (type_, stride, offset) = (a.e(), a.int(), a.int());
                gl.normal_pointer(type_, stride, self.at(offset));
            }
            "fog_coord_pointer" => {
                let (type_, stride, offset) = (a.e(), a.int(), a.int());
                gl.fog_coord_pointer(type_, stride, self.at(offset));
            }
            "index_pointer" => {
                let (type_, stride, offset) = (a.e(), a.int(), a.int());
                gl.index_pointer(type_, stride, self.at(offset));
            }
            "edge_flag_pointer" => {
                let (stride, offset) = (a.int(), a.int());
                gl.edge_flag_pointer(stride, self.at(offset));
            }
            "interleaved_arrays" => {
                let (format, stride, offset) = (a.e(), a.int(), a.int());
                gl.interleaved_arrays(format, stride, self.at(offset));
            }
            "enable_client_state" => gl.enable_client_state(a.e()),
            "disable_client_state" => gl.disable_client_state(a.e()),
            "array_element" => gl.array_element(a.int()),
            "draw_arrays" => gl.draw_arrays(a.e(), a.int(), a.int()),
            "draw_elements" => {
                let (mode, count, type_, offset) = (a.e(), a.int(), a.e(), a.int());
                match self.indices(offset) {
                    Ok(offset) => gl.draw_elements_offset(mode, count, type_, offset),
                    Err(indices) => gl.draw_elements(mode, count, type_, &indices),
                }
            }
            "draw_range_elements" => {
                let (mode, start, end, count, type_, offset) = (a.e(), a.int(), a.int(), a.int(), a.e(), a.int());
                let (start, end) = (start as u32, end as u32);
                match self.indices(offset) {
                    Ok(offset) => gl.draw_range_elements_offset(mode, start, end, count, type_, offset),
                    Err(indices) => gl.draw_range_elements(mode, start, end, count, type_, &indices),
                }
            }
            "multi_draw_arrays" => {
                let (mode, firsts, counts, primcount) = (a.e(), a.int(), a.int(), a.int());
                let n = usize::try_from(primcount).unwrap_or(0);
                let (first, count) = (self.ints(firsts, n), self.ints(counts, n));
                gl.multi_draw_arrays(mode, &first, &count, primcount);
            }
            "multi_draw_elements" => {
                let (mode, counts, type_, primcount) = (a.e(), a.int(), a.e(), a.int());
                let n = usize::try_from(primcount).unwrap_or(0);
                let count = self.ints(counts, n);
                let bytes = self.mem.to_vec::<u8>();
                let offsets: Vec<usize> = (0..n.min(8)).map(|_| a.int() as usize).collect();
                if self.buffer_offsets {
                    gl.multi_draw_elements_offset(mode, &count, type_, &offsets, primcount);
                } else {
                    let indices: Vec<&[u8]> = offsets.iter().map(|&o| &bytes[o..]).collect();
                    gl.multi_draw_elements(mode, &count, type_, &indices, primcount);
                }
            }
            "get_pointerv" => {
                let pname = a.e();
                let known = gl.get_pointerv_error(pname).is_none();
                let p = gl.get_pointerv(pname);
                values.push(if known { self.pointer_name(pname, p.as_ref()) } else { "unwritten".into() });
            }
            "push_client_attrib" => gl.push_client_attrib(a.e()),
            "pop_client_attrib" => gl.pop_client_attrib(),
            "edge_flag" => gl.edge_flag(a.int() as u8),
            "select_buffer" | "select_buffer_null" => {
                let size = a.int();
                self.select.fill(7777);
                let takes = size >= 0 && !gl.inside_begin_end() && gl.render_mode_value() != GL_SELECT;
                gl.select_buffer(size);
                if takes {
                    (self.select_null, self.select_set) = (cmd == "select_buffer_null", true);
                }
                self.select_size = size.clamp(0, 64) as usize;
            }
            "render_mode" => {
                let before = if gl.inside_begin_end() { 0 } else { gl.render_mode_value() };
                let n = gl.render_mode(a.e());
                values.push(n.to_string());
                if before == GL_SELECT {
                    if !self.select_null {
                        let written = gl.select_values();
                        self.select[..written.len()].copy_from_slice(written);
                    }
                    values.extend(self.select[..self.select_size].iter().map(u32::to_string));
                }
            }
            "init_names" => gl.init_names(),
            "load_name" => gl.load_name(a.int() as u32),
            "push_name" => gl.push_name(a.int() as u32),
            "pop_name" => gl.pop_name(),
            "pass_through" => gl.pass_through(a.f()),
            "gl_feedback" => {
                self.real_feedback = true;
                start_feedback(gl);
            }
            "lightfv" => gl.light_fv(a.e(), a.e(), &a.floats()),
            "materialfv" => gl.material_fv(a.e(), a.e(), &a.floats()),
            "polygon_mode" => gl.polygon_mode(a.e(), a.e()),
            "cull_face" => gl.cull_face(a.e()),
            "front_face" => gl.front_face(a.e()),
            "shade_model" => gl.shade_model(a.e()),
            "ortho" => gl.ortho(a.d(), a.d(), a.d(), a.d(), a.d(), a.d()),
            "viewport" => gl.viewport(a.int(), a.int(), a.int(), a.int()),
            "depth_range" => gl.depth_range(a.d(), a.d()),
            "matrix_mode" => gl.matrix_mode(a.e()),
            _ => return self.run_buffers(gl, cmd, a, values),
        }
        true
    }

    /// With `gl_feedback`: the feedback lines since the last collection, read from gleval's
    /// feedback buffer, as interp.c's `collect_feedback` prints Mesa's.
    pub fn collect(&mut self, gl: &mut Gl) -> Vec<String> {
        let mut lines = Vec::new();
        match gl.render_mode_value() {
            GL_SELECT => {}
            GL_RENDER => start_feedback(gl),
            _ => {
                let n = gl.render_mode(GL_RENDER);
                if n < 0 {
                    lines.push("fb overflow".to_owned());
                }
                lines.extend(token_lines(&gl.feedback_values()[..n.max(0) as usize]));
                start_feedback(gl);
            }
        }
        lines
    }
}

fn write_at(mem: &ClientArray, offset: usize, bytes: &[u8]) -> bool {
    mem.write(offset, bytes)
}

fn start_feedback(gl: &mut Gl) {
    gl.feedback_buffer(FEEDBACK_SIZE, GL_4D_COLOR_TEXTURE);
    gl.render_mode(GL_FEEDBACK);
}

/// A `GL_4D_COLOR_TEXTURE` buffer as interp.c's lines.
fn token_lines(fb: &[f32]) -> Vec<String> {
    let mut lines = Vec::new();
    let mut i = 0;
    let vertex = |at: usize| fb[at..at + 12].iter().map(|v| format!(" {v}")).collect::<String>();
    while i < fb.len() {
        let token = fb[i] as u32;
        i += 1;
        let (name, n) = match token {
            GL_POINT_TOKEN => ("fb point".to_owned(), 1),
            GL_LINE_TOKEN => ("fb line".to_owned(), 2),
            GL_LINE_RESET_TOKEN => ("fb line_reset".to_owned(), 2),
            GL_POLYGON_TOKEN => {
                let n = fb[i] as usize;
                i += 1;
                (format!("fb polygon {n}"), n)
            }
            GL_BITMAP_TOKEN => ("fb bitmap".to_owned(), 1),
            GL_DRAW_PIXEL_TOKEN => ("fb draw_pixel".to_owned(), 1),
            GL_COPY_PIXEL_TOKEN => ("fb copy_pixel".to_owned(), 1),
            GL_PASS_THROUGH_TOKEN => {
                lines.push(format!("fb pass_through {}", fb[i]));
                i += 1;
                continue;
            }
            other => panic!("unknown feedback token {other}"),
        };
        let mut line = name;
        for _ in 0..n {
            line.push_str(&vertex(i));
            i += 12;
        }
        lines.push(line);
    }
    lines
}

/// A pointer argument: client memory, or an offset into a buffer object.
enum Pointer {
    Client(Option<ClientPointer>),
    Offset(BufferOffset),
}

impl PointerArg for Pointer {
    fn into_pointer(self) -> Option<ClientPointer> {
        match self {
            Pointer::Client(p) => p,
            Pointer::Offset(o) => o.into_pointer(),
        }
    }

    fn buffer_offset(&self) -> usize {
        match self {
            Pointer::Client(_) => 0,
            Pointer::Offset(o) => o.buffer_offset(),
        }
    }
}
