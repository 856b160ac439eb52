//! What winit reports, as GLUT reports it: special keys, typed characters, modifier bits, and
//! GLUT's cursor shapes as winit's.

use crate::glut::consts::*;
use winit::event::Modifiers;
use winit::keyboard::{Key, NamedKey};
use winit::window::CursorIcon;

/// winit's cursor for a `GLUT_CURSOR_*` shape.
pub(super) fn cursor_icon(cursor: i32) -> CursorIcon {
    match cursor {
        GLUT_CURSOR_LEFT_ARROW => CursorIcon::Default,
        GLUT_CURSOR_INFO => CursorIcon::Pointer,
        GLUT_CURSOR_DESTROY => CursorIcon::NotAllowed,
        GLUT_CURSOR_HELP => CursorIcon::Help,
        GLUT_CURSOR_CYCLE => CursorIcon::Progress,
        GLUT_CURSOR_SPRAY => CursorIcon::Cell,
        GLUT_CURSOR_WAIT => CursorIcon::Wait,
        GLUT_CURSOR_TEXT => CursorIcon::Text,
        GLUT_CURSOR_CROSSHAIR | GLUT_CURSOR_FULL_CROSSHAIR => CursorIcon::Crosshair,
        GLUT_CURSOR_UP_DOWN => CursorIcon::NsResize,
        GLUT_CURSOR_LEFT_RIGHT => CursorIcon::EwResize,
        GLUT_CURSOR_TOP_SIDE => CursorIcon::NResize,
        GLUT_CURSOR_BOTTOM_SIDE => CursorIcon::SResize,
        GLUT_CURSOR_LEFT_SIDE => CursorIcon::WResize,
        GLUT_CURSOR_RIGHT_SIDE => CursorIcon::EResize,
        GLUT_CURSOR_TOP_LEFT_CORNER => CursorIcon::NwResize,
        GLUT_CURSOR_TOP_RIGHT_CORNER => CursorIcon::NeResize,
        GLUT_CURSOR_BOTTOM_RIGHT_CORNER => CursorIcon::SeResize,
        GLUT_CURSOR_BOTTOM_LEFT_CORNER => CursorIcon::SwResize,
        _ => CursorIcon::Default,
    }
}

/// The `GLUT_KEY_*` code of a key GLUT reports to `glutSpecialFunc`.
pub(super) fn special_key(key: &Key) -> Option<i32> {
    let Key::Named(named) = key else { return None };
    let function_keys = [
        NamedKey::F1,
        NamedKey::F2,
        NamedKey::F3,
        NamedKey::F4,
        NamedKey::F5,
        NamedKey::F6,
        NamedKey::F7,
        NamedKey::F8,
        NamedKey::F9,
        NamedKey::F10,
        NamedKey::F11,
        NamedKey::F12,
    ];
    if let Some(k) = function_keys.iter().position(|f| f == named) {
        return Some(GLUT_KEY_F1 + k as i32);
    }
    Some(match named {
        NamedKey::ArrowLeft => GLUT_KEY_LEFT,
        NamedKey::ArrowUp => GLUT_KEY_UP,
        NamedKey::ArrowRight => GLUT_KEY_RIGHT,
        NamedKey::ArrowDown => GLUT_KEY_DOWN,
        NamedKey::PageUp => GLUT_KEY_PAGE_UP,
        NamedKey::PageDown => GLUT_KEY_PAGE_DOWN,
        NamedKey::Home => GLUT_KEY_HOME,
        NamedKey::End => GLUT_KEY_END,
        NamedKey::Insert => GLUT_KEY_INSERT,
        _ => return None,
    })
}

/// The character a released key typed, as GLUT's keyboard callbacks get it.
pub(super) fn key_text(key: &Key) -> Option<&str> {
    match key {
        Key::Character(text) => Some(text.as_str()),
        Key::Named(NamedKey::Enter) => Some("\r"),
        Key::Named(NamedKey::Backspace) => Some("\u{8}"),
        Key::Named(NamedKey::Tab) => Some("\t"),
        Key::Named(NamedKey::Space) => Some(" "),
        Key::Named(NamedKey::Escape) => Some("\u{1b}"),
        Key::Named(NamedKey::Delete) => Some("\u{7f}"),
        _ => None,
    }
}

/// `glutGetModifiers`'s bits for the modifier keys held.
pub(super) fn glut_modifiers(modifiers: &Modifiers) -> i32 {
    let state = modifiers.state();
    let mut bits = 0;
    if state.shift_key() {
        bits |= GLUT_ACTIVE_SHIFT;
    }
    if state.control_key() {
        bits |= GLUT_ACTIVE_CTRL;
    }
    if state.alt_key() {
        bits |= GLUT_ACTIVE_ALT;
    }
    bits
}
