//! Property tests of vertex arrays and selection: random pointers (odd strides, sizes, types,
//! short arrays), random draws (counts, firsts, index types) and selection buffers of every
//! size never panic and only set GL's errors; a draw either draws exactly its elements or sets
//! `GL_INVALID_VALUE` and draws nothing; a small selection buffer holds a prefix of what a
//! large one holds, and `render_mode` says −1 exactly when it overflowed. GL 1.2's and 1.4's
//! draws (`draw_range_elements`, the multi-draws) draw what their single draws draw, or set an
//! error and draw nothing.

use gleval::gl::ClientArray;
use gleval::prelude::*;
use proptest::prelude::*;

fn array_type() -> impl Strategy<Value = u32> {
    prop_oneof![
        Just(GL_BYTE),
        Just(GL_UNSIGNED_BYTE),
        Just(GL_SHORT),
        Just(GL_UNSIGNED_SHORT),
        Just(GL_INT),
        Just(GL_UNSIGNED_INT),
        Just(GL_FLOAT),
        Just(GL_DOUBLE),
        any::<u32>()
    ]
}

fn known_error(e: u32) -> bool {
    matches!(e, GL_NO_ERROR | GL_INVALID_ENUM | GL_INVALID_VALUE | GL_INVALID_OPERATION)
}

/// A context with a vertex array of 16 points.
fn with_points() -> Gl {
    let mut gl = Gl::new(8, 8);
    let points: Vec<f32> = (0..32).map(|i| i as f32 / 32.0).collect();
    gl.vertex_pointer(2, GL_FLOAT, 0, &ClientArray::new(&points));
    gl.enable_client_state(GL_VERTEX_ARRAY);
    gl
}

/// The positions a context drew.
fn drawn(gl: &mut Gl) -> Vec<[f32; 4]> {
    gl.frame().expanded().vertices.iter().map(|v| v.position).collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn multi_draws_are_their_single_draws_or_draw_nothing(
        mode in prop_oneof![0u32..10, Just(0x1234u32)],
        primcount in -2i32..5,
        firsts in proptest::collection::vec(0i32..8, 0..5),
        counts in proptest::collection::vec(-1i32..8, 0..5),
        type_ in prop_oneof![Just(GL_UNSIGNED_BYTE), Just(GL_UNSIGNED_SHORT), Just(GL_UNSIGNED_INT), Just(GL_FLOAT)],
        range in (0u32..20, 0u32..20),
    ) {
        let (mut multi, mut single) = (with_points(), with_points());
        multi.multi_draw_arrays(mode, &firsts, &counts, primcount);
        let error = multi.get_error();
        prop_assert!(known_error(error));
        if error == GL_NO_ERROR {
            for (&f, &c) in firsts.iter().zip(&counts).take(primcount as usize) {
                single.draw_arrays(mode, f, c);
            }
            prop_assert_eq!(single.get_error(), GL_NO_ERROR);
            prop_assert_eq!(drawn(&mut multi), drawn(&mut single));
        } else {
            prop_assert!(drawn(&mut multi).is_empty(), "an error draws nothing");
        }
        // The same with index arrays (each one's indices, of the type, all below 16).
        let index_bytes: Vec<Vec<u8>> = counts.iter().map(|&c| (0..c.max(0) * 4).map(|i| (i % 16) as u8 * u8::from(i % 4 == 0)).collect()).collect();
        let indices: Vec<&[u8]> = index_bytes.iter().map(Vec::as_slice).collect();
        let (mut multi, mut single) = (with_points(), with_points());
        multi.multi_draw_elements(mode, &counts, type_, &indices, primcount);
        let error = multi.get_error();
        prop_assert!(known_error(error));
        if error == GL_NO_ERROR {
            for (&c, i) in counts.iter().zip(&indices).take(primcount as usize) {
                single.draw_elements(mode, c, type_, i);
            }
            prop_assert_eq!(drawn(&mut multi), drawn(&mut single));
        } else {
            prop_assert!(drawn(&mut multi).is_empty(), "an error draws nothing");
        }
        // glDrawRangeElements: glDrawElements when start <= end, else GL_INVALID_VALUE.
        let (start, end) = range;
        let count = counts.first().copied().unwrap_or(0);
        let bytes = index_bytes.first().cloned().unwrap_or_default();
        let (mut ranged, mut plain) = (with_points(), with_points());
        ranged.draw_range_elements(mode, start, end, count, type_, &bytes);
        plain.draw_elements(mode, count, type_, &bytes);
        let (e_ranged, e_plain) = (ranged.get_error(), plain.get_error());
        if end < start {
            prop_assert_eq!(e_ranged, GL_INVALID_VALUE);
            prop_assert!(drawn(&mut ranged).is_empty());
        } else {
            prop_assert_eq!(e_ranged, e_plain);
            prop_assert_eq!(drawn(&mut ranged), drawn(&mut plain));
        }
    }

    #[test]
    fn random_arrays_and_draws_never_panic(
        bytes in 0usize..200,
        pointers in proptest::collection::vec((0usize..6, -2i32..6, array_type(), -8i32..40, 0usize..16), 1..6),
        draws in proptest::collection::vec((0u32..12, -3i32..20, -2i32..30, prop_oneof![Just(GL_UNSIGNED_BYTE), Just(GL_UNSIGNED_SHORT), Just(GL_UNSIGNED_INT), any::<u32>()]), 1..6),
        enabled in proptest::collection::vec(any::<bool>(), 6),
    ) {
        let mut gl = Gl::new(8, 8);
        let memory = ClientArray::from_bytes((0..bytes).map(|i| (i * 37 % 251) as u8).collect());
        for (which, size, type_, stride, offset) in pointers {
            let p = memory.at_byte(offset);
            match which {
                0 => gl.vertex_pointer(size, type_, stride, p),
                1 => gl.normal_pointer(type_, stride, p),
                2 => gl.color_pointer(size, type_, stride, p),
                3 => gl.tex_coord_pointer(size, type_, stride, p),
                4 => gl.edge_flag_pointer(stride, p),
                _ => gl.interleaved_arrays(GL_V2F + type_ % 16, stride, p),
            }
            prop_assert!(known_error(gl.get_error()));
        }
        let caps = [GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_INDEX_ARRAY, GL_TEXTURE_COORD_ARRAY, GL_EDGE_FLAG_ARRAY];
        for (cap, on) in caps.iter().zip(&enabled) {
            if *on { gl.enable_client_state(*cap) } else { gl.disable_client_state(*cap) }
        }
        for (mode, first, count, index_type) in draws {
            let before = gl.frame().vertices.len();
            let indices: Vec<u32> = (0..40).map(|i| (i * 7 % 13) as u32).collect();
            if first % 2 == 0 {
                gl.draw_arrays(mode, first, count);
            } else {
                gl.draw_elements(mode, count, index_type, &indices);
            }
            let e = gl.get_error();
            prop_assert!(known_error(e));
            let drawn = gl.frame().vertices.len() - before;
            if e == GL_NO_ERROR {
                prop_assert_eq!(drawn, count.max(0) as usize);
            } else {
                prop_assert_eq!(drawn, 0);
            }
            gl.array_element(first);
            prop_assert!(known_error(gl.get_error()));
        }
    }

    #[test]
    fn small_selection_buffers_hold_a_prefix(size in -2i32..40, names in proptest::collection::vec(0u32..4, 1..8)) {
        let run = |gl: &mut Gl, size: i32| {
            gl.select_buffer(size);
            gl.render_mode(GL_SELECT);
            gl.init_names();
            for (k, &n) in names.iter().enumerate() {
                match n {
                    0 => gl.push_name(k as u32),
                    1 => gl.load_name(k as u32),
                    2 => gl.pop_name(),
                    _ => {}
                }
                gl.begin(GL_TRIANGLES);
                gl.vertex3f(-0.5, -0.5, k as f32 / 10.0);
                gl.vertex3f(0.5, -0.5, 0.0);
                gl.vertex3f(0.0, 0.5, 0.0);
                gl.end();
            }
            let hits = gl.render_mode(GL_RENDER);
            (hits, gl.select_values().to_vec())
        };
        let mut gl = Gl::new(8, 8);
        let (all_hits, all) = run(&mut gl, 1000);
        prop_assert!(all_hits >= 0);
        let _ = gl.get_error();
        let (hits, some) = run(&mut gl, size);
        let e = gl.get_error();
        prop_assert!(matches!(e, GL_NO_ERROR | GL_INVALID_VALUE | GL_INVALID_OPERATION | GL_STACK_UNDERFLOW | GL_STACK_OVERFLOW));
        if size >= 0 {
            let size = size as usize;
            prop_assert_eq!(&some[..], &all[..all.len().min(size)]);
            prop_assert_eq!(hits == -1, all.len() > size);
            if all.len() <= size {
                prop_assert_eq!(hits, all_hits);
            }
        }
    }
}
