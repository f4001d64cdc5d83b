#!/usr/bin/env python3
"""Combines the cargo-mutants runs of scripts/evidence.sh (one output folder
per file and switch configuration) into one result per mutant: caught when
any configuration that builds it catches it. Survivors are compared with the
equivalent mutants listed, with their argument, in EQUIV; a survivor not
listed there fails (exit 1).

Configurations: RUNS_DIR/cfg-<configuration>.txt holds the cfg set of each
configuration (`rustc --print cfg` of the library, written by
scripts/evidence.sh). A mutant in a function that a configuration compiles
out (a `#[cfg(...)]` on the function or on its `impl` block that the set
does not satisfy) changes nothing there, so its "missed" in that
configuration is not counted; its outcome comes from the configurations
that build it.

Earlier results: a file with no run in RUNS_DIR keeps its figures, its runs
and its survivors from the OUT_JSON written before (runs are scratch; the
committed result is not lost when one file is mutated again). A file whose
runs are all survivor runs (folders named <file>-<configuration>-survivors,
made by `scripts/evidence.sh mutants --survivors`, which tests only the
recorded survivors) keeps its recorded figures (its base, from its last
complete run) too, with each survivor updated: caught when a run now
catches it, unviable when every configuration that builds it found it so,
else still missed. A complete run of a file replaces its figures.

  mutants.py RUNS_DIR OUT_JSON EQUIV_TOML
  mutants.py --survivor-re FILE OUT_JSON   (the --re of a survivor run)
"""
import json
import pathlib
import re
import sys
import tomllib

RANK = {"caught": 3, "timeout": 2, "missed": 1, "unviable": 0}
# previously_caught.txt (--iterate) lumps caught and unviable together: the
# outcomes come from the runs' own files instead (the current mutants.out,
# cargo-mutants' mutants.out.old and the copies scripts/evidence.sh keeps in
# runs/).
FILES = {o: [f"{o}.txt"] for o in RANK}
LOC = re.compile(r"^(?P<file>[^:]+):(?P<line>\d+):(?P<col>\d+): (?P<what>.*)$")
FN = re.compile(r"^\s*(pub(\([^)]*\))?\s+)?(const\s+)?(unsafe\s+)?(extern\s+\"C\"\s+)?fn\s+\w+")
IMPL = re.compile(r"^(unsafe\s+)?impl\b")
CFG = re.compile(r"^\s*#\[cfg\((?P<pred>.*)\)\]\s*$")


def run_name(file):
    """The folder name scripts/evidence.sh gives a file's runs (without
    the configuration): src/wire/srdo.rs -> wire-srdo."""
    return file.removeprefix("src/").removesuffix(".rs").replace("/", "-")


def key(text):
    m = LOC.match(text.strip())
    return (m.group("file"), m.group("what"), int(m.group("line")), int(m.group("col"))) if m else None


def cfg_holds(pred, cfgs):
    """Evaluates a cfg predicate (`name`, `name = "v"`, `not(..)`,
    `all(..)`, `any(..)`) against a set of `rustc --print cfg` lines."""
    tokens = re.findall(r'\w+|"[^"]*"|[(),=]', pred)
    pos = 0

    def take():
        nonlocal pos
        pos += 1
        return tokens[pos - 1]

    def parse():
        name = take()
        if pos < len(tokens) and tokens[pos] == "(" and name in ("not", "all", "any"):
            take()
            args = []
            while tokens[pos] != ")":
                args.append(parse())
                if tokens[pos] == ",":
                    take()
            take()
            if name == "not":
                return not args[0]
            return all(args) if name == "all" else any(args)
        if pos < len(tokens) and tokens[pos] == "=":
            take()
            return f"{name}={take()}" in cfgs
        return name in cfgs

    return parse()


SOURCES = {}


def gates(file, line):
    """The cfg predicates on the function that holds `line` and on its
    `impl` block (the attribute lines right above each)."""
    if file not in SOURCES:
        p = pathlib.Path(file)
        SOURCES[file] = p.read_text().splitlines() if p.exists() else []
    src = SOURCES[file]
    found = []
    for pattern in (FN, IMPL):
        at = next((i for i in range(min(line, len(src)) - 1, -1, -1) if pattern.match(src[i])), None)
        if at is None:
            continue
        i = at - 1
        while i >= 0 and src[i].strip().startswith(("#[", "///", "//")):
            m = CFG.match(src[i])
            if m:
                found.append(m.group("pred"))
            i -= 1
    return found


def built(file, line, cfgs):
    return all(cfg_holds(p, cfgs) for p in gates(file, line))


def config_of(run, configs):
    """The configuration a run folder was made in: the longest
    configuration name in it (wire-srdo-variant-a -> variant-a)."""
    names = [c for c in configs if f"-{c}" in f"-{run}"]
    return max(names, key=len) if names else None


def survivor_re(file, out_json):
    """A cargo-mutants --re for the survivors in the base of `file` (any
    column: the text and line name a mutant)."""
    result = json.loads(pathlib.Path(out_json).read_text())
    base = result.get("base", {}).get(file, {}).get("survivors")
    entries = base if base is not None else [e for e in result["survivors"] if e["file"] == file]

    def esc(text):
        return re.sub(r"([\\.^$|?*+()\[\]{}])", r"\\\1", text)

    return "|".join(sorted({f"^{esc(file)}:{e['line']}:[0-9]+: {esc(e['mutant'])}$" for e in entries}))


def main():
    if sys.argv[1] == "--survivor-re":
        print(survivor_re(sys.argv[2], sys.argv[3]))
        return
    runs, out_json, equiv_path = sys.argv[1:4]
    # (file, mutant text) -> [(line or None, argument)]: an entry with a
    # line explains only the mutant at that line (the text names the
    # operator and function, which several mutants can share).
    listed = {}
    p = pathlib.Path(equiv_path)
    if p.exists():
        for e in tomllib.loads(p.read_text()).get("equivalent", []):
            listed.setdefault((e["file"], e["mutant"]), []).append((e.get("line"), e["argument"]))

    def argument(file, what, line):
        return next((a for at, a in listed.get((file, what), []) if at in (None, line)), None)
    base = pathlib.Path(runs)
    cfg_sets = {f.stem.removeprefix("cfg-"): set(f.read_text().split())
                for f in base.glob("cfg-*.txt")}
    # Per mutant: the best outcome in each configuration (and its run).
    records, configs, not_built, full_run = {}, {}, set(), set()
    outs = sorted(base.glob("*/mutants.out")) + sorted(base.glob("*/mutants.out.old")) + sorted(base.glob("*/runs/*"))
    for d in outs:
        run = d.parent.name if d.name.startswith("mutants.out") else d.parent.parent.name
        survivor_run = run.endswith("-survivors")
        conf = config_of(run, cfg_sets) or run
        configs.setdefault(run, {})
        for outcome in RANK:
            text = "".join((d / n).read_text() + "\n" for n in FILES[outcome] if (d / n).exists())
            for line in text.splitlines():
                k = key(line)
                if k is None:
                    continue
                if not survivor_run:
                    full_run.add(k[0])
                configs[run][outcome] = configs[run].get(outcome, 0) + 1
                if outcome == "missed" and conf in cfg_sets and not built(k[0], k[2], cfg_sets[conf]):
                    not_built.add((k, conf))
                    continue
                per_conf = records.setdefault(k, {})
                prev = per_conf.get(conf)
                if prev is None or RANK[outcome] > RANK[prev[0]]:
                    per_conf[conf] = (outcome, run)
    mutants = {}
    for k, per_conf in records.items():
        outcome, run = max(per_conf.values(), key=lambda o: RANK[o[0]])
        mutants[k] = {"outcome": outcome, "run": run, "configs": per_conf}
    for k, conf in sorted(not_built):
        if k not in records:
            print(f"  note: {k[0]}:{k[2]}: {k[1]}: not built in {conf} and in no other run")

    before = json.loads(pathlib.Path(out_json).read_text()) if pathlib.Path(out_json).exists() else {}
    # A file's base: its figures and survivors from its last complete run
    # (kept in OUT_JSON while survivor runs update it).
    bases = dict(before.get("base", {}))
    for file, figures in before.get("files", {}).items():
        bases.setdefault(file, {"figures": figures,
                                "survivors": [e for e in before.get("survivors", []) if e["file"] == file]})
    new_files = {k[0] for k in mutants} | {k[0] for k, _ in not_built}
    # Files whose runs are all survivor runs (folders named ...-survivors,
    # `scripts/evidence.sh mutants --survivors`): their base is updated. A
    # survivor run may hold a few other mutants (cargo-mutants does not
    # filter every kind by --re); they are left as the base counts them.
    partial = {f for f in new_files if f in bases and f not in full_run}

    base_keys = {f: {(e["mutant"], e["line"]) for e in bases[f]["survivors"]} for f in partial}

    def in_base(k):
        return (k[1], k[2]) in base_keys[k[0]]

    strays = []
    for k, m in sorted(mutants.items()):
        if k[0] in partial and not in_base(k):
            print(f"  note: {k[0]}:{k[2]}: {k[1]}: {m['outcome']}, not a survivor: left as recorded")
            if m["outcome"] == "missed":
                strays.append({"file": k[0], "line": k[2], "mutant": k[1],
                               "argument": None, "note": "missed in a survivor run, not in the base: run the whole file"})
    per_file, survivors, unexplained = {}, [], []

    def survive(entry):
        entry["argument"] = argument(entry["file"], entry["mutant"], entry["line"])
        survivors.append(entry)
        if entry["argument"] is None:
            unexplained.append(entry)

    for (file, what, line, _col), m in sorted(mutants.items()):
        if file in partial:
            continue
        s = per_file.setdefault(file, {o: 0 for o in RANK} | {"equivalent": 0})
        o = m["outcome"]
        if o == "missed" and argument(file, what, line) is not None:
            o = "equivalent"
        s[o] += 1
        if m["outcome"] == "missed":
            survive({"file": file, "line": line, "mutant": what})

    for file in sorted(partial):
        s = dict(bases[file]["figures"])
        for entry in bases[file]["survivors"]:
            new = [m for k, m in mutants.items() if (k[0], k[1], k[2]) == (file, entry["mutant"], entry["line"])]
            best = max((m["outcome"] for m in new), key=RANK.get, default="missed")
            if best == "unviable":
                # Unviable only when every configuration that builds it
                # was run and none let it pass.
                builders = {c for c, cfgs in cfg_sets.items() if built(file, entry["line"], cfgs)}
                tried = set().union(*(m["configs"] for m in new)) if new else set()
                if not builders or not builders <= tried:
                    best = "missed"
            if best == "missed":
                survive(dict(entry))
                continue
            was = "equivalent" if entry.get("argument") is not None else "missed"
            s[was] -= 1
            s[best] += 1
            print(f"  updated: {file}:{entry['line']}: {entry['mutant']}: {best}")
        per_file[file] = s

    for entry in strays:
        survivors.append(entry)
        unexplained.append(entry)
    kept = sorted(set(before.get("files", {})) - set(per_file))
    for file in kept:
        per_file[file] = before["files"][file]
        for entry in before.get("survivors", []):
            if entry["file"] == file:
                survive(dict(entry))
    # Run names: the file's path below src/ with "-" for "/" (earlier
    # runs: the file's stem).
    stems = tuple(n + "-" for f in kept + sorted(partial)
                  for n in (pathlib.Path(f).stem, run_name(f)))
    renewed = tuple(run_name(f) + "-" for f in partial)
    for run, counts in before.get("runs", {}).items():
        # A survivor run replaces the one before it.
        if run.startswith(renewed) and run.endswith("-survivors"):
            continue
        if run not in configs and run.startswith(stems):
            configs[run] = counts
    # Recorded figures: the split of survivors into equivalent and missed
    # follows the arguments listed now.
    for file in kept + sorted(partial):
        s = per_file[file] = dict(per_file[file])
        mine = [e for e in survivors if e["file"] == file and "note" not in e]
        assert s["missed"] + s["equivalent"] == len(mine), f"{file}: survivors and figures differ"
        s["equivalent"] = sum(e["argument"] is not None for e in mine)
        s["missed"] = len(mine) - s["equivalent"]
    per_file = dict(sorted(per_file.items()))
    survivors.sort(key=lambda e: (e["file"], e["line"]))
    tot = {o: sum(s[o] for s in per_file.values()) for o in list(RANK) + ["equivalent"]}
    viable = tot["caught"] + tot["timeout"] + tot["missed"] + tot["equivalent"]
    score = 100.0 * (tot["caught"] + tot["timeout"]) / viable if viable else 0.0
    score_eq = (100.0 * (tot["caught"] + tot["timeout"]) / (viable - tot["equivalent"])
                if viable - tot["equivalent"] else 0.0)
    result = {"runs": dict(sorted(configs.items())), "files": per_file, "total": tot, "score": score,
              "score_without_equivalent": score_eq, "survivors": survivors}
    base = {f: bases[f] for f in sorted(partial) + [f for f in kept if f in before.get("base", {})]}
    if base:
        result["base"] = dict(sorted(base.items()))
    pathlib.Path(out_json).write_text(json.dumps(result, indent=1) + "\n")
    print(f"mutants: {viable} viable, {tot['caught'] + tot['timeout']} caught ({score:.1f} %), "
          f"{tot['equivalent']} equivalent, {len(unexplained)} unexplained survivors")
    for u in unexplained:
        print(f"  survivor: {u['file']}:{u['line']}: {u['mutant']}")
    sys.exit(1 if unexplained else 0)


if __name__ == "__main__":
    main()
