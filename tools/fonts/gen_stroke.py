#!/usr/bin/env python3
"""Generates GLUT's stroke fonts (GLUT_STROKE_ROMAN, GLUT_STROKE_MONO_ROMAN) as freeglut 3.4 has
them, from its published font data (fg_stroke_roman.c, fg_stroke_mono_roman.c): each character's
advance ("Right") and its pen strokes, points in font units, read as data (numbers only), so that
stroke text is freeglut's to the float ('A' advances 80.4905 units, the line height is 152.381).

    git clone https://github.com/freeglut/freeglut && git -C freeglut checkout v3.4.0
    python3 tools/fonts/gen_stroke.py freeglut/src

writes src/glut/fonts/stroke_data.rs (the Rust table) and tests/reference/pictures/glut_strokes.h
(the same numbers for the OSMesa GLUT stand-in), so that gleval and real Mesa draw the same lines.
Numbers are rounded to f32 here, as freeglut's C compiler rounds its float literals.
"""

import os
import re
import struct
import sys

LICENCE = """\
Glyphs and advances of freeglut 3.4's stroke fonts (fg_stroke_roman.c, fg_stroke_mono_roman.c),
read as data by tools/fonts/gen_stroke.py; do not edit. freeglut's notice for that data:

Copyright (c) 1999-2000 Pawel W. Olszta. All Rights Reserved.
Written by Pawel W. Olszta, <olszta@sourceforge.net>

Permission is hereby granted, free of charge, to any person obtaining a copy of this software
and associated documentation files (the "Software"), to deal in the Software without
restriction, including without limitation the rights to use, copy, modify, merge, publish,
distribute, sublicense, and/or sell copies of the Software, and to permit persons to whom the
Software is furnished to do so, subject to the following conditions: The above copyright notice
and this permission notice shall be included in all copies or substantial portions of the
Software. THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR IMPLIED,
INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY, FITNESS FOR A PARTICULAR PURPOSE
AND NONINFRINGEMENT. IN NO EVENT SHALL PAWEL W. OLSZTA BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER
LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM, OUT OF OR IN
CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE SOFTWARE."""


def to_f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


def f32(x):
    """x rounded to the nearest f32, in the fewest digits that read back as that f32 (C's strtof
    and Rust's parser both round correctly, so both tables hold the same floats)."""
    value = to_f32(x)
    text = next(t for t in (f"{value:.{d}g}" for d in range(1, 10)) if to_f32(float(t)) == value)
    text = repr(float(text)) if "e" in text else text  # 1e+02 -> 100.0
    return text if "." in text else text + ".0"


def read_font(path, prefix):
    """The font's line height and its characters 0..127: None, or (advance, strips of (x, y))."""
    text = open(path, encoding="latin-1").read()
    vertices = {}
    for m in re.finditer(r"SFG_StrokeVertex\s+(\w+)\[\]\s*=\s*\{(.*?)\};", text, re.S):
        pairs = re.findall(r"\{\s*([-0-9.eE]+)f?\s*,\s*([-0-9.eE]+)f?\s*\}", m.group(2))
        vertices[m.group(1)] = [(float(x), float(y)) for x, y in pairs]
    strips = {}
    for m in re.finditer(r"SFG_StrokeStrip\s+(\w+)\[\]\s*=\s*\{(.*?)\};", text, re.S):
        strips[m.group(1)] = [(int(n), name) for n, name in re.findall(r"\{\s*(\d+)\s*,\s*(\w+)\s*\}", m.group(2))]
    chars = {}
    for m in re.finditer(r"SFG_StrokeChar\s+(\w+)\s*=\s*\{\s*([-0-9.eE]+)f?\s*,\s*(\d+)\s*,\s*(\w+)\s*\}", text):
        name, right, count, strip_table = m.group(1), float(m.group(2)), int(m.group(3)), m.group(4)
        placed = [vertices[v][:n] for n, v in strips.get(strip_table, [])[:count]]
        chars[name] = (right, placed)
    table = re.search(r"SFG_StrokeChar\s*\*\s*" + prefix + r"_chars\[\]\s*=\s*\{(.*?)\};", text, re.S).group(1)
    entries = [None if t.strip() == "0" else chars[t.strip().lstrip("&")] for t in table.split(",") if t.strip()]
    height = float(re.search(r"SFG_StrokeFont\s+\w+\s*=\s*\{[^,]*,\s*\d+\s*,\s*([-0-9.eE]+)f?", text).group(1))
    if len(entries) != 128:
        raise SystemExit(f"{path}: {len(entries)} characters, expected 128")
    return height, entries


def font_tables(chars):
    """(glyph entries for codes 0..127, flat points, strips as (first point, count))."""
    entries, points, strips = [None] * 128, [], []
    for code, char in enumerate(chars):
        if char is None:
            continue
        advance, placed = char
        entries[code] = (advance, len(strips), len(placed))
        for strip in placed:
            strips.append((len(points), len(strip)))
            points.extend(strip)
    return entries, points, strips


def chunks(items, n):
    return [items[k:k + n] for k in range(0, len(items), n)]


def rust_font(name, glut, height, entries, points, strips):
    lines = [f"/// `{glut}`.",
             f"pub(crate) static {name}: StrokeFont = StrokeFont {{",
             f"    height: {f32(height)},",
             f"    glyphs: &{name}_GLYPHS,",
             f"    strips: &{name}_STRIPS,",
             f"    points: &{name}_POINTS,",
             "};",
             f"static {name}_GLYPHS: [Option<StrokeGlyph>; 128] = ["]
    for code, e in enumerate(entries):
        if e is None:
            lines.append("    None,")
        else:
            shown = f" {chr(code)!r}" if 32 < code < 127 else ""
            lines.append(f"    Some(StrokeGlyph {{ advance: {f32(e[0])}, first: {e[1]}, count: {e[2]} }}), // {code}{shown}")
    lines.append("];")
    lines.append(f"static {name}_STRIPS: [(u16, u16); {len(strips)}] = [")
    for row in chunks(strips, 10):
        lines.append("    " + ", ".join(f"({a}, {b})" for a, b in row) + ",")
    lines.append("];")
    lines.append(f"static {name}_POINTS: [[f32; 2]; {len(points)}] = [")
    for row in chunks(points, 5):
        lines.append("    " + ", ".join(f"[{f32(x)}, {f32(y)}]" for x, y in row) + ",")
    lines.append("];")
    return "\n".join(lines)


def c_font(name, glut, height, entries, points, strips):
    lines = [f"/* {glut}. */",
             f"static const float {name}_POINTS[{len(points)}][2] = {{"]
    for row in chunks(points, 5):
        lines.append("    " + ", ".join(f"{{{f32(x)}f, {f32(y)}f}}" for x, y in row) + ",")
    lines += ["};", f"static const unsigned short {name}_STRIPS[{len(strips)}][2] = {{"]
    for row in chunks(strips, 10):
        lines.append("    " + ", ".join(f"{{{a}, {b}}}" for a, b in row) + ",")
    lines += ["};", f"static const GlutStrokeGlyph {name}_GLYPHS[128] = {{"]
    for e in entries:
        lines.append("    {0.0f, 0, 0, 0}," if e is None else f"    {{{f32(e[0])}f, {e[1]}, {e[2]}, 1}},")
    lines += ["};", f"static const GlutStrokeFont {name} = {{{f32(height)}f, {name}_GLYPHS, "
              f"{name}_STRIPS, {name}_POINTS}};"]
    return "\n".join(lines)


def main():
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    src = sys.argv[1] if len(sys.argv) > 1 else "freeglut/src"
    fonts = []
    for name, glut, file, prefix in [("ROMAN", "GLUT_STROKE_ROMAN", "fg_stroke_roman.c", "StrokeRoman"),
                                     ("MONO_ROMAN", "GLUT_STROKE_MONO_ROMAN", "fg_stroke_mono_roman.c", "StrokeMonoRoman")]:
        height, chars = read_font(os.path.join(src, file), prefix)
        fonts.append((name, glut, height, *font_tables(chars)))
    header = "\n".join("//! " + line if line else "//!" for line in LICENCE.splitlines())
    rust = [header, "", "use super::{StrokeFont, StrokeGlyph};", ""]
    rust += [rust_font(*f) + "\n" for f in fonts]
    with open(os.path.join(root, "src/glut/fonts/stroke_data.rs"), "w") as out:
        out.write("\n".join(rust).rstrip() + "\n")
    c = ["/* " + "\n".join(("   " + line).rstrip() for line in LICENCE.split("\n")).lstrip() + " */",
         "#ifndef GLUT_STROKES_H", "#define GLUT_STROKES_H",
         "/* One glyph: its advance, its first strip and how many (present: 0 where the font has none). */",
         "typedef struct { float advance; unsigned short first, count, present; } GlutStrokeGlyph;",
         "/* A font: its line height, 128 glyphs, strips as (first point, count), points (x, y). */",
         "typedef struct { float height; const GlutStrokeGlyph *glyphs; const unsigned short (*strips)[2];"
         " const float (*points)[2]; } GlutStrokeFont;",
         ""]
    c += [c_font(*f) + "\n" for f in fonts]
    c += ["#endif"]
    with open(os.path.join(root, "tests/reference/pictures/glut_strokes.h"), "w") as out:
        out.write("\n".join(c) + "\n")


if __name__ == "__main__":
    sys.exit(main())
