//! The attribute stack: `glPushAttrib` / `glPopAttrib` (GL 1.1 spec, "Saving and Restoring
//! State"; Mesa `main/attrib.c`), for the one group GLU saves around its drawing, `GL_EVAL_BIT`
//! (`glcurveval.cc`, `glsurfeval.cc`). Other bits are accepted, as GL accepts any mask, but
//! nothing is saved for them: the stack stays crate-private until their groups are kept.

use super::consts::*;
use super::eval::EvalAttrib;
use super::lists::ListCommand;
use super::types::*;
use super::Gl;

/// Mesa's `MAX_ATTRIB_STACK_DEPTH` (`main/config.h`), GL's minimum.
pub(crate) const MAX_ATTRIB_STACK_DEPTH: usize = 16;

/// What one `glPushAttrib` saved: each group whose bit was set.
#[derive(Clone, Debug)]
struct Saved {
    eval: Option<EvalAttrib>,
}

/// The server attribute stack.
#[derive(Clone, Debug, Default)]
pub(crate) struct AttribStack {
    entries: Vec<Saved>,
}

impl Gl {
    /// `glPushAttrib(mask)`: saves the groups of `mask`. A full stack → `GL_STACK_OVERFLOW`
    /// (nothing is saved); inside `begin`/`end` → `GL_INVALID_OPERATION`.
    pub(crate) fn push_attrib(&mut self, mask: GLbitfield) {
        if self.compiled(|| ListCommand::PushAttrib(mask)) || self.reject_inside_begin_end() {
            return;
        }
        if self.attrib_stack.entries.len() >= MAX_ATTRIB_STACK_DEPTH {
            return self.set_error(GL_STACK_OVERFLOW);
        }
        let eval = (mask & GL_EVAL_BIT != 0).then(|| self.eval.attrib());
        self.attrib_stack.entries.push(Saved { eval });
    }

    /// `glPopAttrib`: restores the groups the matching push saved. An empty stack →
    /// `GL_STACK_UNDERFLOW`; inside `begin`/`end` → `GL_INVALID_OPERATION`.
    pub(crate) fn pop_attrib(&mut self) {
        if self.compiled(|| ListCommand::PopAttrib) || self.reject_inside_begin_end() {
            return;
        }
        let Some(saved) = self.attrib_stack.entries.pop() else {
            return self.set_error(GL_STACK_UNDERFLOW);
        };
        if let Some(eval) = saved.eval {
            self.eval.restore(eval);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid1(gl: &mut Gl) -> [i32; 1] {
        let mut n = [0];
        gl.get_integerv(GL_MAP1_GRID_SEGMENTS, &mut n);
        n
    }

    #[test]
    fn pop_restores_the_eval_group() {
        let mut gl = Gl::new(10, 10);
        gl.push_attrib(GL_EVAL_BIT);
        gl.enable(GL_MAP1_VERTEX_3);
        gl.enable(GL_AUTO_NORMAL);
        gl.map_grid1f(7, 0.0, 1.0);
        gl.pop_attrib();
        assert_eq!(gl.is_enabled(GL_MAP1_VERTEX_3), GL_FALSE);
        assert_eq!(gl.is_enabled(GL_AUTO_NORMAL), GL_FALSE);
        assert_eq!(grid1(&mut gl), [1]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn a_push_without_the_eval_bit_leaves_the_evaluators_alone() {
        let mut gl = Gl::new(10, 10);
        gl.push_attrib(GL_COLOR_BUFFER_BIT);
        gl.map_grid1f(7, 0.0, 1.0);
        gl.pop_attrib();
        assert_eq!(grid1(&mut gl), [7]);
        assert_eq!(gl.get_error(), GL_NO_ERROR);
    }

    #[test]
    fn the_seventeenth_push_overflows_and_saves_nothing() {
        let mut gl = Gl::new(10, 10);
        for _ in 0..MAX_ATTRIB_STACK_DEPTH {
            gl.push_attrib(GL_EVAL_BIT);
        }
        assert_eq!(gl.get_error(), GL_NO_ERROR);
        gl.map_grid1f(5, 0.0, 1.0);
        gl.push_attrib(GL_EVAL_BIT);
        assert_eq!(gl.get_error(), GL_STACK_OVERFLOW);
        gl.map_grid1f(9, 0.0, 1.0);
        // The top entry is the sixteenth push's (grid of one segment), not the refused one's.
        gl.pop_attrib();
        assert_eq!(grid1(&mut gl), [1]);
    }

    #[test]
    fn popping_an_empty_stack_underflows() {
        let mut gl = Gl::new(10, 10);
        gl.pop_attrib();
        assert_eq!(gl.get_error(), GL_STACK_UNDERFLOW);
        gl.push_attrib(GL_EVAL_BIT);
        gl.pop_attrib();
        gl.pop_attrib();
        assert_eq!(gl.get_error(), GL_STACK_UNDERFLOW);
    }

    #[test]
    fn inside_begin_end_both_are_invalid_operations() {
        let mut gl = Gl::new(10, 10);
        gl.begin(GL_POINTS);
        gl.push_attrib(GL_EVAL_BIT);
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.pop_attrib();
        assert_eq!(gl.get_error(), GL_STACK_UNDERFLOW, "the push inside begin/end saved nothing");
        gl.push_attrib(GL_EVAL_BIT);
        gl.begin(GL_POINTS);
        gl.pop_attrib();
        gl.end();
        assert_eq!(gl.get_error(), GL_INVALID_OPERATION);
        gl.pop_attrib();
        assert_eq!(gl.get_error(), GL_NO_ERROR, "the pop inside begin/end left the entry");
    }
}
