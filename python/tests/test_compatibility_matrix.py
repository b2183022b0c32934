"""The compatibility matrix: every entry family × every analysis × every door.

Families are every shipped example model and one small rotor per kind of support
(journal bearings in the short, long and finite theories, the finite one also with its
film force from its table in every analysis, rolling bearings, an annular seal beside
the journal bearings, a tapered shaft under axial load), generated here from the journal-bearing rotor of the tests
(tests/models/valid/journal_rotor.toml); the examples bring frequency tables (07), a
torque drive (02, model_motor) and dry friction (03). Analyses are the command
line's: modal, campbell, response, static, runup (20 ms of the model's own run-up),
api684 (where the model gives an operating range), orbits (a coarse branch over
1000–3000 rpm) and report. Each cell either runs,
with every number it writes finite (or null where the output format allows it), or is
refused with one of the documented reasons below. Doors: the command line's JSON and
CSV, Python (to_dict() equals the command line's JSON to 1e-12), and the report's
embedded data (its sections equal the command line's JSON of the same analysis), and
every study quantity kind on every family (test_study_quantities: the command line's
evaluations.jsonl equals Python's Study.run() to the last bit).

The lists FAMILIES and ANALYSES are built from the tree and from `feran --help`, so a
new example, support family or command joins the matrix without editing this test;
a new command that is not in ANALYSES below fails test_every_command_is_in_the_matrix."""
import csv
import glob
import json
import math
import os
import re
import subprocess
import warnings

import numpy as np
import pytest

import feran
from test_analyses import same  # numbers to 1e-12

SOURCE = os.environ.get("FERAN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
FERAN = os.environ.get("FERAN_PROGRAM", os.path.join(SOURCE, "build", "feran"))
JOURNAL = os.path.join(SOURCE, "tests", "models", "valid", "journal_rotor.toml")


def journal_variant(text, kind):
    """The journal rotor with its supports of another kind."""
    if kind == "journal_short":
        return text
    if kind == "journal_long":
        return text.replace('viscosity = "20 mPa*s"', 'viscosity = "20 mPa*s"\ntheory = "long"')
    if kind == "journal_finite":
        return text.replace('viscosity = "20 mPa*s"',
                            'viscosity = "20 mPa*s"\ntheory = "finite"\ncircumferential_cells = 24\naxial_cells = 4')
    if kind == "journal_finite_table":  # the film force from its table in every analysis, not only run-ups
        finite = journal_variant(text, "journal_finite")
        return finite.replace('axial_cells = 4', 'axial_cells = 4\nevaluation = "table"')
    if kind == "rolling":
        blocks = re.findall(r"\[\[journal_bearings\]\]\nname = \"([^\"]+)\"\nnode = \"([^\"]+)\"\n"
                            r"(?:[^\[\n][^\n]*\n)*", text)
        out = re.sub(r"\[\[journal_bearings\]\]\n(?:[^\[\n][^\n]*\n)*\n?", "", text)
        for name, node in blocks:
            out += (f'\n[[rolling_bearings]]\nname = "{name}"\nnode = "{node}"\nelements = 9\n'
                    'element_diameter = "12 mm"\npitch_diameter = "80 mm"\nclearance = "5 um"\n'
                    'hertz_constant = 1e10\n')
        return out
    if kind == "seal":  # a water seal at disk 2 (a balance drum), the journal bearings kept
        return text + ('\n[[annular_seals]]\nname = "balance drum"\nnode = "disk 2"\ndiameter = "150 mm"\n'
                       'length = "40 mm"\nclearance = "0.2 mm"\npressure_drop = "2 MPa"\n'
                       'density = "1000 kg/m^3"\nviscosity = "1 mPa*s"\n')
    if kind == "tapered_axial":
        return text.replace('  length = "400 mm"\n  outer_diameter = "60 mm"\n  elements = 4\n  end_node = "disk 2"',
                            '  length = "400 mm"\n  outer_diameter = "60 mm"\n  outer_diameter_end = "50 mm"\n'
                            '  axial_force = "20 kN"\n  elements = 4\n  end_node = "disk 2"')
    raise ValueError(kind)


SUPPORT_FAMILIES = ["journal_short", "journal_long", "journal_finite", "journal_finite_table", "rolling",
                    "seal", "tapered_axial"]
EXAMPLES = sorted(p for p in glob.glob(os.path.join(SOURCE, "examples", "*", "*.toml"))
                  if not p.endswith(".study.toml"))
FAMILIES = [("example:" + os.path.relpath(p, os.path.join(SOURCE, "examples")), p) for p in EXAMPLES] + \
           [("support:" + k, k) for k in SUPPORT_FAMILIES]

# Each analysis: its command-line options and the same as Python keywords (None: no
# Python door of that name), and whether it writes CSV.
ANALYSES = {
    "modal": ([], {}, False),
    "campbell": (["--points", "9"], dict(points=9), True),
    "response": (["--points", "9"], dict(points=9), True),
    "static": ([], {}, True),
    "runup": (["--duration", "0.02s"], dict(duration="0.02 s"), True),
    "api684": (["--points", "61", "--map-points", "5", "--no-stability"],
               dict(points=61, map_points=5, stability=False), True),
    # A coarse branch: 2 harmonics, at most 12 states per branch.
    "orbits": (["--from", "1000rpm", "--to", "3000rpm", "--harmonics", "2", "--points", "12"],
               dict(from_="1000 rpm", to="3000 rpm", harmonics=2, points=12), True),
    "report": (None, None, False),
}

# The documented reasons a cell may be refused (docs/model-format.md, docs/output-format.md).
REFUSALS = [
    r"oil film .* at rest|carries no load at rest|needs? a speed above 0|speed 0",  # an oil film at rest
    r"operating (speed )?range|--min-speed|min_speed",  # api684 without an operating range
    r"no \[runup\]|give a speed profile|--to|--speed",   # runup without a profile
    r"the model has no \[\[unbalances\]\]|nothing excites",  # response without excitation
    r"added mass that changes with speed",  # runup with an annular seal (its mass varies with speed)
    # orbits: what the periodic analysis cannot take (docs/theory/harmonic_balance.md)
    r"periodic orbits: the model has supports whose coefficients depend on the frequency",
    r"periodic orbits: the model has hysteretic damping",
    r"periodic orbits: the force .* follows a time law of its own",
]


def model_path(tmp_path, family):
    name, source = family
    if name.startswith("example:"):
        return source
    path = tmp_path / f"{source}.toml"
    with open(JOURNAL) as f:
        path.write_text(journal_variant(f.read(), source))
    return str(path)


def finite_numbers(value, where="result"):
    if isinstance(value, dict):
        for k, v in value.items():
            finite_numbers(v, f"{where}.{k}")
    elif isinstance(value, list):
        for i, v in enumerate(value):
            finite_numbers(v, f"{where}[{i}]")
    elif isinstance(value, float):
        assert math.isfinite(value), where


def refused(stderr):
    return any(re.search(r, stderr) for r in REFUSALS)


def test_every_command_is_in_the_matrix():
    """A new analysis (a command of feran --help) must join ANALYSES."""
    text = subprocess.run([FERAN, "--help"], capture_output=True, text=True).stdout
    listed = text.split("Subcommands:")[1].split("Examples:")[0]
    commands = set(re.findall(r"^\s{2}(\w+)\s", listed, re.M))
    # Not analyses of one model: the parameter list and the design studies (these have
    # their own tests: tests/cli/test_study.py, study quantities in tests/unit/study).
    commands -= {"params", "study"}
    assert commands and commands <= set(ANALYSES), sorted(commands - set(ANALYSES))


@pytest.mark.parametrize("family", FAMILIES, ids=[f[0] for f in FAMILIES])
@pytest.mark.parametrize("analysis", sorted(ANALYSES))
def test_cell(tmp_path, family, analysis):
    path = model_path(tmp_path, family)
    options, keywords, has_csv = ANALYSES[analysis]
    if analysis == "report":
        out = tmp_path / "report.html"
        run = subprocess.run([FERAN, "report", path, "-o", str(out)], capture_output=True, text=True)
        if run.returncode != 0:
            assert refused(run.stderr), run.stderr
            assert not out.exists()
            return
        html = out.read_text()
        data = json.loads(re.search(r'<script id="feran-data" type="application/json">\n(.*?)\n</script>',
                                    html, re.S).group(1))
        finite_numbers(data)
        for section in ("campbell", "response", "static", "api684", "orbits"):
            if isinstance(data.get(section), dict):
                assert "error" not in data[section], (section, data[section].get("error"))
        # The report's Campbell diagram is the command's, where the report kept the
        # model's own speeds (without an operating range or a [campbell] stop the
        # report chooses its own, docs/report.md).
        cli = tmp_path / "campbell.json"
        subprocess.run([FERAN, "campbell", path, "--json", str(cli), "-q"], check=True, capture_output=True)
        expect = json.loads(cli.read_text())
        if data["campbell"]["speeds_hz"] == expect["speeds_hz"]:
            same(data["campbell"], expect, "report.campbell")
        return
    json_out, csv_out = tmp_path / f"{analysis}.json", tmp_path / f"{analysis}.csv"
    args = [FERAN, analysis, path, *options, "--json", str(json_out), "-q"]
    if has_csv:
        args += ["--csv", str(csv_out)]
    run = subprocess.run(args, capture_output=True, text=True)
    if run.returncode not in (0, 3):  # 3: a run-up stopped at its blow-up limit, results kept
        assert refused(run.stderr), f"exit {run.returncode}: {run.stderr}"
        assert not json_out.exists() and not csv_out.exists(), "a refused cell wrote a file"
        with pytest.raises((feran.Error, ValueError)):
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                getattr(feran, analysis)(feran.read_model(path), **keywords)
        return
    cli = json.loads(json_out.read_text())
    finite_numbers(cli)
    if has_csv:
        with open(csv_out) as f:
            rows = list(csv.reader(f))
        # A header and a row per point; API 684's a row per resonance peak (none is possible).
        assert len(rows) >= (1 if analysis == "api684" else 2) and all(len(r) == len(rows[0]) for r in rows)
        for row in rows[1:]:
            for cell in row:
                try:
                    x = float(cell)
                except ValueError:
                    continue
                assert math.isfinite(x)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = getattr(feran, analysis)(feran.read_model(path), **keywords)
    if run.returncode == 0:
        same(json.loads(result.to_json()), cli)
        same_bearing_data(result, cli)
        if has_csv:  # the same text through both doors (a run-up's streamed on the command line)
            assert result.to_csv() == csv_out.read_text()


def same_bearing_data(result, cli):
    """Python's bearing_data is the JSON's supports[].operating, value for value (the JSON
    writes NaN and infinity as null)."""
    data = getattr(result, "bearing_data", None)
    if data is None:
        return
    supports = [s for s in cli.get("supports", []) if "operating" in s]
    assert len(data) == len(supports)
    for got, support in zip(data, supports):
        assert set(got) == set(support["operating"]), support["label"]
        for name, values in got.items():
            got_values = np.atleast_1d(np.asarray(values, dtype=float))
            got_values = np.where(np.isfinite(got_values), got_values, np.nan)
            expect = np.atleast_1d(np.array(support["operating"][name], dtype=float))
            assert np.array_equal(got_values, expect, equal_nan=True), (support["label"], name)


# The orbits from a run (start_at) on every family: the branch through the orbit a run
# at 2000 rpm settles on within 10 s (a forced orbit where an unbalance acts, else a
# whirl), the same through the command line and Python, or a documented refusal: what
# the periodic analysis cannot take (exit 1, nothing written), or what the run did
# instead of settling (exit 3, the JSON written with no run and no branch).
RUN_OPTIONS = (["--from", "1000rpm", "--to", "3000rpm", "--harmonics", "2", "--points", "6", "--start-at", "2000rpm",
                "--settle", "10s"],
               dict(from_="1000 rpm", to="3000 rpm", harmonics=2, points=6, start_at="2000 rpm", settle="10 s"))
RUN_ENDS = [r"dies out onto the static equilibrium", r"had not settled after", r"grows beyond a hundred times",
            r"does not repeat after one period", r"time step did not converge"]


@pytest.mark.parametrize("family", FAMILIES, ids=[f[0] for f in FAMILIES])
def test_orbits_from_a_run(tmp_path, family):
    path = model_path(tmp_path, family)
    options, keywords = RUN_OPTIONS
    out = tmp_path / "orbits.json"
    run = subprocess.run([FERAN, "orbits", path, *options, "--json", str(out), "-q"], capture_output=True, text=True)
    if run.returncode == 1:
        assert refused(run.stderr), run.stderr
        assert not out.exists()
        return
    cli = json.loads(out.read_text())
    finite_numbers(cli)
    if run.returncode == 3:
        assert any(re.search(r, run.stderr) for r in RUN_ENDS), run.stderr
        assert cli["run"] is None and cli["branches"] == []
    else:
        assert run.returncode == 0, run.stderr
        assert cli["run"]["speed_hz"] * 60 == pytest.approx(2000.0)
        assert [b["name"] for b in cli["branches"]] == ["from run (down)", "from run (up)"]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        result = feran.orbits(feran.read_model(path), **keywords)
    same(json.loads(result.to_json()), cli)


# The study door: every quantity kind of a design study on every family, one design
# each (its analyses on coarse grids: 9 speeds, 20 ms of run-up). A kind either gives a
# finite number, the same through the command line's evaluations.jsonl and Python's
# feran.read_study(...).run() to the last bit, or the design is refused for that
# quantity with one of the reasons below (the study records the message, and the
# quantity leaves the cell's study). The kinds are read from the study reader's own
# list, so a new kind joins the matrix without editing this test; 'function' takes a
# Python function and is tested in test_study.py.
STUDY_REFUSALS = REFUSALS + [
    r"no \w+ (forward |backward )?critical speed",   # none in the analysed range
    r"no \w+ resonance peak",                         # a response without a resolved peak
    r"no \w+ (forward |backward )?lateral mode",
    r"the response has no probe|no such probe",
    r"unstable without|already unstable|log decrement .* negative",  # level I: unstable without Q
    r"no Q₀: .* is stable up to",                     # level I: no cross-coupling destabilises it
    r"no spring|has no spring",
    r"the model has no unbalance|no \[\[unbalances\]\]",
    r"the model has no journal or rolling bearing",
    r"the rotor does not stay at its static equilibrium",  # a static quantity of an unstable equilibrium
    r"the rotor is unstable at .* where the response is no steady state",  # a response quantity there
    r"no stable self-excited orbit in the range|no jump in the range",  # jump_down_speed without one
    r"no steady state in the range is stable",       # largest_stable_orbit
    r"failed",                                        # an analysis that did not converge, named
]


def quantity_kinds():
    """The kinds the study reader lists for a kind it does not know."""
    study = (f'model = "{JOURNAL}"\n[[variables]]\nname = "v"\npath = "materials[0].rho"\nlower = 1\nupper = 2\n'
             '[[quantities]]\nname = "q"\nkind = "?"\n')
    import tempfile
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "s.toml"), "w") as f:
            f.write(study)
        text = subprocess.run([FERAN, "study", os.path.join(d, "s.toml"), "-q"], capture_output=True, text=True).stderr
    kinds = re.findall(r"'(\w+)'", text.split("the kinds are", 1)[1])
    assert "critical_speed" in kinds, text
    return [k for k in kinds if k != "function"]


KINDS = quantity_kinds()


def quantity_toml(kind, low, high, rho, bearing_value):
    operating = f'operating = ["{low}", "{high}"]'
    keys = {"separation_margin": operating, "required_margin": operating, "margin_surplus": operating,
            "min_margin_surplus": operating, "undamped_critical_speed": operating,
            "level1_q_zero": f'speed = "{high}"',
            "parameter": f'path = "{rho}"'}
    if kind.endswith("bearing_value"):  # min_/max_bearing_value, min_/max_static_bearing_value
        keys[kind] = f'value = "{bearing_value}"'
    return f'[[quantities]]\nname = "{kind}"\nkind = "{kind}"\n{keys.get(kind, "")}\n'


@pytest.mark.parametrize("family", FAMILIES, ids=[f[0] for f in FAMILIES])
def test_study_quantities(tmp_path, family):
    path = model_path(tmp_path, family)
    model = feran.read_model(path)
    densities = [p["path"] for p in model.params() if re.fullmatch(r"materials\[[^\]]+\]\.rho", p["path"])]
    if not densities:
        pytest.skip("no material: nothing for the design variable to set")
    rho = densities[0]
    api = model.to_toml()
    m = re.search(r'min_speed = "([^"]+)"[\s\S]*?max_speed = "([^"]+)"', api.split("[api684]", 1)[1]) \
        if "[api684]" in api else None
    low, high = (m.group(1), m.group(2)) if m else ("1000 rpm", "2000 rpm")
    kinds, refused_kinds = list(KINDS), {}
    # A quantity every bearing of the family has: rolling bearings have no film.
    bearing_value = "max_element_load_n" if "[[rolling_bearings]]" in api and "[[journal_bearings]]" not in api \
        else "eccentricity_ratio"
    while kinds:
        study = (f'model = "{path}"\n[settings]\n"campbell.points" = 9\n"response.points" = 9\n'
                 f'[[variables]]\nname = "rho"\npath = "{rho}"\nlower = "7800 kg/m^3"\nupper = "7900 kg/m^3"\n'
                 + "".join(quantity_toml(k, low, high, rho, bearing_value) for k in kinds)
                 + '[explore]\nmethod = "grid"\nlevels = 1\n')
        if "jump_down_speed" in kinds or "largest_stable_orbit" in kinds:  # a coarse branch (ANALYSES)
            study = study.replace('"response.points" = 9\n', '"response.points" = 9\n"orbits.from" = "1000 rpm"\n'
                                  '"orbits.to" = "3000 rpm"\n"orbits.harmonics" = 2\n"orbits.points" = 12\n')
        if "runup_peak" in kinds or "runup_spring_force" in kinds:
            study = study.replace('"response.points" = 9\n', '"response.points" = 9\n"runup.duration" = "0.02 s"\n')
        file = tmp_path / "s.toml"
        file.write_text(study)
        out = tmp_path / "out"
        run = subprocess.run([FERAN, "study", str(file), "-o", str(out), "-q", "--threads", "1"],
                             capture_output=True, text=True)
        if run.returncode != 0 and "runup.duration" in run.stderr:
            # A model without a run-up profile: the run-up quantities are refused.
            for k in ("runup_peak", "runup_spring_force"):
                if k in kinds:
                    kinds.remove(k)
                    refused_kinds[k] = run.stderr
            continue
        assert run.returncode == 0, run.stderr
        with open(out / "evaluations.jsonl") as f:
            (e,) = [json.loads(line) for line in f]
        if e["evaluated"]:
            break
        failed = re.match(r"quantity '(\w+)': (.*)", e["message"], re.S)
        assert failed, e["message"]
        kind, why = failed.group(1), failed.group(2)
        assert any(re.search(r, why) for r in STUDY_REFUSALS), f"{kind}: {why}"
        kinds.remove(kind)
        refused_kinds[kind] = why
        import shutil
        shutil.rmtree(out)
    if not kinds:
        return
    finite_numbers(e["quantities"])
    assert set(e["quantities"]) == set(kinds)
    # The Python door: the same study, the same numbers to the last bit.
    result = feran.read_study(str(file)).run(threads=1)
    assert [float(q) for q in result.quantities[0]] == [e["quantities"][k] for k in kinds]
    assert result.clipped == [e["clipped"]]
