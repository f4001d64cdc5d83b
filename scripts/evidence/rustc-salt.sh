#!/bin/sh
# RUSTC_WRAPPER of the coverage build of the C tests (scripts/evidence.sh):
# CMake builds the library once per configuration folder with the same Cargo
# features, so every build would get the same symbol names, and the profiles
# of two configurations whose functions differ would not merge ("counter
# mismatch"). A metadata value from the configuration folder makes the names
# differ; then the coverage wrapper of cargo-llvm-cov ($COP_COV_WRAPPER) runs.
salt=$(printf '%s|%s' "${COP_CONFIG_DIR:-}" "${COP_OBDCFG_DIR:-}" | cksum | cut -d' ' -f1)
exec "$COP_COV_WRAPPER" "$@" -Cmetadata="copcfg$salt"
