#!/usr/bin/env python3
"""Runs piglit's OpenGL 1.0 to 1.5 groups on real Mesa or on gleval, and writes one line a test.

    tests/piglit/run.py fetch                       # Debian's prebuilt piglit into target/piglit
    tests/piglit/run.py run --gl gleval --platform glx --out glx.tsv
    tests/piglit/run.py run --gl mesa --platform glx --out mesa.tsv
    tests/piglit/run.py run --groups gl-1.1 ...     # only the 1.0 and 1.1 groups (groups.tsv)
    tests/piglit/run.py table mesa.tsv glx.tsv egl.tsv   # a Markdown table side by side
    tests/piglit/run.py check tests/piglit/expected.tsv glx.tsv --column gleval-glx
    tests/piglit/run.py report mesa.tsv glx.tsv egl.tsv --logs ...   # the same, with reasons
    tests/piglit/run.py groups mesa.tsv glx.tsv egl.tsv   # each group's totals, side by side
    tests/piglit/run.py expected mesa.tsv glx.tsv egl.tsv       # writes tests/piglit/expected.tsv
    tests/piglit/run.py expected --groups gl-1.5 ...   # those groups' rows; the others' kept

`run` starts its own Xvfb for `--platform glx` (and `x11_egl`) unless DISPLAY is set;
`surfaceless_egl` needs no X server. On gleval each test runs through `capi/gleval-run`, so
the test binary and piglit's own libraries (waffle, piglitutil) load libgleval_c under the
names of Mesa's libraries. A test's result is the last `PIGLIT: {"result": ...}` line it
prints; a test that prints none is a `crash` (its exit status noted), one past `--timeout`
seconds a `timeout`.

The test list comes from the package's own `tests/opengl.xml.gz` (the commands with their
arguments, as piglit's runner reads them): the tests whose names start with one of the groups
in `groups.tsv` (`spec@!opengl 1.0@` to `spec@!opengl 1.5@` and the groups of the extensions
GL 1.2 to 1.5 took in), group by group in that file's order, less the tests its `exclude-`
lines leave out.
"""
import argparse
import ast
import concurrent.futures
import gzip
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DEFAULT_PIGLIT = os.path.join(ROOT, "target", "piglit", "usr", "lib", "x86_64-linux-gnu", "piglit")
GROUPS = os.path.join(HERE, "groups.tsv")
RESULT = re.compile(r'PIGLIT: (\{.*"result".*\})')


def fetch(args):
    """Debian's piglit package, only its test executables, libraries and test lists."""
    dest = os.path.join(ROOT, "target", "piglit")
    os.makedirs(dest, exist_ok=True)
    if os.path.isfile(os.path.join(args.piglit, "bin", "gl-1.0-logicop")):
        print(f"piglit already in {dest}")
        return 0
    subprocess.run(["apt-get", "download", "piglit"], cwd=dest, check=True)
    debs = sorted(f for f in os.listdir(dest) if f.startswith("piglit_") and f.endswith(".deb"))
    prefix = "./usr/lib/x86_64-linux-gnu/piglit/"
    parts = [prefix + "bin", prefix + "lib", prefix + "tests/opengl.xml.gz"]
    tar = subprocess.Popen(["dpkg-deb", "--fsys-tarfile", debs[-1]], cwd=dest, stdout=subprocess.PIPE)
    subprocess.run(["tar", "-x"] + parts, cwd=dest, stdin=tar.stdout, check=True)
    tar.wait()
    os.remove(os.path.join(dest, debs[-1]))
    return 0


def groups_file(path=GROUPS):
    """groups.tsv: its (set, group, what) lines in order, and its exclude- rules."""
    lines, excludes = [], []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        fields = line.rstrip("\n").split("\t")
        if fields[0].startswith("exclude-"):
            excludes.append((fields[0], fields[1]))
        else:
            lines.append((fields[0], fields[1], fields[2] if len(fields) > 2 else ""))
    return lines, excludes


def select(spec):
    """The groups (name prefixes) --groups names, in groups.tsv's order: each comma-separated
    word a set (gl-1.1, gl-1.5), a group (spec@!opengl 1.2@) or a group's name without spec@
    and @ (!opengl 1.2, arb_occlusion_query); all of them without --groups."""
    lines, _ = groups_file()
    if not spec or spec == "all":
        return [g for _, g, _ in lines]
    words = [w.strip() for w in spec.split(",") if w.strip()]
    chosen = []
    for w in words:
        found = [g for s, g, _ in lines if w in (s, g, g[len("spec@"):].rstrip("@"))]
        if not found:
            sys.exit(f"run.py: no set or group {w!r} in {GROUPS}")
        chosen += found
    return [g for _, g, _ in lines if g in chosen]


def group_of(name, groups):
    return next((g for g in groups if name.startswith(g)), None)


def excluded(name, argv, excludes):
    for kind, value in excludes:
        if kind == "exclude-command" and os.path.basename(argv[0]) == value:
            return True
        if kind == "exclude-name" and re.search(value, name):
            return True
    return False


def tests(piglit, pattern, groups):
    """(name, argv, concurrent) of the groups' tests: group by group, each in the list's order."""
    _, excludes = groups_file()
    root = ET.parse(gzip.open(os.path.join(piglit, "tests", "opengl.xml.gz"))).getroot()
    found = {g: [] for g in groups}
    for test in root:
        name = test.get("name")
        group = group_of(name, groups)
        if not group or (pattern and not re.search(pattern, name)):
            continue
        options = {o.get("name"): o.get("value") for o in test}
        argv = ast.literal_eval(options["command"])
        if excluded(name, argv, excludes):
            continue
        found[group].append((name, argv, options.get("run_concurrent") == "True"))
    return [t for g in groups for t in found[g]]


def log_path(logs, name):
    """A test's log: its name less spec@, under a folder of its group ("!opengl 1.1/...")."""
    group, _, test = name.partition("@")[2].partition("@")
    return os.path.join(logs, group, test.replace("/", "_") + ".log")


class Xvfb:
    """An X server of our own for the run (none if DISPLAY is already set)."""

    def __init__(self, needed):
        self.proc = None
        if not needed or os.environ.get("DISPLAY"):
            return
        # A display number of this run's own (from the process id), where no other X server
        # holds the lock: two runs at once never share (or end) one server. -noreset: a server
        # resets when its last client leaves and refuses connections meanwhile, so a test that
        # connects just after the previous one left could not open its display.
        start = 200 + os.getpid() % 600
        for n in range(start, start + 50):
            if os.path.exists(f"/tmp/.X{n}-lock") or os.path.exists(f"/tmp/.X11-unix/X{n}"):
                continue
            self.proc = subprocess.Popen(["Xvfb", f":{n}", "-screen", "0", "1280x1024x24", "-nolisten", "tcp", "-noreset"],
                                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            for _ in range(100):
                if os.path.exists(f"/tmp/.X11-unix/X{n}"):
                    break
                time.sleep(0.05)
            os.environ["DISPLAY"] = f":{n}"
            return
        sys.exit("run.py: no free X display number")

    def close(self):
        if self.proc:
            self.proc.terminate()
            self.proc.wait()


def run_one(piglit, gl, platform, timeout, argv, concurrent):
    env = dict(os.environ)
    env["PIGLIT_PLATFORM"] = platform
    env["LD_LIBRARY_PATH"] = os.path.join(piglit, "lib") + (":" + env["LD_LIBRARY_PATH"] if env.get("LD_LIBRARY_PATH") else "")
    env.pop("WAYLAND_DISPLAY", None)
    # gleval-run's symbol check (nm over the test and its libraries) costs more than most
    # tests; a symbol gleval lacked would end the test at the loader instead, as a crash.
    env.setdefault("GLEVAL_RUN_CHECK", "0")
    if platform == "surfaceless_egl":
        env.pop("DISPLAY", None)
        # Surfaceless EGL has no window to show: piglit's window framework would abort in
        # its event loop; with PIGLIT_NO_WINDOW=1 a test runs its display callback once and
        # reports, as Mesa's CI runs piglit there.
        env.setdefault("PIGLIT_NO_WINDOW", "1")
    # As piglit's runner: -auto, and -fbo for the tests it runs concurrently (drawn into a
    # framebuffer object where the GL has them, else into the window).
    command = [os.path.join(piglit, "bin", argv[0])] + argv[1:] + (["-auto", "-fbo"] if concurrent else ["-auto"])
    if gl == "gleval":
        command = [os.path.join(ROOT, "capi", "gleval-run")] + command
    if not os.path.isfile(os.path.join(piglit, "bin", argv[0])):
        return "missing", 0.0, f"{argv[0]}: not in the package\n"
    return attempt(command, env, timeout)


def attempt(command, env, timeout):
    """One run of a test: its result, seconds and output."""
    start = time.monotonic()
    with tempfile.TemporaryDirectory() as cwd:
        try:
            done = subprocess.run(command, cwd=cwd, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                  stderr=subprocess.STDOUT, timeout=timeout, start_new_session=True)
        except subprocess.TimeoutExpired as e:
            return "timeout", time.monotonic() - start, (e.output or b"").decode(errors="replace")
    seconds = time.monotonic() - start
    output = done.stdout.decode(errors="replace")
    results = RESULT.findall(output)
    if not results:
        return f"crash({done.returncode})", seconds, output
    result = json.loads(results[-1]).get("result", "?")
    if done.returncode not in (0, 1) and result == "pass":
        result = f"crash({done.returncode})"
    return result, seconds, output


def run(args):
    if not os.path.isdir(args.piglit):
        sys.exit(f"run.py: no piglit in {args.piglit} (run.py fetch)")
    todo = tests(args.piglit, args.filter, select(args.groups))
    x = Xvfb(args.platform in ("glx", "x11_egl"))
    logs = args.logs
    if logs:
        os.makedirs(logs, exist_ok=True)
    results = {}
    try:
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            jobs = {pool.submit(run_one, args.piglit, args.gl, args.platform, args.timeout, argv, concurrent): name
                    for name, argv, concurrent in todo}
            for job in concurrent.futures.as_completed(jobs):
                name = jobs[job]
                result, seconds, output = job.result()
                results[name] = (result, seconds)
                if logs:
                    path = log_path(logs, name)
                    os.makedirs(os.path.dirname(path), exist_ok=True)
                    with open(path, "w") as f:
                        f.write(output)
                if args.verbose:
                    print(f"{result:10} {seconds:6.1f}s {name}", flush=True)
    finally:
        x.close()
    with open(args.out, "w") as out:
        out.write("# test\tresult\tseconds\n")
        for name, _, _ in todo:
            result, seconds = results[name]
            out.write(f"{name}\t{result}\t{seconds:.1f}\n")
    counts = {}
    for result, _ in results.values():
        key = "crash" if result.startswith("crash") else result
        counts[key] = counts.get(key, 0) + 1
    print(f"piglit {args.gl} {args.platform}: " + ", ".join(f"{n} {k}" for k, n in sorted(counts.items())))
    return 0


def read(path):
    out = {}
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        name, result = line.rstrip("\n").split("\t")[:2]
        out[name] = result
    return out


def short(name):
    """A test's name without spec@ and its group, as the tables show it."""
    return name.split("@", 2)[2]


def by_group(names):
    """The names in groups.tsv's order of their groups: [(group, [name, ...]), ...]."""
    groups = [g for _, g, _ in groups_file()[0]]
    out = {}
    for name in names:
        out.setdefault(group_of(name, groups) or name.rsplit("@", 1)[0] + "@", []).append(name)
    return sorted(out.items(), key=lambda item: groups.index(item[0]) if item[0] in groups else len(groups))


def table(args):
    columns = [read(p) for p in args.results]
    names = list(columns[0])
    print("| test | " + " | ".join(os.path.splitext(os.path.basename(p))[0] for p in args.results) + " |")
    print("|---" * (len(columns) + 1) + "|")
    for name in names:
        print(f"| {short(name)} | " + " | ".join(c.get(name, "-") for c in columns) + " |")
    return 0


def reason(log):
    """Why a test did not pass, from its output: the context or extension it asked for, or
    its first line of complaint."""
    lines = [l.strip() for l in log.splitlines() if l.strip() and not l.startswith("PIGLIT")]
    for l in lines:
        # GLX makes the context and piglit finds its version short; EGL refuses to make it.
        m = re.search(r"(?:Requested a|Failed to create waffle_context for) (OpenGL [\d.]+) Compatibility Context", l)
        if m:
            return f"needs an {m.group(1)} context"
        m = re.search(r"(?:Test requires|Requires) (?:GL version |OpenGL )([\d.]*\d)", l)
        if m:
            return f"needs OpenGL {m.group(1)}"
        m = re.search(r"(?:Test requires|Requires) (\S+)", l)
        if m:
            return f"needs {m.group(1).rstrip('.')}"
        m = re.search(r'Function "(\w+)" not supported', l)
        if m:
            return f"calls {m.group(1)}"
    bad = [l for l in lines if re.search(r"(?i)expected|fail|error|unexpected|mismatch", l)]
    return (bad or lines or [""])[0][:110].replace("|", "/")


def count(results):
    counts = {}
    for r in results:
        key = "crash" if r.startswith("crash") else r
        counts[key] = counts.get(key, 0) + 1
    return counts


def report(args):
    """The Markdown table of the results side by side, each difference with its reason; a
    table a group where the results span more than one."""
    columns = [(os.path.splitext(os.path.basename(p))[0], read(p)) for p in args.results]
    names = list(columns[0][1])
    out = []
    totals = []
    for title, results in columns:
        counts = count(results.get(n, "-") for n in names)
        totals.append(f"| {title} | " + " | ".join(str(counts.get(k, 0)) for k in KINDS) + " |")
    out.append("| run | " + " | ".join(KINDS) + " |")
    out.append("|---" * (len(KINDS) + 1) + "|")
    out += totals
    grouped = by_group(names)
    for group, members in grouped:
        out.append("")
        if len(grouped) > 1:
            out.append(f"### {group[len('spec@'):].rstrip('@')}")
            out.append("")
        out.append("| test | " + " | ".join(t for t, _ in columns) + " | why they differ |")
        out.append("|---" * (len(columns) + 2) + "|")
        for name in members:
            row = [c.get(name, "-") for _, c in columns]
            if len(set(row)) == 1:
                continue
            why = ""
            for (title, results), logs in zip(columns, args.logs or []):
                if results.get(name) != "pass" and logs and os.path.isdir(logs):
                    path = log_path(logs, name)
                    if os.path.exists(path):
                        why = reason(open(path, errors="replace").read())
                        if why:  # else the next run's log (a timeout may have printed nothing)
                            break
            out.append(f"| {short(name)} | " + " | ".join(row) + f" | {why} |")
    print("\n".join(out))
    return 0


def summary(args):
    """Each group's totals, a column a run: pass / fail / skip, and any others by name."""
    columns = [(os.path.splitext(os.path.basename(p))[0], read(p)) for p in args.results]
    names = list(columns[0][1])
    lines = {g: what for _, g, what in groups_file()[0]}

    def cell(results):
        counts = count(results)
        text = f"{counts.pop('pass', 0)} / {counts.pop('fail', 0)} / {counts.pop('skip', 0)}"
        return text + "".join(f", {n} {k}" for k, n in sorted(counts.items()))

    out = ["| group | what | tests | " + " | ".join(f"{t} (pass / fail / skip)" for t, _ in columns) + " |",
           "|---" * (len(columns) + 3) + "|"]
    for group, members in by_group(names):
        out.append(f"| {group[len('spec@'):].rstrip('@')} | {lines.get(group, '')} | {len(members)} | "
                   + " | ".join(cell(c.get(n, "-") for n in members) for _, c in columns) + " |")
    out.append(f"| all | | {len(names)} | " + " | ".join(cell(c.get(n, "-") for n in names) for _, c in columns) + " |")
    print("\n".join(out))
    return 0


def read_expected(path):
    """expected.tsv: {test: {column: result}} in the file's order."""
    expected = {}
    header = None
    for line in open(path):
        fields = line.rstrip("\n").split("\t")
        if line.startswith("#"):
            header = [f.strip("# ") for f in fields]
            continue
        if len(fields) > 1:
            expected[fields[0]] = dict(zip(header[1:], fields[1:]))
    return expected


def expected(args):
    """expected.tsv from the three runs: Mesa's (GLX), gleval's with GLX and with EGL. With
    --groups, only those groups' rows come from the runs; every other group's rows are kept
    as the file (--out) has them."""
    mesa, glx, egl = read(args.mesa), read(args.glx), read(args.egl)
    columns = ["mesa-glx", "gleval-glx", "gleval-egl"]
    rows = {name: [mesa[name], glx.get(name, "-"), egl.get(name, "-")] for name in mesa}
    if args.groups:
        chosen = select(args.groups)
        old = read_expected(args.out) if os.path.exists(args.out) else {}
        kept = {n: [e.get(c, "-") for c in columns] for n, e in old.items() if not group_of(n, chosen)}
        new = {n: r for n, r in rows.items() if group_of(n, chosen)}
        missing = [g for g in chosen if not any(group_of(n, [g]) for n in new)]
        if missing:
            sys.exit(f"run.py: {args.mesa} has no test of {', '.join(missing)}")
        rows = dict(kept, **new)
    with open(args.out, "w") as out:
        out.write("# test\t" + "\t".join(columns) + "\n")
        for _, members in by_group(rows):
            for name in members:
                out.write(f"{name}\t" + "\t".join(rows[name]) + "\n")
    return 0


KINDS = ["pass", "fail", "skip", "warn", "crash", "timeout", "missing"]


def check(args):
    """Every test the expected list says passes on gleval passes in the results (with
    --groups, the expected list's tests of those groups)."""
    expected = read_expected(args.expected)
    if args.groups:
        chosen = select(args.groups)
        expected = {n: e for n, e in expected.items() if group_of(n, chosen)}
    got = read(args.results)
    lost = [n for n, e in expected.items() if e.get(args.column) == "pass" and got.get(n) != "pass"]
    # A crash or a hang is a defect whatever the test.
    broken = [n for n, r in got.items() if r.startswith("crash") or r == "timeout"]
    broken = [n for n in broken if expected.get(n, {}).get(args.column) != got[n]]
    for n in broken:
        print(f"{got[n].upper()}: {n}")
    gained = [n for n, e in expected.items() if e.get(args.column) != "pass" and got.get(n) == "pass"]
    for n in gained:
        print(f"now passes (was {expected[n].get(args.column)}): {n}")
    for n in lost:
        print(f"REGRESSED to {got.get(n)}: {n}")
    passed = sum(1 for r in got.values() if r == "pass")
    print(f"{args.column}: {passed} pass of {len(got)}; {len(lost)} that passed before do not, {len(broken)} newly crash or hang")
    return 1 if lost or broken else 0


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--piglit", default=DEFAULT_PIGLIT)
    sub = p.add_subparsers(dest="cmd", required=True)
    groups_help = "sets or groups of groups.tsv, comma-separated (gl-1.1: the 1.0 and 1.1 groups); all by default"
    sub.add_parser("fetch")
    r = sub.add_parser("run")
    r.add_argument("--gl", choices=["mesa", "gleval"], default="gleval")
    r.add_argument("--platform", choices=["glx", "surfaceless_egl", "x11_egl"], default="glx")
    r.add_argument("--groups", help=groups_help)
    r.add_argument("--jobs", type=int, default=2)
    r.add_argument("--timeout", type=float, default=60)
    r.add_argument("--filter", help="a regular expression the test's name must match")
    r.add_argument("--logs", help="a folder for each test's output")
    r.add_argument("--out", required=True)
    r.add_argument("-v", "--verbose", action="store_true")
    t = sub.add_parser("table")
    t.add_argument("results", nargs="+")
    rep = sub.add_parser("report")
    rep.add_argument("results", nargs="+")
    rep.add_argument("--logs", nargs="*", help="each run's log folder (for the reasons), in the same order")
    g = sub.add_parser("groups")
    g.add_argument("results", nargs="+")
    e = sub.add_parser("expected")
    e.add_argument("mesa")
    e.add_argument("glx")
    e.add_argument("egl")
    e.add_argument("--groups", help="only these groups' rows from the runs; the rest kept from --out")
    e.add_argument("--out", default=os.path.join(HERE, "expected.tsv"))
    c = sub.add_parser("check")
    c.add_argument("expected")
    c.add_argument("results")
    c.add_argument("--column", required=True)
    c.add_argument("--groups", help="only the expected list's tests of these groups (" + groups_help + ")")
    args = p.parse_args()
    return {"fetch": fetch, "run": run, "table": table, "report": report, "groups": summary, "expected": expected,
            "check": check}[args.cmd](args)


if __name__ == "__main__":
    sys.exit(main())
