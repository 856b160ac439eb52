//! A GLUT menu on the screen: where it opens, which item the pointer is on, what a click or a
//! release chooses, and how it looks, drawn with GL calls on a context of its own over the
//! program's last frame (the program's GL state is never touched, as freeglut's menus live in
//! windows of their own).
//!
//! How it behaves, as GLUT's menus do: pressing the attached button opens the menu at the
//! pointer; moving highlights the item under it and opens a sub-menu beside its item; releasing
//! on an entry chooses it (the menu's callback runs with its value). Releasing where it was
//! pressed leaves the menu open, and a later click on an entry chooses it; a click outside, a
//! release elsewhere after a drag, or Escape closes it.
//!
//! How it looks (freeglut's menu colours): light grey items with black Helvetica 18 text, the
//! highlighted item dark blue with white text, a dark frame, a small arrow at the right of an
//! item that opens a sub-menu.

use super::menu::{MenuItem, Menus};
use crate::gl::consts::*;
use crate::gl::{Frame, Gl};

/// The frame around a menu, in pixels.
const BORDER: i32 = 2;
/// Space left and right of a label.
const PAD: i32 = 8;
/// Extra width of a menu with sub-menu items, for the arrow.
const ARROW_ROOM: i32 = 16;
/// A drag shorter than this (pixels) is a click: the release leaves the menu open.
const CLICK_SLOP: i32 = 3;

const BACKGROUND: [f32; 3] = [0.85, 0.85, 0.85];
const TEXT: [f32; 3] = [0.0, 0.0, 0.0];
const HIGHLIGHT: [f32; 3] = [0.15, 0.15, 0.45];
const HIGHLIGHT_TEXT: [f32; 3] = [1.0, 1.0, 1.0];
const FRAME: [f32; 3] = [0.35, 0.35, 0.35];

/// One menu shown: which, where (window pixels, origin top left) and the item highlighted.
#[derive(Clone, Debug, PartialEq)]
struct Shown {
    menu: i32,
    x: i32,
    y: i32,
    width: i32,
    items: usize,
    highlight: Option<usize>,
}

impl Shown {
    fn height(&self, item_height: i32) -> i32 {
        self.items as i32 * item_height + 2 * BORDER
    }

    /// The item at (x, y), if the point is on this menu's items.
    fn item_at(&self, x: i32, y: i32, item_height: i32) -> Option<usize> {
        let inside = x >= self.x && x < self.x + self.width && y >= self.y + BORDER;
        let row = (y - self.y - BORDER).div_euclid(item_height);
        (inside && row >= 0 && (row as usize) < self.items).then_some(row as usize)
    }

    fn contains(&self, x: i32, y: i32, item_height: i32) -> bool {
        x >= self.x && x < self.x + self.width && y >= self.y && y < self.y + self.height(item_height)
    }
}

/// What a pointer event did to an open menu.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum PopupEvent {
    /// Still open (perhaps with another item highlighted).
    Open,
    /// Closed without a choice.
    Closed,
    /// Closed with the entry `value` of `menu` chosen.
    Chosen { menu: i32, value: i32 },
}

/// An open menu and its open sub-menus, outermost first.
#[derive(Debug)]
pub(crate) struct Popup {
    shown: Vec<Shown>,
    window: (i32, i32),
    item_height: i32,
    /// Where the button that opened it went down.
    pressed_at: (i32, i32),
    /// The pointer moved away from there since: a release then chooses or closes.
    dragged: bool,
}

impl Popup {
    /// Opens `menu` with its top left corner at the pointer (moved in to fit the window).
    pub(crate) fn open(gl: &Gl, menu: i32, x: i32, y: i32, window: (i32, i32)) -> Option<Self> {
        let font = gl.glut.program().menus.font(menu);
        let item_height = gl.glut_bitmap_height(font) + 4;
        let mut popup = Self { shown: Vec::new(), window, item_height, pressed_at: (x, y), dragged: false };
        let shown = popup.place(gl, menu, x, y)?;
        popup.shown.push(shown);
        Some(popup)
    }

    /// A menu laid out at (x, y), moved left and up as far as needed to be inside the window.
    fn place(&self, gl: &Gl, menu: i32, x: i32, y: i32) -> Option<Shown> {
        let program = gl.glut.program();
        let items = &program.menus.get(menu)?.items;
        let font = program.menus.font(menu);
        let widest = items.iter().map(|i| gl.glut_bitmap_length(font, i.label())).max();
        let arrow = if items.iter().any(|i| matches!(i, MenuItem::SubMenu { .. })) { ARROW_ROOM } else { 0 };
        let width = widest.unwrap_or(0) + 2 * PAD + arrow + 2 * BORDER;
        let mut shown = Shown { menu, x, y, width, items: items.len(), highlight: None };
        let height = shown.height(self.item_height);
        shown.x = x.min(self.window.0 - width).max(0);
        shown.y = y.min(self.window.1 - height).max(0);
        Some(shown)
    }

    /// The innermost menu level and item under the pointer.
    fn hit(&self, x: i32, y: i32) -> Option<(usize, usize)> {
        let h = self.item_height;
        self.shown.iter().enumerate().rev().find_map(|(level, s)| s.item_at(x, y, h).map(|item| (level, item)))
    }

    fn over_any(&self, x: i32, y: i32) -> bool {
        self.shown.iter().any(|s| s.contains(x, y, self.item_height))
    }

    /// The pointer moved: highlight the item under it and open its sub-menu, if it has one.
    /// Returns whether what is shown changed.
    pub(crate) fn hover(&mut self, gl: &Gl, x: i32, y: i32) -> bool {
        let (px, py) = self.pressed_at;
        if (x - px).abs() > CLICK_SLOP || (y - py).abs() > CLICK_SLOP {
            self.dragged = true;
        }
        let before = self.shown.clone();
        match self.hit(x, y) {
            Some((level, item)) => {
                self.shown.truncate(level + 1);
                let shown = &mut self.shown[level];
                shown.highlight = Some(item);
                let (right, top) = (shown.x + shown.width - BORDER, shown.y + BORDER + item as i32 * self.item_height);
                let sub_menu = match gl.glut.program().menus.get(shown.menu).and_then(|m| m.items.get(item)) {
                    Some(MenuItem::SubMenu { menu, .. }) => Some(*menu),
                    _ => None,
                };
                let sub = sub_menu.and_then(|menu| self.place(gl, menu, right, top - BORDER));
                self.shown.extend(sub);
            }
            // Off the menus: an open sub-menu stays (with its item lit); otherwise nothing is lit.
            None => {
                if let Some(last) = self.shown.last_mut() {
                    last.highlight = None;
                }
            }
        }
        self.shown != before
    }

    /// A mouse button went down while the menu is open: outside it, the menu closes.
    pub(crate) fn press(&mut self, x: i32, y: i32) -> PopupEvent {
        self.dragged = true;
        if self.over_any(x, y) {
            PopupEvent::Open
        } else {
            PopupEvent::Closed
        }
    }

    /// A mouse button came up: on an entry it is chosen; where the menu was opened (a click)
    /// or on a sub-menu's item the menu stays; elsewhere it closes.
    pub(crate) fn release(&mut self, menus: &Menus, x: i32, y: i32) -> PopupEvent {
        if let Some((level, item)) = self.hit(x, y) {
            let menu = self.shown[level].menu;
            return match menus.get(menu).and_then(|m| m.items.get(item)) {
                Some(MenuItem::Entry { value, .. }) => PopupEvent::Chosen { menu, value: *value },
                Some(MenuItem::SubMenu { .. }) => PopupEvent::Open,
                None => PopupEvent::Closed,
            };
        }
        if self.dragged {
            PopupEvent::Closed
        } else {
            self.dragged = true;
            PopupEvent::Open
        }
    }

    /// The menus as a frame to draw over the program's: GL calls on a context of their own,
    /// with window pixels (origin top left) as coordinates.
    pub(crate) fn overlay(&self, gl: &Gl) -> Frame {
        let (width, height) = self.window;
        let mut overlay = Gl::new(width, height);
        overlay.matrix_mode(GL_PROJECTION);
        overlay.ortho(0.0, f64::from(width), f64::from(height), 0.0, -1.0, 1.0);
        overlay.matrix_mode(GL_MODELVIEW);
        for shown in &self.shown {
            let program = gl.glut.program();
            if let Some(menu) = program.menus.get(shown.menu) {
                self.draw_menu(&mut overlay, shown, &menu.items, program.menus.font(shown.menu));
            }
        }
        overlay.take_frame()
    }

    fn draw_menu(&self, gl: &mut Gl, shown: &Shown, items: &[MenuItem], font: crate::glut::fonts::GlutBitmapFont) {
        let (x, y, w, h) = (shown.x as f32, shown.y as f32, shown.width as f32, shown.height(self.item_height) as f32);
        let border = BORDER as f32;
        gl.color3fv(&FRAME);
        gl.rectf(x, y, x + w, y + h);
        gl.color3fv(&BACKGROUND);
        gl.rectf(x + border, y + border, x + w - border, y + h - border);
        for (row, item) in items.iter().enumerate() {
            let top = shown.y + BORDER + row as i32 * self.item_height;
            let lit = shown.highlight == Some(row);
            if lit {
                gl.color3fv(&HIGHLIGHT);
                gl.rectf(x + border, top as f32, x + w - border, (top + self.item_height) as f32);
            }
            let ink = if lit { HIGHLIGHT_TEXT } else { TEXT };
            gl.color3fv(&ink);
            // The baseline sits 6 pixels above the item's bottom (Helvetica 18 descends 4).
            gl.raster_pos2i(shown.x + BORDER + PAD, top + self.item_height - 6);
            gl.glut_bitmap_string(font, item.label());
            if matches!(item, MenuItem::SubMenu { .. }) {
                let (right, middle) =
                    ((shown.x + shown.width - BORDER - PAD) as f32, top as f32 + 0.5 * self.item_height as f32);
                gl.begin(GL_TRIANGLES);
                gl.vertex2f(right - 7.0, middle - 5.0);
                gl.vertex2f(right - 7.0, middle + 5.0);
                gl.vertex2f(right, middle);
                gl.end();
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A main menu of two entries and a sub-menu item, and a sub-menu of two entries.
    fn menus() -> (Gl, i32, i32) {
        let mut gl = Gl::new(400, 300);
        let sub = gl.glut_create_menu(|_, _| {});
        gl.glut_add_menu_entry("Red", 10);
        gl.glut_add_menu_entry("Green", 11);
        let main = gl.glut_create_menu(|_, _| {});
        gl.glut_add_menu_entry("Fill", 1);
        gl.glut_add_menu_entry("Outline polygon", 2);
        gl.glut_add_sub_menu("Colour", sub);
        (gl, main, sub)
    }

    /// The centre of item `row` of the menu shown at `level`.
    fn centre(popup: &Popup, level: usize, row: usize) -> (i32, i32) {
        let s = &popup.shown[level];
        (s.x + s.width / 2, s.y + BORDER + row as i32 * popup.item_height + popup.item_height / 2)
    }

    #[test]
    fn a_drag_to_an_entry_and_a_release_chooses_it() {
        let (gl, main, _) = menus();
        let mut popup = Popup::open(&gl, main, 50, 40, (400, 300)).unwrap();
        assert_eq!((popup.shown[0].x, popup.shown[0].y), (50, 40));
        let (x, y) = centre(&popup, 0, 1);
        assert!(popup.hover(&gl, x, y));
        assert_eq!(popup.shown[0].highlight, Some(1));
        assert_eq!(popup.release(&gl.glut.program().menus, x, y), PopupEvent::Chosen { menu: main, value: 2 });
    }

    #[test]
    fn a_click_leaves_it_open_and_a_second_click_chooses() {
        let (gl, main, sub) = menus();
        let mut popup = Popup::open(&gl, main, 50, 40, (400, 300)).unwrap();
        // Released where it was pressed (on the menu's frame corner, no item): stays open.
        assert_eq!(popup.release(&gl.glut.program().menus, 50, 40), PopupEvent::Open);
        // Over the sub-menu item: the sub-menu opens beside it.
        let (x, y) = centre(&popup, 0, 2);
        popup.hover(&gl, x, y);
        assert_eq!(popup.shown.len(), 2);
        assert_eq!(popup.shown[1].menu, sub);
        assert!(popup.shown[1].x >= popup.shown[0].x + popup.shown[0].width - BORDER);
        let (x, y) = centre(&popup, 1, 1);
        popup.hover(&gl, x, y);
        assert_eq!(popup.press(x, y), PopupEvent::Open);
        assert_eq!(popup.release(&gl.glut.program().menus, x, y), PopupEvent::Chosen { menu: sub, value: 11 });
    }

    #[test]
    fn outside_it_closes_and_it_opens_inside_the_window() {
        let (gl, main, _) = menus();
        let mut popup = Popup::open(&gl, main, 390, 290, (400, 300)).unwrap();
        let s = &popup.shown[0];
        assert_eq!((s.x + s.width, s.y + s.height(popup.item_height)), (400, 300));
        assert_eq!(popup.press(5, 5), PopupEvent::Closed);
        let mut popup = Popup::open(&gl, main, 10, 10, (400, 300)).unwrap();
        popup.hover(&gl, 300, 250);
        assert_eq!(popup.release(&gl.glut.program().menus, 300, 250), PopupEvent::Closed);
        assert!(Popup::open(&gl, 99, 0, 0, (400, 300)).is_none());
    }

    #[test]
    fn leaving_the_sub_menu_item_for_another_closes_the_sub_menu() {
        let (gl, main, _) = menus();
        let mut popup = Popup::open(&gl, main, 20, 20, (400, 300)).unwrap();
        let (x, y) = centre(&popup, 0, 2);
        popup.hover(&gl, x, y);
        assert_eq!(popup.shown.len(), 2);
        let (x, y) = centre(&popup, 0, 0);
        popup.hover(&gl, x, y);
        assert_eq!(popup.shown.len(), 1);
        assert_eq!(popup.shown[0].highlight, Some(0));
    }

    #[test]
    fn the_overlay_draws_the_frame_items_and_labels() {
        let (gl, main, _) = menus();
        let mut popup = Popup::open(&gl, main, 20, 20, (400, 300)).unwrap();
        let (x, y) = centre(&popup, 0, 2);
        popup.hover(&gl, x, y);
        let frame = popup.overlay(&gl);
        assert!(!frame.primitives.is_empty());
        // No clear: the program's picture stays under the menus.
        assert!(!frame.commands.iter().any(|c| matches!(c, crate::gl::Command::Clear { .. })));
    }
}
