"""The compatibility matrix: every entry family × every analysis × every door.

Families are every shipped example model and one small rotor per kind of support
(journal bearings in the short, long and finite theories, rolling bearings, a tapered
shaft under axial load), generated here from the journal-bearing rotor of the tests
(tests/models/valid/journal_rotor.toml); the examples bring frequency tables (07), a
torque drive (02, model_motor) and dry friction (03). Analyses are the command
line's: modal, campbell, response, static, runup (20 ms of the model's own run-up),
api684 (where the model gives an operating range) and report. Each cell either runs,
with every number it writes finite (or null where the output format allows it), or is
refused with one of the documented reasons below. Doors: the command line's JSON and
CSV, Python (to_dict() equals the command line's JSON to 1e-12), and the report's
embedded data (its sections equal the command line's JSON of the same analysis).

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
    if kind == "rolling":
        blocks = re.findall(r"\[\[journal_bearings\]\]\nname = \"([^\"]+)\"\nnode = \"([^\"]+)\"\n(?:[^\[\n][^\n]*\n)*", text)
        out = re.sub(r"\[\[journal_bearings\]\]\n(?:[^\[\n][^\n]*\n)*\n?", "", text)
        for name, node in blocks:
            out += (f'\n[[rolling_bearings]]\nname = "{name}"\nnode = "{node}"\nelements = 9\n'
                    'element_diameter = "12 mm"\npitch_diameter = "80 mm"\nclearance = "5 um"\n'
                    'hertz_constant = 1e10\n')
        return out
    if kind == "tapered_axial":
        return text.replace('  length = "400 mm"\n  outer_diameter = "60 mm"\n  elements = 4\n  end_node = "disk 2"',
                            '  length = "400 mm"\n  outer_diameter = "60 mm"\n  outer_diameter_end = "50 mm"\n'
                            '  axial_force = "20 kN"\n  elements = 4\n  end_node = "disk 2"')
    raise ValueError(kind)


SUPPORT_FAMILIES = ["journal_short", "journal_long", "journal_finite", "rolling", "tapered_axial"]
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
               dict(points=61, map_points=5, stability=False), False),
    "report": (None, None, False),
}

# The documented reasons a cell may be refused (docs/model-format.md, docs/output-format.md).
REFUSALS = [
    r"oil film .* at rest|carries no load at rest|needs? a speed above 0|speed 0",  # an oil film at rest
    r"operating (speed )?range|--min-speed|min_speed",  # api684 without an operating range
    r"no \[runup\]|give a speed profile|--to|--speed",   # runup without a profile
    r"the model has no \[\[unbalances\]\]|nothing excites",  # response without excitation
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
        for section in ("campbell", "response", "static", "api684"):
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
        assert len(rows) >= 2 and all(len(r) == len(rows[0]) for r in rows)
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
