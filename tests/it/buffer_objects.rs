//! GL 1.5's buffer objects against client memory: the same random vertices, colours and
//! indices drawn from client arrays and from buffers (the arrays interleaved in one buffer at
//! offsets, the indices in another) record the same frame and rasterise to the same pixels, by
//! `glDrawArrays`, `glDrawElements`, `glDrawRangeElements` and `glMultiDrawElements`, in
//! display lists too; random buffer calls never panic and raise only GL's errors. Mesa's own
//! answers for the same draws are `tests/reference/calls/cases/buffer_objects.calls`.

use gleval::gl::{BufferOffset, ClientArray};
use gleval::prelude::*;
use gleval::render::soft;
use proptest::prelude::*;

/// A scene: vertices (x, y, z in the view volume) with colours, a draw mode, indices into the
/// vertices, and whether it is drawn through a display list.
#[derive(Clone, Debug)]
struct Scene {
    vertices: Vec<([f32; 3], [u8; 4])>,
    mode: GLenum,
    indices: Vec<u16>,
    listed: bool,
}

fn scene() -> impl Strategy<Value = Scene> {
    let vertex = ([-0.9f32..0.9, -0.9f32..0.9, -0.9f32..0.9], any::<[u8; 4]>());
    (prop::collection::vec(vertex, 1..12), 0u32..10, any::<bool>()).prop_flat_map(|(vertices, mode, listed)| {
        let n = vertices.len() as u16;
        prop::collection::vec(0..n, 0..16).prop_map(move |indices| Scene {
            vertices: vertices.clone(),
            mode,
            indices,
            listed,
        })
    })
}

/// The vertices as one interleaved block: 3 floats then 4 colour bytes (16 bytes each).
fn interleaved(scene: &Scene) -> Vec<u8> {
    let mut block = Vec::new();
    for (p, c) in &scene.vertices {
        p.iter().for_each(|v| block.extend(v.to_ne_bytes()));
        block.extend(c);
    }
    block
}

/// Every draw of the scene on `gl`, its arrays set up already; `elements` draws the indices
/// from the element buffer (`true`) or from client memory.
fn draw(gl: &mut Gl, scene: &Scene, elements: bool) {
    let (count, n) = (scene.indices.len() as GLsizei, scene.vertices.len() as GLsizei);
    if scene.listed {
        gl.new_list(1, GL_COMPILE);
    }
    gl.draw_arrays(scene.mode, 0, n);
    let half = count / 2;
    if elements {
        gl.draw_elements_offset(scene.mode, count, GL_UNSIGNED_SHORT, 0);
        gl.draw_range_elements_offset(scene.mode, 0, n as GLuint, count - half, GL_UNSIGNED_SHORT, 2 * half as usize);
        gl.multi_draw_elements_offset(scene.mode, &[half, count - half], GL_UNSIGNED_SHORT, &[0, 2 * half as usize], 2);
    } else {
        let (first, second) = scene.indices.split_at(half as usize);
        gl.draw_elements(scene.mode, count, GL_UNSIGNED_SHORT, &scene.indices);
        gl.draw_range_elements(scene.mode, 0, n as GLuint, count - half, GL_UNSIGNED_SHORT, second);
        gl.multi_draw_elements(scene.mode, &[half, count - half], GL_UNSIGNED_SHORT, &[first, second], 2);
    }
    if scene.listed {
        gl.end_list();
        gl.call_list(1);
    }
}

/// The scene drawn from client arrays.
fn from_client_memory(scene: &Scene) -> Gl {
    let mut gl = Gl::new(16, 16);
    let block = ClientArray::from_bytes(interleaved(scene));
    gl.vertex_pointer(3, GL_FLOAT, 16, &block);
    gl.color_pointer(4, GL_UNSIGNED_BYTE, 16, block.at_byte(12));
    gl.enable_client_state(GL_VERTEX_ARRAY);
    gl.enable_client_state(GL_COLOR_ARRAY);
    draw(&mut gl, scene, false);
    gl
}

/// The scene drawn from buffer objects, which are unbound (and the vertex buffer deleted)
/// before the draws: the arrays keep their buffer.
fn from_buffers(scene: &Scene) -> Gl {
    let mut gl = Gl::new(16, 16);
    let mut names = [0; 2];
    gl.gen_buffers(2, &mut names);
    let block = interleaved(scene);
    gl.bind_buffer(GL_ARRAY_BUFFER, names[0]);
    gl.buffer_data(GL_ARRAY_BUFFER, block.len() as isize, Some(&block[..]), GL_STATIC_DRAW);
    gl.vertex_pointer(3, GL_FLOAT, 16, BufferOffset(0));
    gl.color_pointer(4, GL_UNSIGNED_BYTE, 16, BufferOffset(12));
    gl.bind_buffer(GL_ARRAY_BUFFER, 0);
    gl.bind_buffer(GL_ELEMENT_ARRAY_BUFFER, names[1]);
    let size = 2 * scene.indices.len() as isize;
    gl.buffer_data(GL_ELEMENT_ARRAY_BUFFER, size, Some(&scene.indices[..]), GL_STREAM_DRAW);
    gl.enable_client_state(GL_VERTEX_ARRAY);
    gl.enable_client_state(GL_COLOR_ARRAY);
    draw(&mut gl, scene, true);
    gl
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn buffers_draw_what_client_memory_draws(scene in scene()) {
        let (mut client, mut buffers) = (from_client_memory(&scene), from_buffers(&scene));
        prop_assert_eq!(client.get_error(), GL_NO_ERROR);
        prop_assert_eq!(buffers.get_error(), GL_NO_ERROR);
        let (a, b) = (client.frame().expanded(), buffers.frame().expanded());
        prop_assert_eq!(&a.vertices, &b.vertices);
        prop_assert_eq!(a.primitives.len(), b.primitives.len());
        let (pa, pb) = (soft::render_frame(client.frame(), 16, 16), soft::render_frame(buffers.frame(), 16, 16));
        prop_assert_eq!(pa.pixels, pb.pixels);
    }

    #[test]
    fn buffer_calls_never_panic(
        calls in prop::collection::vec((0u8..9, any::<u32>(), -4isize..40, -4isize..40, any::<u32>()), 1..40),
    ) {
        let mut gl = Gl::new(4, 4);
        let targets = [GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER];
        let mut map = None;
        for (call, name, a, b, e) in calls {
            let target = targets.get(name as usize % 3).copied().unwrap_or(name);
            match call {
                0 => gl.bind_buffer(target, name % 4),
                1 => gl.buffer_data(target, a, Some(&[7u8; 16][..]), e % 3 + GL_STREAM_DRAW),
                2 => gl.buffer_sub_data(target, a, b, &[1.0f32; 4]),
                3 => gl.get_buffer_sub_data(target, a, b, &mut [0u16; 8]),
                4 => map = gl.map_buffer(target, GL_READ_ONLY + e % 4).or(map),
                5 => { gl.unmap_buffer(target); }
                6 => gl.delete_buffers(1, &[name % 4]),
                7 => {
                    gl.vertex_pointer(2, GL_FLOAT, 0, BufferOffset(a.unsigned_abs()));
                    gl.enable_client_state(GL_VERTEX_ARRAY);
                    gl.draw_arrays(GL_POINTS, 0, b.clamp(-1, 8) as GLsizei);
                }
                _ => gl.draw_elements_offset(GL_LINES, b.clamp(-1, 8) as GLsizei, GL_UNSIGNED_BYTE, a.unsigned_abs()),
            }
            if let Some(m) = &map {
                let mut out = [0u8; 2];
                let _ = m.read(0, &mut out) || m.write(1, &[3u8]);
            }
            let error = gl.get_error();
            prop_assert!(matches!(error, GL_NO_ERROR | GL_INVALID_ENUM | GL_INVALID_VALUE | GL_INVALID_OPERATION));
        }
    }
}
