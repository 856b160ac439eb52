//! The plane geometry of trim loops in (u, v): orientation, areas, segment tests, bounds.

use spade::Point2;

/// A point of the parameter domain, (u, v).
pub(super) type P = [f64; 2];

pub(super) fn midpoint(a: P, b: P) -> P {
    [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
}

pub(super) fn is_finite(p: P) -> bool {
    p[0].is_finite() && p[1].is_finite()
}

/// Spade rejects non-zero coordinates below its minimum; such values are zero for any domain.
pub(super) fn flush(x: f64) -> f64 {
    if x.abs() < spade::MIN_ALLOWED_VALUE {
        0.0
    } else {
        x
    }
}

pub(super) fn point(p: P) -> Point2<f64> {
    Point2::new(p[0], p[1])
}

/// The signed area (positive counter-clockwise), relative to the first point for precision.
pub(super) fn signed_area(points: &[P]) -> f64 {
    let Some(&o) = points.first() else { return 0.0 };
    let n = points.len();
    let twice: f64 = (0..n)
        .map(|i| {
            let (a, b) = (points[i], points[(i + 1) % n]);
            (a[0] - o[0]) * (b[1] - o[1]) - (b[0] - o[0]) * (a[1] - o[1])
        })
        .sum();
    0.5 * twice
}

/// Twice the signed area of triangle abc.
pub(super) fn orient(a: P, b: P, c: P) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Whether the closed segments ab and cd share a point (touching counts).
pub(super) fn segments_meet(a: P, b: P, c: P, d: P) -> bool {
    let (d1, d2, d3, d4) = (orient(c, d, a), orient(c, d, b), orient(a, b, c), orient(a, b, d));
    let opposite = |x: f64, y: f64| (x > 0.0 && y < 0.0) || (x < 0.0 && y > 0.0);
    if opposite(d1, d2) && opposite(d3, d4) {
        return true;
    }
    let on = |p: P, q: P, r: P, o: f64| {
        o == 0.0 && r[0] >= p[0].min(q[0]) && r[0] <= p[0].max(q[0]) && r[1] >= p[1].min(q[1]) && r[1] <= p[1].max(q[1])
    };
    on(c, d, a, d1) || on(c, d, b, d2) || on(a, b, c, d3) || on(a, b, d, d4)
}

/// Whether edge b→c doubles back along edge a→b.
pub(super) fn doubles_back(a: P, b: P, c: P) -> bool {
    orient(a, b, c) == 0.0 && (a[0] - b[0]) * (c[0] - b[0]) + (a[1] - b[1]) * (c[1] - b[1]) > 0.0
}

/// Even-odd point-in-polygon test (ray towards +u).
pub(super) fn inside(points: &[P], p: P) -> bool {
    let mut result = false;
    let n = points.len();
    for i in 0..n {
        let (a, b) = (points[i], points[(i + 1) % n]);
        if (a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]) {
            result = !result;
        }
    }
    result
}

pub(super) fn bbox(points: &[P]) -> [f64; 4] {
    points.iter().fold([f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY], |b, p| {
        [b[0].min(p[0]), b[1].max(p[0]), b[2].min(p[1]), b[3].max(p[1])]
    })
}
