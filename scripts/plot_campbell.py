#!/usr/bin/python3
"""Draws a Campbell diagram from the JSON written by `feran campbell --json`.

Usage: plot_campbell.py campbell.json campbell.png

Left: natural frequency of every tracked mode against speed, the excitation lines
f = k x speed and the critical speeds. Right: the damping ratios, with the stability
threshold when there is one.
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {"forward": "-", "backward": "--", "mixed": "-.", "planar": ":", "none": ":"}


def main(source, target):
    with open(source, encoding="utf-8") as f:
        r = json.load(f)
    speeds = r["speeds_hz"]
    fig, (ax_f, ax_d) = plt.subplots(1, 2, figsize=(12, 5))
    title = r["model"]["title"] or r["model"]["path"]
    fig.suptitle(f"Campbell diagram: {title}")

    top = 0.0
    for m in r["modes"]:
        f = [x if x is not None else float("nan") for x in m["frequency_hz"]]
        d = [100 * x if x is not None else float("nan") for x in m["damping_ratio"]]
        (line,) = ax_f.plot(speeds, f, STYLE.get(m["whirl"], "-"), label=m["label"])
        ax_d.plot(speeds, d, STYLE.get(m["whirl"], "-"), color=line.get_color(), label=m["label"])
        top = max(top, max(x for x in f if x == x))
    for k in r["orders"]:
        ax_f.plot(speeds, [k * s for s in speeds], color="grey", lw=0.8)
        ax_f.annotate(f"{k}x", (speeds[-1], k * speeds[-1]), fontsize=8, color="grey")
    for c in r["critical_speeds"]:
        ax_f.plot(c["speed_hz"], c["frequency_hz"], "ko", ms=5)
        ax_f.annotate(f"{c['speed_hz']:.1f} Hz", (c["speed_hz"], c["frequency_hz"]),
                      textcoords="offset points", xytext=(4, -10), fontsize=8)
    t = r["stability_threshold"]
    if t is not None:
        ax_d.axvline(t["speed_hz"], color="red", lw=1)
        ax_d.annotate(f"unstable above {t['speed_hz']:.1f} Hz\n({t['mode']})", (t["speed_hz"], 0),
                      textcoords="offset points", xytext=(4, 10), fontsize=8, color="red")
    ax_d.axhline(0.0, color="black", lw=0.8)
    ax_f.set_ylim(0, min(top * 1.05, 3 * max(r["orders"]) * speeds[-1] + 1e-9) or 1)
    ax_f.set_xlabel("speed [Hz]")
    ax_f.set_ylabel("natural frequency [Hz]")
    ax_d.set_xlabel("speed [Hz]")
    ax_d.set_ylabel("damping ratio [%]")
    for ax in (ax_f, ax_d):
        ax.grid(True, lw=0.3)
        ax.set_xlim(speeds[0], speeds[-1])
    ax_f.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(target, dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
