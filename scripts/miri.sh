#!/usr/bin/env bash
# Runs every pure-Rust test (library unit tests and the whole-stack tests in
# tests/) under Miri, which detects undefined behaviour: out-of-bounds or
# dangling accesses through the dictionary tables, aliasing violations,
# uninitialised reads. The C API is not exercised here (Miri cannot call C);
# the C tests run under ASan/UBSan instead.
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-target}/miri"
cargo +nightly miri test -q --lib --tests
