//! `bitmap` and `draw_pixels` land exactly on their pixels when rendered: their fragments are
//! one-pixel points at pixel centres, and each rasteriser (the CPU's, and wgpu's: lavapipe in CI)
//! must put each on the intended pixel, no more, no fewer.

use gleval::prelude::*;
use gleval::render::Rasterizer;

const W: i32 = 40;
const H: i32 = 30;

/// An 11 × 9 bitmap of pseudo-random bits, rows of 2 bytes padded to 4 (the default alignment).
fn bits() -> Vec<u8> {
    let mut state = 12345u32;
    (0..9 * 4)
        .map(|_| {
            state = state.wrapping_mul(1_103_515_245).wrapping_add(12345);
            (state >> 16) as u8
        })
        .collect()
}

fn bit(data: &[u8], i: usize, j: usize) -> bool {
    data[j * 4 + i / 8] & (0x80 >> (i % 8)) != 0
}

fn pixel(i: usize, j: usize) -> [u8; 3] {
    [(40 * i) as u8, (60 * j) as u8, 200]
}

fn display(gl: &mut Gl) {
    gl.clear(GL_COLOR_BUFFER_BIT);
    gl.matrix_mode(GL_PROJECTION);
    gl.load_identity();
    gl.ortho(0.0, f64::from(W), 0.0, f64::from(H), -1.0, 1.0);
    gl.color3f(1.0, 1.0, 1.0);
    gl.raster_pos2i(5, 7);
    gl.bitmap(11, 9, 0.0, 0.0, 0.0, 0.0, &bits());
    let rgb: Vec<u8> = (0..4).flat_map(|j| (0..6).flat_map(move |i| pixel(i, j))).collect();
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.raster_pos2i(25, 20);
    gl.draw_pixels(6, 4, GL_RGB, GL_UNSIGNED_BYTE, &rgb);
}

#[test]
fn every_fragment_lands_on_its_own_pixel() {
    lands_on_its_own_pixel(Rasterizer::Cpu);
    lands_on_its_own_pixel(Rasterizer::Wgpu);
}

fn lands_on_its_own_pixel(rasterizer: Rasterizer) {
    let mut app = App::new("raster images", W, H).display(display).with_rasterizer(rasterizer);
    let image = match app.render_image() {
        Ok(image) => image,
        Err(e) if std::env::var("GLEVAL_REQUIRE_ADAPTER").is_ok_and(|v| v == "1") => panic!("{e}"),
        Err(e) => return eprintln!("skipping: {e}"),
    };
    let data = bits();
    let mut wrong = Vec::new();
    for y in 0..H as usize {
        for x in 0..W as usize {
            // Rows of the image are top first; GL's window rows bottom first.
            let at = ((H as usize - 1 - y) * W as usize + x) * 4;
            let got = [image.pixels[at], image.pixels[at + 1], image.pixels[at + 2]];
            let in_bitmap = (5..16).contains(&x) && (7..16).contains(&y) && bit(&data, x - 5, y - 7);
            let in_pixels = (25..31).contains(&x) && (20..24).contains(&y);
            let want = match (in_bitmap, in_pixels) {
                (true, _) => [255; 3],
                (_, true) => pixel(x - 25, y - 20),
                _ => [0; 3],
            };
            if got != want {
                wrong.push((x, y, got, want));
            }
        }
    }
    assert!(
        wrong.is_empty(),
        "{rasterizer:?}: {} pixels differ, first: {:?}",
        wrong.len(),
        &wrong[..wrong.len().min(5)]
    );
}
