# Pinned toolchain versions, sourced by scripts/setup.sh and every script that
# runs a second toolchain, so that a new release cannot change a test run.
#   stable Rust:  rust-toolchain.toml (1.95.0)
#   nightly Rust: Miri, cargo-fuzz (sanitizers), -Z emit-stack-sizes
#   cargo-fuzz:   the cargo subcommand for scripts/fuzz.sh
# shellcheck shell=bash
COP_NIGHTLY=nightly-2026-10-30
COP_CARGO_FUZZ_VERSION=0.13.2
COP_STABLE=1.95.0
