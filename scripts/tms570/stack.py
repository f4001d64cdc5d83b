#!/usr/bin/env python3
"""Worst-case stack depth of a linked TMS570 image, from a static call graph.

    stack.py --elf IMAGE --su DIR [--su DIR ...] [--entries FILE] [--report NAME ...]
             [--indirect SITE=TARGETS ...] [--pump REGEX] [--limit NAME=BYTES ...] [--markdown]

Frame sizes:
  * Rust functions (libcop.a, core): the compiler's own figure, the
    .stack_sizes section that -Z emit-stack-sizes puts into the image
    (address of the function, ULEB128 bytes);
  * C functions: the .su files of gcc -fstack-usage (DIR, searched
    recursively); a "dynamic" frame is an error;
  * anything else (start-up assembly, libgcc routines): the prologue in the
    disassembly (push/stmdb/vpush registers, sub sp), marked "asm".

Calls come from the disassembly (arm-none-eabi-objdump -d): bl/blx <f> are
calls, b<cond> <f> to another function's first instruction is a tail call
(the callee runs on the caller's entry stack). An indirect call (blx rN,
bx rN other than lr) may reach every function whose address is stored
anywhere in the image (tables, literal pools) or built by a movw/movt pair:
the address-taken set.
--indirect SITE=TARGETS narrows that set for the call sites in functions
whose name (demangled, without crate hashes) matches SITE, to the
address-taken functions matching the regex TARGETS, or, with
TARGETS = @SYM[,SYM...], to the functions whose addresses the data objects
SYM hold (a C table of function pointers such as an application's
tCopStoreDriver: a call through one of its fields reaches only what it
holds). A target matches when any name of its body does (the compiler
gives identical functions one body). The first rule whose SITE matches
applies. A rule is sound only
for a site whose every pointer call is of the named kind, so the library
keeps such calls in functions of their own (store::Nv's methods for the
storage driver); a rule must not name targets that match its own SITE
(or a chain of rules leading back to it), or the graph has a cycle that
is no recursion of the program, which fails as recursion. The rules
run.sh gives:
  * <store::Nv as NvMemory>::*  ->  the StorageDriver implementations
    (the store module's only call through a pointer: its image code is
    generic, its visitors are called directly);
  * <ffi::services::CStore (as StorageDriver)>::*  ->  @Driver_l, the
    functions of the application's tCopStoreDriver (store_sim.c's; the
    adapter's methods are the only callers of the driver's functions);
  * dictionary accesses and ObdVarEntry::notify  ->  every address-taken
    function but App* / ObdInitRam* (OBD and variable callbacks).
The library never calls an application callback while another one runs
(--nonnesting, and indirect calls outside the --indirect rules); the OBD
callbacks of a dictionary access can run inside one. The --pump functions
(the C API's event pump loop) are never entered while one of them runs:
pump() returns at once while its pumping flag is set, so a Ccm* call made
from a callback does not reach the stack's processing again. Any cycle
left is recursion and an error.

depth(f) = max(frame(f) + max depth(called), max depth(tail-called)).
The output is one line per entry point (every function named in FILE, or
given with --report) with its depth and the deepest path.
"""
import argparse
import os
import re
import struct
import subprocess
import sys


def read_sections(path):
    """ELF32 section headers: name -> (addr, offset, size, flags)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] != b"\x7fELF" or data[4] != 1:
        sys.exit("stack.py: %s is not an ELF32 file" % path)
    end = ">" if data[5] == 2 else "<"
    shoff, = struct.unpack_from(end + "I", data, 0x20)
    shentsize, shnum, shstrndx = struct.unpack_from(end + "HHH", data, 0x2E)
    heads = []
    for i in range(shnum):
        heads.append(struct.unpack_from(end + "IIIIIIIIII", data, shoff + i * shentsize))
    strtab = heads[shstrndx]
    sections = {}
    for h in heads:
        name_off = strtab[4] + h[0]
        name = data[name_off:data.index(b"\0", name_off)].decode()
        sections[name] = (h[3], h[4], h[5], h[2], h[1])  # addr, offset, size, flags, type
    return data, end, sections


def stack_sizes(data, end, sections):
    """The .stack_sizes entries: function address -> bytes."""
    sizes = {}
    if ".stack_sizes" not in sections:
        return sizes
    _, off, size, _, _ = sections[".stack_sizes"]
    pos, stop = off, off + size
    while pos < stop:
        addr, = struct.unpack_from(end + "I", data, pos)
        pos += 4
        value, shift = 0, 0
        while True:
            byte = data[pos]
            pos += 1
            value |= (byte & 0x7F) << shift
            shift += 7
            if byte < 0x80:
                break
        sizes[addr & ~1] = value
    return sizes


def address_words(data, end, sections):
    """Every aligned 32-bit word of the loaded data sections. Code sections
    are left out: an instruction's encoding can equal a function's address
    by chance (on a big-endian BE-8 image the little-endian instruction
    `bic r0, sl, r0` reads as 0x0000cae1); the literal pools in them come
    from the disassembly's `.word` lines instead (see `disassemble`)."""
    words = set()
    for name, (addr, off, size, flags, typ) in sections.items():
        # SHF_ALLOC, not SHF_EXECINSTR, not NOBITS
        if not flags & 0x2 or flags & 0x4 or typ == 8:
            continue
        for pos in range(off, off + size - 3, 4):
            words.add(struct.unpack_from(end + "I", data, pos)[0] & ~1)
    return words


def su_frames(root):
    """gcc -fstack-usage: function name -> (bytes, qualifier)."""
    frames = {}
    for base, _, files in os.walk(root):
        for name in files:
            if not name.endswith(".su"):
                continue
            with open(os.path.join(base, name)) as f:
                for line in f:
                    parts = line.rstrip("\n").split("\t")
                    if len(parts) != 3:
                        continue
                    func = parts[0].rsplit(":", 1)[-1]
                    size = int(parts[1])
                    old = frames.get(func)
                    if old is None or old[0] < size:
                        frames[func] = (size, parts[2])
    return frames


FUNC_RE = re.compile(r"^([0-9a-f]+) <(.+)>:$")
INSN_RE = re.compile(r"^\s+([0-9a-f]+):\t(\S+)\t?(.*)$")
TARGET_RE = re.compile(r"^([0-9a-f]+) <([^>+]+)(\+0x[0-9a-f]+)?>")
REG_LIST_RE = re.compile(r"\{([^}]*)\}")


def reg_count(text):
    m = REG_LIST_RE.search(text)
    if not m:
        return 0
    n = 0
    for part in m.group(1).split(","):
        part = part.strip()
        if "-" in part:
            a, b = part.split("-")
            n += int(re.sub(r"\D", "", b)) - int(re.sub(r"\D", "", a)) + 1
        elif part:
            n += 1
    return n


def disassemble(elf, objdump):
    out = subprocess.run([objdump, "-d", "--no-show-raw-insn", elf], check=True,
                         stdout=subprocess.PIPE, universal_newlines=True).stdout
    funcs = {}  # name -> dict(addr, calls, tails, indirect, asm_frame)
    # Addresses built with movw/movt, and the literal-pool words of the code
    # (objdump prints them as `.word`, telling data from code by the ELF's
    # mapping symbols).
    consts = set()
    low = {}
    cur, cur_name = None, None
    for line in out.splitlines():
        m = FUNC_RE.match(line)
        if m:
            cur_name = m.group(2)
            cur = {"addr": int(m.group(1), 16), "calls": set(), "tails": set(),
                   "indirect": 0, "asm": 0, "prologue": True}
            funcs[m.group(2)] = cur
            continue
        m = INSN_RE.match(line)
        if m and m.group(2) == ".word":
            consts.add(int(m.group(3).split()[0], 16) & ~1)
            continue
        if not m or cur is None:
            continue
        op, args = m.group(2), m.group(3)
        mv = re.match(r"(r\d+|ip|lr|fp|sl), #(\d+)", args)
        if op == "movw" and mv:
            low[mv.group(1)] = int(mv.group(2))
        elif op == "movt" and mv and mv.group(1) in low:
            consts.add(((int(mv.group(2)) << 16) | low[mv.group(1)]) & ~1)
        if cur["prologue"]:
            if op in ("push", "stmdb") and ("sp!" in args or op == "push"):
                cur["asm"] += 4 * reg_count(args)
                continue
            if op == "vpush":
                cur["asm"] += 8 * reg_count(args)
                continue
            sm = re.match(r"sp, sp, #(\d+)", args)
            if op == "sub" and sm:
                cur["asm"] += int(sm.group(1))
                continue
            cur["prologue"] = False
        base = re.sub(r"\.w$|\.n$", "", op)
        t = TARGET_RE.match(args)
        if base in ("bl", "blx") and t:
            cur["calls"].add(t.group(2))
        elif base in ("blx",) or (base == "bx" and args.strip() != "lr"):
            cur["indirect"] += 1
        elif re.match(r"^b(eq|ne|cs|cc|hs|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le|al)?$", base) and t:
            if t.group(3) is None and t.group(2) != cur_name:
                cur["tails"].add(t.group(2))
    return funcs, consts


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--elf", required=True)
    ap.add_argument("--su", required=True, action="append",
                    help="directory of .su files (searched recursively; may be repeated)")
    ap.add_argument("--objdump", default="arm-none-eabi-objdump")
    ap.add_argument("--entries", help="file with one entry-point name a line")
    ap.add_argument("--report", action="append", default=[])
    ap.add_argument("--stop", default="",
                    help="regex: functions counted with their own frame only "
                         "(the application's side, for the library-only column)")
    ap.add_argument("--limit", action="append", default=[], help="NAME=BYTES: fail above")
    ap.add_argument("--markdown", action="store_true")
    ap.add_argument("--callbacks", default="",
                    help="regex: for every --report entry, the stack in use when each "
                         "matching function (the application's callbacks) is entered")
    ap.add_argument("--app-pointers", default="",
                    help="regex: address-taken functions the application calls through its own "
                         "pointers and never hands to the library")
    ap.add_argument("--indirect", action="append", default=[],
                    help="SITE=TARGETS: indirect calls in functions matching the regex SITE "
                         "reach only the address-taken functions matching the regex TARGETS, "
                         "or, for TARGETS @SYM[,SYM...], only the functions whose addresses "
                         "the data objects SYM hold (the first matching rule applies)")
    ap.add_argument("--pump", default="",
                    help="regex: functions never entered again while one of them runs "
                         "(the C API's event pump, guarded by its pumping flag)")
    ap.add_argument("--nonnesting", default="",
                    help="regex: application callbacks the library calls directly and "
                         "never while another one runs")
    ap.add_argument("--verbose", action="store_true", help="every frame of each deepest path")
    args = ap.parse_args()

    data, end, sections = read_sections(args.elf)
    rust = stack_sizes(data, end, sections)
    csu = {}
    for d in args.su:
        for k, v in su_frames(d).items():
            if k not in csu or csu[k][0] < v[0]:
                csu[k] = v
    funcs, consts = disassemble(args.elf, args.objdump)
    # Functions with one body share an address; the disassembly names one,
    # a rule's target may match another of its names.
    names_at = {}
    nm = subprocess.run([args.objdump.replace("objdump", "nm"), args.elf], check=True,
                        stdout=subprocess.PIPE, universal_newlines=True).stdout
    for line in nm.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[1] in "Tt":
            names_at.setdefault(int(parts[0], 16) & ~1, set()).add(parts[2])
    demangle_all(list(funcs) + [n for ns in names_at.values() for n in ns])
    by_addr = {f["addr"]: name for name, f in funcs.items()}
    taken = sorted(by_addr[a] for a in (address_words(data, end, sections) | consts) & set(by_addr))

    frame, source = {}, {}
    errors = []
    for name, f in funcs.items():
        plain = re.sub(r"\.\d+$", "", name)
        if f["addr"] in rust:
            frame[name], source[name] = rust[f["addr"]], "rust"
        elif name in csu or plain in csu:
            size, qual = csu.get(name) or csu[plain]
            if "dynamic" in qual and "bounded" not in qual:
                errors.append("%s: dynamic stack frame (%s)" % (name, qual))
            frame[name], source[name] = size, "c"
        else:
            frame[name], source[name] = f["asm"], "asm"

    stop = re.compile(args.stop) if args.stop else None
    memo = {}

    cb = re.compile(args.callbacks) if args.callbacks else re.compile(r"$^")
    app_ptr = re.compile(args.app_pointers) if args.app_pointers else None
    objects = data_objects(args)
    rules = []
    for x in args.indirect:
        site, targets = x.split("=", 1)
        if targets.startswith("@"):
            held = set()
            for sym in targets[1:].split(","):
                if sym not in objects:
                    errors.append("--indirect %s: no data object %s in the image" % (x, sym))
                    continue
                held |= set(by_addr[a] for a in words_of(data, end, sections, *objects[sym])
                            if a in by_addr)
            rules.append((re.compile(site), held))
        else:
            rules.append((re.compile(site), re.compile(targets)))

    def targeted(rule, c):
        if isinstance(rule, set):
            return c in rule
        names = {c} | names_at.get(funcs[c]["addr"], set())
        return any(rule.search(rule_name(n)) is not None for n in names)

    nonnest = re.compile(args.nonnesting) if args.nonnesting else None
    pump = re.compile(args.pump) if args.pump else None

    def edges_of(name, state):
        """(callee, child state, pushes own frame) of the calls that can run.

        state = (in_cb, in_pump). in_cb: an application callback is running.
        The library never calls a second one then (callbacks are never
        nested: what a callback causes is queued until it has returned),
        except the OBD callbacks of a dictionary access (--indirect rules),
        which can run inside one. in_pump: a --pump function is running; no
        --pump function is entered then."""
        in_cb, in_pump = state
        f = funcs[name]
        lib = source[name] == "rust"
        out = []

        def add(c, child_cb, pushes):
            is_pump = pump is not None and pump.search(rule_name(c)) is not None
            if is_pump and in_pump:
                return  # the pump returns at once while it runs
            out.append((c, (child_cb, in_pump or is_pump), pushes))

        for c in f["calls"]:
            if lib and nonnest is not None and nonnest.search(c):
                if not in_cb:
                    add(c, True, True)
            else:
                add(c, in_cb, True)
        for c in f["tails"]:
            add(c, in_cb, False)
        if f["indirect"]:
            rule = next((t for s_, t in rules if s_.search(rule_name(name))), None)
            if rule is None and lib and in_cb:
                return out
            for c in (sorted(rule) if isinstance(rule, set) else taken):
                if lib and app_ptr is not None and app_ptr.search(c):
                    continue  # a pointer the application never hands to the library
                if rule is not None and not targeted(rule, c):
                    continue  # not of the pointer type this call site calls
                add(c, in_cb or (lib and rule is None), True)
        return out

    def depth(name, path, state, lib_only):
        key = (name, state, lib_only)
        if key in memo:
            return memo[key]
        if name not in funcs:
            errors.append("%s: called but not in the image" % name)
            return (0, [name])
        own = frame[name]
        if lib_only and stop is not None and stop.search(name) and path:
            memo[key] = (0, [name])  # the application's side counts 0 here
            return memo[key]
        best_call, best_path = 0, []
        best_tail, tail_path = 0, []
        here = path + [(name, state)]
        for callee, child, pushes in edges_of(name, state):
            if (callee, child) in here:
                errors.append("recursion: %s" % " -> ".join(demangle_short(x) for x, _ in here + [(callee, 0)]))
                continue
            d, p = depth(callee, here, child, lib_only)
            if not pushes:
                if d > best_tail:
                    best_tail, tail_path = d, p
            elif d > best_call:
                best_call, best_path = d, p
        if own + best_call >= best_tail:
            result = (own + best_call, [name] + best_path)
        else:
            result = (best_tail, [name + " (tail)"] + tail_path)
        memo[key] = result
        return result

    entries = list(args.report)
    if args.entries:
        with open(args.entries) as f:
            entries += [line.strip() for line in f if line.strip()]
    entries = list(dict.fromkeys(entries))  # once each, in order
    # The other names of a body (see names_at) as entry points.
    for line in nm.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[1] in "Tt" and parts[2] not in funcs:
            other = by_addr.get(int(parts[0], 16) & ~1)
            if other is not None:
                funcs[parts[2]] = funcs[other]
                frame[parts[2]], source[parts[2]] = frame[other], source[other]
    limits = dict((k, int(v)) for k, v in (x.split("=") for x in args.limit))
    failed = False
    rows = []
    for e in entries:
        if e not in funcs:
            rows.append((e, None, None, []))
            continue
        full, path = depth(e, [], START, False)
        lib = depth(e, [], START, True)[0] if stop else full
        rows.append((e, full, lib, path))
        if e in limits and full > limits[e]:
            failed = True
            errors.append("%s: %d bytes, limit %d" % (e, full, limits[e]))
    cb_rows = []
    if args.callbacks:
        for e in args.report:
            if e not in funcs:
                continue
            best = {}  # (function, state) -> most stack in use on entry
            todo = [(e, 0, (e,), START)]
            while todo:
                name, used, path, state = todo.pop()
                if name not in funcs or best.get((name, state), -1) >= used:
                    continue
                best[(name, state)] = used
                if cb.search(name) and name != e:
                    continue  # the callback's own depth is added below
                for callee, child, pushes in edges_of(name, state):
                    if callee in path:
                        continue
                    todo.append((callee, used + (frame[name] if pushes else 0), path + (callee,), child))
            worst = {}
            for (name, state), used in best.items():
                if cb.search(name) and name != e:
                    # The callback runs as one (in_cb), in the pump or not.
                    d = depth(name, [], (True, state[1]), False)[0]
                    if name not in worst or used + d > sum(worst[name]):
                        worst[name] = (used, d)
            for name in sorted(worst):
                cb_rows.append((e, name) + worst[name])
    demangle_all(p[:-7] if p.endswith(" (tail)") else p for row in rows for p in row[3])
    if args.markdown:
        print("| entry point | library alone | with the demo's callbacks, driver and C library | deepest path |")
        print("|---|---:|---:|---|")
    for e, full, lib, path in rows:
        if full is None:
            print(("| `%s` | - | - | not linked |" if args.markdown else "stack %-28s not in the image") % e)
            continue
        shown = " > ".join(demangle_short(p) for p in path[:8]) + (" > ..." if len(path) > 8 else "")
        if args.markdown:
            print("| `%s` | %d | %d | %s |" % (e, lib, full, shown))
        else:
            print("stack %-28s %5d bytes (library alone %5d)  %s" % (e, full, lib, shown))
    if cb_rows:
        if args.markdown:
            print()
            print("| called from | callback | stack in use on entry | callback's own depth | total |")
            print("|---|---|---:|---:|---:|")
        for e, name, used, d in cb_rows:
            if args.markdown:
                print("| `%s` | `%s` | %d | %d | %d |" % (e, name, used, d, used + d))
            else:
                print("callback %-14s %-26s entered with %5d bytes in use, own depth %5d, total %5d"
                      % (e, name, used, d, used + d))
    if args.verbose:
        for e, full, lib, path in rows:
            for p in path:
                q = p[:-7] if p.endswith(" (tail)") else p
                print("    %-60s %5d %s" % (demangle_short(p), frame.get(q, 0), source.get(q, "")))
    counts = {}
    for s in source.values():
        counts[s] = counts.get(s, 0) + 1
    print("frames: %d from .stack_sizes, %d from gcc -fstack-usage, %d from prologues; "
          "%d address-taken functions as indirect-call targets"
          % (counts.get("rust", 0), counts.get("c", 0), counts.get("asm", 0), len(taken)),
          file=sys.stderr)
    for e in sorted(set(errors)):
        print("ERROR " + e, file=sys.stderr)
    sys.exit(1 if errors or failed else 0)


START = (False, False)  # (in a callback, in the pump) at an entry point
DEMANGLED = {}
FULL = {}


def rule_name(name):
    """The name --indirect, --pump match: demangled, without crate hashes
    (C names as they are)."""
    return FULL.get(name, name)


def data_objects(args):
    """Data symbols of the image: name -> (address, size)."""
    nm = subprocess.run([args.objdump.replace("objdump", "nm"), "-S", args.elf], check=True,
                        stdout=subprocess.PIPE, universal_newlines=True).stdout
    objects = {}
    for line in nm.splitlines():
        parts = line.split()
        if len(parts) == 4 and parts[2] in "dDrRbB":
            objects[parts[3]] = (int(parts[0], 16), int(parts[1], 16))
    return objects


def words_of(data, end, sections, addr, size):
    """The aligned 32-bit words of [addr, addr + size) in the image (as code
    addresses: the Thumb bit cleared)."""
    out = []
    for sec_addr, off, sec_size, flags, typ in sections.values():
        if typ == 8 or not flags & 0x2 or not sec_addr <= addr < sec_addr + sec_size:
            continue
        for a in range(addr, min(addr + size, sec_addr + sec_size) - 3, 4):
            out.append(struct.unpack_from(end + "I", data, off + a - sec_addr)[0] & ~1)
    return out


def demangle_all(names):
    """Readable names (arm-none-eabi-c++filt reads Rust v0 names), without
    crate hashes and generic arguments."""
    names = sorted(set(n for n in names if n.startswith("_R")))
    if not names:
        return
    out = subprocess.run(["arm-none-eabi-c++filt"], input="\n".join(names) + "\n", check=True,
                         stdout=subprocess.PIPE, universal_newlines=True).stdout.splitlines()
    for raw, nice in zip(names, out):
        nice = re.sub(r"\[[0-9a-f]+\]", "", nice)
        FULL[raw] = nice
        prev = None
        while prev != nice:  # innermost generic arguments first
            prev = nice
            nice = re.sub(r"::<[^<>]*>", "", nice)
            nice = re.sub(r"(?<=\w)<[^<>]*>", "", nice)
        nice = re.sub(r"^<(.*) as [^<>]*>", r"\1", nice)
        nice = re.sub(r"^<([^<>]*)>", r"\1", nice)
        nice = re.sub(r"^cop::", "", nice)
        DEMANGLED[raw] = nice


def demangle_short(name):
    tail = name.endswith(" (tail)")
    base = name[:-7] if tail else name
    return DEMANGLED.get(base, base) + (" (tail)" if tail else "")


if __name__ == "__main__":
    main()
