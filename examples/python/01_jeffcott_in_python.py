"""A rotor built in Python: the first Python tutorial of feran.

It builds the Jeffcott rotor in code (a disk of mass m at the middle of a massless
clamped–clamped shaft), computes its Campbell diagram and finds the first forward
critical speed, checks it against the closed form, changes a design parameter by
its path and draws the diagram and the unbalance response. Run it with Debian's
python3 after `bash scripts/demo.sh` (which installs the package), or from the
build tree with PYTHONPATH=build/python:

    python3 examples/python/01_jeffcott_in_python.py [OUTPUT_DIRECTORY]

At mid-span the disk's translation and tilt decouple, so the first forward critical
speed is exactly sqrt(k/m) undamped, with the shaft's stiffness k = 192 E I / L^3
(Euler–Bernoulli), whatever the disk's polar inertia.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # draw to files; remove to see the figures on screen

import feran  # noqa: E402
import feran.plot  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out, exist_ok=True)

# The model, table by table as a model file has them (docs/model-format.md): values
# are numbers in SI units or text with a unit.
E, d, L, m = 210e9, 0.012, 0.5, 5.0
model = feran.Model("Jeffcott rotor, built in Python")
model.set_table("options", shear_deformation=False)  # Euler–Bernoulli, as the closed form
model.add_material(name="massless steel", E=E, nu=0.3, rho=0.0)
model.add_shaft(name="shaft", material="massless steel", start_node="left",
                sections=[dict(length=L / 2, outer_diameter=d, end_node="disk"),
                          dict(length=L / 2, outer_diameter=d, end_node="right")])
model.add_rigid_body(name="disk", node="disk", mass=m, Ja=0.02, Jp=0.04)
model.add_spring(name="damper", node="disk", cy="20 N*s/m", cz="20 N*s/m")
model.add_fixed(node="left").add_fixed(node="right")
model.add_unbalance(name="unbalance", node="disk", mass="1 g", radius="10 mm")

# The Campbell diagram and its first forward critical speed (order 1).
campbell = feran.campbell(model, stop="80 Hz", points=81)
first = campbell.critical_speeds(whirl="forward", order=1)[0]
k = 192 * E * (math.pi * d**4 / 64) / L**3
# The damper (c = 20 N s/m) makes the crossing the damped natural frequency
# omega_n sqrt(1 - zeta^2), zeta = c / (2 sqrt(k m)): 3e-5 below sqrt(k/m).
zeta = 20.0 / (2 * math.sqrt(k * m))
expected = math.sqrt(k / m) * math.sqrt(1 - zeta**2)
print(f"first forward critical speed: {first / (2 * math.pi):.4f} Hz "
      f"(closed form {expected / (2 * math.pi):.4f} Hz)")
# The crossing is found by root finding on the tracked curve (tolerance 1e-8 rad/s);
# the shaft is meshed exactly (one element per half): the two agree to 1e-6.
assert abs(first / expected - 1) < 1e-6, (first, expected)

# A design change by its path: twice the disk's mass lowers the critical speed by
# sqrt(2), and the damping ratio by sqrt(2) too.
heavier = model.copy()
heavier["rigid_bodies[disk].mass"] = 2 * m
first_heavier = feran.campbell(heavier, stop="80 Hz", points=81).critical_speeds(whirl="forward", order=1)[0]
ratio = math.sqrt(2) * math.sqrt(1 - zeta**2) / math.sqrt(1 - zeta**2 / 2)
assert abs(first / first_heavier / ratio - 1) < 1e-6
print(f"with twice the mass: {first_heavier / (2 * math.pi):.4f} Hz")

# The unbalance response at the disk peaks at the critical speed.
response = feran.response(model, stop="80 Hz", points=801, probe="disk")
peak = response.speeds[response.orbit_major[0].argmax()]
assert abs(peak / first - 1) < 0.01  # to the sweep's spacing of 0.1 Hz and the damping's shift
feran.plot.campbell(campbell).savefig(os.path.join(out, "jeffcott_campbell.png"), dpi=100)
feran.plot.bode(response, "disk", criticals=[first]).savefig(os.path.join(out, "jeffcott_bode.png"), dpi=100)
print(f"written: {out}/jeffcott_campbell.png, {out}/jeffcott_bode.png")
