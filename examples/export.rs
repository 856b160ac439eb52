//! Writes two surfaces, tessellated through the typed API, as OBJ, PLY and binary glTF.
//!
//! `cargo run --release --example export -- [FOLDER]` (default `out/export`) writes there
//! - `teapot.obj`, `.ply`, `.glb`: each of the 32 Bezier patches of [`gleval::data::teapot`]
//!   tessellated on a 16 × 16 grid and appended into one mesh with outward normals and
//!   per-patch (u, v) texture coordinates;
//! - `trimmed.obj`, `.ply`, `.glb`: the hill of `examples/trimmed.rs` as a rational B-spline
//!   surface with a round and a triangular hole, its trimmed (u, v) region triangulated by
//!   [`gleval::tess::trim::triangulate`] and every vertex evaluated on the surface.

use gleval::data::teapot::teapot_patches;
use gleval::math::{BSplineSurface, KnotVector};
use gleval::tess::export::{write_glb, write_obj, write_ply};
use gleval::tess::trim::{triangulate, TrimLoop};
use gleval::tess::Mesh;
use std::error::Error;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

/// Grid segments per patch along u and along v.
const SEGMENTS: usize = 16;

fn teapot_mesh() -> Result<Mesh, Box<dyn Error>> {
    let mut mesh = Mesh::default();
    for patch in teapot_patches() {
        mesh.append(&patch.tessellate(SEGMENTS, SEGMENTS)?);
    }
    Ok(mesh)
}

/// The trimmed hill: a bicubic Bezier net (Trimmed.c's, made rational by weighting the four
/// inner points 2), the unit domain less a circle of radius 0.2 around (0.5, 0.6) and a triangle.
fn trimmed_mesh() -> Result<Mesh, Box<dyn Error>> {
    let mut net = Vec::new();
    for u in 0..4 {
        for v in 0..4 {
            let inner = (u == 1 || u == 2) && (v == 1 || v == 2);
            let (z, w) = if inner { (3.0, 2.0) } else { (-3.0, 1.0) };
            net.extend_from_slice(&[2.0 * (u as f64 - 1.5) * w, 2.0 * (v as f64 - 1.5) * w, z * w, w]);
        }
    }
    let knots = KnotVector::new(vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0]);
    let surface = BSplineSurface::try_new(4, 4, 4, knots.clone(), knots, net)?;
    // Holes run clockwise, the outer boundary counter-clockwise (GLU's rule).
    let outer = TrimLoop::new(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
    let circle = (0..48)
        .map(|k| {
            let a = -(k as f64) * std::f64::consts::TAU / 48.0;
            [0.5 + 0.2 * a.cos(), 0.6 + 0.2 * a.sin()]
        })
        .collect();
    let triangle = TrimLoop::new(vec![[0.1, 0.1], [0.2, 0.3], [0.3, 0.1]]);
    let grid: Vec<f64> = (0..=24).map(|k| k as f64 / 24.0).collect();
    let region = triangulate(&[outer, TrimLoop::new(circle), triangle], [0.0, 1.0, 0.0, 1.0], &grid, &grid)?;
    let mut mesh = Mesh::default();
    for &[u, v] in &region.points {
        let s = surface.eval_rational_with_partials(u, v)?;
        let (a, b) = (s.du, s.dv);
        let n = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        mesh.positions.push(s.point.map(|c| c as f32));
        mesh.normals.push(if len > 0.0 { n.map(|c| (c / len) as f32) } else { [0.0; 3] });
        mesh.tex_coords.push([u as f32, v as f32]);
    }
    mesh.indices = region.triangles().flatten().collect();
    Ok(mesh)
}

/// Creates `path`, lets `write` fill it, and reports its size.
fn save(path: &Path, write: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>) -> Result<(), Box<dyn Error>> {
    let mut out = BufWriter::new(File::create(path)?);
    write(&mut out)?;
    out.flush()?;
    println!("wrote {} ({} bytes)", path.display(), std::fs::metadata(path)?.len());
    Ok(())
}

fn main() -> Result<(), Box<dyn Error>> {
    let folder = std::env::args().nth(1).map_or_else(|| PathBuf::from("out/export"), PathBuf::from);
    std::fs::create_dir_all(&folder)?;
    for (name, mesh) in [("teapot", teapot_mesh()?), ("trimmed", trimmed_mesh()?)] {
        println!("{name}: {} vertices, {} triangles", mesh.positions.len(), mesh.triangle_count());
        save(&folder.join(format!("{name}.obj")), |out| write_obj(&mesh, out))?;
        save(&folder.join(format!("{name}.ply")), |out| write_ply(&mesh, out))?;
        save(&folder.join(format!("{name}.glb")), |out| write_glb(&mesh, out))?;
    }
    Ok(())
}
