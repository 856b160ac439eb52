//! Zoomed pixel rectangles (GL 1.1 spec §3.6.3, "Conversion to Fragments"): pixel (i, j) of an
//! image drawn at (xr, yr) with `glPixelZoom(zx, zy)` becomes the fragments whose centres lie in
//! the rectangle with corners (xr + zx·i, yr + zy·j) and (xr + zx·(i + 1), yr + zy·(j + 1)).
//! `glDrawPixels` and `glCopyPixels` both go through [`zoomed_pixels`].
//!
//! Mesa 22 (llvmpipe) draws the image as one textured quad from the rounded raster position
//! (`st_cb_drawpixels.c`), sampled at pixel centres. Measured with OSMesa on a 3 × 2 image (zooms
//! 1, 2.5, 1.5, −2, −2.5, −1.5, 0.5, 0.4, 1/3, 0, ±10³⁰): a centre on the quad's low edge (left,
//! bottom) is in, on its high edge out; a negative zoom mirrors the image about the raster
//! position; zoom 0 draws nothing; 10³⁰ fills the window from the raster position on. Where a
//! centre falls exactly on the boundary between two image pixels (zooms such as 2.5 or 0.5),
//! Mesa takes the column nearer the raster position and the row farther from it (its
//! interpolated texture coordinates round so); one row of the 2.5 × 2.5 picture mixes both
//! (the quad's two triangles interpolate differently), which this rule cannot follow.

use std::ops::Range;

/// The window columns (or rows), within `0..limit`, whose centres c + ½ lie in the zoomed
/// image's extent [lo, hi): from `origin` to `origin + zoom · n`, in either order.
#[must_use]
pub fn zoom_extent(origin: i32, zoom: f32, n: usize, limit: u32) -> Range<u32> {
    // 0 · ∞ would be NaN: an empty image has no extent whatever the zoom.
    let length = if n == 0 { 0.0 } else { f64::from(zoom) * n as f64 };
    let (a, b) = (f64::from(origin), f64::from(origin) + length);
    if b.is_nan() {
        return 0..0;
    }
    let (lo, hi) = (a.min(b), a.max(b));
    let pixel = |x: f64| (x - 0.5).ceil().clamp(0.0, f64::from(limit)) as u32;
    pixel(lo)..pixel(hi)
}

/// The image column window column `c` shows: a tie goes to the column nearer the origin.
fn column_of(c: u32, origin: i32, zoom: f32, n: usize) -> usize {
    let s = (f64::from(c) + 0.5 - f64::from(origin)) / f64::from(zoom);
    ((s.ceil() - 1.0).max(0.0) as usize).min(n - 1)
}

/// The image row window row `r` shows: a tie goes to the row farther from the origin.
fn row_of(r: u32, origin: i32, zoom: f32, n: usize) -> usize {
    let t = (f64::from(r) + 0.5 - f64::from(origin)) / f64::from(zoom);
    (t.floor().max(0.0) as usize).min(n - 1)
}

/// Every fragment of a `width` × `height` image drawn at window (`x0`, `y0`) with `zoom`, inside
/// a `window` of (width, height) pixels: ((i, j) in the image, (x, y) in the window), both
/// counted from the bottom left. Each covered window pixel appears once, so the work is bounded
/// by the window whatever the zoom.
pub fn zoomed_pixels(
    [x0, y0]: [i32; 2],
    zoom: [f32; 2],
    (width, height): (usize, usize),
    (window_width, window_height): (u32, u32),
) -> impl Iterator<Item = ((usize, usize), (u32, u32))> {
    let columns: Vec<(u32, usize)> =
        zoom_extent(x0, zoom[0], width, window_width).map(|x| (x, column_of(x, x0, zoom[0], width))).collect();
    zoom_extent(y0, zoom[1], height, window_height).flat_map(move |y| {
        let j = row_of(y, y0, zoom[1], height);
        columns.clone().into_iter().map(move |(x, i)| ((i, j), (x, y)))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 3 × 2 image zoomed into a 24 × 8 window, as rows of image pixel numbers (top row
    /// first), `.` where nothing is drawn: the layout of the OSMesa probe.
    fn picture(origin: [i32; 2], zoom: [f32; 2]) -> Vec<String> {
        let mut rows = vec![vec!['.'; 24]; 8];
        for ((i, j), (x, y)) in zoomed_pixels(origin, zoom, (3, 2), (24, 8)) {
            rows[7 - y as usize][x as usize] = char::from(b'a' + (3 * j + i) as u8);
        }
        rows.into_iter().map(|r| r.into_iter().collect::<String>().trim_end_matches('.').to_string()).collect()
    }

    #[test]
    fn whole_zooms_repeat_pixels_and_negative_ones_mirror() {
        // Mesa's pictures (OSMesa probe), pixel 0..2 the bottom row, 3..5 the top one.
        let p = picture([12, 6], [-2.0, -2.0]);
        assert_eq!(p[2..6], ["......ccbbaa", "......ccbbaa", "......ffeedd", "......ffeedd"]);
        let p = picture([2, 1], [1.0, 1.0]);
        assert_eq!(p[5..7], ["..def", "..abc"]);
        let p = picture([12, 6], [-1.0, 1.0]);
        assert_eq!(p[0..2], [".........fed", ".........cba"]);
    }

    #[test]
    fn fractional_zooms_take_the_low_edge_and_leave_the_high_one() {
        // Zoom 2.5 from x = 2 covers [2, 9.5): columns 2..=8 (the centre 9.5 is out).
        let p = picture([2, 1], [2.5, 1.0]);
        assert_eq!(p[6].len(), 9);
        // Zoom −2.5 from x = 12 covers [4.5, 12): the centre 4.5 is in.
        let p = picture([12, 6], [-2.5, -1.0]);
        assert!(p[2].starts_with("....c"));
        // Small zooms drop pixels: 0.5 keeps one, and its ties go as Mesa's.
        assert_eq!(picture([2, 1], [0.5, 0.5])[6], "..d");
        // Zoom 2.5 × 1.5: column ties toward the origin, row ties away (Mesa's picture).
        let p = picture([2, 1], [2.5, 1.5]);
        assert_eq!(p[4..7], ["..dddeeff", "..dddeeff", "..aaabbcc"]);
        let p = picture([12, 6], [-2.5, -1.5]);
        assert_eq!(p[2..5], ["....cccbbaaa", "....fffeeddd", "....fffeeddd"]);
        assert_eq!(picture([2, 1], [0.4, 1.0])[6], "..b");
    }

    #[test]
    fn degenerate_and_huge_zooms_stay_in_the_window() {
        assert!(zoomed_pixels([2, 1], [0.0, 1.0], (3, 2), (24, 8)).next().is_none());
        assert!(zoomed_pixels([2, 1], [f32::NAN, 1.0], (3, 2), (24, 8)).next().is_none());
        let p = picture([2, 1], [1e30, 1.0]);
        assert_eq!(p[6], format!("..{}", "a".repeat(22)));
        let p = picture([2, 1], [-1e30, 1.0]);
        assert_eq!(p[6], "aa");
        assert_eq!(zoom_extent(2, f32::INFINITY, 1, 24), 2..24);
        assert_eq!(zoom_extent(2, f32::INFINITY, 0, 24), 2..2);
        assert_eq!(zoom_extent(i32::MAX, f32::MAX, 5, 24), 24..24);
        assert_eq!(zoom_extent(i32::MIN, -f32::MAX, 5, 24), 0..0);
        let all = zoomed_pixels([2, 1], [f32::INFINITY, -f32::INFINITY], (3, 2), (24, 8)).count();
        assert_eq!(all, 22, "columns 2.. of row 0 (rows below y = 1)");
    }
}
