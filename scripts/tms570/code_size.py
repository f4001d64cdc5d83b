#!/usr/bin/env python3
"""Code size of the SRDO, GFC and CRC modules in a linked TMS570 image.

usage: code_size.py <image.elf> [--files] [--functions N]

After link-time optimisation most SRDO code is inlined into a few large
functions (`Stack::poll` holds the frame dispatch of every module), so the
symbol table alone under-counts it. This script attributes every byte of
executable code to the source file the DWARF line table names for it:

* a byte belongs to SRDO+GFC+CRC when its line-table row points into
  src/srdo/ (SRDO, GFC, configuration check, CRC stream), src/wire/srdo.rs
  (frame format), src/ffi/srdo.rs (the Ccm*Srdo*/Srdo* C functions) or the
  `crc` crate;
* a row from Rust's core library (an inlined `slice::get`, iterator, ...)
  counts for the crate file of the nearest preceding row in the same
  function, i.e. for the code it was inlined into; core rows at the start
  of a function count for the function's first crate row;
* bytes of a function that no row covers (literal pools, padding) count
  for the function's own file, as above.

Constant data: named read-only objects whose demangled name contains
`srdo` (the 512-byte CRC table `cop::srdo::crc::CRC16`, ...). Compiler-
generated anonymous constants (jump tables) have no name and are not
counted. The whole image (`arm-none-eabi-size`: text, data, bss) is printed
as well, so the share of the modules can be judged.

Output: `key=value` lines (srdo_code, srdo_rodata, srdo_total, text, data,
bss); `--files` adds the bytes per source file; `--functions N` adds the N
functions holding the most SRDO+GFC+CRC bytes (`function <SRDO+GFC+CRC
bytes> <function size> <name>`), largest first.
"""

import re
import subprocess
import sys
from collections import defaultdict

TOOLS = "arm-none-eabi-"


def run(*args):
    return subprocess.run(args, check=True, capture_output=True, text=True).stdout


def is_core(path):
    return "/rustlib/src/rust/library/" in path


def is_safety(path):
    p = path.replace("\\", "/")
    if re.search(r"/crc-[0-9][^/]*/src/", p):
        return True
    return bool(
        re.search(r"(^|/)src/srdo/", p)
        or p.endswith("src/wire/srdo.rs")
        or p.endswith("src/ffi/srdo.rs")
    )


def functions(elf):
    """(start, end, name) of every function symbol, sorted."""
    out = []
    for line in run(TOOLS + "nm", "-S", "-C", "--defined-only", elf).splitlines():
        parts = line.split(None, 3)
        if len(parts) == 4 and parts[2] in "tTwW":
            start, size = int(parts[0], 16) & ~1, int(parts[1], 16)
            if size:
                out.append((start, start + size, parts[3]))
    return sorted(out)


def line_rows(elf):
    """Sorted (address, path or None for end of sequence)."""
    rows = []
    path = None
    text = run(TOOLS + "objdump", "--dwarf=decodedline", elf)
    for line in text.splitlines():
        s = line.strip()
        if not s:
            continue
        if s.endswith(":") and " " not in s:
            path = s[:-1]
            continue
        cols = s.split()
        if len(cols) >= 3 and re.fullmatch(r"0x[0-9a-fA-F]+|0", cols[2]):
            rows.append((int(cols[2], 16), None if cols[1] == "-" else path))
    # At one address the last row wins; an end-of-sequence row never
    # hides a real row that starts there.
    by_addr = {}
    for addr, p in rows:
        if p is not None or addr not in by_addr:
            by_addr[addr] = p
    return sorted(by_addr.items())


def rodata(elf):
    total = 0
    names = []
    for line in run(TOOLS + "nm", "-S", "-C", "--defined-only", elf).splitlines():
        parts = line.split(None, 3)
        if len(parts) == 4 and parts[2] in "rR" and "srdo" in parts[3].lower():
            total += int(parts[1], 16)
            names.append((parts[3], int(parts[1], 16)))
    return total, names


def image_sizes(elf):
    lines = run(TOOLS + "size", elf).splitlines()
    text, data, bss = lines[1].split()[:3]
    return int(text), int(data), int(bss)


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    elf = sys.argv[1]
    funcs = functions(elf)
    rows = line_rows(elf)
    per_file = defaultdict(int)
    per_function = []
    safety = 0
    r = 0
    for start, end, name in funcs:
        # Rows that fall into this function, as (from, to, path).
        while r < len(rows) and rows[r][0] < start:
            r += 1
        spans = []
        current = None
        # The row in force at the function's start (if one began before).
        if r > 0 and rows[r - 1][0] < start and rows[r - 1][1] is not None:
            current = rows[r - 1][1]
        pos = start
        k = r
        while k < len(rows) and rows[k][0] < end:
            addr, p = rows[k]
            if addr > pos:
                spans.append((pos, addr, current))
            pos, current = addr, p
            k += 1
        spans.append((pos, end, current))
        first_crate = next((p for _, _, p in spans if p and not is_core(p)), None)
        owner = first_crate
        in_function = 0
        for a, b, p in spans:
            if p and not is_core(p):
                owner = p
            who = owner or p or "?"
            per_file[who] += b - a
            if who and is_safety(who):
                safety += b - a
                in_function += b - a
        if in_function:
            per_function.append((in_function, end - start, name))
    ro, ro_names = rodata(elf)
    text, data, bss = image_sizes(elf)
    print(f"srdo_code={safety}")
    print(f"srdo_rodata={ro}")
    print(f"srdo_total={safety + ro}")
    print(f"text={text}")
    print(f"data={data}")
    print(f"bss={bss}")
    if "--files" in sys.argv:
        for path, n in sorted(per_file.items(), key=lambda x: -x[1]):
            mark = "*" if is_safety(path) else " "
            print(f"file {mark} {n:7d} {path}")
        for name, n in ro_names:
            print(f"rodata * {n:7d} {name}")
    if "--functions" in sys.argv:
        i = sys.argv.index("--functions")
        top = int(sys.argv[i + 1]) if i + 1 < len(sys.argv) else 10
        for n, size, name in sorted(per_function, key=lambda x: (-x[0], x[2]))[:top]:
            print(f"function {n:7d} {size:7d} {name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
