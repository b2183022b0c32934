"""Unbalance response from Python: Bode and polar plots, orbits, bearing forces.

The second Python tutorial of feran. A disk sits at the middle of a steel shaft
whose ends run in two damped bearings; an unbalance on the disk drives it through
its first critical speed. The script computes the steady unbalance response at the
disk and the journals, draws the Bode and polar plots, the orbit at the peak and the
bearing forces against speed, and holds every number against the closed form.

    python3 examples/python/02_unbalance_response.py [OUTPUT_DIRECTORY]

The closed form (massless shaft, disk at mid-span, isotropic bearings, so the disk
translates without tilting and whirls in a forward circle): the shaft's mid-span
stiffness k_s = 48 E I / L^3 (pinned ends, Euler–Bernoulli) in series with the two
bearings side by side, each of impedance k_b + iΩc_b, gives the complex stiffness

    k(Ω) = 1 / (1 / k_s + 1 / (2 (k_b + iΩ c_b))),

the disk's amplitude r = m_u e Ω² / |k(Ω) − M Ω²|, the journals' r_j =
|k_s / (k_s + 2 (k_b + iΩ c_b))| r, and each bearing's force |k(Ω)| r / 2.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # draw to files; remove to see the figures on screen

import numpy as np  # noqa: E402

import feran  # noqa: E402
import feran.plot  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out, exist_ok=True)

E, d, L, M = 211e9, 0.040, 0.6, 10.0     # Pa, m, m, kg
k_b, c_b = 5e6, 2000.0                    # N/m and N s/m, each bearing
m_u, e = 0.010, 0.010                     # 10 g at 10 mm: 1e-4 kg m

model = feran.Model("Jeffcott rotor on damped bearings")
model.set_table("options", shear_deformation=False)   # Euler–Bernoulli, as the closed form
model.add_material(name="massless steel", E=E, nu=0.3, rho=0.0)
model.add_shaft(name="shaft", material="massless steel", start_node="journal left",
                sections=[dict(length=L / 2, outer_diameter=d, end_node="disk"),
                          dict(length=L / 2, outer_diameter=d, end_node="journal right")])
model.add_rigid_body(name="disk", node="disk", mass=M, Ja=0.05, Jp=0.1)
for side in ("left", "right"):
    # Every DOF needs mass: a milligram journal, too light to show in the response.
    model.add_rigid_body(name=f"journal {side}", node=f"journal {side}", mass=1e-6, Ja=1e-9, Jp=1e-9)
    model.add_spring(name=f"bearing {side}", node=f"journal {side}", ky=k_b, kz=k_b, cy=c_b, cz=c_b)
model.add_fixed(node="journal left", dofs=["u", "rx"])
model.add_unbalance(name="unbalance", node="disk", mass=m_u, radius=e)

# The first forward critical speed, from the Campbell diagram.
campbell = feran.campbell(model, stop="200 Hz", points=101, modes=6)
critical = campbell.critical_speeds(whirl="forward", order=1)
print("forward critical speeds: " + ", ".join(f"{s / (2 * math.pi):.2f} Hz" for s in critical))

# The unbalance response, at the disk and at the left journal.
response = feran.response(model, start="5 Hz", stop="200 Hz", points=391,
                          probe=["disk", "journal left"])
speeds = response.speeds
disk, journal = response.probe_index("disk"), response.probe_index("journal left")
peak = int(response.orbit_major[disk].argmax())
print(f"peak at the disk: {response.orbit_major[disk, peak] * 1e6:.1f} µm at "
      f"{speeds[peak] / (2 * math.pi):.1f} Hz; bearing force there "
      f"{response.spring_peak[0, peak]:.1f} N")

# The closed form, point by point.
k_s = 48 * E * (math.pi * d**4 / 64) / L**3
bearings = 2 * (k_b + 1j * speeds * c_b)
k = 1 / (1 / k_s + 1 / bearings)
r_disk = m_u * e * speeds**2 / np.abs(k - M * speeds**2)
r_journal = np.abs(k_s / (k_s + bearings)) * r_disk
force = np.abs(k) * r_disk / 2

errors = {
    "disk amplitude": np.max(np.abs(response.orbit_major[disk] / r_disk - 1)),
    "journal amplitude": np.max(np.abs(response.orbit_major[journal] / r_journal - 1)),
    "bearing forces": max(np.max(np.abs(response.spring_peak[i] / force - 1)) for i in (0, 1)),
    # a forward circle: the minor semi-axis equals the major one
    "circular orbit": np.max(np.abs(response.orbit_minor[disk] / response.orbit_major[disk] - 1)),
}
for what, err in errors.items():
    print(f"{what}: largest difference from the closed form {err:.1e}")
# The journals' milligram changes the response by up to m_j Ω² / k_b = 3e-7; the rest is
# rounding. 1e-6 leaves room for both.
assert all(err < 1e-6 for err in errors.values()), errors

feran.plot.bode(response, "disk", criticals=critical).savefig(os.path.join(out, "unbalance_bode.png"), dpi=90)
feran.plot.polar(response, "disk").savefig(os.path.join(out, "unbalance_polar.png"), dpi=90)
feran.plot.orbit(response, "disk", speeds[peak]).savefig(os.path.join(out, "unbalance_orbit.png"), dpi=90)
feran.plot.forces(response).savefig(os.path.join(out, "unbalance_bearing_forces.png"), dpi=90)
response.to_pandas().to_csv(os.path.join(out, "unbalance_response.csv"), index=False)
print(f"written: {out}/unbalance_bode.png, unbalance_polar.png, unbalance_orbit.png, "
      "unbalance_bearing_forces.png, unbalance_response.csv")
