#!/usr/bin/env bash
# Installs everything the demo and the test suite need. Idempotent: each step
# checks first and does nothing when its tool is already present.
#
#   scripts/setup.sh            everything (tests)
#   scripts/setup.sh --demo     only what the demo needs (cmake, C compiler)
#   scripts/setup.sh --evidence only what scripts/evidence.sh needs (coverage,
#                               mutation testing, plots)
set -euo pipefail

MODE="${1:-all}"
# shellcheck source=scripts/toolchains.sh
. "$(dirname "$0")/toolchains.sh"
CBINDGEN_VERSION=0.29.4
PY_CANOPEN_VERSION=2.4.1
PY_CAN_VERSION=4.6.1
LLVM_COV_VERSION=0.9.1
MUTANTS_VERSION=27.1.0
MATPLOTLIB_VERSION=3.11.2

log() { printf '[setup] %s\n' "$*"; }

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

apt_install() {
    local missing=()
    for p in "$@"; do
        dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
    done
    if [ "${#missing[@]}" -gt 0 ]; then
        log "apt: ${missing[*]}"
        $SUDO apt-get update -qq
        DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
    fi
}

if ! command -v cargo >/dev/null 2>&1; then
    if [ -x "$HOME/.cargo/bin/cargo" ]; then
        export PATH="$HOME/.cargo/bin:$PATH"
    else
        echo "setup: a Rust toolchain (rustup, cargo) is required" >&2
        exit 1
    fi
fi

apt_install cmake make gcc libc6-dev python3 python3-pip
if [ "$MODE" = "--demo" ]; then
    log "demo prerequisites present"
    exit 0
fi

if [ "$MODE" = "--evidence" ]; then
    for tc in stable nightly; do
        if ! rustup component list --installed --toolchain "$tc" 2>/dev/null | grep -q '^llvm-tools'; then
            log "rustup: llvm-tools-preview ($tc)"
            rustup component add llvm-tools-preview --toolchain "$tc"
        fi
    done
    if ! cargo llvm-cov --version 2>/dev/null | grep -q "$LLVM_COV_VERSION"; then
        log "cargo install cargo-llvm-cov $LLVM_COV_VERSION"
        cargo install cargo-llvm-cov --version "$LLVM_COV_VERSION" --locked --quiet
    fi
    if ! cargo mutants --version 2>/dev/null | grep -q "$MUTANTS_VERSION"; then
        log "cargo install cargo-mutants $MUTANTS_VERSION"
        cargo install cargo-mutants --version "$MUTANTS_VERSION" --locked --quiet
    fi
    if ! python3 -c "import matplotlib, sys; sys.exit(0 if matplotlib.__version__ == '$MATPLOTLIB_VERSION' else 1)" 2>/dev/null; then
        log "pip: matplotlib $MATPLOTLIB_VERSION"
        python3 -m pip install --quiet --disable-pip-version-check "matplotlib==$MATPLOTLIB_VERSION"
    fi
    log "evidence prerequisites present"
    exit 0
fi

apt_install gcc-arm-none-eabi binutils-arm-none-eabi \
    gcc-s390x-linux-gnu libc6-dev-s390x-cross qemu-user valgrind tshark can-utils
# qemu-user provides qemu-armeb, which runs the TMS570 target programs (scripts/tms570.sh);
# tshark runs the SRDO dissector (tools/wireshark) over the captures of the simulated bus,
# can-utils' log2asc reads their candump -l logs with canplayer's parser

rustup component list --installed 2>/dev/null | grep -q '^rust-src' || { log "rustup: rust-src"; rustup component add rust-src; }
rustup component list --installed 2>/dev/null | grep -q '^clippy' || { log "rustup: clippy"; rustup component add clippy; }
rustup component list --installed 2>/dev/null | grep -q '^rustfmt' || { log "rustup: rustfmt"; rustup component add rustfmt; }
rustup target list --installed | grep -q '^s390x-unknown-linux-gnu$' || { log "rustup: s390x target"; rustup target add s390x-unknown-linux-gnu; }
rustup run "$COP_STABLE" rustc -V >/dev/null 2>&1 || {
    log "rustup: $COP_STABLE"
    rustup toolchain install "$COP_STABLE" --profile minimal --component rustfmt,clippy,rust-src \
        --target s390x-unknown-linux-gnu >/dev/null
}
if ! rustup run "$COP_NIGHTLY" cargo miri --version >/dev/null 2>&1; then
    log "rustup: $COP_NIGHTLY with miri"
    rustup toolchain install "$COP_NIGHTLY" --profile minimal --component miri,rust-src >/dev/null
fi

if ! cbindgen --version 2>/dev/null | grep -q "$CBINDGEN_VERSION"; then
    log "cargo install cbindgen $CBINDGEN_VERSION"
    cargo install cbindgen --version "$CBINDGEN_VERSION" --locked --quiet
fi

if ! cargo fuzz --version 2>/dev/null | grep -q "$COP_CARGO_FUZZ_VERSION"; then
    log "cargo install cargo-fuzz $COP_CARGO_FUZZ_VERSION"
    cargo install cargo-fuzz --version "$COP_CARGO_FUZZ_VERSION" --locked --quiet
fi

if ! python3 -c "import canopen, can, sys; sys.exit(0 if canopen.__version__ == '$PY_CANOPEN_VERSION' else 1)" 2>/dev/null; then
    log "pip: canopen $PY_CANOPEN_VERSION, python-can $PY_CAN_VERSION"
    python3 -m pip install --quiet --disable-pip-version-check \
        "canopen==$PY_CANOPEN_VERSION" "python-can==$PY_CAN_VERSION"
fi
log "all prerequisites present"
