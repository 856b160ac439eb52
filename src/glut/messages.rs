//! freeglut's messages: the warnings it prints for calls it ignores, `glutReportErrors`, and
//! the program's own handlers for them (`glutInitWarningFunc`, `glutInitErrorFunc`), which
//! receive the message instead of stderr.

use crate::gl::consts::GL_NO_ERROR;
use crate::gl::Gl;
use std::rc::Rc;

/// A handler of freeglut's messages (`glutInitWarningFunc`, `glutInitErrorFunc`).
pub type MessageFn = Rc<dyn Fn(&str)>;

/// The handlers a program installed.
#[derive(Clone, Default)]
pub(crate) struct Messages {
    pub warning: Option<MessageFn>,
    pub error: Option<MessageFn>,
}

/// The program's name as freeglut prints it (its `argv[0]`).
fn program_name() -> String {
    std::env::args().next().unwrap_or_default()
}

impl Gl {
    /// A freeglut warning: to the program's warning handler, or to stderr as freeglut prints
    /// it (`freeglut (PROGRAM): MESSAGE`).
    pub fn glut_warning(&self, message: &str) {
        // The handler runs with the program's state free: it may call GLUT.
        let handler = self.glut.program().messages.warning.clone();
        match handler {
            Some(handler) => handler(message),
            None => eprintln!("freeglut ({}): {message}", program_name()),
        }
    }

    /// `glutInitWarningFunc`: `Some(f)` receives freeglut's warnings instead of stderr.
    pub fn glut_init_warning_func(&mut self, handler: Option<MessageFn>) {
        self.glut.program_mut().messages.warning = handler;
    }

    /// `glutInitErrorFunc`: `Some(f)` receives freeglut's error messages instead of stderr
    /// (gleval's errors are the calls it ignores with a complaint, so the program goes on).
    pub fn glut_init_error_func(&mut self, handler: Option<MessageFn>) {
        self.glut.program_mut().messages.error = handler;
    }

    /// `glutReportErrors`: every GL error set, each as freeglut reports it
    /// (`GL error: MESSAGE`, with GLU's text for the code), until `glGetError` is clear.
    pub fn glut_report_errors(&mut self) {
        loop {
            let code = self.get_error();
            if code == GL_NO_ERROR {
                break;
            }
            let text = crate::glu::glu_error_string(code).unwrap_or("unknown error");
            self.glut_warning(&format!("GL error: {text}"));
        }
    }
}
