#!/usr/bin/env bash
# The demo: two C applications of this library on the simulated CAN bus.
#
#   scripts/demo.sh
#
# 1. examples_c/io_node - a CiA 401-style I/O node (node-ID 2) written
#    against the SYS TEC API; a scripted master sends the SDO requests of
#    the seed-004 examples and the node answers them.
# 2. examples_c/safety_demo - a CiA 304 safety network: a sensor (node 1)
#    sends E-stop state and speed limit in SRDO 1, an actuator (node 2)
#    drives a safe output; E-stop with GFC, one injected bus fault, recovery.
#    Its traffic is written to build/safety_demo.pcap and build/safety_demo.log.
#
# Installs the prerequisites (scripts/setup.sh --demo), configures and
# builds with CMake into build/ and runs both. Idempotent: a second run
# only runs the programs again.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

say() { printf '\n==== %s\n' "$*"; }

say "prerequisites (scripts/setup.sh --demo)"
scripts/setup.sh --demo

say "configure and build (CMake -> build/; the library is built by cargo per example configuration)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Debug >/dev/null
cmake --build build -j2 --target io_node safety_demo two_channel

say "demo 1 of 3: I/O node (examples_c/io_node, target run_io_node)
     A master sends NMT start and the three SDO requests of seed 004
     (write 8 outputs, read 8 inputs, read an analog input); every frame on
     the bus is printed in candump format, then the node's answers are checked."
cmake --build build --target run_io_node

say "demo 2 of 3: safety network (examples_c/safety_demo, target run_safety_demo)
     Sensor (node 1) -> SRDO 1 (COB-IDs 0x101/0x102, normal and inverted
     data) -> actuator (node 2) with a safe output. Watch for: the SRDO
     configuration in the NMT callback (CRC into 0x13FF, 0xA5 into 0x13FE),
     '>>> SAFE OUTPUT ON', the E-stop with the global fail-safe command (001),
     the lost inverted frame (SRVT timeout, status handshake 0x50 -> 0xB0),
     and the recovery after RESET."
COP_SIM_PCAP="$PWD/build/safety_demo.pcap" COP_SIM_CANDUMP="$PWD/build/safety_demo.log" \
    cmake --build build --target run_safety_demo

say "demo 3 of 3: two channels (examples_c/two_channel, target run_two_channel)
     Four stack instances in one program (COP_MAX_INSTANCES 4): a sensor and an
     actuator with two CAN controllers each, channel A on can0, channel B on
     can1. The actuator cross-checks the channels. Watch for: a silent
     controller found by channel B's SCT, a corrupted frame on channel A
     (kCopSrdoDataError), and the channels disagreeing; each time the safe
     state, and RESET bringing the output back."
cmake --build build --target run_two_channel

say "done: the three demos ran (build/examples_c/io_node/io_node, build/examples_c/safety_demo/safety_demo,
     build/examples_c/two_channel/two_channel)
     The safety demo's traffic: build/safety_demo.pcap (Wireshark, tshark) and
     build/safety_demo.log (candump -l, canplayer). With the SRDO dissector:
       tshark -2 -X lua_script:tools/wireshark/cop_srdo.lua -o cop_srdo.srvt_ms:10 -r build/safety_demo.pcap"
