"""The periodic orbits through Python: feran.orbits on the oil-whip rotor of examples/06
equals the command line's JSON (every array of every branch and bifurcation, to 1e-12
relative: the same library code, the JSON keeping 17 digits); OrbitsResult.orbit()
redraws each probe's orbit from its Fourier series, closed (θ from 0 to 2π), its
centre over one period the state's mean (1e-12 of the orbit), its largest distance
from it the state's amplitude on the phases the amplitude is taken at (1e-12) and,
sampled finely, within what either grid can miss; feran.plot.bifurcation draws every
segment between two states, dashed exactly where one of them is unstable, and one
marker per bifurcation where it lies; feran.plot.periodic_orbit draws orbit()'s
points."""
import json
import math
import os
import subprocess
import warnings

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

import feran  # noqa: E402
import feran.plot  # noqa: E402

SOURCE = os.environ.get("FERAN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
FERAN = os.environ.get("FERAN_PROGRAM", os.path.join(SOURCE, "build", "feran"))
MODEL = os.path.join(SOURCE, "examples", "06_oil_whip", "model.toml")
RTOL = 1e-12
# A coarse whirl branch past its fold: the equilibrium with its Hopf point, then 60
# self-excited orbits at 3 harmonics (0.4 s).
OPTIONS = ["--from", "5250rpm", "--to", "5400rpm", "--harmonics", "3", "--points", "60"]
KEYWORDS = dict(from_="5250 rpm", to="5400 rpm", harmonics=3, points=60)


@pytest.fixture(scope="module")
def both(tmp_path_factory):
    out = tmp_path_factory.mktemp("orbits") / "orbits.json"
    subprocess.run([FERAN, "orbits", MODEL, *OPTIONS, "--json", str(out), "-q"], check=True,
                   stderr=subprocess.DEVNULL)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the same warnings the command gives
        result = feran.orbits(feran.read_model(MODEL), **KEYWORDS)
    return result, json.loads(out.read_text())


def close(a, b):
    np.testing.assert_allclose(np.asarray(a, dtype=float), np.asarray(b, dtype=float), rtol=RTOL, atol=1e-300)


def test_the_branches_are_the_command_lines(both):
    r, j = both
    assert r.parameter == "speed"
    assert r.probes == [p["name"] for p in j["probes"]]
    assert [b["name"] for b in r.branches] == [b["name"] for b in j["branches"]]
    kinds = [f["kind"] for b in j["branches"] for f in b["bifurcations"]]
    assert "hopf" in kinds and "fold" in kinds  # the case reaches what it must compare
    for b, jb in zip(r.branches, j["branches"]):
        for key in ("kind", "ended_by", "clipped", "criticality"):
            assert b[key] == jb[key], key
        for arrays, states in ((b, jb["points"]), (b["bifurcations"], jb["bifurcations"])):
            assert len(arrays["parameter"]) == len(states)
            close(arrays["speed"] * 60 / (2 * math.pi), [s["speed_hz"] * 60 for s in states])
            close(arrays["frequency"] / (2 * math.pi), [s["frequency_hz"] for s in states])
            close(arrays["largest_multiplier"], [s["largest_multiplier"] for s in states])
            close(arrays["truncation"], [s["truncation"] for s in states])
            assert list(arrays["stable"]) == [s["stable"] for s in states]
            for key in ("amplitude", "largest", "mean_v", "mean_w"):
                close(arrays[key], [[p[f"{key}_m"] for p in s["probes"]] for s in states])
        assert list(b["bifurcations"]["kind"]) == [f["kind"] for f in jb["bifurcations"]]
        assert list(b["bifurcations"]["after"]) == [f["after"] for f in jb["bifurcations"]]
        close(b["bifurcations"]["critical_frequency"] / (2 * math.pi),
              [f["critical_frequency_hz"] for f in jb["bifurcations"]])


def test_orbit_is_the_states_series(both):
    r, _ = both
    b = r.branches[1]
    for point in (1, len(b["parameter"]) // 2, len(b["parameter"]) - 1):
        theta, v, w = r.orbit(1, point, samples=2000)
        assert theta.shape == (2000,) and v.shape == w.shape == (len(r.probes), 2000)
        assert theta[0] == 0 and theta[-1] == pytest.approx(2 * math.pi)  # the orbit closed: the first phase twice
        for i in range(len(r.probes)):
            size = b["amplitude"][point, i]
            assert np.mean(v[i][:-1]) == pytest.approx(b["mean_v"][point, i], abs=1e-12 * size)
            assert np.mean(w[i][:-1]) == pytest.approx(b["mean_w"][point, i], abs=1e-12 * size)
            # The amplitude is the largest distance over max(4N, 64) = 96 phases (N = 8H = 24
            # samples): on that grid, the same to rounding; over 2000 phases, within what
            # either grid can miss, (HΔθ)²/8: 4.8e-3 above (Δθ = 2π/96; measured 5e-5) and
            # 1.1e-5 below (Δθ = 2π/1999).
            _, cv, cw = r.orbit(1, point, samples=97)
            coarse = np.max(np.hypot(cv[i] - b["mean_v"][point, i], cw[i] - b["mean_w"][point, i]))
            assert coarse == pytest.approx(size, rel=1e-12)
            drawn = np.max(np.hypot(v[i] - b["mean_v"][point, i], w[i] - b["mean_w"][point, i]))
            missed = lambda phases: (3 * 2 * math.pi / phases) ** 2 / 8  # noqa: E731
            assert size * (1 - missed(1999)) <= drawn <= size * (1 + missed(96))


def lines(fig, prefix):
    return [line for line in fig.axes[0].lines if (line.get_gid() or "").startswith(prefix)]


def test_the_bifurcation_diagram_draws_stability_and_bifurcations(both):
    r, _ = both
    fig = feran.plot.bifurcation(r, "journal A")
    for n, b in enumerate(r.branches):
        segments = lines(fig, f"branch {n}")
        assert len(segments) == len(b["parameter"]) - 1
        for k, segment in enumerate(segments):
            both_stable = b["stable"][k] and b["stable"][k + 1]
            assert segment.get_linestyle() == ("-" if both_stable else "--"), (n, k)
        for k, kind in enumerate(b["bifurcations"]["kind"]):
            (marker,) = lines(fig, f"{kind} {n}.{k}")
            x, y = marker.get_data()
            assert x[0] == pytest.approx(b["bifurcations"]["speed"][k] / (2 * math.pi), rel=RTOL)
            assert y[0] == pytest.approx(b["bifurcations"]["amplitude"][k, 1], rel=RTOL)
    fig = feran.plot.periodic_orbit(r, "whirl 1", point=10)
    _, v, w = r.orbit(1, 10)
    for i in range(len(r.probes)):
        x, y = lines(fig, f"orbit {i}")[0].get_data()
        np.testing.assert_array_equal(x, v[i])
        np.testing.assert_array_equal(y, w[i])


# The same whirl reached from a run (start_at): at 5380 rpm, above the Hopf point, the
# run grows into the whip; the branch through its orbit, followed down, is the whirl
# branch of the fixture (which left the Hopf point): the same fold (1e-5 relative: each
# located to the corrector's tolerance on its own steps), and it ends where it meets
# the equilibrium, at the fixture's Hopf point (within the last step, 0.2 %). Python's
# `run` and branches equal the command line's JSON (1e-12).
START = dict(KEYWORDS, branch="whirl", start_at="5380 rpm", direction="down", points=120)


def test_a_branch_from_a_run_is_the_whirl_branch(both, tmp_path):
    whirl, _ = both
    out = tmp_path / "run.json"
    subprocess.run([FERAN, "orbits", MODEL, *OPTIONS[:-2], "--points", "120", "--branch", "whirl", "--start-at",
                    "5380rpm", "--direction", "down", "--json", str(out), "-q"], check=True,
                   stderr=subprocess.DEVNULL)
    j = json.loads(out.read_text())
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = feran.orbits(feran.read_model(MODEL), **START)
    assert r.run["kind"] == "self_excited"
    close(r.run["parameter"] * 60 / (2 * math.pi), 5380.0)
    per_hz = 1 / (2 * math.pi)
    for key, jkey, scale in (("speed", "speed_hz", per_hz), ("frequency", "frequency_hz", per_hz),
                             ("settled_after", "settled_after_s", 1.0), ("mismatch", "mismatch", 1.0)):
        close(r.run[key] * scale, j["run"][jkey])
    assert 0.45 < r.run["frequency"] / r.run["speed"] < 0.5  # the whip's ratio
    assert [b["name"] for b in r.branches] == ["from run (down)"] == [b["name"] for b in j["branches"]]
    b, jb = r.branches[0], j["branches"][0]
    close(b["frequency"] / (2 * math.pi), [s["frequency_hz"] for s in jb["points"]])
    close(b["amplitude"], [[p["amplitude_m"] for p in s["probes"]] for s in jb["points"]])
    # The run's orbit, corrected, is the branch's first state (1 % in frequency).
    assert b["frequency"][0] == pytest.approx(r.run["frequency"], rel=1e-2)
    fold = [s for s, k in zip(b["bifurcations"]["speed"], b["bifurcations"]["kind"]) if k == "fold"]
    ref = whirl.branches[1]
    ref_fold = [s for s, k in zip(ref["bifurcations"]["speed"], ref["bifurcations"]["kind"]) if k == "fold"]
    assert len(fold) == 1 and len(ref_fold) == 1
    assert fold[0] == pytest.approx(ref_fold[0], rel=1e-5)
    assert "meets the static equilibrium" in b["ended_by"]
    hopf = whirl.branches[0]["bifurcations"]["speed"][0]
    assert b["speed"][-1] == pytest.approx(hopf, rel=2e-3)
    assert not b["stable"][-1]


def test_a_run_that_dies_out_says_so():
    """Well below the fold the equilibrium is the only steady state: the run dies out onto
    it, and the analysis keeps no branch and says why."""
    with pytest.warns(UserWarning, match="dies out onto the static equilibrium"):
        r = feran.orbits(feran.read_model(MODEL), **dict(START, from_="4000 rpm", start_at="4000 rpm"))
    assert r.run is None and r.branches == []
