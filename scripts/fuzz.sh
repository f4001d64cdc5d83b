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
for t in $TARGETS; do
    mkdir -p "corpus-new/$t" "corpus/$t"
    echo "--- fuzz $t for ${SECS}s"
    cargo "+$COP_NIGHTLY" fuzz run "$t" "corpus-new/$t" "corpus/$t" -- \
        -max_total_time="$SECS" -print_final_stats=1 2>&1 | grep -E "^(stat::number_of_executed_units|stat::new_units_added|==[0-9]+==|SUMMARY|Done)" || true
    if [ -d "artifacts/$t" ] && [ -n "$(ls -A "artifacts/$t" 2>/dev/null)" ]; then
        echo "FAIL: crash artifacts in fuzz/artifacts/$t"
        exit 1
    fi
done
echo "fuzzing: no crashes"
