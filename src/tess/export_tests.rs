//! Each file read back by an independent reader (tobj, ply-rs-bw, the gltf crate with its
//! validation) and compared with the mesh that was written.

use super::*;
use crate::data::teapot::teapot_patches;
use crate::math::BezierPatch;

/// Two patches of the teapot appended: shared edges, a collapsed edge with zero normals (the
/// lid's knob), and vertices numbered past the first patch.
fn sample_mesh() -> Mesh {
    let patches = teapot_patches();
    let mut mesh = Mesh::default();
    for k in [4, 20] {
        mesh.append(&patches[k].tessellate(5, 4).unwrap());
    }
    mesh
}

/// Position, normal and texture coordinates of one triangle corner.
type Corner = ([f32; 3], Option<[f32; 3]>, Option<[f32; 2]>);

/// The triangles as corner attributes, what survives any re-indexing by a reader.
fn corners(mesh: &Mesh) -> Vec<Corner> {
    let at = |i: u32| {
        let i = i as usize;
        (mesh.positions[i], mesh.normals.get(i).copied(), mesh.tex_coords.get(i).copied())
    };
    mesh.indices.iter().map(|&i| at(i)).collect()
}

fn obj_round_trip(mesh: &Mesh) -> Mesh {
    let mut bytes = Vec::new();
    write_obj(mesh, &mut bytes).unwrap();
    let options = tobj::LoadOptions { single_index: true, triangulate: false, ..Default::default() };
    let (models, _) =
        tobj::load_obj_buf(&mut bytes.as_slice(), &options, |_| Err(tobj::LoadError::OpenFileFailed)).unwrap();
    let mut back = Mesh::default();
    for m in models {
        let m = m.mesh;
        let part = Mesh {
            positions: m.positions.chunks(3).map(|p| [p[0], p[1], p[2]]).collect(),
            normals: m.normals.chunks(3).map(|n| [n[0], n[1], n[2]]).collect(),
            tex_coords: m.texcoords.chunks(2).map(|t| [t[0], t[1]]).collect(),
            indices: m.indices,
        };
        back.append(&part);
    }
    back
}

#[test]
fn obj_reads_back_with_tobj() {
    let mesh = sample_mesh();
    let back = obj_round_trip(&mesh);
    assert_eq!(corners(&back), corners(&mesh));
    // Without normals and texture coordinates the faces are plain indices.
    let bare = Mesh { normals: vec![], tex_coords: vec![], ..mesh.clone() };
    let back = obj_round_trip(&bare);
    assert!(back.normals.is_empty() && back.tex_coords.is_empty());
    assert_eq!(corners(&back), corners(&bare));
}

fn ply_floats(element: &ply_rs_bw::ply::DefaultElement, names: &[&str]) -> Vec<f32> {
    names
        .iter()
        .map(|n| match element[*n] {
            ply_rs_bw::ply::Property::Float(v) => v,
            ref other => panic!("{n}: {other:?}"),
        })
        .collect()
}

fn ply_round_trip(mesh: &Mesh) -> Mesh {
    let mut bytes = Vec::new();
    write_ply(mesh, &mut bytes).unwrap();
    let parser = ply_rs_bw::parser::Parser::<ply_rs_bw::ply::DefaultElement>::new();
    let ply = parser.read_ply(&mut bytes.as_slice()).unwrap();
    assert_eq!(ply.header.encoding, ply_rs_bw::ply::Encoding::BinaryLittleEndian);
    let mut back = Mesh::default();
    for v in &ply.payload["vertex"] {
        let p = ply_floats(v, &["x", "y", "z"]);
        back.positions.push([p[0], p[1], p[2]]);
        if v.contains_key("nx") {
            let n = ply_floats(v, &["nx", "ny", "nz"]);
            back.normals.push([n[0], n[1], n[2]]);
        }
        if v.contains_key("s") {
            let t = ply_floats(v, &["s", "t"]);
            back.tex_coords.push([t[0], t[1]]);
        }
    }
    for f in &ply.payload["face"] {
        match &f["vertex_indices"] {
            ply_rs_bw::ply::Property::ListUInt(list) if list.len() == 3 => back.indices.extend(list),
            other => panic!("face {other:?}"),
        }
    }
    back
}

#[test]
fn ply_reads_back_with_ply_rs() {
    let mesh = sample_mesh();
    assert_eq!(ply_round_trip(&mesh), mesh);
    let bare = Mesh { normals: vec![], ..mesh };
    assert_eq!(ply_round_trip(&bare), bare);
}

fn glb_round_trip(mesh: &Mesh) -> (Mesh, usize) {
    let mut bytes = Vec::new();
    write_glb(mesh, &mut bytes).unwrap();
    assert_eq!(bytes.len() % 4, 0);
    // from_slice validates the document against the glTF 2.0 schema rules.
    let gltf = gltf::Gltf::from_slice(&bytes).unwrap();
    assert_eq!(gltf.scenes().count(), 1);
    assert_eq!(gltf.nodes().count(), 1);
    let blob = gltf.blob.clone();
    let mut back = Mesh::default();
    for m in gltf.meshes() {
        for prim in m.primitives() {
            assert_eq!(prim.mode(), gltf::mesh::Mode::Triangles);
            let bounds = prim.bounding_box();
            let (lo, hi) = super::bounds(&mesh.positions);
            assert_eq!((bounds.min, bounds.max), (lo, hi));
            let reader = prim.reader(|_| blob.as_deref());
            back.positions.extend(reader.read_positions().unwrap());
            back.normals.extend(reader.read_normals().into_iter().flatten());
            back.tex_coords.extend(reader.read_tex_coords(0).into_iter().flat_map(|t| t.into_f32()));
            back.indices.extend(reader.read_indices().unwrap().into_u32());
        }
    }
    (back, gltf.meshes().count())
}

#[test]
fn glb_reads_back_with_the_gltf_crate() {
    let mesh = sample_mesh();
    let (back, meshes) = glb_round_trip(&mesh);
    assert_eq!(meshes, 1);
    assert_eq!((&back.positions, &back.tex_coords, &back.indices), (&mesh.positions, &mesh.tex_coords, &mesh.indices));
    // Normals come back as written, except at the knob's top, collapsed to a point: glTF wants
    // unit normals there, and the knob's top is flat (its first two rows of control points
    // lie at z = 3.15), so the estimate from the neighbouring triangles points up.
    let mut collapsed = 0;
    for (k, (n, m)) in back.normals.iter().zip(&mesh.normals).enumerate() {
        if *m == [0.0; 3] {
            collapsed += 1;
            assert_eq!(mesh.positions[k], [0.0, 0.0, 3.15]);
            assert!((n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0).abs() < 1e-6, "{n:?}");
            assert!(n[2] > 0.95, "{n:?}");
        } else {
            assert_eq!(n, m);
        }
    }
    assert_eq!(collapsed, 6, "one collapsed vertex per grid column of the knob's patch");
    let bare = Mesh { tex_coords: vec![], normals: vec![], ..mesh };
    assert_eq!(glb_round_trip(&bare), (bare, 1));
}

#[test]
fn glb_bounds_are_the_extreme_coordinates() {
    // Worked by hand: a triangle from (-1, 2, 0.5) to (3, -4, 0) to (0, 0, 7).
    let mesh = Mesh {
        positions: vec![[-1.0, 2.0, 0.5], [3.0, -4.0, 0.0], [0.0, 0.0, 7.0]],
        indices: vec![0, 1, 2],
        ..Mesh::default()
    };
    let mut bytes = Vec::new();
    write_glb(&mesh, &mut bytes).unwrap();
    let gltf = gltf::Gltf::from_slice(&bytes).unwrap();
    let prim = gltf.meshes().next().unwrap().primitives().next().unwrap();
    let b = prim.bounding_box();
    assert_eq!((b.min, b.max), ([-1.0, -4.0, 0.0], [3.0, 2.0, 7.0]));
}

#[test]
fn empty_meshes_make_valid_files() {
    let empty = Mesh::default();
    assert_eq!(obj_round_trip(&empty), empty);
    assert_eq!(ply_round_trip(&empty), empty);
    assert_eq!(glb_round_trip(&empty), (empty, 0));
}

/// One of the three exporters, writing into memory.
type Writer = fn(&Mesh, &mut Vec<u8>) -> io::Result<()>;

#[test]
fn inconsistent_meshes_are_refused_without_writing() {
    let quad = BezierPatch::try_new(3, 2, 2, vec![0., 0., 0., 0., 1., 0., 1., 0., 0., 1., 1., 0.]).unwrap();
    let good = quad.tessellate(2, 2).unwrap();
    let mut past_end = good.clone();
    past_end.indices[4] = 9;
    let mut partial = good.clone();
    partial.indices.pop();
    let mut short_normals = good.clone();
    short_normals.normals.pop();
    let mut nan = good.clone();
    nan.tex_coords[3][1] = f32::NAN;
    for bad in [past_end, partial, short_normals, nan] {
        let writers: [Writer; 3] = [|m, o| write_obj(m, o), |m, o| write_ply(m, o), |m, o| write_glb(m, o)];
        for write in writers {
            let mut out = Vec::new();
            let err = write(&bad, &mut out).unwrap_err();
            assert_eq!(err.kind(), io::ErrorKind::InvalidInput);
            assert!(out.is_empty());
        }
    }
}
