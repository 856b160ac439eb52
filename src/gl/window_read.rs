//! Reading the window as drawn so far: the [`WindowImage`] a rasteriser hands back (colour and
//! depth), and the reader a context calls when GL reads its framebuffer in the middle of a
//! frame (`glCopyTexImage`, `glCopyTexSubImage`).
//!
//! The `gl` layer has no framebuffer: whoever owns a rasteriser installs a reader with
//! [`Gl::set_window_reader`] (`App` does, with its own rasteriser; so does the C ABI, and an
//! OSMesa context reads its canvas), and the context calls it with the frame recorded so far.
//! A context without a reader (a bare [`Gl::new`]) reads the window as GL starts it:
//! transparent black at depth 1. `glReadPixels` takes its reader as an argument
//! ([`Gl::read_pixels`]); `glCopyPixels` needs none: it is a frame command that each rasteriser
//! executes in order ([`super::PixelCopy`]).

use super::frame::Frame;
use super::Gl;

/// A window's buffers: RGBA8 colour and depth in [0, 1], rows from the top, as the rasterisers
/// keep them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct WindowImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// RGBA8, `width · height · 4` bytes, rows top to bottom.
    pub color: Vec<u8>,
    /// One depth a pixel, rows top to bottom; empty when the reader was not asked for it.
    pub depth: Vec<f32>,
    /// The samples each occlusion query slot of the frame counted ([`super::Command::Query`]);
    /// a slot past the end counted none.
    pub samples: Vec<u64>,
}

impl WindowImage {
    /// A window as GL starts it (transparent black, depth 1).
    #[must_use]
    pub fn blank(width: u32, height: u32) -> Self {
        let n = width as usize * height as usize;
        Self { width, height, color: vec![0; 4 * n], depth: vec![1.0; n], samples: Vec::new() }
    }

    /// The index of window pixel (`x`, `y`), y counted from the bottom as GL counts it.
    fn index(&self, x: i64, y: i64) -> Option<usize> {
        let inside = (0..i64::from(self.width)).contains(&x) && (0..i64::from(self.height)).contains(&y);
        inside.then(|| (i64::from(self.height) - 1 - y) as usize * self.width as usize + x as usize)
    }

    /// The colour of window pixel (`x`, `y`) as floats, `None` outside the window.
    #[must_use]
    pub fn color_at(&self, x: i64, y: i64) -> Option<[f32; 4]> {
        let i = self.index(x, y)?;
        let p = self.color.get(4 * i..4 * i + 4)?;
        Some(std::array::from_fn(|k| f32::from(p[k]) / 255.0))
    }

    /// The depth of window pixel (`x`, `y`), `None` outside the window or without depth.
    #[must_use]
    pub fn depth_at(&self, x: i64, y: i64) -> Option<f32> {
        self.depth.get(self.index(x, y)?).copied()
    }
}

/// What a reader is: given the frame recorded so far and the window's size, the window with
/// that frame drawn (`None` when it cannot be drawn; the caller reads nothing then).
pub type WindowReader = Box<dyn FnMut(&Frame, u32, u32) -> Option<WindowImage>>;

/// A context's reader, if one is installed.
#[derive(Default)]
pub(crate) struct Reader(Option<WindowReader>);

impl std::fmt::Debug for Reader {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(if self.0.is_some() { "Reader(installed)" } else { "Reader(none)" })
    }
}

impl Gl {
    /// Installs the reader GL calls when it reads the window mid-frame (see the module docs).
    pub fn set_window_reader(&mut self, reader: impl FnMut(&Frame, u32, u32) -> Option<WindowImage> + 'static) {
        self.recorder.window_reader = Reader(Some(Box::new(reader)));
    }

    /// The window with everything recorded so far drawn, through the installed reader (a blank
    /// window without one).
    pub(crate) fn read_window(&mut self) -> Option<WindowImage> {
        let (w, h) = (self.width().max(1) as u32, self.height().max(1) as u32);
        let Some(mut reader) = self.recorder.window_reader.0.take() else { return Some(WindowImage::blank(w, h)) };
        let image = reader(self.frame(), w, h);
        self.recorder.window_reader.0 = Some(reader);
        image
    }
}
