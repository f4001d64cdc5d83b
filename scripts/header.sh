#!/usr/bin/env bash
# Generates include/cop.h from the exported functions (src/ffi) with
# cbindgen, in both instance forms at once:
#
#   scripts/header.sh            write include/cop.h
#   scripts/header.sh --verify   fail when the committed include/cop.h differs
#
# An exported function of a multi-instance build has a first parameter that
# exists only there (#[cfg(multi_instance)], src/ffi/instance.rs); cbindgen
# prints it as a plain parameter. This script writes it as the instance
# macro of the SYS TEC headers, which cop_types.h defines for both forms:
#
#   tCopInstanceHdl InstanceHandle     ->  CCM_DECL_INSTANCE_HDL(_)
#   tCopInstanceHdl *pInstanceHandle   ->  CCM_DECL_PTR_INSTANCE_HDL(_)
#   tCopPtrInstance pInstance          ->  MCO_DECL_INSTANCE_PTR(_)
#   tCopPtrInstance *pInstancePtr      ->  MCO_DECL_PTR_INSTANCE_PTR(_)
set -euo pipefail
cd "$(dirname "$0")/.."

raw=$(mktemp)
out=$(mktemp)
trap 'rm -f "$raw" "$out"' EXIT
cbindgen --quiet --config cbindgen.toml --crate cop --output "$raw"
sed -E \
    -e 's/tCopInstanceHdl InstanceHandle,[ ]?/CCM_DECL_INSTANCE_HDL_ /' \
    -e 's/tCopInstanceHdl InstanceHandle\)/CCM_DECL_INSTANCE_HDL)/' \
    -e 's/tCopInstanceHdl \*pInstanceHandle,[ ]?/CCM_DECL_PTR_INSTANCE_HDL_ /' \
    -e 's/tCopPtrInstance pInstance,[ ]?/MCO_DECL_INSTANCE_PTR_ /' \
    -e 's/tCopPtrInstance pInstance\)/MCO_DECL_INSTANCE_PTR)/' \
    -e 's/tCopPtrInstance \*pInstancePtr,[ ]?/MCO_DECL_PTR_INSTANCE_PTR_ /' \
    -e 's/_ $/_/' \
    "$raw" >"$out"
# Every instance parameter must have become a macro.
if grep -nE 'tCopInstanceHdl|tCopPtrInstance' "$out"; then
    echo "header.sh: an instance parameter of another form is left (above)" >&2
    exit 1
fi

if [ "${1:-}" = "--verify" ]; then
    if ! diff -u include/cop.h "$out"; then
        echo "include/cop.h is stale: run scripts/header.sh" >&2
        exit 1
    fi
    echo "include/cop.h is up to date"
else
    cp "$out" include/cop.h
fi
