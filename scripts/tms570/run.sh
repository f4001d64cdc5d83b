#!/usr/bin/env bash
# Target programs for the TMS570 (Cortex-R4F, big-endian, VFPv3-D16,
# hard-float), run under qemu-armeb (Linux user mode, Debian qemu-user).
#
#   run.sh run     the safety demo (examples_c/safety_demo: sensor and actuator
#                  node, their dictionaries, App* callbacks, configuration
#                  signature, the simulated bus inside the program) and the C
#                  tests of c_tests/cfg and c_tests/cfg_manual, each a static target program with the
#                  start-up and C library of examples_c/target; the demo's
#                  frames and 0x13FF CRCs must equal the committed host trace.
#                  Then the alignment check and the stack table.
#   run.sh stack   only the stack table (scripts/tms570/stack.py)
#   run.sh sizes   .text of a complete safety node and of an I/O node
#
# Called through scripts/tms570.sh. Prints "target run: N passed, 0 failed".
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$(pwd)
T=armebv7r-none-eabihf
case "${CARGO_TARGET_DIR:-target}" in
/*) OUT=$CARGO_TARGET_DIR/tms570-run ;;
*) OUT=$ROOT/${CARGO_TARGET_DIR:-target}/tms570-run ;;
esac
mkdir -p "$OUT"
RUSTFLAGS_T="-C target-cpu=cortex-r4f -C target-feature=+strict-align -Z emit-stack-sizes"
GCC=arm-none-eabi-gcc
CPU=(-mbig-endian -mcpu=cortex-r4f -mfpu=vfpv3-d16 -mfloat-abi=hard -marm -mno-unaligned-access)
CFLAGS=("${CPU[@]}" -O2 -g -std=c11 -ffreestanding -fno-builtin -ffunction-sections -fdata-sections
    -fstack-usage -nostdinc -isystem "$($GCC -print-file-name=include)"
    -isystem "$ROOT/examples_c/target/libc/include" -I"$ROOT/include" -I"$ROOT/examples_c/sim"
    -DCOP_HOST_SIMULATION -Wall -Wextra -Werror)
LDFLAGS=("${CPU[@]}" -nostdlib -static -Wl,--gc-sections -Wl,-z,noexecstack -Wl,-e,_start)

# archive <config dir> <name> <features>: libcop.a for the target, from the
# application's copcfg.h/obdcfg.h; prints its path.
archive() {
    local dir="$OUT/cargo-$2"
    COP_CONFIG_DIR="$ROOT/$1" RUSTC_BOOTSTRAP=1 CARGO_TARGET_DIR="$dir" RUSTFLAGS="$RUSTFLAGS_T" \
        cargo rustc -q --release --lib --crate-type staticlib -Zbuild-std=core --target $T \
        --features "$3" 2> >(grep -v -e 'unstable feature specified for `-Ctarget-feature`: `strict-align`' \
            -e 'this feature is not stably supported' -e '^ *|$' -e '^ *= \(note\|help\)' -e '^$' >&2) ||
        return 1
    echo "$dir/$T/release/libcop.a"
}

# program <elf> <archive> <config dir> <sources...>: compile and link.
program() {
    local elf=$1 lib=$2 cfg=$3 obj=$OUT/obj/$(basename "$1" .elf)
    shift 3
    rm -rf "$obj" && mkdir -p "$obj"
    local objs=() s o
    for s in examples_c/target/start.S examples_c/target/libc/libc.c examples_c/sim/cdrv_sim.c "$@"; do
        o="$obj/$(basename "$s").o"
        # shellcheck disable=SC2086 # EXTRA_CFLAGS: -D options of a test
        (cd "$obj" && $GCC "${CFLAGS[@]}" ${EXTRA_CFLAGS:-} -I"$ROOT/$cfg" -I"$ROOT/$(dirname "$s")" -c -o "$o" "$ROOT/$s")
        objs+=("$o")
    done
    $GCC "${LDFLAGS[@]}" -o "$elf" "${objs[@]}" "$lib" -lgcc
}

# align <archive>...: every object of the archives (the library, core,
# compiler_builtins) must say that it never accesses unaligned data. LLVM
# writes Tag_CPU_unaligned_access "v6" for code that may (the default of
# armv7r) and "None" under +strict-align; qemu-user cannot trap unaligned
# accesses (Linux user mode runs with alignment checking off), so the
# compiler's attribute is what is checked.
align() {
    local a members tagged
    for a in "$@"; do
        members=$(readelf -A "$a" | grep -c '^File: ')
        tagged=$(readelf -A "$a" | grep -c 'Tag_CPU_unaligned_access: None')
        if [ "$members" -eq 0 ] || [ "$tagged" -ne "$members" ] || readelf -A "$a" | grep -q 'Tag_CPU_unaligned_access: v6'; then
            echo "FAIL alignment: $a: $tagged of $members objects have Tag_CPU_unaligned_access None"
            readelf -A "$a" | grep -E '^File|unaligned'
            return 1
        fi
        echo "ok   alignment: $(basename "$(dirname "$(dirname "$(dirname "$a")")")"): $members of $members objects Tag_CPU_unaligned_access None"
    done
}

# stack_table <archive>: every function the archive exports (the Ccm*/Cop*
# API and the stack callbacks an objdict.h names), linked with the safety
# demo's application so that its callbacks, the simulated driver and the C
# library are in the graph, and with the simulated storage driver
# (examples_c/sim/store_sim.c, as an application registers it with
# CcmSetStoreDriver) so that the store module's path ends in a real
# driver; the table is scripts/tms570/stack.py's. The goal is 2,048 bytes
# (docs/tms570.md).
STACK_LIMIT_CCMPROCESS=2048
stack_table() {
    local lib=$1 objs=() s st=$OUT/obj/stack_store
    shift
    arm-none-eabi-nm --target=elf32-bigarm -g --defined-only "$lib" 2>/dev/null |
        awk '$2 == "T" {print $3}' | grep -Ev '^(__|mem|_R|rust_)' | sort -u >"$OUT/exported.txt"
    for s in "$OUT"/obj/safety_demo/*.o; do objs+=("$s"); done
    rm -rf "$st" && mkdir -p "$st"
    (cd "$st" && $GCC "${CFLAGS[@]}" -DSIM_STORE_NO_FILE -I"$ROOT/examples_c/safety_demo" \
        -c -o "$st/store_sim.c.o" "$ROOT/examples_c/sim/store_sim.c")
    $GCC "${LDFLAGS[@]}" -o "$OUT/stack.elf" "${objs[@]}" "$st/store_sim.c.o" -Wl,-u,SimStoreDriver \
        $(sed 's/^/-Wl,-u,/' "$OUT/exported.txt") "$lib" -lgcc
    # Indirect calls (the first matching rule applies):
    # * the store module's only pointer call is the storage driver, in the
    #   methods of its NvMemory adapter (store::Nv, out of line): they reach
    #   the StorageDriver implementations, and those (the methods of the C
    #   adapter CStore, m_fpOpen's included) the functions of the
    #   application's tCopStoreDriver (store_sim.c's Driver_l);
    # * a dictionary access calls OBD callbacks (the functions in the
    #   dictionary tables, not App* or ObdInitRam*), and a variable's
    #   notification (ObdVarEntry::notify) the tVarCallback of
    #   CcmDefineVarTab, which is no App* or ObdInitRam* function either;
    # * the demo's SensorCycle/ActuatorCycle pointers stay in safety_node.c.
    # The C API's event pump never runs inside itself (its pumping flag).
    python3 scripts/tms570/stack.py --elf "$OUT/stack.elf" --su "$OUT/obj/safety_demo" --su "$st" \
        --entries "$OUT/exported.txt" --report CcmProcess --report main \
        --callbacks '^(App|ObdInitRam)' --nonnesting '^App' --stop '^(App|Cdrv|Tgt|Obd|Sim|Safety|Sensor|Actuator|Open$|Read$|Write$|Erase$|Commit$)' \
        --app-pointers '^(SensorCycle|ActuatorCycle)$' \
        --indirect '^<cop::ffi::services::CStore( as cop::store::StorageDriver)?>::=@Driver_l' \
        --indirect '^<cop::store::Nv as cop::store::image::NvMemory>::=^<[^<>]+ as cop::store::StorageDriver>::[a-z_]+$' \
        --indirect 'ObjectDictionary|ObdVarEntry>::notify$=^(?!App|ObdInitRam)' --pump '^cop::ffi::global::pump_events::' \
        --limit CcmProcess=$STACK_LIMIT_CCMPROCESS "$@"
}

run_programs() {
    local pass=0 fail=0 lib_demo lib_test name srcs
    lib_demo=$(archive examples_c/safety_demo demo sim-instances)
    lib_test=$(archive c_tests/cfg test sim-instances)
    echo "archives: $lib_demo, $lib_test"
    if align "$lib_demo" "$lib_test"; then pass=$((pass + 1)); else fail=$((fail + 1)); fi

    local d=examples_c/safety_demo
    program "$OUT/safety_demo.elf" "$lib_demo" $d \
        $d/main.c $d/safety_node.c $d/sensor.c $d/actuator.c $d/objdict_sensor.c $d/objdict_actuator.c
    if python3 cmake/expect_output.py --expect $d/expected.txt -- qemu-armeb "$OUT/safety_demo.elf" >"$OUT/safety_demo.log" 2>&1 &&
        python3 cmake/expect_output.py --extract "^  can0 |^SRDO 0x1301 CRC" --compare $d/expected_trace.txt -- \
            qemu-armeb "$OUT/safety_demo.elf" >>"$OUT/safety_demo.log" 2>&1; then
        echo "ok   safety_demo (output as expected.txt; $(grep -c '^  can0 ' $d/expected_trace.txt) frames and the 0x13FF CRCs equal expected_trace.txt)"
        pass=$((pass + 1))
    else
        echo "FAIL safety_demo"; cat "$OUT/safety_demo.log"; fail=$((fail + 1))
    fi

    # The two-channel example: four instances (COP_MAX_INSTANCES 4, the
    # multi-instance ABI), two buses; output and both channels' traces as
    # on the host.
    local t=examples_c/two_channel lib_two
    lib_two=$(archive $t two sim-instances)
    if align "$lib_two"; then pass=$((pass + 1)); else fail=$((fail + 1)); fi
    program "$OUT/two_channel.elf" "$lib_two" $t \
        $t/main.c $t/sensor_ch_a.c $t/sensor_ch_b.c $t/actuator_ch_a.c $t/actuator_ch_b.c
    if python3 cmake/expect_output.py --expect $t/expected.txt -- qemu-armeb "$OUT/two_channel.elf" >"$OUT/two_channel.log" 2>&1 &&
        python3 cmake/expect_output.py --extract "^  can0 " --compare $t/expected_trace_can0.txt -- \
            qemu-armeb "$OUT/two_channel.elf" >>"$OUT/two_channel.log" 2>&1 &&
        python3 cmake/expect_output.py --extract "^  can1 " --compare $t/expected_trace_can1.txt -- \
            qemu-armeb "$OUT/two_channel.elf" >>"$OUT/two_channel.log" 2>&1; then
        echo "ok   two_channel (four instances; output as expected.txt; $(cat $t/expected_trace_can0.txt $t/expected_trace_can1.txt | wc -l) frames on can0/can1 equal the committed traces)"
        pass=$((pass + 1))
    else
        echo "FAIL two_channel"; cat "$OUT/two_channel.log"; fail=$((fail + 1))
    fi

    # The two-instance C test (c_tests/cfg_multi, COP_MAX_INSTANCES 2).
    local lib_multi rc_multi=0
    lib_multi=$(archive c_tests/cfg_multi multi sim-instances)
    program "$OUT/test_multi.elf" "$lib_multi" c_tests/cfg_multi \
        c_tests/test_multi.c c_tests/test_check.c c_tests/objdict_all.c c_tests/objdict_srdo_peer.c
    qemu-armeb "$OUT/test_multi.elf" >"$OUT/test_multi.log" 2>&1 || rc_multi=$?
    if [ $rc_multi -eq 0 ]; then
        echo "ok   test_multi (c_tests/cfg_multi; $(tail -1 "$OUT/test_multi.log"))"
        pass=$((pass + 1))
    else
        echo "FAIL test_multi (exit $rc_multi)"; tail -20 "$OUT/test_multi.log"; fail=$((fail + 1))
    fi

    # The C tests of c_tests/cfg (the main test configuration) and
    # c_tests/cfg_manual (the safety manual's application code, static SRDO
    # mapping), with sources and defines as c_tests/CMakeLists.txt builds
    # them for CTest; not test_abi, whose expected offsets are those of
    # x86-64 (the Cortex-R4F layout is asserted at compile time by
    # c_tests/abi_ilp32.c, CTest test_abi_ilp32*).
    local name cfg defs srcs lib
    declare -A libs=([c_tests/cfg]=$lib_test)
    libs[c_tests/cfg_manual]=$(archive c_tests/cfg_manual manual sim-instances)
    if align "${libs[c_tests/cfg_manual]}"; then pass=$((pass + 1)); else fail=$((fail + 1)); fi
    while read -r name cfg defs srcs; do
        local rc=0 dflags=()
        lib=${libs[$cfg]}
        [ "$defs" = - ] || for x in ${defs//,/ }; do dflags+=("-D$x"); done
        # The store test's simulated memory (examples_c/sim/store_sim.c,
        # linked through the sim library under CMake) without its host-file
        # mode: the target's C library has no files.
        if [ "$name" = test_store ]; then
            srcs="$srcs ../examples_c/sim/store_sim.c"
            dflags+=(-DSIM_STORE_NO_FILE)
        fi
        # shellcheck disable=SC2086 # the list of sources
        EXTRA_CFLAGS="${dflags[*]}" program "$OUT/$name.elf" "$lib" "$cfg" \
            $(for f in $srcs test_util.c test_check.c; do echo "c_tests/$f"; done)
        qemu-armeb "$OUT/$name.elf" >"$OUT/$name.log" 2>&1 || rc=$?
        if [ $rc -eq 0 ]; then
            echo "ok   $name ($cfg; $(tail -1 "$OUT/$name.log"))"
            pass=$((pass + 1))
        else
            echo "FAIL $name (exit $rc)"; tail -20 "$OUT/$name.log"; fail=$((fail + 1))
        fi
    done < <(python3 scripts/tms570/c_tests.py c_tests/CMakeLists.txt cfg cfg_manual | grep -v '^test_abi ')

    # The HALCoGen DCAN/RTI driver sketch of docs/tms570.md compiles (C99,
    # pedantic) against the library's headers and stub HALCoGen prototypes.
    if $GCC "${CPU[@]}" -std=c99 -pedantic -Wall -Wextra -Werror -ffreestanding -nostdinc \
        -isystem "$($GCC -print-file-name=include)" -isystem examples_c/target/libc/include \
        -Iinclude -I$d -c -o "$OUT/cdrv_dcan.o" examples_c/target/halcogen/cdrv_dcan.c; then
        echo "ok   examples_c/target/halcogen/cdrv_dcan.c compiles ($(arm-none-eabi-size "$OUT/cdrv_dcan.o" | awk 'NR==2 {print $1}') bytes .text)"
        pass=$((pass + 1))
    else
        echo "FAIL examples_c/target/halcogen/cdrv_dcan.c"; fail=$((fail + 1))
    fi
    if stack_table "$lib_demo" >"$OUT/stack.txt" 2>"$OUT/stack.err"; then
        echo "ok   stack: $(grep -m1 'stack CcmProcess' "$OUT/stack.txt" | sed 's/  */ /g') (limit $STACK_LIMIT_CCMPROCESS)"
        pass=$((pass + 1))
    else
        echo "FAIL stack"; cat "$OUT/stack.err"; fail=$((fail + 1))
    fi
    echo "target run: $pass passed, $fail failed"
    [ $fail -eq 0 ]
}

# text_of <elf>: "<whole .text> <part from libcop.a>" from the link map.
text_of() {
    python3 - "$1.map" "$1" <<'PY'
import re, subprocess, sys
total = int(subprocess.run(["arm-none-eabi-size", "-A", sys.argv[2]], check=True,
                           stdout=subprocess.PIPE, universal_newlines=True).stdout
            .split("\n.text ")[1].split()[0])
lib, pending, in_text = 0, False, False
for line in open(sys.argv[1]):
    if re.match(r"^\.text\b", line):
        in_text = True
    elif re.match(r"^\.\S", line):
        in_text = False
    if not in_text:
        continue
    m = re.match(r"^\s+(?:\.text\S*\s+)?0x[0-9a-f]+\s+0x([0-9a-f]+)\s+(\S+)$", line)
    if m and "libcop.a(" in m.group(2):
        lib += int(m.group(1), 16)
print(total, lib)
PY
}

# sizes: .text of two complete images, each with its own libcop.a built from
# its copcfg.h/obdcfg.h: the safety demo (two safety nodes' application,
# SRDO/GFC, the simulated driver, the C library) and the I/O node example.
sizes() {
    local lib_demo lib_io d=examples_c/safety_demo i=examples_c/io_node demo io
    lib_demo=$(archive $d demo sim-instances)
    lib_io=$(archive $i io sim-instances)
    LDFLAGS+=(-Wl,-Map,"$OUT/safety_node.elf.map")
    program "$OUT/safety_node.elf" "$lib_demo" $d \
        $d/main.c $d/safety_node.c $d/sensor.c $d/actuator.c $d/objdict_sensor.c $d/objdict_actuator.c
    LDFLAGS[-1]=-Wl,-Map,"$OUT/io_node.elf.map"
    program "$OUT/io_node.elf" "$lib_io" $i $i/main.c $i/objdict.c
    read -r -a demo < <(text_of "$OUT/safety_node.elf")
    read -r -a io < <(text_of "$OUT/io_node.elf")
    echo "target-size: safety node .text ${demo[0]} bytes (libcop.a ${demo[1]}), I/O node .text ${io[0]} bytes (libcop.a ${io[1]}); ARM mode, opt-level of Cargo.toml, +strict-align"
}

case "${1:-run}" in
run) run_programs ;;
sizes) sizes ;;
stack)
    [ -f "$OUT/obj/safety_demo/main.c.o" ] || run_programs >/dev/null
    stack_table "$(archive examples_c/safety_demo demo sim-instances)" --markdown
    ;;
*) echo "usage: $0 run|stack|sizes" >&2; exit 2 ;;
esac
