//! `glutInit`, the window's initial attributes, `glutCreateWindow` and `glutMainLoop`.

use super::callbacks;
use crate::context::{install, take_owned};
use gleval::app::{App, Options};
use std::cell::RefCell;
use std::ffi::{c_char, c_int, c_uint, CStr};

/// What the program asked for before the main loop.
struct Setup {
    options: Options,
    size: (i32, i32),
    display_mode: u32,
    title: String,
}

thread_local! {
    static SETUP: RefCell<Setup> = RefCell::new(Setup {
        options: Options::default(),
        // GLUT's default window size.
        size: (300, 300),
        display_mode: 0,
        title: String::new(),
    });
}

/// gleval's options and whether each takes a value (`App` parses them: `Options::from_args`).
const OPTIONS: [(&str, bool); 6] =
    [("--png", true), ("--time", true), ("--frames", true), ("--gpu", false), ("--wgpu", false), ("--profile", false)];

/// How many of `args` (from the first) are one gleval option with its value; 0 if the first
/// is not one.
fn option_len(args: &[String]) -> usize {
    let Some(first) = args.first() else { return 0 };
    if first.starts_with("--png=") {
        return 1;
    }
    match OPTIONS.iter().find(|(name, _)| first == name) {
        Some((_, true)) => args.len().min(2),
        Some((_, false)) => 1,
        None => 0,
    }
}

/// Splits the program's arguments into gleval's options and the program's own.
fn split_options(args: Vec<String>) -> (Vec<String>, Vec<bool>) {
    let mut ours = Vec::new();
    let mut keep = vec![true; args.len()];
    let mut i = 0;
    while i < args.len() {
        let n = option_len(&args[i..]);
        if n == 0 {
            i += 1;
            continue;
        }
        ours.extend_from_slice(&args[i..i + n]);
        keep[i..i + n].fill(false);
        i += n;
    }
    (ours, keep)
}

entry! {
    /// `glutInit(&argc, argv)`: takes `--png PATH`, `--time N`, `--frames N`, `--gpu`, `--wgpu`
    /// and `--profile` out of `argv` (as GLUT takes its own options) and keeps them for the main
    /// loop.
    unsafe fn glutInit(argcp: *mut c_int, argv: *mut *mut c_char) {
        let (Some(argc), false) = (unsafe { argcp.as_mut() }, argv.is_null()) else { return };
        let n = usize::try_from(*argc).unwrap_or(0);
        // SAFETY: `argv` holds `argc` strings (C's promise for main's arguments).
        let strings: Vec<String> = (0..n)
            .map(|i| unsafe { *argv.add(i) })
            .map(|p| if p.is_null() { String::new() } else { unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned() })
            .collect();
        let (ours, mut keep) = split_options(strings);
        if let Some(program) = keep.first_mut() {
            *program = true;
        }
        let mut kept = 0;
        for (i, keep) in keep.into_iter().enumerate() {
            if keep {
                unsafe { *argv.add(kept) = *argv.add(i) };
                kept += 1;
            }
        }
        if kept < n {
            unsafe { *argv.add(kept) = std::ptr::null_mut() };
        }
        *argc = kept as c_int;
        SETUP.with(|s| s.borrow_mut().options = Options::from_args(ours));
    }
}

entry! {
    /// `glutInitWindowSize`.
    fn glutInitWindowSize(width: c_int, height: c_int) {
        SETUP.with(|s| s.borrow_mut().size = (width, height))
    }
}

entry! {
    /// `glutInitWindowPosition`: where the window system places the window is its business.
    fn glutInitWindowPosition(_x: c_int, _y: c_int) {}
}

entry! {
    /// `glutInitDisplayMode`: kept for `glutGet`; the window always has colour and depth.
    fn glutInitDisplayMode(mode: c_uint) {
        SETUP.with(|s| s.borrow_mut().display_mode = mode)
    }
}

/// An `App` with the program's title, size and display mode.
fn app_from_setup() -> App {
    SETUP.with(|s| {
        let s = s.borrow();
        App::new(&s.title, s.size.0, s.size.1).init_display_mode(s.display_mode)
    })
}

entry! {
    /// `glutCreateWindow(title)`: makes the context the program's GL calls go to (GLUT makes
    /// the window's context current); returns the window's number, 1.
    unsafe fn glutCreateWindow(title: *const c_char) -> c_int {
        let title = if title.is_null() { String::new() } else { unsafe { CStr::from_ptr(title) }.to_string_lossy().into_owned() };
        SETUP.with(|s| s.borrow_mut().title = title);
        // freeglut on Mesa has no colour-index window to give: its fatal error, status 1.
        gleval::glut::display_mode::exit_unless_possible(SETUP.with(|s| s.borrow().display_mode));
        // `App` makes contexts as its windows have them (size, display mode, tessellator).
        let mut gl = app_from_setup().record_frame();
        let _ = gl.take_frame();
        install(gl);
        1
    }
}

entry! {
    /// `glutMainLoop`: runs the program (a window, or headless with `--png PATH`, `--time N`)
    /// and exits the process when it ends, as GLUT's main loop never returns.
    fn glutMainLoop() {
        let Some(made) = take_owned() else {
            eprintln!("gleval: glutMainLoop called before glutCreateWindow");
            std::process::exit(1);
        };
        let options = SETUP.with(|s| s.borrow().options.clone());
        let app = callbacks::register(app_from_setup().init(hand_over(made)));
        callbacks::set_in_loop(true);
        // The loop does not return to C either way: a panic inside it (a bug) ends the
        // program with status 1 after its message, as a failed run does.
        let ran = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| app.run_with(options)));
        std::process::exit(if ran.is_ok() { 0 } else { 1 });
    }
}

/// `App`'s init step: the context the program set up before the main loop replaces the fresh
/// one `App` made, keeping the fresh one's tessellator (`--gpu`). What the program drew before
/// the loop is dropped, as a window not yet shown loses it.
fn hand_over(made: Box<gleval::gl::Gl>) -> impl FnMut(&mut gleval::gl::Gl) {
    let mut made = Some(made);
    move |fresh| {
        if let Some(mut mine) = made.take() {
            mine.set_tessellator(fresh.tessellator());
            let _ = mine.take_frame();
            std::mem::swap(fresh, &mut *mine);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn options_leave_the_programs_arguments() {
        let args = ["prog", "-v", "--png", "a.png", "--gpu", "x", "--png=b.png", "--frames"];
        let (ours, keep) = split_options(args.iter().map(|s| s.to_string()).collect());
        assert_eq!(ours, ["--png", "a.png", "--gpu", "--png=b.png", "--frames"]);
        assert_eq!(keep, [true, true, false, false, false, true, false, false]);
    }
}
