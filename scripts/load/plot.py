"""Plot of the load campaign (scripts/load.sh): per sweep point and main
run (SRDOs spread over the period), the offered load against the SRDO
alarms the checker found correct, false and missed, the SDO errors, and
the worst pair latency; SRDOs of 4 and 8 bytes.

    python3 scripts/load/plot.py DRIVER.csv CYCLE.csv OUT.png
"""

import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def rows(path, size):
    with open(path, newline="") as f:
        data = [r for r in csv.DictReader(f) if r["due"] == "spread" and r["bytes"] == size]
    return sorted(data, key=lambda r: float(r["offered"]))


def per_s(r, key):
    # Per simulated second: the runs differ in length.
    return int(r[key]) / float(r["seconds"])


def main():
    driver, cycle, out = sys.argv[1:4]
    fig, (ax_alarm, ax_sdo, ax_lat) = plt.subplots(1, 3, figsize=(15, 4.4))
    for size, marker in (("4", "o"), ("8", "s")):
        data = rows(driver, size)
        x = [float(r["offered"]) for r in data]
        for key, colour in (("correct", "tab:green"), ("false", "tab:red"), ("missed", "tab:orange")):
            ax_alarm.plot(x, [per_s(r, key) for r in data], marker=marker, color=colour,
                          label=f"{key}, {size}-byte SRDOs")
        ax_sdo.plot(x, [per_s(r, "sdo_errors") for r in data], marker=marker, color="tab:purple",
                    label=f"SDO errors, {size}-byte SRDOs")
        ax_sdo.plot(x, [per_s(r, "lost_safety") for r in data], marker=marker, color="tab:red",
                    label=f"lost safety frames, {size}-byte SRDOs")
        for path, mode, style in ((driver, "driver timestamps", "-"), (cycle, "stack's cycle", "--")):
            d = rows(path, size)
            ax_lat.plot([float(r["offered"]) for r in d], [float(r["worst_latency_ms"]) for r in d],
                        marker=marker, linestyle=style, label=f"{size}-byte SRDOs, {mode}")
    for ax in (ax_alarm, ax_sdo, ax_lat):
        ax.axvline(100.0, color="grey", linewidth=0.8)
        ax.set_xlabel("offered load without SDO (% of 1 Mbit/s, stuff bits included)")
        ax.grid(True, alpha=0.3)
    ax_alarm.set_ylabel("SRDO alarms per simulated second")
    ax_alarm.set_title("alarms judged by the bus-time checker")
    ax_alarm.legend(fontsize=7)
    ax_sdo.set_ylabel("per simulated second")
    ax_sdo.set_title("SDO errors and lost safety frames")
    ax_sdo.legend(fontsize=7)
    ax_lat.set_yscale("log")
    ax_lat.set_ylabel("worst pair latency (ms)")
    ax_lat.set_title("queueing of frame 1 to end of frame 2")
    ax_lat.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=100)


if __name__ == "__main__":
    main()
