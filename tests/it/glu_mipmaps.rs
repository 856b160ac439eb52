//! `gluScaleImage` bit for bit: `tests/reference/glu/scale_image.c` prints what real GLU 9.0.2
//! writes for every format GLU takes with every pair of GL 1.1 types (`GL_BITMAP` included),
//! several sizes (shrinking, growing, exact halving, sides of 1) and pixel-store modes
//! (alignment, row length, skips, swapped bytes, LSB first), and its error codes; gleval must
//! write the same bytes (the buffer starts as 0xcd bytes, so bytes GLU leaves alone count too).

use gleval::prelude::*;
use std::path::Path;

const BUF: usize = 16384;

/// scale_image.c's input: bytes, or floats in [-0.25, 1.25) for `GL_FLOAT`.
fn input(type_: u32, seed: u32) -> Vec<u8> {
    let mut state = seed;
    let mut next = || {
        state = state.wrapping_mul(1_103_515_245).wrapping_add(12345);
        (state >> 16) & 0xffff
    };
    if type_ == GL_FLOAT {
        (0..BUF / 4).flat_map(|_| (next() as f32 / 65536.0 * 1.5 - 0.25).to_ne_bytes()).collect()
    } else {
        (0..BUF).map(|_| next() as u8).collect()
    }
}

/// scale_image.c's `store`.
fn store(gl: &mut Gl, s: i32) {
    let (u, p) = (s == 1 || s == 3, s == 2 || s == 3);
    let pick = |on: bool, a: i32, b: i32| if on { a } else { b };
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, pick(u, 8, 1));
    gl.pixel_storei(GL_UNPACK_ROW_LENGTH, pick(u, 9, 0));
    gl.pixel_storei(GL_UNPACK_SKIP_ROWS, pick(u, 2, 0));
    gl.pixel_storei(GL_UNPACK_SKIP_PIXELS, pick(u, 3, 0));
    gl.pixel_storei(GL_UNPACK_SWAP_BYTES, i32::from(s == 3));
    gl.pixel_storei(GL_UNPACK_LSB_FIRST, i32::from(u));
    gl.pixel_storei(GL_PACK_ALIGNMENT, pick(p, 8, 2));
    gl.pixel_storei(GL_PACK_ROW_LENGTH, pick(p, 11, 0));
    gl.pixel_storei(GL_PACK_SKIP_ROWS, pick(p, 1, 0));
    gl.pixel_storei(GL_PACK_SKIP_PIXELS, pick(p, 5, 0));
    gl.pixel_storei(GL_PACK_SWAP_BYTES, i32::from(s == 3));
    gl.pixel_storei(GL_PACK_LSB_FIRST, i32::from(p));
}

#[test]
fn scale_image_matches_real_glu() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/glu/scale_image.txt");
    let text = std::fs::read_to_string(path).expect("scale_image.txt");
    let mut lines = text.lines();
    let (mut cases, mut failures) = (0, Vec::new());
    let mut gl = Gl::new(4, 4);
    while let (Some(header), Some(bytes)) = (lines.next(), lines.next()) {
        let v: Vec<i64> = header[2..].split(' ').map(|x| x.parse().unwrap()).collect();
        let [format, tin, tout, win, hin, wout, hout, s, seed, rc] = v[..] else { panic!("{header}") };
        store(&mut gl, s as i32);
        let data = input(tin as u32, seed as u32);
        let mut out = vec![0xcdu8; BUF];
        let (f, ti, to) = (format as u32, tin as u32, tout as u32);
        let got = gl.glu_scale_image(f, win as i32, hin as i32, ti, &data, wout as i32, hout as i32, to, &mut out);
        let end = out.iter().rposition(|&b| b != 0xcd).map_or(0, |i| i + 1);
        let hex: String = out[..end].iter().map(|b| format!("{b:02x}")).collect();
        if i64::from(got) != rc || hex != bytes {
            let at = hex.bytes().zip(bytes.bytes()).position(|(a, b)| a != b).unwrap_or(0) / 2;
            failures.push(format!(
                "{header}: returned {got}, first byte differing {at} ({} vs {} bytes)",
                end,
                bytes.len() / 2
            ));
        }
        cases += 1;
    }
    assert!(cases > 800);
    assert!(failures.is_empty(), "{} of {cases} differ from GLU:\n{}", failures.len(), failures.join("\n"));
}

mod properties {
    use super::*;
    use proptest::prelude::*;

    fn format() -> impl Strategy<Value = u32> {
        prop::sample::select(vec![
            GL_RGB,
            GL_RGBA,
            GL_LUMINANCE_ALPHA,
            GL_COLOR_INDEX,
            GL_STENCIL_INDEX,
            GL_BGR,
            0x1234,
            GL_BITMAP,
        ])
    }

    fn type_() -> impl Strategy<Value = u32> {
        prop::sample::select(vec![
            GL_UNSIGNED_BYTE,
            GL_BYTE,
            GL_SHORT,
            GL_UNSIGNED_SHORT,
            GL_INT,
            GL_UNSIGNED_INT,
            GL_FLOAT,
            GL_BITMAP,
            GL_UNSIGNED_SHORT_5_6_5,
            GL_UNSIGNED_INT_8_8_8_8,
            GL_UNSIGNED_BYTE_2_3_3_REV,
            GL_UNSIGNED_SHORT_4_4_4_4,
            GL_UNSIGNED_INT_2_10_10_10_REV,
            GL_DOUBLE,
        ])
    }

    fn size() -> impl Strategy<Value = i32> {
        prop_oneof![4 => -2i32..9, 1 => Just(i32::MAX), 1 => Just(i32::MIN)]
    }

    proptest! {
        /// Any sizes, formats, types, pixel-store modes and slice lengths (short ones too):
        /// no panic, and one of GLU's answers.
        #[test]
        fn scale_image_and_mipmaps_never_panic(
            f in format(), tin in type_(), tout in type_(), (w, h, w2, h2) in (size(), size(), size(), size()),
            s in 0i32..4, len_in in 0usize..2048, len_out in 0usize..2048,
        ) {
            let mut gl = Gl::new(4, 4);
            store(&mut gl, s);
            let data = input(tin, 3);
            let mut out = vec![0u8; len_out];
            let rc = gl.glu_scale_image(f, w, h, tin, &data[..len_in], w2, h2, tout, &mut out) as u32;
            prop_assert!(rc == 0 || [GLU_INVALID_ENUM, GLU_INVALID_VALUE, GLU_INVALID_OPERATION].contains(&rc), "{}", rc);
            gl.bind_texture(GL_TEXTURE_1D, 1);
            let rc = gl.glu_build_1d_mipmaps(GL_TEXTURE_1D, 3, w.min(64), f, tin, &data[..len_in]) as u32;
            prop_assert!(rc == 0 || [GLU_INVALID_ENUM, GLU_INVALID_VALUE, GLU_INVALID_OPERATION].contains(&rc), "{}", rc);
            let rc = gl.glu_build_2d_mipmap_levels(GL_TEXTURE_2D, 3, w, h, f, tin, w2, h2, s, &data[..len_in]) as u32;
            prop_assert!(rc == 0 || [GLU_INVALID_ENUM, GLU_INVALID_VALUE, GLU_INVALID_OPERATION].contains(&rc), "{}", rc);
        }

        /// The 3D builders with any sides (small, so that real levels are made), formats,
        /// types (packed ones too), pixel-store modes (image height and skipped images too),
        /// level ranges and slice lengths: no panic, and one of GLU's answers.
        #[test]
        fn mipmaps_3d_never_panic(
            f in format(), t in type_(), (w, h, d) in (-1i32..7, -1i32..7, -1i32..7),
            (user, base, max) in (-1i32..4, -1i32..4, -1i32..5), s in 0i32..4, image in (0i32..9, 0i32..3),
            len in 0usize..2048, plain in any::<bool>(), internal in prop::sample::select(vec![3, 0x1234]),
        ) {
            let mut gl = Gl::new(4, 4);
            store(&mut gl, s);
            gl.pixel_storei(GL_UNPACK_IMAGE_HEIGHT, image.0);
            gl.pixel_storei(GL_UNPACK_SKIP_IMAGES, image.1);
            let data = input(t, 3);
            let data = &data[..len.min(data.len())];
            gl.bind_texture(GL_TEXTURE_3D, 1);
            let rc = if plain {
                gl.glu_build_3d_mipmaps(GL_TEXTURE_3D, internal, w, h, d, f, t, data)
            } else {
                gl.glu_build_3d_mipmap_levels(GL_TEXTURE_3D, internal, w, h, d, f, t, user, base, max, data)
            } as u32;
            prop_assert!(rc == 0 || [GLU_INVALID_ENUM, GLU_INVALID_VALUE, GLU_INVALID_OPERATION].contains(&rc), "{}", rc);
            let _ = gl.glu_image_len_3d((w, h, d), f, t, !plain);
        }
    }
}
