#!/usr/bin/env bash
# Runs every pure-Rust test (library unit tests and the whole-stack tests in
# tests/) under Miri, which detects undefined behaviour: out-of-bounds or
# dangling accesses through the dictionary tables, aliasing violations,
# uninitialised reads. The C API is not exercised here (Miri cannot call C);
# the C tests run under ASan/UBSan instead.
#
#   scripts/miri.sh            every test, two Miri runs side by side
#   scripts/miri.sh --serial   every test, one binary after the other
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
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-target}/miri"
. scripts/toolchains.sh
MIRI=(cargo "+$COP_NIGHTLY" miri test -q)

if [ "${1:-}" = "--serial" ] || [ "$(nproc 2>/dev/null || echo 1)" -lt 2 ]; then
    exec "${MIRI[@]}" --lib --tests
fi

# Build once; the jobs below then only run.
"${MIRI[@]}" --lib --tests --no-run

# One job a line: the arguments of `cargo miri test` (no spaces inside an
# argument).
jobs=(
    "--lib -- od::dcf::"
    "--lib -- od:: --skip od::dcf::"
    "--lib -- --skip od::"
)
while IFS= read -r f; do
    jobs+=("--test $(basename "$f" .rs)")
done < <(ls -S tests/*.rs)

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
