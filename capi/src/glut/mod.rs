//! `GL/freeglut_std.h` and `GL/freeglut_ext.h`: GLUT over `App`.
//!
//! Before `glutMainLoop` the calls collect what the program asks for (window sizes, titles,
//! display mode, callbacks); each `glutCreateWindow` and `glutCreateSubWindow` makes a window
//! with its own context, which GL calls go to while it is current. `glutMainLoop` hands the
//! windows and their callbacks to `App` and runs them (windows, or headless with `--png PATH`).

mod callbacks;
mod font_objects;
mod fonts;
mod init;
mod menus;
mod requests;
mod settings;
mod shapes;
mod strokes;
mod windows;
