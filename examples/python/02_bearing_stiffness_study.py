"""A parameter study from Python: the critical speed against bearing stiffness.

The disk of the Jeffcott rotor now sits on a pinned shaft whose ends rest on two
bearings of stiffness kb (the second Python tutorial of feran). A loop changes kb by
its parameter path, over four decades, computes the first forward critical speed of
each design, and draws the curve that an undamped critical speed map shows: rigid
shaft on soft bearings at the left, pinned shaft on rigid bearings at the right.

    python3 examples/python/02_bearing_stiffness_study.py [OUTPUT_DIRECTORY]

The closed form to hold it against: the shaft's mid-span stiffness when pinned,
ks = 48 E I / L^3, in series with the two bearings side by side, 2 kb, so that
omega = sqrt(k / m) with 1/k = 1/ks + 1/(2 kb) (massless shaft, the disk at
mid-span, Euler–Bernoulli).
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import feran  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out, exist_ok=True)

E, d, L, m = 210e9, 0.012, 0.5, 5.0
model = feran.Model("Jeffcott rotor on two bearings")
model.set_table("options", shear_deformation=False)
model.add_material(name="massless steel", E=E, nu=0.3, rho=0.0)
model.add_shaft(name="shaft", material="massless steel", start_node="left",
                sections=[dict(length=L / 2, outer_diameter=d, end_node="disk"),
                          dict(length=L / 2, outer_diameter=d, end_node="right")])
model.add_rigid_body(name="disk", node="disk", mass=m, Ja=0.02, Jp=0.04)
# The journals need some mass for every DOF to have one; a milligram changes the
# first mode by far less than the tolerance below.
for end in ("left", "right"):
    model.add_rigid_body(name=f"journal {end}", node=end, mass=1e-6, Ja=1e-9, Jp=1e-9)
    model.add_spring(name=f"bearing {end}", node=end, ky=1e6, kz=1e6)
model.add_fixed(node="left", dofs=["u", "rx"])  # no axial or torsional rigid motion

ks = 48 * E * (math.pi * d**4 / 64) / L**3
stiffness = np.logspace(4, 8, 17)  # N/m
computed, expected = [], []
for kb in stiffness:
    for end in ("left", "right"):
        model[f"springs[bearing {end}].ky"] = kb
        model[f"springs[bearing {end}].kz"] = kb
    campbell = feran.campbell(model, stop="80 Hz", points=41, modes=4)
    computed.append(campbell.critical_speeds(whirl="forward", order=1)[0] / (2 * math.pi))
    expected.append(math.sqrt(1 / (1 / ks + 1 / (2 * kb)) / m) / (2 * math.pi))

computed, expected = np.array(computed), np.array(expected)
error = np.max(np.abs(computed / expected - 1))
print(f"first forward critical speed from {computed[0]:.3f} Hz (kb = 1e4 N/m) to {computed[-1]:.3f} Hz "
      f"(kb = 1e8 N/m); largest difference from the closed form {error:.1e}")
# The journals' milligram and their tilt inertia shift the mode by less than 1e-5.
assert error < 1e-5, error

fig, ax = plt.subplots(figsize=(6, 4))
ax.semilogx(stiffness, computed, "o", label="feran")
ax.semilogx(stiffness, expected, "-", label="closed form")
ax.set_xlabel("bearing stiffness [N/m]")
ax.set_ylabel("first forward critical speed [Hz]")
ax.legend()
fig.savefig(os.path.join(out, "bearing_stiffness_study.png"), dpi=100)
print(f"written: {out}/bearing_stiffness_study.png")
