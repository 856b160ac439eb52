#!/usr/bin/env python3
"""Adds to gleval's constant tables every constant of the system's GL/gl.h and GL/glu.h that they
lack, so that a program naming any constant of those headers compiles (and gets the header's
value): src/gl/consts.rs (then run tools/capi/gen_constants.py for capi/include/GL/gl.h), and
src/glu/consts.rs with capi/include/GL/glu.h.

Only names and values are read from the system headers (the values are the API's facts); each
added constant goes under a section comment naming the header section it came from. Feature
macros (GL_VERSION_1_x, GLU_VERSION_1_x, extension names) are not constants and are left out.
Running it again adds nothing. Run from the repository root:
    python3 tools/capi/gen_missing_constants.py [GL_H] [GLU_H]
    python3 tools/capi/gen_constants.py
"""
import re
import sys

DEFINE = re.compile(r"^#define\s+(GLU?_[A-Z0-9_]+)\s+(0x[0-9A-Fa-f]+|-?[0-9]+)\s*$")
SECTION = re.compile(r"^/\*\s*([A-Za-z][^*]*?)\s*\*/\s*$|^\s*\*\s+([A-Z][A-Za-z0-9 ,/()._-]+?)\s*$")
FEATURE = re.compile(r"^GLU?_VERSION_\d_\d$")


def header_constants(path):
    """(name, value, section) for every integer #define of the header, in its order."""
    section = ""
    out = []
    for line in open(path, encoding="latin-1"):
        s = SECTION.match(line)
        if s:
            title = (s.group(1) or s.group(2)).strip()
            # Commented-out defines and notes ("XXX obsolete") are not section titles.
            if "0x" not in title and not title.startswith("XXX"):
                section = title
            continue
        d = DEFINE.match(line.strip())
        if d and not FEATURE.match(d.group(1)):
            out.append((d.group(1), d.group(2), section))
    return out


def rust_names(path):
    return set(re.findall(r"^pub const ([A-Z0-9_]+):", open(path).read(), re.M))


def add_rust(path, constants, header_name, ty):
    have = rust_names(path)
    lines, last = [], None
    for name, value, section in constants:
        if name in have:
            continue
        have.add(name)
        if section != last:
            lines.append(f"\n// {header_name}: {section or 'constants'}.")
            last = section
        lines.append(f"pub const {name}: {ty} = {value};")
    if lines:
        with open(path, "a") as f:
            f.write("\n".join(lines) + "\n")
    return len([l for l in lines if l.startswith("pub const")])


def add_c(path, constants, anchor):
    """Inserts missing #defines before `anchor` (the first function declarations) in a C header."""
    text = open(path).read()
    have = set(re.findall(r"^#define (GLU?_[A-Z0-9_]+) ", text, re.M))
    lines, last = [], None
    for name, value, section in constants:
        if name in have:
            continue
        have.add(name)
        if section != last:
            lines.append(f"/* {section or 'constants'}. */")
            last = section
        lines.append(f"#define {name} {value}")
    if lines:
        i = text.index(anchor)
        text = text[:i] + "\n".join(lines) + "\n\n" + text[i:]
        open(path, "w").write(text)


gl_h = sys.argv[1] if len(sys.argv) > 1 else "/usr/include/GL/gl.h"
glu_h = sys.argv[2] if len(sys.argv) > 2 else "/usr/include/GL/glu.h"
gl = [c for c in header_constants(gl_h) if c[0] not in ("GL_FALSE", "GL_TRUE")]
glu = header_constants(glu_h)
n_gl = add_rust("src/gl/consts.rs", gl, "GL/gl.h", "GLenum")
n_glu = add_rust("src/glu/consts.rs", glu, "GL/glu.h", "GLenum")
add_c("capi/include/GL/glu.h", glu, "/* Errors. */")
print(f"added {n_gl} GL and {n_glu} GLU constants; now run tools/capi/gen_constants.py")
