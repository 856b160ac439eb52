//! The multisample attribute group (GL 1.3 spec §3.2.1 and §4.1.3, `GL_ARB_multisample`; table
//! 6.17; Mesa `main/multisample.c`): `glSampleCoverage` and the enables `GL_MULTISAMPLE`,
//! `GL_SAMPLE_ALPHA_TO_COVERAGE`, `GL_SAMPLE_ALPHA_TO_ONE` and `GL_SAMPLE_COVERAGE`, which
//! `GL_MULTISAMPLE_BIT` saves, with the group's `glGet` rows.
//!
//! Every buffer gleval draws into has one sample (`GL_SAMPLE_BUFFERS` 0, `GL_SAMPLES` 0), and
//! GL 1.3 §3.2.1 says that then multisample rasterisation is off and none of this state changes
//! a fragment; it is kept and answered as GL and Mesa keep it.

use super::consts::*;
use super::lists::ListCommand;
use super::state_var::{int_limit, put, row, Kind, StateVar};
use super::types::*;
use super::Gl;

/// `GL_MULTISAMPLE_BIT`'s state besides its enables: `glSampleCoverage`'s value, clamped to
/// [0, 1], and its invert flag, kept as the byte given (as Mesa keeps it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Multisample {
    pub coverage_value: f32,
    pub coverage_invert: GLboolean,
}

impl Default for Multisample {
    fn default() -> Self {
        Self { coverage_value: 1.0, coverage_invert: GL_FALSE }
    }
}

/// The enables GL files under the group (GL 1.3 table 6.17).
pub(crate) const MULTISAMPLE_ENABLES: &[GLenum] =
    &[GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE];

impl Gl {
    /// `glSampleCoverage` (GL 1.3): the coverage value (clamped to [0, 1]) and whether it is
    /// inverted, which `GL_SAMPLE_COVERAGE` applies to a multisampled buffer's samples.
    pub fn sample_coverage(&mut self, value: GLclampf, invert: GLboolean) {
        if self.compiled_state_call(|| ListCommand::SampleCoverage(value, invert)) {
            return;
        }
        self.server.multisample = Multisample { coverage_value: value.clamp(0.0, 1.0), coverage_invert: invert };
    }
}

/// The group's `glGet` rows, and the buffer's sample counts.
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_SAMPLE_COVERAGE_VALUE, 1, Kind::Float, |gl, o| put(o, &[gl.server.multisample.coverage_value])),
    row(GL_SAMPLE_COVERAGE_INVERT, 1, Kind::Bool, |gl, o| put(o, &[gl.server.multisample.coverage_invert])),
    int_limit!(GL_SAMPLE_BUFFERS, 0),
    int_limit!(GL_SAMPLES, 0),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_group_as_mesa_keeps_it() {
        let mut gl = Gl::new(4, 4);
        assert_eq!(gl.is_enabled(GL_MULTISAMPLE), GL_TRUE);
        gl.push_attrib(GL_MULTISAMPLE_BIT);
        gl.sample_coverage(2.5, 7);
        gl.enable(GL_SAMPLE_ALPHA_TO_COVERAGE);
        gl.disable(GL_MULTISAMPLE);
        let (mut value, mut invert, mut flag) = ([0.0f32], [0u8], [0.0f32]);
        gl.get_floatv(GL_SAMPLE_COVERAGE_VALUE, &mut value);
        gl.get_booleanv(GL_SAMPLE_COVERAGE_INVERT, &mut invert);
        gl.get_floatv(GL_SAMPLE_COVERAGE_INVERT, &mut flag);
        assert_eq!((value, invert, flag), ([1.0], [7], [1.0]));
        gl.pop_attrib();
        assert_eq!(gl.server.multisample, Multisample::default());
        assert_eq!((gl.is_enabled(GL_MULTISAMPLE), gl.is_enabled(GL_SAMPLE_ALPHA_TO_COVERAGE)), (GL_TRUE, GL_FALSE));
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }
}
