//! `gluProject`, `gluUnProject`, `gluUnProject4` and `gluPickMatrix` against the system's GLU
//! (SGI GLU 9.0.2's `project.c`) on 600 random and singular inputs and 100 pick regions:
//! `tests/reference/glu/project.txt`, written by `project.c` (`regen.sh`), holds GLU's inputs
//! and outputs bit for bit; ours must be the same bits.

use gleval::prelude::*;
use std::path::Path;

fn double(hex: &str) -> f64 {
    f64::from_bits(u64::from_str_radix(hex, 16).expect("hex double"))
}

#[test]
fn projections_agree_with_glu_bit_for_bit() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/glu/project.txt");
    let text = std::fs::read_to_string(path).expect("project.txt");
    let (mut calls, mut picks, mut failures) = (0, 0, Vec::new());
    let mut gl = Gl::new(4, 4);
    for (line_no, line) in text.lines().enumerate() {
        let t: Vec<&str> = line.split(' ').collect();
        if t[0] == "pick" {
            picks += 1;
            let view: Vec<GLint> = t[1..5].iter().map(|v| v.parse().unwrap()).collect();
            let [x, y, dx, dy] = [5, 6, 7, 8].map(|i| double(t[i]));
            let expected: Vec<f32> = t[9..25].iter().map(|v| v.parse().unwrap()).collect();
            gl.load_identity();
            gl.glu_pick_matrix(x, y, dx, dy, &view);
            gl.begin(GL_POINTS);
            gl.vertex2f(0.0, 0.0);
            gl.end();
            let frame = gl.take_frame();
            let ours = frame.states.last().expect("a state").modelview.to_cols_array();
            if ours.iter().zip(&expected).any(|(a, b)| (a - b).abs() > 1e-6 * b.abs().max(1.0)) {
                failures.push(format!("line {}: pick {ours:?} vs {expected:?}", line_no + 1));
            }
            continue;
        }
        calls += 1;
        let (kind, ret): (u32, GLint) = (t[0].parse().unwrap(), t[1].parse().unwrap());
        let model: Vec<f64> = t[2..18].iter().map(|h| double(h)).collect();
        let proj: Vec<f64> = t[18..34].iter().map(|h| double(h)).collect();
        let view: Vec<GLint> = t[34..38].iter().map(|v| v.parse().unwrap()).collect();
        let input: Vec<f64> = t[38..42].iter().map(|h| double(h)).collect();
        let (near, far) = (double(t[42]), double(t[43]));
        let expected: Vec<u64> = t[44..48].iter().map(|h| u64::from_str_radix(h, 16).unwrap()).collect();
        let mut out = [0.0f64; 4];
        let [a, b, c, d] = &mut out;
        let ours = match kind {
            0 => gl.glu_project(input[0], input[1], input[2], &model, &proj, &view, a, b, c),
            1 => gl.glu_un_project(input[0] * 300.0, input[1] * 300.0, input[2], &model, &proj, &view, a, b, c),
            _ => gl.glu_un_project4(
                input[0] * 300.0,
                input[1] * 300.0,
                input[2],
                input[3],
                &model,
                &proj,
                &view,
                near,
                far,
                a,
                b,
                c,
                d,
            ),
        };
        let bits: Vec<u64> = out.iter().map(|v| v.to_bits()).collect();
        // NaN payloads may differ; any NaN matches a NaN.
        let same = bits
            .iter()
            .zip(&expected)
            .all(|(x, y)| x == y || (f64::from_bits(*x).is_nan() && f64::from_bits(*y).is_nan()));
        if ours != ret || !same {
            failures.push(format!(
                "line {}: {ours} {out:?} vs GLU {ret} {:?}",
                line_no + 1,
                expected.iter().map(|b| f64::from_bits(*b)).collect::<Vec<_>>()
            ));
        }
    }
    assert!(calls >= 600 && picks >= 100, "reference too short: {calls} calls, {picks} picks");
    assert!(failures.is_empty(), "{} differ from GLU:\n{}", failures.len(), failures.join("\n"));
}
