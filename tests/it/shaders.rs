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

/// The sources the crate embeds are the files validated above. (The layouts of the structs the
/// CPU writes for them are checked against naga's reflection by the crate's unit tests, beside
/// the Rust twins: `src/gpu/layout.rs`.)
#[cfg(feature = "gpu")]
#[test]
fn embedded_shader_is_the_file() {
    let file = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders/raster.wgsl")).unwrap();
    assert_eq!(gleval::testing::RASTER_WGSL, file);
}

#[cfg(feature = "gpu")]
#[test]
fn embedded_mesh_shaders_are_the_files() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
    assert_eq!(gleval::testing::EVAL_MESH_WGSL, std::fs::read_to_string(dir.join("eval_mesh.wgsl")).unwrap());
    assert_eq!(gleval::testing::MESH_RASTER_WGSL, std::fs::read_to_string(dir.join("mesh_raster.wgsl")).unwrap());
}
