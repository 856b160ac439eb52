//! Writes the Utah teapot, tessellated through the typed API, as OBJ, PLY and binary glTF.
//!
//! `cargo run --release --example export -- [FOLDER]` (default `out/export`) writes
//! `teapot.obj`, `teapot.ply` and `teapot.glb` there: each of the 32 Bezier patches of
//! [`gleval::math::teapot`] tessellated on a 16 × 16 grid and appended into one mesh with
//! outward normals and per-patch (u, v) texture coordinates.

use gleval::math::teapot::teapot_patches;
use gleval::tess::export::{write_glb, write_obj, write_ply};
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
    let mesh = teapot_mesh()?;
    println!("teapot: {} vertices, {} triangles", mesh.positions.len(), mesh.triangle_count());
    save(&folder.join("teapot.obj"), |out| write_obj(&mesh, out))?;
    save(&folder.join("teapot.ply"), |out| write_ply(&mesh, out))?;
    save(&folder.join("teapot.glb"), |out| write_glb(&mesh, out))?;
    Ok(())
}
