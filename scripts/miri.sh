#!/usr/bin/env bash
# Runs the pure-Rust tests under Miri, which detects undefined behaviour:
# out-of-bounds or dangling accesses through the dictionary tables, aliasing
# violations, uninitialised reads. The C API is not exercised here (Miri
# cannot call C); the C tests run under ASan/UBSan instead.
#
#   scripts/miri.sh            the library's unit tests and tests/dynod.rs
#                              (the test command's Miri stage)
#   scripts/miri.sh --all      every test: also the other files of tests/
#                              (about twice as long)
#   scripts/miri.sh --serial   one binary after the other (with or without --all)
#   scripts/miri.sh --print-default
#                              the default set as `scripts/evidence.sh
#                              unsafe-reach` checks it (lib,dynod)
#
# Undefined behaviour needs `unsafe`, and outside src/ffi (which Miri cannot
# reach) the only `unsafe` blocks are those of src/od/table.rs. Line coverage
# per test binary (cargo llvm-cov --lib, then --test <file> for each file of
# tests/) shows which of its blocks each binary reaches: the unit tests reach
# 10 of the 28, tests/dynod.rs 21 (the dynamic dictionary's pool), the two
# together the 25 that any Rust test reaches (the other 3, variable
# callbacks and a pool path, only the C tests reach); no other file of
# tests/ reaches a block these two do not. So the default set runs every
# block Miri can check; --all adds the other whole-stack scenarios over the
# same blocks (a long run outside the test command, README "The two commands").
#
# Miri interprets one thread at a time, so with two or more CPUs the tests
# run as a queue of jobs taken by two workers (after one shared build):
# the library's unit tests in three parts (the DCF container tests, the
# other object dictionary tests, everything else; libtest's name filter
# and --skip with the same words, so the parts add up to all of them),
# then one job per file of tests/, the largest file first, so that the
# queue ends with short jobs and neither worker waits long for the other.
# Each job's output is printed in queue order when all have ended; the
# script fails when any job fails.
set -euo pipefail
cd "$(dirname "$0")/.."
# The files of tests/ the default run takes besides the unit tests.
DEFAULT_TESTS=(dynod)
if [ "${1:-}" = "--print-default" ]; then
    (IFS=,; echo "lib,${DEFAULT_TESTS[*]}")
    exit 0
fi
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-target}/miri"
. scripts/toolchains.sh
MIRI=(cargo "+$COP_NIGHTLY" miri test -q)

all=0 serial=0
for arg in "$@"; do
    case "$arg" in
    --all) all=1 ;;
    --serial) serial=1 ;;
    *) echo "usage: $0 [--all] [--serial]" >&2; exit 2 ;;
    esac
done
[ "$(nproc 2>/dev/null || echo 1)" -ge 2 ] || serial=1
# The test binaries of tests/ that run, largest file first.
if [ "$all" = 1 ]; then
    mapfile -t tests < <(ls -S tests/*.rs | xargs -n1 basename -s .rs)
else
    tests=("${DEFAULT_TESTS[@]}")
fi
test_args=()
for t in "${tests[@]}"; do
    test_args+=(--test "$t")
done

if [ "$serial" = 1 ]; then
    exec "${MIRI[@]}" --lib "${test_args[@]}"
fi

# Build once; the jobs below then only run.
"${MIRI[@]}" --lib "${test_args[@]}" --no-run

# One job a line: the arguments of `cargo miri test` (no spaces inside an
# argument).
jobs=(
    "--lib -- od::dcf::"
    "--lib -- od:: --skip od::dcf::"
    "--lib -- --skip od::"
)
for t in "${tests[@]}"; do
    jobs+=("--test $t")
done

logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
export COP_MIRI_LOGS="$logs" COP_NIGHTLY
# Job "<number> <arguments>": output to <number>.log, exit code to
# <number>.rc, seconds to <number>.s.
run_job() {
    local n=${1%% *} args rc=0 t0=$SECONDS
    read -ra args <<<"${1#* }"
    cargo "+$COP_NIGHTLY" miri test -q "${args[@]}" >"$COP_MIRI_LOGS/$n.log" 2>&1 || rc=$?
    echo "$rc" >"$COP_MIRI_LOGS/$n.rc"
    echo $((SECONDS - t0)) >"$COP_MIRI_LOGS/$n.s"
}
export -f run_job
for i in "${!jobs[@]}"; do
    echo "$i ${jobs[$i]}"
done | xargs -d '\n' -n1 -P2 bash -c 'run_job "$1"' _ || true

failed=()
for i in "${!jobs[@]}"; do
    echo "--- Miri: ${jobs[$i]} ($(cat "$logs/$i.s" 2>/dev/null || echo ?) s)"
    cat "$logs/$i.log" 2>/dev/null || true
    if [ "$(cat "$logs/$i.rc" 2>/dev/null || echo missing)" != 0 ]; then
        failed+=("${jobs[$i]}")
    fi
done
if [ "${#failed[@]}" -gt 0 ]; then
    printf 'Miri failed: %s\n' "${failed[@]}"
    exit 1
fi
