//! The pixel path's commands of the call scripts (`tests/reference/calls/interp_pixels.h`
//! is their C side): transfer, maps, zoom, copies, the texture calls that read the window,
//! residency and priorities, colour index, reads.

use super::Args;
use gleval::gl::{WindowImage, MAX_PIXEL_MAP_TABLE};
use gleval::prelude::*;
use gleval::render::soft;

/// Runs `cmd` if it is one of the pixel commands, pushing what it prints into `values`; false
/// for another command. (The feedback token of a copy is written by the runner, for every
/// copy a line executes.)
pub(super) fn pixel_call(gl: &mut Gl, cmd: &str, a: &mut Args<'_>, values: &mut Vec<String>) -> bool {
    match cmd {
        "pixel_zoom" => gl.pixel_zoom(a.f(), a.f()),
        "pixel_transferf" => gl.pixel_transferf(a.e(), a.f()),
        "pixel_transferi" => gl.pixel_transferi(a.e(), a.int()),
        "pixel_mapfv" | "pixel_mapuiv" | "pixel_mapusv" => {
            let (map, n, v) = (a.e(), a.int(), a.array());
            match cmd {
                "pixel_mapfv" => gl.pixel_mapfv(map, n, &v.iter().map(|&x| x as f32).collect::<Vec<_>>()),
                "pixel_mapuiv" => gl.pixel_mapuiv(map, n, &v.iter().map(|&x| x as u32).collect::<Vec<_>>()),
                _ => gl.pixel_mapusv(map, n, &v.iter().map(|&x| x as u16).collect::<Vec<_>>()),
            }
        }
        "get_pixel_mapfv" | "get_pixel_mapuiv" | "get_pixel_mapusv" => {
            let map = a.e();
            // interp reads the size with glGetIntegerv, which fails between begin and end.
            let size = if gl.inside_begin_end() { 0 } else { gl.pixel_map_size(map) };
            match cmd {
                "get_pixel_mapfv" => {
                    let mut v = [0.0f32; MAX_PIXEL_MAP_TABLE];
                    gl.get_pixel_mapfv(map, &mut v);
                    values.extend(v[..size].iter().map(f32::to_string));
                }
                "get_pixel_mapuiv" => {
                    let mut v = [0u32; MAX_PIXEL_MAP_TABLE];
                    gl.get_pixel_mapuiv(map, &mut v);
                    values.extend(v[..size].iter().map(u32::to_string));
                }
                _ => {
                    let mut v = [0u16; MAX_PIXEL_MAP_TABLE];
                    gl.get_pixel_mapusv(map, &mut v);
                    values.extend(v[..size].iter().map(u16::to_string));
                }
            }
        }
        "copy_pixels" => {
            gl.copy_pixels(a.int(), a.int(), a.int(), a.int(), a.e());
        }
        "copy_tex_image_2d" => {
            let (t, level, f, x, y, w, h, border) =
                (a.e(), a.int(), a.e(), a.int(), a.int(), a.int(), a.int(), a.int());
            gl.copy_tex_image_2d(t, level, f, x, y, w, h, border);
        }
        "copy_tex_image_1d" => {
            let (t, level, f, x, y, w, border) = (a.e(), a.int(), a.e(), a.int(), a.int(), a.int(), a.int());
            gl.copy_tex_image_1d(t, level, f, x, y, w, border);
        }
        "copy_tex_sub_image_2d" => {
            let (t, level, xo, yo, x, y, w, h) = (a.e(), a.int(), a.int(), a.int(), a.int(), a.int(), a.int(), a.int());
            gl.copy_tex_sub_image_2d(t, level, xo, yo, x, y, w, h);
        }
        "copy_tex_sub_image_3d" => {
            let (t, level, xo, yo, zo) = (a.e(), a.int(), a.int(), a.int(), a.int());
            let (x, y, w, h) = (a.int(), a.int(), a.int(), a.int());
            gl.copy_tex_sub_image_3d(t, level, xo, yo, zo, x, y, w, h);
        }
        "copy_tex_sub_image_1d" => {
            let (t, level, xo, x, y, w) = (a.e(), a.int(), a.int(), a.int(), a.int(), a.int());
            gl.copy_tex_sub_image_1d(t, level, xo, x, y, w);
        }
        "tex_sub_image_1d" => {
            let (t, level, xo, w, format, type_) = (a.e(), a.int(), a.int(), a.int(), a.e(), a.e());
            let bytes: Vec<u8> = a.floats().iter().map(|&b| b as u8).collect();
            gl.tex_sub_image_1d(t, level, xo, w, format, type_, &bytes);
        }
        "are_textures_resident" => {
            let n = a.int();
            let array = a.array();
            let names: Vec<u32> = array.iter().map(|&v| v as u32).collect();
            let mut residences = vec![7u8; names.len()];
            let answer = if array.is_empty() && n >= 0 {
                // C's NULL: Mesa answers GL_FALSE without an error.
                0
            } else {
                gl.are_textures_resident(n, &names, &mut residences)
            };
            values.push(answer.to_string());
            values.extend(residences.iter().map(u8::to_string));
        }
        "prioritize_textures" => {
            let n = a.int();
            let names: Vec<u32> = a.array().iter().map(|&v| v as u32).collect();
            let priorities = a.floats();
            // A NULL priority array does nothing in Mesa (the C ABI answers it so).
            if !(priorities.is_empty() && n >= 0) {
                gl.prioritize_textures(n, &names, &priorities);
            }
        }
        "indexf" => gl.indexf(a.f()),
        "indexd" => gl.indexd(a.d()),
        "indexi" => gl.indexi(a.int()),
        "indexs" => gl.indexs(a.int() as i16),
        "indexub" => gl.indexub(a.int() as u8),
        "clear_index" => gl.clear_index(a.f()),
        "index_mask" => {
            let t = a.next();
            let mask = t
                .strip_prefix("0x")
                .map_or_else(|| t.parse().expect("mask"), |h| u32::from_str_radix(h, 16).expect("hex"));
            gl.index_mask(mask);
        }
        "pixels_clear" => {
            gl.clear_color(a.f(), a.f(), a.f(), a.f());
            gl.clear_depth(a.d());
            gl.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        }
        "read_pixels" => read_pixels(gl, a, values),
        _ => return false,
    }
    true
}

/// `read_pixels x y w h format type`: what interp prints (4 floats at most for `GL_FLOAT`, else
/// the first 16 bytes), from a buffer of 0xEE bytes.
fn read_pixels(gl: &mut Gl, a: &mut Args<'_>, values: &mut Vec<String>) {
    let (x, y, w, h, format, type_) = (a.int(), a.int(), a.int(), a.int(), a.e(), a.e());
    let mut out = vec![0xEEu8; 4096];
    let window = |frame: &Frame| -> Option<WindowImage> { Some(soft::render_window(frame, 64, 64)) };
    gl.read_pixels((x, y), (w, h), format, type_, window, &mut out);
    let pixels = if w > 0 && h > 0 { (w * h) as usize } else { 0 };
    if type_ == GL_FLOAT {
        let floats = out.chunks_exact(4).take(pixels.min(16));
        values.extend(floats.map(|b| format!("{}", f32::from_ne_bytes([b[0], b[1], b[2], b[3]]))));
    } else {
        values.extend(out[..16].iter().map(u8::to_string));
    }
}
