#!/usr/bin/env python3
"""Writes the benchmark models: Friswell, Penny, Garvey & Lees (2010), Example 5.9.1,
meshed with N shaft elements (N a multiple of 3, so that the disks sit on nodes).

The model is the one of tests/support/test_models.hpp (friswell_5_9_1): a steel
shaft 1.5 m long, 50 mm in diameter; disks 280 x 70 mm at 0.5 m and 350 x 70 mm at
1.0 m (bore 50 mm); isotropic bearings of 1 MN/m at both ends; axial and torsional
motion held at the first bearing. The book's model has no unbalance; for the
response and run-up cases these files add 1 g at 100 mm on the second disk.
Usage: make_models.py [OUTDIR] [N ...]
"""
import os
import sys

TEMPLATE = """\
# Friswell et al. (2010), Example 5.9.1, meshed with {n} shaft elements ({dofs} DOF).
# Written by bench/make_models.py; the model of tests/support/test_models.hpp plus an
# unbalance (1 g at 100 mm on disk 2) for the response and run-up benchmarks.
title = "Friswell Example 5.9.1, {n} elements"

[[materials]]
name = "steel"
E = "211 GPa"
G = "81.2 GPa"
rho = "7810 kg/m^3"

[[shafts]]
material = "steel"
start_node = "bearing 1"

{sections}
[[rigid_bodies]]
name = "disk 1"
node = "disk 1"
outer_diameter = "280 mm"
inner_diameter = "50 mm"
width = "70 mm"
material = "steel"

[[rigid_bodies]]
name = "disk 2"
node = "disk 2"
outer_diameter = "350 mm"
inner_diameter = "50 mm"
width = "70 mm"
material = "steel"

[[springs]]
name = "bearing 1"
node = "bearing 1"
ky = "1 MN/m"
kz = "1 MN/m"

[[springs]]
name = "bearing 2"
node = "bearing 2"
ky = "1 MN/m"
kz = "1 MN/m"

[[fixed]]
node = "bearing 1"
dofs = ["u", "rx"]

[[unbalances]]
node = "disk 2"
mass = "1 g"
radius = "100 mm"

[campbell]
start = "0 rpm"
stop = "4000 rpm"
points = 100
modes = 8

[response]
start = "0 rpm"
stop = "4000 rpm"
points = 100
probes = ["disk 2"]
"""

# The shaft in three equal sections of 500 mm, the disks at their ends.
SECTION = """\
  [[shafts.sections]]
  length = "500 mm"
  outer_diameter = "50 mm"
  elements = {elements}
  end_node = "{end}"
"""


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "models")
    sizes = [int(a) for a in sys.argv[2:]] or [6, 48, 99, 201, 501, 5001]
    os.makedirs(outdir, exist_ok=True)
    for n in sizes:
        if n % 3:
            sys.exit(f"make_models.py: {n} is not a multiple of 3")
        path = os.path.join(outdir, f"friswell_5_9_1_{n}.toml")
        with open(path, "w") as f:
            sections = "\n".join(SECTION.format(elements=n // 3, end=end)
                                 for end in ("disk 1", "disk 2", "bearing 2"))
            f.write(TEMPLATE.format(n=n, sections=sections, dofs=6 * (n + 1)))


if __name__ == "__main__":
    main()
