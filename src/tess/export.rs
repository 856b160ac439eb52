//! Writing a [`Mesh`] to the three formats other tools read: Wavefront OBJ (text), PLY
//! (binary little-endian) and binary glTF 2.0 (`.glb`).
//!
//! All three keep the mesh as it is: the same vertices in the same order, the same triangles,
//! normals and texture coordinates when the mesh has them. A mesh that is not consistent
//! (attribute arrays of another length than the positions, an index past the last vertex, a
//! dangling partial triangle, a value that is not finite) is refused with
//! [`io::ErrorKind::InvalidInput`] before anything is written.

use super::Mesh;
use std::fmt::Write as _;
use std::io::{self, Write};

/// Checks what every format needs of the mesh.
fn check(mesh: &Mesh) -> io::Result<()> {
    let n = mesh.positions.len();
    let bad = |why: String| Err(io::Error::new(io::ErrorKind::InvalidInput, why));
    if !mesh.normals.is_empty() && mesh.normals.len() != n {
        return bad(format!("{} normals for {n} vertices", mesh.normals.len()));
    }
    if !mesh.tex_coords.is_empty() && mesh.tex_coords.len() != n {
        return bad(format!("{} texture coordinates for {n} vertices", mesh.tex_coords.len()));
    }
    if mesh.indices.len() % 3 != 0 {
        return bad(format!("{} indices do not make whole triangles", mesh.indices.len()));
    }
    if let Some(i) = mesh.indices.iter().find(|&&i| i as usize >= n) {
        return bad(format!("index {i} past the last of {n} vertices"));
    }
    let values = mesh.positions.iter().flatten().chain(mesh.normals.iter().flatten());
    if !values.chain(mesh.tex_coords.iter().flatten()).all(|v| v.is_finite()) {
        return bad("a vertex attribute is not finite".into());
    }
    Ok(())
}

/// Writes Wavefront OBJ: `v`, `vn` and `vt` lines, then one `f` line per triangle with 1-based
/// indices (`a/a/a`, `a//a`, `a/a` or `a`, after what the mesh has). Numbers are written in
/// Rust's shortest round-trip form, so reading them back gives the same `f32`s.
///
/// ```
/// use gleval::math::BezierPatch;
/// use gleval::tess::export::write_obj;
/// let quad = BezierPatch::try_new(3, 2, 2, vec![0.,0.,0., 0.,1.,0., 1.,0.,0., 1.,1.,0.]).unwrap();
/// let mut out = Vec::new();
/// write_obj(&quad.tessellate(1, 1).unwrap(), &mut out).unwrap();
/// let text = String::from_utf8(out).unwrap();
/// assert!(text.contains("\nv 1 1 0\n"));
/// assert!(text.contains("\nf 1/1/1 2/2/2 4/4/4\n"));
/// ```
pub fn write_obj(mesh: &Mesh, mut out: impl Write) -> io::Result<()> {
    check(mesh)?;
    let mut text = String::from("# written by gleval\n");
    for p in &mesh.positions {
        let _ = writeln!(text, "v {} {} {}", p[0], p[1], p[2]);
    }
    for n in &mesh.normals {
        let _ = writeln!(text, "vn {} {} {}", n[0], n[1], n[2]);
    }
    for t in &mesh.tex_coords {
        let _ = writeln!(text, "vt {} {}", t[0], t[1]);
    }
    let (has_n, has_t) = (!mesh.normals.is_empty(), !mesh.tex_coords.is_empty());
    for tri in mesh.indices.chunks_exact(3) {
        text.push('f');
        for &i in tri {
            let k = i as u64 + 1;
            let _ = match (has_t, has_n) {
                (true, true) => write!(text, " {k}/{k}/{k}"),
                (false, true) => write!(text, " {k}//{k}"),
                (true, false) => write!(text, " {k}/{k}"),
                (false, false) => write!(text, " {k}"),
            };
        }
        text.push('\n');
    }
    out.write_all(text.as_bytes())
}

/// Writes binary little-endian PLY: element `vertex` with float properties `x y z`, then
/// `nx ny nz` and `s t` when the mesh has them; element `face` with `list uchar uint
/// vertex_indices`, three per face.
///
/// ```
/// use gleval::math::BezierPatch;
/// use gleval::tess::export::write_ply;
/// let quad = BezierPatch::try_new(3, 2, 2, vec![0.,0.,0., 0.,1.,0., 1.,0.,0., 1.,1.,0.]).unwrap();
/// let mut out = Vec::new();
/// write_ply(&quad.tessellate(1, 1).unwrap(), &mut out).unwrap();
/// assert!(out.starts_with(b"ply\nformat binary_little_endian 1.0\n"));
/// // Header, then 4 vertices of 8 floats and 2 faces of 1 + 3 * 4 bytes.
/// let header = out.windows(11).position(|w| w == b"end_header\n").unwrap() + 11;
/// assert_eq!(out.len() - header, 4 * 8 * 4 + 2 * 13);
/// ```
pub fn write_ply(mesh: &Mesh, mut out: impl Write) -> io::Result<()> {
    check(mesh)?;
    let (has_n, has_t) = (!mesh.normals.is_empty(), !mesh.tex_coords.is_empty());
    let mut header = format!(
        "ply\nformat binary_little_endian 1.0\ncomment written by gleval\nelement vertex {}\n",
        mesh.positions.len()
    );
    let mut names = vec!["x", "y", "z"];
    if has_n {
        names.extend(["nx", "ny", "nz"]);
    }
    if has_t {
        names.extend(["s", "t"]);
    }
    for name in names {
        let _ = writeln!(header, "property float {name}");
    }
    let _ =
        write!(header, "element face {}\nproperty list uchar uint vertex_indices\nend_header\n", mesh.triangle_count());
    let mut body = header.into_bytes();
    for (k, p) in mesh.positions.iter().enumerate() {
        let normal = mesh.normals.get(k).map(|n| &n[..]).unwrap_or(&[]);
        let tex = mesh.tex_coords.get(k).map(|t| &t[..]).unwrap_or(&[]);
        for v in p.iter().chain(normal).chain(tex) {
            body.extend_from_slice(&v.to_le_bytes());
        }
    }
    for tri in mesh.indices.chunks_exact(3) {
        body.push(3);
        for i in tri {
            body.extend_from_slice(&i.to_le_bytes());
        }
    }
    out.write_all(&body)
}

/// glTF's numbers for the accessors and buffer views we write (glTF 2.0 §5.1.3, §5.11.4).
const FLOAT: u32 = 5126;
const UNSIGNED_INT: u32 = 5125;
const ARRAY_BUFFER: u32 = 34962;
const ELEMENT_ARRAY_BUFFER: u32 = 34963;

/// One attribute or index array as laid out in the binary chunk.
struct View {
    bytes: Vec<u8>,
    target: u32,
    component: u32,
    kind: &'static str,
    count: usize,
}

fn float_view<const N: usize>(values: &[[f32; N]], kind: &'static str) -> View {
    let bytes = values.iter().flatten().flat_map(|v| v.to_le_bytes()).collect();
    View { bytes, target: ARRAY_BUFFER, component: FLOAT, kind, count: values.len() }
}

/// glTF requires unit `NORMAL`s (glTF 2.0 §3.7.2.1), but a point where the surface collapses
/// (the lid's knob, a cone's apex) has a zero normal in a [`Mesh`]. Such a vertex gets the
/// direction of the area-weighted sum of its triangles' face normals, the usual estimate of a
/// vertex normal (Gouraud's), or +z when all its triangles are degenerate too.
fn unit_normals(mesh: &Mesh) -> Vec<[f32; 3]> {
    let mut normals = mesh.normals.clone();
    let zero: Vec<bool> = normals.iter().map(|n| *n == [0.0; 3]).collect();
    if !zero.contains(&true) {
        return normals;
    }
    let mut sums = vec![[0.0f64; 3]; normals.len()];
    for tri in mesh.indices.chunks_exact(3) {
        let [a, b, c] = [0, 1, 2].map(|k| mesh.positions[tri[k] as usize].map(f64::from));
        let (e, f) = ([b[0] - a[0], b[1] - a[1], b[2] - a[2]], [c[0] - a[0], c[1] - a[1], c[2] - a[2]]);
        let face = [e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]];
        for &i in tri.iter().filter(|&&i| zero[i as usize]) {
            for c in 0..3 {
                sums[i as usize][c] += face[c];
            }
        }
    }
    for (k, n) in normals.iter_mut().enumerate().filter(|(k, _)| zero[*k]) {
        let s = sums[k];
        let len = (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]).sqrt();
        *n = if len > 0.0 { s.map(|v| (v / len) as f32) } else { [0.0, 0.0, 1.0] };
    }
    normals
}

/// Component-wise minimum and maximum of the positions, which glTF requires on POSITION.
fn bounds(positions: &[[f32; 3]]) -> ([f32; 3], [f32; 3]) {
    let mut lo = [f32::INFINITY; 3];
    let mut hi = [f32::NEG_INFINITY; 3];
    for p in positions {
        for c in 0..3 {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    (lo, hi)
}

/// The JSON chunk: one buffer, a view and an accessor per array, one mesh, node and scene.
/// A mesh without triangles becomes a scene with one node and no mesh, since glTF forbids
/// empty accessors and buffers.
fn gltf_json(mesh: &Mesh, views: &[View]) -> String {
    let mut json =
        String::from(r#"{"asset":{"version":"2.0","generator":"gleval"},"scene":0,"scenes":[{"nodes":[0]}],"#);
    if views.is_empty() {
        json.push_str(r#""nodes":[{}]}"#);
        return json;
    }
    let total: usize = views.iter().map(|v| v.bytes.len()).sum();
    let _ = write!(json, r#""nodes":[{{"mesh":0}}],"buffers":[{{"byteLength":{total}}}],"bufferViews":["#);
    let mut offset = 0;
    for (k, v) in views.iter().enumerate() {
        let sep = if k == 0 { "" } else { "," };
        let (len, target) = (v.bytes.len(), v.target);
        let _ = write!(json, r#"{sep}{{"buffer":0,"byteOffset":{offset},"byteLength":{len},"target":{target}}}"#);
        offset += len;
    }
    json.push_str(r#"],"accessors":["#);
    let (lo, hi) = bounds(&mesh.positions);
    for (k, v) in views.iter().enumerate() {
        let sep = if k == 0 { "" } else { "," };
        let (component, count, kind) = (v.component, v.count, v.kind);
        let _ = write!(json, r#"{sep}{{"bufferView":{k},"componentType":{component},"count":{count},"type":"{kind}""#);
        if k == 0 {
            let _ = write!(json, r#","min":[{},{},{}],"max":[{},{},{}]"#, lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
        }
        json.push('}');
    }
    // Views are: positions, then normals and texture coordinates if present, then indices.
    let mut attributes = String::from(r#""POSITION":0"#);
    let mut next = 1;
    if !mesh.normals.is_empty() {
        let _ = write!(attributes, r#","NORMAL":{next}"#);
        next += 1;
    }
    if !mesh.tex_coords.is_empty() {
        let _ = write!(attributes, r#","TEXCOORD_0":{next}"#);
        next += 1;
    }
    let _ = write!(
        json,
        r#"],"meshes":[{{"primitives":[{{"attributes":{{{attributes}}},"indices":{next},"mode":4}}]}}]}}"#
    );
    json
}

/// Appends a GLB chunk (glTF 2.0 §4.4.3): length, type, data padded to 4 bytes with `pad`.
fn push_chunk(glb: &mut Vec<u8>, kind: &[u8; 4], data: &[u8], pad: u8) {
    let padded = data.len().div_ceil(4) * 4;
    glb.extend_from_slice(&(padded as u32).to_le_bytes());
    glb.extend_from_slice(kind);
    glb.extend_from_slice(data);
    glb.resize(glb.len() + padded - data.len(), pad);
}

/// Writes binary glTF 2.0 (GLB): one buffer in the BIN chunk holding positions, normals and
/// texture coordinates (`f32`) and `u32` indices, one triangle-list primitive with `POSITION`
/// (with its `min`/`max`), `NORMAL` and `TEXCOORD_0` when present, in one mesh, node and scene.
/// The JSON chunk is padded with spaces and the BIN chunk with zeros, as the format asks.
/// Zero normals (collapsed points) are replaced by unit ones, since glTF accepts no other (see
/// the module source); everything else is written as it is. A mesh without triangles gives a
/// scene with one empty node, as glTF has no empty accessors.
///
/// ```
/// use gleval::math::BezierPatch;
/// use gleval::tess::export::write_glb;
/// let quad = BezierPatch::try_new(3, 2, 2, vec![0.,0.,0., 0.,1.,0., 1.,0.,0., 1.,1.,0.]).unwrap();
/// let mut out = Vec::new();
/// write_glb(&quad.tessellate(1, 1).unwrap(), &mut out).unwrap();
/// assert_eq!(&out[..4], b"glTF");
/// assert_eq!(u32::from_le_bytes(out[8..12].try_into().unwrap()) as usize, out.len());
/// ```
pub fn write_glb(mesh: &Mesh, mut out: impl Write) -> io::Result<()> {
    check(mesh)?;
    let mut views = Vec::new();
    if !mesh.indices.is_empty() {
        views.push(float_view(&mesh.positions, "VEC3"));
        if !mesh.normals.is_empty() {
            views.push(float_view(&unit_normals(mesh), "VEC3"));
        }
        if !mesh.tex_coords.is_empty() {
            views.push(float_view(&mesh.tex_coords, "VEC2"));
        }
        let bytes = mesh.indices.iter().flat_map(|i| i.to_le_bytes()).collect();
        let count = mesh.indices.len();
        views.push(View { bytes, target: ELEMENT_ARRAY_BUFFER, component: UNSIGNED_INT, kind: "SCALAR", count });
    }
    let json = gltf_json(mesh, &views);
    let mut glb = Vec::new();
    glb.extend_from_slice(b"glTF");
    glb.extend_from_slice(&2u32.to_le_bytes());
    glb.extend_from_slice(&0u32.to_le_bytes()); // total length, filled in below
    push_chunk(&mut glb, b"JSON", json.as_bytes(), b' ');
    if !views.is_empty() {
        let bin: Vec<u8> = views.iter().flat_map(|v| v.bytes.iter().copied()).collect();
        push_chunk(&mut glb, b"BIN\0", &bin, 0);
    }
    let total = u32::try_from(glb.len())
        .map_err(|_| io::Error::new(io::ErrorKind::InvalidInput, "mesh too large for a GLB file (4 GiB)"))?;
    glb[8..12].copy_from_slice(&total.to_le_bytes());
    out.write_all(&glb)
}

#[cfg(test)]
#[path = "export_tests.rs"]
mod tests;
