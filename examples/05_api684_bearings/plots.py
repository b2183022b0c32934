"""Maps of the bearing study: the smallest API 617 margin surplus and the vibration in
the operating range over bearing stiffness and inboard length, with the best design.

    feran study bearings.study.toml -o out/bearings          # about a minute
    PYTHONPATH=build/python python3 examples/05_api684_bearings/plots.py out/bearings

Reading the evaluations back is resuming the finished study: nothing is computed again.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")

import feran  # noqa: E402
import feran.plot  # noqa: E402

directory = sys.argv[1] if len(sys.argv) > 1 else "out/bearings"
here = os.path.dirname(os.path.abspath(__file__))
result = feran.read_study(os.path.join(here, "bearings.study.toml")).run(directory, resume=True)
print(f"{len(result)} designs ({result.resumed} read back), {int(result.feasible.sum())} pass")
for name, quantity in (("surplus_map", "least surplus, impeller 1"), ("vibration_map", "vibration")):
    fig = feran.plot.response_surface(result, "k", "inboard length", quantity)
    path = os.path.join(directory, f"{name}.png")
    fig.savefig(path, dpi=90, bbox_inches="tight")
    print(path)
