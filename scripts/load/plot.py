"""Plot of the load campaign (scripts/load.sh): per run of the sweep and the
main network, the offered load against the SRDO alarms the checker found
correct, false and missed, and the worst pair latency.

    python3 scripts/load/plot.py DRIVER.csv CYCLE.csv OUT.png
"""

import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def rows(path):
    with open(path, newline="") as f:
        return [r for r in csv.DictReader(f) if r["burst"] == "0"]


def main():
    driver, cycle, out = sys.argv[1:4]
    fig, (ax_alarm, ax_lat) = plt.subplots(1, 2, figsize=(11, 4.2))
    for path, label, marker in ((driver, "driver timestamps", "o"), (cycle, "stack's cycle", "s")):
        data = sorted(rows(path), key=lambda r: float(r["offered"]))
        x = [float(r["offered"]) for r in data]
        for key, colour in (("correct", "tab:green"), ("false", "tab:red"), ("missed", "tab:orange")):
            # Alarms per simulated second: the runs differ in length.
            y = [int(r[key]) / float(r["seconds"]) for r in data]
            ax_alarm.plot(x, y, marker=marker, color=colour, label=f"{key} ({label})",
                          linestyle="-" if marker == "o" else "--")
        ax_lat.plot(x, [float(r["worst_latency_ms"]) for r in data], marker=marker,
                    label=label, linestyle="-" if marker == "o" else "--")
    for ax in (ax_alarm, ax_lat):
        ax.axvline(100.0, color="grey", linewidth=0.8)
        ax.set_xlabel("offered load (% of 1 Mbit/s, without SDO)")
        ax.grid(True, alpha=0.3)
    ax_alarm.set_ylabel("SRDO alarms per simulated second")
    ax_alarm.set_title("alarms judged by the bus-time checker")
    ax_alarm.legend(fontsize=7)
    ax_lat.set_yscale("log")
    ax_lat.set_ylabel("worst pair latency (ms)")
    ax_lat.set_title("queueing of frame 1 to end of frame 2")
    ax_lat.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
