//! The polygon's normal and the projection of its vertices onto the sweep plane (GLU's
//! `libtess/normal.c`).
//!
//! Without a normal from `gluTessNormal`, GLU takes the two vertices farthest apart along the
//! widest axis and the third vertex that makes the largest triangle with them; the projection
//! then drops the normal's largest coordinate (more exact than a true projection), and a
//! computed normal is flipped if needed so that the contours' total signed area is positive.

use super::mesh::{Mesh, F_HEAD, V_HEAD};
use crate::glu::consts::GLU_TESS_MAX_COORD;

fn dot(u: [f64; 3], v: [f64; 3]) -> f64 {
    u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
}

/// The axis of `v`'s largest coordinate (`LongAxis`).
fn long_axis(v: [f64; 3]) -> usize {
    let mut i = 0;
    if v[1].abs() > v[0].abs() {
        i = 1;
    }
    if v[2].abs() > v[i].abs() {
        i = 2;
    }
    i
}

/// The mesh's vertices in list order.
fn vertices(m: &Mesh) -> impl Iterator<Item = usize> + '_ {
    let mut v = V_HEAD;
    std::iter::from_fn(move || {
        v = m.v[v].next;
        (v != V_HEAD).then_some(v)
    })
}

/// A normal of the contours' plane (`ComputeNormal` of `normal.c`).
fn compute_normal(m: &Mesh) -> [f64; 3] {
    let mut max_val = [-2.0 * GLU_TESS_MAX_COORD; 3];
    let mut min_val = [2.0 * GLU_TESS_MAX_COORD; 3];
    let (mut max_vert, mut min_vert) = ([V_HEAD; 3], [V_HEAD; 3]);
    for v in vertices(m) {
        for i in 0..3 {
            let c = m.v[v].coords[i];
            if c < min_val[i] {
                (min_val[i], min_vert[i]) = (c, v);
            }
            if c > max_val[i] {
                (max_val[i], max_vert[i]) = (c, v);
            }
        }
    }
    let mut i = 0;
    if max_val[1] - min_val[1] > max_val[0] - min_val[0] {
        i = 1;
    }
    if max_val[2] - min_val[2] > max_val[i] - min_val[i] {
        i = 2;
    }
    if min_val[i] >= max_val[i] {
        // Every vertex is the same: any normal does.
        return [0.0, 0.0, 1.0];
    }
    let (v1, v2) = (m.v[min_vert[i]].coords, m.v[max_vert[i]].coords);
    let d1 = [v1[0] - v2[0], v1[1] - v2[1], v1[2] - v2[2]];
    let mut max_len2 = 0.0;
    let mut norm = [0.0; 3];
    for v in vertices(m) {
        let c = m.v[v].coords;
        let d2 = [c[0] - v2[0], c[1] - v2[1], c[2] - v2[2]];
        let t = [d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]];
        let len2 = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
        if len2 > max_len2 {
            max_len2 = len2;
            norm = t;
        }
    }
    if max_len2 <= 0.0 {
        // Collinear: any normal perpendicular to the line does.
        norm = [0.0; 3];
        norm[long_axis(d1)] = 1.0;
    }
    norm
}

/// Flips `t` if the contours' total signed area is negative, so that counter-clockwise
/// contours wind +1 (`CheckOrientation`).
fn check_orientation(m: &mut Mesh) {
    let mut area = 0.0;
    let mut f = m.f[F_HEAD].next;
    while f != F_HEAD {
        let start = m.f[f].an_edge;
        if m.e[start].winding > 0 {
            let mut e = start;
            loop {
                let (o, d) = (&m.v[m.org(e)], &m.v[m.dst(e)]);
                area += (o.s - d.s) * (o.t + d.t);
                e = m.lnext(e);
                if e == start {
                    break;
                }
            }
        }
        f = m.f[f].next;
    }
    if area < 0.0 {
        let all: Vec<usize> = vertices(m).collect();
        for v in all {
            m.v[v].t = -m.v[v].t;
        }
    }
}

impl Mesh {
    /// Whether every vertex projected to finite `(s, t)` (false after a NaN coordinate).
    pub(crate) fn all_projected_finite(&self) -> bool {
        vertices(self).all(|v| self.v[v].s.is_finite() && self.v[v].t.is_finite())
    }
}

/// Projects every vertex to `(s, t)` (`__gl_projectPolygon`), with `normal` from
/// `gluTessNormal` or computed when it is zero.
pub(crate) fn project_polygon(m: &mut Mesh, normal: [f64; 3]) {
    let computed = normal == [0.0; 3];
    let norm = if computed { compute_normal(m) } else { normal };
    let i = long_axis(norm);
    // libtess's S_UNIT_X = 1, S_UNIT_Y = 0: project along the axis, keeping right-handedness.
    let (sx, sy) = (1.0, 0.0);
    let mut s_unit = [0.0; 3];
    let mut t_unit = [0.0; 3];
    s_unit[(i + 1) % 3] = sx;
    s_unit[(i + 2) % 3] = sy;
    t_unit[(i + 1) % 3] = if norm[i] > 0.0 { -sy } else { sy };
    t_unit[(i + 2) % 3] = if norm[i] > 0.0 { sx } else { -sx };
    let all: Vec<usize> = vertices(m).collect();
    for v in all {
        let c = m.v[v].coords;
        m.v[v].s = dot(c, s_unit);
        m.v[v].t = dot(c, t_unit);
    }
    if computed {
        check_orientation(m);
    }
}
