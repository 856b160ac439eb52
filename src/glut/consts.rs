//! GLUT's constants, with freeglut's values (`GL/freeglut_std.h`), which are GLUT 3.7's.
#![allow(missing_docs)]

use crate::gl::types::GLenum;

// Bitmap fonts (glutBitmapCharacter).
pub use super::fonts::{
    GLUT_BITMAP_8_BY_13, GLUT_BITMAP_9_BY_15, GLUT_BITMAP_HELVETICA_10, GLUT_BITMAP_HELVETICA_12,
    GLUT_BITMAP_HELVETICA_18, GLUT_BITMAP_TIMES_ROMAN_10, GLUT_BITMAP_TIMES_ROMAN_24,
};
// Stroke fonts (glutStrokeCharacter).
pub use super::fonts::{GLUT_STROKE_MONO_ROMAN, GLUT_STROKE_ROMAN};

// Mouse buttons and states (glutMouseFunc), window entry (glutEntryFunc).
/// The left mouse button.
pub const GLUT_LEFT_BUTTON: i32 = 0;
/// The middle button.
pub const GLUT_MIDDLE_BUTTON: i32 = 1;
/// The right button.
pub const GLUT_RIGHT_BUTTON: i32 = 2;
/// A button pressed.
pub const GLUT_DOWN: i32 = 0;
/// A button released.
pub const GLUT_UP: i32 = 1;
/// The pointer left the window.
pub const GLUT_LEFT: i32 = 0;
/// The pointer entered the window.
pub const GLUT_ENTERED: i32 = 1;

// Special keys (glutSpecialFunc, glutSpecialUpFunc).
pub const GLUT_KEY_F1: i32 = 1;
pub const GLUT_KEY_F2: i32 = 2;
pub const GLUT_KEY_F3: i32 = 3;
pub const GLUT_KEY_F4: i32 = 4;
pub const GLUT_KEY_F5: i32 = 5;
pub const GLUT_KEY_F6: i32 = 6;
pub const GLUT_KEY_F7: i32 = 7;
pub const GLUT_KEY_F8: i32 = 8;
pub const GLUT_KEY_F9: i32 = 9;
pub const GLUT_KEY_F10: i32 = 10;
pub const GLUT_KEY_F11: i32 = 11;
pub const GLUT_KEY_F12: i32 = 12;
pub const GLUT_KEY_LEFT: i32 = 100;
pub const GLUT_KEY_UP: i32 = 101;
pub const GLUT_KEY_RIGHT: i32 = 102;
pub const GLUT_KEY_DOWN: i32 = 103;
pub const GLUT_KEY_PAGE_UP: i32 = 104;
pub const GLUT_KEY_PAGE_DOWN: i32 = 105;
pub const GLUT_KEY_HOME: i32 = 106;
pub const GLUT_KEY_END: i32 = 107;
pub const GLUT_KEY_INSERT: i32 = 108;

// Modifier bits (glutGetModifiers).
pub const GLUT_ACTIVE_SHIFT: i32 = 1;
pub const GLUT_ACTIVE_CTRL: i32 = 2;
pub const GLUT_ACTIVE_ALT: i32 = 4;

// Display mode bits (glutInitDisplayMode).
pub const GLUT_RGB: u32 = 0;
pub const GLUT_RGBA: u32 = 0;
pub const GLUT_INDEX: u32 = 1;
pub const GLUT_SINGLE: u32 = 0;
pub const GLUT_DOUBLE: u32 = 2;
pub const GLUT_ACCUM: u32 = 4;
pub const GLUT_ALPHA: u32 = 8;
pub const GLUT_DEPTH: u32 = 16;
pub const GLUT_STENCIL: u32 = 32;
pub const GLUT_MULTISAMPLE: u32 = 128;
pub const GLUT_STEREO: u32 = 256;

// glutGet names.
pub const GLUT_WINDOW_X: GLenum = 100;
pub const GLUT_WINDOW_Y: GLenum = 101;
pub const GLUT_WINDOW_WIDTH: GLenum = 102;
pub const GLUT_WINDOW_HEIGHT: GLenum = 103;
pub const GLUT_WINDOW_DEPTH_SIZE: GLenum = 106;
pub const GLUT_WINDOW_DOUBLEBUFFER: GLenum = 115;
pub const GLUT_WINDOW_RGBA: GLenum = 116;
pub const GLUT_SCREEN_WIDTH: GLenum = 200;
pub const GLUT_SCREEN_HEIGHT: GLenum = 201;
pub const GLUT_INIT_WINDOW_X: GLenum = 500;
pub const GLUT_INIT_WINDOW_Y: GLenum = 501;
pub const GLUT_INIT_WINDOW_WIDTH: GLenum = 502;
pub const GLUT_INIT_WINDOW_HEIGHT: GLenum = 503;
pub const GLUT_INIT_DISPLAY_MODE: GLenum = 504;
pub const GLUT_ELAPSED_TIME: GLenum = 700;
/// `glutGet`: the number of items in the current menu.
pub const GLUT_MENU_NUM_ITEMS: GLenum = 300;
