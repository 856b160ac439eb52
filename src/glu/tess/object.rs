//! The tessellator object (`GLUtesselator*`): its properties, its begin/end nesting and the
//! contours it collects, and `gluTessEndPolygon`'s pipeline (GLU's `libtess/tess.c`).
//!
//! Calls out of order are repaired the way GLU repairs them: the missing call is reported
//! through the error callback (`GLU_TESS_MISSING_BEGIN_POLYGON`, ...) and then made, except
//! that a missing `gluTessEndPolygon` discards the polygon. The first contour of up to 100
//! vertices is only cached: if it is the only one and a fan from its first vertex covers it,
//! it is drawn as that fan without the sweep, as GLU does.
//!
//! One deliberate difference: a polygon that needs the sweep and has a NaN coordinate (which
//! crashes GLU's sweep) is reported as `GLU_TESS_COORD_TOO_LARGE` and not drawn.

use super::callbacks::{TessCallbacks, TessData};
use super::mesh::{Mesh, NIL};
use super::normal::project_polygon;
use super::render::{render_boundary, render_cache, render_mesh, CachedVertex, Sink};
use super::sweep::{Sweep, SweepHooks};
use crate::gl::types::GLenum;
use crate::gl::Gl;
use crate::glu::consts::*;
use crate::glu::UserData;

/// A tessellator object (`GLUtesselator*`): a copyable handle into its [`Gl`] context.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct GLUtesselator(pub(crate) usize);

/// Where the object is in the begin/end nesting (`TessState`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum State {
    Dormant,
    InPolygon,
    InContour,
}

/// Vertices of the first contour kept for the quick path (`TESS_MAX_CACHE`).
const MAX_CACHE: usize = 100;

/// The state of one tessellator.
pub(crate) struct TessObject {
    state: State,
    /// `last_edge.org` is the latest vertex of the contour being built.
    last_edge: usize,
    mesh: Option<Mesh>,
    normal: [f64; 3],
    rel_tolerance: f64,
    winding_rule: GLenum,
    boundary_only: bool,
    /// The cached first contour is to go into the mesh at the next vertex.
    empty_cache: bool,
    cache: Vec<CachedVertex>,
    pub callbacks: TessCallbacks,
    polygon_data: Option<UserData>,
}

impl std::fmt::Debug for TessObject {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TessObject")
            .field("state", &self.state)
            .field("winding_rule", &self.winding_rule)
            .field("boundary_only", &self.boundary_only)
            .field("cached", &self.cache.len())
            .finish()
    }
}

/// The callbacks and the context together: where the sweep and the renderer send things.
struct Output<'a> {
    gl: &'a mut Gl,
    cb: &'a mut TessCallbacks,
    data: &'a mut Option<UserData>,
}

impl Sink for Output<'_> {
    fn begin(&mut self, prim: GLenum) {
        self.cb.begin(self.gl, prim, self.data);
    }
    fn edge_flag(&mut self, boundary: bool) {
        self.cb.edge_flag(self.gl, boundary, self.data);
    }
    fn vertex(&mut self, data: Option<&TessData>) {
        self.cb.vertex(self.gl, data, self.data);
    }
    fn end(&mut self) {
        self.cb.end(self.gl, self.data);
    }
}

impl SweepHooks for Output<'_> {
    fn combine(&mut self, coords: [f64; 3], data: [Option<TessData>; 4], weights: [f32; 4]) -> Option<TessData> {
        self.cb.combine(self.gl, coords, data, weights, self.data)
    }
    fn error(&mut self, code: GLenum) {
        self.cb.error(self.gl, code, self.data);
    }
}

impl TessObject {
    /// A new object in GLU's initial state (`gluNewTess`).
    pub fn new() -> Self {
        Self {
            state: State::Dormant,
            last_edge: NIL,
            mesh: None,
            normal: [0.0; 3],
            rel_tolerance: 0.0,
            winding_rule: GLU_TESS_WINDING_ODD,
            boundary_only: false,
            empty_cache: false,
            cache: Vec::new(),
            callbacks: TessCallbacks::default(),
            polygon_data: None,
        }
    }

    /// Reports `code` through the error callback.
    pub fn error(&mut self, gl: &mut Gl, code: GLenum) {
        self.callbacks.error(gl, code, &mut self.polygon_data);
    }

    /// Brings the nesting to `target` one level at a time, reporting each missing call
    /// (`GotoState`).
    fn require_state(&mut self, gl: &mut Gl, target: State) {
        while self.state != target {
            if self.state < target {
                if self.state == State::Dormant {
                    self.error(gl, GLU_TESS_MISSING_BEGIN_POLYGON);
                    self.begin_polygon(gl, None);
                } else {
                    self.error(gl, GLU_TESS_MISSING_BEGIN_CONTOUR);
                    self.begin_contour(gl);
                }
            } else if self.state == State::InContour {
                self.error(gl, GLU_TESS_MISSING_END_CONTOUR);
                self.end_contour(gl);
            } else {
                self.error(gl, GLU_TESS_MISSING_END_POLYGON);
                self.make_dormant();
            }
        }
    }

    /// Drops the polygon being collected (`MakeDormant`).
    fn make_dormant(&mut self) {
        self.mesh = None;
        self.state = State::Dormant;
        self.last_edge = NIL;
    }

    /// `gluDeleteTess`: ends any polygon first, reporting what was missing.
    pub fn delete(&mut self, gl: &mut Gl) {
        self.require_state(gl, State::Dormant);
    }

    /// `gluTessProperty`. An invalid winding rule falls through to `GLU_TESS_BOUNDARY_ONLY`,
    /// as in GLU's `tess.c` (a missing `break`).
    pub fn property(&mut self, gl: &mut Gl, which: GLenum, value: f64) {
        match which {
            GLU_TESS_TOLERANCE => {
                // GLU's test, which lets NaN through.
                if value.is_nan() || (0.0..=1.0).contains(&value) {
                    self.rel_tolerance = value;
                    return;
                }
            }
            GLU_TESS_WINDING_RULE => {
                let rule = value as GLenum;
                if f64::from(rule) == value && (GLU_TESS_WINDING_ODD..=GLU_TESS_WINDING_ABS_GEQ_TWO).contains(&rule) {
                    self.winding_rule = rule;
                    return;
                }
                if f64::from(rule) != value {
                    self.error(gl, GLU_INVALID_VALUE);
                    return;
                }
                self.boundary_only = value != 0.0;
                return;
            }
            GLU_TESS_BOUNDARY_ONLY => {
                self.boundary_only = value != 0.0;
                return;
            }
            _ => {
                self.error(gl, GLU_INVALID_ENUM);
                return;
            }
        }
        self.error(gl, GLU_INVALID_VALUE);
    }

    /// `gluGetTessProperty`: 0 and `GLU_INVALID_ENUM` for an unknown property.
    pub fn get_property(&mut self, gl: &mut Gl, which: GLenum) -> f64 {
        match which {
            GLU_TESS_TOLERANCE => self.rel_tolerance,
            GLU_TESS_WINDING_RULE => f64::from(self.winding_rule),
            GLU_TESS_BOUNDARY_ONLY => f64::from(u8::from(self.boundary_only)),
            _ => {
                self.error(gl, GLU_INVALID_ENUM);
                0.0
            }
        }
    }

    /// `gluTessNormal`.
    pub fn set_normal(&mut self, normal: [f64; 3]) {
        self.normal = normal;
    }

    /// `gluTessBeginPolygon`.
    pub fn begin_polygon(&mut self, gl: &mut Gl, data: Option<UserData>) {
        self.require_state(gl, State::Dormant);
        self.state = State::InPolygon;
        self.cache.clear();
        self.empty_cache = false;
        self.mesh = None;
        self.polygon_data = data;
    }

    /// `gluTessBeginContour`.
    pub fn begin_contour(&mut self, gl: &mut Gl) {
        self.require_state(gl, State::InPolygon);
        self.state = State::InContour;
        self.last_edge = NIL;
        // The cache goes into the mesh only at this contour's first vertex, so that an empty
        // contour (easy to make with `gluNextContour`) does not spoil the quick path.
        if !self.cache.is_empty() {
            self.empty_cache = true;
        }
    }

    /// `gluTessEndContour`.
    pub fn end_contour(&mut self, gl: &mut Gl) {
        self.require_state(gl, State::InContour);
        self.state = State::InPolygon;
    }

    /// Adds a vertex after `last_edge` in the contour being built (`AddVertex`).
    fn add_vertex(mesh: &mut Mesh, last_edge: &mut usize, coords: [f64; 3], data: Option<TessData>) {
        let e = if *last_edge == NIL {
            let e = mesh.make_edge_alone();
            mesh.splice(e, e ^ 1);
            e
        } else {
            mesh.split_edge(*last_edge);
            mesh.lnext(*last_edge)
        };
        let v = mesh.org(e);
        mesh.v[v].data = data;
        mesh.v[v].coords = coords;
        // A counter-clockwise contour adds +1 to the winding number inside it.
        mesh.e[e].winding = 1;
        mesh.e[e ^ 1].winding = -1;
        *last_edge = e;
    }

    /// Moves the cached contour into a new mesh (`EmptyCache`).
    fn empty_cache(&mut self) {
        let mut mesh = Mesh::new();
        for v in std::mem::take(&mut self.cache) {
            Self::add_vertex(&mut mesh, &mut self.last_edge, v.coords, v.data);
        }
        self.mesh = Some(mesh);
        self.empty_cache = false;
    }

    /// `gluTessVertex`: coordinates beyond ±`GLU_TESS_MAX_COORD` are clamped and reported.
    pub fn vertex(&mut self, gl: &mut Gl, coords: [f64; 3], data: Option<TessData>) {
        self.require_state(gl, State::InContour);
        if self.empty_cache {
            self.empty_cache();
            self.last_edge = NIL;
        }
        let mut too_large = false;
        let clamped = coords.map(|x| {
            if x < -GLU_TESS_MAX_COORD {
                too_large = true;
                -GLU_TESS_MAX_COORD
            } else if x > GLU_TESS_MAX_COORD {
                too_large = true;
                GLU_TESS_MAX_COORD
            } else {
                x
            }
        });
        if too_large {
            self.error(gl, GLU_TESS_COORD_TOO_LARGE);
        }
        if self.mesh.is_none() {
            if self.cache.len() < MAX_CACHE {
                self.cache.push(CachedVertex { coords: clamped, data });
                return;
            }
            self.empty_cache();
        }
        if let Some(mesh) = self.mesh.as_mut() {
            Self::add_vertex(mesh, &mut self.last_edge, clamped, data);
        }
    }

    /// `gluTessEndPolygon`: the quick path, or projection, sweep, triangulation (or boundary
    /// extraction) and output.
    pub fn end_polygon(&mut self, gl: &mut Gl) {
        self.require_state(gl, State::InPolygon);
        self.state = State::Dormant;
        let mut out = Output { gl, cb: &mut self.callbacks, data: &mut self.polygon_data };
        if self.mesh.is_none() {
            if !out.cb.flag_boundary
                && render_cache(&self.cache, self.normal, self.winding_rule, self.boundary_only, &mut out)
            {
                self.polygon_data = None;
                return;
            }
            self.empty_cache();
        }
        let Some(mut mesh) = self.mesh.take() else { return };
        let mut out = Output { gl, cb: &mut self.callbacks, data: &mut self.polygon_data };
        project_polygon(&mut mesh, self.normal);
        if !mesh.all_projected_finite() {
            // A NaN coordinate: GLU's sweep crashes on it; gleval reports it and draws nothing.
            out.error(GLU_TESS_COORD_TOO_LARGE);
            self.polygon_data = None;
            return;
        }
        if Sweep::compute_interior(&mut mesh, self.winding_rule, &mut out) {
            if self.boundary_only {
                mesh.set_winding_number(1, true);
            } else {
                mesh.tessellate_interior();
            }
            if out.cb.draws() {
                if self.boundary_only {
                    render_boundary(&mesh, &mut out);
                } else {
                    let flag = out.cb.flag_boundary;
                    render_mesh(&mut mesh, flag, &mut out);
                }
            }
        }
        self.polygon_data = None;
    }
}
