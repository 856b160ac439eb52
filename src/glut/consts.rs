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

// freeglut: The freeglut and GLUT API versions.
pub const GLUT_API_VERSION: i32 = 4;
pub const GLUT_XLIB_IMPLEMENTATION: i32 = 13;

// freeglut: GLUT API macro definitions -- the display mode definitions.
pub const GLUT_LUMINANCE: u32 = 0x0200;

// freeglut: GLUT API macro definitions -- windows and menu related definitions.
pub const GLUT_MENU_NOT_IN_USE: i32 = 0x0000;
pub const GLUT_MENU_IN_USE: i32 = 0x0001;
pub const GLUT_NOT_VISIBLE: i32 = 0x0000;
pub const GLUT_VISIBLE: i32 = 0x0001;
pub const GLUT_HIDDEN: i32 = 0x0000;
pub const GLUT_FULLY_RETAINED: i32 = 0x0001;
pub const GLUT_PARTIALLY_RETAINED: i32 = 0x0002;
pub const GLUT_FULLY_COVERED: i32 = 0x0003;

// freeglut: GLUT API macro definitions -- the glutGet parameters.
pub const GLUT_WINDOW_BUFFER_SIZE: GLenum = 0x0068;
pub const GLUT_WINDOW_STENCIL_SIZE: GLenum = 0x0069;
pub const GLUT_WINDOW_RED_SIZE: GLenum = 0x006B;
pub const GLUT_WINDOW_GREEN_SIZE: GLenum = 0x006C;
pub const GLUT_WINDOW_BLUE_SIZE: GLenum = 0x006D;
pub const GLUT_WINDOW_ALPHA_SIZE: GLenum = 0x006E;
pub const GLUT_WINDOW_ACCUM_RED_SIZE: GLenum = 0x006F;
pub const GLUT_WINDOW_ACCUM_GREEN_SIZE: GLenum = 0x0070;
pub const GLUT_WINDOW_ACCUM_BLUE_SIZE: GLenum = 0x0071;
pub const GLUT_WINDOW_ACCUM_ALPHA_SIZE: GLenum = 0x0072;
pub const GLUT_WINDOW_PARENT: GLenum = 0x0075;
pub const GLUT_WINDOW_NUM_CHILDREN: GLenum = 0x0076;
pub const GLUT_WINDOW_COLORMAP_SIZE: GLenum = 0x0077;
pub const GLUT_WINDOW_NUM_SAMPLES: GLenum = 0x0078;
pub const GLUT_WINDOW_STEREO: GLenum = 0x0079;
pub const GLUT_WINDOW_CURSOR: GLenum = 0x007A;
pub const GLUT_SCREEN_WIDTH_MM: GLenum = 0x00CA;
pub const GLUT_SCREEN_HEIGHT_MM: GLenum = 0x00CB;
pub const GLUT_DISPLAY_MODE_POSSIBLE: GLenum = 0x0190;
pub const GLUT_WINDOW_FORMAT_ID: GLenum = 0x007B;

// freeglut: GLUT API macro definitions -- the glutDeviceGet parameters.
pub const GLUT_HAS_KEYBOARD: GLenum = 0x0258;
pub const GLUT_HAS_MOUSE: GLenum = 0x0259;
pub const GLUT_HAS_SPACEBALL: GLenum = 0x025A;
pub const GLUT_HAS_DIAL_AND_BUTTON_BOX: GLenum = 0x025B;
pub const GLUT_HAS_TABLET: GLenum = 0x025C;
pub const GLUT_NUM_MOUSE_BUTTONS: GLenum = 0x025D;
pub const GLUT_NUM_SPACEBALL_BUTTONS: GLenum = 0x025E;
pub const GLUT_NUM_BUTTON_BOX_BUTTONS: GLenum = 0x025F;
pub const GLUT_NUM_DIALS: GLenum = 0x0260;
pub const GLUT_NUM_TABLET_BUTTONS: GLenum = 0x0261;
pub const GLUT_DEVICE_IGNORE_KEY_REPEAT: GLenum = 0x0262;
pub const GLUT_DEVICE_KEY_REPEAT: GLenum = 0x0263;
pub const GLUT_HAS_JOYSTICK: GLenum = 0x0264;
pub const GLUT_OWNS_JOYSTICK: GLenum = 0x0265;
pub const GLUT_JOYSTICK_BUTTONS: GLenum = 0x0266;
pub const GLUT_JOYSTICK_AXES: GLenum = 0x0267;
pub const GLUT_JOYSTICK_POLL_RATE: GLenum = 0x0268;

// freeglut: GLUT API macro definitions -- the glutLayerGet parameters.
pub const GLUT_OVERLAY_POSSIBLE: GLenum = 0x0320;
pub const GLUT_LAYER_IN_USE: GLenum = 0x0321;
pub const GLUT_HAS_OVERLAY: GLenum = 0x0322;
pub const GLUT_TRANSPARENT_INDEX: GLenum = 0x0323;
pub const GLUT_NORMAL_DAMAGED: GLenum = 0x0324;
pub const GLUT_OVERLAY_DAMAGED: GLenum = 0x0325;

// freeglut: GLUT API macro definitions -- the glutVideoResizeGet parameters.
pub const GLUT_VIDEO_RESIZE_POSSIBLE: GLenum = 0x0384;
pub const GLUT_VIDEO_RESIZE_IN_USE: GLenum = 0x0385;
pub const GLUT_VIDEO_RESIZE_X_DELTA: GLenum = 0x0386;
pub const GLUT_VIDEO_RESIZE_Y_DELTA: GLenum = 0x0387;
pub const GLUT_VIDEO_RESIZE_WIDTH_DELTA: GLenum = 0x0388;
pub const GLUT_VIDEO_RESIZE_HEIGHT_DELTA: GLenum = 0x0389;
pub const GLUT_VIDEO_RESIZE_X: GLenum = 0x038A;
pub const GLUT_VIDEO_RESIZE_Y: GLenum = 0x038B;
pub const GLUT_VIDEO_RESIZE_WIDTH: GLenum = 0x038C;
pub const GLUT_VIDEO_RESIZE_HEIGHT: GLenum = 0x038D;

// freeglut: GLUT API macro definitions -- the glutUseLayer parameters.
pub const GLUT_NORMAL: GLenum = 0x0000;
pub const GLUT_OVERLAY: GLenum = 0x0001;

// freeglut: GLUT API macro definitions -- the glutSetCursor parameters.
pub const GLUT_CURSOR_RIGHT_ARROW: i32 = 0x0000;
pub const GLUT_CURSOR_LEFT_ARROW: i32 = 0x0001;
pub const GLUT_CURSOR_INFO: i32 = 0x0002;
pub const GLUT_CURSOR_DESTROY: i32 = 0x0003;
pub const GLUT_CURSOR_HELP: i32 = 0x0004;
pub const GLUT_CURSOR_CYCLE: i32 = 0x0005;
pub const GLUT_CURSOR_SPRAY: i32 = 0x0006;
pub const GLUT_CURSOR_WAIT: i32 = 0x0007;
pub const GLUT_CURSOR_TEXT: i32 = 0x0008;
pub const GLUT_CURSOR_CROSSHAIR: i32 = 0x0009;
pub const GLUT_CURSOR_UP_DOWN: i32 = 0x000A;
pub const GLUT_CURSOR_LEFT_RIGHT: i32 = 0x000B;
pub const GLUT_CURSOR_TOP_SIDE: i32 = 0x000C;
pub const GLUT_CURSOR_BOTTOM_SIDE: i32 = 0x000D;
pub const GLUT_CURSOR_LEFT_SIDE: i32 = 0x000E;
pub const GLUT_CURSOR_RIGHT_SIDE: i32 = 0x000F;
pub const GLUT_CURSOR_TOP_LEFT_CORNER: i32 = 0x0010;
pub const GLUT_CURSOR_TOP_RIGHT_CORNER: i32 = 0x0011;
pub const GLUT_CURSOR_BOTTOM_RIGHT_CORNER: i32 = 0x0012;
pub const GLUT_CURSOR_BOTTOM_LEFT_CORNER: i32 = 0x0013;
pub const GLUT_CURSOR_INHERIT: i32 = 0x0064;
pub const GLUT_CURSOR_NONE: i32 = 0x0065;
pub const GLUT_CURSOR_FULL_CROSSHAIR: i32 = 0x0066;

// freeglut: GLUT API macro definitions -- RGB color component specification definitions.
pub const GLUT_RED: i32 = 0x0000;
pub const GLUT_GREEN: i32 = 0x0001;
pub const GLUT_BLUE: i32 = 0x0002;

// freeglut: GLUT API macro definitions -- additional keyboard and joystick definitions.
pub const GLUT_KEY_REPEAT_OFF: i32 = 0x0000;
pub const GLUT_KEY_REPEAT_ON: i32 = 0x0001;
pub const GLUT_KEY_REPEAT_DEFAULT: i32 = 0x0002;
pub const GLUT_JOYSTICK_BUTTON_A: i32 = 0x0001;
pub const GLUT_JOYSTICK_BUTTON_B: i32 = 0x0002;
pub const GLUT_JOYSTICK_BUTTON_C: i32 = 0x0004;
pub const GLUT_JOYSTICK_BUTTON_D: i32 = 0x0008;

// freeglut: GLUT API macro definitions -- game mode definitions.
pub const GLUT_GAME_MODE_ACTIVE: GLenum = 0x0000;
pub const GLUT_GAME_MODE_POSSIBLE: GLenum = 0x0001;
pub const GLUT_GAME_MODE_WIDTH: GLenum = 0x0002;
pub const GLUT_GAME_MODE_HEIGHT: GLenum = 0x0003;
pub const GLUT_GAME_MODE_PIXEL_DEPTH: GLenum = 0x0004;
pub const GLUT_GAME_MODE_REFRESH_RATE: GLenum = 0x0005;
pub const GLUT_GAME_MODE_DISPLAY_CHANGED: GLenum = 0x0006;

// freeglut: Additional GLUT Key definitions for the Special key function.
pub const GLUT_KEY_NUM_LOCK: i32 = 0x006D;
pub const GLUT_KEY_BEGIN: i32 = 0x006E;
pub const GLUT_KEY_DELETE: i32 = 0x006F;
pub const GLUT_KEY_SHIFT_L: i32 = 0x0070;
pub const GLUT_KEY_SHIFT_R: i32 = 0x0071;
pub const GLUT_KEY_CTRL_L: i32 = 0x0072;
pub const GLUT_KEY_CTRL_R: i32 = 0x0073;
pub const GLUT_KEY_ALT_L: i32 = 0x0074;
pub const GLUT_KEY_ALT_R: i32 = 0x0075;
pub const GLUT_KEY_SUPER_L: i32 = 0x0076;
pub const GLUT_KEY_SUPER_R: i32 = 0x0077;

// freeglut: Additional GLUT modifiers.
pub const GLUT_ACTIVE_SUPER: i32 = 0x0008;
pub const GLUT_ACTION_EXIT: i32 = 0;
pub const GLUT_ACTION_GLUTMAINLOOP_RETURNS: i32 = 1;
pub const GLUT_ACTION_CONTINUE_EXECUTION: i32 = 2;
pub const GLUT_CREATE_NEW_CONTEXT: i32 = 0;
pub const GLUT_USE_CURRENT_CONTEXT: i32 = 1;

// freeglut: Direct/Indirect rendering context options (has meaning only in Unix/X11).
pub const GLUT_FORCE_INDIRECT_CONTEXT: i32 = 0;
pub const GLUT_ALLOW_DIRECT_CONTEXT: i32 = 1;
pub const GLUT_TRY_DIRECT_CONTEXT: i32 = 2;
pub const GLUT_FORCE_DIRECT_CONTEXT: i32 = 3;

// freeglut: GLUT API Extension macro definitions -- the glutGet parameters.
pub const GLUT_INIT_STATE: GLenum = 0x007C;
pub const GLUT_ACTION_ON_WINDOW_CLOSE: GLenum = 0x01F9;
pub const GLUT_WINDOW_BORDER_WIDTH: GLenum = 0x01FA;
pub const GLUT_WINDOW_BORDER_HEIGHT: GLenum = 0x01FB;
pub const GLUT_WINDOW_HEADER_HEIGHT: GLenum = 0x01FB;
pub const GLUT_VERSION: GLenum = 0x01FC;
pub const GLUT_RENDERING_CONTEXT: GLenum = 0x01FD;
pub const GLUT_DIRECT_RENDERING: GLenum = 0x01FE;
pub const GLUT_FULL_SCREEN: GLenum = 0x01FF;
pub const GLUT_SKIP_STALE_MOTION_EVENTS: GLenum = 0x0204;
pub const GLUT_GEOMETRY_VISUALIZE_NORMALS: GLenum = 0x0205;
pub const GLUT_STROKE_FONT_DRAW_JOIN_DOTS: GLenum = 0x0206;
pub const GLUT_ALLOW_NEGATIVE_WINDOW_POSITION: GLenum = 0x0207;
pub const GLUT_WINDOW_SRGB: GLenum = 0x007D;

// freeglut: Only one GLUT_AUXn bit may be used at a time.
pub const GLUT_AUX: u32 = 0x1000;
pub const GLUT_AUX1: u32 = 0x1000;
pub const GLUT_AUX2: u32 = 0x2000;
pub const GLUT_AUX3: u32 = 0x4000;
pub const GLUT_AUX4: u32 = 0x8000;

// freeglut: Set the requested OpenGL version.
pub const GLUT_INIT_MAJOR_VERSION: GLenum = 0x0200;
pub const GLUT_INIT_MINOR_VERSION: GLenum = 0x0201;
pub const GLUT_INIT_FLAGS: GLenum = 0x0202;
pub const GLUT_INIT_PROFILE: GLenum = 0x0203;

// freeglut: Flags for glutInitContextFlags, see fg_init.c.
pub const GLUT_DEBUG: i32 = 0x0001;
pub const GLUT_FORWARD_COMPATIBLE: i32 = 0x0002;

// freeglut: Flags for glutInitContextProfile, see fg_init.c.
pub const GLUT_CORE_PROFILE: i32 = 0x0001;
pub const GLUT_COMPATIBILITY_PROFILE: i32 = 0x0002;

// freeglut: GLUT API Extension macro definitions -- Spaceball button definitions.
pub const GLUT_SPACEBALL_BUTTON_A: i32 = 0x0001;
pub const GLUT_SPACEBALL_BUTTON_B: i32 = 0x0002;
pub const GLUT_SPACEBALL_BUTTON_C: i32 = 0x0004;
pub const GLUT_SPACEBALL_BUTTON_D: i32 = 0x0008;
pub const GLUT_SPACEBALL_BUTTON_E: i32 = 0x0010;

// freeglut: Multi-touch/multi-pointer extensions.
pub const GLUT_HAS_MULTI: i32 = 1;

// freeglut: Initialization functions, see fg_init.c.
pub const GLUT_APPSTATUS_PAUSE: i32 = 0x0001;
pub const GLUT_APPSTATUS_RESUME: i32 = 0x0002;

// freeglut: GLUT API macro definitions -- the display mode definitions.
pub const GLUT_CAPTIONLESS: u32 = 0x0400;
pub const GLUT_BORDERLESS: u32 = 0x0800;
pub const GLUT_SRGB: u32 = 0x1000;
