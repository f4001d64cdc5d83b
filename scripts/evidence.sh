#!/usr/bin/env bash
# Evidence for the safety core (src/srdo/, src/wire/srdo.rs, src/ffi/srdo.rs):
# requirement trace, structural coverage, mutation score, one report.
#
#   scripts/evidence.sh trace            check docs/requirements.toml against the
#                                        tests' `req:` annotations, write docs/traceability.md
#   scripts/evidence.sh trace-check      the same check, writes nothing (lint stage)
#   scripts/evidence.sh coverage         line + branch coverage over the three switch
#                                        configurations of `scripts/test.sh rust`
#   scripts/evidence.sh mutants [FILE] [-- cargo-mutants args]
#                                        mutation testing, each file in configurations
#                                        that compile its code; compares the survivors
#                                        with docs/evidence/equivalent_mutants.toml
#   scripts/evidence.sh report           docs/evidence/report.md with its figures
#   scripts/evidence.sh all              trace, coverage, mutants, report (long)
#
# Not part of scripts/test.sh except `trace-check` (lint stage). Results go to
# docs/evidence/ (committed) and target/evidence/ (scratch).
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
export CARGO_TERM_COLOR=never
OUT=docs/evidence
WORK=target/evidence
mkdir -p "$OUT" "$WORK"

# The three switch configurations of `scripts/test.sh rust`.
CONFIG_NAMES=(default variant-a variant-b)
config_args() {
    case "$1" in
    default) echo "" ;;
    variant-a) echo "--features srdo-static-mapping,srdo-granularity-16,cdrv-timestamp,pdo-bit-mapping" ;;
    variant-b) echo "--no-default-features --features srdo-check-srvt-before-1strx,srdo-dummy-mapping,srdo-allow-gaps,pdo-bit-mapping,pdo-granularity-64" ;;
    esac
}
# The files whose figures the evidence gives.
CORE_REGEX='src/(srdo/(check|crc|hooks|mod|objects|plan)\.rs|wire/srdo\.rs|ffi/srdo\.rs)$'
MUTANT_FILES=(src/srdo/check.rs src/srdo/crc.rs src/srdo/hooks.rs src/srdo/mod.rs
    src/srdo/objects.rs src/srdo/plan.rs src/wire/srdo.rs src/ffi/srdo.rs)

setup() { [ -n "${EVIDENCE_NO_SETUP:-}" ] || scripts/setup.sh --evidence; }
log() { printf '[evidence] %s\n' "$*" >&2; }

cmd_trace() { python3 scripts/evidence/trace.py --write "$WORK/trace.json"; }
cmd_trace_check() { python3 scripts/evidence/trace.py --check; }

cmd_coverage() {
    setup
    # Branch coverage needs the nightly compiler (-Z coverage-options=branch).
    local tc=(+nightly) branch=(--branch)
    cargo "${tc[@]}" llvm-cov clean --workspace
    for c in "${CONFIG_NAMES[@]}"; do
        log "coverage: cargo test in configuration $c"
        # shellcheck disable=SC2046
        cargo "${tc[@]}" llvm-cov --no-report "${branch[@]}" -j2 $(config_args "$c") >"$WORK/cov-$c.log" 2>&1 ||
            { tail -30 "$WORK/cov-$c.log"; exit 1; }
    done
    log "coverage: merged report"
    cargo "${tc[@]}" llvm-cov report "${branch[@]}" --json --summary-only --output-path "$WORK/coverage-summary.json"
    cargo "${tc[@]}" llvm-cov report "${branch[@]}" --lcov --output-path "$WORK/coverage.lcov"
    cargo "${tc[@]}" llvm-cov report "${branch[@]}" --text --show-missing-lines >"$WORK/coverage.txt" 2>/dev/null || true
    python3 scripts/evidence/coverage.py "$WORK/coverage.lcov" "$CORE_REGEX" "$OUT/coverage.json" "$OUT/uncovered.md"
}

# Which configurations compile the code of a file: every file is built in all
# three; the report keeps the best result per mutant (a mutant that only one
# configuration compiles is caught or missed there).
cmd_mutants() {
    setup
    local files=("${MUTANT_FILES[@]}") extra=()
    if [ $# -gt 0 ] && [ "$1" != "--" ]; then files=("$1"); shift; fi
    if [ $# -gt 0 ] && [ "$1" = "--" ]; then shift; extra=("$@"); fi
    for f in "${files[@]}"; do
        for c in "${CONFIG_NAMES[@]}"; do
            local dir
            dir="$WORK/mutants/$(basename "$f" .rs)-$c"
            mkdir -p "$dir"
            log "mutants: $f in configuration $c"
            # shellcheck disable=SC2046
            cargo mutants -j1 --file "$f" --output "$dir" \
                $(config_args "$c") "${extra[@]}" || true
        done
    done
    python3 scripts/evidence/mutants.py "$WORK/mutants" "$OUT/mutants.json" docs/evidence/equivalent_mutants.toml
}

cmd_report() {
    setup
    cmd_trace
    log "report: fault-injection campaign (10^5 cycles, fixed seed)"
    cargo run -q -j2 --example fault_injection -- --cycles 100000 --seed 0x5EED0304 >"$WORK/faults.txt"
    {
        rustc --version; rustc +nightly --version
        cargo llvm-cov --version; cargo mutants --version
        python3 --version; python3 -c 'import matplotlib; print("matplotlib", matplotlib.__version__)'
    } >"$WORK/versions.txt" 2>&1 || true
    python3 scripts/evidence/report.py "$OUT" "$WORK"
}

case "${1:-}" in
trace) cmd_trace ;;
trace-check) cmd_trace_check ;;
coverage) cmd_coverage ;;
mutants) shift; cmd_mutants "$@" ;;
report) cmd_report ;;
all) cmd_trace; cmd_coverage; cmd_mutants; cmd_report ;;
*) sed -n '2,19p' "$0"; exit 2 ;;
esac
