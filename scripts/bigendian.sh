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
    cmake -S . -B build-s390x -DCMAKE_TOOLCHAIN_FILE=cmake/s390x-toolchain.cmake \
        -DCOP_SANITIZERS=OFF -DCMAKE_BUILD_TYPE=Debug >/dev/null
    cmake --build build-s390x -j2
    ctest --test-dir build-s390x --output-on-failure -j2
fi
