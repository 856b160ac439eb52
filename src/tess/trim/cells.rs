//! The band along the trim loops triangulated cell by cell, as GLU's slicer meets its grid: each
//! grid cell the loops pass through is clipped against them (the loop pieces inside the cell
//! joined by runs of the cell's boundary), and each piece is ear-clipped. Linear in the band's
//! size, with no global triangulation; loop edges gain a vertex wherever they cross a grid line
//! and grid points next to the loops are kept, however close.
//!
//! Points exactly on grid lines are decided by one rule everywhere: a point on a u line counts
//! as right of it, on a v line as above it, as if the lines sat an infinitesimal ε (u) and ε²
//! (v) lower. That fixes the cell of every point, the order of crossings that coincide, and the
//! order of crossings at one point along a cell's side. Whatever the rule cannot settle (a loop
//! inside one cell, an inconsistent walk, a piece that does not clip) returns `None`, and so does
//! a result whose area differs from the loops' shoelace area: the caller then uses the
//! constrained Delaunay triangulation.

use super::band::Band;
use super::geometry::{orient, signed_area, P};
use super::lattice::{count_at_most, count_below, LatticeLines};
use super::mesh::GridStrip;

/// A point's place on a cell's boundary, counter-clockwise from the bottom-left corner: the side
/// (0 bottom, 1 right, 2 top, 3 left), the coordinate along it increasing counter-clockwise, and
/// the infinitesimal offset that orders crossings at one point (corners: −∞, first).
type Key = (u8, f64, f64);

fn key_less(a: &Key, b: &Key) -> bool {
    a.partial_cmp(b) == Some(std::cmp::Ordering::Less)
}

fn key_order(a: &Key, b: &Key) -> std::cmp::Ordering {
    a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal)
}

/// A crossing of a loop edge with an interior grid line.
#[derive(Clone, Copy, Debug)]
struct Crossing {
    /// Edge parameter in [0, 1].
    t: f64,
    /// A u line (the loop moves right or left) or a v line (up or down).
    across_u: bool,
    /// +1 right/up, −1 left/down.
    step: i8,
    point: P,
    /// The edge's direction.
    dir: P,
}

impl Crossing {
    /// Its place on the side of the cell it leaves.
    fn exit_key(&self) -> Key {
        let [du, dv] = self.dir;
        let [u, v] = self.point;
        match (self.across_u, self.step > 0) {
            (true, true) => (1, v, -dv / du),
            (true, false) => (3, -v, dv / du),
            (false, true) => (2, -u, du / dv),
            (false, false) => (0, u, -du / dv),
        }
    }

    /// Its place on the side of the cell it enters.
    fn entry_key(&self) -> Key {
        let [du, dv] = self.dir;
        let [u, v] = self.point;
        match (self.across_u, self.step > 0) {
            (true, true) => (3, -v, dv / du),
            (true, false) => (1, v, -dv / du),
            (false, true) => (0, u, -du / dv),
            (false, false) => (2, -u, du / dv),
        }
    }

    /// Whether this comes before `other` on the same edge: by t, and at equal t a u crossing
    /// moving right precedes, one moving left follows (the ε-lower lines).
    fn before(&self, other: &Self) -> bool {
        if self.t != other.t {
            return self.t < other.t;
        }
        if self.across_u == other.across_u {
            return false;
        }
        let (u, _) = if self.across_u { (self, other) } else { (other, self) };
        (u.step > 0) == self.across_u
    }
}

/// The loop pieces of one cell: mesh point ids from the entry crossing to the exit crossing.
struct Fragment {
    cell: usize,
    entry: Key,
    exit: Key,
    ids: std::ops::Range<usize>,
}

/// Mesh points beyond the grid points: crossings, loop vertices, grid points not retained.
struct Points<'a> {
    band: &'a Band,
    nu: usize,
    first: usize,
    extra: Vec<P>,
    lattice_extra: std::collections::HashMap<usize, u32>,
}

impl Points<'_> {
    fn position(&self, id: u32) -> P {
        let id = id as usize;
        if id < self.first {
            self.band.grid_points[id]
        } else {
            self.extra[id - self.first]
        }
    }

    fn push(&mut self, p: P) -> u32 {
        self.extra.push(p);
        (self.first + self.extra.len() - 1) as u32
    }

    /// The id of grid point (i, j).
    fn lattice(&mut self, grid: &LatticeLines, i: usize, j: usize) -> u32 {
        let k = j * self.nu + i;
        match self.band.mesh_index[k] {
            u32::MAX => {
                if let Some(&id) = self.lattice_extra.get(&k) {
                    return id;
                }
                let id = self.push([grid.u[i], grid.v[j]]);
                self.lattice_extra.insert(k, id);
                id
            }
            id => id,
        }
    }

    /// The id of a point on the loops: the grid point's when it is one.
    fn on_loop(&mut self, grid: &LatticeLines, p: P) -> u32 {
        // The line equal to x, if any.
        let find = |lines: &[f64], x: f64| count_at_most(lines, x).checked_sub(1).filter(|&i| lines[i] == x);
        match (find(&grid.u, p[0]), find(&grid.v, p[1])) {
            (Some(i), Some(j)) => self.lattice(grid, i, j),
            _ => self.push(p),
        }
    }
}

/// Coordinates this close to a grid line, relative to the spacing there, are put on it: a
/// vertex or crossing a rounding error away from a line or grid point would leave triangles
/// thinner than rounding, whose side of the loop no test can tell.
const SNAP: f64 = 1e-12;

/// x, or the grid line within [`SNAP`] spacings of it.
fn snap(lines: &[f64], x: f64) -> f64 {
    let k = count_below(lines, x);
    for i in [k.wrapping_sub(1), k] {
        let (Some(&line), Some(spacing)) = (lines.get(i), spacing(lines, i)) else { continue };
        if (x - line).abs() <= SNAP * spacing {
            return line;
        }
    }
    x
}

/// The smaller of the spacings on either side of line i.
fn spacing(lines: &[f64], i: usize) -> Option<f64> {
    let below = i.checked_sub(1).and_then(|h| Some(lines.get(i)? - lines.get(h)?));
    // i is usize::MAX for "below the first line" (snap's k - 1 at k = 0).
    let above = i.checked_add(1).and_then(|j| lines.get(j)).and_then(|&next| Some(next - lines.get(i)?));
    match (below, above) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// The cell of p under the half-open rule (clamped into the grid).
fn cell_of(grid: &LatticeLines, p: P) -> (usize, usize) {
    let index = |lines: &[f64], x: f64| count_at_most(lines, x).saturating_sub(1).min(lines.len() - 2);
    (index(&grid.u, p[0]), index(&grid.v, p[1]))
}

/// The crossings of edge a→b with the interior grid lines, in order along the edge
/// (`by_axis` holds each axis's crossings on the way).
fn crossings(grid: &LatticeLines, a: P, b: P, out: &mut Vec<Crossing>, by_axis: &mut [Vec<Crossing>; 2]) {
    let dir = [b[0] - a[0], b[1] - a[1]];
    for (axis, lines) in [(0, &grid.u), (1, &grid.v)] {
        let found = &mut by_axis[axis];
        found.clear();
        let interior = &lines[1..lines.len() - 1];
        let (lo, hi) = (a[axis].min(b[axis]), a[axis].max(b[axis]));
        // Sides differ (x ≥ line counts as the upper side): lo < line ≤ hi.
        let first = count_at_most(interior, lo);
        let last = count_at_most(interior, hi);
        let crossed = &interior[first..last];
        // In the order the edge meets them, so that each axis's list is sorted along the edge.
        let lines: Box<dyn Iterator<Item = &f64>> =
            if dir[axis] > 0.0 { Box::new(crossed.iter()) } else { Box::new(crossed.iter().rev()) };
        for &line in lines {
            let t = (line - a[axis]) / dir[axis];
            let point = if line == a[axis] {
                a
            } else if line == b[axis] {
                b
            } else {
                let other = 1 - axis;
                let lo_o = a[other].min(b[other]);
                let hi_o = a[other].max(b[other]);
                let mut p = [0.0; 2];
                p[axis] = line;
                let other_lines = if other == 0 { &grid.u } else { &grid.v };
                p[other] = snap(other_lines, (a[other] + t * dir[other]).clamp(lo_o, hi_o));
                p
            };
            let step = if dir[axis] > 0.0 { 1 } else { -1 };
            found.push(Crossing { t, across_u: axis == 0, step, point, dir });
        }
    }
    // Both lists merged along the edge; on a tie (neither before the other) the u crossing
    // first, as a stable sort of the u crossings followed by the v crossings orders them.
    out.clear();
    let [us, vs] = &*by_axis;
    let (mut i, mut j) = (0, 0);
    while i < us.len() || j < vs.len() {
        if i < us.len() && (j == vs.len() || !vs[j].before(&us[i])) {
            out.push(us[i]);
            i += 1;
        } else {
            out.push(vs[j]);
            j += 1;
        }
    }
}

/// Triangulates the band cell by cell. Returns the extra points (ids from
/// `band.grid_points.len()` on) and the band's counter-clockwise triangles, or `None` where the
/// constrained triangulation must do it.
pub(super) fn triangulate_cells(
    band: &Band,
    grid: &LatticeLines,
    loops: &[Vec<P>],
    kept: &[bool],
    strips: &[GridStrip],
) -> Option<(Vec<P>, Vec<[u32; 3]>)> {
    let loops: Vec<Vec<P>> =
        loops.iter().map(|l| l.iter().map(|p| [snap(&grid.u, p[0]), snap(&grid.v, p[1])]).collect()).collect();
    let loops = &loops[..];
    let domain_area = (grid.u[grid.u.len() - 1] - grid.u[0]) * (grid.v[grid.v.len() - 1] - grid.v[0]);
    let expected_area =
        if band.inside_domain { domain_area } else { 0.0 } + loops.iter().map(|l| signed_area(l)).sum::<f64>();
    let nu = grid.u.len();
    let cu = nu - 1;
    let mut points =
        Points { band, nu, first: band.grid_points.len(), extra: Vec::new(), lattice_extra: Default::default() };
    let (fragments, ids) = fragments(grid, loops, &mut points)?;
    // Fragments by cell.
    let mut order: Vec<usize> = (0..fragments.len()).collect();
    order.sort_by_key(|&f| fragments[f].cell);
    let mut triangles = Vec::new();
    let mut has_fragments = vec![false; band.clean.len()];
    let (mut polygon, mut entries, mut visited, mut passed) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for group in order.chunk_by(|&a, &b| fragments[a].cell == fragments[b].cell) {
        let cell = fragments[group[0]].cell;
        has_fragments[cell] = true;
        let (ci, cj) = (cell % cu, cell / cu);
        // The corners, each at the start of its side; grid points (i, j), given ids when used.
        let corners: [(Key, (usize, usize)); 4] = [
            ((0, grid.u[ci], f64::NEG_INFINITY), (ci, cj)),
            ((1, grid.v[cj], f64::NEG_INFINITY), (ci + 1, cj)),
            ((2, -grid.u[ci + 1], f64::NEG_INFINITY), (ci + 1, cj + 1)),
            ((3, -grid.v[cj + 1], f64::NEG_INFINITY), (ci, cj + 1)),
        ];
        entries.clear();
        entries.extend_from_slice(group);
        entries.sort_by(|&a, &b| key_order(&fragments[a].entry, &fragments[b].entry));
        visited.clear();
        visited.resize(entries.len(), false);
        for start in 0..entries.len() {
            if visited[start] {
                continue;
            }
            polygon.clear();
            let mut at = start;
            loop {
                if visited[at] {
                    return None;
                }
                visited[at] = true;
                let f = &fragments[entries[at]];
                polygon.extend_from_slice(&ids[f.ids.clone()]);
                // The next entry counter-clockwise after the exit (entries are sorted), and the
                // corners passed on the way.
                let next = (0..entries.len()).find(|&k| key_less(&f.exit, &fragments[entries[k]].entry));
                let wrapped = next.is_none();
                let next = next.unwrap_or(0);
                let next_entry = fragments[entries[next]].entry;
                passed.clear();
                if wrapped {
                    let after = corners.iter().filter(|(key, _)| key_less(&f.exit, key));
                    let before = corners.iter().filter(|(key, _)| key_less(key, &next_entry));
                    passed.extend(after.chain(before).map(|&(_, ij)| ij));
                } else {
                    let between =
                        corners.iter().filter(|(key, _)| key_less(&f.exit, key) && key_less(key, &next_entry));
                    passed.extend(between.map(|&(_, ij)| ij));
                }
                for &(i, j) in &passed {
                    polygon.push(points.lattice(grid, i, j));
                }
                at = next;
                if at == start {
                    break;
                }
            }
            if has_pinch(&polygon, &points) {
                for mut piece in split_pinches(&polygon, &points) {
                    clip_ears(&mut piece, &points, &mut triangles)?;
                }
            } else {
                clip_ears(&mut polygon, &points, &mut triangles)?;
            }
        }
    }
    // Band cells no loop passes through: wholly inside or outside, as a retained corner says.
    // This runs over every cell, and finds few: each row's flags are computed without branches
    // (so that the loop vectorises) and only a row with a flag set is visited.
    let rows = band.clean.chunks_exact(cu).zip(has_fragments.chunks_exact(cu));
    let mut flags = vec![false; cu];
    for (cj, (clean, loops_in)) in rows.enumerate() {
        let (below, above) = (&kept[cj * nu..(cj + 1) * nu], &kept[(cj + 1) * nu..(cj + 2) * nu]);
        let corners = below[..cu].iter().zip(&below[1..]).zip(above[..cu].iter().zip(&above[1..]));
        for ((flag, (&clean, &loops_in)), ((&a, &b), (&c, &d))) in
            flags.iter_mut().zip(clean.iter().zip(loops_in)).zip(corners)
        {
            *flag = !clean & !loops_in & (a | b | c | d);
        }
        if !flags.iter().fold(false, |any, &f| any | f) {
            continue;
        }
        for ci in (0..cu).filter(|&ci| flags[ci]) {
            let [a, b, c, d] =
                [(ci, cj), (ci + 1, cj), (ci + 1, cj + 1), (ci, cj + 1)].map(|(i, j)| points.lattice(grid, i, j));
            triangles.push([a, b, c]);
            triangles.push([a, c, d]);
        }
    }
    // The clean cells' area, run by run.
    let clean_area: f64 = strips
        .iter()
        .map(|s| {
            let (bottom, top) = (band.grid_points[s.bottom as usize], band.grid_points[s.top as usize]);
            let right = band.grid_points[(s.bottom + s.cells) as usize];
            (right[0] - bottom[0]) * (top[1] - bottom[1])
        })
        .sum();
    // The safety net: the triangles and the clean cells cover exactly the loops' area.
    let band_area: f64 = triangles
        .iter()
        .map(|t| 0.5 * orient(points.position(t[0]), points.position(t[1]), points.position(t[2])))
        .sum();
    if (band_area + clean_area - expected_area).abs() > 1e-9 * domain_area {
        return None;
    }
    Some((points.extra, triangles))
}

/// Every loop cut into its pieces per cell; `None` for a loop that crosses no grid line or a
/// vertex found outside the cell the walk is in.
fn fragments(grid: &LatticeLines, loops: &[Vec<P>], points: &mut Points) -> Option<(Vec<Fragment>, Vec<u32>)> {
    /// The loop as vertices and crossings (with their mesh ids), edge by edge.
    enum Item {
        Vertex(usize),
        Cross(Crossing, u32),
    }
    let mut fragments = Vec::new();
    let mut ids: Vec<u32> = Vec::new();
    let (mut cuts, mut by_axis) = (Vec::new(), [Vec::new(), Vec::new()]);
    let (cu, cv) = (grid.u.len() - 1, grid.v.len() - 1);
    for l in loops {
        let n = l.len();
        let vertex_ids: Vec<u32> = l.iter().map(|&p| points.on_loop(grid, p)).collect();
        let mut items = Vec::with_capacity(2 * n);
        for i in 0..n {
            items.push(Item::Vertex(i));
            let j = (i + 1) % n;
            crossings(grid, l[i], l[j], &mut cuts, &mut by_axis);
            for &c in &cuts {
                // A crossing at an end of the edge is that vertex.
                let id = if c.point == l[i] {
                    vertex_ids[i]
                } else if c.point == l[j] {
                    vertex_ids[j]
                } else {
                    points.on_loop(grid, c.point)
                };
                items.push(Item::Cross(c, id));
            }
        }
        let first = items.iter().position(|it| matches!(it, Item::Cross(..)))?;
        items.rotate_left(first);
        // The cell before the first crossing: that of the vertex starting its edge (now last).
        let start_vertex = items.iter().rev().find_map(|it| if let Item::Vertex(i) = it { Some(*i) } else { None })?;
        let (mut ci, mut cj) = cell_of(grid, l[start_vertex]);
        let mut k = 0;
        while k < items.len() {
            let Item::Cross(c, entry_id) = items[k] else { return None };
            if c.across_u {
                ci = ci.checked_add_signed(isize::from(c.step)).filter(|&i| i < cu)?;
            } else {
                cj = cj.checked_add_signed(isize::from(c.step)).filter(|&j| j < cv)?;
            }
            let start = ids.len();
            ids.push(entry_id);
            k += 1;
            while let Some(Item::Vertex(i)) = items.get(k) {
                if cell_of(grid, l[*i]) != (ci, cj) {
                    return None;
                }
                ids.push(vertex_ids[*i]);
                k += 1;
            }
            let Item::Cross(exit, exit_id) = items[k % items.len()] else { return None };
            ids.push(exit_id);
            dedup_consecutive(&mut ids, start);
            fragments.push(Fragment {
                cell: cj * cu + ci,
                entry: c.entry_key(),
                exit: exit.exit_key(),
                ids: start..ids.len(),
            });
        }
        // The walk ends in the cell it started from.
        if cell_of(grid, l[start_vertex]) != (ci, cj) {
            return None;
        }
    }
    Some((fragments, ids))
}

/// Drops repeats of the previous id in `ids[start..]`.
fn dedup_consecutive(ids: &mut Vec<u32>, start: usize) {
    let mut write = start;
    for read in start..ids.len() {
        if write == start || ids[write - 1] != ids[read] {
            ids[write] = ids[read];
            write += 1;
        }
    }
    ids.truncate(write);
}

/// Whether the walk's polygon passes a point twice (not counting a repeat of the previous one).
fn has_pinch(polygon: &[u32], points: &Points) -> bool {
    let n = polygon.len();
    (0..n).any(|i| {
        let p = points.position(polygon[i]);
        (i + 2..n).any(|j| points.position(polygon[j]) == p && !(i == 0 && j == n - 1))
    })
}

/// The walk's polygon cut at every point it passes twice (two pieces of the region meeting at
/// a point, as a loop vertex on a corner leaves them) into simple cycles.
fn split_pinches(polygon: &[u32], points: &Points) -> Vec<Vec<u32>> {
    let mut pieces = Vec::new();
    let mut stack = vec![polygon.to_vec()];
    while let Some(mut ring) = stack.pop() {
        dedup_consecutive(&mut ring, 0);
        while ring.len() > 1 && ring.first() == ring.last() {
            ring.pop();
        }
        let n = ring.len();
        let repeat = (0..n).find_map(|i| {
            let p = points.position(ring[i]);
            (i + 1..n).find(|&j| points.position(ring[j]) == p).map(|j| (i, j))
        });
        match repeat {
            Some((i, j)) => {
                stack.push(ring[i..j].to_vec());
                stack.push(ring[j..].iter().chain(&ring[..i]).copied().collect());
            }
            None => pieces.push(ring),
        }
    }
    pieces
}

/// Twice the signed area of the polygon of ids (its sign is what counts).
fn ring_area(polygon: &[u32], at: &impl Fn(u32) -> P) -> f64 {
    let Some(&first) = polygon.first() else { return 0.0 };
    let o = at(first);
    let n = polygon.len();
    (0..n)
        .map(|i| {
            let (a, b) = (at(polygon[i]), at(polygon[(i + 1) % n]));
            (a[0] - o[0]) * (b[1] - o[1]) - (b[0] - o[0]) * (a[1] - o[1])
        })
        .sum()
}

/// Removes repeated points and the zero-width spikes where the walk runs back along itself (a
/// loop piece lying on the cell's side, retraced by the side): a vertex where the boundary
/// reverses on one line.
fn remove_spikes(polygon: &mut Vec<u32>, at: &impl Fn(u32) -> P) {
    let mut changed = true;
    while changed && polygon.len() >= 3 {
        changed = false;
        dedup_consecutive(polygon, 0);
        while polygon.len() > 1 && polygon.first() == polygon.last() {
            polygon.pop();
            changed = true;
        }
        let n = polygon.len();
        if n < 3 {
            break;
        }
        if let Some(i) = (0..n).find(|&i| {
            let (a, b, c) = (at(polygon[(i + n - 1) % n]), at(polygon[i]), at(polygon[(i + 1) % n]));
            let back = (b[0] - a[0]) * (c[0] - b[0]) + (b[1] - a[1]) * (c[1] - b[1]) <= 0.0;
            a == b || b == c || (orient(a, b, c) == 0.0 && back)
        }) {
            polygon.remove(i);
            changed = true;
        }
    }
}

/// Ear clipping of a counter-clockwise polygon (ids, repeats allowed) into `out`; `None` when
/// no ear can be found in a polygon that still has area.
fn clip_ears(polygon: &mut Vec<u32>, points: &Points, out: &mut Vec<[u32; 3]>) -> Option<()> {
    let at = |id: u32| points.position(id);
    remove_spikes(polygon, &at);
    let area = ring_area(polygon, &at);
    if area < 0.0 {
        return None;
    }
    if area == 0.0 {
        return Some(());
    }
    while polygon.len() > 3 {
        let n = polygon.len();
        let ear = (0..n).find(|&i| {
            let (a, b, c) = (polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n]);
            let (pa, pb, pc) = (at(a), at(b), at(c));
            orient(pa, pb, pc) > 0.0
                && !polygon.iter().any(|&d| {
                    let pd = at(d);
                    pd != pa
                        && pd != pb
                        && pd != pc
                        && orient(pa, pb, pd) >= 0.0
                        && orient(pb, pc, pd) >= 0.0
                        && orient(pc, pa, pd) >= 0.0
                })
        });
        match ear {
            Some(i) => {
                out.push([polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n]]);
                polygon.remove(i);
            }
            None => {
                return (ring_area(polygon, &at) == 0.0).then_some(());
            }
        }
    }
    if polygon.len() == 3 {
        let t = [polygon[0], polygon[1], polygon[2]];
        let area = orient(at(t[0]), at(t[1]), at(t[2]));
        if area < 0.0 {
            return None;
        }
        if area > 0.0 {
            out.push(t);
        }
    }
    Some(())
}
