#!/usr/bin/env bash
# Runs the whole Rust test suite and the CTest suite big-endian: s390x under
# qemu-user (.cargo/config.toml names the linker and the runner).
set -euo pipefail
cd "$(dirname "$0")/.."
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-target}"
echo "--- cargo test --target s390x-unknown-linux-gnu"
cargo test -q --target s390x-unknown-linux-gnu
if [ -f cmake/s390x-toolchain.cmake ]; then
    echo "--- CTest, s390x"
    # The C tests here look at byte order, not at the shipped optimisation:
    # the library builds of the C tests (one per configuration) without LTO
    # at opt-level 0, with debug assertions and overflow checks, in a third
    # of the time. The host C tests (stage c), the target builds and the
    # benchmarks use the release profile as shipped.
    export CARGO_PROFILE_RELEASE_LTO=false CARGO_PROFILE_RELEASE_OPT_LEVEL=0 \
        CARGO_PROFILE_RELEASE_CODEGEN_UNITS=16 CARGO_PROFILE_RELEASE_DEBUG=false \
        CARGO_PROFILE_RELEASE_DEBUG_ASSERTIONS=true CARGO_PROFILE_RELEASE_OVERFLOW_CHECKS=true
    cmake -S . -B build-s390x -DCMAKE_TOOLCHAIN_FILE=cmake/s390x-toolchain.cmake \
        -DCOP_SANITIZERS=OFF -DCMAKE_BUILD_TYPE=Debug >/dev/null
    cmake --build build-s390x -j2
    ctest --test-dir build-s390x --output-on-failure -j2
fi
