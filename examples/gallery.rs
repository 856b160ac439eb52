//! Runs the built-in programs (the textbook's BezCurve and BezSurf evaluator calls) through the
//! GL façade and reports what each one draws. Rendering to PNG arrives with the renderer; until
//! then each frame is written as a plain-text vertex dump under `out/gallery/`.

use gleval::prelude::*;
use std::fmt::Write as _;

/// BezCurve.c (seed 004, 9.4.3): a quartic Bezier curve and its control points.
fn bez_curve(gl: &mut Gl) {
    let pts: [[f32; 3]; 5] = [[-2.0, 0.0, 0.0], [-1.0, 1.0, 0.0], [0.0, 0.0, 0.0], [1.0, -1.0, 0.0], [2.0, 0.0, 0.0]];
    let (npts, un) = (5, 100);
    gl.color3f(0.0, 0.0, 1.0);
    gll::bez_curve(gl, pts.as_flattened(), npts, un);
    gl.color3f(1.0, 0.0, 0.0);
    gll::points(gl, pts.as_flattened(), npts);
}

/// BezSurf.c (seed 004, 9.4.3): a bicubic patch as wireframe and filled, with auto normals.
fn bez_surf(gl: &mut Gl) {
    #[rustfmt::skip]
    let pts: [[[f32; 3]; 4]; 4] = [
        [[-1.5, -1.5, 4.0], [-0.5, -1.5, 2.0], [0.5, -1.5, -1.0], [1.5, -1.5, 2.0]],
        [[-1.5, -0.5, 1.0], [-0.5, -0.5, 3.0], [0.5, -0.5, 0.0], [1.5, -0.5, -1.0]],
        [[-1.5, 0.5, 4.0], [-0.5, -0.5, 0.0], [0.5, 0.5, 3.0], [1.5, 0.5, 4.0]],
        [[-1.5, 1.5, -2.0], [-0.5, 1.5, -2.0], [0.5, 1.5, 0.0], [1.5, 1.5, 1.0]],
    ];
    let flat = pts.as_flattened().as_flattened();
    gl.enable(GL_AUTO_NORMAL);
    gll::bez_surface(gl, GL_LINE, flat, 4, 4, 20, 20);
    gll::points(gl, flat, 16);
    gll::bez_surface(gl, GL_FILL, flat, 4, 4, 20, 20);
    gll::points(gl, flat, 16);
}

fn dump(frame: &Frame) -> String {
    let mut s = String::new();
    for (p, verts) in frame.iter() {
        let _ = writeln!(s, "primitive mode=0x{:04x} vertices={}", p.mode, verts.len());
        for v in verts {
            let [x, y, z, w] = v.position;
            let [nx, ny, nz] = v.normal;
            let _ = writeln!(s, "  p=({x:.6} {y:.6} {z:.6} {w:.6}) n=({nx:.6} {ny:.6} {nz:.6})");
        }
    }
    s
}

/// A built-in program: name, window size, display function.
type Program = (&'static str, i32, i32, fn(&mut Gl));

fn main() -> std::io::Result<()> {
    let programs: [Program; 2] = [("bezcurve", 400, 200, bez_curve), ("bezsurf", 500, 200, bez_surf)];
    let dir = std::path::Path::new("out/gallery");
    std::fs::create_dir_all(dir)?;
    println!("{:<10} {:>10} {:>9} {:>6}", "program", "primitives", "vertices", "error");
    for (name, w, h, program) in programs {
        let mut gl = Gl::new(w, h);
        program(&mut gl);
        let error = gl.get_error();
        let frame = gl.take_frame();
        std::fs::write(dir.join(format!("{name}.txt")), dump(&frame))?;
        println!("{name:<10} {:>10} {:>9} {error:>#6x}", frame.primitives.len(), frame.vertices.len());
    }
    println!("vertex dumps written to {}", dir.display());
    Ok(())
}
