//! The call-script commands of `interp_buffers.c` (GL 1.5's buffer objects) on `Gl`.

use super::arrays::Harness;
use super::Args;
use gleval::prelude::*;

impl Harness {
    /// `n` bytes of client memory from byte `offset` (what a `const void *` data argument
    /// reads), `None` for interp.c's NULL (-1).
    fn data(&self, offset: i32, n: usize) -> Option<Vec<u8>> {
        let from = usize::try_from(offset).ok()?;
        let bytes = self.mem.to_vec::<u8>();
        Some(bytes[from..].iter().copied().chain(std::iter::repeat(0)).take(n).collect())
    }

    /// Runs one of `interp_buffers.c`'s commands; false when `cmd` is not one.
    pub fn run_buffers(&mut self, gl: &mut Gl, cmd: &str, a: &mut Args, values: &mut Vec<String>) -> bool {
        match cmd {
            "buffer_offsets" => self.buffer_offsets = a.next() == "on",
            "gen_buffers" => {
                let n = a.int();
                let mut names = [7777u32; 16];
                gl.gen_buffers(n, &mut names);
                values.extend(names.iter().take(usize::try_from(n).unwrap_or(0)).map(u32::to_string));
            }
            "delete_buffers" => {
                let n = a.int();
                let names: Vec<u32> = a.array().iter().map(|&v| v as u32).collect();
                gl.delete_buffers(n, &names);
            }
            "is_buffer" => values.push(gl.is_buffer(a.int() as u32).to_string()),
            "bind_buffer" => gl.bind_buffer(a.e(), a.int() as u32),
            "buffer_data" => {
                let (target, size, mem, usage) = (a.e(), a.int(), a.int(), a.e());
                let data = self.data(mem, usize::try_from(size).unwrap_or(0));
                gl.buffer_data(target, size as isize, data.as_deref(), usage);
            }
            "buffer_sub_data" => {
                let (target, offset, size, mem) = (a.e(), a.int(), a.int(), a.int());
                let data = self.data(mem, usize::try_from(size).unwrap_or(0)).unwrap_or_default();
                gl.buffer_sub_data(target, offset as isize, size as isize, &data);
            }
            "get_buffer_sub_data" => {
                let (target, offset, size) = (a.e(), a.int(), a.int());
                let mut out = vec![238u8; 1 << 16];
                gl.get_buffer_sub_data(target, offset as isize, size as isize, &mut out);
                values.extend(out.iter().take(usize::try_from(size).unwrap_or(0).min(32)).map(u8::to_string));
            }
            "map_buffer" => {
                let map = gl.map_buffer(a.e(), a.e());
                values.push(if map.is_some() { "mapped" } else { "null" }.into());
                if map.is_some() {
                    self.mapped = map;
                }
            }
            "map_write" => {
                let (offset, type_, v) = (a.int() as usize, a.e(), a.array());
                let map = self.mapped.as_ref().expect("map_write needs a mapping");
                let ok = match type_ {
                    GL_UNSIGNED_BYTE => map.write(offset, &v.iter().map(|&x| x as u8).collect::<Vec<_>>()),
                    GL_UNSIGNED_SHORT => map.write(offset, &v.iter().map(|&x| x as u16).collect::<Vec<_>>()),
                    GL_UNSIGNED_INT => map.write(offset, &v.iter().map(|&x| x as u32).collect::<Vec<_>>()),
                    _ => map.write(offset, &v.iter().map(|&x| x as f32).collect::<Vec<_>>()),
                };
                assert!(ok, "map_write outside the mapping");
            }
            "map_read" => {
                let (offset, n) = (a.int() as usize, a.int() as usize);
                let map = self.mapped.as_ref().expect("map_read needs a mapping");
                let mut out = vec![0u8; n];
                assert!(map.read(offset, &mut out), "map_read outside the mapping");
                values.extend(out.iter().map(u8::to_string));
            }
            "unmap_buffer" => values.push(gl.unmap_buffer(a.e()).to_string()),
            "get_buffer_parameteriv" => {
                let mut v = [7777];
                gl.get_buffer_parameteriv(a.e(), a.e(), &mut v);
                values.push(if v[0] == 7777 { "unwritten".into() } else { v[0].to_string() });
            }
            "get_buffer_pointerv" => {
                let (target, pname) = (a.e(), a.e());
                let writes = gl.get_buffer_pointerv_error(target, pname).is_none();
                let mut out = [None];
                gl.get_buffer_pointerv(target, pname, &mut out);
                let name = match &out[0] {
                    _ if !writes => "unwritten",
                    None => "null",
                    Some(p) if Some(p) == self.mapped.as_ref() => "map",
                    Some(_) => "elsewhere",
                };
                values.push(name.into());
            }
            _ => return self.run_queries(gl, cmd, a, values),
        }
        true
    }
}

impl Harness {
    /// Runs one of `interp_buffers.c`'s query commands; false when `cmd` is not one.
    pub fn run_queries(&mut self, gl: &mut Gl, cmd: &str, a: &mut Args, values: &mut Vec<String>) -> bool {
        match cmd {
            "gen_queries" => {
                let n = a.int();
                let mut names = [7777u32; 16];
                gl.gen_queries(n, &mut names);
                values.extend(names.iter().take(usize::try_from(n).unwrap_or(0)).map(u32::to_string));
            }
            "delete_queries" => {
                let n = a.int();
                let names: Vec<u32> = a.array().iter().map(|&v| v as u32).collect();
                gl.delete_queries(n, &names);
            }
            "is_query" => values.push(gl.is_query(a.int() as u32).to_string()),
            "begin_query" => gl.begin_query(a.e(), a.int() as u32),
            "end_query" => gl.end_query(a.e()),
            "get_queryiv" | "get_query_objectiv" | "get_query_objectuiv" => {
                let mut v = [7777];
                match cmd {
                    "get_queryiv" => gl.get_queryiv(a.e(), a.e(), &mut v),
                    "get_query_objectiv" => gl.get_query_objectiv(a.int() as u32, a.e(), &mut v),
                    _ => {
                        let mut u = [7777u32];
                        gl.get_query_objectuiv(a.int() as u32, a.e(), &mut u);
                        v[0] = u[0] as i32;
                    }
                }
                values.push(if v[0] == 7777 { "unwritten".into() } else { v[0].to_string() });
            }
            _ => return false,
        }
        true
    }
}
