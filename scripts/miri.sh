#!/usr/bin/env bash
# Runs every pure-Rust test (library unit tests and the whole-stack tests in
# tests/) under Miri, which detects undefined behaviour: out-of-bounds or
# dangling accesses through the dictionary tables, aliasing violations,
# uninitialised reads. The C API is not exercised here (Miri cannot call C);
# the C tests run under ASan/UBSan instead.
#
#   scripts/miri.sh            every test, in two groups side by side
#   scripts/miri.sh --serial   every test, one binary after the other
#
# Miri interprets one thread at a time, so with two or more CPUs the test
# binaries run as two groups in parallel (after one shared build): the
# library's unit tests with the two slowest whole-stack files, and the
# other files. Each group's output is printed when it ends; the script
# fails when either group fails.
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-target}/miri"
. scripts/toolchains.sh
MIRI=(cargo "+$COP_NIGHTLY" miri test -q)

if [ "${1:-}" = "--serial" ] || [ "$(nproc 2>/dev/null || echo 1)" -lt 2 ]; then
    exec "${MIRI[@]}" --lib --tests
fi

# Build once; the groups below then only run.
"${MIRI[@]}" --lib --tests --no-run

first=(dynod sdo_block)
group_a=(--lib)
group_b=()
for f in tests/*.rs; do
    name=$(basename "$f" .rs)
    if [[ " ${first[*]} " == *" $name "* ]]; then
        group_a+=(--test "$name")
    else
        group_b+=(--test "$name")
    fi
done

logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
"${MIRI[@]}" "${group_a[@]}" >"$logs/a" 2>&1 &
pid_a=$!
rc_b=0
"${MIRI[@]}" "${group_b[@]}" >"$logs/b" 2>&1 || rc_b=$?
rc_a=0
wait "$pid_a" || rc_a=$?
echo "--- Miri: unit tests, ${first[*]}"
cat "$logs/a"
echo "--- Miri: the other whole-stack tests"
cat "$logs/b"
[ "$rc_a" -eq 0 ] && [ "$rc_b" -eq 0 ]
