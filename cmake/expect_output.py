#!/usr/bin/env python3
"""Runs a program and checks its output, for CTest.

    expect_output.py --expect FILE [--extract REGEX --compare FILE] -- program [args...]

--expect FILE      one regular expression (Python syntax) per line; each must
                   match the program's output, in this order, every search
                   starting where the previous match ended. Empty lines and
                   lines starting with '#' are ignored.
--extract REGEX    the output lines matching REGEX ...
--compare FILE     ... must be exactly the lines of FILE (e.g. a committed
                   candump trace); with --update the file is rewritten instead.

The program must exit with 0. On a failure the output is printed with the
reason, and the exit code is 1.
"""
import argparse
import re
import subprocess
import sys


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--expect")
    parser.add_argument("--extract")
    parser.add_argument("--compare")
    parser.add_argument("--update", action="store_true")
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = [c for c in args.command if c != "--" and c != ""]
    if not command:
        parser.error("no program given")

    run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    output = run.stdout.decode("utf-8", errors="replace")
    failures = []
    if run.returncode != 0:
        failures.append("exit code %d" % run.returncode)

    if args.expect:
        pos = 0
        with open(args.expect, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                pattern = line.rstrip("\n")
                if not pattern.strip() or pattern.lstrip().startswith("#"):
                    continue
                m = re.compile(pattern, re.MULTILINE).search(output, pos)
                if m is None:
                    failures.append("%s:%d: not found (in this order): %s" % (args.expect, number, pattern))
                    break
                pos = m.end()

    if args.extract:
        # trailing blanks do not count (a candump line of a DLC-0 frame ends in one)
        lines = [l.rstrip() for l in output.splitlines() if re.search(args.extract, l)]
        if args.update:
            with open(args.compare, "w", encoding="utf-8") as f:
                f.write("\n".join(lines) + "\n")
        else:
            with open(args.compare, encoding="utf-8") as f:
                expected = [l.rstrip() for l in f.read().splitlines()]
            if lines != expected:
                for i in range(max(len(lines), len(expected))):
                    got = lines[i] if i < len(lines) else "<missing>"
                    want = expected[i] if i < len(expected) else "<missing>"
                    if got != want:
                        failures.append("%s: line %d differs: got %r, expected %r" % (args.compare, i + 1, got, want))
                        break

    if failures:
        sys.stdout.write(output)
        for f in failures:
            print("expect_output: " + f)
        return 1
    print("expect_output: %s passed (%d lines of output)" % (command[-1], len(output.splitlines())))
    return 0


if __name__ == "__main__":
    sys.exit(main())
