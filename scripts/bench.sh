#!/usr/bin/env bash
# The benchmark table: instruction counts (callgrind on the host, x86-64),
# code sizes and RAM of the TMS570 build (armebv7r-none-eabihf).
#
#   scripts/bench.sh                         measure and print the report
#   scripts/bench.sh > docs/benchmarks.md    what docs/benchmarks.md is
#   scripts/bench.sh --json                  the figures as one JSON object
#
# The report (Markdown) goes to stdout, build and progress messages to
# stderr. The script fails only when a measurement fails (a build, a
# valgrind run, or a scenario whose own checks fail); a figure that misses
# its target is reported in the table, never an error.
#
# Method (details in the notes the report prints):
# * bench/ is a separate crate (own workspace) that depends on the library
#   with `std` and runs one scenario N times; each measured region is an
#   `#[inline(never)] fn measure_*`. callgrind counts only inside it
#   (--collect-atstart=no --toggle-collect); the figure per call is
#   (Ir(2N) - Ir(N)) / N, so set-up and one-time costs cancel.
# * bench/capi is a C program linked against libcop.a as a C application
#   links it (its own copcfg.h / obdcfg.h / objdict.h, a C driver, the
#   App* callbacks); its measured regions are C functions `measure_*`.
# * Code sizes: scripts/tms570.sh builds and links the TMS570 image in
#   four variants (ARM / Thumb-2 x opt-level s / z);
#   scripts/tms570/code_size.py attributes the code to source files and
#   functions; `scripts/tms570.sh sizes` links the safety demo and the I/O
#   node example and gives their .text.
# * RAM: bench/target-sizes exports `size_of` of the stack's types for the
#   target as symbol sizes, read with arm-none-eabi-nm; the field layout of
#   the per-SRDO types is rustc's (-Zprint-type-sizes, scripts/type_layout.py).
set -euo pipefail
shopt -s inherit_errexit
cd "$(dirname "$0")/.."
JSON=0
case "${1:-}" in
    --json) JSON=1 ;;
    "") ;;
    *) printf 'usage: scripts/bench.sh [--json]\n' >&2; exit 2 ;;
esac
ROOT=$(pwd)
export PATH="$HOME/.cargo/bin:$PATH"
export CARGO_TERM_COLOR=never
OUT=${CARGO_TARGET_DIR:-$ROOT/target}
case "$OUT" in /*) ;; *) OUT=$ROOT/$OUT ;; esac
WORK=$OUT/bench-work
mkdir -p "$WORK"
log() { printf '[bench] %s\n' "$*" >&2; }
die() { printf '[bench] FAILED: %s\n' "$*" >&2; exit 1; }

for tool in valgrind arm-none-eabi-gcc arm-none-eabi-nm python3; do
    command -v "$tool" >/dev/null || die "$tool missing (scripts/setup.sh installs it)"
done

# ------------------------------------------------------------ host builds
host_build() { # $1 = name, rest = cargo arguments; prints the binary
    log "host build ($1)"
    (cd bench && CARGO_TARGET_DIR="$OUT/bench-host-$1" cargo build -q --release "${@:2}" >&2) ||
        die "bench build ($1)"
    echo "$OUT/bench-host-$1/release/cop-bench"
}
BIN_PM=$(host_build progmon)
BIN_NOPM=$(host_build no-progmon --no-default-features)

# Ir inside `measure_<fn>` for one run: ir <binary> <fn> <args...>
# (bench/capi binaries: C functions without the crate prefix; their
# profiles stay in $WORK for `where` below).
rm -f "$WORK"/profile-*.out
ir() {
    local bin=$1 fn=$2 out sym
    shift 2
    out=$WORK/profile-$(basename "$bin")-$(IFS=-; echo "$*").out
    sym="cop_bench::measure_$fn"
    case "$bin" in */capi-*) sym="measure_$fn" ;; esac
    rm -f "$out"
    valgrind --tool=callgrind --callgrind-out-file="$out" --collect-atstart=no \
        --toggle-collect="$sym" "$bin" "$@" >/dev/null 2>"$WORK/valgrind.log" ||
        { cat "$WORK/valgrind.log" >&2; die "cop-bench $*"; }
    awk '/^summary:/ {print $2; found=1} END {if (!found) exit 1}' "$out" ||
        die "no callgrind summary for cop-bench $*"
    case "$bin" in */capi-*) ;; *) rm -f "$out" ;; esac
}

# Instructions per call: per_call <binary> <fn> <N> <scenario args...>
# (Ir at 2N iterations - Ir at N iterations) / N.
per_call() {
    local bin=$1 fn=$2 n=$3 a b
    shift 3
    a=$(ir "$bin" "$fn" "$@" "$n")
    b=$(ir "$bin" "$fn" "$@" $((2 * n)))
    awk -v a="$a" -v b="$b" -v n="$n" 'BEGIN {printf "%.1f\n", (b - a) / n}'
}

# Number formatting: 1234.0 -> 1,234; 12.5 -> 12.5.
fmt() {
    awk -v x="$1" 'BEGIN {
        r = sprintf("%.1f", x); if (r ~ /\.0$/) r = sprintf("%d", x + (x < 0 ? -0.5 : 0.5));
        split(r, p, "."); s = p[1]; o = "";
        while (length(s) > 3) { o = "," substr(s, length(s) - 2) o; s = substr(s, 1, length(s) - 3) }
        printf "%s%s%s", s, o, (p[2] != "" ? "." p[2] : "")
    }'
}
minus() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.1f\n", a - b}'; }
div() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.1f\n", a / b}'; }
# verdict <measured> <target>: "met" or "MISSED by D (+P %)".
verdict() {
    local d p
    if awk -v m="$1" -v t="$2" 'BEGIN {exit !(m <= t)}'; then
        echo met
        return
    fi
    d=$(awk -v m="$1" -v t="$2" 'BEGIN {printf "%d\n", m - t + 0.5}')
    p=$(awk -v m="$1" -v t="$2" 'BEGIN {printf "%d\n", (m - t) * 100 / t + 0.5}')
    echo "MISSED by $(fmt "$d") (+$(fmt "$p") %)"
}

CYCLES=500    # cycles per run (N); 2N in the second run
LOOKUPS=6000  # a multiple of the address count of every lookup dictionary
CRCS=200

# ------------------------------------------------------------------- SRDO
log "SRDO reception and idle cycles (progmon on and off)"
declare -A RX IDLE
for pm in on off; do
    bin=$BIN_PM
    [ $pm = off ] && bin=$BIN_NOPM
    for n in 1 8 32 64; do
        IDLE[$pm,$n]=$(per_call "$bin" cycle $CYCLES srdo-idle $n)
        rx_cycle=$(per_call "$bin" cycle $CYCLES srdo-rx $n)
        RX[$pm,$n]=$(minus "$rx_cycle" "${IDLE[$pm,$n]}")
    done
done
per_srdo_idle() { div "$(minus "${IDLE[$1,64]}" "${IDLE[$1,1]}")" 63; }
IDLE_PER_OFF=$(per_srdo_idle off)
IDLE_PER_ON=$(per_srdo_idle on)
flat() { # spread of RX[$1,*] from 1 to 64 in percent
    awk -v a="${RX[$1,1]}" -v b="${RX[$1,64]}" 'BEGIN {printf "%+.1f\n", (b - a) * 100 / a}'
}
FLAT_ON=$(flat on)
FLAT_OFF=$(flat off)

# ------------------------------------------------------------------ C API
# libcop.a with bench/capi/cfg (program monitor on) or cfg_nopm (off), the
# C program compiled for 1, 8, 32 and 64 receive SRDOs.
capi_build() { # $1 = on | off | two (two instances, program monitor off)
    local cfg=cfg dir=$OUT/bench-capi-$1 n counts="1 8 32 64" extra=""
    [ "$1" = off ] && cfg=cfg_nopm
    [ "$1" = two ] && cfg=cfg_two && counts=1 && extra=bench/capi/objdict_other.c
    log "C API build (program monitor $1)"
    COP_CONFIG_DIR=$ROOT/bench/capi/$cfg CARGO_TARGET_DIR=$dir \
        cargo build -q --release --features std --lib >&2 || die "libcop.a (bench/capi/$cfg)"
    for n in $counts; do
        # shellcheck disable=SC2086 # $extra: the second dictionary or nothing
        gcc -O2 -Wall -Wextra -Werror -DBENCH_SRDOS=$n -DCOP_HOST_SIMULATION -Iinclude \
            -Ibench/capi/$cfg -Ibench/capi bench/capi/capi.c bench/capi/objdict.c $extra \
            "$dir/release/libcop.a" -lpthread -ldl -lm -o "$WORK/capi-$1-$n" || die "bench/capi ($1, $n)"
    done
}
declare -A CRX CIDLE
for pm in on off; do
    capi_build $pm
    log "C API cycles (program monitor $pm)"
    for n in 1 8 32 64; do
        CIDLE[$pm,$n]=$(per_call "$WORK/capi-$pm-$n" cycle $CYCLES idle)
        CRX[$pm,$n]=$(minus "$(per_call "$WORK/capi-$pm-$n" cycle $CYCLES rx)" "${CIDLE[$pm,$n]}")
    done
done
# The pair on instance 1 of a two-instance build (program monitor off).
capi_build two
log "C API cycles (two instances)"
CIDLE[two,1]=$(per_call "$WORK/capi-two-1" cycle $CYCLES idle)
CRX[two,1]=$(minus "$(per_call "$WORK/capi-two-1" cycle $CYCLES rx)" "${CIDLE[two,1]}")
CTWO_PCT=$(awk -v a="${CRX[off,1]}" -v b="${CRX[two,1]}" 'BEGIN {printf "%+.1f\n", (b - a) * 100 / a}')
# The program monitor's idle cost per receive SRDO (an AppProgMonEvent per
# SRDO and CcmProcess), from the idle cycles with 1 and 64 SRDOs.
CPM_PER_SRDO=$(awk -v a="${CIDLE[on,1]}" -v b="${CIDLE[on,64]}" 'BEGIN {printf "%.0f\n", (b - a) / 63}')
CHANDSHAKE=$(per_call "$WORK/capi-off-8" handshake $CYCLES handshake)
CSEND=$(per_call "$WORK/capi-off-8" send $CYCLES send)
# Where the instructions of a C API figure go: where <binary> <fn> <scenario>
# [<base scenario>] prints bench/where.py's table (self cost per part of the
# library, from the same N / 2N runs as per_call).
profile() { # <binary> <fn> <scenario> <N> -> the profile file of that run
    local out=$WORK/profile-$(basename "$1")-$3-$4.out
    [ -f "$out" ] || ir "$@" >/dev/null
    echo "$out"
}
where() {
    local bin=$1 fn=$2 files=()
    for s in "${@:3}"; do
        files+=("$(profile "$bin" "$fn" "$s" $CYCLES)" "$(profile "$bin" "$fn" "$s" $((2 * CYCLES)))")
    done
    (cd "$WORK" && python3 "$ROOT/bench/where.py" "$ROOT" $CYCLES "${files[@]}") || die "bench/where.py"
}
log "C API: where the instructions go"
WHERE_PAIR_OFF=$(where "$WORK/capi-off-1" cycle rx idle)
WHERE_PAIR_ON=$(where "$WORK/capi-on-1" cycle rx idle)
WHERE_IDLE=$(where "$WORK/capi-off-8" cycle idle)
WHERE_SEND=$(where "$WORK/capi-off-8" send send)
WHERE_HANDSHAKE=$(where "$WORK/capi-off-8" handshake handshake)
cflat() { awk -v a="${CRX[$1,1]}" -v b="${CRX[$1,64]}" 'BEGIN {printf "%+.1f\n", (b - a) * 100 / a}'; }
CFLAT_ON=$(cflat on)
CFLAT_OFF=$(cflat off)

log "CRC"
CRC=$(per_call "$BIN_PM" crc $CRCS srdo-crc16)

log "dictionary lookups"
declare -A FIND
for n in 30 300 3000; do
    FIND[$n]=$(per_call "$BIN_PM" find $LOOKUPS od-find $n)
done
# Growth per doubling of the dictionary, 30 -> 3000 objects.
PER_DOUBLING=$(awk -v a="${FIND[30]}" -v b="${FIND[3000]}" \
    'BEGIN {printf "%.1f\n", (b - a) / (log(100) / log(2))}')

log "SDO expedited transfers"
SDO_IDLE=$(per_call "$BIN_PM" cycle $CYCLES sdo-idle)
SDO_UP=$(minus "$(per_call "$BIN_PM" cycle $CYCLES sdo-upload)" "$SDO_IDLE")
SDO_DOWN=$(minus "$(per_call "$BIN_PM" cycle $CYCLES sdo-download)" "$SDO_IDLE")

log "DynBuildOd"
# The scenario prints "container <bytes> bytes <entries> entries".
info=$("$BIN_PM" dyn-build 1536 1) || die "dyn-build 1536"
read -r _ DYN_BYTES _ DYN_ENTRIES _ <<<"$info"
info=$("$BIN_PM" dyn-build 768 1) || die "dyn-build 768"
read -r _ DYN_BYTES_HALF _ DYN_ENTRIES_HALF _ <<<"$info"
DYN_FULL=$(per_call "$BIN_PM" dyn_build 3 dyn-build 1536)
DYN_HALF=$(per_call "$BIN_PM" dyn_build 3 dyn-build 768)
DYN_RATIO=$(awk -v a="$DYN_FULL" -v b="$DYN_HALF" 'BEGIN {printf "%.2f\n", a / b}')
DYN_LINEAR=$(awk -v r="$DYN_RATIO" 'BEGIN {print (r <= 2.2 ? "linear" : "NOT linear")}')

# ------------------------------------------------------------------ sizes
declare -A CODE TEXT DATA BSS
for v in arm-s arm-z thumb-s thumb-z; do
    log "TMS570 image $v"
    thumb=0
    case $v in thumb-*) thumb=1 ;; esac
    TMS570_VARIANT=$v TMS570_OPT_LEVEL=${v#*-} TMS570_THUMB=$thumb CARGO_TARGET_DIR=$OUT \
        scripts/tms570.sh >"$WORK/tms570-$v.log" || { cat "$WORK/tms570-$v.log" >&2; die "tms570.sh ($v)"; }
    elf=$(awk '/^linked: / {print $2}' "$WORK/tms570-$v.log")
    python3 scripts/tms570/code_size.py "$elf" --files --functions 10 >"$WORK/size-$v.txt" ||
        die "code_size.py ($v)"
    CODE[$v]=$(awk -F= '/^srdo_total=/ {print $2}' "$WORK/size-$v.txt")
    TEXT[$v]=$(awk -F= '/^text=/ {print $2}' "$WORK/size-$v.txt")
    DATA[$v]=$(awk -F= '/^data=/ {print $2}' "$WORK/size-$v.txt")
    BSS[$v]=$(awk -F= '/^bss=/ {print $2}' "$WORK/size-$v.txt")
done
log "TMS570 image with SRDO_MAX_SRDO_IN_OBD = 8"
TMS570_VARIANT=arm-s-srdo8 TMS570_OPT_LEVEL=s COP_SRDO_MAX_SRDO_IN_OBD=8 CARGO_TARGET_DIR=$OUT \
    scripts/tms570.sh >"$WORK/tms570-srdo8.log" || { cat "$WORK/tms570-srdo8.log" >&2; die "tms570.sh (8 SRDOs)"; }
ELF8=$(awk '/^linked: / {print $2}' "$WORK/tms570-srdo8.log")
read -r _ DATA8 BSS8 _ < <(arm-none-eabi-size "$ELF8" | awk 'NR == 2')
log "TMS570 safety node and I/O node (scripts/tms570.sh sizes)"
CARGO_TARGET_DIR=$OUT scripts/tms570.sh sizes >"$WORK/tms570-nodes.log" ||
    { cat "$WORK/tms570-nodes.log" >&2; die "tms570.sh sizes"; }
# "target-size: safety node .text T bytes (libcop.a L), I/O node .text T bytes (libcop.a L); ..."
read -r TEXT_SAFETY LIB_SAFETY TEXT_IO LIB_IO < <(sed -n \
    's|^target-size: safety node \.text \([0-9]*\) bytes (libcop\.a \([0-9]*\)), I/O node \.text \([0-9]*\) bytes (libcop\.a \([0-9]*\)).*|\1 \2 \3 \4|p' \
    "$WORK/tms570-nodes.log") || true
[ -n "${LIB_IO:-}" ] || { cat "$WORK/tms570-nodes.log" >&2; die "no target-size line from tms570.sh sizes"; }

# ------------------------------------------------------------------- RAM
declare -A SIZE
# target_sizes <key> <capacity> [cargo args]: SIZE[<key>,<TYPE>] = bytes.
target_sizes() {
    local key=$1 cap=$2 dir=$OUT/bench-target-sizes lib
    shift 2
    [ $# -gt 0 ] && dir=$dir-variant
    log "target layout with SRDO_MAX_SRDO_IN_OBD = $cap $*"
    (cd bench/target-sizes && COP_SRDO_MAX_SRDO_IN_OBD=$cap RUSTC_BOOTSTRAP=1 \
        CARGO_TARGET_DIR="$dir" RUSTFLAGS="-C target-cpu=cortex-r4f" \
        cargo build -q --release -Zbuild-std=core --target armebv7r-none-eabihf "$@" >&2) ||
        die "target-sizes build ($cap $*)"
    lib=$dir/armebv7r-none-eabihf/release/libcop_target_sizes.a
    while read -r name bytes; do
        SIZE[$key,$name]=$bytes
    done < <(arm-none-eabi-nm -S "$lib" 2>/dev/null | python3 -c '
import sys
for line in sys.stdin:
    c = line.split()
    if len(c) == 4 and c[3].startswith("COP_SIZEOF_"):
        print(c[3][len("COP_SIZEOF_"):], int(c[1], 16))')
    [ -n "${SIZE[$key,STACK]:-}" ] || die "no COP_SIZEOF_STACK in $lib"
}
for cap in 1 8 64; do
    target_sizes "$cap" "$cap"
done
# Field layout of the per-SRDO types at capacity 64, as rustc lays them out
# for the target (the leaf crate is rebuilt so that rustc prints it).
log "target field layout of the per-SRDO types (-Zprint-type-sizes)"
(cd bench/target-sizes && cargo clean -q --release --target armebv7r-none-eabihf -p cop-target-sizes \
    --target-dir "$OUT/bench-target-sizes" >&2 && COP_SRDO_MAX_SRDO_IN_OBD=64 RUSTC_BOOTSTRAP=1 \
    CARGO_TARGET_DIR="$OUT/bench-target-sizes" RUSTFLAGS="-C target-cpu=cortex-r4f" \
    cargo rustc -q --release -Zbuild-std=core --target armebv7r-none-eabihf --lib -- -Zprint-type-sizes \
    >"$WORK/type-sizes.txt") || die "target-sizes build (-Zprint-type-sizes)"
python3 scripts/type_layout.py "$WORK/type-sizes.txt" cop::srdo::Slot cop::srdo::plan::Plan \
    cop::srdo::plan::General >"$WORK/srdo-layout.txt" || die "type_layout.py"
type_size() { awk -F'\t' -v t="$1" '$1 == t && $2 == "(size)" {print $4}' "$WORK/srdo-layout.txt"; }
SLOT_BYTES=$(type_size cop::srdo::Slot)
PLAN_BYTES=$(type_size cop::srdo::plan::Plan)
target_sizes static1 1 --features cop/srdo-static-mapping
target_sizes static64 64 --features cop/srdo-static-mapping
# Per SRDO: what one more SRDO of capacity adds (slot + copy plan).
PER_SRDO=$(awk -v a="${SIZE[1,SRDO]}" -v b="${SIZE[64,SRDO]}" 'BEGIN {printf "%.1f\n", (b - a) / 63}')
# What the per-SRDO figure holds beyond one Slot and one Plan (the Srdo's
# own alignment padding spread over 63 SRDOs, or a per-SRDO array that the
# layout table does not list).
PER_SRDO_REST=$(awk -v p="$PER_SRDO" -v s="$SLOT_BYTES" -v q="$PLAN_BYTES" 'BEGIN {printf "%.1f\n", p - s - q}')
SRDO_FIXED=$(awk -v s="${SIZE[1,SRDO]}" -v p="$PER_SRDO" 'BEGIN {printf "%.0f\n", s - p}')
PER_SRDO_STATIC=$(awk -v a="${SIZE[static1,SRDO]}" -v b="${SIZE[static64,SRDO]}" 'BEGIN {printf "%.1f\n", (b - a) / 63}')
PER_SRDO_AT8=$(awk -v s="${SIZE[8,SRDO]}" 'BEGIN {printf "%.1f\n", s / 8}')

# ----------------------------------------------------------------- report
RUSTC=$(rustc -V)
VALGRIND=$(valgrind --version)
ARMGCC=$(arm-none-eabi-gcc --version | head -1)
COMMIT=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
DIRTY=$(git status --porcelain --untracked-files=no 2>/dev/null | grep -q . && echo " (with uncommitted changes)" || true)

# The figures as one JSON object: in $WORK/figures.json after every run,
# on stdout instead of the report with --json.
{
    printf '{"capi_srdo_pair_pm_on": %s, "capi_srdo_pair_pm_off": %s, "capi_srdo_pair_pm_on_64": %s, ' \
        "${CRX[on,1]}" "${CRX[off,1]}" "${CRX[on,64]}"
    printf '"capi_state_handshake": %s, "capi_idle_process": %s, "capi_send_srdo": %s, ' \
        "$CHANDSHAKE" "${CIDLE[off,8]}" "$CSEND"
    printf '"rust_srdo_pair_pm_on": %s, "rust_srdo_pair_pm_off": %s, ' "${RX[on,1]}" "${RX[off,1]}"
    printf '"code_srdo_gfc_crc_arm_z": %s, "code_srdo_gfc_crc_thumb_z": %s, ' "${CODE[arm-z]}" "${CODE[thumb-z]}"
    printf '"text_safety_node": %s, "text_io_node": %s, "ram_per_srdo_dynamic": %s, ' \
        "$TEXT_SAFETY" "$TEXT_IO" "$PER_SRDO"
    printf '"capi_srdo_pair_two_instances": %s, "capi_idle_per_srdo_pm_on": %s}\n' \
        "${CRX[two,1]}" "$CPM_PER_SRDO"
} >"$WORK/figures.json"
if [ $JSON = 1 ]; then
    cat "$WORK/figures.json"
    log "done"
    exit 0
fi

cat <<EOF
# Benchmarks

Measured on $(date -u +%Y-%m-%d) at commit \`$COMMIT\`$DIRTY with $RUSTC, $VALGRIND and
$ARMGCC. Reproduce with

    scripts/bench.sh > docs/benchmarks.md

(part of \`scripts/test.sh\`, stage \`bench\`; it takes a few minutes). Instruction
counts are x86-64 instructions counted by callgrind (exact and repeatable,
not times); sizes and RAM are those of the TMS570 build
(\`armebv7r-none-eabihf\`, Cortex-R4F, big-endian).

| figure | target | measured | verdict |
|---|---|---|---|
| C API: received SRDO pair through \`CcmProcess\`, C driver and \`AppSrdoEvent\` with the handshake, 1 SRDO (program monitor off / on) | ≤ 300 / ≤ 350 | $(fmt "${CRX[off,1]}") / $(fmt "${CRX[on,1]}") | $(verdict "${CRX[off,1]}" 300) / $(verdict "${CRX[on,1]}" 350) |
| C API pair with 1, 8, 32, 64 configured SRDOs (program monitor on) | flat (≤ +10 %) | $(fmt "${CRX[on,1]}") / $(fmt "${CRX[on,8]}") / $(fmt "${CRX[on,32]}") / $(fmt "${CRX[on,64]}") ($CFLAT_ON %) | $(awk -v f="$CFLAT_ON" 'BEGIN {print (f <= 10 ? "met" : "MISSED")}') |
| the same, program monitor off | flat | $(fmt "${CRX[off,1]}") / $(fmt "${CRX[off,8]}") / $(fmt "${CRX[off,32]}") / $(fmt "${CRX[off,64]}") ($CFLAT_OFF %) | $(awk -v f="$CFLAT_OFF" 'BEGIN {print (f <= 10 ? "met" : "MISSED")}') |
| C API: \`CcmGetSrdoState\` + \`CcmSetSrdoState\` | ≤ 40 | $(fmt "$CHANDSHAKE") | $(verdict "$CHANDSHAKE" 40) |
| C API: idle \`CcmProcess\`, 8 SRDOs, heartbeat producer, SDO server, 4 PDOs (program monitor off) | ≤ 120 | $(fmt "${CIDLE[off,8]}") | $(verdict "${CIDLE[off,8]}" 120) |
| C API: received SRDO pair on instance 1 of a two-instance build (program monitor off), against one instance | ≤ +10 % | $(fmt "${CRX[two,1]}") ($CTWO_PCT %) | $(awk -v f="$CTWO_PCT" 'BEGIN {print (f <= 10 ? "met" : "MISSED")}') |
| C API: idle \`CcmProcess\` per receive SRDO, program monitor on (an \`AppProgMonEvent\` each) | ≤ 90 | $(fmt "$CPM_PER_SRDO") | $(verdict "$CPM_PER_SRDO" 90) |
| C API: \`CcmSendSrdo\`, one transmit SRDO (4 × UNSIGNED8), both \`CdrvWriteMsg\` | ≤ 250 | $(fmt "$CSEND") | $(verdict "$CSEND" 250) |
| instructions per valid received SRDO pair, 4 mapped bytes (program monitor on / off) | ≤ 300 | $(fmt "${RX[on,1]}") / $(fmt "${RX[off,1]}") | $(verdict "${RX[on,1]}" 300) / $(verdict "${RX[off,1]}" 300) |
| the same with 1, 8, 32, 64 configured SRDOs (program monitor on) | flat (≤ +10 % from 1 to 64) | $(fmt "${RX[on,1]}") / $(fmt "${RX[on,8]}") / $(fmt "${RX[on,32]}") / $(fmt "${RX[on,64]}") ($FLAT_ON %) | $(awk -v f="$FLAT_ON" 'BEGIN {print (f <= 10 ? "met" : "MISSED")}') |
| the same, program monitor off | flat | $(fmt "${RX[off,1]}") / $(fmt "${RX[off,8]}") / $(fmt "${RX[off,32]}") / $(fmt "${RX[off,64]}") ($FLAT_OFF %) | $(awk -v f="$FLAT_OFF" 'BEGIN {print (f <= 10 ? "met" : "MISSED")}') |
| instructions per SRDO per idle \`CcmProcess\` tick (program monitor off / on) | ≤ 15 / report | $(fmt "$IDLE_PER_OFF") / $(fmt "$IDLE_PER_ON") | $(verdict "$IDLE_PER_OFF" 15) / reported |
| \`CcmCalcSrdoCrc\`, 16 mapping entries | ≤ 1,500 | $(fmt "$CRC") | $(verdict "$CRC" 1500) |
| OD lookup in a 300-object dictionary | ≤ 80, O(log n) | $(fmt "${FIND[300]}") (30: $(fmt "${FIND[30]}"), 3,000: $(fmt "${FIND[3000]}"); +$(fmt "$PER_DOUBLING") per doubling) | $(verdict "${FIND[300]}" 80); O(log n) |
| SDO expedited request → response (upload / download) | report | $(fmt "$SDO_UP") / $(fmt "$SDO_DOWN") | reported |
| \`DynBuildOd\` of a 1.5 KB container | ≤ 200,000, linear in entries | $(fmt "$DYN_FULL") ($(fmt "$DYN_BYTES") B, $DYN_ENTRIES entries); $DYN_BYTES_HALF B, $DYN_ENTRIES_HALF entries: $(fmt "$DYN_HALF"); ratio $DYN_RATIO for twice the entries | $(verdict "$DYN_FULL" 200000); $DYN_LINEAR |
| code size SRDO+GFC+CRC, ARM (opt-level z / s) | ≤ 6,000 B | $(fmt "${CODE[arm-z]}") / $(fmt "${CODE[arm-s]}") B | $(verdict "${CODE[arm-z]}" 6000) / $(verdict "${CODE[arm-s]}" 6000) |
| code size SRDO+GFC+CRC, Thumb-2 (opt-level z / s) | ≤ 4,000 B | $(fmt "${CODE[thumb-z]}") / $(fmt "${CODE[thumb-s]}") B | $(verdict "${CODE[thumb-z]}" 4000) / $(verdict "${CODE[thumb-s]}" 4000) |
| \`.text\` of a complete safety node (safety demo, TMS570, ARM, opt-level of Cargo.toml) | report | $(fmt "$TEXT_SAFETY") B (libcop.a $(fmt "$LIB_SAFETY") B) | reported |
| \`.text\` of an I/O node (examples_c/io_node, TMS570, ARM) | report | $(fmt "$TEXT_IO") B (libcop.a $(fmt "$LIB_IO") B) | reported |
| RAM per SRDO (dynamic mapping, the default) | ≤ 64 B | $(fmt "$PER_SRDO") B: \`Slot\` $SLOT_BYTES + \`Plan\` $PLAN_BYTES (+ $SRDO_FIXED B per node; $(fmt "$PER_SRDO_AT8") B per SRDO at 8 SRDOs) | $(verdict "$PER_SRDO" 64) |
| RAM per SRDO, static mapping (\`srdo-static-mapping\`) | ≤ 64 B | $(fmt "$PER_SRDO_STATIC") B | $(verdict "$PER_SRDO_STATIC" 64) |
| RAM of the whole stack with 8 SRDOs | report | $(fmt "${SIZE[8,STACK]}") B (\`Stack\`); C API instance $(fmt "${SIZE[8,INSTANCE]}") B; image .data + .bss $(fmt "$DATA8") + $(fmt "$BSS8") B | reported |

## What each row measures

* **C API rows** (bench/capi): a C program linked against libcop.a (built
  with bench/capi/cfg or cfg_nopm) as a C application links it, with an
  objdict.h dictionary (bench/capi/objdict.h: n receive SRDOs of four
  UNSIGNED8 entries each, normal / inverted / normal / inverted, 2 data
  bytes per frame; a transmit SRDO after them; heartbeat producer 60 s,
  SDO server, two receive and two transmit PDOs), a C driver (a ring of
  received frames handed out by \`CdrvReadMsg\` / \`CdrvReleaseMsg\`, a
  counter behind \`CdrvWriteMsg\`) and the manual's \`AppSrdoEvent\`
  (\`CcmGetSrdoState\`, checks bits 4-5, \`CcmSetSrdoState\` with bits
  4-5 set). Pair = \`CcmProcess\` that reads both frames of the last
  SRDO minus an idle \`CcmProcess\` of the same node; the driver's and
  the callback's instructions are included. Handshake: the two calls from
  the main loop. Send: \`CcmSendSrdo\` of the transmit SRDO (node with 8
  receive SRDOs, program monitor off). Each run checks one event per pair,
  the mapped variables, no \`AppSrdoError\` and two frames per send.

* **Received SRDO pair**: one \`CcmProcess\` cycle (\`Stack::process\`) of a node
  with n running receive SRDOs that takes the normal and the inverted frame
  of SRDO n (4 data bytes each, two UNSIGNED16 pairs) from the driver: both
  frames' dispatch (NMT, error control, SRDO COB-ID table), the checks, the
  writes of the four mapped variables, the events with the
  application's handling of them (\`AppSrdoEvent\` marks the SRDO processed
  with \`CcmGetSrdoState\` / \`CcmSetSrdoState\`; with the program monitor,
  \`AppProgMonEvent\` for the received SRDO), **minus** an idle cycle of the
  same node (so the timer checks of all SRDOs and the other modules' polls
  are not counted). The driver is an in-memory ring (bench/src/port.rs), a
  few instructions per frame. SCT 65.535 s, SRVT 20 ms, 100 µs ticks
  advancing by one per cycle, so no deadline passes.
* **Idle tick per SRDO**: (idle cycle with 64 receive SRDOs − idle cycle with
  1) / 63. With the program monitor every SRDO reports
  \`kSrdoPMEvSctChecked\` in every cycle, so each SRDO costs one event round
  trip to the application.
* **CRC**: \`Srdo::calc_crc\`, the whole work of \`CcmCalcSrdoCrc\` except the
  pointer check and the instance lock: the 93-byte stream (13 parameter
  bytes + 16 × 5) read from the dictionary and the CRC-16 over it.
* **OD lookup**: \`ObjectDictionary::find(index, sub)\` with the call
  itself, averaged over every (index, subindex) of a dictionary whose
  objects all lie in one part (0x2000–0x5FFF; the worst case, lookups
  search one part): half plain variables, half records of three
  subindices, looked up in a fixed shuffled order. 30, 300 and 3,000
  objects; the growth per doubling of the dictionary shows O(log n).
* **SDO**: one cycle that takes an expedited request from the driver and
  sends the response, minus an idle cycle (reference dictionary
  \`cop::testod\`, PRE-OPERATIONAL): upload of 0x1018 sub 1 (ROM), download
  of 4 bytes to 0x2002 (UNSIGNED32 RAM, range and access checks, write
  hooks).
* **DynBuildOd**: \`DynPool::build\` (the work of \`DynBuildOd\` after its
  pointer checks) on the reference dictionary in PRE-OPERATIONAL, with the
  tables in a static pool and no process image; \`DynDestroyOd\` after each
  build is not measured. The container is generated (bench/src/main.rs,
  \`dyn_container\`): per group of four entries a new record 0x3000 + g
  with an UNSIGNED32, an UNSIGNED16 and an UNSIGNED8 (numeric, read-write)
  and a write of the existing UNSIGNED32 0x2002. Twice the entries should
  cost about twice (ratio ≈ 2) when the build is linear.
* **Code size**: the image scripts/tms570.sh links (scripts/tms570/link_main.c
  calls CcmInitCANopen, CcmProcess, Ccm{Read,Write}Object, CcmSendSrdo,
  CcmSendGfc, CcmCheckSrdoConfig, CcmCalcSrdoCrc, Ccm{Get,Set}SrdoState),
  LTO, \`--gc-sections\`. Code counts for SRDO+GFC+CRC when the DWARF line
  table puts it in src/srdo/ (reception, transmission, timers, GFC,
  configuration check, CRC stream, write hooks, objects), src/wire/srdo.rs,
  src/ffi/srdo.rs or the \`crc\` crate, including SRDO code inlined into
  other functions (\`Stack::poll\`); inlined core-library code counts for the
  file it was inlined into. Plus the named SRDO constants (the 512-byte CRC
  table). scripts/tms570/code_size.py documents the rule.
* **\`.text\` of a node**: \`scripts/tms570.sh sizes\`: the safety demo
  (examples_c/safety_demo: the safety nodes' application, its dictionaries,
  SRDO/GFC, the simulated driver and the C library) and the I/O node
  example (examples_c/io_node), each linked for the TMS570 with its own
  libcop.a built from its copcfg.h / obdcfg.h; the whole \`.text\` of the
  image, and in brackets the part the link map assigns to libcop.a.
* **RAM per SRDO**: (\`size_of::<Srdo>()\` at capacity 64 − at capacity 1) / 63
  on the target: the run-time slot of one SRDO and its copy plan (dynamic
  mapping: a reference to each mapped subindex, its element and length;
  static mapping: the two variable fields instead). The
  fixed part (COB-ID and index lookup tables, flags) is the "per node"
  figure; "at 8 SRDOs" is \`size_of::<Srdo>()\` / 8 with
  \`COP_SRDO_MAX_SRDO_IN_OBD=8\`. Mapped variables and the dictionary tables
  are the application's and not counted.
* **Whole stack**: \`size_of::<Stack>()\` on the target with
  \`COP_SRDO_MAX_SRDO_IN_OBD=8\` and the other capacities at their defaults;
  the C API instance adds the driver port and the application's callbacks;
  the image figures are those of the linked test image (C main included).

Host figures are built with the library's release settings (opt-level "s",
LTO, one codegen unit). Program monitor on = default features; off =
\`--no-default-features --features srdo-gfc\`.

## Where the C API instructions go

Per call, from the same callgrind runs as the table above ((Ir(2N) − Ir(N)) / N
for every line of the profile, bench/where.py): each line of machine code
counts for the part of the source its line comes from (after inlining, one
function holds lines of many files; \`mostly in\` names the functions of the
binary that hold them). Lines of the Rust core library count for the
function they were inlined into. The rows add up to the figure of the table.

Received SRDO pair, program monitor off (the pair cycle minus the idle
cycle; 1 SRDO):

$WHERE_PAIR_OFF

The same with the program monitor on:

$WHERE_PAIR_ON

Idle \`CcmProcess\` (8 SRDOs, program monitor off):

$WHERE_IDLE

\`CcmSendSrdo\` of the transmit SRDO:

$WHERE_SEND

\`CcmGetSrdoState\` + \`CcmSetSrdoState\` from the main loop (the
application's part is the calling C code: the local variable, the OR of the
two bits, the calls):

$WHERE_HANDSHAKE

## Whole images (scripts/tms570/link_main.c, \`arm-none-eabi-size\`)

| variant | text | data | bss | of which SRDO+GFC+CRC |
|---|---|---|---|---|
EOF
for v in arm-s arm-z thumb-s thumb-z; do
    echo "| ${v/-/, opt-level } | $(fmt "${TEXT[$v]}") | $(fmt "${DATA[$v]}") | $(fmt "${BSS[$v]}") | $(fmt "${CODE[$v]}") |"
done
cat <<EOF

Default capacities (64 SRDOs, 8 + 8 PDOs). The stack instance lies in .bss
(zeroed at start-up; no flash image of it).

## Where the SRDO+GFC+CRC code is (opt-level z, largest functions)

The ten functions of the image holding the most SRDO+GFC+CRC bytes (the
attribution above, per function symbol; after LTO a function holds code of
several source files, so its size can exceed its SRDO part).

EOF
functions_table() { # $1 = variant
    echo "| function | SRDO+GFC+CRC bytes in it | function size |"
    echo "|---|---|---|"
    awk '/^function / {n = $2; f = $3; $1 = $2 = $3 = ""; sub(/^ +/, ""); printf "%s\t%s\t%s\n", $0, n, f}' \
        "$WORK/size-$1.txt" | while IFS=$'\t' read -r name n f; do
        echo "| \`${name//|/\\|}\` | $(fmt "$n") | $(fmt "$f") |"
    done
}
echo "ARM (of $(fmt "${CODE[arm-z]}") B):"
echo
functions_table arm-z
echo
echo "Thumb-2 (of $(fmt "${CODE[thumb-z]}") B):"
echo
functions_table thumb-z
cat <<EOF

## RAM of the stack on the target (\`size_of\`, bytes)

| type | 1 SRDO | 8 SRDOs | 64 SRDOs |
|---|---|---|---|
EOF
for t in STACK:Stack SRDO:Srdo PDO:Pdo SDO_SERVER:SdoServer SDO_CLIENT:SdoClient NMTM:NmtMaster \
    ACTION_QUEUE:ActionQueue HBC:HeartbeatConsumer EMCY:EmcyProducer OD:ObjectDictionary \
    INSTANCE:"C API instance (Stack + port + callbacks)"; do
    k=${t%%:*}
    echo "| ${t#*:} | $(fmt "${SIZE[1,$k]}") | $(fmt "${SIZE[8,$k]}") | $(fmt "${SIZE[64,$k]}") |"
done
cat <<EOF

## RAM per SRDO with dynamic mapping: where the bytes go

Each SRDO of capacity has one \`Slot\` (run-time state) and one \`Plan\`
(copy plan) in \`Srdo\`; field layout as rustc lays it out for the target
(\`-Zprint-type-sizes\`, capacity 64, offsets in bytes). \`Plan\` is an enum
whose larger variant \`General\` is its whole size (no separate tag: the
never-null references carry the variant).

| type | field | offset | bytes |
|---|---|---|---|
EOF
awk -F'\t' '$2 != "(size)" {printf "| `%s` | %s | %s | %s |\n", $1, $2, $3, $4}
    $2 == "(size)" {printf "| `%s` | **size** | | **%s** |\n", $1, $4}' "$WORK/srdo-layout.txt" |
    sed 's/`cop::srdo::plan::/`/; s/`cop::srdo::/`/'
cat <<EOF
| per SRDO | \`Slot\` + \`Plan\` | | $((SLOT_BYTES + PLAN_BYTES)) |
| per SRDO | rest of the measured $(fmt "$PER_SRDO") B, outside \`Slot\` and \`Plan\` | | $(fmt "$PER_SRDO_REST") |

## All instruction counts (per call)

| scenario | program monitor on | off |
|---|---|---|
EOF
for n in 1 8 32 64; do
    echo "| idle cycle, $n receive SRDO$([ $n = 1 ] || echo s) | $(fmt "${IDLE[on,$n]}") | $(fmt "${IDLE[off,$n]}") |"
done
for n in 1 8 32 64; do
    echo "| received pair minus idle cycle, $n SRDO$([ $n = 1 ] || echo s) | $(fmt "${RX[on,$n]}") | $(fmt "${RX[off,$n]}") |"
done
echo "| idle cycle, SDO node | $(fmt "$SDO_IDLE") | |"
for n in 1 8 32 64; do
    echo "| C API: idle \`CcmProcess\`, $n receive SRDO$([ $n = 1 ] || echo s) | $(fmt "${CIDLE[on,$n]}") | $(fmt "${CIDLE[off,$n]}") |"
done
for n in 1 8 32 64; do
    echo "| C API: received pair minus idle, $n SRDO$([ $n = 1 ] || echo s) | $(fmt "${CRX[on,$n]}") | $(fmt "${CRX[off,$n]}") |"
done
log "done"
