//! GLUT's pop-up menus as a program builds them (GLUT 3 spec §6: `glutCreateMenu`,
//! `glutAddMenuEntry`, `glutAddSubMenu`, `glutAttachMenu`, ...). This file holds the menus and
//! the calls that change them; `popup.rs` shows them and picks an entry.
//!
//! Menus are numbered from 1 as freeglut numbers them, and calls act on the *current* menu, the
//! one made last or chosen with `glutSetMenu`. Where freeglut stops the program with an error
//! (adding to no menu, an item number out of range, attaching a menu that does not exist), these
//! calls print the same complaint to stderr and change nothing: a typo in a menu should not end
//! a demo, and never a test.

// Without the runner (`App`: features gpu and png) menus are built but never shown.
#![cfg_attr(not(all(feature = "gpu", feature = "png")), allow(dead_code))]

use super::fonts::{GlutBitmapFont, GLUT_BITMAP_HELVETICA_18};
use crate::gl::Gl;

/// A menu callback (`glutCreateMenu(func)`): called with the value of the entry chosen.
pub type MenuFn = Box<dyn FnMut(&mut Gl, i32)>;

/// A menu's destroy callback (`glutMenuDestroyFunc(func)`).
pub type MenuDestroyFn = Box<dyn FnMut(&mut Gl)>;

/// One line of a menu.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum MenuItem {
    /// `glutAddMenuEntry(label, value)`.
    Entry { label: String, value: i32 },
    /// `glutAddSubMenu(label, menu)`: a cascading menu opens beside it.
    SubMenu { label: String, menu: i32 },
}

impl MenuItem {
    pub(crate) fn label(&self) -> &str {
        match self {
            Self::Entry { label, .. } | Self::SubMenu { label, .. } => label,
        }
    }
}

/// A menu: its items top to bottom and its callback (out while it runs).
pub(crate) struct Menu {
    pub items: Vec<MenuItem>,
    callback: Option<MenuFn>,
    /// `glutSetMenuData`: the program's pointer, kept as a number.
    data: usize,
    /// `glutMenuDestroyFunc`: runs when the menu is destroyed.
    on_destroy: Option<MenuDestroyFn>,
    /// `glutSetMenuFont`: the font its labels are drawn in.
    font: Option<GlutBitmapFont>,
}

/// Every menu of the program and the current one: program-wide, as freeglut's menu ids are
/// (a menu made in one window can be set, changed and attached in another). Which menu each
/// mouse button opens is the window's (`GlutState::attached_menus`).
#[derive(Default)]
pub(crate) struct Menus {
    /// Menu `id` is `menus[id - 1]`; destroyed menus leave `None` (ids are not reused, as
    /// freeglut's are not while later ones live).
    menus: Vec<Option<Menu>>,
    /// `glutGetMenu`: 0 when there is none.
    current: i32,
}

fn complain(call: &str, what: &str) {
    eprintln!("gleval: {call}: {what}; the call is ignored");
}

impl Menus {
    /// The menu with this id, if it exists.
    pub(crate) fn get(&self, id: i32) -> Option<&Menu> {
        let index = usize::try_from(id).ok()?.checked_sub(1)?;
        self.menus.get(index)?.as_ref()
    }

    fn get_mut(&mut self, id: i32) -> Option<&mut Menu> {
        let index = usize::try_from(id).ok()?.checked_sub(1)?;
        self.menus.get_mut(index)?.as_mut()
    }

    /// The font menu `id`'s labels are drawn in (freeglut's default, Helvetica 18).
    pub(crate) fn font(&self, id: i32) -> GlutBitmapFont {
        self.get(id).and_then(|m| m.font).unwrap_or(GLUT_BITMAP_HELVETICA_18)
    }

    /// The current menu for a call that changes it, or a complaint.
    fn current_mut(&mut self, call: &str) -> Option<&mut Menu> {
        let current = self.current;
        let menu = self.get_mut(current);
        if menu.is_none() {
            complain(call, "no current menu");
        }
        menu
    }

    /// The 1-based `item` of the current menu, or a complaint.
    fn item_mut(&mut self, call: &str, item: i32) -> Option<&mut MenuItem> {
        let menu = self.current_mut(call)?;
        let index = usize::try_from(item).ok().and_then(|i| i.checked_sub(1));
        let found = index.and_then(|i| menu.items.get_mut(i));
        if found.is_none() {
            complain(call, &format!("the current menu has no item {item}"));
        }
        found
    }

    /// A sub-menu id that exists, or a complaint.
    fn valid_sub_menu(&self, call: &str, menu: i32) -> bool {
        let ok = self.get(menu).is_some();
        if !ok {
            complain(call, &format!("there is no menu {menu}"));
        }
        ok
    }

    /// Takes a menu's callback out to run it with the context.
    pub(crate) fn take_callback(&mut self, id: i32) -> Option<MenuFn> {
        self.get_mut(id)?.callback.take()
    }

    /// Puts a callback back after it ran (unless it destroyed its own menu).
    pub(crate) fn restore_callback(&mut self, id: i32, callback: MenuFn) {
        if let Some(menu) = self.get_mut(id) {
            menu.callback.get_or_insert(callback);
        }
    }

    /// Makes `id` current while its callback runs (GLUT sets the current menu to the one whose
    /// entry was chosen) and returns what was current before.
    pub(crate) fn swap_current(&mut self, id: i32) -> i32 {
        std::mem::replace(&mut self.current, id)
    }
}

impl std::fmt::Debug for Menus {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Menus")
            .field("menus", &self.menus.iter().map(|m| m.as_ref().map(|m| &m.items)).collect::<Vec<_>>())
            .field("current", &self.current)
            .finish()
    }
}

impl Gl {
    /// `glutCreateMenu(func)`: a new, empty menu, made current; returns its id (from 1).
    /// `func(gl, value)` runs when one of its entries is chosen.
    pub fn glut_create_menu(&mut self, func: impl FnMut(&mut Gl, i32) + 'static) -> i32 {
        let mut program = self.glut.program_mut();
        let menus = &mut program.menus;
        let menu = Menu { items: Vec::new(), callback: Some(Box::new(func)), data: 0, on_destroy: None, font: None };
        menus.menus.push(Some(menu));
        menus.current = menus.menus.len() as i32;
        menus.current
    }

    /// `glutSetMenu(menu)`: makes `menu` current (an id that does not exist is ignored).
    pub fn glut_set_menu(&mut self, menu: i32) {
        let menus = &mut self.glut.program_mut().menus;
        if menus.valid_sub_menu("glutSetMenu", menu) {
            menus.current = menu;
        }
    }

    /// `glutGetMenu`: the current menu's id, 0 if there is none.
    #[must_use]
    pub fn glut_get_menu(&self) -> i32 {
        let menus = &self.glut.program().menus;
        if menus.get(menus.current).is_some() {
            menus.current
        } else {
            0
        }
    }

    /// `glutDestroyMenu(menu)`: the menu is gone; buttons it was attached to open nothing, and
    /// if it was current there is no current menu.
    pub fn glut_destroy_menu(&mut self, menu: i32) {
        if !self.glut.program().menus.valid_sub_menu("glutDestroyMenu", menu) {
            return;
        }
        // freeglut runs the menu's destroy callback with the menu current, before it goes (the
        // program's state free while it runs: it may call GLUT).
        let on_destroy = self.glut.program_mut().menus.get_mut(menu).and_then(|m| m.on_destroy.take());
        if let Some(mut on_destroy) = on_destroy {
            let previous = self.glut.program_mut().menus.swap_current(menu);
            on_destroy(self);
            self.glut.program_mut().menus.current = previous;
        }
        for attached in &mut self.glut.attached_menus {
            if *attached == menu {
                *attached = 0;
            }
        }
        let menus = &mut self.glut.program_mut().menus;
        if let Some(slot) = menus.menus.get_mut(menu as usize - 1) {
            *slot = None;
        }
        if menus.current == menu {
            menus.current = 0;
        }
    }

    /// `glutMenuDestroyFunc(func)` (freeglut): `func` runs when the current menu is destroyed.
    pub fn glut_menu_destroy_func(&mut self, func: Option<MenuDestroyFn>) {
        if let Some(menu) = self.glut.program_mut().menus.current_mut("glutMenuDestroyFunc") {
            menu.on_destroy = func;
        }
    }

    /// `glutSetMenuData(data)` (freeglut): a number the program keeps with the current menu.
    pub fn glut_set_menu_data(&mut self, data: usize) {
        if let Some(menu) = self.glut.program_mut().menus.current_mut("glutSetMenuData") {
            menu.data = data;
        }
    }

    /// `glutGetMenuData` (freeglut): what `glutSetMenuData` kept (0 initially or without a
    /// current menu).
    #[must_use]
    pub fn glut_get_menu_data(&self) -> usize {
        let menus = &self.glut.program().menus;
        menus.get(menus.current).map_or(0, |m| m.data)
    }

    /// `glutSetMenuFont(menu, font)` (freeglut): menu `menu`'s labels are drawn in `font`.
    pub fn glut_set_menu_font(&mut self, menu: i32, font: GlutBitmapFont) {
        match self.glut.program_mut().menus.get_mut(menu) {
            Some(m) => m.font = Some(font),
            None => complain("glutSetMenuFont", &format!("there is no menu {menu}")),
        }
    }

    /// `glutAddMenuEntry(label, value)`: an entry at the bottom of the current menu.
    pub fn glut_add_menu_entry(&mut self, label: &str, value: i32) {
        if let Some(menu) = self.glut.program_mut().menus.current_mut("glutAddMenuEntry") {
            menu.items.push(MenuItem::Entry { label: label.to_owned(), value });
        }
    }

    /// `glutAddSubMenu(label, menu)`: an item at the bottom of the current menu that opens
    /// `menu` beside it.
    pub fn glut_add_sub_menu(&mut self, label: &str, menu: i32) {
        let menus = &mut self.glut.program_mut().menus;
        if !menus.valid_sub_menu("glutAddSubMenu", menu) {
            return;
        }
        if let Some(current) = menus.current_mut("glutAddSubMenu") {
            current.items.push(MenuItem::SubMenu { label: label.to_owned(), menu });
        }
    }

    /// `glutChangeToMenuEntry(item, label, value)`: item `item` (from 1) of the current menu
    /// becomes an entry.
    pub fn glut_change_to_menu_entry(&mut self, item: i32, label: &str, value: i32) {
        if let Some(slot) = self.glut.program_mut().menus.item_mut("glutChangeToMenuEntry", item) {
            *slot = MenuItem::Entry { label: label.to_owned(), value };
        }
    }

    /// `glutChangeToSubMenu(item, label, menu)`: item `item` (from 1) of the current menu
    /// becomes a sub-menu item.
    pub fn glut_change_to_sub_menu(&mut self, item: i32, label: &str, menu: i32) {
        let menus = &mut self.glut.program_mut().menus;
        if !menus.valid_sub_menu("glutChangeToSubMenu", menu) {
            return;
        }
        if let Some(slot) = menus.item_mut("glutChangeToSubMenu", item) {
            *slot = MenuItem::SubMenu { label: label.to_owned(), menu };
        }
    }

    /// `glutRemoveMenuItem(item)`: item `item` (from 1) leaves the current menu; the ones
    /// below move up.
    pub fn glut_remove_menu_item(&mut self, item: i32) {
        let menus = &mut self.glut.program_mut().menus;
        if menus.item_mut("glutRemoveMenuItem", item).is_some() {
            if let Some(menu) = menus.current_mut("glutRemoveMenuItem") {
                menu.items.remove(item as usize - 1);
            }
        }
    }

    /// `glutGet(GLUT_MENU_NUM_ITEMS)`'s answer: the items of the current menu.
    pub(crate) fn glut_menu_num_items(&self) -> i32 {
        let menus = &self.glut.program().menus;
        menus.get(menus.current).map_or(0, |m| m.items.len() as i32)
    }

    /// `glutAttachMenu(button)`: pressing `button` (`GLUT_LEFT_BUTTON`, `_MIDDLE_`, `_RIGHT_`)
    /// in the window opens the current menu; the program's mouse callback no longer sees that
    /// button.
    pub fn glut_attach_menu(&mut self, button: i32) {
        let current = self.glut.program().menus.current;
        if self.glut.program().menus.get(current).is_none() {
            return complain("glutAttachMenu", "no current menu");
        }
        match usize::try_from(button).ok().and_then(|b| self.glut.attached_menus.get_mut(b)) {
            Some(slot) => *slot = current,
            None => complain("glutAttachMenu", &format!("{button} is not a mouse button")),
        }
    }

    /// `glutDetachMenu(button)`: `button` opens no menu any more.
    pub fn glut_detach_menu(&mut self, button: i32) {
        if let Some(slot) = usize::try_from(button).ok().and_then(|b| self.glut.attached_menus.get_mut(b)) {
            *slot = 0;
        }
    }

    /// Runs the callback of `menu` for a chosen entry's `value`, with `menu` current while it
    /// runs, as GLUT does.
    pub(crate) fn run_menu_callback(&mut self, menu: i32, value: i32) {
        // Out of the program's state while it runs: the callback may call GLUT.
        let Some(mut callback) = self.glut.program_mut().menus.take_callback(menu) else { return };
        let previous = self.glut.program_mut().menus.swap_current(menu);
        callback(self, value);
        let mut program = self.glut.program_mut();
        // A callback that chose another menu keeps its choice.
        if program.menus.current == menu {
            program.menus.current = previous;
        }
        program.menus.restore_callback(menu, callback);
    }

    /// The menu the window's `button` opens, if any (one destroyed opens nothing).
    pub(crate) fn glut_attached_menu(&self, button: i32) -> Option<i32> {
        let id = *self.glut.attached_menus.get(usize::try_from(button).ok()?)?;
        self.glut.program().menus.get(id).map(|_| id)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::glut::consts::*;
    use std::cell::RefCell;
    use std::rc::Rc;

    #[test]
    fn menus_number_from_one_and_calls_act_on_the_current_menu() {
        let mut gl = Gl::new(100, 100);
        assert_eq!(gl.glut_get_menu(), 0);
        let sub = gl.glut_create_menu(|_, _| {});
        gl.glut_add_menu_entry("a", 1);
        let main = gl.glut_create_menu(|_, _| {});
        assert_eq!((sub, main), (1, 2));
        assert_eq!(gl.glut_get_menu(), main);
        gl.glut_add_menu_entry("b", 2);
        gl.glut_add_sub_menu("more", sub);
        assert_eq!(gl.glut_menu_num_items(), 2);
        gl.glut_set_menu(sub);
        assert_eq!(gl.glut_menu_num_items(), 1);
        gl.glut_set_menu(main);
        gl.glut_change_to_menu_entry(2, "c", 3);
        gl.glut_remove_menu_item(1);
        let program = gl.glut.program();
        let items = &program.menus.get(main).unwrap().items;
        assert_eq!(items, &[MenuItem::Entry { label: "c".into(), value: 3 }]);
    }

    #[test]
    fn bad_calls_change_nothing() {
        let mut gl = Gl::new(100, 100);
        gl.glut_add_menu_entry("orphan", 1);
        gl.glut_attach_menu(GLUT_RIGHT_BUTTON);
        let menu = gl.glut_create_menu(|_, _| {});
        gl.glut_add_sub_menu("missing", 7);
        gl.glut_remove_menu_item(0);
        gl.glut_remove_menu_item(1);
        gl.glut_change_to_menu_entry(-3, "x", 1);
        gl.glut_attach_menu(5);
        gl.glut_attach_menu(-1);
        gl.glut_set_menu(42);
        assert_eq!(gl.glut_get_menu(), menu);
        assert_eq!(gl.glut_menu_num_items(), 0);
        assert_eq!(gl.glut_attached_menu(GLUT_RIGHT_BUTTON), None);
        gl.glut_attach_menu(GLUT_RIGHT_BUTTON);
        assert_eq!(gl.glut_attached_menu(GLUT_RIGHT_BUTTON), Some(menu));
        gl.glut_destroy_menu(menu);
        assert_eq!(gl.glut_attached_menu(GLUT_RIGHT_BUTTON), None);
        assert_eq!(gl.glut_get_menu(), 0);
        gl.glut_add_menu_entry("after destroy", 1);
        gl.glut_destroy_menu(menu);
    }

    #[test]
    fn a_callback_runs_with_its_menu_current_and_may_change_menus() {
        let mut gl = Gl::new(100, 100);
        let seen = Rc::new(RefCell::new(Vec::new()));
        let log = seen.clone();
        let first = gl.glut_create_menu(move |gl, value| {
            log.borrow_mut().push((gl.glut_get_menu(), value));
            gl.glut_add_menu_entry("added by the callback", 9);
        });
        let second = gl.glut_create_menu(|_, _| {});
        gl.run_menu_callback(first, 4);
        assert_eq!(*seen.borrow(), [(first, 4)]);
        assert_eq!(gl.glut_get_menu(), second);
        assert_eq!(gl.glut.program().menus.get(first).unwrap().items.len(), 1);
        // A callback that destroys its own menu.
        let doomed = gl.glut_create_menu(|gl, _| gl.glut_destroy_menu(3));
        gl.run_menu_callback(doomed, 0);
        assert!(gl.glut.program().menus.get(doomed).is_none());
    }
}
