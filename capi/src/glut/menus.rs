//! GLUT's pop-up menus (`Gl::glut_create_menu` …): a C menu callback runs with the context
//! current, as GLUT's callbacks do.

use crate::context::{enter, with_gl};
use std::ffi::{c_char, c_int, c_void, CStr};

/// A C menu callback: the chosen entry's value.
type MenuFn = extern "C" fn(c_int);

/// A label as C gives it (NUL-terminated; not UTF-8 is replaced, NULL is empty).
///
/// # Safety
/// `s` is NULL or a NUL-terminated string.
unsafe fn label(s: *const c_char) -> String {
    if s.is_null() {
        return String::new();
    }
    unsafe { CStr::from_ptr(s) }.to_string_lossy().into_owned()
}

forward! {
    glutSetMenu(menu: c_int) => glut_set_menu;
    glutGetMenu() -> c_int => glut_get_menu;
    glutDestroyMenu(menu: c_int) => glut_destroy_menu;
    glutRemoveMenuItem(item: c_int) => glut_remove_menu_item;
    glutAttachMenu(button: c_int) => glut_attach_menu;
    glutDetachMenu(button: c_int) => glut_detach_menu;
}

entry! {
    /// `glutCreateMenu`: a new menu whose choices call `func` (NULL: choices do nothing).
    fn glutCreateMenu(func: Option<MenuFn>) -> c_int {
        with_gl(|gl| {
            gl.glut_create_menu(move |gl, value| {
                if let Some(f) = func {
                    enter(gl, || f(value));
                }
            })
        })
    }
}

entry! {
    /// `glutAddMenuEntry`.
    unsafe fn glutAddMenuEntry(name: *const c_char, value: c_int) {
        let name = unsafe { label(name) };
        with_gl(|gl| gl.glut_add_menu_entry(&name, value))
    }
}

entry! {
    /// `glutAddSubMenu`.
    unsafe fn glutAddSubMenu(name: *const c_char, menu: c_int) {
        let name = unsafe { label(name) };
        with_gl(|gl| gl.glut_add_sub_menu(&name, menu))
    }
}

entry! {
    /// `glutChangeToMenuEntry`.
    unsafe fn glutChangeToMenuEntry(item: c_int, name: *const c_char, value: c_int) {
        let name = unsafe { label(name) };
        with_gl(|gl| gl.glut_change_to_menu_entry(item, &name, value))
    }
}

entry! {
    /// `glutChangeToSubMenu`.
    unsafe fn glutChangeToSubMenu(item: c_int, name: *const c_char, menu: c_int) {
        let name = unsafe { label(name) };
        with_gl(|gl| gl.glut_change_to_sub_menu(item, &name, menu))
    }
}

entry! {
    /// `glutSetMenuData(data)` (freeglut): the program's pointer, kept with the current menu.
    fn glutSetMenuData(data: *mut c_void) {
        with_gl(|gl| gl.glut_set_menu_data(data as usize))
    }
}

entry! {
    /// `glutGetMenuData` (freeglut).
    fn glutGetMenuData() -> *mut c_void {
        with_gl(|gl| gl.glut_get_menu_data() as *mut c_void)
    }
}

entry! {
    /// `glutSetMenuFont(menu, font)` (freeglut): the bitmap font menu `menu` is drawn in
    /// (another handle is no bitmap font: nothing changes).
    fn glutSetMenuFont(menu: c_int, font: *mut c_void) {
        if let Some(font) = super::fonts::font(font) {
            with_gl(|gl| gl.glut_set_menu_font(menu, font))
        }
    }
}
