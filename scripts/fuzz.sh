#!/usr/bin/env bash
# Fuzzing with cargo-fuzz (libFuzzer, nightly toolchain, AddressSanitizer).
#   scripts/fuzz.sh smoke           every target briefly (part of the test command)
#   scripts/fuzz.sh long [seconds]  every target for `seconds` (default 600) each
# The seed corpus is committed in fuzz/corpus/<target>/; new inputs found
# during a run go to fuzz/corpus-new/<target>/ (not committed).
set -euo pipefail
cd "$(dirname "$0")/../fuzz"
. ../scripts/toolchains.sh
MODE=${1:-smoke}
case "$MODE" in
smoke) SECS=${2:-20} ;;
long) SECS=${2:-600} ;;
*) echo "usage: $0 smoke|long [seconds]" >&2; exit 2 ;;
esac
TARGETS=$(cargo "+$COP_NIGHTLY" fuzz list)
# Every target built in one cargo run; `cargo fuzz run` below finds them
# up to date.
cargo "+$COP_NIGHTLY" fuzz build
# libFuzzer runs on one core: with two CPUs two targets run side by side,
# each for the same time as alone. Output goes to a log per target,
# printed in target order.
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
export COP_FUZZ_LOGS="$logs" COP_NIGHTLY SECS
fuzz_one() {
    mkdir -p "corpus-new/$1" "corpus/$1"
    cargo "+$COP_NIGHTLY" fuzz run "$1" "corpus-new/$1" "corpus/$1" -- \
        -max_total_time="$SECS" -print_final_stats=1 >"$COP_FUZZ_LOGS/$1" 2>&1 || true
}
export -f fuzz_one
workers=$(( $(nproc 2>/dev/null || echo 1) >= 2 ? 2 : 1 ))
printf '%s\n' $TARGETS | xargs -n1 -P"$workers" bash -c 'fuzz_one "$1"' _
for t in $TARGETS; do
    echo "--- fuzz $t for ${SECS}s"
    grep -E "^(stat::number_of_executed_units|stat::new_units_added|==[0-9]+==|SUMMARY|Done)" "$logs/$t" || true
    if [ -d "artifacts/$t" ] && [ -n "$(ls -A "artifacts/$t" 2>/dev/null)" ]; then
        echo "FAIL: crash artifacts in fuzz/artifacts/$t"
        exit 1
    fi
done
echo "fuzzing: no crashes"
