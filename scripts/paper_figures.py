#!/usr/bin/python3
"""Draws the paper's Figs. 1 and 4-10 from the JSON that feran wrote.

Usage: paper_figures.py DATA_DIR OUT_DIR

DATA_DIR holds the results of scripts/figures.sh (fig01_campbell.json, ...); OUT_DIR
receives fig01.png/.svg ... fig10.png/.svg, drawn with the axes, curves, legends and
units of Fischer & Strackeljan (2006). A short summary of the numbers that
docs/validation.md quotes is printed on standard output.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from PIL import Image  # noqa: E402  (python3-pil, a dependency of python3-matplotlib)

WHIRLS = ["backward 1", "forward 1", "backward 2", "forward 2"]
WHIRL_STYLE = {"backward 1": ("tab:blue", "--"), "forward 1": ("tab:blue", "-"),
               "backward 2": ("tab:red", "--"), "forward 2": ("tab:red", "-"),
               "backward 3": ("tab:green", "--"), "forward 3": ("tab:green", "-")}
PNG_DPI = 90


def load(data, name):
    with open(os.path.join(data, name + ".json"), encoding="utf-8") as f:
        return json.load(f)


def series(values):
    return np.array([np.nan if x is None else x for x in values], dtype=float)


def paper_names(campbell):
    """The paper's names of the tracked modes, by whirl alone ("forward 2": the second
    forward mode by frequency at the first speed), keyed by feran's labels (which name
    the shape too: "forward conical 1")."""
    counts, names = {}, {}
    for m in campbell["modes"]:
        counts[m["whirl"]] = counts.get(m["whirl"], 0) + 1
        names[m["label"]] = f"{m['whirl']} {counts[m['whirl']]}"
    return names


def mode(campbell, label):
    names = paper_names(campbell)
    for m in campbell["modes"]:
        if names[m["label"]] == label:
            return m
    raise KeyError(f"no mode {label} in {campbell['model']['path']}")


def critical(campbell):
    """First-order critical speeds by the paper's mode name [Hz]."""
    names = paper_names(campbell)
    return {names[c["mode"]]: c["speed_hz"] for c in campbell["critical_speeds"] if c["order"] == 1}


def curve(campbell, label, key="frequency_hz"):
    """One tracked mode's values per speed (NaN where it was not followed)."""
    return series(mode(campbell, label)[key])


def save(fig, out, name, title):
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    png = os.path.join(out, name + ".png")
    fig.savefig(png, dpi=PNG_DPI)
    fig.savefig(os.path.join(out, name + ".svg"))
    plt.close(fig)
    # A 64-colour palette keeps the PNGs small (a quarter of the size) at no visible cost.
    Image.open(png).convert("RGB").quantize(colors=64).save(png, optimize=True)


REV = "frequency of revolution [Hz]"
REV_SHORT = "frequency of rev. [Hz]"
MAGNITUDE = "magnitude of rotor displacement [mm]"


def frame(ax, xlim, ylim, xlabel, ylabel, legend="best"):
    """The paper's axis limits and labels, a light grid and the legend (None: none)."""
    ax.set_xlim(*xlim)
    ax.set_ylim(*ylim)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, lw=0.3)
    if legend is not None:
        ax.legend(fontsize=8, loc=legend)


def campbell_panel(ax, r, labels, xmax, ymax):
    """Eigenfrequencies of the named whirls and the 1x line ("run-up")."""
    speeds = np.array(r["speeds_hz"])
    for label in labels:
        colour, style = WHIRL_STYLE[label]
        name = label.replace(" ", " whirl ")
        ax.plot(speeds, curve(r, label), style, color=colour, label=name)
    ax.plot([0, xmax], [0, xmax], color="black", lw=0.8, label="run-up")
    frame(ax, (0, xmax), (0, ymax), REV_SHORT, "eigenfrequency [Hz]", "upper left")


def time_axis(ax, runup):
    """Time on the top axis, from the run-up's (linear) speed profile."""
    profile = runup["profile"]
    t = np.array([p["time_s"] for p in profile])
    s = np.array([p["speed_hz"] for p in profile])
    rate = (s[-1] - s[0]) / (t[-1] - t[0])
    top = ax.secondary_xaxis("top", functions=(lambda f: (f - s[0]) / rate + t[0],
                                               lambda x: (x - t[0]) * rate + s[0]))
    top.set_xlabel("time [s]")


def runup_curve(runup, probe=0):
    p = runup["probes"][probe]
    return np.array(runup["speed_hz"]), 1e3 * np.array(p["magnitude_m"])


def steady_curve(response, probe=0):
    p = response["probes"][probe]
    return np.array(response["speeds_hz"]), 1e3 * np.array(p["amplitude_m"])


def first_above(speed, value, limit):
    above = np.nonzero(value > limit)[0]
    return speed[above[0]] if len(above) else None


def fig01(data, out):
    r = load(data, "fig01_campbell")
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    speeds = np.array(r["speeds_hz"])
    first = True
    for m in r["modes"]:
        if m["type"] not in ("lateral", "coupled"):
            continue
        backward = m["whirl"] == "backward"
        ax.plot(speeds, series(m["frequency_hz"]), "--" if backward else "-", color="tab:blue",
                label="feran simulation" if first and not backward else None)
        first = first and backward
    ax.plot([0, 200], [0, 200], color="black", lw=0.8, label="run-up (1x)")
    for c in r["critical_speeds"]:
        ax.plot(c["speed_hz"], c["frequency_hz"], "ko", ms=3)
    ax.text(5, 330, "solid: forward whirl, dashed: backward whirl\n"
            "(the paper's measured points are not available as numbers)", fontsize=7, va="top")
    frame(ax, (0, 200), (0, 350), REV, "eigenfrequency [Hz]", "center right")
    save(fig, out, "fig01", "Fig. 1: Campbell diagram of the centrifuge")
    crit = critical(r)
    return [("Fig. 1", "first critical speed (forward 1), centrifuge", f"{crit['forward 1']:.2f} Hz"),
            ("Fig. 1", "forward whirl 3 at 200 Hz", f"{curve(r, 'forward 3')[-1]:.1f} Hz")]


def fig04(data, out):
    with_ = load(data, "fig04_campbell_with")
    without = load(data, "fig04_campbell_without")
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    campbell_panel(left, with_, WHIRLS, 80, 160)
    speeds = np.array(with_["speeds_hz"])
    d_without = 100 * curve(without, "forward 1", "damping_ratio")
    d_with = 100 * curve(with_, "forward 1", "damping_ratio")
    right.plot(speeds, d_without, color="tab:blue", label="without internal damping")
    right.plot(speeds, d_with, color="tab:red", label="with internal damping")
    right.axhline(0, color="black", lw=0.8)
    threshold = with_["stability_threshold_hz"]
    if threshold is not None:
        right.axvline(threshold, color="tab:red", lw=0.6, ls=":")
        right.annotate(f"unstable above {threshold:.1f} Hz", (threshold, -12), xytext=(-110, 0),
                       textcoords="offset points", fontsize=8, color="tab:red")
    frame(right, (0, 80), (-20, 40), REV_SHORT, "damping of forw. whirl 1 [%]", "best")
    save(fig, out, "fig04",
         "Fig. 4: Campbell diagram with internal damping (left), damping of forward whirl 1 (right)")
    crit = critical(without)
    crit_with = critical(with_)
    i33 = int(np.argmin(np.abs(speeds - 33.0)))
    return [("Fig. 4", "first critical speed without / with internal damping",
             f"{crit['forward 1']:.2f} / {crit_with['forward 1']:.2f} Hz"),
            ("Fig. 4", "damping of forward whirl 1 at 0 Hz, with / without",
             f"{d_with[0]:.1f} / {d_without[0]:.1f} %"),
            ("Fig. 4", "damping of forward whirl 1 at 33 Hz, with / without",
             f"{d_with[i33]:.1f} / {d_without[i33]:.1f} %"),
            ("Fig. 4", "damping of forward whirl 1 at 80 Hz, with / without",
             f"{d_with[-1]:.1f} / {d_without[-1]:.1f} %"),
            ("Fig. 4", "stability threshold with internal damping", f"{threshold:.2f} Hz")]


def fig05(data, out):
    steady = load(data, "fig05_steady_state")
    with_ = load(data, "fig05_runup_with")
    without = load(data, "fig05_runup_without")
    top = 0.7
    fig, ax = plt.subplots(figsize=(7, 4.4))
    ss, sa = steady_curve(steady)
    ax.plot(ss, sa, "--", color="black", label="with internal damping, steady state")
    ws, wm = runup_curve(with_)
    ax.plot(ws, wm, color="tab:red", lw=0.6, label="with internal damping, time integration")
    os_, om = runup_curve(without)
    ax.plot(os_, om, color="tab:blue", lw=0.6, label="without internal damping, time integration")
    leaves = first_above(ws, wm, top)
    if leaves is not None:
        ax.annotate(f"leaves the axis at {leaves:.1f} Hz;\nrun stopped at {ws[-1]:.1f} Hz "
                    f"(|r| = {wm[-1]:.0f} mm)", (leaves, top), xytext=(-175, -30),
                    textcoords="offset points", fontsize=8, color="tab:red",
                    arrowprops={"arrowstyle": "->", "color": "tab:red", "lw": 0.6})
    time_axis(ax, without)
    frame(ax, (0, 80), (0, top), REV, MAGNITUDE, "upper left")
    save(fig, out, "fig05",
         "Fig. 5: run-up with and without internal damping (clipped at the paper's 0.7 mm)")
    sp = steady["summary"]["probes"][0]
    pk = without["probes"][0]["peak"]
    return [("Fig. 5", "steady-state peak", f"{1e3 * sp['peak_amplitude_m']:.3f} mm at {sp['speed_hz']:.2f} Hz"),
            ("Fig. 5", "run-up peak without internal damping",
             f"{1e3 * pk['magnitude_m']:.3f} mm at {pk['speed_hz']:.2f} Hz"),
            ("Fig. 5", "run-up with internal damping: |r| > 0.7 mm from", f"{leaves:.1f} Hz"),
            ("Fig. 5", "run-up with internal damping: stopped (blow-up) at",
             f"{ws[-1]:.1f} Hz, complete = {with_['complete']}")]


def fig06(data, out):
    steady = load(data, "fig05_steady_state")
    without = load(data, "fig05_runup_without")
    fig, ax = plt.subplots(figsize=(7, 4.4))
    ss, sa = steady_curve(steady)
    ax.plot(ss, sa, "--", color="black", label="steady state")
    s, m = runup_curve(without)
    ax.plot(s, m, color="grey", lw=0.6, label="without coulomb damping")
    rows = []
    for name, force, colour in (("5_2N", "5.2", "tab:blue"), ("20_8N", "20.8", "tab:green"),
                                ("41_6N", "41.6", "tab:red")):
        r = load(data, f"fig06_runup_{name}")
        s, m = runup_curve(r)
        ax.plot(s, m, color=colour, lw=0.6, label=f"Fct0 = {force} N")
        pk = r["probes"][0]["peak"]
        late = m[s >= 75.0]
        rows.append(("Fig. 6", f"F_ct0 = {force} N: peak; |r| range 75-80 Hz",
                     f"{1e3 * pk['magnitude_m']:.3f} mm at {pk['speed_hz']:.1f} Hz; "
                     f"{late.min():.2f}-{late.max():.2f} mm"))
    time_axis(ax, without)
    frame(ax, (0, 80), (0, 1.2), REV, MAGNITUDE, "upper right")
    save(fig, out, "fig06", "Fig. 6: run-ups with Coulomb friction between rotor and shaft (Fcr0 = 0)")
    return rows


def whirl_frequency(runup, probe=0, box=0.1, half_window=0.1):
    """Frequency of the dominant low-frequency whirl in r = v + iw: three 100 ms box
    filters remove the synchronous motion (>= 40 Hz), the phase of what is left is
    fitted by a line over +-0.1 s. Negative: backward whirl. Returns (speeds, Hz).
    A value depends on the signal up to 0.25 s away (filter and fit)."""
    t = np.array(runup["time_s"])
    p = runup["probes"][probe]["dofs"]
    z = np.array(p["v"]) + 1j * np.array(p["w"])
    n = int(round(box / (t[1] - t[0])))
    for _ in range(3):
        z = np.convolve(z, np.ones(n) / n, mode="same")
    phase = np.unwrap(np.angle(z))
    speed = np.array(runup["speed_hz"])
    h = int(round(half_window / (t[1] - t[0])))
    centres = range(h + 2 * n, len(t) - h - 2 * n, 50)
    f = [np.polyfit(t[i - h:i + h], phase[i - h:i + h], 1)[0] / (2 * np.pi) for i in centres]
    return speed[list(centres)], np.array(f)


def fig07(data, out):
    runup = load(data, "fig07_runup_step")
    steady = load(data, "fig07_steady_state")
    soft = load(data, "fig08_campbell_step")
    fig, (ax, right) = plt.subplots(1, 2, figsize=(12, 4.4), gridspec_kw={"width_ratios": [2, 1]})
    s = np.array(runup["speed_hz"])
    v = 1e3 * np.array(runup["probes"][0]["dofs"]["v"])
    ax.plot(s, v, color="tab:blue", lw=0.4, label="time integration")
    ss = np.array(steady["speeds_hz"])
    va = 1e3 * np.array(steady["probes"][0]["dofs"]["v"]["amplitude"])
    ax.plot(ss, va, "--", color="black", label="steady state stiffness shift")
    ax.plot(ss, -va, "--", color="black")
    time_axis(ax, runup)
    frame(ax, (0, 140), (-0.25, 0.25), REV, "rotor displacement v(t) [mm]", "upper right")

    speeds, f = whirl_frequency(runup)
    after = speeds >= 42.5  # the filter and the fit reach 0.25 s (2.5 Hz) back, past the step
    right.plot(speeds[after], -f[after], ".", ms=2, color="tab:blue",
               label="whirl in the run-up (backward)")
    cs = np.array(soft["speeds_hz"])
    bw1 = curve(soft, "backward 1")
    right.plot(cs[cs >= 40], bw1[cs >= 40], color="black", lw=0.8, label="backward whirl 1 (Campbell, Fig. 8)")
    right.axhline(0.98, color="grey", lw=0.5, ls=":")
    right.axhline(0.68, color="grey", lw=0.5, ls=":")
    right.set_title("excited whirl after the step (0.98 and 0.68 Hz dotted)", fontsize=9)
    frame(right, (40, 140), (0, 1.2), REV, "whirl frequency [Hz]", "best")
    save(fig, out, "fig07", "Fig. 7: run-up, mounting stiffness stepped to 10 % at 40 Hz")
    fb = -f
    at = lambda x: float(np.interp(x, speeds, fb))  # noqa: E731
    reach = speeds[after][np.nonzero(fb[after] <= 0.68)[0][0]]
    return [("Fig. 7", "run-up: excited backward whirl at 43.5 / 50 / 60 Hz / end",
             f"{at(43.5):.3f} / {at(50):.3f} / {at(60):.3f} / {fb[-1]:.3f} Hz"),
            ("Fig. 7", "run-up: backward whirl reaches 0.68 Hz at", f"{reach:.1f} Hz"),
            ("Fig. 7", "run-up: largest |v| 40-45 Hz (after the step)",
             f"{np.abs(v[(s > 40.0) & (s < 45.0)]).max():.3f} mm")]


def fig08(data, out):
    r = load(data, "fig08_campbell_step")
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    campbell_panel(left, r, WHIRLS, 60, 30)
    speeds = np.array(r["speeds_hz"])
    for label in WHIRLS:
        colour, style = WHIRL_STYLE[label]
        right.plot(speeds, 100 * curve(r, label, "damping_ratio"), style, color=colour,
                   label=label.replace(" ", " whirl "))
    right.axvline(40, color="grey", lw=0.6, ls=":")
    frame(right, (0, 60), (0, 60), REV_SHORT, "damping [%]", "upper left")
    save(fig, out, "fig08",
         "Fig. 8: Campbell diagram (left) and damping (right), mounting stiffness stepped to 10 % at 40 Hz")
    bw1 = curve(r, "backward 1")
    largest = max(np.nanmax(curve(r, label, "damping_ratio")) for label in WHIRLS)
    return [("Fig. 8", "backward whirl 1 at 40 / 60 Hz", f"{bw1[speeds == 40.0][0]:.3f} / {bw1[-1]:.3f} Hz"),
            ("Fig. 8", "largest damping of whirls 1-2", f"{100 * largest:.1f} %")]


def fig09(data, out):
    unchanged = load(data, "fig09_campbell_unchanged")
    arctan = load(data, "fig09_campbell_arctan")
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    campbell_panel(left, unchanged, WHIRLS, 60, 30)
    left.set_title("100 % mounting stiffness", fontsize=9)
    campbell_panel(right, arctan, WHIRLS, 60, 30)
    right.set_title("arctan law, f_as = 3.98 Hz", fontsize=9)
    save(fig, out, "fig09", "Fig. 9: Campbell diagrams of the centrifuge")
    c0 = critical(unchanged)
    c1 = critical(arctan)
    return [("Fig. 9", "first critical speed, unchanged / arctan law",
             f"{c0['forward 1']:.3f} / {c1['forward 1']:.3f} Hz")]


def fig10(data, out):
    s100 = load(data, "fig10_steady_state_100")
    s10 = load(data, "fig10_steady_state_10")
    constant = load(data, "fig10_runup_constant")
    arctan = load(data, "fig10_runup_arctan")
    fig, ax = plt.subplots(figsize=(7, 4.4))
    s, a = steady_curve(s100)
    ax.plot(s, a, "--", color="black", label="steady state, const. stiffness 100 %")
    s, a = steady_curve(s10)
    ax.plot(s, a, ":", color="black", label="steady state, const. stiffness 10 %")
    s, m = runup_curve(constant)
    ax.plot(s, m, color="tab:blue", lw=0.5, label="constant stiffness")
    s, m = runup_curve(arctan)
    ax.plot(s, m, color="tab:red", lw=0.5, label="stiffness shift")
    time_axis(ax, constant)
    frame(ax, (0, 100), (0, 0.25), REV, MAGNITUDE, "upper right")
    save(fig, out, "fig10", "Fig. 10: run-ups with constant mounting stiffness and with the arctan law")
    pc = constant["probes"][0]["peak"]
    pa = arctan["probes"][0]["peak"]
    return [("Fig. 10", "run-up peak, constant stiffness / arctan law",
             f"{1e3 * pc['magnitude_m']:.3f} mm at {pc['speed_hz']:.1f} Hz / "
             f"{1e3 * pa['magnitude_m']:.3f} mm at {pa['speed_hz']:.1f} Hz, "
             f"{100 * (1 - pa['magnitude_m'] / pc['magnitude_m']):.1f} % lower"),
            ("Fig. 10", "steady-state peak 100 % / 10 %",
             f"{1e3 * s100['summary']['probes'][0]['peak_amplitude_m']:.3f} / "
             f"{1e3 * s10['summary']['probes'][0]['peak_amplitude_m']:.3f} mm")]


def main(data, out):
    os.makedirs(out, exist_ok=True)
    rows = []
    for draw in (fig01, fig04, fig05, fig06, fig07, fig08, fig09, fig10):
        rows += draw(data, out)
    width = max(len(r[1]) for r in rows)
    for fig, what, value in rows:
        print(f"{fig:8} {what:{width}}  {value}")
    print(f"Figures: {out}/fig01..fig10 (.png, .svg); data: {data}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
