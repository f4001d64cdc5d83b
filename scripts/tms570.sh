#!/usr/bin/env bash
# Builds libcop.a for the TMS570 (armebv7r-none-eabihf, Cortex-R4F,
# big-endian), links it with arm-none-eabi-gcc against a C main that
# provides only the documented application symbols, fails on any other
# undefined symbol, and prints the sizes.
#
#   scripts/tms570.sh          the link check (above)
#   scripts/tms570.sh run      also: the safety demo and the C tests as target
#                              programs under qemu-armeb, the alignment check
#                              and the stack table (scripts/tms570/run.sh)
#   scripts/tms570.sh sizes    .text of a complete safety node and an I/O node
#
# The archive is built with +strict-align: no instruction of it may access
# unaligned data (TMS570 start-up code may enable alignment faults).
# armebv7r-none-eabihf is a tier-3 target: rustup has no precompiled core
# for it, so core is built from rust-src (-Zbuild-std=core, allowed on the
# pinned stable compiler with RUSTC_BOOTSTRAP=1).
#
# Variants (used by scripts/bench.sh for the code-size table; the defaults
# are the plain link check):
#   TMS570_VARIANT=name   names the cargo target sub-directory and the image
#                         (default "arm"; image link_check.elf, others
#                         link_check-<name>.elf)
#   TMS570_OPT_LEVEL=z|s  release opt-level (default: Cargo.toml's profile)
#   TMS570_THUMB=1        Thumb-2 code (-C target-feature=+thumb-mode)
# Capacities such as COP_SRDO_MAX_SRDO_IN_OBD pass through to build.rs.
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in
run | sizes | stack) exec scripts/tms570/run.sh "$1" ;;
"" | link) ;;
*) echo "usage: $0 [link|run|sizes|stack]" >&2; exit 2 ;;
esac
T=armebv7r-none-eabihf
OUT=${CARGO_TARGET_DIR:-target}/tms570
mkdir -p "$OUT"
VARIANT=${TMS570_VARIANT:-arm}
FLAGS=""
if [ "${TMS570_THUMB:-0}" = 1 ]; then
    FLAGS="-C target-feature=+thumb-mode"
fi
if [ -n "${TMS570_OPT_LEVEL:-}" ]; then
    export CARGO_PROFILE_RELEASE_OPT_LEVEL=$TMS570_OPT_LEVEL
fi
build() { # $1 = extra rustflags, $2 = cargo target dir suffix
    # The flags go to every crate of the image (core included), so that a
    # Thumb-2 build is Thumb-2 throughout.
    RUSTC_BOOTSTRAP=1 CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-target}/tms570-$2" \
        RUSTFLAGS="-C target-cpu=cortex-r4f -C target-feature=+strict-align $1" \
        cargo rustc -q --release --lib --crate-type staticlib -Zbuild-std=core --target $T \
        2> >(grep -v -e 'unstable feature specified for `-Ctarget-feature`: `\(thumb-mode\|strict-align\)`' \
            -e 'this feature is not stably supported' -e '^ *|$' -e '^ *= \(note\|help\)' -e '^$' >&2) ||
        return 1 # (errexit does not reach into the command substitution)
    echo "${CARGO_TARGET_DIR:-target}/tms570-$2/$T/release/libcop.a"
}
ARM_LIB=$(build "$FLAGS" "$VARIANT")
echo "archive: $ARM_LIB"

# 1. The archive's undefined symbols: only Cdrv*, Tgt*, App* and mem*.
undef=$(arm-none-eabi-nm --target=elf32-bigarm -u "$ARM_LIB" 2>/dev/null | awk 'NF==2 {print $2}' | sort -u)
defined=$(arm-none-eabi-nm --target=elf32-bigarm --defined-only "$ARM_LIB" 2>/dev/null | awk 'NF==3 {print $3}' | sort -u)
missing=$(comm -23 <(echo "$undef") <(echo "$defined"))
bad=$(echo "$missing" | grep -Ev '^(Cdrv|Tgt|App)|^(__aeabi_)?mem(cpy|move|set|clr|cmp)[48]?$' || true)
echo "symbols the application provides:"
echo "$missing" | sed 's/^/  /'
if [ -n "$bad" ]; then
    echo "FAIL: undocumented undefined symbols:" $bad
    exit 1
fi

# 2. No object of the archive may access unaligned data (+strict-align).
members=$(readelf -A "$ARM_LIB" | grep -c '^File: ')
aligned=$(readelf -A "$ARM_LIB" | grep -c 'Tag_CPU_unaligned_access: None')
if [ "$members" -eq 0 ] || [ "$aligned" -ne "$members" ]; then
    echo "FAIL: $aligned of $members objects have Tag_CPU_unaligned_access None"
    exit 1
fi
echo "alignment: $members of $members objects Tag_CPU_unaligned_access None"

# 3. A real big-endian link against a C main.
ELF="$OUT/link_check.elf"
[ "$VARIANT" = arm ] || ELF="$OUT/link_check-$VARIANT.elf"
CFLAGS="-mcpu=cortex-r4f -mbig-endian -mbe32 -mfloat-abi=hard -mfpu=vfpv3-d16 -Os -ffunction-sections -fdata-sections"
arm-none-eabi-gcc $CFLAGS -nostdlib -nostartfiles -Wl,--gc-sections -Wl,-e,_start -Wl,-z,noexecstack \
    -o "$ELF" scripts/tms570/link_main.c "$ARM_LIB" -lgcc
echo "linked: $ELF"
arm-none-eabi-size "$ELF"
