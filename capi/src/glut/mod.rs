//! `GL/glut.h`: GLUT over `App`.
//!
//! Before `glutMainLoop` the calls only collect what the program asks for (window size, title,
//! display mode, callbacks); `glutCreateWindow` makes the context that GL calls between it and
//! the main loop go to. `glutMainLoop` hands that context and the callbacks to an `App` and
//! runs it (a window, or headless with `--png PATH`); it does not return, as GLUT's.

mod callbacks;
mod font_objects;
mod fonts;
mod init;
mod menus;
mod requests;
mod shapes;
mod strokes;
