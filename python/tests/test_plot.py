"""feran.plot: each figure draws the data of its result (read back from the artists),
and the figures' own computations (orbits over a period, waterfall spectra) agree with
independent values."""
import math
import os

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

import feran  # noqa: E402
import feran.plot  # noqa: E402

SOURCE = os.environ.get("FERAN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
EXAMPLE = os.path.join(SOURCE, "examples", "01_internal_damping", "model.toml")
CENTRIFUGE = os.path.join(SOURCE, "examples", "02_centrifuge", "model.toml")


@pytest.fixture(scope="module")
def model():
    return feran.read_model(EXAMPLE)


def lines(fig, gid):
    return [line for ax in fig.axes for line in ax.get_lines() if line.get_gid() == gid]


def test_rotor_draws_every_section_body_and_spring():
    model = feran.read_model(CENTRIFUGE)
    g = model.geometry()
    fig = feran.plot.rotor(model)
    ax = fig.axes[0]
    sections = [p for p in ax.patches if p.get_gid() == "section"]
    assert len(sections) == 2 * len(g["segment_x0"])
    # Each section is drawn from x0 to x1 with the wall (outer - inner)/2 thick.
    xs = sorted({(round(p.get_x(), 12), round(p.get_x() + p.get_width(), 12)) for p in sections})
    assert xs == sorted({(round(a, 12), round(b, 12)) for a, b in zip(g["segment_x0"], g["segment_x1"])})
    walls = sorted(round(p.get_height(), 12) for p in sections)
    assert walls == sorted(round((d - di) / 2, 12) for d, di in zip(g["segment_outer"], g["segment_inner"])
                           for _ in (0, 1))
    bodies = [p for p in ax.patches if p.get_gid() == "body"]
    assert len(bodies) == len(g["body_names"])
    # A body's drawn diameter is that of the solid disk with its mass and polar inertia.
    for p, m, jp in zip(bodies, g["body_mass"], g["body_Jp"]):
        if jp > 0:
            assert p.get_height() == pytest.approx(math.sqrt(8 * jp / m))
    assert len(lines(fig, "spring")) >= len(g["spring_names"])
    names = ", ".join(t.get_text() for t in ax.texts)
    assert all(n in names for n in g["nodes"] if not n.isdigit())


def test_campbell_draws_modes_orders_criticals_and_threshold(model):
    c = feran.campbell(model, stop="80 Hz", points=41, orders=[1, 2])
    fig = feran.plot.campbell(c)
    ax = fig.axes[0]
    modes = [col for col in ax.collections if isinstance(col, LineCollection)]
    assert len(modes) == len(c.labels)
    for i, col in enumerate(modes):
        segments = col.get_segments()
        np.testing.assert_allclose([s[0][1] for s in segments], c.frequency_hz[i][:-1])
        np.testing.assert_allclose([s[0][0] for s in segments], c.speeds_hz[:-1])
        # coloured by the damping ratio at the middle of each segment
        np.testing.assert_allclose(col.get_array(), 0.5 * (c.damping_ratio[i][:-1] + c.damping_ratio[i][1:]))
    for k in (1, 2):
        (line,) = lines(fig, f"order {k}")
        np.testing.assert_allclose(line.get_ydata(), k * np.asarray(line.get_xdata()))
    drawn = sorted(line.get_xdata()[0] for line in lines(fig, "critical"))
    np.testing.assert_allclose(drawn, sorted(x["speed_hz"] for x in c.criticals))
    # The threshold line sits at the speed where a damping ratio crosses zero.
    (threshold,) = lines(fig, "stability threshold")
    s = threshold.get_xdata()[0]
    i = c.stability_threshold["mode"]
    assert np.interp(s, c.speeds_hz, c.damping_ratio[i]) == pytest.approx(0, abs=1e-3)
    # rpm: the same diagram, every speed and frequency times 60
    fig_rpm = feran.plot.campbell(c, unit="rpm", colour=None)
    first = [line for line in fig_rpm.axes[0].get_lines() if line.get_gid() == f"mode {c.labels[0]}"][0]
    np.testing.assert_allclose(first.get_ydata(), 60 * c.frequency_hz[0])


def test_mode_shapes_2d_and_3d(model):
    r = feran.modal(model, speed="20 Hz", shapes=True)
    i = [k for k, (t, w) in enumerate(zip(r.type, r.whirl)) if t == "lateral" and w == "forward"][0]
    fig = feran.plot.mode_shape(r, i)
    order = np.argsort(r.x)
    np.testing.assert_allclose(lines(fig, "shape v")[0].get_ydata(), r.shapes[i][order, 1].real)
    fig3 = feran.plot.mode_shape_3d(r, i)
    orbits = lines(fig3, "orbit")
    assert len(orbits) == len(r.x)
    # A forward orbit turns from +v towards +w: the signed area of (v, w) is positive.
    k = int(np.argmax(np.abs(r.shapes[i][:, 1])))
    v, w = orbits[list(order).index(k)].get_data_3d()[1:]
    assert 0.5 * np.sum(v[:-1] * w[1:] - v[1:] * w[:-1]) > 0
    with pytest.raises(ValueError, match="shapes=True"):
        feran.plot.mode_shape(feran.modal(model), 0)


def test_bode_polar_orbit_and_deflected_shape(model):
    nodes = model.geometry()["nodes"]
    r = feran.response(model, stop="60 Hz", points=61, probe=nodes)
    crit = feran.campbell(model, stop="60 Hz", points=61).critical_speeds(whirl="forward", order=1)
    fig = feran.plot.bode(r, "rotor", criticals=crit)
    p = r.probe_index("rotor")
    np.testing.assert_allclose(lines(fig, "amplitude")[0].get_ydata(), np.abs(r.displacement[p, :, 1]))
    np.testing.assert_allclose(lines(fig, "phase")[0].get_ydata(), np.degrees(np.angle(r.displacement[p, :, 1])))
    assert len(lines(fig, "critical")) == 2 * len(crit)
    fig = feran.plot.polar(r, "rotor", dof="w")
    np.testing.assert_allclose(lines(fig, "polar")[0].get_xdata(), r.displacement[p, :, 2].real)
    # The drawn orbit reaches the library's major semi-axis (to the sampling of 400
    # points over the period: 1 - cos(pi/400) < 4e-5).
    fig = feran.plot.orbit(r, "rotor", "30 Hz", points=400)
    x, y = lines(fig, "orbit")[0].get_data()
    k = int(np.argmin(np.abs(r.speeds - 2 * np.pi * 30)))
    assert np.max(np.hypot(x, y)) == pytest.approx(r.orbit_major[p, k], rel=4e-5)
    assert np.min(np.hypot(x, y)) == pytest.approx(r.orbit_minor[p, k], rel=1e-3, abs=1e-12)
    fig = feran.plot.deflected_shape(r, speed="30 Hz")
    order = np.argsort(r.probe_x)
    np.testing.assert_allclose(lines(fig, "major")[0].get_ydata(), r.orbit_major[order, k])
    s = feran.static(model)
    fig = feran.plot.deflected_shape(s)
    np.testing.assert_allclose(lines(fig, "static v")[0].get_ydata(), s.displacement[np.argsort(s.x), 1])
    # Forces: one line per spring and per support, the peaks the library computed,
    # in rpm the speeds times 60.
    fig = feran.plot.forces(r, unit="rpm")
    for i, name in enumerate(r.springs):
        (line,) = lines(fig, f"spring {name}")
        np.testing.assert_allclose(line.get_ydata(), r.spring_peak[i])
        np.testing.assert_allclose(line.get_xdata(), r.speeds * 60 / (2 * np.pi))
    assert r.reactions and np.all(r.reaction_peak[:, 1:] > 0)
    for i, name in enumerate(r.reactions):
        np.testing.assert_allclose(lines(fig, f"reaction {name}")[0].get_ydata(), r.reaction_peak[i])
    with pytest.raises(ValueError, match="no spring 'bearing 9'"):
        feran.plot.forces(r, springs=["bearing 9"])


def test_runup_envelope_and_waterfall(model):
    u = feran.runup(model, from_="0 Hz", to="40 Hz", ramp_time="1 s", probe="rotor")
    fig = feran.plot.runup_envelope(u)
    np.testing.assert_allclose(lines(fig, "envelope 0")[0].get_ydata(), u.envelope[0])
    # The envelope holds the largest |r| of each bin: never below the samples in it.
    assert np.nanmax(u.envelope[0]) >= np.max(u.magnitude[0]) * (1 - 1e-12)
    # At constant speed the unbalance response is at the rotation frequency: the
    # waterfall's last spectrum peaks at 20 Hz, to its frequency resolution.
    steady = feran.runup(model, speed="20 Hz", duration="2 s", probe="rotor")
    speeds, freqs, spectra = feran.plot.waterfall_spectra(steady, window=0.5)
    peak = freqs[np.argmax(spectra[-1])]
    assert peak == pytest.approx(20.0, abs=freqs[1])
    np.testing.assert_allclose(speeds, 2 * np.pi * 20)
    # The result's waterfall (C++, the report's definition) is numpy's: the windows'
    # Hann-tapered, mean-removed rfft scaled by 2/sum(taper), to round-off (1e-12 of
    # the largest amplitude: FFTs of a few hundred points in a different order).
    t, q = u.time, u.displacement[0, :, 1]
    n = int(round(0.1 / float(np.median(np.diff(t)))))
    taper = np.hanning(n)
    starts = range(0, len(t) - n + 1, max(1, int(n * 0.5)))
    expected = np.array([np.abs(np.fft.rfft((q[s:s + n] - q[s:s + n].mean()) * taper)) * 2 / taper.sum()
                         for s in starts])
    speeds, freqs, spectra = feran.plot.waterfall_spectra(u, window=0.1)
    assert spectra.shape == expected.shape
    np.testing.assert_allclose(spectra, expected, rtol=0, atol=1e-12 * expected.max())
    np.testing.assert_allclose(freqs, np.fft.rfftfreq(n, float(np.median(np.diff(t)))), rtol=1e-14)
    np.testing.assert_array_equal(speeds, [u.speed[s + n // 2] for s in starts])
    fig = feran.plot.waterfall(u, window=0.1, fmax=100)
    assert len(lines(fig, "spectrum")) == spectra_count(u, 0.1)
    assert len(lines(fig, "order 1")) == 1


def spectra_count(result, window):
    return len(feran.plot.waterfall_spectra(result, window=window)[0])
