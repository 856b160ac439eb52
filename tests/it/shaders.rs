//! Every WGSL file under `shaders/` parses and validates with naga, without a GPU.

use std::path::Path;

fn validate(source: &str) -> Result<(), String> {
    let module = naga::front::wgsl::parse_str(source).map_err(|e| e.emit_to_string(source))?;
    let mut validator =
        naga::valid::Validator::new(naga::valid::ValidationFlags::all(), naga::valid::Capabilities::empty());
    validator.validate(&module).map(|_| ()).map_err(|e| e.emit_to_string(source))
}

/// The sources the crate makes its shader modules from (some are two files joined).
#[cfg(feature = "gpu")]
fn embedded() -> [(&'static str, &'static str); 3] {
    [
        ("raster.wgsl + fragment.wgsl", gleval::testing::RASTER_WGSL),
        ("mesh_raster.wgsl + fragment.wgsl", gleval::testing::MESH_RASTER_WGSL),
        ("eval_mesh.wgsl", gleval::testing::EVAL_MESH_WGSL),
    ]
}

#[cfg(feature = "gpu")]
#[test]
fn every_shader_validates_with_naga() {
    for (name, source) in embedded() {
        if let Err(e) = validate(source) {
            panic!("{name} does not validate:\n{e}");
        }
    }
}

/// Every file under `shaders/` is part of a module the crate builds.
#[cfg(feature = "gpu")]
#[test]
fn every_shader_file_is_used() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
    let mut checked = 0;
    for entry in std::fs::read_dir(&dir).expect("shaders/ exists") {
        let path = entry.expect("entry").path();
        if path.extension().is_some_and(|e| e == "wgsl") {
            let source = std::fs::read_to_string(&path).expect("readable");
            assert!(embedded().iter().any(|(_, s)| s.contains(&source)), "{} is not in any module", path.display());
            checked += 1;
        }
    }
    assert!(checked >= 4, "only {checked} shaders found in {}", dir.display());
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
fn embedded_shaders_are_the_files() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
    let read = |name: &str| std::fs::read_to_string(dir.join(name)).unwrap();
    let fragment = read("fragment.wgsl");
    assert_eq!(gleval::testing::FRAGMENT_WGSL, fragment);
    assert_eq!(gleval::testing::RASTER_WGSL, read("raster.wgsl") + &fragment);
    assert_eq!(gleval::testing::EVAL_MESH_WGSL, read("eval_mesh.wgsl"));
    assert_eq!(gleval::testing::MESH_RASTER_WGSL, read("mesh_raster.wgsl") + &fragment);
}
