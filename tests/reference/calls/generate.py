#!/usr/bin/env python3
"""Generates cases/generated.calls: a few thousand pseudo-random evaluator calls, valid and
invalid (wrong enums, zero/negative/huge orders and strides, u1 == u2, grids of 0 segments,
calls inside begin/end), replayed by interp.c on real Mesa and by tests/it/mesa_calls.rs on
gleval. Deterministic (fixed seed). Geometry stays inside the clip volume and colours inside
[0, 1], and the current colour, normal and texture coordinate are set first in every case, so
feedback compares like for like (FORMAT.md)."""
import random

rng = random.Random(20261122)
TARGETS1 = ["GL_MAP1_VERTEX_3", "GL_MAP1_VERTEX_4", "GL_MAP1_COLOR_4", "GL_MAP1_NORMAL", "GL_MAP1_INDEX",
            "GL_MAP1_TEXTURE_COORD_1", "GL_MAP1_TEXTURE_COORD_2", "GL_MAP1_TEXTURE_COORD_3", "GL_MAP1_TEXTURE_COORD_4"]
TARGETS2 = [t.replace("MAP1", "MAP2") for t in TARGETS1]
K = {"VERTEX_3": 3, "VERTEX_4": 4, "COLOR_4": 4, "NORMAL": 3, "INDEX": 1,
     "TEXTURE_COORD_1": 1, "TEXTURE_COORD_2": 2, "TEXTURE_COORD_3": 3, "TEXTURE_COORD_4": 4}
BAD_ENUMS = ["0x0D99", "0x0D8F", "0x0DB9", "0x0DAF", "0x1234", "GL_FILL", "GL_COEFF"]


def k_of(target):
    for name, k in K.items():
        if target.endswith(name):
            return k
    return 3


def fmt(x):
    return ("%.4f" % x).rstrip("0").rstrip(".") if x != int(x) else str(int(x))


def points(target, count, k, stride):
    """Values for `count` points at `stride`; unread slots are 9."""
    vals = [9.0] * ((count - 1) * stride + k if count > 0 else k)
    for p in range(count):
        w = rng.uniform(0.6, 1.8) if target.endswith("VERTEX_4") else 1.0
        for c in range(k):
            if target.endswith("VERTEX_4") and c == 3:
                v = w
            elif "COLOR" in target:
                v = rng.uniform(0.0, 1.0)
            elif "VERTEX" in target:
                v = rng.uniform(-0.9, 0.9) * w
            else:
                v = rng.uniform(-2.0, 2.0)
            vals[p * stride + c] = v
    return vals


def pick_target(dims):
    if rng.random() < 0.06:
        return rng.choice(BAD_ENUMS)
    if rng.random() < 0.05:
        return rng.choice(TARGETS2 if dims == 1 else TARGETS1)  # wrong dimension
    table = TARGETS1 if dims == 1 else TARGETS2
    return rng.choice(table[:4] if rng.random() < 0.6 else table)


def domain():
    # Map domains cover the whole grid range, so nothing is extrapolated out of the clip volume.
    a, b = rng.choice([(0, 1), (1, 0), (0, 1)])
    if rng.random() < 0.04:
        b = a  # u1 == u2
    return a, b


def map1():
    t = pick_target(1)
    k = k_of(t)
    order = rng.choice([1, 2, 3, 4, 5, 7]) if rng.random() > 0.08 else rng.choice([0, -1, 31, 30])
    if t.endswith("VERTEX_3") or t.endswith("VERTEX_4"):
        order = max(order, 2) if 0 < order <= 30 else order
    stride = k + rng.choice([0, 0, 0, 1, 2]) if rng.random() > 0.08 else rng.choice([0, k - 1, -3])
    u1, u2 = domain()
    count = min(max(order, 0), 31)
    vals = points(t, count, k, max(stride, k))
    return "map1f %s %s %s %d %d [%s]" % (t, fmt(u1), fmt(u2), stride, order, " ".join(fmt(v) for v in vals))


def map2():
    t = pick_target(2)
    k = k_of(t)
    uo = rng.choice([1, 2, 3, 4]) if rng.random() > 0.06 else rng.choice([0, 31])
    vo = rng.choice([1, 2, 3, 4]) if rng.random() > 0.06 else rng.choice([0, 31])
    if t.endswith("VERTEX_3") or t.endswith("VERTEX_4"):
        uo, vo = (max(uo, 2) if 0 < uo <= 30 else uo), (max(vo, 2) if 0 < vo <= 30 else vo)
    layout_u = rng.random() < 0.5
    cu, cv = min(max(uo, 0), 31), min(max(vo, 0), 31)
    if layout_u:
        vstride, ustride = k, k * max(cv, 1)
    else:
        ustride, vstride = k, k * max(cu, 1)
    if rng.random() < 0.06:
        ustride = rng.choice([0, k - 1])
    if rng.random() < 0.06:
        vstride = rng.choice([0, k - 1])
    u1, u2 = domain()
    v1, v2 = domain()
    need = (cu - 1) * max(ustride, k) + (cv - 1) * max(vstride, k) + k if cu and cv else k
    flat = points(t, 1, k, k)[:0]
    vals = [9.0] * need
    for i in range(cu):
        for j in range(cv):
            p = points(t, 1, k, k)
            for c in range(k):
                vals[i * max(ustride, k) + j * max(vstride, k) + c] = p[c]
    return "map2f %s %s %s %d %d %s %s %d %d [%s]" % (
        t, fmt(u1), fmt(u2), ustride, uo, fmt(v1), fmt(v2), vstride, vo, " ".join(fmt(v) for v in vals))


def grid_call(dims):
    n = rng.choice([1, 2, 3, 4, 5]) if rng.random() > 0.1 else rng.choice([0, -2])
    a, b = rng.choice([(0, 1), (1, 0), (0, 1), (0.2, 0.8)])
    if dims == 1:
        return "map_grid1f %d %s %s" % (n, fmt(a), fmt(b)), n
    m = rng.choice([1, 2, 3, 4]) if rng.random() > 0.1 else 0
    return "map_grid2f %d %s %s %d %s %s" % (n, fmt(a), fmt(b), m, fmt(a), fmt(b)), (n, m)


def mesh(grid1, grid2):
    if rng.random() < 0.5:
        mode = rng.choice(["GL_POINT", "GL_LINE", "GL_LINE", "GL_FILL" if rng.random() < 0.2 else "GL_POINT"])
        n = max(grid1, 1)
        i1 = rng.randint(0, n)
        return "eval_mesh1 %s %d %d" % (mode, i1, rng.randint(i1 - 1, n))
    mode = rng.choice(["GL_POINT", "GL_LINE", "GL_FILL", "GL_FILL"] + (["GL_POINTS"] if rng.random() < 0.1 else []))
    n, m = max(grid2[0], 1), max(grid2[1], 1)
    i1, j1 = rng.randint(0, n), rng.randint(0, m)
    return "eval_mesh2 %s %d %d %d %d" % (mode, i1, rng.randint(i1 - 1, n), j1, rng.randint(j1 - 1, m))


def cap():
    # Only the vertex maps are ever enabled here (the others are defined and queried): with
    # colour, normal or texture maps switching on and off between evaluations, Mesa mixes up
    # its vertex attribute slots (current colour showing up as a texture coordinate, texture
    # coordinates truncated: the Mesa bug of FORMAT.md section 5). The attribute maps are
    # covered by the hand-written cases, which set every current value first.
    enabled = [t for t in TARGETS1 + TARGETS2 if "VERTEX" in t]
    return rng.choice(enabled + ["GL_AUTO_NORMAL"] + (["0x1234"] if rng.random() < 0.1 else []))


def case(index):
    out = ["case generated_%03d" % index, "color4f 1 1 1 1", "normal3f 0 0 1", "tex_coord4f 0 0 0 1"]
    out += ["map_grid1f 3 0 1", "map_grid2f 3 0 1 3 0 1"]
    # Valid vertex maps of order >= 2 from the start: Mesa's AUTO_NORMAL reads past the control
    # points of an order-1 map (the initial one), which makes its output vary from run to run.
    out += ["map1f GL_MAP1_VERTEX_3 0 1 3 2 [-0.5 -0.5 0 0.5 0.5 0]",
            "map1f GL_MAP1_VERTEX_4 0 1 4 2 [-0.5 0.5 0 1 0.5 -0.5 0 1]",
            "map2f GL_MAP2_VERTEX_3 0 1 6 2 0 1 3 2 [-0.5 -0.5 0 -0.5 0.5 0.25 0.5 -0.5 0.25 0.5 0.5 0]",
            "map2f GL_MAP2_VERTEX_4 0 1 8 2 0 1 4 2 [-0.5 -0.5 0 1 -0.5 0.5 0 1 0.5 -0.5 0 1 0.5 0.5 0.5 1]"]
    grid1, grid2 = 3, (3, 3)
    inside = False
    for _ in range(rng.randint(25, 45)):
        r = rng.random()
        if inside:
            if r < 0.5:
                out.append("eval_coord1f %s" % fmt(rng.uniform(0, 1)) if rng.random() < 0.5 else "eval_coord2f %s %s" % (fmt(rng.uniform(0, 1)), fmt(rng.uniform(0, 1))))
            elif r < 0.65:
                out.append("eval_point1 %d" % rng.randint(0, grid1) if rng.random() < 0.5 else "eval_point2 %d %d" % (rng.randint(0, grid2[0]), rng.randint(0, grid2[1])))
            elif r < 0.8:
                out.append(rng.choice([map1(), "map_grid1f 2 0 1", "eval_mesh1 GL_LINE 0 1", "enable GL_MAP1_VERTEX_3",
                                       "is_enabled GL_AUTO_NORMAL", "get_mapfv GL_MAP1_VERTEX_3 GL_ORDER"]))
            else:
                out.append("end")
                inside = False
            continue
        if r < 0.18:
            out.append(map1())
        elif r < 0.34:
            out.append(map2())
        elif r < 0.42:
            call, n = grid_call(1)
            out.append(call)
            if isinstance(n, int) and n >= 1:
                grid1 = n
        elif r < 0.50:
            call, (n, m) = grid_call(2)
            out.append(call)
            if n >= 1 and m >= 1:
                grid2 = (n, m)
        elif r < 0.62:
            out.append(("enable %s" if rng.random() < 0.7 else "disable %s") % cap())
        elif r < 0.80:
            out.append(mesh(grid1, grid2))
        elif r < 0.86:
            out.append("get_map%sv %s %s" % (rng.choice("fdi"), pick_target(rng.choice([1, 2])), rng.choice(["GL_COEFF", "GL_ORDER", "GL_DOMAIN", "0x0A03"])))
        elif r < 0.90:
            out.append("active_texture %s" % rng.choice(["GL_TEXTURE0", "GL_TEXTURE0", "GL_TEXTURE1"]))
        else:
            out.append("begin %s" % rng.choice(["GL_POINTS", "GL_LINE_STRIP", "GL_TRIANGLES"]))
            inside = True
    if inside:
        out.append("end")
    return out


lines = ["# Generated by generate.py (seed 20261122): valid and invalid evaluator calls.", ""]
for i in range(90):
    lines += case(i) + [""]
open("cases/generated.calls", "w").write("\n".join(lines))
