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
