//! The evaluator state (GL 1.1 spec §5.1; Mesa `main/eval.c`, `vbo/vbo_exec_eval.c`): the 18
//! maps with their control points, the enables, `GL_AUTO_NORMAL` and the two grids.

mod coord;
mod job;
mod map;
mod mesh;
mod query;
mod target;

pub(crate) use job::PendingMeshes;
pub use job::{MapSample, MeshJob};
pub use target::{MapTarget, Slot};

use super::consts::*;
use super::state_var::{int_limit, put, row, Kind, StateVar};
use super::types::*;
use crate::gl::lists::ListCommand;
pub(crate) use map::Map;

/// A `glMapGrid` grid: `n` segments over [a, b], with the step GL stores (computed in float).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Grid {
    pub n: i32,
    pub a: f32,
    pub b: f32,
    pub step: f32,
}

impl Grid {
    /// Initial grid: one segment over [0, 1]. Mesa leaves the step 0 here (a quirk, spec 1.4);
    /// we use the step the spec implies, 1.
    fn initial() -> Self {
        Self { n: 1, a: 0.0, b: 1.0, step: 1.0 }
    }

    fn new(n: i32, a: f32, b: f32) -> Self {
        Self { n, a, b, step: (b - a) / n as f32 }
    }

    /// The parameter of grid line `i`: exactly `b` at `i == n` (GL's one absolute numeric
    /// requirement, §5.1), `a + i·step` otherwise (also outside 0..=n, extrapolating).
    pub fn param(&self, i: i64) -> f32 {
        if i == i64::from(self.n) {
            self.b
        } else {
            self.a + i as f32 * self.step
        }
    }
}

/// Which map feeds each vertex attribute, after GL's precedence rules (spec 1.2).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct ActiveMaps {
    pub vertex: Option<Slot>,
    pub color: Option<Slot>,
    pub normal: Option<Slot>,
    pub tex: Option<Slot>,
}

/// GL's precedence over the enabled maps `on` (Mesa `vbo_exec_eval_update`): VERTEX_4 over
/// VERTEX_3, the texture map with most coordinates wins, COLOR_4 and NORMAL independent; INDEX
/// never active.
fn active_maps(on: &[bool; Slot::COUNT]) -> ActiveMaps {
    let pick = |slots: &[Slot]| slots.iter().copied().find(|s| on[*s as usize]);
    ActiveMaps {
        vertex: pick(&[Slot::Vertex4, Slot::Vertex3]),
        color: pick(&[Slot::Color4]),
        normal: pick(&[Slot::Normal]),
        tex: pick(&[Slot::TexCoord4, Slot::TexCoord3, Slot::TexCoord2, Slot::TexCoord1]),
    }
}

/// The evaluator part of a GL context.
#[derive(Clone, Debug)]
pub(crate) struct EvalState {
    pub map1: [Map; Slot::COUNT],
    pub map2: [Map; Slot::COUNT],
    enabled1: [bool; Slot::COUNT],
    enabled2: [bool; Slot::COUNT],
    /// [`EvalState::active`] of each dimension, worked out when an enable changes (every
    /// `glEvalCoord` asks for it).
    active: [ActiveMaps; 2],
    pub auto_normal: bool,
    pub grid1: Grid,
    pub grid2: (Grid, Grid),
}

impl Default for EvalState {
    fn default() -> Self {
        Self {
            map1: Slot::ALL.map(|s| Map::initial(s, 1)),
            map2: Slot::ALL.map(|s| Map::initial(s, 2)),
            enabled1: [false; Slot::COUNT],
            enabled2: [false; Slot::COUNT],
            active: [ActiveMaps::default(); 2],
            auto_normal: false,
            grid1: Grid::initial(),
            grid2: (Grid::initial(), Grid::initial()),
        }
    }
}

/// What `glPushAttrib(GL_EVAL_BIT)` saves: enables, `GL_AUTO_NORMAL` and the grids, not the
/// control points (spec 1.11).
#[derive(Clone, Debug)]
pub(crate) struct EvalAttrib {
    enabled1: [bool; Slot::COUNT],
    enabled2: [bool; Slot::COUNT],
    auto_normal: bool,
    grid1: Grid,
    grid2: (Grid, Grid),
}

impl EvalAttrib {
    /// These enables (the maps' and `GL_AUTO_NORMAL`) with `grids`' grids: what popping
    /// `GL_ENABLE_BIT` without `GL_EVAL_BIT` restores.
    pub fn enables_with_grids_of(self, grids: &EvalAttrib) -> Self {
        Self { grid1: grids.grid1, grid2: grids.grid2, ..self }
    }
}

impl EvalState {
    /// The `GL_EVAL_BIT` group.
    pub fn attrib(&self) -> EvalAttrib {
        EvalAttrib {
            enabled1: self.enabled1,
            enabled2: self.enabled2,
            auto_normal: self.auto_normal,
            grid1: self.grid1,
            grid2: self.grid2,
        }
    }

    /// Restores a saved `GL_EVAL_BIT` group.
    pub fn restore(&mut self, a: EvalAttrib) {
        self.enabled1 = a.enabled1;
        self.enabled2 = a.enabled2;
        self.update_active();
        self.auto_normal = a.auto_normal;
        self.grid1 = a.grid1;
        self.grid2 = a.grid2;
    }

    /// `Some(state)` if `cap` is a map target or `GL_AUTO_NORMAL`.
    pub fn is_enabled(&self, cap: GLenum) -> Option<bool> {
        if cap == GL_AUTO_NORMAL {
            return Some(self.auto_normal);
        }
        let t = MapTarget::from_enum(cap)?;
        Some(if t.dims == 1 { self.enabled1[t.slot as usize] } else { self.enabled2[t.slot as usize] })
    }

    /// Sets an evaluator enable; false if `cap` is not one.
    pub fn set_enabled(&mut self, cap: GLenum, on: bool) -> bool {
        if cap == GL_AUTO_NORMAL {
            self.auto_normal = on;
            return true;
        }
        match MapTarget::from_enum(cap) {
            Some(t) if t.dims == 1 => self.enabled1[t.slot as usize] = on,
            Some(t) => self.enabled2[t.slot as usize] = on,
            None => return false,
        }
        self.update_active();
        true
    }

    /// The maps that feed each attribute now (see [`EvalState::active`]).
    pub fn active(&self, dims: u8) -> ActiveMaps {
        self.active[usize::from(dims != 1)]
    }

    fn update_active(&mut self) {
        self.active = [active_maps(&self.enabled1), active_maps(&self.enabled2)];
    }

    /// The map of a given dimension and slot.
    pub fn map(&self, dims: u8, slot: Slot) -> &Map {
        if dims == 1 {
            &self.map1[slot as usize]
        } else {
            &self.map2[slot as usize]
        }
    }
}

/// The grids' `glGet` rows (GL 1.1 table 6.15; the maps themselves through `glGetMap`).
pub(crate) static GET_ROWS: &[StateVar] = &[
    row(GL_MAP1_GRID_DOMAIN, 2, Kind::Float, |gl, o| put(o, &[gl.server.eval.grid1.a, gl.server.eval.grid1.b])),
    row(GL_MAP2_GRID_DOMAIN, 4, Kind::Float, |gl, o| {
        let (u, v) = gl.server.eval.grid2;
        put(o, &[u.a, u.b, v.a, v.b])
    }),
    row(GL_MAP1_GRID_SEGMENTS, 1, Kind::Int, |gl, o| o[0] = f64::from(gl.server.eval.grid1.n)),
    row(GL_MAP2_GRID_SEGMENTS, 2, Kind::Int, |gl, o| put(o, &[gl.server.eval.grid2.0.n, gl.server.eval.grid2.1.n])),
    int_limit!(GL_MAX_EVAL_ORDER, MAX_EVAL_ORDER),
];

/// The evaluator calls as a display list holds them.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum EvalCall {
    Map1 {
        target: GLenum,
        u: (f32, f32),
        stride: i32,
        order: i32,
        points: Vec<f32>,
    },
    Map2 {
        target: GLenum,
        u: (f32, f32),
        ustride: i32,
        uorder: i32,
        v: (f32, f32),
        vstride: i32,
        vorder: i32,
        points: Vec<f32>,
    },
    MapGrid1(i32, f32, f32),
    MapGrid2(i32, f32, f32, i32, f32, f32),
    EvalCoord1(f32),
    EvalCoord2(f32, f32),
    EvalPoint1(i32),
    EvalPoint2(i32, i32),
    EvalMesh1(GLenum, i32, i32),
    EvalMesh2(GLenum, i32, i32, i32, i32),
}

impl super::Gl {
    /// Replays a listed call of the group.
    pub(crate) fn replay_eval_call(&mut self, call: &EvalCall) {
        use EvalCall as C;
        match call {
            C::Map1 { target, u, stride, order, points } => self.map1f(*target, u.0, u.1, *stride, *order, points),
            C::Map2 { target, u, ustride, uorder, v, vstride, vorder, points } => {
                self.map2f(*target, u.0, u.1, *ustride, *uorder, v.0, v.1, *vstride, *vorder, points)
            }
            C::MapGrid1(n, u1, u2) => self.map_grid1f(*n, *u1, *u2),
            C::MapGrid2(un, u1, u2, vn, v1, v2) => self.map_grid2f(*un, *u1, *u2, *vn, *v1, *v2),
            C::EvalCoord1(u) => self.eval_coord1f(*u),
            C::EvalCoord2(u, v) => self.eval_coord2f(*u, *v),
            C::EvalPoint1(i) => self.eval_point1(*i),
            C::EvalPoint2(i, j) => self.eval_point2(*i, *j),
            C::EvalMesh1(mode, i1, i2) => self.eval_mesh1(*mode, *i1, *i2),
            C::EvalMesh2(mode, i1, i2, j1, j2) => self.eval_mesh2(*mode, *i1, *i2, *j1, *j2),
        }
    }
}

impl super::Gl {
    /// `glMapGrid1f`: `un` < 1 → `GL_INVALID_VALUE`. A zero-length or reversed domain is allowed.
    pub fn map_grid1f(&mut self, un: GLint, u1: GLfloat, u2: GLfloat) {
        if self.compiled(|| ListCommand::Eval(EvalCall::MapGrid1(un, u1, u2))) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        if un < 1 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        self.server.eval.grid1 = Grid::new(un, u1, u2);
    }

    /// `glMapGrid1d` (cast to float, as Mesa stores grids).
    pub fn map_grid1d(&mut self, un: GLint, u1: GLdouble, u2: GLdouble) {
        self.map_grid1f(un, u1 as f32, u2 as f32);
    }

    /// `glMapGrid2f`: `un` < 1 or `vn` < 1 → `GL_INVALID_VALUE`.
    pub fn map_grid2f(&mut self, un: GLint, u1: GLfloat, u2: GLfloat, vn: GLint, v1: GLfloat, v2: GLfloat) {
        if self.compiled(|| ListCommand::Eval(EvalCall::MapGrid2(un, u1, u2, vn, v1, v2))) {
            return;
        }
        if self.reject_inside_begin_end() {
            return;
        }
        if un < 1 || vn < 1 {
            self.set_error(GL_INVALID_VALUE);
            return;
        }
        self.server.eval.grid2 = (Grid::new(un, u1, u2), Grid::new(vn, v1, v2));
    }

    /// `glMapGrid2d` (cast to float).
    pub fn map_grid2d(&mut self, un: GLint, u1: GLdouble, u2: GLdouble, vn: GLint, v1: GLdouble, v2: GLdouble) {
        self.map_grid2f(un, u1 as f32, u2 as f32, vn, v1 as f32, v2 as f32);
    }

    /// `glEvalPoint1(i)`: `glEvalCoord1f` at grid line `i` (not range-checked; extrapolates).
    pub fn eval_point1(&mut self, i: GLint) {
        if self.compiled(|| ListCommand::Eval(EvalCall::EvalPoint1(i))) {
            return;
        }
        let u = self.server.eval.grid1.param(i.into());
        self.eval_coord1f(u);
    }

    /// `glEvalPoint2(i, j)`: `glEvalCoord2f` at grid point (i, j).
    pub fn eval_point2(&mut self, i: GLint, j: GLint) {
        if self.compiled(|| ListCommand::Eval(EvalCall::EvalPoint2(i, j))) {
            return;
        }
        let (gu, gv) = self.server.eval.grid2;
        self.eval_coord2f(gu.param(i.into()), gv.param(j.into()));
    }
}
