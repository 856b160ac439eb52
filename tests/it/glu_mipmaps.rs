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
