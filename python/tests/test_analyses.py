"""Every analysis from Python equals the command line's JSON on every shipped example,
to 1e-12 relative (the same library code runs both ways; the tolerance allows only for
rounding in the JSON text, which keeps 17 significant digits), and the numpy arrays
hold the numbers the JSON holds."""
import glob
import json
import math
import os
import subprocess
import warnings

import numpy as np
import pytest

import feran

SOURCE = os.environ.get("FERAN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
FERAN = os.environ.get("FERAN_PROGRAM", os.path.join(SOURCE, "build", "feran"))
EXAMPLES = sorted(p for p in glob.glob(os.path.join(SOURCE, "examples", "*", "*.toml"))
                  if not p.endswith(".study.toml"))  # the models, not the design studies
RTOL = 1e-12

# (analysis, command-line options, the same as Python keywords)
CASES = [
    ("modal", ["--speed", "30Hz"], dict(speed="30 Hz")),
    ("modal", ["--speed", "10Hz", "--shapes"], dict(speed="10 Hz", shapes=True)),
    ("campbell", ["--stop", "60Hz", "--points", "13"], dict(stop="60 Hz", points=13)),
    ("response", ["--stop", "60Hz", "--points", "13", "--stations", "all"],
     dict(stop="60 Hz", points=13, stations="all")),
    ("static", [], {}),
]


def same(a, b, where="result"):
    """Asserts a and b (parsed JSON) equal, numbers to RTOL."""
    if isinstance(a, dict):
        assert isinstance(b, dict) and sorted(a) == sorted(b), where
        for k in a:
            same(a[k], b[k], f"{where}.{k}")
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            same(x, y, f"{where}[{i}]")
    elif isinstance(a, float) or isinstance(b, float):
        assert a == pytest.approx(b, rel=RTOL, abs=1e-300) or (math.isnan(a) and math.isnan(b)), where
    else:
        assert a == b, where


def cli_json(tmp_path, analysis, path, options):
    out = tmp_path / f"{analysis}.json"
    subprocess.run([FERAN, analysis, path, *options, "--json", str(out), "-q"], check=True,
                   stderr=subprocess.DEVNULL)
    return json.loads(out.read_text())


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: os.path.relpath(p, SOURCE))
@pytest.mark.parametrize("analysis,options,keywords", CASES, ids=[" ".join([c[0], *c[1]]) for c in CASES])
def test_every_analysis_equals_the_command_line(tmp_path, path, analysis, options, keywords):
    model = feran.read_model(path)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # some examples evaluate tables beyond their range, on purpose
        result = getattr(feran, analysis)(model, **keywords)
    same(result.to_dict(), cli_json(tmp_path, analysis, path, options))


RUNUPS = [
    ("01_internal_damping/model.toml", ["--from", "0Hz", "--to", "40Hz", "--ramp-time", "0.1s"],
     dict(from_="0 Hz", to="40 Hz", ramp_time="0.1 s")),
    ("03_coulomb_friction/model_20_8N.toml", ["--speed", "20Hz", "--duration", "0.05s", "--integrator", "ros34pw2"],
     dict(speed="20 Hz", duration="0.05 s", integrator="ros34pw2")),
    ("02_centrifuge/model.toml", ["--table", "0s:0Hz,0.05s:10Hz,0.1s:10Hz", "--integrator", "rk3",
                                  "--modes", "12", "--dt", "2e-5s"],
     dict(table=[(0, "0 Hz"), ("0.05 s", "10 Hz"), (0.1, 2 * math.pi * 10)], integrator="rk3", modes=12,
          dt=2e-5)),
]


@pytest.mark.parametrize("path,options,keywords", RUNUPS, ids=[r[0] for r in RUNUPS])
def test_runup_equals_the_command_line(tmp_path, path, options, keywords):
    path = os.path.join(SOURCE, "examples", path)
    result = feran.runup(feran.read_model(path), **keywords)
    cli = cli_json(tmp_path, "runup", path, options)
    same(result.to_dict(), cli)
    assert result.complete
    for i, probe in enumerate(cli["probes"]):
        np.testing.assert_allclose(result.magnitude[i], probe["magnitude_m"], rtol=RTOL)
    np.testing.assert_allclose(result.time, cli["time_s"], rtol=RTOL)


EXAMPLE = os.path.join(SOURCE, "examples", "01_internal_damping", "model.toml")


def test_campbell_arrays_and_critical_speeds(tmp_path):
    model = feran.read_model(EXAMPLE)
    c = feran.campbell(model, stop="80 Hz", points=81, orders=[1, 2])
    cli = cli_json(tmp_path, "campbell", EXAMPLE, ["--stop", "80Hz", "--points", "81", "--orders", "1,2"])
    assert c.frequency_hz.shape == (len(cli["modes"]), len(cli["speeds_hz"]))
    for i, mode in enumerate(cli["modes"]):
        assert c.labels[i] == mode["label"]
        np.testing.assert_allclose(c.frequency_hz[i], mode["frequency_hz"], rtol=RTOL)
        np.testing.assert_allclose(c.damping_ratio[i], mode["damping_ratio"], rtol=RTOL)
    np.testing.assert_allclose(c.speeds_hz, cli["speeds_hz"], rtol=RTOL)
    # The look-up selects by the whirl at the crossing and by the order, not by label text.
    forward = [x["speed_hz"] for x in cli["critical_speeds"] if x["whirl"] == "forward" and x["order"] == 1]
    np.testing.assert_allclose(c.critical_speeds(whirl="forward", order=1, unit="Hz"), forward, rtol=RTOL)
    assert len(forward) >= 1
    assert np.all(np.diff(c.critical_speeds(order=2)) >= 0)
    assert c.critical_speeds(order=2, unit="rpm") == pytest.approx(60 * c.critical_speeds(order=2, unit="Hz"))
    # At a critical speed of order k the mode's frequency is k times the speed.
    for x in c.criticals:
        assert x["frequency_hz"] == pytest.approx(x["order"] * x["speed_hz"], rel=1e-9)
    assert c.stability_threshold["speed_hz"] == pytest.approx(cli["stability_threshold_hz"], rel=RTOL)
    with pytest.raises(feran.Error, match="whirl="):
        c.critical_speeds(whirl="forwards")


def test_every_speed_in_rad_s_comes_in_hz_and_rpm_too():
    # rpm = 60 Hz = 60 ω/2π, to rounding (1e-15); None stays None.
    model = feran.read_model(EXAMPLE)
    c = feran.campbell(model, stop="80 Hz", points=5)
    assert np.allclose(c.speeds_rpm, c.speeds * 30 / np.pi, rtol=1e-15, atol=0)
    assert np.allclose(c.speeds_rpm, 60 * c.speeds_hz, rtol=1e-15, atol=0)
    assert c.speeds_rpm[-1] == pytest.approx(4800, rel=1e-14)
    m = feran.modal(model, speed="1800 rpm")
    assert m.speed_rpm == pytest.approx(1800, rel=1e-14) and m.speed_hz == pytest.approx(30, rel=1e-14)
    r = feran.response(model, stop="80 Hz", points=5)
    assert np.allclose(r.speeds_rpm, r.speeds * 30 / np.pi, rtol=1e-15, atol=0)
    assert (r.first_unstable_speed_rpm is None) == (r.first_unstable_speed is None)
    u = feran.runup(model, speed="10 Hz", duration="0.01 s")
    assert np.allclose(u.speed_rpm, 600, rtol=1e-14)


def test_response_arrays_match_the_json(tmp_path):
    model = feran.read_model(EXAMPLE)
    r = feran.response(model, stop="60 Hz", points=31, probe=["rotor", 1])
    cli = cli_json(tmp_path, "response", EXAMPLE, ["--stop", "60Hz", "--points", "31", "--probe", "rotor",
                                                   "--probe", "1"])
    assert r.probes == [p["name"] or str(p["node"]) for p in cli["probes"]]
    for i, probe in enumerate(cli["probes"]):
        np.testing.assert_allclose(r.orbit_major[i], probe["amplitude_m"], rtol=RTOL)
        np.testing.assert_allclose(r.orbit_minor[i], probe["minor_m"], rtol=RTOL)
        for d, dof in enumerate(["u", "v", "w", "rx", "ry", "rz"]):
            np.testing.assert_allclose(np.abs(r.displacement[i, :, d]), probe["dofs"][dof]["amplitude"], rtol=RTOL,
                                       atol=1e-300)
    # The orbit's major semi-axis lies between max(|v|, |w|) and sqrt(|v|^2 + |w|^2), whatever
    # the phases (an ellipse inscribed in the |v| x |w| rectangle touches its sides).
    v, w = np.abs(r.displacement[:, :, 1]), np.abs(r.displacement[:, :, 2])
    assert np.all(r.orbit_major <= np.sqrt(v**2 + w**2) * (1 + 1e-12))
    assert np.all(r.orbit_major >= np.maximum(v, w) * (1 - 1e-12))
    assert r.probe_index("rotor") == 0


def test_frequency_sweep_and_extra_force(tmp_path):
    model = feran.read_model(EXAMPLE)
    r = feran.response(model, speed="20 Hz", freq_start="1 Hz", freq_stop="50 Hz", freq_points=25,
                       force="rotor:y:1N", unbalance=False, probe="rotor")
    cli = cli_json(tmp_path, "response", EXAMPLE, ["--speed", "20Hz", "--freq-start", "1Hz", "--freq-stop",
                                                   "50Hz", "--freq-points", "25", "--force", "rotor:y:1N",
                                                   "--no-unbalance", "--probe", "rotor"])
    same(r.to_dict(), cli)
    assert r.frequency_sweep
    np.testing.assert_allclose(r.frequencies / (2 * np.pi), np.linspace(1, 50, 25), rtol=1e-12)


def test_static_arrays_balance_the_load():
    model = feran.read_model(EXAMPLE)
    s = feran.static(model)
    # Equilibrium (an invariant, not the solver's own residual): the forces the rotor puts
    # on its supports and on the springs to ground add up to the applied weight.
    carried = s.reaction_force.sum(axis=0)[1] + sum(
        f[1] for f, to in zip(s.spring_force, model.geometry()["spring_to_x"]) if np.isnan(to))
    assert carried == pytest.approx(s.total_load[1], rel=1e-9)
    assert s.displacement.shape == (len(s.nodes), 6)


def test_bad_options_are_errors():
    model = feran.read_model(EXAMPLE)
    with pytest.raises(feran.Error, match="give a speed with its unit"):
        feran.campbell(model, stop="80")
    with pytest.raises(feran.Error, match="probe 'rotr': no such node; did you mean 'rotor'"):
        feran.response(model, stop="60 Hz", probe="rotr")
    with pytest.raises(feran.Error, match="ramp_time"):
        feran.runup(model, from_="0 Hz", to="10 Hz", ramp_time=-1)
    with pytest.raises(feran.Error, match="solver"):
        feran.modal(model, solver="fast")
    with pytest.raises(TypeError):
        feran.campbell(model, "80 Hz")  # keywords only, as the CLI's options are named


def test_to_pandas_holds_the_arrays():
    model = feran.read_model(EXAMPLE)
    c = feran.campbell(model, stop="60 Hz", points=7)
    frame = c.to_pandas()
    assert len(frame) == c.frequency_hz.size
    for i, label in enumerate(c.labels):
        rows = frame[frame["label"] == label]
        np.testing.assert_array_equal(rows["frequency_hz"], c.frequency_hz[i])
        np.testing.assert_array_equal(rows["speed_hz"], c.speeds_hz)
        assert list(rows["whirl"]) == c.whirl_at[i]
    r = feran.response(model, stop="60 Hz", points=7, probe=["rotor", "drive"])
    frame = r.to_pandas()
    rows = frame[frame["probe"] == "drive"]
    np.testing.assert_array_equal(rows["v"], r.displacement[1, :, 1])
    np.testing.assert_array_equal(rows["speed_hz"], r.speeds / (2 * np.pi))
    m = feran.modal(model)
    assert list(m.to_pandas()["frequency_hz"]) == list(m.frequency_hz)
    s = feran.static(model)
    np.testing.assert_array_equal(s.to_pandas()["v"], s.displacement[:, 1])
    u = feran.runup(model, speed="10 Hz", duration="0.02 s", probe="rotor")
    np.testing.assert_array_equal(u.to_pandas()["rotor.r"], u.magnitude[0])


API684 = os.path.join(SOURCE, "examples", "05_api684_bearings", "model.toml")


def test_api684_equals_the_command_line_and_its_arrays_hold_its_numbers(tmp_path):
    options = ["--min-speed", "9000rpm", "--max-speed", "11000rpm", "--anticipated-q", "2e6", "--points", "201",
               "--map-points", "11"]
    r = feran.api684(feran.read_model(API684), min_speed="9000 rpm", max_speed="11000 rpm",
                     anticipated_q="2 MN/m", points=201, map_points=11)
    cli = cli_json(tmp_path, "api684", API684, options)
    same(json.loads(r.to_json()), cli)
    rpm = 30 / math.pi
    np.testing.assert_allclose(r.undamped_criticals * rpm, [c["speed_rpm"] for c in cli["undamped_criticals"]],
                               rtol=RTOL)
    for case, jc in zip(r.cases, cli["cases"]):
        assert case["passes"] == jc["passes"]
        for i, probe in enumerate(jc["probes"]):
            np.testing.assert_allclose(case["amplitude"][i], probe["amplitude_m"], rtol=RTOL)
    np.testing.assert_allclose(r.map["criticals"][:, 0] * rpm, cli["map"]["criticals_rpm"][0], rtol=RTOL)
    assert r.stability["q_zero"] == pytest.approx(cli["stability"]["q_zero_n_per_m"], rel=RTOL)
    assert r.passes == cli["separation_margins_pass"]


def test_api684_reads_its_table_and_reports_bad_arguments():
    model = feran.read_model(EXAMPLE).set_table("api684", min_speed="30 Hz", max_speed="40 Hz")
    r = feran.api684(model, points=51, map=False, stability=False)
    assert r.map is None and r.stability is None
    assert r.max_speed == pytest.approx(80 * math.pi)
    with pytest.raises(feran.Error, match="unbalance must be 4W/N or model, got '5W/N'"):
        feran.api684(model, unbalance="5W/N")
    with pytest.raises(feran.Error, match="operating speed range"):
        feran.api684(feran.read_model(EXAMPLE))  # a model without [api684]


def report_data(html):
    tag = '<script id="feran-data" type="application/json">'
    start = html.index(tag) + len(tag)
    return json.loads(html[start:html.index("</script>", start)])


def test_report_holds_the_data_of_the_command_lines_report(tmp_path):
    out = tmp_path / "cli.html"
    subprocess.run([FERAN, "report", EXAMPLE, "-o", str(out), "-q"], check=True)
    cli = report_data(out.read_text())
    html = feran.report(feran.read_model(EXAMPLE), str(tmp_path / "py.html"))
    assert (tmp_path / "py.html").read_text() == html
    py = report_data(html)
    for d in (cli, py):  # when and how it was made differ; the rest is the same computation
        del d["inputs"]["created"], d["inputs"]["command"]
    same(py, cli)
    assert html.startswith("<!DOCTYPE html>") and "plotly.js v" in html
    assert py["inputs"]["version"] == feran.__version__


def test_report_configuration_errors_name_file_line_and_column(tmp_path):
    config = tmp_path / "report.toml"
    config.write_text('[campbell]\nstpo = "50 Hz"\n')
    with pytest.raises(feran.ModelError, match=r"report.toml:2:1: .*did you mean 'stop'"):
        feran.report(feran.read_model(EXAMPLE), config=str(config))


def test_journal_bearings_carry_the_weight_and_report_their_forces(tmp_path):
    """Example 06: at the static equilibrium the two journal bearings carry the
    rotor's weight (their forces sum to the total load, to Newton's tolerance); the
    response's bearing arrays hold the JSON's numbers; a run-up started at the
    equilibrium under gravity starts there."""
    path = os.path.join(SOURCE, "examples", "06_oil_whip", "model.toml")
    model = feran.read_model(path)
    st = feran.static(model)
    assert st.bearings == ["bearing A", "bearing B"]
    assert st.bearing_force.shape == (2, 6)
    np.testing.assert_allclose(st.bearing_force[:, 1].sum(), st.total_load[1], rtol=1e-9)
    resp = feran.response(model, stop="60 Hz", points=5)
    out = tmp_path / "r.json"
    subprocess.run([FERAN, "response", path, "--stop", "60Hz", "--points", "5", "--json", str(out)], check=True,
                   capture_output=True)
    peaks = [b["peak_lateral_force_n"] for b in json.loads(out.read_text())["supports"]]
    np.testing.assert_allclose(resp.bearing_peak, peaks, rtol=RTOL)
    run = feran.runup(model, speed="3000 rpm", duration="2 ms", gravity=True, start="equilibrium")
    journal = list(run.probes).index("journal A")  # [runup] probes
    np.testing.assert_allclose(run.displacement[journal, 0, 1:3], st.displacement[0, 1:3], rtol=1e-9)
    with pytest.raises(feran.Error, match="start"):
        feran.runup(model, speed="3000 rpm", duration="2 ms", start="moving")
