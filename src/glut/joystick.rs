//! freeglut's deprecated joystick calls (`glutJoystickGetNumAxes` ... `glutJoystickGetCenter`),
//! answered as freeglut 3.4 answers them on X11 with no joystick plugged in (seen with a probe
//! under Xvfb): two joysticks, each "not working", with 2 axes and 32 buttons, dead band,
//! saturation and ranges 0 until the program sets them, which it may. (freeglut crashes when
//! these are called before anything has set its joysticks up; here they always answer.) An
//! identifier beyond the two, or an axis beyond the two, reads 0 and changes nothing.

use crate::gl::Gl;

/// How many joysticks freeglut keeps, and the axes each has without a device.
const JOYSTICKS: usize = 2;
const AXES: usize = 2;

/// One joystick's settings.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Joystick {
    dead_band: [f32; AXES],
    saturation: [f32; AXES],
    min: [f32; AXES],
    max: [f32; AXES],
    center: [f32; AXES],
}

/// Both joysticks.
pub(crate) type Joysticks = [Joystick; JOYSTICKS];

/// A joystick range: minimum, maximum or centre.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JoystickRange {
    /// `glutJoystickGet/SetMinRange`.
    Min,
    /// `glutJoystickGet/SetMaxRange`.
    Max,
    /// `glutJoystickGet/SetCenter`.
    Center,
}

impl Joystick {
    fn range(&mut self, which: JoystickRange) -> &mut [f32; AXES] {
        match which {
            JoystickRange::Min => &mut self.min,
            JoystickRange::Max => &mut self.max,
            JoystickRange::Center => &mut self.center,
        }
    }
}

impl Gl {
    fn joystick(&mut self, ident: i32) -> Option<std::cell::RefMut<'_, Joystick>> {
        let k = usize::try_from(ident).ok()?;
        std::cell::RefMut::filter_map(self.glut.program_mut(), |p| p.options.joysticks.get_mut(k)).ok()
    }

    /// `glutJoystickGetNumAxes(ident)`: 2 (0 for an identifier beyond the two).
    pub fn glut_joystick_get_num_axes(&mut self, ident: i32) -> i32 {
        if self.joystick(ident).is_some() {
            AXES as i32
        } else {
            0
        }
    }

    /// `glutJoystickGetNumButtons(ident)`: 32.
    pub fn glut_joystick_get_num_buttons(&mut self, ident: i32) -> i32 {
        if self.joystick(ident).is_some() {
            32
        } else {
            0
        }
    }

    /// `glutJoystickNotWorking(ident)`: 1, there is no joystick.
    pub fn glut_joystick_not_working(&mut self, _ident: i32) -> i32 {
        1
    }

    /// `glutJoystickGetDeadBand(ident, axis)`.
    pub fn glut_joystick_get_dead_band(&mut self, ident: i32, axis: i32) -> f32 {
        let axis = usize::try_from(axis).unwrap_or(AXES);
        self.joystick(ident).and_then(|j| j.dead_band.get(axis).copied()).unwrap_or(0.0)
    }

    /// `glutJoystickSetDeadBand(ident, axis, value)`.
    pub fn glut_joystick_set_dead_band(&mut self, ident: i32, axis: i32, value: f32) {
        let axis = usize::try_from(axis).unwrap_or(AXES);
        if let Some(slot) = self.joystick(ident).as_mut().and_then(|j| j.dead_band.get_mut(axis)) {
            *slot = value;
        }
    }

    /// `glutJoystickGetSaturation(ident, axis)`.
    pub fn glut_joystick_get_saturation(&mut self, ident: i32, axis: i32) -> f32 {
        let axis = usize::try_from(axis).unwrap_or(AXES);
        self.joystick(ident).and_then(|j| j.saturation.get(axis).copied()).unwrap_or(0.0)
    }

    /// `glutJoystickSetSaturation(ident, axis, value)`.
    pub fn glut_joystick_set_saturation(&mut self, ident: i32, axis: i32, value: f32) {
        let axis = usize::try_from(axis).unwrap_or(AXES);
        if let Some(slot) = self.joystick(ident).as_mut().and_then(|j| j.saturation.get_mut(axis)) {
            *slot = value;
        }
    }

    /// `glutJoystickGetMinRange`/`MaxRange`/`Center(ident, axes)`: the range's value of each
    /// axis into `axes` (as many as both have).
    pub fn glut_joystick_get_range(&mut self, ident: i32, which: JoystickRange, axes: &mut [f32]) {
        if let Some(mut j) = self.joystick(ident) {
            for (out, value) in axes.iter_mut().zip(j.range(which).iter()) {
                *out = *value;
            }
        }
    }

    /// `glutJoystickSetMinRange`/`MaxRange`/`Center(ident, axes)`: the range's value of each
    /// axis from `axes`.
    pub fn glut_joystick_set_range(&mut self, ident: i32, which: JoystickRange, axes: &[f32]) {
        if let Some(mut j) = self.joystick(ident) {
            for (slot, value) in j.range(which).iter_mut().zip(axes) {
                *slot = *value;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn as_freeglut_answers_without_a_joystick() {
        // Figures from freeglut 3.4 under Xvfb.
        let mut gl = Gl::new(4, 4);
        assert_eq!((gl.glut_joystick_get_num_axes(0), gl.glut_joystick_get_num_buttons(0)), (2, 32));
        assert_eq!(gl.glut_joystick_not_working(0), 1);
        let mut a = [9.0; 3];
        gl.glut_joystick_get_range(0, JoystickRange::Min, &mut a);
        assert_eq!(a, [0.0, 0.0, 9.0]);
        gl.glut_joystick_set_range(0, JoystickRange::Min, &[-5.0, 5.0]);
        gl.glut_joystick_get_range(0, JoystickRange::Min, &mut a);
        assert_eq!(a, [-5.0, 5.0, 9.0]);
        gl.glut_joystick_set_dead_band(0, 1, 0.25);
        assert_eq!(gl.glut_joystick_get_dead_band(0, 1), 0.25);
        assert_eq!(gl.glut_joystick_get_saturation(7, 0), 0.0);
        gl.glut_joystick_set_saturation(-1, 9, 1.0);
    }
}
