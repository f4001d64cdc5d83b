#!/usr/bin/env bash
# Evidence for the safety core (src/srdo/, src/wire/srdo.rs, src/ffi/srdo.rs):
# requirement trace, structural coverage, mutation score, one report.
#
#   scripts/evidence.sh trace            check docs/requirements.toml against the
#                                        tests' `req:` annotations, write docs/traceability.md
#   scripts/evidence.sh trace-check      the same check, writes nothing (lint stage)
#   scripts/evidence.sh coverage         line + branch coverage over the three switch
#                                        configurations of `scripts/test.sh rust`
#                                        and of the C tests (CTest, instrumented library);
#                                        fails on an uncovered place without a reason
#   scripts/evidence.sh coverage-c       only the C tests again, then the merged report
#   scripts/evidence.sh coverage-report  only the merged report of the last runs
#   scripts/evidence.sh mutants [FILE] [-- cargo-mutants args]
#                                        mutation testing, each file in configurations
#                                        that compile its code; compares the survivors
#                                        with docs/evidence/equivalent_mutants.toml
#   scripts/evidence.sh mutants --survivors [FILE]
#                                        only the recorded survivors again (after a new
#                                        test): updates them in docs/evidence/mutants.json
#   scripts/evidence.sh unsafe-reach     which unsafe blocks each Rust test binary
#                                        reaches (docs/evidence/unsafe_reach.md); fails
#                                        when the default set of scripts/miri.sh misses one
#   scripts/evidence.sh report           docs/evidence/report.md with its figures (runs the
#                                        fault-injection and load campaigns)
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
    cov_c_tests "${tc[@]}"
    cov_report "${tc[@]}"
}

# The C tests again and the merged report, with the Rust tests' profiles of
# the last `coverage` run.
cmd_coverage_c() {
    setup
    cov_c_tests +nightly
    cov_report +nightly
}

# The merged report. cargo-llvm-cov merges the profiles (and writes the
# whole crate's summary); the lcov of the safety core is exported object by
# object and summed by coverage.py: llvm-cov keeps only the first object's
# record of a function name, and the C entry points (#[no_mangle]) have the
# same name in every test program, most of which never call them.
cov_report() {
    local tc=("$1") branch=(--branch)
    log "coverage: merged report"
    cargo "${tc[@]}" llvm-cov report "${branch[@]}" --summary-only >"$WORK/coverage-crate.txt" 2>/dev/null
    local bin profdata sources=() f o
    bin="$(rustc "${tc[@]}" --print sysroot)/lib/rustlib/$(rustc "${tc[@]}" -vV | sed -n 's/^host: //p')/bin"
    profdata=$(ls target/llvm-cov-target/*.profdata)
    for f in src/srdo/*.rs src/wire/srdo.rs src/ffi/srdo.rs; do
        [[ "$f" =~ $CORE_REGEX ]] && sources+=("$PWD/$f")
    done
    : >"$WORK/coverage.lcov"
    for o in $(find target/llvm-cov-target/debug/deps target/llvm-cov-target/debug/examples -maxdepth 1 \
        -type f -perm -u+x ! -name '*.*' | sort) target/llvm-cov-target/debug/ctest/*; do
        "$bin/llvm-cov" export -format=lcov -instr-profile "$profdata" "$o" "${sources[@]}" \
            >>"$WORK/coverage.lcov" 2>/dev/null || true
    done
    python3 scripts/evidence/coverage.py "$WORK/coverage.lcov" "$CORE_REGEX" "$OUT/coverage.json" "$OUT/uncovered.md"
}

# The C tests (CTest) against the instrumented library: cargo-llvm-cov's
# show-env gives the rustc wrapper and flags that instrument the crate, CMake
# builds each library configuration of c_tests/ with them (no sanitizers: their
# runtime and the profile runtime would both be linked), every C test program
# writes its profile next to those of the Rust tests, and the programs are
# offered to the report as objects under a name it collects (cop-cc<n>).
# rustc links the profile runtime (profiler_builtins) into the programs it
# links, not into a static library: the C programs get it from the
# toolchain's rlib (an archive), pulled in by its runtime hook symbol.
cov_c_tests() {
    local build="$PWD/$WORK/cmake-cov" objdir=target/llvm-cov-target/debug/ctest
    log "coverage: C tests (CMake, CTest) against the instrumented library"
    rm -f target/llvm-cov-target/cop-ctest-*.profraw
    # Cargo does not see the wrapper's flags: build the libraries afresh.
    rm -rf "$build/cargo"
    (
        eval "$(cargo "$@" llvm-cov show-env --branch --sh 2>/dev/null)"
        unset CARGO_LLVM_COV_TARGET_DIR CARGO_LLVM_COV_BUILD_DIR
        export COP_COV_WRAPPER="$RUSTC_WRAPPER" RUSTC_WRAPPER="$PWD/scripts/evidence/rustc-salt.sh"
        export LLVM_PROFILE_FILE="$PWD/target/llvm-cov-target/cop-ctest-%p.profraw"
        export RUSTUP_TOOLCHAIN="${1#+}"
        local runtime
        runtime=$(ls "$(rustc --print sysroot)"/lib/rustlib/*/lib/libprofiler_builtins-*.rlib)
        # Coverage counts source regions, not machine code: an unoptimised
        # build without LTO counts the same and builds the eight library
        # configurations faster.
        export CARGO_PROFILE_RELEASE_LTO=false CARGO_PROFILE_RELEASE_OPT_LEVEL=0
        export CARGO_PROFILE_RELEASE_CODEGEN_UNITS=16
        cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCOP_SANITIZERS=OFF \
            -DCMAKE_C_STANDARD_LIBRARIES="-Wl,-u,__llvm_profile_runtime $runtime" >"$WORK/cov-c.log" 2>&1
        cmake --build "$build" -j2 >>"$WORK/cov-c.log" 2>&1 || { tail -30 "$WORK/cov-c.log"; exit 1; }
        ctest --test-dir "$build" -j2 --output-on-failure >>"$WORK/cov-c.log" 2>&1 ||
            { tail -40 "$WORK/cov-c.log"; exit 1; }
        grep -E 'tests passed|tests failed' "$WORK/cov-c.log" >&2
    )
    rm -rf "$objdir"
    mkdir -p "$objdir"
    local n=0 f
    while IFS= read -r f; do
        [ "$(head -c4 "$f" | od -An -tx1 | tr -d ' ')" = 7f454c46 ] || continue
        # grep -c reads all of it (grep -q would stop readelf: pipefail)
        [ "$(readelf -SW "$f" 2>/dev/null | grep -c __llvm_covmap)" -gt 0 ] || continue
        n=$((n + 1))
        ln -s "$f" "$objdir/cop-cc$(printf '%02x' "$n")"
    done < <(find "$build" -path "$build/cargo" -prune -o -type f -perm -u+x -print | sort)
    log "coverage: $n instrumented C test programs"
}

# Mutation testing. Every file is mutated in each configuration of
# MUTANT_CONFIGS (default: all three; a mutant in a function that a switch
# compiles out builds there and changes nothing: mutants.py does not count it
# in that configuration); the combined result keeps the best outcome per
# mutant. `mutants --survivors` tests only a file's recorded survivors
# (folders <file>-<config>-survivors) and updates only those; any other run of
# a file replaces its figures. The tests run are the
# library's unit tests and the SRDO integration tests (MUTANT_TESTS), which
# keeps a mutant at a build and well under a minute (the test command of a
# mutant that makes a loop endless ends after 90 s, a timeout, which counts
# as caught). Long: progress is
# cargo-mutants' own (target/evidence/mutants/<file>-<config>/log), runs are
# resumable (--iterate skips the mutants a previous run caught) and can be
# split (MUTANT_SHARD=k/n, cargo-mutants --shard).
# The C entry points of src/ffi/srdo.rs are tested from Rust in
# src/ffi/srdo_tests.rs (part of --lib: their calls need `unsafe`, which
# only src/ffi may use); the C tests (CTest) do not run under cargo-mutants.
MUTANT_TESTS=(--lib --test srdo_bus --test srdo_check_od --test srdo_config --test srdo_faults
    --test srdo_filter --test srdo_nmt_gfc --test srdo_support --test srdo_transmit --test store_srdo)
cmd_mutants() {
    setup
    local files=("${MUTANT_FILES[@]}") extra=() configs suffix=""
    read -r -a configs <<<"${MUTANT_CONFIGS:-${CONFIG_NAMES[*]}}"
    if [ "${1:-}" = "--survivors" ]; then suffix=-survivors; shift; fi
    if [ $# -gt 0 ] && [ "$1" != "--" ]; then files=("$1"); shift; fi
    if [ $# -gt 0 ] && [ "$1" = "--" ]; then shift; extra=("$@"); fi
    local shard=()
    [ -z "${MUTANT_SHARD:-}" ] || shard=(--shard "$MUTANT_SHARD")
    # The cfg set of every configuration: mutants.py does not count a
    # survivor in a configuration that compiles its function out.
    mkdir -p "$WORK/mutants"
    for c in "${CONFIG_NAMES[@]}"; do
        # shellcheck disable=SC2046
        cargo rustc --lib -q $(config_args "$c") -- --print cfg >"$WORK/mutants/cfg-$c.txt"
    done
    for f in "${files[@]}"; do
        for c in "${configs[@]}"; do
            local dir iterate=()
            # One folder per path (src/wire/srdo.rs and src/ffi/srdo.rs
            # share a file name): wire-srdo-default, ffi-srdo-default, ...
            # (mutants.py: run_name).
            local name=${f#src/}
            name=${name%.rs}
            dir="$WORK/mutants/${name//\//-}-$c$suffix"
            local only=()
            if [ -n "$suffix" ]; then
                only=(--re "$(python3 scripts/evidence/mutants.py --survivor-re "$f" "$OUT/mutants.json")")
                [ "${only[1]}" != "" ] || continue
            fi
            mkdir -p "$dir"
            if [ -f "$dir/mutants.out/outcomes.json" ]; then
                # --iterate tests only what earlier runs did not catch; their
                # outcomes are kept for the combined result.
                iterate=(--iterate)
                mkdir -p "$dir/runs"
                cp -r "$dir/mutants.out" "$dir/runs/$(date -u +%Y%m%dT%H%M%S)"
            fi
            log "mutants: $f in configuration $c ($(cargo mutants --list --file "$f" $(config_args "$c") "${only[@]}" "${extra[@]}" 2>/dev/null | wc -l) mutants; log $dir/log)"
            # shellcheck disable=SC2046
            cargo mutants -j1 --file "$f" --output "$dir" --no-shuffle "${iterate[@]}" "${shard[@]}" \
                --baseline skip --timeout 90 --build-timeout 900 \
                $(config_args "$c") "${only[@]}" "${extra[@]}" -- "${MUTANT_TESTS[@]}" 2>&1 | tee -a "$dir/log" | grep -E '^(MISSED|TIMEOUT)|mutants tested' >&2 || true
        done
    done
    python3 scripts/evidence/mutants.py "$WORK/mutants" "$OUT/mutants.json" docs/evidence/equivalent_mutants.toml
}

# Line coverage per test binary (default switches): the unit tests, then
# each file of tests/ alone; unsafe_reach.py compares the blocks they reach
# with the set scripts/miri.sh runs by default (lib: the unit tests).
cmd_unsafe_reach() {
    setup
    local dir="$WORK/unsafe-reach" t miri_default
    miri_default=$(scripts/miri.sh --print-default)
    mkdir -p "$dir"
    export CARGO_LLVM_COV_TARGET_DIR="$PWD/target/unsafe-reach"
    log "unsafe-reach: unit tests"
    cargo llvm-cov --lib -j2 --json --output-path "$dir/lib.json" >"$dir/lib.log" 2>&1 ||
        { tail -30 "$dir/lib.log"; exit 1; }
    for t in tests/*.rs; do
        t=$(basename "$t" .rs)
        log "unsafe-reach: tests/$t.rs"
        cargo llvm-cov --test "$t" -j2 --json --output-path "$dir/$t.json" >"$dir/$t.log" 2>&1 ||
            { tail -30 "$dir/$t.log"; exit 1; }
    done
    python3 scripts/evidence/unsafe_reach.py "$OUT/unsafe_reach.md" "$miri_default" "$dir"/*.json
}

cmd_report() {
    setup
    cmd_trace
    log "report: fault-injection campaign (10^5 cycles, fixed seed)"
    cargo run -q -j2 --example fault_injection -- --cycles 100000 --seed 0x5EED0304 >"$WORK/faults.txt"
    log "report: long campaign (10^6 cycles, release build) and its timing plot"
    cargo run -q -j2 --release --example fault_injection -- --cycles 1000000 --seed 0x5EED0304 \
        --pairs "$WORK/pairs.csv" >"$WORK/timing.txt"
    CARGO_TARGET_DIR=target/srdo_plot cargo run -q -j2 --release --manifest-path tools/srdo_plot/Cargo.toml -- \
        "$WORK/pairs.csv" "$OUT/timing.svg"
    log "report: load campaign (scripts/load.sh: docs/load.md, docs/load.png)"
    scripts/load.sh >"$WORK/load.txt"
    {
        rustc --version; rustc +nightly --version
        cargo llvm-cov --version; cargo mutants --version
        python3 --version; python3 -c 'import matplotlib; print("matplotlib", matplotlib.__version__)'
        grep -A1 '^name = "plotters"$' tools/srdo_plot/Cargo.lock | tr -d '"' | paste -sd' '
        cmake --version | head -1; cc --version | head -1
    } >"$WORK/versions.txt" 2>&1 || true
    python3 scripts/evidence/report.py "$OUT" "$WORK"
}

case "${1:-}" in
trace) cmd_trace ;;
trace-check) cmd_trace_check ;;
coverage) cmd_coverage ;;
coverage-c) cmd_coverage_c ;;
coverage-report) cov_report +nightly ;;
mutants) shift; cmd_mutants "$@" ;;
unsafe-reach) cmd_unsafe_reach ;;
report) cmd_report ;;
all) cmd_trace; cmd_coverage; cmd_mutants; cmd_unsafe_reach; cmd_report ;;
*) sed -n '2,25p' "$0"; exit 2 ;;
esac
