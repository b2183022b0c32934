"""Draws one picture of every figure of feran.plot from the shipped examples: the
gallery of docs/python.md (docs/figures/python/).

Usage: PYTHONPATH=build/python python3 scripts/python_figures.py [OUT_DIR]
(default docs/figures/python; after `cmake --install` no PYTHONPATH is needed).
The test suite runs it into the build tree, so that every figure keeps drawing.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")

import feran  # noqa: E402
import feran.plot  # noqa: E402

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "docs", "figures", "python")
os.makedirs(out, exist_ok=True)
internal = feran.read_model(os.path.join(root, "examples", "01_internal_damping", "model.toml"))
centrifuge = feran.read_model(os.path.join(root, "examples", "02_centrifuge", "model.toml"))


def save(fig, name):
    path = os.path.join(out, f"{name}.png")
    fig.savefig(path, dpi=72, bbox_inches="tight")
    matplotlib.pyplot.close(fig)
    print(path)


save(feran.plot.rotor(centrifuge), "rotor")
save(feran.plot.campbell(feran.campbell(internal, stop="80 Hz", points=161, orders=[1, 2])), "campbell")
save(feran.plot.campbell(feran.campbell(centrifuge, stop="12000 rpm", points=101), unit="rpm",
                         colour="log_decrement", fmax=15000), "campbell_rpm_log_decrement")
modes = feran.modal(internal, speed="30 Hz", shapes=True)
save(feran.plot.mode_shape(modes, 2), "mode_shape")
save(feran.plot.mode_shape_3d(modes, 2), "mode_shape_3d")
nodes = internal.geometry()["nodes"]
response = feran.response(internal, stop="60 Hz", points=241, probe=nodes)
criticals = feran.campbell(internal, stop="60 Hz", points=61).critical_speeds(whirl="forward", order=1)
save(feran.plot.bode(response, "rotor", criticals=criticals), "bode")
save(feran.plot.polar(response, "rotor"), "polar")
save(feran.plot.orbit(response, "rotor", "30 Hz"), "orbit")
save(feran.plot.deflected_shape(response, speed="30 Hz"), "deflected_shape_response")
save(feran.plot.deflected_shape(feran.static(internal, gravity="-z")), "deflected_shape_static")
save(feran.plot.forces(feran.response(centrifuge, stop="60 Hz", points=241)), "forces")
runup = feran.runup(centrifuge, probe="rotor")
save(feran.plot.runup_envelope(runup), "runup_envelope")
save(feran.plot.waterfall(runup, probe="rotor", fmax=150), "waterfall")

# A design study of Friswell et al.'s Example 5.9.1 rotor: bearing span and stiffness
# against the separation margin of its critical speeds from 2900-3300 rpm.
friswell = feran.read_model(os.path.join(root, "tests", "models", "studies", "friswell_5_9_1.toml"))
stiffness = ["springs[bearing 1].ky", "springs[bearing 1].kz", "springs[bearing 2].ky", "springs[bearing 2].kz"]
study = feran.Study(friswell, variables=[
    {"name": "span", "path": "shafts[shaft].sections[2].length", "lower": "0.2 m", "upper": "0.4 m"},
    {"name": "k", "paths": stiffness, "lower": "10 MN/m", "upper": "100 MN/m", "scale": "log"}],
    quantities=[{"name": "margin", "kind": "separation_margin", "operating": ["2900 rpm", "3300 rpm"]},
                {"name": "first critical", "kind": "critical_speed", "unit": "rpm"},
                {"name": "stiffness", "function": lambda m: m["springs[bearing 1].ky"]}],
    objectives=[{"quantity": "margin", "sense": "maximise"}, {"quantity": "stiffness", "sense": "minimise"}],
    explore={"method": "sobol", "samples": 128})
designs = study.run()
save(feran.plot.pareto_front(designs), "study_pareto_front")
save(feran.plot.parallel_coordinates(designs), "study_parallel_coordinates")
save(feran.plot.response_surface(designs, "span", "k", "margin"), "study_response_surface")
