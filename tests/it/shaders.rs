//! Every WGSL file under `shaders/` parses and validates with naga, without a GPU.

use std::path::Path;

fn validate(source: &str) -> Result<(), String> {
    let module = naga::front::wgsl::parse_str(source).map_err(|e| e.emit_to_string(source))?;
    let mut validator =
        naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::empty());
    validator.validate(&module).map(|_| ()).map_err(|e| e.emit_to_string(source))
}

#[test]
fn every_shader_validates_with_naga() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
    let mut checked = 0;
    for entry in std::fs::read_dir(&dir).expect("shaders/ exists") {
        let path = entry.expect("entry").path();
        if path.extension().is_some_and(|e| e == "wgsl") {
            let source = std::fs::read_to_string(&path).expect("readable");
            if let Err(e) = validate(&source) {
                panic!("{} does not validate:\n{e}", path.display());
            }
            checked += 1;
        }
    }
    assert!(checked > 0, "no shaders found in {}", dir.display());
}

#[test]
fn naga_rejects_a_broken_shader() {
    // The check above can fail: a type error is caught.
    let bad = "@fragment fn f() -> @location(0) vec4<f32> { return vec3<f32>(1.0); }";
    assert!(validate(bad).is_err());
}

#[cfg(feature = "gpu")]
#[test]
fn embedded_shader_is_the_file() {
    let file = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders/raster.wgsl")).unwrap();
    assert_eq!(gleval::render::RASTER_WGSL, file);
}

/// Member offsets and the size of a WGSL struct, as naga lays it out for the GPU.
#[cfg(feature = "gpu")]
fn wgsl_layout(source: &str, name: &str) -> (Vec<(String, u32)>, u32) {
    let module = naga::front::wgsl::parse_str(source).expect("parses");
    for (_, ty) in module.types.iter() {
        if ty.name.as_deref() == Some(name) {
            if let naga::TypeInner::Struct { members, span } = &ty.inner {
                let offsets = members.iter().map(|m| (m.name.clone().unwrap_or_default(), m.offset)).collect();
                return (offsets, *span);
            }
        }
    }
    panic!("no struct {name}");
}

/// The `#[repr(C)]` twins of the GPU tessellator's structs have the shader's layout: every
/// member at the same offset and the same size, so bytemuck casts are what the shader reads.
#[cfg(feature = "gpu")]
#[test]
fn mesh_buffer_layouts_match_the_shaders() {
    use gleval::render::mesh_gpu::*;
    use std::mem::{offset_of, size_of};
    let check = |source: &str, name: &str, size: usize, rust: &[(&str, usize)]| {
        let (members, span) = wgsl_layout(source, name);
        assert_eq!(span as usize, size, "{name}: WGSL size {span}, Rust size {size}");
        assert_eq!(members.len(), rust.len(), "{name}: member count");
        for ((wname, woff), (rname, roff)) in members.iter().zip(rust) {
            assert_eq!(*woff as usize, *roff, "{name}.{wname} (Rust {rname}): WGSL offset {woff}, Rust {roff}");
        }
    };
    check(
        EVAL_MESH_WGSL,
        "MapDesc",
        size_of::<GpuMapDesc>(),
        &[
            ("slot", offset_of!(GpuMapDesc, slot)),
            ("dim", offset_of!(GpuMapDesc, dim)),
            ("uorder", offset_of!(GpuMapDesc, uorder)),
            ("vorder", offset_of!(GpuMapDesc, vorder)),
            ("point_offset", offset_of!(GpuMapDesc, point_offset)),
            ("u_offset", offset_of!(GpuMapDesc, u_offset)),
            ("v_offset", offset_of!(GpuMapDesc, v_offset)),
            ("pad", offset_of!(GpuMapDesc, pad)),
        ],
    );
    check(
        EVAL_MESH_WGSL,
        "Job",
        size_of::<GpuMeshJob>(),
        &[
            ("maps", offset_of!(GpuMeshJob, maps)),
            ("map_count", offset_of!(GpuMeshJob, map_count)),
            ("nu", offset_of!(GpuMeshJob, nu)),
            ("nv", offset_of!(GpuMeshJob, nv)),
            ("mode", offset_of!(GpuMeshJob, mode)),
            ("out_offset", offset_of!(GpuMeshJob, out_offset)),
            ("index_offset", offset_of!(GpuMeshJob, index_offset)),
            ("auto_normal", offset_of!(GpuMeshJob, auto_normal)),
            ("pad", offset_of!(GpuMeshJob, pad)),
            ("normal", offset_of!(GpuMeshJob, normal)),
            ("color", offset_of!(GpuMeshJob, color)),
            ("tex", offset_of!(GpuMeshJob, tex)),
        ],
    );
    check(
        EVAL_MESH_WGSL,
        "Meta",
        size_of::<GpuMeshMeta>(),
        &[("job_count", 0), ("total_points", 4), ("provoking_last", 8), ("_pad", 12)],
    );
    let (_, vertex) = wgsl_layout(EVAL_MESH_WGSL, "Vertex");
    assert_eq!(u64::from(vertex), VERTEX_BYTES);
    check(
        MESH_RASTER_WGSL,
        "Light",
        size_of::<GpuLight>(),
        &[
            ("ambient", offset_of!(GpuLight, ambient)),
            ("diffuse", offset_of!(GpuLight, diffuse)),
            ("specular", offset_of!(GpuLight, specular)),
            ("position", offset_of!(GpuLight, position)),
            ("spot_direction", offset_of!(GpuLight, spot_direction)),
            ("params", offset_of!(GpuLight, params)),
            ("attenuation", offset_of!(GpuLight, attenuation)),
        ],
    );
    check(
        MESH_RASTER_WGSL,
        "Material",
        size_of::<GpuMaterial>(),
        &[
            ("ambient", offset_of!(GpuMaterial, ambient)),
            ("diffuse", offset_of!(GpuMaterial, diffuse)),
            ("specular", offset_of!(GpuMaterial, specular)),
            ("emission", offset_of!(GpuMaterial, emission)),
            ("shininess", offset_of!(GpuMaterial, shininess)),
        ],
    );
    check(
        MESH_RASTER_WGSL,
        "Draw",
        size_of::<GpuDraw>(),
        &[
            ("modelview", offset_of!(GpuDraw, modelview)),
            ("projection", offset_of!(GpuDraw, projection)),
            ("normal_matrix", offset_of!(GpuDraw, normal_matrix)),
            ("viewport", offset_of!(GpuDraw, viewport)),
            ("depth_range", offset_of!(GpuDraw, depth_range)),
            ("flags", offset_of!(GpuDraw, flags)),
            ("color_material", offset_of!(GpuDraw, color_material)),
            ("model_ambient", offset_of!(GpuDraw, model_ambient)),
            ("primitive", offset_of!(GpuDraw, primitive)),
            ("materials", offset_of!(GpuDraw, materials)),
            ("lights", offset_of!(GpuDraw, lights)),
        ],
    );
}

/// The slot and mode numbers the compute shader hard-codes are the Rust enums'.
#[cfg(feature = "gpu")]
#[test]
fn shader_constants_match_the_enums() {
    use gleval::gl::Slot;
    let source = gleval::render::mesh_gpu::EVAL_MESH_WGSL;
    let module = naga::front::wgsl::parse_str(source).expect("parses");
    let value = |name: &str| -> u32 {
        let (_, c) = module.constants.iter().find(|(_, c)| c.name.as_deref() == Some(name)).expect(name);
        match module.global_expressions[c.init] {
            naga::Expression::Literal(naga::Literal::U32(v)) => v,
            ref other => panic!("{name}: {other:?}"),
        }
    };
    assert_eq!(value("SLOT_COLOR"), Slot::Color4 as u32);
    assert_eq!(value("SLOT_NORMAL"), Slot::Normal as u32);
    assert_eq!(value("SLOT_TEX1"), Slot::TexCoord1 as u32);
    assert_eq!(value("SLOT_TEX4"), Slot::TexCoord4 as u32);
    assert_eq!(value("SLOT_VERTEX3"), Slot::Vertex3 as u32);
    assert_eq!(value("SLOT_VERTEX4"), Slot::Vertex4 as u32);
    use gleval::gl::MeshMode;
    use gleval::render::mesh_gpu::mode_number;
    assert_eq!(value("MODE_POINTS"), mode_number(MeshMode::Points));
    assert_eq!(value("MODE_FILL"), mode_number(MeshMode::Fill));
    assert_eq!(value("MODE_SCATTERED"), mode_number(MeshMode::Triangles));
}

#[cfg(feature = "gpu")]
#[test]
fn embedded_mesh_shaders_are_the_files() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
    assert_eq!(gleval::render::mesh_gpu::EVAL_MESH_WGSL, std::fs::read_to_string(dir.join("eval_mesh.wgsl")).unwrap());
    assert_eq!(
        gleval::render::mesh_gpu::MESH_RASTER_WGSL,
        std::fs::read_to_string(dir.join("mesh_raster.wgsl")).unwrap()
    );
}
