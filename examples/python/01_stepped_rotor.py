"""A stepped rotor built in Python: Campbell diagram, critical speeds, mode shapes.

The first Python tutorial of feran. It builds a steel rotor of five sections
(journals, shoulders and a thick middle) carrying two disks, on two bearings at its
ends, entirely in code; computes its Campbell diagram, lists the forward critical
speeds, draws the rotor, the diagram and the first mode shapes; and holds the
element model against the exact solution of the stepped beam. Run it with Debian's
python3 after `bash scripts/demo.sh` (which installs the package), or from the build
tree with PYTHONPATH=build/python:

    python3 examples/python/01_stepped_rotor.py [OUTPUT_DIRECTORY]

The check: at rest, with Euler–Bernoulli sections without rotary inertia, the
bending frequencies of the stepped beam with point masses, point tilt inertias and
point springs are the roots of a 2 × 2 determinant built from the exact solution of
E I w'''' = ρ A ω² w in each section (transfer matrices, Pestel & Leckie 1963). The
element model (cubic Hermite elements, error ∝ h⁴) must agree to 1e-6.
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

# --- The model, table by table as a model file has them (docs/model-format.md) ---
E, nu, rho = 211e9, 0.3, 7810.0
sections = [  # (length, outer diameter, end node), in m, from the left bearing
    (0.10, 0.040, "shoulder left"),
    (0.20, 0.060, "disk 1"),
    (0.30, 0.080, "disk 2"),
    (0.20, 0.060, "shoulder right"),
    (0.10, 0.040, "bearing right"),
]
k_bearing = 2e7  # N/m, each bearing, both directions
model = feran.Model("Stepped rotor, built in Python")
model.add_material(name="steel", E=E, nu=nu, rho=rho)
model.add_shaft(name="rotor", material="steel", start_node="bearing left",
                sections=[dict(length=length, outer_diameter=d, end_node=end, elements=8)
                          for length, d, end in sections])
model.add_rigid_body(name="impeller 1", node="disk 1", outer_diameter="300 mm", width="30 mm",
                     material="steel")
model.add_rigid_body(name="impeller 2", node="disk 2", outer_diameter="250 mm", width="40 mm",
                     material="steel")
for side in ("left", "right"):
    model.add_spring(name=f"bearing {side}", node=f"bearing {side}", ky=k_bearing, kz=k_bearing,
                     cy="500 N*s/m", cz="500 N*s/m")
model.add_fixed(node="bearing left", dofs=["u", "rx"])  # no axial or torsional rigid motion
model.set_table("campbell", stop="20000 rpm", points=101, modes=8)

geometry = model.geometry()
print(f"{model.n_dofs} DOFs; rigid bodies {list(geometry['body_names'])}, "
      f"masses {np.round(geometry['body_mass'], 3)} kg")

# --- The Campbell diagram and its forward critical speeds (synchronous, order 1) ---
campbell = feran.campbell(model)
forward = campbell.critical_speeds(whirl="forward", order=1, unit="rpm")
backward = campbell.critical_speeds(whirl="backward", order=1, unit="rpm")
print("forward critical speeds below 20000 rpm: " + ", ".join(f"{s:.0f} rpm" for s in forward))
print("backward critical speeds: " + ", ".join(f"{s:.0f} rpm" for s in backward))
assert len(forward) >= 2
# Gyroscopic stiffening: each forward critical lies above the backward one of its mode.
assert all(f > b for f, b in zip(forward, backward))

# --- Mode shapes at the first forward critical speed ---
modes = feran.modal(model, speed=f"{forward[0]} rpm", modes=8, shapes=True)
lateral = [i for i, t in enumerate(modes.type) if t == "lateral"]
first_forward = next(i for i in lateral if modes.whirl[i] == "forward")
print(f"at {forward[0]:.0f} rpm the first forward mode has {modes.frequency_hz[first_forward]:.2f} Hz, "
      f"damping ratio {modes.damping_ratio[first_forward]:.4f}")
# At its own critical speed the mode's frequency equals the speed (order 1), to the
# root finder's tolerance.
assert abs(modes.frequency_hz[first_forward] * 60 / forward[0] - 1) < 1e-6

feran.plot.rotor(model).savefig(os.path.join(out, "stepped_rotor.png"), dpi=90)
feran.plot.campbell(campbell, unit="rpm").savefig(os.path.join(out, "stepped_campbell.png"), dpi=90)
feran.plot.mode_shape(modes, first_forward).savefig(os.path.join(out, "stepped_mode_1.png"), dpi=90)
feran.plot.mode_shape_3d(modes, first_forward).savefig(os.path.join(out, "stepped_mode_1_3d.png"), dpi=90)


# --- The check against the exact solution of the stepped beam (at rest) ---
def at_rest_frequencies(elements):
    """The first three bending frequencies at rest, Euler–Bernoulli, no rotary inertia."""
    check = model.copy()
    check.set_table("options", shear_deformation=False, rotary_inertia=False)
    for side in ("left", "right"):  # undamped, as the exact solution
        check[f"springs[bearing {side}].cy"] = 0
        check[f"springs[bearing {side}].cz"] = 0
    for i in range(len(sections)):
        check[f"shafts[rotor].sections[{i}].elements"] = elements
    at_rest = feran.modal(check, speed=0, modes=12)
    # Each bending frequency comes twice (v and w); keep one of each pair.
    lateral = np.sort(at_rest.frequency_hz[np.asarray(at_rest.type) == "lateral"])
    return lateral[::2][:3]


def exact_determinant(omega):
    """The free-end conditions at the right end for the two free starting values (w, w')
    at the left end; zero at a natural frequency."""
    disks = {"disk 1": (0.300, 0.030), "disk 2": (0.250, 0.040)}

    def point(state, mass=0.0, Ja=0.0, k=0.0):
        w, slope, moment, shear = state  # w, w', E I w'', E I w'''
        return np.array([w, slope, moment - Ja * omega**2 * slope, shear + (mass * omega**2 - k) * w])

    def field(state, length, d):
        EI, rhoA = E * math.pi * d**4 / 64, rho * math.pi * d**2 / 4
        beta = (rhoA * omega**2 / EI) ** 0.25
        A = np.zeros((4, 4))
        A[0, 1] = A[1, 2] = A[2, 3] = 1.0
        A[3, 0] = beta**4
        lam, V = np.linalg.eig(A * length)
        expm = (V @ np.diag(np.exp(lam)) @ np.linalg.inv(V)).real
        scale = np.diag([1.0, 1.0, EI, EI])
        return scale @ expm @ np.linalg.inv(scale) @ state

    columns = []
    for start in (np.array([1.0, 0.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0, 0.0])):
        s = point(start, k=k_bearing)
        for length, d, end in sections:
            s = field(s, length, d)
            if end in disks:
                D, width = disks[end]
                m = rho * math.pi * D**2 / 4 * width
                s = point(s, mass=m, Ja=m * D**2 / 16 + m * width**2 / 12)
        s = point(s, k=k_bearing)
        columns.append(s[2:])
    return np.linalg.det(np.array(columns).T)


def exact_frequencies(count, f_max=2000.0):
    grid = np.linspace(1.0, f_max, 4000) * 2 * math.pi
    values = [exact_determinant(w) for w in grid]
    roots = []
    for a, b, fa, fb in zip(grid[:-1], grid[1:], values[:-1], values[1:]):
        if fa * fb < 0:
            for _ in range(80):  # bisection to machine precision
                mid = 0.5 * (a + b)
                fm = exact_determinant(mid)
                a, b, fa = (a, mid, fa) if fa * fm <= 0 else (mid, b, fm)
            roots.append(0.5 * (a + b) / (2 * math.pi))
        if len(roots) == count:
            break
    return roots


exact = np.array(exact_frequencies(3))
coarse, fine = at_rest_frequencies(4), at_rest_frequencies(8)
print("at rest, Euler–Bernoulli: " + ", ".join(f"{c:.4f} Hz (exact {e:.4f})" for c, e in zip(fine, exact)))
error_coarse, error_fine = np.abs(coarse / exact - 1), np.abs(fine / exact - 1)
rate = np.log2(error_coarse / error_fine)
print(f"relative errors with 4 and 8 elements per section: {np.array2string(error_coarse, precision=1)}, "
      f"{np.array2string(error_fine, precision=1)}; convergence rate {np.array2string(rate, precision=2)}")
# Cubic Hermite elements: frequencies converge as h⁴ (Strang & Fix 1973); with eight
# elements per section every one of the three is within 1e-6 of the exact value.
assert np.all(error_fine < 1e-6), (fine, exact)
assert np.all((rate > 3.7) & (rate < 4.3)), rate
print(f"written: {out}/stepped_rotor.png, stepped_campbell.png, stepped_mode_1.png, stepped_mode_1_3d.png")
