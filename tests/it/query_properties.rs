//! Property tests of the state queries and the parameter forms beside them: any name, any
//! slice length and any values never panic, set only GL's error codes, write exactly what
//! `Gl::get_len` (the C ABI's promise) says or nothing, and the four `glGet` variants agree
//! with each other as GL 1.1 §6.1.2 converts.

use gleval::prelude::*;
use proptest::prelude::*;

/// Names around GL 1.1's state variables (0x0B00..0x0DFF holds most), the later ones gleval
/// answers, and anything.
fn pname() -> impl Strategy<Value = u32> {
    prop_oneof![
        0x0B00u32..0x0E00,
        0x0C00u32..0x0C40,
        0x3000u32..0x3010,
        0x4000u32..0x4010,
        0x8000u32..0x8100,
        0x8830u32..0x8840,
        any::<u32>()
    ]
}

fn value() -> impl Strategy<Value = f32> {
    prop_oneof![-3.0f32..3.0, Just(f32::NAN), Just(f32::INFINITY), Just(3e9), Just(-0.0), 0.0f32..200.0]
}

/// A state change with arbitrary arguments, through the new entry points.
#[derive(Clone, Debug)]
enum Change {
    Light(u32, u32, Vec<i32>, Vec<f32>),
    Material(u32, u32, Vec<i32>, Vec<f32>),
    Fog(u32, Vec<i32>),
    TexEnv(u32, u32, Vec<i32>),
    TexParameter(u32, u32, Vec<i32>, Vec<f32>),
    Enable(u32),
    Color(f32, f32, f32),
    Blend([u32; 4], [u32; 2], [f32; 4]),
    Begin,
    End,
}

fn ints() -> impl Strategy<Value = Vec<i32>> {
    proptest::collection::vec(prop_oneof![any::<i32>(), -3i32..300], 0..6)
}

fn floats() -> impl Strategy<Value = Vec<f32>> {
    proptest::collection::vec(value(), 0..6)
}

/// Blend factors, equations and anything.
fn blend_enum() -> impl Strategy<Value = u32> {
    prop_oneof![0u32..2, 0x0300u32..0x030A, 0x8001u32..0x800C, any::<u32>()]
}

fn change() -> impl Strategy<Value = Change> {
    let light = prop_oneof![0x4000u32..0x4009, any::<u32>()];
    let face = prop_oneof![Just(GL_FRONT), Just(GL_BACK), Just(GL_FRONT_AND_BACK), any::<u32>()];
    let light_name = prop_oneof![0x1200u32..0x1210, 0x1600u32..0x1604, any::<u32>()];
    prop_oneof![
        (light, light_name.clone(), ints(), floats()).prop_map(|(l, p, i, f)| Change::Light(l, p, i, f)),
        (face, light_name, ints(), floats()).prop_map(|(l, p, i, f)| Change::Material(l, p, i, f)),
        (0x0B60u32..0x0B68, ints()).prop_map(|(p, i)| Change::Fog(p, i)),
        (prop_oneof![Just(GL_TEXTURE_ENV), any::<u32>()], 0x2200u32..0x2202, ints())
            .prop_map(|(t, p, i)| Change::TexEnv(t, p, i)),
        (prop_oneof![Just(GL_TEXTURE_1D), Just(GL_TEXTURE_2D), any::<u32>()], 0x1000u32..0x1006, ints(), floats())
            .prop_map(|(t, p, i, f)| Change::TexParameter(t, p, i, f)),
        pname().prop_map(Change::Enable),
        (value(), value(), value()).prop_map(|(r, g, b)| Change::Color(r, g, b)),
        (
            [blend_enum(), blend_enum(), blend_enum(), blend_enum()],
            [blend_enum(), blend_enum()],
            [value(), value(), value(), value()]
        )
            .prop_map(|(f, e, c)| Change::Blend(f, e, c)),
        Just(Change::Begin),
        Just(Change::End),
    ]
}

fn apply(gl: &mut Gl, c: &Change) {
    match c {
        Change::Light(l, p, i, f) => {
            gl.light_iv(*l, *p, i);
            gl.light_fv(*l, *p, f);
            gl.light_i(*l, *p, i.first().copied().unwrap_or(1));
            gl.light_model_iv(*p, i);
            gl.light_model_f(*p, f.first().copied().unwrap_or(0.0));
        }
        Change::Material(face, p, i, f) => {
            gl.material_iv(*face, *p, i);
            gl.material_fv(*face, *p, f);
            gl.material_i(*face, *p, i.first().copied().unwrap_or(1));
        }
        Change::Fog(p, i) => gl.fogiv(*p, i),
        Change::TexEnv(t, p, i) => gl.tex_enviv(*t, *p, i),
        Change::TexParameter(t, p, i, f) => {
            gl.tex_parameteriv(*t, *p, i);
            gl.tex_parameterfv(*t, *p, f);
        }
        Change::Enable(cap) => gl.enable(*cap),
        Change::Color(r, g, b) => gl.color3f(*r, *g, *b),
        Change::Blend(f, [rgb, alpha], c) => {
            gl.blend_func_separate(f[0], f[1], f[2], f[3]);
            gl.blend_func(f[1], f[0]);
            gl.blend_equation_separate(*rgb, *alpha);
            gl.blend_equation(*alpha);
            gl.blend_color(c[0], c[1], c[2], c[3]);
        }
        Change::Begin => gl.begin(GL_POINTS),
        Change::End => gl.end(),
    }
}

fn known_error(e: u32) -> bool {
    matches!(e, GL_NO_ERROR | GL_INVALID_ENUM | GL_INVALID_VALUE | GL_INVALID_OPERATION | GL_STACK_OVERFLOW)
}

/// The doubles `glGetDoublev(pname)` writes into a slice of 32, and how many.
fn doubles(gl: &mut Gl, pname: u32) -> (Vec<f64>, usize) {
    let mut v = vec![f64::from_bits(0x7FF8_DEAD_BEEF_0001); 32];
    gl.get_doublev(pname, &mut v);
    let n = v.iter().rposition(|x| x.to_bits() != 0x7FF8_DEAD_BEEF_0001).map_or(0, |k| k + 1);
    (v, n)
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: std::env::var("PROPTEST_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(300),
        ..ProptestConfig::default()
    })]

    /// Whatever state the changes leave, every `glGet` writes `get_len` values or none, and
    /// the variants agree: booleans are "not zero", floats the doubles rounded to f32.
    #[test]
    fn every_get_writes_its_length_and_the_variants_agree(
        changes in proptest::collection::vec(change(), 0..12),
        names in proptest::collection::vec(pname(), 1..12),
    ) {
        let mut gl = Gl::new(32, 32);
        for c in &changes {
            apply(&mut gl, c);
            let e = gl.get_error();
            prop_assert!(known_error(e), "error {e:#x} after {c:?}");
        }
        gl.end();
        let _ = gl.get_error();
        for &pname in &names {
            let len = gl.get_len(pname);
            let (d, n) = doubles(&mut gl, pname);
            let error = gl.get_error();
            prop_assert!(error == GL_NO_ERROR || (error == GL_INVALID_ENUM && n == 0), "{pname:#x}: {error:#x}");
            if error == GL_INVALID_ENUM {
                prop_assert_eq!(len, 1);
                continue;
            }
            prop_assert!(n <= len && len <= 16, "{pname:#x}: wrote {n}, get_len {len}");
            let (mut f, mut b, mut i) = (vec![0.0f32; len], vec![7u8; len], vec![0i32; len]);
            gl.get_floatv(pname, &mut f);
            gl.get_booleanv(pname, &mut b);
            gl.get_integerv(pname, &mut i);
            prop_assert_eq!(gl.get_error(), GL_NO_ERROR);
            for k in 0..len {
                prop_assert!(f[k].to_bits() == (d[k] as f32).to_bits(), "{pname:#x}[{k}]: {} vs {}", f[k], d[k]);
                prop_assert_eq!(b[k], u8::from(d[k] != 0.0), "{:#x}[{}]", pname, k);
            }
            // One element short: GL_INVALID_VALUE and nothing written.
            let mut short = vec![-5i32; len - 1];
            gl.get_integerv(pname, &mut short);
            prop_assert_eq!(gl.get_error(), GL_INVALID_VALUE);
            prop_assert!(short.iter().all(|&x| x == -5));
        }
    }

    /// Values set through the vector forms read back through the queries, and the integer
    /// forms' colours normalise as GL 1.1 table 2.6 says (within the f32 rounding).
    #[test]
    fn parameters_read_back(light in 0u32..8, color in proptest::array::uniform4(-1.0f32..1.0), exponent in 0.0f32..128.0) {
        let mut gl = Gl::new(8, 8);
        let l = GL_LIGHT0 + light;
        gl.light_fv(l, GL_DIFFUSE, &color);
        gl.light_f(l, GL_SPOT_EXPONENT, exponent);
        let (mut c, mut e) = ([0.0f32; 4], [0.0f32; 1]);
        gl.get_light_fv(l, GL_DIFFUSE, &mut c);
        gl.get_light_fv(l, GL_SPOT_EXPONENT, &mut e);
        prop_assert_eq!(c, color);
        prop_assert_eq!(e[0], exponent);
        let ints = color.map(|x| (f64::from(x) * 2_147_483_647.0) as i32);
        gl.material_iv(GL_BACK, GL_EMISSION, &ints);
        let mut m = [0.0f32; 4];
        gl.get_material_fv(GL_BACK, GL_EMISSION, &mut m);
        for k in 0..4 {
            prop_assert!((m[k] - color[k]).abs() < 1e-6, "{} vs {}", m[k], color[k]);
        }
        let mut back = [0i32; 4];
        gl.get_material_iv(GL_BACK, GL_EMISSION, &mut back);
        for k in 0..4 {
            prop_assert!((i64::from(back[k]) - i64::from(ints[k])).abs() <= 256, "{} vs {}", back[k], ints[k]);
        }
        prop_assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    /// `glGetTexImage` and `glGetPolygonStipple` write inside the length they announce, for
    /// any pack modes.
    #[test]
    fn packed_queries_stay_inside_their_length(
        align in prop_oneof![Just(1), Just(2), Just(4), Just(8)],
        row_length in 0i32..9,
        skip in (0i32..4, 0i32..4),
        lsb in any::<bool>(),
        format in prop_oneof![Just(GL_RGBA), Just(GL_RGB), Just(GL_LUMINANCE), Just(GL_ALPHA), Just(GL_LUMINANCE_ALPHA), Just(GL_RED)],
        type_ in prop_oneof![Just(GL_UNSIGNED_BYTE), Just(GL_FLOAT), Just(GL_SHORT), Just(GL_UNSIGNED_INT)],
        size in (1i32..6, 1i32..6),
    ) {
        let mut gl = Gl::new(8, 8);
        let texels: Vec<u8> = (0..size.0 * size.1 * 4).map(|k| (k * 37 % 256) as u8).collect();
        gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
        gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGBA as i32, size.0, size.1, 0, GL_RGBA, GL_UNSIGNED_BYTE, &texels);
        for (pname, v) in [(GL_PACK_ALIGNMENT, align), (GL_PACK_ROW_LENGTH, row_length), (GL_PACK_SKIP_ROWS, skip.0), (GL_PACK_SKIP_PIXELS, skip.1), (GL_PACK_LSB_FIRST, i32::from(lsb))] {
            gl.pixel_storei(pname, v);
        }
        let len = gl.tex_image_len(GL_TEXTURE_2D, 0, format, type_).expect("a defined level");
        let mut out = vec![0xEEu8; len + 64];
        gl.get_tex_image(GL_TEXTURE_2D, 0, format, type_, &mut out);
        prop_assert!(out[len..].iter().all(|&b| b == 0xEE));
        // One byte short (an empty slice is C's NULL, which Mesa answers by doing nothing).
        if len > 1 {
            let mut short = vec![0xEEu8; len - 1];
            gl.get_tex_image(GL_TEXTURE_2D, 0, format, type_, &mut short);
            prop_assert_eq!(gl.get_error(), GL_INVALID_VALUE);
        }
        let stipple_len = gl.polygon_stipple_len();
        let mut mask = vec![0xEEu8; stipple_len + 64];
        gl.get_polygon_stipple(&mut mask);
        prop_assert!(mask[stipple_len..].iter().all(|&b| b == 0xEE));
        prop_assert_eq!(gl.get_error(), GL_NO_ERROR);
    }
}
