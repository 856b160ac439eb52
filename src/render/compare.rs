//! Comparing pictures the way the conformance tests do (and as users' PNG tests can): a pixel matches if some pixel within one pixel
//! of it in the other image has every channel within `TOLERANCE`, checked both ways (so a
//! missing object and an extra object both count). The score is the larger of the two
//! mismatched fractions. One-pixel shifts (rasterisation rules at edges, which differ between
//! llvmpipe's GL and lavapipe's Vulkan rules) and small shading differences (float rounding in
//! lighting) therefore cost nothing, while a wrong colour, a missing primitive or a wrong
//! winding/culling does.

use std::path::{Path, PathBuf};

/// Per-channel difference still counted as equal: 24/255 covers lighting rounding and
/// interpolation differences between rasterisers, far below any real colour change.
pub const TOLERANCE: u8 = 24;

/// An RGB picture, rows top to bottom.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RgbImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height * 3` bytes.
    pub rgb: Vec<u8>,
}

impl RgbImage {
    /// Drops the alpha channel of a rendered [`super::Image`].
    #[must_use]
    pub fn from_rgba(image: &super::Image) -> Self {
        let rgb = image.pixels.chunks_exact(4).flat_map(|p| [p[0], p[1], p[2]]).collect();
        Self { width: image.width, height: image.height, rgb }
    }

    fn at(&self, x: i64, y: i64) -> Option<[u8; 3]> {
        if x < 0 || y < 0 || x >= i64::from(self.width) || y >= i64::from(self.height) {
            return None;
        }
        let i = ((y as usize) * self.width as usize + x as usize) * 3;
        Some([self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]])
    }
}

/// Loads a PNG (any colour type) as RGB.
pub fn load_png(path: &Path) -> Result<RgbImage, String> {
    let file = std::fs::File::open(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file));
    decoder.set_transformations(png::Transformations::EXPAND);
    let mut reader = decoder.read_info().map_err(|e| e.to_string())?;
    let mut buf = vec![0; reader.output_buffer_size().ok_or("no size")?];
    let info = reader.next_frame(&mut buf).map_err(|e| e.to_string())?;
    let channels = info.color_type.samples();
    let rgb = buf[..info.buffer_size()].chunks_exact(channels).flat_map(|p| [p[0], p[1], p[2]]).collect();
    Ok(RgbImage { width: info.width, height: info.height, rgb })
}

/// Writes an RGB PNG.
pub fn save_png(path: &Path, image: &RgbImage) -> Result<(), String> {
    let file = std::fs::File::create(path).map_err(|e| e.to_string())?;
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), image.width, image.height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().map_err(|e| e.to_string())?;
    writer.write_image_data(&image.rgb).map_err(|e| e.to_string())
}

/// The result of comparing two images of the same size.
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// Pixels of either image without a match in the other (the larger count).
    pub mismatched: usize,
    /// `mismatched` over the pixel count.
    pub fraction: f64,
    /// Where the reference had no match in the actual image, or vice versa.
    pub mask: Vec<bool>,
}

fn unmatched(a: &RgbImage, b: &RgbImage) -> Vec<bool> {
    let mut out = Vec::with_capacity((a.width * a.height) as usize);
    for y in 0..i64::from(a.height) {
        for x in 0..i64::from(a.width) {
            let p = a.at(x, y).expect("inside");
            let found = (-1..=1).any(|dy| {
                (-1..=1)
                    .any(|dx| b.at(x + dx, y + dy).is_some_and(|q| (0..3).all(|c| p[c].abs_diff(q[c]) <= TOLERANCE)))
            });
            out.push(!found);
        }
    }
    out
}

/// Compares two pictures of the same size (an error otherwise).
pub fn compare(reference: &RgbImage, actual: &RgbImage) -> Result<Comparison, String> {
    if (reference.width, reference.height) != (actual.width, actual.height) {
        return Err(format!(
            "size {}x{} vs reference {}x{}",
            actual.width, actual.height, reference.width, reference.height
        ));
    }
    let (ab, ba) = (unmatched(reference, actual), unmatched(actual, reference));
    let count = |m: &[bool]| m.iter().filter(|&&b| b).count();
    let mismatched = count(&ab).max(count(&ba));
    let mask: Vec<bool> = ab.iter().zip(&ba).map(|(a, b)| *a || *b).collect();
    Ok(Comparison { mismatched, fraction: mismatched as f64 / mask.len().max(1) as f64, mask })
}

/// Mismatches in red over a faded reference.
pub fn diff_image(reference: &RgbImage, c: &Comparison) -> RgbImage {
    let rgb = reference
        .rgb
        .chunks_exact(3)
        .zip(&c.mask)
        .flat_map(|(p, &bad)| if bad { [255, 0, 0] } else { [128 + p[0] / 2, 128 + p[1] / 2, 128 + p[2] / 2] })
        .collect();
    RgbImage { width: reference.width, height: reference.height, rgb }
}

/// Compares `actual` with the reference PNG; on failure writes `<name>.actual.png` and
/// `<name>.diff.png` beside the reference and panics with the score.
pub fn assert_matches(reference_path: &Path, actual: &RgbImage, threshold: f64) -> f64 {
    let reference = load_png(reference_path).unwrap_or_else(|e| panic!("reference: {e}"));
    let c = compare(&reference, actual).unwrap_or_else(|e| panic!("{}: {e}", reference_path.display()));
    if c.fraction > threshold {
        let beside = |suffix: &str| -> PathBuf { reference_path.with_extension(suffix) };
        let _ = save_png(&beside("actual.png"), actual);
        let _ = save_png(&beside("diff.png"), &diff_image(&reference, &c));
        panic!(
            "{}: {:.3}% of pixels differ (threshold {:.3}%); wrote {} and {}",
            reference_path.display(),
            c.fraction * 100.0,
            threshold * 100.0,
            beside("actual.png").display(),
            beside("diff.png").display()
        );
    }
    c.fraction
}

#[cfg(test)]
mod tests {
    use super::*;

    fn canvas(w: u32, h: u32) -> RgbImage {
        RgbImage { width: w, height: h, rgb: vec![255; (w * h * 3) as usize] }
    }

    fn line(img: &mut RgbImage, y: u32, x0: u32, x1: u32, colour: [u8; 3]) {
        for x in x0..x1 {
            let i = ((y * img.width + x) * 3) as usize;
            img.rgb[i..i + 3].copy_from_slice(&colour);
        }
    }

    #[test]
    fn identical_and_shifted_images_score_zero() {
        let mut a = canvas(40, 20);
        line(&mut a, 10, 5, 30, [0, 0, 255]);
        let mut shifted = canvas(40, 20);
        line(&mut shifted, 11, 6, 31, [0, 0, 255]);
        assert_eq!(compare(&a, &a).unwrap().fraction, 0.0);
        assert_eq!(compare(&a, &shifted).unwrap().mismatched, 0);
    }

    #[test]
    fn moved_missing_and_recoloured_objects_are_caught() {
        let mut a = canvas(40, 20);
        line(&mut a, 10, 5, 30, [0, 0, 255]);
        let mut moved = canvas(40, 20);
        line(&mut moved, 14, 5, 30, [0, 0, 255]);
        let mut recoloured = canvas(40, 20);
        line(&mut recoloured, 10, 5, 30, [0, 0, 200]);
        let blank = canvas(40, 20);
        for other in [&moved, &recoloured, &blank] {
            assert!(compare(&a, other).unwrap().mismatched >= 25, "a 25-pixel line must count");
        }
        assert!(compare(&a, &canvas(41, 20)).is_err());
    }
}
