//! GLUT font handles by number: the values freeglut gives its fonts where a handle is a small
//! integer (`GL/freeglut_std.h` on Windows, and gleval's own `GL/glut.h`), for the C ABI to
//! turn a `void *font` back into a font. (On Linux freeglut's handles are instead the
//! addresses of its font objects, `&glutStrokeRoman`; the C ABI maps those to these numbers.)

use super::{
    GlutBitmapFont, GlutStrokeFont, GLUT_BITMAP_8_BY_13, GLUT_BITMAP_9_BY_15, GLUT_BITMAP_HELVETICA_10,
    GLUT_BITMAP_HELVETICA_12, GLUT_BITMAP_HELVETICA_18, GLUT_BITMAP_TIMES_ROMAN_10, GLUT_BITMAP_TIMES_ROMAN_24,
    GLUT_STROKE_MONO_ROMAN, GLUT_STROKE_ROMAN,
};

impl GlutBitmapFont {
    /// Every bitmap font, in freeglut's numbering (2 ..= 8).
    pub const ALL: [Self; 7] = [
        GLUT_BITMAP_9_BY_15,
        GLUT_BITMAP_8_BY_13,
        GLUT_BITMAP_TIMES_ROMAN_10,
        GLUT_BITMAP_TIMES_ROMAN_24,
        GLUT_BITMAP_HELVETICA_10,
        GLUT_BITMAP_HELVETICA_12,
        GLUT_BITMAP_HELVETICA_18,
    ];

    /// The font freeglut numbers `id` ([`GlutBitmapFont::id`]), if it is a bitmap font.
    #[must_use]
    pub fn from_id(id: usize) -> Option<Self> {
        Self::ALL.into_iter().find(|f| usize::from(f.id()) == id)
    }
}

impl GlutStrokeFont {
    /// Both stroke fonts, in freeglut's numbering (0 and 1).
    pub const ALL: [Self; 2] = [GLUT_STROKE_ROMAN, GLUT_STROKE_MONO_ROMAN];

    /// The font freeglut numbers `id` ([`GlutStrokeFont::id`]), if it is a stroke font.
    #[must_use]
    pub fn from_id(id: usize) -> Option<Self> {
        Self::ALL.into_iter().find(|f| usize::from(f.id()) == id)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_freeglut_s_and_name_one_font_each() {
        // GL/freeglut_std.h (the _WIN32 branch): STROKE_ROMAN 0, MONO_ROMAN 1, 9_BY_15 2,
        // 8_BY_13 3, TIMES_ROMAN_10 4, TIMES_ROMAN_24 5, HELVETICA_10 6, _12 7, _18 8.
        let bitmap: Vec<u8> = GlutBitmapFont::ALL.iter().map(|f| f.id()).collect();
        assert_eq!(bitmap, [2, 3, 4, 5, 6, 7, 8]);
        assert_eq!(GLUT_STROKE_ROMAN.id(), 0);
        assert_eq!(GLUT_STROKE_MONO_ROMAN.id(), 1);
        for id in 0..=9 {
            let bitmap = GlutBitmapFont::from_id(id);
            let stroke = GlutStrokeFont::from_id(id);
            assert_eq!(bitmap.is_some(), (2..=8).contains(&id), "{id}");
            assert_eq!(stroke.is_some(), id <= 1, "{id}");
            assert_eq!(
                bitmap.map(|f| usize::from(f.id())).or(stroke.map(|f| usize::from(f.id()))),
                Some(id).filter(|&i| i <= 8)
            );
        }
        assert_eq!(GlutBitmapFont::from_id(usize::MAX), None);
    }
}
