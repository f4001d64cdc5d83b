#!/usr/bin/env bash
# Builds libcop.a for the TMS570 (armebv7r-none-eabihf, Cortex-R4F,
# big-endian), links it with arm-none-eabi-gcc against a C main that
# provides only the documented application symbols, fails on any other
# undefined symbol, and prints the sizes.
set -euo pipefail
cd "$(dirname "$0")/.."
T=armebv7r-none-eabihf
OUT=${CARGO_TARGET_DIR:-target}/tms570
mkdir -p "$OUT"
build() { # $1 = extra rustflags, $2 = cargo target dir suffix
    RUSTC_BOOTSTRAP=1 CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-target}/tms570-$2" \
        cargo rustc -q --release --lib --crate-type staticlib -Zbuild-std=core --target $T \
        -- -C target-cpu=cortex-r4f $1
    echo "${CARGO_TARGET_DIR:-target}/tms570-$2/$T/release/libcop.a"
}
ARM_LIB=$(build "" arm)
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

# 2. A real big-endian link against a C main.
CFLAGS="-mcpu=cortex-r4f -mbig-endian -mbe32 -mfloat-abi=hard -mfpu=vfpv3-d16 -Os -ffunction-sections -fdata-sections"
arm-none-eabi-gcc $CFLAGS -nostdlib -nostartfiles -Wl,--gc-sections -Wl,-e,_start -Wl,-z,noexecstack \
    -o "$OUT/link_check.elf" scripts/tms570/link_main.c "$ARM_LIB" -lgcc
echo "linked: $OUT/link_check.elf"
arm-none-eabi-size "$OUT/link_check.elf"
