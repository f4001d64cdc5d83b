#!/usr/bin/env python3
"""Combines the cargo-mutants runs of scripts/evidence.sh (one output folder
per file and switch configuration) into one result per mutant: caught when
any configuration that builds it catches it. Survivors are compared with the
equivalent mutants listed, with their argument, in EQUIV; a survivor not
listed there fails (exit 1). A file with no run in RUNS_DIR keeps its
figures, its runs and its survivors from the OUT_JSON written before (runs
are scratch; the committed result is not lost when one file is mutated
again).

  mutants.py RUNS_DIR OUT_JSON EQUIV_TOML
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


def run_name(file):
    """The folder name scripts/evidence.sh gives a file's runs (without
    the configuration): src/wire/srdo.rs -> wire-srdo."""
    return file.removeprefix("src/").removesuffix(".rs").replace("/", "-")


def key(text):
    m = LOC.match(text.strip())
    return (m.group("file"), m.group("what"), int(m.group("line")), int(m.group("col"))) if m else None


def main():
    runs, out_json, equiv_path = sys.argv[1:4]
    equiv = {}
    p = pathlib.Path(equiv_path)
    if p.exists():
        for e in tomllib.loads(p.read_text()).get("equivalent", []):
            equiv[(e["file"], e["mutant"])] = e["argument"]
    mutants, configs = {}, {}
    base = pathlib.Path(runs)
    outs = sorted(base.glob("*/mutants.out")) + sorted(base.glob("*/mutants.out.old")) + sorted(base.glob("*/runs/*"))
    for d in outs:
        run = d.parent.name if d.name.startswith("mutants.out") else d.parent.parent.name
        configs.setdefault(run, {})
        for outcome in RANK:
            text = "".join((d / n).read_text() + "\n" for n in FILES[outcome] if (d / n).exists())
            for line in text.splitlines():
                k = key(line)
                if k is None:
                    continue
                configs[run][outcome] = configs[run].get(outcome, 0) + 1
                prev = mutants.get(k)
                if prev is None or RANK[outcome] > RANK[prev["outcome"]]:
                    mutants[k] = {"outcome": outcome, "run": run}
    per_file, survivors, unexplained = {}, [], []
    for (file, what, line, _col), m in sorted(mutants.items()):
        s = per_file.setdefault(file, {o: 0 for o in RANK} | {"equivalent": 0})
        o = m["outcome"]
        if o == "missed" and (file, what) in equiv:
            o = "equivalent"
        s[o] += 1
        if m["outcome"] == "missed":
            entry = {"file": file, "line": line, "mutant": what,
                     "argument": equiv.get((file, what))}
            survivors.append(entry)
            if entry["argument"] is None:
                unexplained.append(entry)
    old = pathlib.Path(out_json)
    if old.exists():
        before = json.loads(old.read_text())
        kept = sorted(set(before.get("files", {})) - set(per_file))
        for file in kept:
            per_file[file] = before["files"][file]
            for entry in before.get("survivors", []):
                if entry["file"] == file:
                    entry["argument"] = equiv.get((file, entry["mutant"]))
                    survivors.append(entry)
                    if entry["argument"] is None:
                        unexplained.append(entry)
        # Run names: the file's path below src/ with "-" for "/" (earlier
        # runs: the file's stem).
        stems = tuple(n + "-" for f in kept
                      for n in (pathlib.Path(f).stem, run_name(f)))
        for run, counts in before.get("runs", {}).items():
            if run not in configs and run.startswith(stems):
                configs[run] = counts
        per_file = dict(sorted(per_file.items()))
        survivors.sort(key=lambda e: (e["file"], e["line"]))
    tot = {o: sum(s[o] for s in per_file.values()) for o in list(RANK) + ["equivalent"]}
    viable = tot["caught"] + tot["timeout"] + tot["missed"] + tot["equivalent"]
    score = 100.0 * (tot["caught"] + tot["timeout"]) / viable if viable else 0.0
    score_eq = (100.0 * (tot["caught"] + tot["timeout"]) / (viable - tot["equivalent"])
                if viable - tot["equivalent"] else 0.0)
    result = {"runs": configs, "files": per_file, "total": tot, "score": score,
              "score_without_equivalent": score_eq, "survivors": survivors}
    pathlib.Path(out_json).write_text(json.dumps(result, indent=1) + "\n")
    print(f"mutants: {viable} viable, {tot['caught'] + tot['timeout']} caught ({score:.1f} %), "
          f"{tot['equivalent']} equivalent, {len(unexplained)} unexplained survivors")
    for u in unexplained:
        print(f"  survivor: {u['file']}:{u['line']}: {u['mutant']}")
    sys.exit(1 if unexplained else 0)


if __name__ == "__main__":
    main()
