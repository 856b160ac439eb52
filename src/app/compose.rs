//! Headless pictures of a program's windows: each top-level window's frame with its subwindows
//! drawn over it in place (GLUT's subwindows are windows inside their parent, each with its own
//! context), one PNG a top-level window.

use super::program::Program;
use super::Headless;
use crate::render::{Image, RenderError};

/// Copies `src` over `dst` with its top left corner at (x, y) of `dst`, clipped to `dst`.
fn blit(dst: &mut Image, src: &Image, x: i32, y: i32) {
    let (dw, dh) = (dst.width as i32, dst.height as i32);
    for row in 0..src.height as i32 {
        let ty = y + row;
        if ty < 0 || ty >= dh {
            continue;
        }
        let x0 = x.max(0);
        let x1 = (x + src.width as i32).min(dw);
        if x0 >= x1 {
            continue;
        }
        let s = ((row * src.width as i32 + (x0 - x)) * 4) as usize;
        let d = ((ty * dw + x0) * 4) as usize;
        let n = ((x1 - x0) * 4) as usize;
        dst.pixels[d..d + n].copy_from_slice(&src.pixels[s..s + n]);
    }
}

/// Where window `id`'s picture goes when the first top-level window's goes to `path`: `path`
/// itself for the first, otherwise `-ID` before the extension (`out.png`, `out-2.png`, ...).
pub(crate) fn png_path(path: &str, id: i32, first: bool) -> String {
    if first {
        return path.to_owned();
    }
    let p = std::path::Path::new(path);
    let stem = p.file_stem().map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let name = match p.extension() {
        Some(ext) => format!("{stem}-{id}.{}", ext.to_string_lossy()),
        None => format!("{stem}-{id}"),
    };
    p.with_file_name(name).to_string_lossy().into_owned()
}

impl Program {
    /// Window `k`'s last frame with its shown subwindows (and theirs) over it, bottom to top.
    pub(crate) fn render_tree(&mut self, k: usize, renderer: &mut Headless) -> Result<Image, RenderError> {
        let slot = &mut self.slots[k];
        let (id, w, h) = (slot.facts.id, slot.facts.width.max(1), slot.facts.height.max(1));
        let frame = slot.gl.take_frame();
        let mut image = renderer.render_frame(&frame, w as u32, h as u32)?;
        for child in self.children(id) {
            if !self.slots[child].facts.shown {
                continue;
            }
            let (x, y) = (self.slots[child].facts.x, self.slots[child].facts.y);
            let picture = self.render_tree(child, renderer)?;
            blit(&mut image, &picture, x, y);
        }
        Ok(image)
    }

    /// The picture of every shown top-level window, with its number.
    pub(crate) fn render_windows(&mut self, renderer: &mut Headless) -> Result<Vec<(i32, Image)>, RenderError> {
        let mut out = Vec::new();
        for k in self.top_level() {
            if self.slots[k].facts.shown {
                let id = self.slots[k].facts.id;
                out.push((id, self.render_tree(k, renderer)?));
            }
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn further_windows_are_named_by_their_number() {
        assert_eq!(png_path("out/a.png", 1, true), "out/a.png");
        assert_eq!(png_path("out/a.png", 3, false), "out/a-3.png");
        assert_eq!(png_path("a", 2, false), "a-2");
    }

    #[test]
    fn a_subwindow_is_copied_in_place_and_clipped() {
        let mut dst = Image { width: 4, height: 3, pixels: vec![0; 48] };
        let src = Image { width: 2, height: 2, pixels: vec![9; 16] };
        blit(&mut dst, &src, 3, 2);
        let set: Vec<usize> = (0..12).filter(|i| dst.pixels[i * 4] == 9).collect();
        assert_eq!(set, [11]);
    }
}
