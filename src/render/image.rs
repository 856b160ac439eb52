//! The picture a headless render hands back, whichever rasteriser drew it.

/// An RGBA8 picture, rows top to bottom (PNG order).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height * 4` bytes.
    pub pixels: Vec<u8>,
}
