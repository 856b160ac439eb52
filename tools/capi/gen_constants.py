#!/usr/bin/env python3
"""Rewrites the constants of capi/include/GL/gl.h from gleval's Rust table, src/gl/consts.rs:
one `#define` per `pub const GL_*`, the Rust file's `//` section comments as C comments. The
section lies between `/* Errors. */` and `/* State, errors and queries. */` (the first
function declarations). capi/tests/headers.sh then checks every value against the system's
headers. Run from the repository root: python3 tools/capi/gen_constants.py"""
import re

consts = open("src/gl/consts.rs").read()
lines = []
for line in consts.splitlines():
    comment = re.match(r"^// (.*)$", line)
    const = re.match(r"^pub const (GL_[A-Z0-9_]+): \w+ = ([0-9xA-Fa-f_]+);", line)
    if comment:
        lines.append(f"/* {comment.group(1)} */")
    elif const and const.group(1) not in ("GL_FALSE", "GL_TRUE"):
        lines.append(f"#define {const.group(1)} {const.group(2).replace('_', '')}")
header = open("capi/include/GL/gl.h").read()
start = header.index("/* Errors. */")
end = header.index("/* State, errors and queries. */")
open("capi/include/GL/gl.h", "w").write(header[:start] + "\n".join(lines) + "\n\n" + header[end:])
