#!/usr/bin/env python3
"""Where the instructions of one measured call go, by part of the library.

    bench/where.py ROOT N RUN_N.out RUN_2N.out [BASE_N.out BASE_2N.out]

RUN_N / RUN_2N are callgrind profiles of the same scenario, one with N and
one with 2N calls of the measured function (ROOT: the repository, to tell
its source files). With BASE_N / BASE_2N (a second scenario, measured the
same way), the second scenario's figures are subtracted: a received pair is
the cycle that reads it minus an idle cycle. For every (source line's file,
function) pair of the self cost that `callgrind_annotate --inclusive=no`
prints, the difference between the two runs divided by N is what one call
spends there, so the rows add up to the per-call figure of the benchmark
table (set-up and start-up cancel out).

A row is counted for the part of the source file the line belongs to (after
inlining, a function holds lines of many files); lines of the Rust core
library count for the function they were inlined into. Prints a Markdown
table: part, instructions per call, share, and the functions holding most
of them.
"""

import re
import subprocess
import sys
from collections import defaultdict

# (part, how to recognise it): the first match wins; tested against the
# source file when the line is the project's, else against the function.
PARTS = [
    ("application and driver (C: bench/capi/capi.c)", r"bench/capi/|^(measure_|Cdrv|App|Tgt)"),
    ("C edge: exported functions, instance registry, driver port (src/ffi/)", r"src/ffi/|^Ccm|^Srdo|cop::ffi::"),
    ("SRDO/GFC core (src/srdo/, src/wire/srdo.rs)", r"src/srdo/|src/wire/srdo\.rs|cop::srdo::"),
    ("PDO (src/pdo/)", r"src/pdo/|cop::pdo::"),
    ("dictionary (src/od/)", r"src/od/|cop::od::"),
    ("stack: cycle phases, dispatch, action queue (src/ccm*, src/event.rs, src/port.rs)",
     r"src/ccm|src/event\.rs|src/port\.rs|cop::ccm::|cop::event::"),
    ("other services (NMT, heartbeat, SYNC, SDO, EMCY, ...)", r"src/"),
]

LINE = re.compile(r"^\s*([\d,]+)\s+(?:\([^)]*\)\s+)?(\S.*?):(.+?)(?:\s+\[[^\]]*\])?\s*$")


def self_costs(path):
    """{(file, function): Ir} of one profile."""
    out = subprocess.run(
        ["callgrind_annotate", "--inclusive=no", "--threshold=100", "--auto=no", path],
        check=True, capture_output=True, text=True).stdout
    costs = {}
    in_table = False
    for line in out.splitlines():
        if "file:function" in line:
            in_table = True
            continue
        if not in_table:
            continue
        m = LINE.match(line)
        if m:
            costs[(m.group(2), m.group(3))] = int(m.group(1).replace(",", ""))
    return costs


def part_of(file, function, root):
    # callgrind_annotate prints the repository's files relative to the
    # working directory, or absolute.
    # ("???": no line information, as for C compiled without -g.)
    own = file != "???" and (file.startswith(root) or not file.startswith("/"))
    key = file.removeprefix(root).lstrip("/") if own else function
    for name, pattern in PARTS:
        if re.search(pattern, key):
            return name
    if not own and function.startswith("cop::"):
        return PARTS[-1][0]
    return "other (C library, start-up)"


def short(function):
    """A function name without crate path noise and generic arguments."""
    f = re.sub(r"^<([^<>]*?) as [^<>]*>", r"\1", function)
    f = re.sub(r"<[^<>]*>", "", re.sub(r"<[^<>]*>", "", f))
    f = f.replace("cop::", "")
    return f.split(" ")[0]


def main():
    root, n = sys.argv[1], int(sys.argv[2])
    profiles = [self_costs(p) for p in sys.argv[3:]]
    if len(profiles) not in (2, 4):
        sys.exit("usage: where.py ROOT N RUN_N RUN_2N [BASE_N BASE_2N]")
    parts = defaultdict(float)
    funcs = defaultdict(lambda: defaultdict(float))
    keys = set().union(*profiles)
    for key in keys:
        per = [p.get(key, 0) for p in profiles]
        d = (per[1] - per[0]) / n
        if len(per) == 4:
            d -= (per[3] - per[2]) / n
        if abs(d) < 0.05:
            continue
        part = part_of(key[0], key[1], root)
        parts[part] += d
        funcs[part][short(key[1])] += d
    total = sum(parts.values())
    print("| part | instructions | share | mostly in |")
    print("|---|---|---|---|")
    for part, v in sorted(parts.items(), key=lambda kv: -kv[1]):
        if round(v) == 0:
            continue
        top = sorted(funcs[part].items(), key=lambda kv: -abs(kv[1]))[:3]
        names = ", ".join(f"`{f}` {c:.0f}" for f, c in top if round(c) != 0)
        print(f"| {part} | {v:.0f} | {100 * v / total:.0f} % | {names} |")
    print(f"| **total** | **{total:.0f}** | 100 % | |")


if __name__ == "__main__":
    main()
