#!/usr/bin/env bash
# Load campaign on the physical model of the simulated bus
# (examples/load_campaign.rs): a master and eight safety nodes at 1 Mbit/s
# with receive buffers high 16 / low 10, 45 SRDOs every 10 ms, SDO block
# uploads, SYNC with eight synchronous PDOs, heartbeats (and the same with
# every SRDO due at once, with lost SRDO frames, with low receive buffers
# too small); then a sweep of 32 .. 64 SRDOs of 4 and of 8 bytes past the
# bus limit. An independent checker judges every SRDO alarm from the bus
# arrival times.
#
#   scripts/load.sh              10 simulated minutes in both timestamp modes
#                                (receive time from the driver, CDRV_TIMESTAMP,
#                                and at the stack's cycle), the sweep, the
#                                tables in docs/load.md and the plot docs/load.png
#   scripts/load.sh --minutes N  the main run N simulated minutes long
#   scripts/load.sh --quick      3 simulated seconds, a short sweep, no files
#                                (the faults stage of scripts/test.sh)
#
# Exit code 1 when a run has a false SRDO alarm, or at or below 100 %
# offered load a lost safety frame, an unreported deadline miss or an SDO
# error, or when a check run does not show what it checks.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

if [ "${1:-}" = "--quick" ]; then
    exec cargo run -q --example load_campaign --features std -- --quick
fi
minutes=10
if [ "${1:-}" = "--minutes" ]; then
    minutes=${2:?--minutes N}
fi

work=target/load
mkdir -p "$work" docs
md=docs/load.md
{
    echo "# Load campaign"
    echo
    echo "Written by \`scripts/load.sh\` ($minutes simulated minutes per main run, at most 60 s for the check runs, 20 s per sweep point)."
    echo
} >"$md"
status=0
for mode in driver cycle; do
    if [ "$mode" = driver ]; then
        features=std,cdrv-timestamp
        export CARGO_TARGET_DIR=target/load-timestamp
    else
        features=std
        unset CARGO_TARGET_DIR
    fi
    echo "== receive times: $mode (cargo --release --features $features)"
    cargo build -q --release --example load_campaign --features "$features"
    bin=${CARGO_TARGET_DIR:-target}/release/examples/load_campaign
    start=$(date +%s)
    if ! "$bin" --minutes "$minutes" --csv "$work/$mode.csv" | tee "$work/$mode.txt"; then
        status=1
    fi
    echo "   $(( $(date +%s) - start )) s of real time"
    {
        echo "## Receive times: $mode"
        echo
        grep -v '^load campaign' "$work/$mode.txt" | grep -v '^ok\|^FAILED'
        echo
    } >>"$md"
done
unset CARGO_TARGET_DIR
if ! python3 -c 'import matplotlib' 2>/dev/null; then
    echo "the plot needs matplotlib (scripts/setup.sh --evidence installs it); tables written" >&2
    exit 1
fi
python3 scripts/load/plot.py "$work/driver.csv" "$work/cycle.csv" docs/load.png
echo "written: $md docs/load.png"
exit $status
