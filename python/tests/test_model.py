"""The model and modal analysis from Python: the same results as the command line,
errors as exceptions with their location, copies that are independent."""
import copy
import json
import os
import subprocess
import sys
import threading

import numpy as np
import pytest

import feran

SOURCE = os.environ.get("FERAN_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
EXAMPLE = os.path.join(SOURCE, "examples", "01_internal_damping", "model.toml")
FERAN = os.environ.get("FERAN_PROGRAM", os.path.join(SOURCE, "build", "feran"))


def test_modal_equals_the_command_line(tmp_path):
    model = feran.read_model(EXAMPLE)
    result = feran.modal(model, speed="30 Hz")
    out = tmp_path / "modes.json"
    subprocess.run([FERAN, "modal", EXAMPLE, "--speed", "30Hz", "--json", str(out), "-q"], check=True)
    cli = json.loads(out.read_text())
    mine = result.to_dict()
    assert [m["frequency_hz"] for m in mine["modes"]] == [m["frequency_hz"] for m in cli["modes"]]
    np.testing.assert_allclose(result.frequency_hz, [m["frequency_hz"] for m in cli["modes"]], rtol=1e-12)
    assert isinstance(result.frequency_hz, np.ndarray)


def test_errors_carry_their_location(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(open(EXAMPLE).read().replace('length = "60 mm"', 'length = "-60 mm"'))
    with pytest.raises(feran.ModelError) as e:
        feran.read_model(str(bad))
    assert e.value.file == str(bad)
    assert e.value.line == 18
    assert e.value.column > 0
    assert "'length' must be positive" in e.value.message
    assert isinstance(e.value, feran.Error)


def test_parameters_by_path_and_independent_copies():
    model = feran.read_model(EXAMPLE)
    other = copy.copy(model)
    model["rigid_bodies[rotor].mass"] = "18.2 kg"
    assert model["rigid_bodies[rotor].mass"] == pytest.approx(18.2)
    assert other["rigid_bodies[rotor].mass"] == pytest.approx(9.1)
    # Twice the mass: the rotor's translational frequencies fall by about sqrt(2).

    def lowest_lateral(m):
        r = feran.modal(m)
        return min(f for f, t in zip(r.frequency_hz, r.type) if t == "lateral" and f > 0)

    assert lowest_lateral(model) < 0.9 * lowest_lateral(other)
    with pytest.raises(feran.ParameterError, match="did you mean"):
        model["rigid_bodies[rotor].mas"] = "1 kg"
    paths = [p["path"] for p in model.params()]
    assert "materials[steel].E" in paths
    # Written back, the model reads to the same parameters.
    again = feran.read_model(model.to_toml())
    assert [p["value"] for p in again.params()] == [p["value"] for p in model.params()]


def test_analyses_release_the_interpreter_while_they_compute():
    # While an analysis computes, other Python threads run. A second thread wakes
    # every millisecond and counts. With the interpreter's switch interval set to
    # 100 s, it can take the interpreter's lock only when the main thread gives it
    # up, never by forcing a switch: were the lock held through the solve, the
    # count could not change between the call's start and end, however loaded the
    # machine, so the test needs no timing.
    model = feran.read_model(EXAMPLE)
    big = feran.read_model(open(EXAMPLE).read().replace("elements = 6", "elements = 40"))
    done = threading.Event()
    count = [0]

    def tick():
        while not done.wait(0.001):
            count[0] += 1

    interval = sys.getswitchinterval()
    thread = threading.Thread(target=tick)
    sys.setswitchinterval(100.0)
    try:
        thread.start()
        before = count[0]
        for _ in range(5):
            feran.modal(big, solver="dense")
        during = count[0] - before
    finally:
        done.set()
        thread.join()
        sys.setswitchinterval(interval)
    assert during > 0
    assert model.n_dofs == 42
