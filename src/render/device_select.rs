//! Quiet Vulkan start-up on a machine without a desktop session.
//!
//! Mesa's device-select layer (`VK_LAYER_MESA_device_select`, an implicit layer: every Vulkan
//! instance loads it, wgpu's included) asks for a Wayland compositor when the instance is
//! created. Where there is no desktop session (`XDG_RUNTIME_DIR` unset: a CI machine, ssh, a
//! container) libwayland prints `error: XDG_RUNTIME_DIR is invalid or not set in the
//! environment.`, twice, though nothing failed and the picture is drawn. `NODEVICE_SELECT=1`,
//! read by the layer when the instance is created (Mesa's
//! `src/vulkan/device-select-layer/device_select_layer.c`), turns the layer off.

use std::ffi::OsString;
use std::path::Path;

/// The variable that turns Mesa's device-select layer off.
pub const NODEVICE_SELECT: &str = "NODEVICE_SELECT";

/// Sets `NODEVICE_SELECT=1` when the device-select layer could only print a false error: the
/// user has not set `NODEVICE_SELECT` or asked the layer for a device (`DRI_PRIME`,
/// `MESA_VK_DEVICE_SELECT`), and there is no desktop session (`XDG_RUNTIME_DIR` unset or not a
/// directory). Otherwise the environment is left as it is.
///
/// Call it at a program's edge, before any wgpu instance exists and while no other thread reads
/// the environment: [`App::run`](crate::app::App::run) and
/// [`App::run_with`](crate::app::App::run_with) do (so every C program through `glutMainLoop`),
/// and the C ABI before `glReadPixels` makes its wgpu renderer.
pub fn quiet_device_select() {
    if wants_quiet(|name| std::env::var_os(name)) {
        std::env::set_var(NODEVICE_SELECT, "1");
    }
}

/// The decision, on an environment given as a lookup.
fn wants_quiet(var: impl Fn(&str) -> Option<OsString>) -> bool {
    let chosen = [NODEVICE_SELECT, "DRI_PRIME", "MESA_VK_DEVICE_SELECT"].iter().any(|name| var(name).is_some());
    let session = var("XDG_RUNTIME_DIR").is_some_and(|dir| Path::new(&dir).is_dir());
    !chosen && !session
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env<'a>(vars: &'a [(&'a str, &'a str)]) -> impl Fn(&str) -> Option<OsString> + 'a {
        move |name| vars.iter().find(|(n, _)| *n == name).map(|(_, v)| OsString::from(v))
    }

    #[test]
    fn only_without_a_session_and_without_the_user_s_choice() {
        let tmp = std::env::temp_dir();
        let tmp = tmp.to_str().expect("a UTF-8 temporary directory");
        assert!(wants_quiet(env(&[])));
        assert!(wants_quiet(env(&[("XDG_RUNTIME_DIR", "/no/such/directory")])));
        assert!(!wants_quiet(env(&[("XDG_RUNTIME_DIR", tmp)])));
        assert!(!wants_quiet(env(&[("NODEVICE_SELECT", "0")])));
        assert!(!wants_quiet(env(&[("DRI_PRIME", "1")])));
        assert!(!wants_quiet(env(&[("MESA_VK_DEVICE_SELECT", "10de:1234")])));
    }
}
