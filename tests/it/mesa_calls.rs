//! Differential test against real Mesa: every script in `tests/reference/calls/cases` is run on
//! our `Gl` and its output compared with what Mesa 22.3 (OSMesa) printed for the same script
//! (`expected/*.out`, regenerated from real Mesa by `regen.sh`; CI checks they still match).
//! The format and the feedback conventions are in `tests/reference/calls/FORMAT.md`.

mod arrays;
mod buffers;

use gleval::gl::MapTarget;
use gleval::prelude::*;
use std::path::{Path, PathBuf};

#[path = "mesa_calls_pixels.rs"]
mod pixels;
#[path = "mesa_calls_queries.rs"]
mod queries;

fn calls_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/calls")
}

/// Cases where we follow the spec or our convention instead of Mesa (FORMAT.md §5).
const DEVIATIONS: &[(&str, &str)] = &[
    ("quirks.calls", "Mesa lets evaluated values leak into never-set current state; the spec forbids it"),
    ("map2_null_points", "a missing point array is GL_INVALID_VALUE in gleval; Mesa accepts NULL in glMap2"),
    (
        "max_texture_size",
        "GL_MAX_TEXTURE_SIZE is wgpu's 8192, the largest texture gleval's renderer makes; llvmpipe says 16384",
    ),
    (
        "compressed_formats_listed",
        "gleval lists no compressed texture format (src/gl/texture/compressed.rs says why); llvmpipe lists 12",
    ),
    (
        "mt_active_texture_errors",
        "glActiveTexture(GL_TEXTURE8) is GL_INVALID_ENUM in gleval, which has no shaders and so 8 units in all \
         (piglit's texunits); llvmpipe takes units up to its 192 shader image units",
    ),
    (
        "mt_unit_beyond_the_fixed_function_units",
        "gleval cannot select GL_TEXTURE8 (see mt_active_texture_errors), so the calls after it act on unit 0",
    ),
];

fn enum_value(token: &str) -> u32 {
    let named = [
        ("GL_AUTO_NORMAL", GL_AUTO_NORMAL),
        ("GL_COEFF", GL_COEFF),
        ("GL_ORDER", GL_ORDER),
        ("GL_DOMAIN", GL_DOMAIN),
        ("GL_POINT", GL_POINT),
        ("GL_LINE", GL_LINE),
        ("GL_FILL", GL_FILL),
        ("GL_POINTS", GL_POINTS),
        ("GL_LINES", GL_LINES),
        ("GL_LINE_LOOP", GL_LINE_LOOP),
        ("GL_LINE_STRIP", GL_LINE_STRIP),
        ("GL_TRIANGLES", GL_TRIANGLES),
        ("GL_TRIANGLE_STRIP", GL_TRIANGLE_STRIP),
        ("GL_TRIANGLE_FAN", GL_TRIANGLE_FAN),
        ("GL_QUADS", GL_QUADS),
        ("GL_QUAD_STRIP", GL_QUAD_STRIP),
        ("GL_POLYGON", GL_POLYGON),
        ("GL_MAX_EVAL_ORDER", GL_MAX_EVAL_ORDER),
        ("GL_MAP1_GRID_DOMAIN", GL_MAP1_GRID_DOMAIN),
        ("GL_MAP1_GRID_SEGMENTS", GL_MAP1_GRID_SEGMENTS),
        ("GL_MAP2_GRID_DOMAIN", GL_MAP2_GRID_DOMAIN),
        ("GL_MAP2_GRID_SEGMENTS", GL_MAP2_GRID_SEGMENTS),
        ("GL_TEXTURE_2D", GL_TEXTURE_2D),
        ("GL_LIGHTING", GL_LIGHTING),
        ("GL_NORMALIZE", GL_NORMALIZE),
        ("GL_COMPILE", GL_COMPILE),
        ("GL_COMPILE_AND_EXECUTE", GL_COMPILE_AND_EXECUTE),
        ("GL_LIST_BASE", GL_LIST_BASE),
        ("GL_LIST_INDEX", GL_LIST_INDEX),
        ("GL_LIST_MODE", GL_LIST_MODE),
        ("GL_MAX_LIST_NESTING", GL_MAX_LIST_NESTING),
        ("GL_BYTE", GL_BYTE),
        ("GL_UNSIGNED_BYTE", GL_UNSIGNED_BYTE),
        ("GL_SHORT", GL_SHORT),
        ("GL_UNSIGNED_SHORT", GL_UNSIGNED_SHORT),
        ("GL_INT", GL_INT),
        ("GL_UNSIGNED_INT", GL_UNSIGNED_INT),
        ("GL_FLOAT", GL_FLOAT),
        ("GL_2_BYTES", GL_2_BYTES),
        ("GL_3_BYTES", GL_3_BYTES),
        ("GL_4_BYTES", GL_4_BYTES),
        ("GL_DOUBLE", GL_DOUBLE),
        ("GL_SRC_ALPHA", GL_SRC_ALPHA),
        ("GL_ONE_MINUS_SRC_ALPHA", GL_ONE_MINUS_SRC_ALPHA),
        ("GL_ONE", GL_ONE),
        ("GL_ZERO", GL_ZERO),
        ("GL_SRC_ALPHA_SATURATE", GL_SRC_ALPHA_SATURATE),
        ("GL_GREATER", GL_GREATER),
        ("GL_ALWAYS", GL_ALWAYS),
        ("GL_NEVER", GL_NEVER),
        ("GL_FOG_MODE", GL_FOG_MODE),
        ("GL_FOG_DENSITY", GL_FOG_DENSITY),
        ("GL_FOG_START", GL_FOG_START),
        ("GL_FOG_END", GL_FOG_END),
        ("GL_EXP", GL_EXP),
        ("GL_EXP2", GL_EXP2),
        ("GL_ALPHA_TEST", GL_ALPHA_TEST),
        ("GL_CURRENT_COLOR", GL_CURRENT_COLOR),
        ("GL_CURRENT_NORMAL", GL_CURRENT_NORMAL),
        ("GL_CURRENT_TEXTURE_COORDS", GL_CURRENT_TEXTURE_COORDS),
        ("GL_CURRENT_RASTER_POSITION", GL_CURRENT_RASTER_POSITION),
        ("GL_CURRENT_RASTER_POSITION_VALID", GL_CURRENT_RASTER_POSITION_VALID),
        ("GL_CURRENT_RASTER_COLOR", GL_CURRENT_RASTER_COLOR),
        ("GL_CURRENT_RASTER_TEXTURE_COORDS", GL_CURRENT_RASTER_TEXTURE_COORDS),
        ("GL_CURRENT_RASTER_DISTANCE", GL_CURRENT_RASTER_DISTANCE),
        ("GL_COLOR_INDEX", GL_COLOR_INDEX),
        ("GL_STENCIL_INDEX", GL_STENCIL_INDEX),
        ("GL_DEPTH_COMPONENT", GL_DEPTH_COMPONENT),
        ("GL_RED", GL_RED),
        ("GL_GREEN", GL_GREEN),
        ("GL_BLUE", GL_BLUE),
        ("GL_BGR", GL_BGR),
        ("GL_BGRA", GL_BGRA),
        ("GL_BITMAP", GL_BITMAP),
        ("GL_UNSIGNED_SHORT_5_6_5", GL_UNSIGNED_SHORT_5_6_5),
        ("GL_UNSIGNED_SHORT_4_4_4_4", GL_UNSIGNED_SHORT_4_4_4_4),
        ("GL_UNSIGNED_BYTE_3_3_2", GL_UNSIGNED_BYTE_3_3_2),
        ("GL_UNSIGNED_INT_8_8_8_8_REV", GL_UNSIGNED_INT_8_8_8_8_REV),
        ("GL_PERSPECTIVE_CORRECTION_HINT", GL_PERSPECTIVE_CORRECTION_HINT),
        ("GL_POINT_SMOOTH_HINT", GL_POINT_SMOOTH_HINT),
        ("GL_LINE_SMOOTH_HINT", GL_LINE_SMOOTH_HINT),
        ("GL_POLYGON_SMOOTH_HINT", GL_POLYGON_SMOOTH_HINT),
        ("GL_FOG_HINT", GL_FOG_HINT),
        ("GL_DONT_CARE", GL_DONT_CARE),
        ("GL_FASTEST", GL_FASTEST),
        ("GL_NICEST", GL_NICEST),
        ("GL_HINT_BIT", GL_HINT_BIT),
        ("GL_S", GL_S),
        ("GL_T", GL_T),
        ("GL_R", GL_R),
        ("GL_Q", GL_Q),
        ("GL_TEXTURE_GEN_MODE", GL_TEXTURE_GEN_MODE),
        ("GL_OBJECT_PLANE", GL_OBJECT_PLANE),
        ("GL_EYE_PLANE", GL_EYE_PLANE),
        ("GL_OBJECT_LINEAR", GL_OBJECT_LINEAR),
        ("GL_EYE_LINEAR", GL_EYE_LINEAR),
        ("GL_SPHERE_MAP", GL_SPHERE_MAP),
        ("GL_NORMAL_MAP", GL_NORMAL_MAP),
        ("GL_REFLECTION_MAP", GL_REFLECTION_MAP),
        ("GL_TEXTURE_GEN_S", GL_TEXTURE_GEN_S),
        ("GL_TEXTURE_GEN_T", GL_TEXTURE_GEN_T),
        ("GL_TEXTURE_GEN_Q", GL_TEXTURE_GEN_Q),
        ("GL_ENABLE_BIT", GL_ENABLE_BIT),
        ("GL_EVAL_BIT", GL_EVAL_BIT),
        ("GL_CURRENT_BIT", GL_CURRENT_BIT),
        ("GL_LIGHTING_BIT", GL_LIGHTING_BIT),
        ("GL_TEXTURE_BIT", GL_TEXTURE_BIT),
        ("GL_ALL_ATTRIB_BITS", GL_ALL_ATTRIB_BITS),
        ("GL_CULL_FACE", GL_CULL_FACE),
        ("GL_DEPTH_TEST", GL_DEPTH_TEST),
        ("GL_BLEND", GL_BLEND),
        ("GL_FOG", GL_FOG),
        ("GL_TEXTURE_1D", GL_TEXTURE_1D),
        ("GL_RGB", GL_RGB),
        ("GL_RGBA", GL_RGBA),
        ("GL_LUMINANCE", GL_LUMINANCE),
        ("GL_LUMINANCE_ALPHA", GL_LUMINANCE_ALPHA),
        ("GL_ALPHA", GL_ALPHA),
        ("GL_TEXTURE_MIN_FILTER", GL_TEXTURE_MIN_FILTER),
        ("GL_TEXTURE_MAG_FILTER", GL_TEXTURE_MAG_FILTER),
        ("GL_TEXTURE_WRAP_S", GL_TEXTURE_WRAP_S),
        ("GL_TEXTURE_WRAP_T", GL_TEXTURE_WRAP_T),
        ("GL_NEAREST", GL_NEAREST),
        ("GL_LINEAR", GL_LINEAR),
        ("GL_LINEAR_MIPMAP_LINEAR", GL_LINEAR_MIPMAP_LINEAR),
        ("GL_NEAREST_MIPMAP_NEAREST", GL_NEAREST_MIPMAP_NEAREST),
        ("GL_REPEAT", GL_REPEAT),
        ("GL_CLAMP", GL_CLAMP),
        ("GL_CLAMP_TO_EDGE", GL_CLAMP_TO_EDGE),
        ("GL_TEXTURE_ENV", GL_TEXTURE_ENV),
        ("GL_TEXTURE_ENV_MODE", GL_TEXTURE_ENV_MODE),
        ("GL_TEXTURE_ENV_COLOR", GL_TEXTURE_ENV_COLOR),
        ("GL_MODULATE", GL_MODULATE),
        ("GL_DECAL", GL_DECAL),
        ("GL_BLEND", GL_BLEND),
        ("GL_REPLACE", GL_REPLACE),
        ("GL_ADD", GL_ADD),
        ("GL_UNPACK_ALIGNMENT", GL_UNPACK_ALIGNMENT),
        ("GL_UNPACK_ROW_LENGTH", GL_UNPACK_ROW_LENGTH),
        ("GL_UNPACK_SKIP_ROWS", GL_UNPACK_SKIP_ROWS),
        ("GL_PACK_ALIGNMENT", GL_PACK_ALIGNMENT),
        ("GL_TEXTURE_BINDING_1D", GL_TEXTURE_BINDING_1D),
        ("GL_TEXTURE_BINDING_2D", GL_TEXTURE_BINDING_2D),
        ("GL_LINE_STIPPLE", GL_LINE_STIPPLE),
        ("GL_LINE_SMOOTH", GL_LINE_SMOOTH),
        ("GL_POINT_SMOOTH", GL_POINT_SMOOTH),
        ("GL_POLYGON_OFFSET_FILL", GL_POLYGON_OFFSET_FILL),
        ("GL_POLYGON_OFFSET_LINE", GL_POLYGON_OFFSET_LINE),
        ("GL_POLYGON_OFFSET_POINT", GL_POLYGON_OFFSET_POINT),
        ("GL_CLIP_PLANE0", GL_CLIP_PLANE0),
        ("GL_CLIP_PLANE1", GL_CLIP_PLANE1),
        ("GL_CLIP_PLANE2", GL_CLIP_PLANE2),
        ("GL_CLIP_PLANE3", GL_CLIP_PLANE3),
        ("GL_CLIP_PLANE4", GL_CLIP_PLANE4),
        ("GL_CLIP_PLANE5", GL_CLIP_PLANE5),
        ("GL_LINE_STIPPLE_PATTERN", GL_LINE_STIPPLE_PATTERN),
        ("GL_LINE_STIPPLE_REPEAT", GL_LINE_STIPPLE_REPEAT),
        ("GL_POLYGON_OFFSET_FACTOR", GL_POLYGON_OFFSET_FACTOR),
        ("GL_POLYGON_OFFSET_UNITS", GL_POLYGON_OFFSET_UNITS),
        ("GL_MAX_CLIP_PLANES", GL_MAX_CLIP_PLANES),
        ("GL_LINE_BIT", GL_LINE_BIT),
        ("GL_POLYGON_BIT", GL_POLYGON_BIT),
        ("GL_TRANSFORM_BIT", GL_TRANSFORM_BIT),
        ("GL_FRONT", GL_FRONT),
        ("GL_DIFFUSE", GL_DIFFUSE),
        ("GL_SHININESS", GL_SHININESS),
        ("GL_POLYGON_STIPPLE", GL_POLYGON_STIPPLE),
        ("GL_POLYGON_STIPPLE_BIT", GL_POLYGON_STIPPLE_BIT),
    ];
    if let Some((_, v)) = named.iter().find(|(n, _)| *n == token) {
        return *v;
    }
    if let Some(unit) = token.strip_prefix("GL_TEXTURE").and_then(|n| n.parse::<u32>().ok()) {
        return GL_TEXTURE0 + unit;
    }
    let targets = [
        "COLOR_4",
        "INDEX",
        "NORMAL",
        "TEXTURE_COORD_1",
        "TEXTURE_COORD_2",
        "TEXTURE_COORD_3",
        "TEXTURE_COORD_4",
        "VERTEX_3",
        "VERTEX_4",
    ];
    for (dim, base) in [("GL_MAP1_", GL_MAP1_COLOR_4), ("GL_MAP2_", GL_MAP2_COLOR_4)] {
        if let Some(rest) = token.strip_prefix(dim) {
            if let Some(i) = targets.iter().position(|t| *t == rest) {
                return base + i as u32;
            }
        }
    }
    if let Some(v) = arrays::enum_value(token) {
        return v;
    }
    if let Some(v) = queries::named_enum(token) {
        return v;
    }
    if let Some(hex) = token.strip_prefix("0x") {
        return u32::from_str_radix(hex, 16).unwrap_or_else(|_| panic!("bad enum {token}"));
    }
    // A negative integer where C's interp reads `strtol` into a GLuint.
    token.parse().or_else(|_| token.parse::<i32>().map(|v| v as u32)).unwrap_or_else(|_| panic!("unknown enum {token}"))
}

/// An image's numbers as interp.c passes them: floats for `GL_FLOAT`, else bytes.
fn image_bytes(type_: u32, numbers: &[f32]) -> Vec<u8> {
    if type_ == GL_FLOAT {
        bytemuck_floats(numbers)
    } else {
        numbers.iter().map(|&x| x as u8).collect()
    }
}

/// Floats as the bytes C's array holds (native byte order).
fn bytemuck_floats(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_ne_bytes()).collect()
}

/// Splits a script line into tokens, with `[` and `]` always separate.
fn tokenize(line: &str) -> Vec<String> {
    let line = line.split('#').next().unwrap_or("");
    line.replace('[', " [ ").replace(']', " ] ").split_whitespace().map(str::to_owned).collect()
}

/// A parsed line's arguments.
struct Args<'a> {
    tokens: &'a [String],
    at: usize,
}

impl Args<'_> {
    fn next(&mut self) -> &str {
        self.at += 1;
        &self.tokens[self.at - 1]
    }
    fn int(&mut self) -> i32 {
        self.next().parse().expect("int")
    }
    fn f(&mut self) -> f32 {
        self.next().parse().expect("float")
    }
    fn d(&mut self) -> f64 {
        self.next().parse().expect("double")
    }
    fn e(&mut self) -> u32 {
        enum_value(self.next())
    }
    /// `[ v ... ]` or `null` (an empty slice).
    fn array(&mut self) -> Vec<f64> {
        if self.next() == "null" {
            return Vec::new();
        }
        let mut out = Vec::new();
        loop {
            let t = self.next();
            if t == "]" {
                return out;
            }
            out.push(t.parse().expect("array value"));
        }
    }
    fn floats(&mut self) -> Vec<f32> {
        self.array().iter().map(|&v| v as f32).collect()
    }
}

/// Runs one script on `Gl`, producing output lines in interp.c's format.
struct Runner {
    gl: Gl,
    inside: bool,
    deferred: bool,
    texgen_normal: bool,
    /// A list is being compiled (see `run_line`).
    compiling: bool,
    /// The vertex-array, selection and feedback commands' buffers.
    arrays: arrays::Harness,
    collected: usize,
    out: Vec<String>,
}

impl Runner {
    fn new() -> Self {
        Self {
            gl: fresh_gl(),
            inside: false,
            deferred: false,
            texgen_normal: false,
            compiling: false,
            arrays: arrays::Harness::default(),
            collected: 0,
            out: Vec::new(),
        }
    }

    /// What a new context of the case starts with besides `Gl` itself.
    fn case_state_reset(&mut self) {
        self.inside = false;
        self.deferred = false;
        self.texgen_normal = false;
        self.compiling = false;
        self.arrays = arrays::Harness::default();
        self.collected = 0;
    }

    fn case(&mut self, name: &str) {
        self.gl = fresh_gl();
        self.case_state_reset();
        self.out.push(format!("case {name}"));
    }

    fn run_line(&mut self, number: usize, tokens: &[String]) {
        let cmd = tokens[0].as_str();
        if cmd == "case" {
            return self.case(&tokens[1]);
        }
        if cmd == "buffers" {
            let mut a = Args { tokens, at: 1 };
            let (stencil, accum) = (a.int() as u8, a.int() as u8);
            self.case_state_reset();
            self.gl = fresh_gl_with(stencil, accum);
            self.out.push(format!("{number} buffers err=-"));
            return;
        }
        let mut a = Args { tokens, at: 1 };
        let mut values: Vec<String> = Vec::new();
        // The feedback token a glBitmap or glDrawPixels writes if it succeeds.
        let mut raster_token = None;
        // glCopyPixels calls executed by this line (directly or from a list) each write one.
        let copies = self.gl.frame().pixel_copies.len();
        let gl = &mut self.gl;
        match cmd {
            "map1f" => {
                let (t, u1, u2, s, o) = (a.e(), a.f(), a.f(), a.int(), a.int());
                gl.map1f(t, u1, u2, s, o, &a.floats());
            }
            "map1d" => {
                let (t, u1, u2, s, o) = (a.e(), a.d(), a.d(), a.int(), a.int());
                gl.map1d(t, u1, u2, s, o, &a.array());
            }
            "map2f" => {
                let (t, u1, u2, us, uo, v1, v2, vs, vo) =
                    (a.e(), a.f(), a.f(), a.int(), a.int(), a.f(), a.f(), a.int(), a.int());
                gl.map2f(t, u1, u2, us, uo, v1, v2, vs, vo, &a.floats());
            }
            "map2d" => {
                let (t, u1, u2, us, uo, v1, v2, vs, vo) =
                    (a.e(), a.d(), a.d(), a.int(), a.int(), a.d(), a.d(), a.int(), a.int());
                gl.map2d(t, u1, u2, us, uo, v1, v2, vs, vo, &a.array());
            }
            "map_grid1f" => gl.map_grid1f(a.int(), a.f(), a.f()),
            "map_grid1d" => gl.map_grid1d(a.int(), a.d(), a.d()),
            "map_grid2f" => gl.map_grid2f(a.int(), a.f(), a.f(), a.int(), a.f(), a.f()),
            "map_grid2d" => gl.map_grid2d(a.int(), a.d(), a.d(), a.int(), a.d(), a.d()),
            "eval_coord1f" => gl.eval_coord1f(a.f()),
            "eval_coord1d" => gl.eval_coord1d(a.d()),
            "eval_coord2f" => gl.eval_coord2f(a.f(), a.f()),
            "eval_coord2d" => gl.eval_coord2d(a.d(), a.d()),
            "eval_point1" => gl.eval_point1(a.int()),
            "eval_point2" => gl.eval_point2(a.int(), a.int()),
            "eval_mesh1" => gl.eval_mesh1(a.e(), a.int(), a.int()),
            "eval_mesh2" => gl.eval_mesh2(a.e(), a.int(), a.int(), a.int(), a.int()),
            "enable" => gl.enable(a.e()),
            "disable" => gl.disable(a.e()),
            "is_enabled" => values.push(gl.is_enabled(a.e()).to_string()),
            "begin" => {
                gl.begin(a.e());
                self.inside = true;
            }
            "end" => {
                gl.end();
                self.inside = false;
            }
            "vertex3f" => gl.vertex3f(a.f(), a.f(), a.f()),
            "vertex4f" => gl.vertex4f(a.f(), a.f(), a.f(), a.f()),
            "color4f" => gl.color4f(a.f(), a.f(), a.f(), a.f()),
            "normal3f" => gl.normal3f(a.f(), a.f(), a.f()),
            "tex_coord4f" => gl.tex_coord4f(a.f(), a.f(), a.f(), a.f()),
            "active_texture" => gl.active_texture(a.e()),
            "get_mapfv" | "get_mapdv" | "get_mapiv" => values = get_map(gl, cmd, a.e(), a.e()),
            "get_integerv" | "get_floatv" => values = get_state(gl, cmd, a.e()),
            "new_list" => gl.new_list(a.int() as u32, a.e()),
            "end_list" => gl.end_list(),
            "call_list" => gl.call_list(a.int() as u32),
            "gen_lists" => values.push(gl.gen_lists(a.int()).to_string()),
            "delete_lists" => gl.delete_lists(a.int() as u32, a.int()),
            "is_list" => values.push(gl.is_list(a.int() as u32).to_string()),
            "list_base" => gl.list_base(a.int() as u32),
            "call_lists" => {
                let (n, type_) = (a.int(), a.e());
                let bytes: Vec<u8> = a.floats().iter().map(|&b| b as u8).collect();
                gl.call_lists(n, type_, &bytes);
            }
            "gen_textures" => {
                let n = a.int();
                let mut names = [0; 16];
                gl.gen_textures(n, &mut names[..usize::try_from(n).unwrap_or(0).min(16)]);
                values.extend(names.iter().take(usize::try_from(n).unwrap_or(0).min(16)).map(u32::to_string));
            }
            "bind_texture" => gl.bind_texture(a.e(), a.int() as u32),
            "delete_textures" => {
                let n = a.int();
                let names: Vec<u32> = a.floats().iter().map(|&f| f as u32).collect();
                gl.delete_textures(n, &names);
            }
            "is_texture" => values.push(gl.is_texture(a.int() as u32).to_string()),
            "tex_image_2d" | "tex_sub_image_2d" => {
                let sub = cmd == "tex_sub_image_2d";
                // tex_image_2d: level internalformat width height border;
                // tex_sub_image_2d: level xoffset yoffset width height.
                let (target, level) = (a.e(), a.int());
                let p = if sub { a.int() } else { a.e() as i32 };
                let (q, w, h) = (a.int(), a.int(), a.int());
                let (format, type_) = (a.e(), a.e());
                let bytes = image_bytes(type_, &a.floats());
                if sub {
                    gl.tex_sub_image_2d(target, level, p, q, w, h, format, type_, &bytes);
                } else {
                    gl.tex_image_2d(target, level, p, q, w, h, format, type_, &bytes);
                }
            }
            "tex_image_3d" | "tex_sub_image_3d" => {
                // tex_image_3d: level internalformat width height depth border;
                // tex_sub_image_3d: level xoffset yoffset zoffset width height depth.
                let sub = cmd == "tex_sub_image_3d";
                let (target, level) = (a.e(), a.int());
                let (offset, internal) = if sub { ([a.int(), a.int(), a.int()], 0) } else { ([0; 3], a.e() as i32) };
                let (w, h, d) = (a.int(), a.int(), a.int());
                let border = if sub { 0 } else { a.int() };
                let (format, type_) = (a.e(), a.e());
                let bytes = image_bytes(type_, &a.floats());
                let [x, y, z] = offset;
                if sub {
                    gl.tex_sub_image_3d(target, level, x, y, z, w, h, d, format, type_, &bytes);
                } else {
                    gl.tex_image_3d(target, level, internal, w, h, d, border, format, type_, &bytes);
                }
            }
            "tex_parameteri" => gl.tex_parameteri(a.e(), a.e(), a.e() as i32),
            "tex_envi" => gl.tex_envi(a.e(), a.e(), a.e() as i32),
            "pixel_storei" => gl.pixel_storei(a.e(), a.int()),
            "stencil_func" => gl.stencil_func(a.e(), a.int(), a.int() as u32),
            "stencil_op" => gl.stencil_op(a.e(), a.e(), a.e()),
            "stencil_mask" => gl.stencil_mask(a.int() as u32),
            "clear_stencil" => gl.clear_stencil(a.int()),
            "accum" => gl.accum(a.e(), a.f()),
            "clear_accum" => gl.clear_accum(a.f(), a.f(), a.f(), a.f()),
            "depth_mask" => gl.depth_mask(a.int() as u8),
            "color_mask" => gl.color_mask(a.int() as u8, a.int() as u8, a.int() as u8, a.int() as u8),
            "scissor" => gl.scissor(a.int(), a.int(), a.int(), a.int()),
            "logic_op" => gl.logic_op(a.e()),
            "draw_buffer" => gl.draw_buffer(a.e()),
            "read_buffer" => gl.read_buffer(a.e()),
            "clear" => gl.clear(a.e()),
            "blend_func" => gl.blend_func(a.e(), a.e()),
            "alpha_func" => gl.alpha_func(a.e(), a.f()),
            "fogi" => gl.fogi(a.e(), a.e() as i32),
            "fogf" => gl.fogf(a.e(), a.f()),
            "load_transpose_matrixf" | "mult_transpose_matrixf" => {
                let m: Vec<f32> = (0..16).map(|_| a.d() as f32).collect();
                if cmd.starts_with('l') {
                    gl.load_transpose_matrixf(&m)
                } else {
                    gl.mult_transpose_matrixf(&m)
                }
            }
            "load_transpose_matrixd" | "mult_transpose_matrixd" => {
                let m: Vec<f64> = (0..16).map(|_| a.d()).collect();
                if cmd.starts_with('l') {
                    gl.load_transpose_matrixd(&m)
                } else {
                    gl.mult_transpose_matrixd(&m)
                }
            }
            "translatef" => gl.translatef(a.f(), a.f(), a.f()),
            "scalef" => gl.scalef(a.f(), a.f(), a.f()),
            "rotatef" => gl.rotatef(a.f(), a.f(), a.f(), a.f()),
            "raster_pos2f" => gl.raster_pos2f(a.f(), a.f()),
            "raster_pos3f" => gl.raster_pos3f(a.f(), a.f(), a.f()),
            "raster_pos4f" => gl.raster_pos4f(a.f(), a.f(), a.f(), a.f()),
            "bitmap" => {
                let (w, h, xo, yo, xm, ym) = (a.int(), a.int(), a.f(), a.f(), a.f(), a.f());
                let bytes: Vec<u8> = a.floats().iter().map(|&b| b as u8).collect();
                raster_token = raster_feedback(gl, "bitmap");
                gl.bitmap(w, h, xo, yo, xm, ym, &bytes);
            }
            "draw_pixels" | "render_draw_pixels" => {
                let (w, h, format, type_) = (a.int(), a.int(), a.e(), a.e());
                let values = a.floats();
                let bytes: Vec<u8> = if type_ == GL_FLOAT {
                    bytemuck::cast_slice(&values).to_vec()
                } else {
                    values.iter().map(|&b| b as u8).collect()
                };
                if cmd == "draw_pixels" {
                    raster_token = raster_feedback(gl, "draw_pixel");
                }
                gl.draw_pixels(w, h, format, type_, &bytes);
            }
            "typed" => typed_call(gl, &mut a),
            "hint" => gl.hint(a.e(), a.e()),
            "tex_geni" => gl.tex_geni(a.e(), a.e(), a.e() as i32),
            "tex_genfv" => gl.tex_genfv(a.e(), a.e(), &a.floats()),
            "get_tex_genfv" => {
                let (coord, pname) = (a.e(), a.e());
                let mut v = [0.0f32; 4];
                gl.get_tex_genfv(coord, pname, &mut v);
                let count = if pname == GL_TEXTURE_GEN_MODE { 1 } else { 4 };
                values = v[..count].iter().map(|x| x.to_string()).collect();
            }
            "line_stipple" => gl.line_stipple(a.int(), a.int() as u16),
            "polygon_offset" => gl.polygon_offset(a.f(), a.f()),
            "clip_plane" => gl.clip_plane(a.e(), &a.array()),
            "polygon_stipple" => gl.polygon_stipple(&a.floats().iter().map(|&b| b as u8).collect::<Vec<u8>>()),
            "get_clip_plane" => {
                let mut eq = [0.0f64; 4];
                gl.get_clip_plane(a.e(), &mut eq);
                values.extend(eq.iter().map(|c| c.to_string()));
            }
            "matrix_mode" => gl.matrix_mode(a.e()),
            "load_identity" => gl.load_identity(),
            "materialf" => gl.material_f(a.e(), a.e(), a.f()),
            "push_attrib" => gl.push_attrib(a.e()),
            "pop_attrib" => gl.pop_attrib(),
            "texgen_normal" => self.texgen_normal = true,
            "defer_errors" => self.deferred = a.next() == "on",
            "get_error" => {
                let e = gl.get_error();
                self.out.push(format!("{number} get_error err=0x{e:04x}"));
                return;
            }
            other => {
                if !self.arrays.run(gl, other, &mut a, &mut values)
                    && !queries::run(gl, other, &mut a, &mut values)
                    && !pixels::pixel_call(gl, other, &mut a, &mut values)
                {
                    panic!("unknown command {other}");
                }
            }
        }
        let err = if self.inside || self.deferred || cmd == "defer_errors" {
            "-".to_owned()
        } else {
            format!("0x{:04x}", self.gl.get_error())
        };
        let mut line = format!("{number} {cmd} err={err}");
        for v in values {
            line.push(' ');
            line.push_str(&v);
        }
        let succeeded = err == "0x0000";
        self.out.push(line);
        if let (Some(token), true) = (raster_token, succeeded) {
            // Feedback mode reports the raster position instead of the pixels drawn.
            self.out.push(token);
            self.collected = self.gl.frame().expanded().primitives.len();
        }
        if cmd == "render_draw_pixels" {
            // Drawn in render mode: pixels in the colour buffer, nothing in feedback.
            self.collected = self.gl.frame().expanded().primitives.len();
        }
        for _ in copies..self.gl.frame().pixel_copies.len() {
            self.out.extend(raster_feedback(&mut self.gl, "copy_pixel"));
        }
        if cmd == "new_list" || cmd == "end_list" {
            // Mesa buffers what GL_COMPILE_AND_EXECUTE draws until the list ends (its vertex
            // lists run when complete), so feedback shows it after `end_list`.
            let mut index = [0];
            self.gl.get_integerv(GL_LIST_INDEX, &mut index);
            self.compiling = index[0] != 0;
        }
        if !self.inside && !self.compiling && cmd != "defer_errors" && cmd != "texgen_normal" {
            self.collect_feedback();
        }
    }

    /// Emits `fb` lines for the primitives drawn since the last collection (FORMAT.md §3).
    fn collect_feedback(&mut self) {
        if self.arrays.real_feedback {
            let lines = self.arrays.collect(&mut self.gl);
            return self.out.extend(lines);
        }
        if self.gl.render_mode_value() == GL_SELECT {
            return;
        }
        let frame = self.gl.frame().expanded();
        self.collected = self.collected.min(frame.primitives.len());
        for p in &frame.primitives[self.collected..] {
            let v: Vec<String> = frame.vertices_of(p).iter().map(|v| self.feedback_vertex(v)).collect();
            let n = v.len();
            let mut emit = |kind: &str, idx: &[usize]| {
                let body: Vec<&str> = idx.iter().map(|&i| v[i].as_str()).collect();
                self.out.push(format!("fb {kind} {}", body.join(" ")));
            };
            match p.mode {
                GL_POINTS => (0..n).for_each(|i| emit("point", &[i])),
                GL_LINE_STRIP => (1..n).for_each(|i| emit("line", &[i - 1, i])),
                GL_LINES => (0..n / 2).for_each(|i| emit("line", &[2 * i, 2 * i + 1])),
                GL_TRIANGLES => (0..n / 3).for_each(|i| emit("polygon 3", &[3 * i, 3 * i + 1, 3 * i + 2])),
                GL_TRIANGLE_STRIP => (2..n).for_each(|i| {
                    let k = i - 2;
                    let tri = if k % 2 == 0 { [k, k + 1, k + 2] } else { [k + 1, k, k + 2] };
                    emit("polygon 3", &tri);
                }),
                GL_QUAD_STRIP => (1..n / 2).for_each(|q| {
                    let b = 2 * (q - 1);
                    emit("polygon 3", &[b + 2, b, b + 3]);
                    emit("polygon 3", &[b, b + 1, b + 3]);
                }),
                other => panic!("feedback for mode {other} not emulated"),
            }
        }
        self.collected = frame.primitives.len();
    }

    /// Window coordinates for viewport (0,0,2,2), clip w, colour, texcoord (or the normal under
    /// `texgen_normal`).
    fn feedback_vertex(&self, v: &Vertex) -> String {
        let [x, y, z, w] = v.position;
        let tex =
            if self.texgen_normal { [v.normal[0], v.normal[1], v.normal[2], v.tex_coord[3]] } else { v.tex_coord };
        let all = [x / w + 1.0, y / w + 1.0, (z / w) * 0.5 + 0.5, w]
            .into_iter()
            .chain(v.color)
            .chain(tex)
            .map(|c| format!("{c}"))
            .collect::<Vec<_>>();
        all.join(" ")
    }
}

/// `typed NAME values`: a type variant of a per-vertex call through its v form, the values
/// cast to the call's type as C casts them.
fn typed_call(gl: &mut Gl, a: &mut Args) {
    let name = a.next().to_owned();
    let (base, ty) = name.trim_end_matches('v').split_at(name.trim_end_matches('v').len() - 1);
    // Two-letter types (ub, us, ui) end in b, s or i too.
    let (base, ty) = match base.strip_suffix('u') {
        Some(b) => (b.to_owned(), format!("u{ty}")),
        None => (base.to_owned(), ty.to_owned()),
    };
    let n = base.chars().last().and_then(|c| c.to_digit(10)).expect("a component count") as usize;
    let values: Vec<f64> = (0..n).map(|_| a.d()).collect();
    macro_rules! call {
        ($t:ty, $($fn:literal => $method:ident),+) => {{
            let v: Vec<$t> = values.iter().map(|&x| x as $t).collect();
            match base.as_str() {
                $($fn => gl.$method(&v),)+
                other => panic!("typed {other}{ty}v not emulated"),
            }
        }};
    }
    match ty.as_str() {
        "b" => call!(i8, "glColor3" => color3bv, "glColor4" => color4bv, "glNormal3" => normal3bv,
            "glSecondaryColor3" => secondary_color3bv),
        "ub" => call!(u8, "glColor3" => color3ubv, "glColor4" => color4ubv, "glSecondaryColor3" => secondary_color3ubv),
        "s" => call!(i16, "glColor3" => color3sv, "glColor4" => color4sv, "glNormal3" => normal3sv,
            "glSecondaryColor3" => secondary_color3sv,
            "glVertex2" => vertex2sv, "glVertex3" => vertex3sv, "glVertex4" => vertex4sv,
            "glTexCoord1" => tex_coord1sv, "glTexCoord2" => tex_coord2sv, "glTexCoord3" => tex_coord3sv,
            "glTexCoord4" => tex_coord4sv, "glRasterPos2" => raster_pos2sv, "glRasterPos3" => raster_pos3sv,
            "glRasterPos4" => raster_pos4sv),
        "us" => call!(u16, "glColor3" => color3usv, "glColor4" => color4usv,
            "glSecondaryColor3" => secondary_color3usv),
        "i" => call!(i32, "glColor3" => color3iv, "glColor4" => color4iv, "glNormal3" => normal3iv,
            "glSecondaryColor3" => secondary_color3iv,
            "glVertex2" => vertex2iv, "glVertex3" => vertex3iv, "glVertex4" => vertex4iv,
            "glTexCoord1" => tex_coord1iv, "glTexCoord2" => tex_coord2iv, "glTexCoord3" => tex_coord3iv,
            "glTexCoord4" => tex_coord4iv, "glRasterPos3" => raster_pos3iv, "glRasterPos4" => raster_pos4iv),
        "ui" => call!(u32, "glColor3" => color3uiv, "glColor4" => color4uiv,
            "glSecondaryColor3" => secondary_color3uiv),
        "f" => {
            call!(f32, "glSecondaryColor3" => secondary_color3fv, "glTexCoord1" => tex_coord1fv, "glTexCoord2" => tex_coord2fv,
            "glTexCoord3" => tex_coord3fv, "glTexCoord4" => tex_coord4fv)
        }
        _ => call!(f64, "glColor3" => color3dv, "glColor4" => color4dv, "glNormal3" => normal3dv,
            "glSecondaryColor3" => secondary_color3dv,
            "glVertex2" => vertex2dv, "glVertex3" => vertex3dv, "glVertex4" => vertex4dv,
            "glTexCoord1" => tex_coord1dv, "glTexCoord2" => tex_coord2dv, "glTexCoord3" => tex_coord3dv,
            "glTexCoord4" => tex_coord4dv, "glRasterPos4" => raster_pos4dv),
    }
}

/// What feedback mode writes for a glBitmap or glDrawPixels at the current raster position
/// (window coordinates, clip w, the raster colour and texture coordinates), if it is valid.
fn raster_feedback(gl: &mut Gl, token: &str) -> Option<String> {
    let mut valid = [0];
    gl.get_integerv(GL_CURRENT_RASTER_POSITION_VALID, &mut valid);
    if valid[0] == 0 {
        return None;
    }
    let mut values = Vec::new();
    for pname in [GL_CURRENT_RASTER_POSITION, GL_CURRENT_RASTER_COLOR, GL_CURRENT_RASTER_TEXTURE_COORDS] {
        let mut v = [0.0f32; 4];
        gl.get_floatv(pname, &mut v);
        values.extend(v.map(|x| x.to_string()));
    }
    Some(format!("fb {token} {}", values.join(" ")))
}

fn fresh_gl() -> Gl {
    fresh_gl_with(0, 0)
}

/// interp.c's context with `stencil` and `accum` bits (`buffers S A`; 0 and 0 for a case).
fn fresh_gl_with(stencil: u8, accum: u8) -> Gl {
    let mut gl = Gl::new(64, 64);
    gl.set_buffer_config(gleval::gl::BufferConfig { stencil_bits: stencil, accum_bits: accum, double: false });
    gl.viewport(0, 0, 2, 2);
    // The texture copies read the window as drawn, as interp.c's OSMesa buffer.
    gl.set_window_reader(|frame, w, h| Some(gleval::render::soft::render_window(frame, w, h)));
    gl
}

/// `get_map*` with interp.c's value counts: the map's current order decides the GL_COEFF count.
fn get_map(gl: &mut Gl, cmd: &str, target: u32, query: u32) -> Vec<String> {
    let Some(t) = MapTarget::from_enum(target) else {
        let mut sink = [0.0f32; 4];
        gl.get_mapfv(target, query, &mut sink);
        return Vec::new();
    };
    let mut order = [0i32; 2];
    gl.get_mapiv(target, GL_ORDER, &mut order);
    let count = match query {
        GL_ORDER => usize::from(t.dims),
        GL_DOMAIN => 2 * usize::from(t.dims),
        GL_COEFF => (order[0].max(0) * if t.dims == 2 { order[1].max(0) } else { 1 }) as usize * t.components(),
        _ => 0,
    };
    let size = count.max(4);
    match cmd {
        "get_mapfv" => {
            let mut v = vec![0.0f32; size];
            gl.get_mapfv(target, query, &mut v);
            v[..count].iter().map(|x| x.to_string()).collect()
        }
        "get_mapdv" => {
            let mut v = vec![0.0f64; size];
            gl.get_mapdv(target, query, &mut v);
            v[..count].iter().map(|x| x.to_string()).collect()
        }
        _ => {
            let mut v = vec![0i32; size];
            gl.get_mapiv(target, query, &mut v);
            v[..count].iter().map(|x| x.to_string()).collect()
        }
    }
}

fn get_state(gl: &mut Gl, cmd: &str, pname: u32) -> Vec<String> {
    let count = match pname {
        GL_MAP1_GRID_DOMAIN | GL_MAP2_GRID_SEGMENTS => 2,
        GL_MAP2_GRID_DOMAIN | GL_CURRENT_RASTER_POSITION | GL_CURRENT_RASTER_COLOR => 4,
        GL_CURRENT_RASTER_TEXTURE_COORDS | GL_CURRENT_COLOR | GL_CURRENT_TEXTURE_COORDS => 4,
        GL_CURRENT_NORMAL => 3,
        GL_COLOR_WRITEMASK | GL_SCISSOR_BOX | GL_ACCUM_CLEAR_VALUE => 4,
        _ => 1,
    };
    if cmd == "get_integerv" {
        let mut v = [0i32; 4];
        gl.get_integerv(pname, &mut v);
        v[..count].iter().map(|x| x.to_string()).collect()
    } else {
        let mut v = [0.0f32; 4];
        gl.get_floatv(pname, &mut v);
        v[..count].iter().map(|x| x.to_string()).collect()
    }
}

/// Runs a script file, returning its output lines grouped by case (case name, lines).
fn run_script(path: &Path) -> Vec<(String, Vec<String>)> {
    let text = std::fs::read_to_string(path).expect("script");
    let mut runner = Runner::new();
    for (i, line) in text.lines().enumerate() {
        let tokens = tokenize(line);
        if !tokens.is_empty() {
            runner.run_line(i + 1, &tokens);
        }
    }
    group_by_case(runner.out)
}

fn group_by_case(lines: Vec<String>) -> Vec<(String, Vec<String>)> {
    let mut out: Vec<(String, Vec<String>)> = Vec::new();
    for line in lines {
        match line.strip_prefix("case ") {
            Some(name) => out.push((name.to_owned(), Vec::new())),
            None => out.last_mut().expect("output starts with a case").1.push(line),
        }
    }
    out
}

/// Compares two output lines token by token: numbers within `tol` (relative above 1), the rest
/// exactly.
fn line_mismatch(ours: &str, mesa: &str, tol: f64) -> Option<String> {
    let (a, b): (Vec<&str>, Vec<&str>) = (ours.split(' ').collect(), mesa.split(' ').collect());
    if a.len() != b.len() {
        return Some(format!("token count {} vs {}", a.len(), b.len()));
    }
    for (x, y) in a.iter().zip(&b) {
        match (x.parse::<f64>(), y.parse::<f64>()) {
            // Numerically: -0 and 0 are the same value (Mesa's texgen normalises the sign).
            (Ok(p), Ok(q)) => {
                let both_nan = p.is_nan() && q.is_nan();
                if !both_nan && (p - q).abs() > tol * q.abs().max(1.0) {
                    return Some(format!("{x} vs {y}"));
                }
            }
            _ if x == y => {}
            _ => return Some(format!("{x} vs {y}")),
        }
    }
    None
}

#[test]
fn evaluator_scripts_agree_with_real_mesa() {
    let mut files: Vec<PathBuf> = std::fs::read_dir(calls_dir().join("cases"))
        .expect("cases dir")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "calls"))
        .collect();
    files.sort();
    assert!(files.len() >= 5, "the reference scripts are missing");
    let (mut cases, mut calls, mut failures) = (0, 0, Vec::new());
    for file in &files {
        let name = file.file_name().unwrap().to_string_lossy().to_string();
        if DEVIATIONS.iter().any(|(d, _)| *d == name) {
            continue;
        }
        let expected_path = calls_dir().join("expected").join(name.replace(".calls", ".out"));
        let expected = group_by_case(
            std::fs::read_to_string(&expected_path).expect("expected").lines().map(str::to_owned).collect(),
        );
        let ours = run_script(file);
        assert_eq!(ours.len(), expected.len(), "{name}: case count");
        for ((case, our_lines), (mesa_case, mesa_lines)) in ours.iter().zip(&expected) {
            assert_eq!(case, mesa_case);
            if DEVIATIONS.iter().any(|(d, _)| d == case) {
                continue;
            }
            cases += 1;
            calls += mesa_lines.iter().filter(|l| !l.starts_with("fb ")).count();
            let tol =
                if case.contains("order30") || our_lines.iter().any(|l| l.contains("texgen")) { 1e-4 } else { 2e-5 };
            if our_lines.len() != mesa_lines.len() {
                let first = our_lines.iter().zip(mesa_lines).find(|(o, m)| line_mismatch(o, m, tol).is_some());
                let (o, m) = first.map_or(("", ""), |(o, m)| (o.as_str(), m.as_str()));
                let (ours, mesa) = (our_lines.len(), mesa_lines.len());
                failures.push(format!(
                    "{name}/{case}: {ours} lines vs Mesa's {mesa}; first difference\n  ours: {o}\n  mesa: {m}"
                ));
                continue;
            }
            for (o, m) in our_lines.iter().zip(mesa_lines) {
                if let Some(why) = line_mismatch(o, m, tol) {
                    failures.push(format!("{name}/{case}: {why}\n  ours: {o}\n  mesa: {m}"));
                    break;
                }
            }
        }
    }
    println!("{cases} cases, {calls} calls compared with Mesa");
    assert!(failures.is_empty(), "{} cases differ from Mesa:\n{}", failures.len(), failures.join("\n"));
    assert!(cases > 80 && calls > 1000, "too few cases ran: {cases} cases, {calls} calls");
}
