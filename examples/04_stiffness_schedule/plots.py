"""Figures of the schedule study: the Pareto front, parallel coordinates and the
largest deflection over the switching frequency and the remaining fraction.

    feran study schedule.study.toml -o out/schedule        # about 100 s on two cores
    PYTHONPATH=build/python python3 examples/04_stiffness_schedule/plots.py out/schedule

Reading the evaluations back is resuming the finished study: nothing is computed
again (a study not yet finished is completed first).
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")

import feran  # noqa: E402
import feran.plot  # noqa: E402

directory = sys.argv[1] if len(sys.argv) > 1 else "out/schedule"
here = os.path.dirname(os.path.abspath(__file__))
result = feran.read_study(os.path.join(here, "schedule.study.toml")).run(directory, resume=True)
print(f"{len(result)} designs ({result.resumed} read back), Pareto set of {len(result.pareto)}")
for name, fig in (("pareto_front", feran.plot.pareto_front(result)),
                  ("parallel_coordinates", feran.plot.parallel_coordinates(result)),
                  ("deflection_surface", feran.plot.response_surface(result, "f_as", "remaining", "deflection"))):
    path = os.path.join(directory, f"{name}.png")
    fig.savefig(path, dpi=90, bbox_inches="tight")
    print(path)
