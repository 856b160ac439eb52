//! The type variants of GL's per-vertex calls: `glColor3b` … `glColor4usv`, GL 1.4's
//! `glSecondaryColor3b` … `glSecondaryColor3usv`, `glNormal3b` …
//! `glNormal3sv`, `glVertex2i` … `glVertex4sv`, `glTexCoord1d` … `glTexCoord4sv`, the
//! remaining `glRasterPos` forms and `glRect*v`. Each converts its values and calls the float
//! form, so lists, errors and state are the float form's.
//!
//! Conversions (GL 1.1 spec §2.7, table 2.6): colour and normal components of an integer type
//! are normalised, unsigned c to c / (2ᵇ − 1) and signed c to (2c + 1) / (2ᵇ − 1), computed as
//! Mesa's `UBYTE_TO_FLOAT` … `INT_TO_FLOAT` compute them, so that the values agree with Mesa's
//! bit for bit (checked in `tests/reference/calls/cases/typed.calls`); positions, texture
//! coordinates and raster positions convert integers as they are. A `*v` slice shorter than the
//! call reads is `GL_INVALID_VALUE`, as everywhere in this façade.

use super::types::*;
use super::Gl;

/// A component type of GL's typed calls and how its values become floats.
pub trait GlComponent: Copy {
    /// The value as a colour or normal component (normalised for integer types).
    fn normalized(self) -> f32;
    /// The value as a coordinate (converted as it is).
    fn plain(self) -> f32;
}

impl GlComponent for GLbyte {
    fn normalized(self) -> f32 {
        (2.0 * f32::from(self) + 1.0) * (1.0 / 255.0)
    }
    fn plain(self) -> f32 {
        f32::from(self)
    }
}

impl GlComponent for GLubyte {
    fn normalized(self) -> f32 {
        f32::from(self) / 255.0
    }
    fn plain(self) -> f32 {
        f32::from(self)
    }
}

impl GlComponent for GLshort {
    fn normalized(self) -> f32 {
        (2.0 * f32::from(self) + 1.0) * (1.0 / 65535.0)
    }
    fn plain(self) -> f32 {
        f32::from(self)
    }
}

impl GlComponent for GLushort {
    fn normalized(self) -> f32 {
        f32::from(self) * (1.0 / 65535.0)
    }
    fn plain(self) -> f32 {
        f32::from(self)
    }
}

impl GlComponent for GLint {
    fn normalized(self) -> f32 {
        // Mesa: the numerator in float, the scale in double.
        (f64::from(2.0 * self as f32 + 1.0) * (1.0 / 4_294_967_295.0)) as f32
    }
    fn plain(self) -> f32 {
        self as f32
    }
}

impl GlComponent for GLuint {
    fn normalized(self) -> f32 {
        (f64::from(self) * (1.0 / 4_294_967_295.0)) as f32
    }
    fn plain(self) -> f32 {
        self as f32
    }
}

impl GlComponent for GLdouble {
    fn normalized(self) -> f32 {
        self as f32
    }
    fn plain(self) -> f32 {
        self as f32
    }
}

impl GlComponent for GLfloat {
    fn normalized(self) -> f32 {
        self
    }
    fn plain(self) -> f32 {
        self
    }
}

impl Gl {
    /// `glColor3*` of any component type: alpha 1.
    fn color3<T: GlComponent>(&mut self, [r, g, b]: [T; 3]) {
        self.color4f(r.normalized(), g.normalized(), b.normalized(), 1.0);
    }

    /// `glColor4*` of any component type.
    fn color4<T: GlComponent>(&mut self, [r, g, b, a]: [T; 4]) {
        self.color4f(r.normalized(), g.normalized(), b.normalized(), a.normalized());
    }

    /// `glSecondaryColor3*` of any component type (GL 1.4), converted as `glColor3*`.
    fn secondary_color3<T: GlComponent>(&mut self, [r, g, b]: [T; 3]) {
        self.secondary_color3f(r.normalized(), g.normalized(), b.normalized());
    }

    fn normal3<T: GlComponent>(&mut self, [x, y, z]: [T; 3]) {
        self.normal3f(x.normalized(), y.normalized(), z.normalized());
    }

    fn vertex_n<T: GlComponent, const N: usize>(&mut self, v: [T; N]) {
        let f = v.map(GlComponent::plain);
        match N {
            2 => self.vertex2f(f[0], f[1]),
            3 => self.vertex3f(f[0], f[1], f[2]),
            _ => self.vertex4f(f[0], f[1], f[2], f[3]),
        }
    }

    fn tex_coord_n<T: GlComponent, const N: usize>(&mut self, v: [T; N]) {
        let f = v.map(GlComponent::plain);
        match N {
            1 => self.tex_coord1f(f[0]),
            2 => self.tex_coord2f(f[0], f[1]),
            3 => self.tex_coord3f(f[0], f[1], f[2]),
            _ => self.tex_coord4f(f[0], f[1], f[2], f[3]),
        }
    }

    fn window_pos_n<T: GlComponent, const N: usize>(&mut self, v: [T; N]) {
        let f = v.map(GlComponent::plain);
        match N {
            2 => self.window_pos3f(f[0], f[1], 0.0),
            _ => self.window_pos3f(f[0], f[1], f[2]),
        }
    }

    fn raster_pos_n<T: GlComponent, const N: usize>(&mut self, v: [T; N]) {
        let f = v.map(GlComponent::plain);
        match N {
            2 => self.raster_pos2f(f[0], f[1]),
            3 => self.raster_pos3f(f[0], f[1], f[2]),
            _ => self.raster_pos4f(f[0], f[1], f[2], f[3]),
        }
    }
}

/// Scalar forms: `name(a, b, …)` → `helper([a, b, …])`.
macro_rules! scalar_forms {
    ($helper:ident; $($name:ident($t:ty; $($arg:ident),+));+ $(;)?) => {
        impl Gl {
            $(
                #[doc = concat!("`gl", stringify!($name), "`: converted as the module says, then as the float form.")]
                pub fn $name(&mut self, $($arg: $t),+) {
                    self.$helper([$($arg),+]);
                }
            )+
        }
    };
}

/// Vector forms: `name(&[T])` reading `N` values → `helper([…; N])`.
macro_rules! vector_forms {
    ($helper:ident; $($name:ident($t:ty; $n:literal));+ $(;)?) => {
        impl Gl {
            $(
                #[doc = concat!("`gl", stringify!($name), "`: `v` needs ", stringify!($n), " values.")]
                pub fn $name(&mut self, v: &[$t]) {
                    if let Some(v) = self.first::<$n, $t>(v) {
                        self.$helper(v);
                    }
                }
            )+
        }
    };
}

scalar_forms!(color3;
    color3b(GLbyte; r, g, b); color3s(GLshort; r, g, b); color3i(GLint; r, g, b);
    color3d(GLdouble; r, g, b); color3us(GLushort; r, g, b); color3ui(GLuint; r, g, b));
scalar_forms!(color4;
    color4b(GLbyte; r, g, b, a); color4s(GLshort; r, g, b, a); color4i(GLint; r, g, b, a);
    color4d(GLdouble; r, g, b, a); color4ub(GLubyte; r, g, b, a); color4us(GLushort; r, g, b, a);
    color4ui(GLuint; r, g, b, a));
vector_forms!(color3;
    color3bv(GLbyte; 3); color3sv(GLshort; 3); color3iv(GLint; 3); color3dv(GLdouble; 3);
    color3ubv(GLubyte; 3); color3usv(GLushort; 3); color3uiv(GLuint; 3));
vector_forms!(color4;
    color4bv(GLbyte; 4); color4sv(GLshort; 4); color4iv(GLint; 4); color4dv(GLdouble; 4);
    color4ubv(GLubyte; 4); color4usv(GLushort; 4); color4uiv(GLuint; 4));

scalar_forms!(secondary_color3;
    secondary_color3b(GLbyte; r, g, b); secondary_color3s(GLshort; r, g, b);
    secondary_color3i(GLint; r, g, b); secondary_color3d(GLdouble; r, g, b);
    secondary_color3ub(GLubyte; r, g, b); secondary_color3us(GLushort; r, g, b);
    secondary_color3ui(GLuint; r, g, b));
vector_forms!(secondary_color3;
    secondary_color3bv(GLbyte; 3); secondary_color3sv(GLshort; 3); secondary_color3iv(GLint; 3);
    secondary_color3dv(GLdouble; 3); secondary_color3ubv(GLubyte; 3); secondary_color3usv(GLushort; 3);
    secondary_color3uiv(GLuint; 3));

scalar_forms!(normal3;
    normal3b(GLbyte; x, y, z); normal3s(GLshort; x, y, z); normal3i(GLint; x, y, z);
    normal3d(GLdouble; x, y, z));
vector_forms!(normal3;
    normal3bv(GLbyte; 3); normal3sv(GLshort; 3); normal3iv(GLint; 3); normal3dv(GLdouble; 3));

scalar_forms!(vertex_n;
    vertex2i(GLint; x, y); vertex2s(GLshort; x, y); vertex3i(GLint; x, y, z); vertex3s(GLshort; x, y, z);
    vertex4d(GLdouble; x, y, z, w); vertex4i(GLint; x, y, z, w); vertex4s(GLshort; x, y, z, w));
vector_forms!(vertex_n;
    vertex2dv(GLdouble; 2); vertex2iv(GLint; 2); vertex2sv(GLshort; 2);
    vertex3dv(GLdouble; 3); vertex3iv(GLint; 3); vertex3sv(GLshort; 3);
    vertex4dv(GLdouble; 4); vertex4iv(GLint; 4); vertex4sv(GLshort; 4));

scalar_forms!(tex_coord_n;
    tex_coord1d(GLdouble; s); tex_coord1i(GLint; s); tex_coord1s(GLshort; s);
    tex_coord2d(GLdouble; s, t); tex_coord2i(GLint; s, t); tex_coord2s(GLshort; s, t);
    tex_coord3d(GLdouble; s, t, r); tex_coord3i(GLint; s, t, r); tex_coord3s(GLshort; s, t, r);
    tex_coord4d(GLdouble; s, t, r, q); tex_coord4i(GLint; s, t, r, q); tex_coord4s(GLshort; s, t, r, q));
vector_forms!(tex_coord_n;
    tex_coord1fv(GLfloat; 1); tex_coord1dv(GLdouble; 1); tex_coord1iv(GLint; 1); tex_coord1sv(GLshort; 1);
    tex_coord2dv(GLdouble; 2); tex_coord2iv(GLint; 2); tex_coord2sv(GLshort; 2);
    tex_coord3fv(GLfloat; 3); tex_coord3dv(GLdouble; 3); tex_coord3iv(GLint; 3); tex_coord3sv(GLshort; 3);
    tex_coord4fv(GLfloat; 4); tex_coord4dv(GLdouble; 4); tex_coord4iv(GLint; 4); tex_coord4sv(GLshort; 4));

scalar_forms!(raster_pos_n;
    raster_pos2s(GLshort; x, y); raster_pos3s(GLshort; x, y, z); raster_pos4i(GLint; x, y, z, w);
    raster_pos4s(GLshort; x, y, z, w));
vector_forms!(raster_pos_n;
    raster_pos2sv(GLshort; 2); raster_pos3iv(GLint; 3); raster_pos3sv(GLshort; 3);
    raster_pos4dv(GLdouble; 4); raster_pos4iv(GLint; 4); raster_pos4sv(GLshort; 4));

scalar_forms!(window_pos_n;
    window_pos2f(GLfloat; x, y); window_pos2d(GLdouble; x, y); window_pos2i(GLint; x, y);
    window_pos2s(GLshort; x, y); window_pos3d(GLdouble; x, y, z); window_pos3i(GLint; x, y, z);
    window_pos3s(GLshort; x, y, z));
vector_forms!(window_pos_n;
    window_pos2fv(GLfloat; 2); window_pos2dv(GLdouble; 2); window_pos2iv(GLint; 2); window_pos2sv(GLshort; 2);
    window_pos3fv(GLfloat; 3); window_pos3dv(GLdouble; 3); window_pos3iv(GLint; 3); window_pos3sv(GLshort; 3));

impl Gl {
    /// `glRects`.
    pub fn rects(&mut self, x1: GLshort, y1: GLshort, x2: GLshort, y2: GLshort) {
        self.rectf(x1.plain(), y1.plain(), x2.plain(), y2.plain());
    }

    /// `glRect*v` of any type: two corners of 2 values each.
    fn rect_v<T: GlComponent>(&mut self, v1: &[T], v2: &[T]) {
        let (Some([x1, y1]), Some([x2, y2])) = (self.first::<2, T>(v1), self.first::<2, T>(v2)) else { return };
        self.rectf(x1.plain(), y1.plain(), x2.plain(), y2.plain());
    }

    /// `glRectfv`: `v1` and `v2` need 2 values each.
    pub fn rectfv(&mut self, v1: &[GLfloat], v2: &[GLfloat]) {
        self.rect_v(v1, v2);
    }

    /// `glRectdv`: `v1` and `v2` need 2 values each.
    pub fn rectdv(&mut self, v1: &[GLdouble], v2: &[GLdouble]) {
        self.rect_v(v1, v2);
    }

    /// `glRectiv`: `v1` and `v2` need 2 values each.
    pub fn rectiv(&mut self, v1: &[GLint], v2: &[GLint]) {
        self.rect_v(v1, v2);
    }

    /// `glRectsv`: `v1` and `v2` need 2 values each.
    pub fn rectsv(&mut self, v1: &[GLshort], v2: &[GLshort]) {
        self.rect_v(v1, v2);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::consts::*;

    #[test]
    fn short_slices_are_invalid_values_and_change_nothing() {
        let mut gl = Gl::new(8, 8);
        gl.color3bv(&[1, 2]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        gl.rectsv(&[0, 0], &[1]);
        assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        let mut c = [0.0; 4];
        gl.get_floatv(GL_CURRENT_COLOR, &mut c);
        assert_eq!(c, [1.0; 4]);
    }

    #[test]
    fn extremes_map_to_the_ends_of_the_range() {
        // GL 1.1 table 2.6: the most negative value is -1, the largest 1.
        assert_eq!(i8::MIN.normalized(), -1.0);
        assert_eq!(i8::MAX.normalized(), 1.0);
        assert_eq!(i16::MIN.normalized(), -1.0);
        assert_eq!(u16::MAX.normalized(), 1.0);
        assert_eq!(i32::MIN.normalized(), -1.0);
        assert_eq!(i32::MAX.normalized(), 1.0);
        assert_eq!(u32::MAX.normalized(), 1.0);
    }
}
