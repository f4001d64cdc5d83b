#!/usr/bin/env bash
# The import rules of ARCHITECTURE.md, checked on the sources (lint stage of
# scripts/test.sh). Each rule names the files it covers and the paths they
# must not use; comment lines are not looked at (doc links are no imports).
#
#   scripts/layers.sh        prints every violation, fails if there is one
set -euo pipefail
cd "$(dirname "$0")/.."

# Files that still break a rule, with the reason; each line is
# "<file> <layer it imports>". The dynamic OD checks PDO mappings with the
# PDO module's rules and SDO parameter objects against the SDO module's
# channels (its tests declare PDO objects).
EXCEPTIONS=(
    "src/od/dynamic.rs services"
    "src/od/dynamic/tests.rs services"
)

failed=0

# rule <name> <layer> <regex of the forbidden paths> <files...>
rule() {
    local name=$1 layer=$2 pattern=$3 file hits
    shift 3
    for file in "$@"; do
        [ -f "$file" ] || continue
        if printf '%s\n' "${EXCEPTIONS[@]}" | grep -qxF "$file $layer"; then
            continue
        fi
        hits=$(grep -nE "$pattern" "$file" | grep -vE '^[0-9]+:[[:space:]]*//' || true)
        if [ -n "$hits" ]; then
            printf '%s: %s\n' "$name" "$file"
            printf '    %s\n' "$hits"
            failed=1
        fi
    done
}

# A path into module $1 from anywhere in the crate: crate::m, super::m,
# super::super::m, or m inside a `use crate::{...}` group.
into() {
    printf '(\\b(crate|super)(::super)*::%s\\b)|(use crate::\\{[^}]*\\b%s\\b)' "$1" "$1"
}

mapfile -t CORE < <(find src -name '*.rs' -not -path 'src/ffi/*' -not -name lib.rs | sort)
mapfile -t OD < <(find src/od -name '*.rs' | sort)
mapfile -t WIRE < <(find src/wire -name '*.rs' | sort)
mapfile -t SERVICES < <(find src/nmt src/heartbeat src/emcy src/sync src/store src/sdo src/pdo \
    src/srdo -name '*.rs' 2>/dev/null | sort)

# The C layer sits on top: nothing of the core imports it.
rule "core imports the C layer" ffi "$(into ffi)" "${CORE[@]}"
# The dictionary knows neither the stack nor the services.
rule "dictionary imports the stack" ccm "$(into ccm)" "${OD[@]}"
rule "dictionary imports a service" services \
    "\\b(crate|super)(::super)*::(nmt|heartbeat|emcy|sync|store|sdo|pdo|srdo)\\b" "${OD[@]}"
# The services are driven by the stack, never the other way round.
rule "service imports the stack" ccm "$(into ccm)" "${SERVICES[@]}"
# Frame layouts are pure: they know the port's frame type, errors and the
# build configuration, nothing with state.
rule "wire imports a stateful layer" stateful \
    "\\b(crate|super)(::super)*::(od|ccm|event|sdo|pdo|srdo|nmt|heartbeat|emcy|sync|store|sim|testod)\\b" \
    "${WIRE[@]}"
# Inside the C layer: the registry, the callback adapter and the helpers
# below it know no exported function; the adapter and the helpers do not
# know the registry.
rule "C layer base imports an exported function" exported \
    "\\b(crate::ffi|super)::(ccm|master|pdo|services|srdo|dynod|stack_callbacks)\\b" \
    src/ffi/global.rs src/ffi/callbacks.rs src/ffi/ptr.rs src/ffi/types.rs src/ffi/driver.rs src/ffi/tables.rs
rule "C layer helper imports the registry" global "\\b(crate::ffi|super)::global\\b" \
    src/ffi/callbacks.rs src/ffi/ptr.rs src/ffi/types.rs src/ffi/driver.rs src/ffi/tables.rs
# unsafe is allowed in two modules only (src/lib.rs: ffi, src/od/mod.rs:
# table); a new allowance elsewhere is a decision for ARCHITECTURE.md.
allowed=$(grep -rnE 'allow\((unsafe_code)\)' src | grep -vE '^src/lib\.rs:[0-9]+:#\[allow\(unsafe_code\)\]$|^src/od/mod\.rs:[0-9]+:#\[allow\(unsafe_code\)\]$' || true)
if [ -n "$allowed" ]; then
    printf 'unsafe allowed outside src/ffi and src/od/table.rs:\n    %s\n' "$allowed"
    failed=1
fi

if [ "$failed" -ne 0 ]; then
    echo "layer rules violated (ARCHITECTURE.md, \"What each layer may import\")" >&2
    exit 1
fi
echo "layer rules hold (${#CORE[@]} core files)"
