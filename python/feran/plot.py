"""Figures of feran's models and results (matplotlib).

Every function draws one figure from a model or a result and returns the
matplotlib Figure; pass ``ax=`` to draw into axes of your own (the figure of those
axes is returned). Speeds and frequencies are shown in Hz unless ``unit="rpm"``.
Nothing is computed here that the library has not computed, except what a figure
itself is made of: the points of an orbit over one period, and the spectra of a
waterfall (the spectra of a run-up's samples, RunupResult.waterfall).

    import feran, feran.plot
    model = feran.read_model("examples/01_internal_damping/model.toml")
    fig = feran.plot.campbell(feran.campbell(model, stop="80 Hz"))
    fig.savefig("campbell.png")
"""
import math

import numpy as np

import matplotlib
import matplotlib.pyplot as plt
from matplotlib.collections import LineCollection
from matplotlib.patches import Polygon, Rectangle
from matplotlib.ticker import EngFormatter

DOFS = ("u", "v", "w", "rx", "ry", "rz")
_SPEED_UNITS = {"Hz": 1 / (2 * math.pi), "rpm": 60 / (2 * math.pi), "rad/s": 1.0}


def _speed_factor(unit):
    try:
        return _SPEED_UNITS[unit]
    except KeyError:
        raise ValueError(f"unit={unit!r}: expected 'Hz', 'rpm' or 'rad/s'") from None


def _axes(ax, projection=None, size=(7, 4.5)):
    if ax is not None:
        return ax.figure, ax
    fig = plt.figure(figsize=size)
    return fig, fig.add_subplot(projection=projection)


def _dof(dof):
    if dof not in DOFS:
        raise ValueError(f"dof={dof!r}: expected one of {', '.join(DOFS)}")
    return DOFS.index(dof)


# -- the rotor ---------------------------------------------------------------------

def rotor(model, ax=None, names=True):
    """The rotor drawn to scale in the x–r plane: shaft sections (hollow ones with
    their bore), rigid bodies as disks whose diameter is that of a solid disk with
    their mass and polar inertia (d = sqrt(8 Jp / m)), spring–dampers as markers to
    ground or to their second node, and the node names."""
    g = model.geometry()
    owned = ax is None
    fig, ax = _axes(ax, size=(9, 3.5))
    for x0, x1, d, di, d1, di1, rot in zip(g["segment_x0"], g["segment_x1"], g["segment_outer"],
                                           g["segment_inner"], g["segment_outer_end"], g["segment_inner_end"],
                                           g["segment_rotating"]):
        colour = "0.55" if rot else "tab:brown"
        for sign in (1, -1):
            if d1 == d and di1 == di:
                y0 = di / 2 if sign > 0 else -d / 2
                ax.add_patch(Rectangle((x0, y0), x1 - x0, (d - di) / 2, facecolor=colour, edgecolor="k", lw=0.5,
                                       gid="section"))
            else:  # a tapered section: a trapezoid between the bore and the outer surface
                corners = [(x0, sign * di / 2), (x1, sign * di1 / 2), (x1, sign * d1 / 2), (x0, sign * d / 2)]
                ax.add_patch(Polygon(corners, closed=True, facecolor=colour, edgecolor="k", lw=0.5, gid="section"))
    radius = float(np.max(np.concatenate([g["segment_outer"], g["segment_outer_end"]]), initial=0.0)) / 2
    extent = (float(np.min(g["node_x"])), float(np.max(g["node_x"])))
    for name, x, m, jp, rot in zip(g["body_names"], g["body_x"], g["body_mass"], g["body_Jp"], g["body_rotating"]):
        d = math.sqrt(8 * jp / m) if m > 0 and jp > 0 else 2 * max(radius, 1e-3) * 2
        width = 0.15 * d
        ax.add_patch(Rectangle((x - width / 2, -d / 2), width, d, facecolor="tab:blue" if rot else "tab:orange",
                               alpha=0.6, edgecolor="k", lw=0.5, gid="body"))
        radius = max(radius, d / 2)
        extent = (min(extent[0], x - width / 2), max(extent[1], x + width / 2))
    span = max(float(np.ptp(g["node_x"])) if len(g["node_x"]) else 0.0, 1e-3)
    ground = -1.25 * max(radius, 0.02 * span)
    for name, x, to in zip(g["spring_names"], g["spring_x"], g["spring_to_x"]):
        if math.isnan(to):
            ax.plot([x, x], [0, ground], color="tab:green", lw=1.5, gid="spring")
            ax.plot([x], [ground], marker="^", color="tab:green", ms=9, gid="spring")
        else:
            ax.plot([x, to], [0, 0.9 * ground], color="tab:green", lw=1.5, ls="--", gid="spring")
    ax.plot(g["node_x"], np.zeros(len(g["node_x"])), "k.", ms=3, gid="nodes")
    if names:
        # Nodes at one place (a shaft's end, a bearing's housing) share one label.
        at = {}
        for name, x in zip(g["nodes"], g["node_x"]):
            if not name.isdigit():
                at.setdefault(round(float(x), 9), []).append(name)
        for x, here in at.items():
            ax.annotate(", ".join(here), (x, 1.15 * radius), ha="center", va="bottom", fontsize=7, rotation=90,
                        gid="name")
    x_limits = (extent[0] - 0.05 * span, extent[1] + 0.05 * span)
    y_limits = (1.6 * ground, 3.5 * max(radius, 0.02 * span))
    ax.set_xlim(*x_limits)
    ax.set_ylim(*y_limits)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("r [m]")
    ax.set_title(model.title or model.path)
    if owned:  # a figure of the drawing's own proportions, so that it fills the figure
        aspect = (y_limits[1] - y_limits[0]) / (x_limits[1] - x_limits[0])
        width, height = 9.0, 9.0 * aspect + 1.2
        if height > 7:
            width, height = max(5.8 / aspect + 1.5, 6.0), 7.0
        fig.set_size_inches(width, max(height, 2.5))
        fig.tight_layout()
    return fig


# -- Campbell diagram -----------------------------------------------------------------

def campbell(result, unit="Hz", colour="damping_ratio", orders=True, criticals=True, whirl=True, fmax=None,
             ax=None, cmap="coolwarm_r"):
    """The Campbell diagram: the frequency of each tracked mode against speed,
    coloured by its damping ratio (``colour="damping_ratio"``) or log decrement
    (``"log_decrement"``; ``None``: one colour per mode) on a diverging scale
    symmetric about zero (the report's: red below zero, unstable; blue above), forward whirl marked ▲ and
    backward ▼, the excitation lines f = k × speed, the critical speeds (○) and the
    stability threshold (a dotted vertical line). The frequency axis ends at
    ``fmax`` (in ``unit``), by default a little above the highest excitation line,
    where the critical speeds are; modes above it are drawn but out of view."""
    factor = _speed_factor(unit)
    fig, ax = _axes(ax)
    x = result.speeds * factor
    y = result.frequency_hz if unit == "Hz" else result.frequency_hz * (60 if unit == "rpm" else 2 * math.pi)
    if colour not in (None, "damping_ratio", "log_decrement"):
        raise ValueError(f"colour={colour!r}: expected 'damping_ratio', 'log_decrement' or None")
    values = getattr(result, colour) if colour else None
    finite = values[np.isfinite(values)] if values is not None else np.array([])
    norm = None
    if finite.size:
        # One scale for every door (the report's too): diverging, centred on zero
        # damping and symmetric about it, so that red always means unstable (below
        # zero) and blue well damped, with ticks on both sides.
        limit = float(np.max(np.abs(finite))) or 1.0
        norm = matplotlib.colors.Normalize(-limit, limit)
    for i, label in enumerate(result.labels):
        if colour and norm is not None:
            points = np.column_stack([x, y[i]])
            segments = np.stack([points[:-1], points[1:]], axis=1)
            lines = LineCollection(segments, cmap=cmap, norm=norm, lw=2, gid=f"mode {label}")
            lines.set_array(0.5 * (values[i][:-1] + values[i][1:]))
            ax.add_collection(lines)
        else:
            ax.plot(x, y[i], lw=2, label=label, gid=f"mode {label}")
        if whirl:
            at = np.array(result.whirl_at[i])
            step = max(1, len(x) // 25)
            for word, marker in (("forward", "^"), ("backward", "v")):
                pick = np.nonzero(at == word)[0][::step]
                ax.plot(x[pick], y[i][pick], marker, ms=4, color="k", alpha=0.6, gid=f"whirl {word}")
    if colour and norm is not None:
        fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax,
                     label="damping ratio" if colour == "damping_ratio" else "log decrement")
    if fmax is not None:
        top = float(fmax)
    elif orders and result.orders:
        top = 1.15 * max(result.orders) * x[-1]
    else:
        top = float(np.nanmax(y)) * 1.05 if y.size else 1.0
    if orders:
        for k in result.orders:
            ax.plot(x, k * x, "k--", lw=0.8, gid=f"order {k}")
            ax.annotate(f"{k}×", (x[-1], k * x[-1]), fontsize=8, clip_on=True)
    if criticals:
        for c in result.criticals:
            s = c["speed"] * factor
            ax.plot([s], [c["order"] * s], "o", mfc="none", mec="k", ms=8, gid="critical")
    if result.stability_threshold is not None:
        s = result.stability_threshold["speed"] * factor
        ax.axvline(s, color="r", ls=":", gid="stability threshold")
        ax.annotate("onset of instability", (s, 0.95 * top), rotation=90, color="r", fontsize=8, ha="right")
    ax.set_xlim(x[0], x[-1])
    ax.set_ylim(0, top)
    ax.set_xlabel(f"speed [{unit}]")
    ax.set_ylabel(f"natural frequency [{unit}]")
    ax.set_title("Campbell diagram")
    if not colour:
        ax.legend(fontsize=8)
    return fig


# -- mode shapes ---------------------------------------------------------------------

def _mode_index(result, mode):
    if isinstance(mode, str):
        raise ValueError("mode: give the index of the mode in the result (0 for the first)")
    if not 0 <= mode < len(result):
        raise IndexError(f"mode {mode}: the result has {len(result)} modes")
    if result.shapes.shape[0] == 0:
        raise ValueError("the modal result has no shapes: run feran.modal(..., shapes=True)")
    return mode


def _rotor_order(result):
    return np.argsort(result.x, kind="stable")


def mode_shape(result, mode, ax=None):
    """A mode shape in 2D: the displacements v and w along x at the phase where the
    shape is largest (the real part of the complex shape after rotating its largest
    component to be real), with the nodes marked."""
    i = _mode_index(result, mode)
    fig, ax = _axes(ax)
    shape = result.shapes[i]
    order = _rotor_order(result)
    x = result.x[order]
    for d, style in ((1, "-"), (2, "--")):
        ax.plot(x, shape[order, d].real, style, marker=".", label=DOFS[d], gid=f"shape {DOFS[d]}")
    ax.axhline(0, color="k", lw=0.5)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("normalised displacement")
    ax.set_title(f"mode {i + 1}: {result.frequency_hz[i]:.4g} Hz, {result.whirl[i]}, "
                 f"damping {result.damping_ratio[i]:.3g}")
    ax.legend()
    return fig


def mode_shape_3d(result, mode, points=60, ax=None):
    """A mode shape in 3D: the orbit of every node over one period, (v, w) against x,
    the shaft line at the phase of largest motion, and the start of each orbit
    marked (the direction of travel shows the whirl)."""
    i = _mode_index(result, mode)
    fig, ax = _axes(ax, projection="3d", size=(8, 5))
    shape = result.shapes[i]
    order = _rotor_order(result)
    x = result.x[order]
    phase = np.linspace(0, 2 * math.pi, points)
    turn = np.exp(1j * phase)
    for n in order:
        v = (shape[n, 1] * turn).real
        w = (shape[n, 2] * turn).real
        ax.plot(np.full(points, result.x[n]), v, w, color="tab:blue", lw=1, gid="orbit")
        ax.plot([result.x[n]], [v[0]], [w[0]], "o", color="tab:blue", ms=3, gid="orbit start")
    ax.plot(x, shape[order, 1].real, shape[order, 2].real, color="k", lw=2, gid="shaft line")
    ax.plot(x, np.zeros_like(x), np.zeros_like(x), color="0.6", lw=0.8)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("v")
    ax.set_zlabel("w")
    ax.set_title(f"mode {i + 1}: {result.frequency_hz[i]:.4g} Hz, {result.whirl[i]}")
    return fig


# -- unbalance response ---------------------------------------------------------------

def _sweep_axis(result, unit):
    factor = _speed_factor(unit)
    if result.frequency_sweep:
        return result.frequencies * factor, f"excitation frequency [{unit}]"
    return result.speeds * factor, f"speed [{unit}]"


def bode(result, probe, dof="v", unit="Hz", criticals=None, fig=None):
    """Bode plot of a probe: amplitude (log scale) and phase of one DOF against the
    sweep. ``criticals``: speeds (rad/s) to mark, e.g. campbell.critical_speeds(...)."""
    p = result.probe_index(probe)
    d = _dof(dof)
    x, label = _sweep_axis(result, unit)
    z = result.displacement[p, :, d]
    if fig is None:
        fig = plt.figure(figsize=(7, 5.5))
    ax_a, ax_p = fig.subplots(2, 1, sharex=True)
    ax_a.semilogy(x, np.abs(z), gid="amplitude")
    ax_p.plot(x, np.degrees(np.angle(z)), gid="phase")
    for s in criticals if criticals is not None else []:
        for a in (ax_a, ax_p):
            a.axvline(s * _speed_factor(unit), color="r", ls=":", lw=0.8, gid="critical")
    unit_a = "m" if d < 3 else "rad"
    ax_a.set_ylabel(f"|{dof}| [{unit_a}]")
    ax_p.set_ylabel("phase [deg]")
    ax_p.set_xlabel(label)
    ax_a.set_title(f"response at {result.probes[p]}")
    return fig


def polar(result, probe, dof="v", unit="Hz", ax=None):
    """Polar (Nyquist) plot of a probe: the complex amplitude of one DOF over the
    sweep, with the first and last points labelled."""
    p = result.probe_index(probe)
    z = result.displacement[p, :, _dof(dof)]
    x, _ = _sweep_axis(result, unit)
    fig, ax = _axes(ax, size=(5.5, 5.5))
    ax.plot(z.real, z.imag, ".-", gid="polar")
    for k in (0, len(z) - 1):
        ax.annotate(f"{x[k]:.4g} {unit}", (z.real[k], z.imag[k]), fontsize=8)
    ax.axhline(0, color="k", lw=0.5)
    ax.axvline(0, color="k", lw=0.5)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(f"Re {dof} [m]")
    ax.set_ylabel(f"Im {dof} [m]")
    ax.set_title(f"polar plot at {result.probes[p]}")
    return fig


def forces(result, unit="Hz", springs=None, reactions=True, ax=None):
    """Peak lateral forces against the sweep: of each spring–damper (a bearing's load)
    and, with ``reactions``, of each fixed support that carries a lateral load;
    ``springs`` selects springs by
    name (default: all)."""
    x, label = _sweep_axis(result, unit)
    fig, ax = _axes(ax)
    names = list(result.springs) if springs is None else list(springs)
    for name in names:
        if name not in result.springs:
            raise ValueError(f"springs: no spring {name!r} in the result; it has {', '.join(result.springs)}")
        ax.plot(x, result.spring_peak[list(result.springs).index(name)], label=name, gid=f"spring {name}")
    if reactions:
        for i, name in enumerate(result.reactions):
            if not np.any(result.reaction_peak[i] > 0):
                continue  # a support that carries no lateral load (axial or torsional only)
            ax.plot(x, result.reaction_peak[i], ls="--", label=f"support {name}", gid=f"reaction {name}")
    ax.set_xlabel(label)
    ax.set_ylabel("peak lateral force [N]")
    ax.set_title("bearing and support forces")
    if ax.get_lines():
        ax.legend(fontsize=8)
    return fig


def _nearest_point(result, speed):
    axis = result.frequencies if result.frequency_sweep else result.speeds
    return int(np.argmin(np.abs(axis - speed)))


def _as_speed(speed):
    from ._feran import _speed  # the library's reading of a speed, as the analyses use it
    return _speed(speed)


def orbit(result, probe, speed, points=100, ax=None):
    """The orbit of a probe, (v, w) over one period, at the point of the sweep
    nearest to ``speed`` ('30 Hz' or rad/s), its start marked: travel from the
    marker shows the whirl."""
    p = result.probe_index(probe)
    k = _nearest_point(result, _as_speed(speed))
    v, w = result.displacement[p, k, 1], result.displacement[p, k, 2]
    turn = np.exp(1j * np.linspace(0, 2 * math.pi, points))
    fig, ax = _axes(ax, size=(5, 5))
    ax.plot((v * turn).real, (w * turn).real, gid="orbit")
    ax.plot([(v * turn).real[0]], [(w * turn).real[0]], "o", gid="orbit start")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("v [m]")
    ax.set_ylabel("w [m]")
    axis = result.frequencies if result.frequency_sweep else result.speeds
    ax.set_title(f"orbit at {result.probes[p]}, {axis[k] / (2 * math.pi):.4g} Hz")
    return fig


def deflected_shape(result, speed=None, ax=None):
    """The deflected shape along the shaft: for a static result, v and w of every
    node; for a response, the amplitude of the orbit (major semi-axis) of every
    probe at the point nearest ``speed`` — run the response with probe=every node
    (model.geometry()["nodes"]) for the whole shaft."""
    fig, ax = _axes(ax)
    if hasattr(result, "frequency_sweep"):
        if speed is None:
            raise ValueError("speed: the point of the sweep to draw ('30 Hz' or rad/s)")
        k = _nearest_point(result, _as_speed(speed))
        x = result.probe_x
        order = np.argsort(x, kind="stable")
        ax.plot(x[order], result.orbit_major[order, k], ".-", gid="major")
        ax.set_ylabel("orbit major semi-axis [m]")
        axis = result.frequencies if result.frequency_sweep else result.speeds
        ax.set_title(f"deflected shape at {axis[k] / (2 * math.pi):.4g} Hz")
    else:
        order = np.argsort(result.x, kind="stable")
        for d, style in ((1, "-"), (2, "--")):
            ax.plot(result.x[order], result.displacement[order, d], style, marker=".", label=DOFS[d],
                    gid=f"static {DOFS[d]}")
        ax.set_ylabel("displacement [m]")
        ax.set_title("static deflection")
        ax.legend()
    ax.axhline(0, color="k", lw=0.5)
    ax.set_xlabel("x [m]")
    return fig


# -- periodic orbits -------------------------------------------------------------------

_BIFURCATION_MARKERS = {"fold": "s", "hopf": "o", "neimark_sacker": "D", "period_doubling": "^",
                        "static_instability": "v"}


def _probe_index(result, probe):
    if probe is None:
        return 0
    return result.probes.index(probe) if isinstance(probe, str) else int(probe)


def bifurcation(result, probe=None, quantity="amplitude", unit="Hz", ax=None):
    """The bifurcation diagram of an orbits result: the orbit's ``quantity`` at a probe
    ("amplitude": the largest distance from its centre, "largest": from the axis,
    "mean_v", "mean_w") against the branches' parameter, stable states solid and
    unstable ones dashed, each bifurcation marked (fold ■, Hopf ●, Neimark–Sacker ◆,
    period doubling ▲). Speeds in ``unit``; a parameter path in its SI unit."""
    i = _probe_index(result, probe)
    speed = result.parameter == "speed"
    factor = _speed_factor(unit) if speed else 1.0
    fig, ax = _axes(ax)
    for n, b in enumerate(result.branches):
        x, y, stable = b["parameter"] * factor, b[quantity][:, i], b["stable"]
        colour = f"C{n % 10}"
        for k in range(1, len(x)):
            ax.plot(x[k - 1:k + 1], y[k - 1:k + 1], "-" if stable[k - 1] and stable[k] else "--", color=colour,
                    label=b["name"] if k == 1 else None, gid=f"branch {n}")
        f = b["bifurcations"]
        for k, kind in enumerate(f["kind"]):
            ax.plot([f["parameter"][k] * factor], [f[quantity][k, i]], _BIFURCATION_MARKERS.get(kind, "x"),
                    color="k", ms=7, mfc="none", gid=f"{kind} {n}.{k}")
            ax.annotate(kind.replace("_", "–" if kind == "neimark_sacker" else " "),
                        (f["parameter"][k] * factor, f[quantity][k, i]), fontsize=8, xytext=(4, 4),
                        textcoords="offset points")
    ax.set_xlabel(f"speed [{unit}]" if speed else result.parameter)
    ax.set_ylabel(quantity.replace("_", " "))
    ax.yaxis.set_major_formatter(EngFormatter(unit="m"))
    ax.set_title(f"steady states at {result.probes[i]} (solid: stable, dashed: unstable)")
    ax.legend()
    return fig


def periodic_orbit(result, branch=0, point=-1, probe=None, ax=None):
    """A steady state's orbit (v, w) over one period at each probe (or one), its start
    marked: the orbit of ``point`` of branch ``branch`` (an index, or the branch's name)
    of an orbits result."""
    if isinstance(branch, str):
        branch = [b["name"] for b in result.branches].index(branch)
    b = result.branches[branch]
    point = point % len(b["parameter"])
    _, v, w = result.orbit(branch, point)
    fig, ax = _axes(ax, size=(5, 5))
    for i in range(len(result.probes)) if probe is None else [_probe_index(result, probe)]:
        ax.plot(v[i], w[i], label=result.probes[i], gid=f"orbit {i}")
        ax.plot([v[i][0]], [w[i][0]], "o", color=ax.lines[-1].get_color(), gid=f"orbit start {i}")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("v [m]")
    ax.set_ylabel("w [m]")
    where = (f"{b['speed'][point] / (2 * math.pi):.4g} Hz" if result.parameter == "speed"
             else f"{result.parameter} = {b['parameter'][point]:.4g}")
    ax.set_title(f"{b['name']} at {where}, {'stable' if b['stable'][point] else 'unstable'}")
    ax.legend()
    return fig


# -- run-ups --------------------------------------------------------------------------

def runup_envelope(result, probe=None, unit="Hz", ax=None):
    """The envelope of a run-up: the largest |r| of each probe (or one) in each
    speed bin, taken at every step of the integration, against speed."""
    factor = _speed_factor(unit)
    fig, ax = _axes(ax)
    names = result.probes if probe is None else [probe]
    for name in names:
        i = result.probes.index(name) if isinstance(name, str) else int(name)
        ax.plot(result.envelope_speed * factor, result.envelope[i], label=result.probes[i], gid=f"envelope {i}")
    ax.set_xlabel(f"speed [{unit}]")
    ax.set_ylabel("largest |r| [m]")
    ax.set_title("run-up envelope")
    ax.legend()
    return fig


def waterfall_spectra(result, probe=0, dof="v", window=None, overlap=0.5):
    """The spectra of a waterfall: the run-up's samples of one DOF cut into windows
    of ``window`` seconds (default: a twentieth of the run), each with a Hann window
    and its mean removed; returns (speed at each window's middle [rad/s],
    frequencies [Hz], amplitude spectra, shape (windows, frequencies), in the DOF's
    unit as the amplitude of a sine). The result's own ``waterfall()``, which the
    report draws too."""
    i = result.probes.index(probe) if isinstance(probe, str) else int(probe)
    if len(result.time) < 8:
        raise ValueError("the run-up has too few samples for a waterfall")
    return result.waterfall(i, _dof(dof), window, overlap)


def waterfall(result, probe=0, dof="v", window=None, unit="Hz", orders=(1,), fmax=None, ax=None):
    """Waterfall of a run-up: the amplitude spectrum of one DOF of a probe, window by
    window, drawn as lines stacked against speed (3D), with the order lines
    f = k × speed in the floor."""
    speeds, freqs, spectra = waterfall_spectra(result, probe, dof, window)
    factor = _speed_factor(unit)
    fig, ax = _axes(ax, projection="3d", size=(8, 5.5))
    keep = freqs <= (fmax if fmax else freqs[-1])
    scale = 60 if unit == "rpm" else (2 * math.pi if unit == "rad/s" else 1)
    for s, a in zip(speeds, spectra):
        ax.plot(freqs[keep] * scale, np.full(keep.sum(), s * factor), a[keep], color="tab:blue", lw=0.8,
                gid="spectrum")
    for k in orders:
        ax.plot(k * speeds * factor, speeds * factor, np.zeros_like(speeds), "r--", lw=0.8, gid=f"order {k}")
    ax.set_xlabel(f"frequency [{unit}]")
    ax.set_ylabel(f"speed [{unit}]")
    ax.set_zlabel(f"|{dof}|", labelpad=14)
    ax.zaxis.set_major_formatter(EngFormatter(unit="m" if _dof(dof) < 3 else "rad"))
    ax.set_title(f"waterfall at {result.probes[probe] if isinstance(probe, int) else probe}")
    return fig


# -- design studies ----------------------------------------------------------------

def _study_column(result, name):
    """The values of a variable or quantity of a study result by name, its label (name
    and SI unit) and whether the variable is on a log scale."""
    study = result._study
    if name in study.variable_names:
        j = study.variable_names.index(name)
        unit = study.variable_units[j]
        return result.values[:, j], f"{name} [{unit}]" if unit else name, study.variable_log[j]
    if name in study.quantity_names:
        j = study.quantity_names.index(name)
        unit = study.quantity_units[j]
        return result.quantities[:, j], f"{name} [{unit}]" if unit else name, False
    raise ValueError(f"{name!r} is neither a variable ({', '.join(study.variable_names)}) nor a quantity "
                     f"({', '.join(study.quantity_names)}) of the study")


def pareto_front(result, x=None, y=None, ax=None):
    """The designs of a study in the plane of two quantities (default its first two
    objectives): the feasible ones as dots, the infeasible ones as crosses, and the
    Pareto set (the study's, in its objectives) joined in order of x."""
    objectives = [name for name, _ in result._study.objectives]
    if x is None or y is None:
        if len(objectives) < 2:
            raise ValueError("pareto_front: the study has fewer than two objectives; give x= and y=")
        x, y = x or objectives[0], y or objectives[1]
    xs, xlabel, _ = _study_column(result, x)
    ys, ylabel, _ = _study_column(result, y)
    fig, ax = _axes(ax)
    ok, bad = result.feasible, result.evaluated & ~result.feasible
    ax.plot(xs[ok], ys[ok], ".", color="0.6", label="feasible", gid="feasible")
    if bad.any():
        ax.plot(xs[bad], ys[bad], "x", color="tab:red", ms=4, label="infeasible", gid="infeasible")
    front = np.asarray(result.pareto, dtype=int)
    front = front[np.argsort(xs[front], kind="stable")]
    ax.plot(xs[front], ys[front], "o-", color="tab:blue", label=f"Pareto set ({len(front)})", gid="pareto")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title("Pareto front")
    ax.legend()
    return fig


def parallel_coordinates(result, columns=None, colour=None, ax=None):
    """One line per evaluated design through its variables and quantities (default all
    of them), each axis scaled from its smallest to its largest value (a log-scaled
    variable in its decades), coloured by ``colour`` (default the first objective);
    infeasible designs grey. The axes' ranges are written at their ends."""
    study = result._study
    columns = list(columns) if columns else list(study.variable_names) + list(study.quantity_names)
    if colour is None and study.objectives:
        colour = study.objectives[0][0]
    rows = np.flatnonzero(result.evaluated)
    fig, ax = _axes(ax, size=(max(6, 1.6 * len(columns)), 4.5))
    scaled = np.empty((len(rows), len(columns)))
    for k, name in enumerate(columns):
        v, _, log = _study_column(result, name)
        v = np.log10(v[rows]) if log else v[rows]
        lo, hi = (v.min(), v.max()) if len(v) else (0.0, 1.0)
        scaled[:, k] = (v - lo) / (hi - lo) if hi > lo else 0.5
        shown = (10 ** lo, 10 ** hi) if log else (lo, hi)
        ax.text(k, -0.04, f"{shown[0]:.4g}", ha="center", va="top", fontsize=7)
        ax.text(k, 1.04, f"{shown[1]:.4g}", ha="center", va="bottom", fontsize=7)
    c = _study_column(result, colour)[0][rows] if colour else np.zeros(len(rows))
    feasible = result.feasible[rows]
    ticks = np.arange(len(columns))
    grey = [np.column_stack([ticks, s]) for s, f in zip(scaled, feasible) if not f]
    if grey:
        ax.add_collection(LineCollection(grey, colors="0.8", lw=0.6, gid="infeasible"))
    good = LineCollection([np.column_stack([ticks, s]) for s, f in zip(scaled, feasible) if f], lw=0.9,
                          cmap="viridis", gid="feasible")
    good.set_array(c[feasible])
    ax.add_collection(good)
    if colour and feasible.any():
        fig.colorbar(good, ax=ax, label=_study_column(result, colour)[1])
    for k in ticks:
        ax.axvline(k, color="k", lw=0.8)
    ax.set_xticks(ticks, columns, rotation=20)
    ax.set_xlim(-0.2, len(columns) - 0.8)
    ax.set_ylim(-0.12, 1.12)
    ax.set_yticks([])
    ax.set_title("parallel coordinates")
    return fig


def response_surface(result, x, y, quantity, levels=15, ax=None):
    """A quantity over two variables: filled contours over the evaluated designs
    (linear interpolation on their Delaunay triangulation, in the variables' own
    scales: any sample or grid), the designs as dots and the best feasible one of a
    single-objective study as a star."""
    import matplotlib.tri as mtri
    xs, xlabel, xlog = _study_column(result, x)
    ys, ylabel, ylog = _study_column(result, y)
    zs, zlabel, _ = _study_column(result, quantity)
    ok = result.evaluated & np.isfinite(zs)
    if ok.sum() < 3:
        raise ValueError("response_surface: fewer than three evaluated designs")
    u = np.log10(xs[ok]) if xlog else xs[ok]
    v = np.log10(ys[ok]) if ylog else ys[ok]
    fig, ax = _axes(ax)
    triangles = mtri.Triangulation(u, v)
    filled = ax.tricontourf(triangles, zs[ok], levels=levels, cmap="viridis")
    fig.colorbar(filled, ax=ax, label=zlabel)
    ax.plot(u, v, ".", color="k", ms=2, gid="designs")
    best = result.best if len(result._study.objectives) == 1 else None
    if best is not None:
        bu = np.log10(xs[best]) if xlog else xs[best]
        bv = np.log10(ys[best]) if ylog else ys[best]
        ax.plot([bu], [bv], "*", color="tab:red", ms=12, gid="best")
    ax.set_xlabel(f"log10 {xlabel}" if xlog else xlabel)
    ax.set_ylabel(f"log10 {ylabel}" if ylog else ylabel)
    ax.set_title(f"{quantity} over {x} and {y}")
    return fig
