#!/usr/bin/env bash
# The complete test run: everything CI checks, in one command.
#   scripts/test.sh            all stages
#   scripts/test.sh rust c     only the named stages
# Stages: lint rust faults header c wireshark peer target bigendian miri fuzz bench
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)
export PATH="$HOME/.cargo/bin:$PATH"
export CARGO_TERM_COLOR=never

scripts/setup.sh

STAGES=("$@")
if [ "${#STAGES[@]}" -eq 0 ]; then
    STAGES=(lint rust faults header c wireshark peer target bigendian miri fuzz bench)
fi

stage() { printf '\n=== %s ===\n' "$*"; }
started=$(date +%s)

run_stage() {
    case "$1" in
    lint)
        stage "format and lints"
        cargo fmt --all -- --check
        scripts/layers.sh
        scripts/evidence.sh trace-check
        python3 -m unittest discover -q -s scripts/evidence -p 'test_*.py'
        cargo clippy --all-targets -- -D warnings
        cargo clippy --lib --no-default-features -- -D warnings
        # The multi-instance form of the C edge (COP_MAX_INSTANCES 2).
        COP_MAX_INSTANCES=2 CARGO_TARGET_DIR=target/multi cargo clippy --lib --features std -- -D warnings
        CARGO_TARGET_DIR=target/embedded-can cargo clippy --all-targets --features embedded-can -- -D warnings
        cargo clippy --lib --features srdo-static-mapping,srdo-granularity-16,pdo-bit-mapping,pdo-granularity-64 -- -D warnings
        CARGO_TARGET_DIR=target/dcf2bin cargo fmt --manifest-path tools/dcf2bin/Cargo.toml -- --check
        CARGO_TARGET_DIR=target/dcf2bin cargo clippy --manifest-path tools/dcf2bin/Cargo.toml --all-targets -- -D warnings
        ;;
    rust)
        stage "cargo test (default switches)"
        cargo test -q
        stage "cargo test (static mapping, granularity 16, timestamps, PDO bit mapping with 8 entries)"
        CARGO_TARGET_DIR=target/variant-a cargo test -q --features srdo-static-mapping,srdo-granularity-16,cdrv-timestamp,pdo-bit-mapping
        stage "cargo test (no GFC, no program monitor, SRVT checked before 2nd frame, dummy mapping, gaps, PDO bit mapping with granularity 64)"
        CARGO_TARGET_DIR=target/variant-b cargo test -q --no-default-features --features srdo-check-srvt-before-1strx,srdo-dummy-mapping,srdo-allow-gaps,pdo-bit-mapping,pdo-granularity-64
        stage "embedded-can adapter, the Rust safety sensor and actuator through it, rustdoc"
        CARGO_TARGET_DIR=target/embedded-can cargo test -q --features embedded-can --lib port::embedded
        CARGO_TARGET_DIR=target/embedded-can cargo run -q --example safety_sensor --features embedded-can
        CARGO_TARGET_DIR=target/embedded-can cargo run -q --example safety_actuator --features embedded-can
        RUSTDOCFLAGS=-Dwarnings cargo doc -q --no-deps
        CARGO_TARGET_DIR=target/embedded-can RUSTDOCFLAGS=-Dwarnings cargo doc -q --no-deps --features std,embedded-can
        stage "dcf2bin (host tool; its python-canopen comparisons need scripts/setup.sh)"
        CARGO_TARGET_DIR=target/dcf2bin cargo test -q --manifest-path tools/dcf2bin/Cargo.toml
        ;;
    faults)
        # The same campaign runs as a test in every `rust` variant; this
        # stage prints its table. Long run: --cycles 10000000 with --release.
        stage "SRDO fault-injection campaign (10^5 cycles, fixed seed)"
        cargo run -q --example fault_injection -- --cycles 100000 --seed 0x5EED0304
        # Smoke run of the load campaign (scripts/load.sh; the long run is
        # `scripts/load.sh`, 10 simulated minutes).
        stage "Load campaign on the physical bus model (3 simulated seconds)"
        scripts/load.sh --quick
        ;;
    header)
        stage "scripts/header.sh --verify (include/cop.h is up to date)"
        scripts/header.sh --verify
        ;;
    c)
        stage "CMake build and CTest (ASan/UBSan)"
        cmake -S . -B build -DCMAKE_BUILD_TYPE=Debug >/dev/null
        cmake --build build -j2
        ctest --test-dir build --output-on-failure -j2
        ;;
    wireshark)
        # tshark with tools/wireshark/cop_srdo.lua over captures of the
        # simulated bus: one per fault class, the C safety demo, the Rust
        # safety examples.
        stage "Wireshark dissector over the captures of the simulated bus"
        caps=target/captures
        rm -rf "$caps" && mkdir -p "$caps/rust"
        cargo run -q --example fault_captures -- "$caps/faults"
        for ex in safety_sensor safety_actuator; do
            COP_SIM_PCAP="$caps/rust/$ex.pcap" COP_SIM_CANDUMP="$caps/rust/$ex.log" \
                CARGO_TARGET_DIR=target/embedded-can cargo run -q --example "$ex" --features embedded-can >/dev/null
        done
        cmake -S . -B build -DCMAKE_BUILD_TYPE=Debug >/dev/null
        cmake --build build -j2 --target safety_demo >/dev/null
        COP_CAPTURES="$caps/faults" COP_SAFETY_DEMO=build/examples_c/safety_demo/safety_demo \
            COP_RUST_CAPTURES="$caps/rust" \
            python3 -m unittest discover -v -s tools/wireshark -p 'test_*.py'
        ;;
    peer)
        [ -x scripts/peer.sh ] || { echo "peer tests: scripts/peer.sh missing"; exit 1; }
        stage "python-canopen peer"
        scripts/peer.sh
        ;;
    target)
        [ -x scripts/tms570.sh ] || { echo "target check: scripts/tms570.sh missing"; exit 1; }
        stage "TMS570 (armebv7r-none-eabihf) build and link check"
        scripts/tms570.sh
        stage "TMS570 target programs under qemu-armeb (safety demo, C tests), alignment, stack"
        scripts/tms570.sh run
        ;;
    bigendian)
        [ -x scripts/bigendian.sh ] || { echo "big-endian run: scripts/bigendian.sh missing"; exit 1; }
        stage "big-endian (s390x under qemu)"
        scripts/bigendian.sh
        ;;
    miri)
        [ -x scripts/miri.sh ] || { echo "miri: scripts/miri.sh missing"; exit 1; }
        stage "Miri"
        scripts/miri.sh
        ;;
    fuzz)
        [ -x scripts/fuzz.sh ] || { echo "fuzz: scripts/fuzz.sh missing"; exit 1; }
        stage "fuzz smoke runs"
        scripts/fuzz.sh smoke
        ;;
    bench)
        [ -x scripts/bench.sh ] || { echo "bench: scripts/bench.sh missing"; exit 1; }
        stage "benchmark table"
        scripts/bench.sh
        ;;
    *)
        echo "unknown stage $1" >&2
        exit 2
        ;;
    esac
}

for s in "${STAGES[@]}"; do
    t0=$(date +%s)
    run_stage "$s"
    printf -- '--- stage %s: %ds\n' "$s" $(( $(date +%s) - t0 ))
done
printf '\nall stages passed (%s) in %ds\n' "${STAGES[*]}" $(( $(date +%s) - started ))
