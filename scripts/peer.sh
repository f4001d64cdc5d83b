#!/usr/bin/env bash
# Interoperability tests against a CANopen implementation nobody here wrote:
# python-canopen (master, SDO client and server, NMT, heartbeat, PDO, a
# dynamic object dictionary from peer/peer_dynod.dcf) on a python-can bus
# whose other node is this library, loaded with ctypes from
# build/peer/peer/libcop_peer.so (peer/CMakeLists.txt; dcf2bin makes the
# container of the dynamic OD while it builds). The `peer` stage of
# scripts/test.sh; python-canopen and python-can come from scripts/setup.sh.
#
#   scripts/peer.sh                     build (if needed) and run every test
#   scripts/peer.sh -v                  ... naming each test
#   scripts/peer.sh -k srdo             only tests whose name contains "srdo"
#   COP_PEER_TRACE=1 scripts/peer.sh    print the frames of every test
#
# Failing tests print their frames in candump form.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
BUILD=build/peer

python3 -c "import canopen, can" 2>/dev/null || {
    echo "peer: python-canopen / python-can missing (scripts/setup.sh installs them)" >&2
    exit 1
}
cmake -S . -B "$BUILD" -DCOP_BUILD_TESTS=OFF -DCOP_BUILD_PEER=ON -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$BUILD" --target cop_peer -j2

export COP_PEER_LIB="$PWD/$BUILD/peer/libcop_peer.so"
python3 -m unittest discover -s peer/tests -t peer/tests "$@"
