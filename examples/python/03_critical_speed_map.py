"""An undamped critical speed map from Python, with the bearings' own stiffness.

The third Python tutorial of feran. A pump rotor (a uniform steel shaft on two
bearings, a disk between them and an overhung impeller) is analysed with both
bearings set to one stiffness k_b after another over four decades; for each, the
first forward critical speeds (order 1, gyroscopic terms at the synchronous speed)
come from a Campbell diagram. Drawn against k_b on log–log axes they form the
undamped critical speed map of API 684. Overlaid is the bearings' own stiffness
against speed; where it crosses a curve lies a critical speed of the rotor in those
bearings.

    python3 examples/python/03_critical_speed_map.py [OUTPUT_DIRECTORY]

Three checks, each independent of the map itself:
- soft bearings: the rotor moves as a rigid body, and its forward critical speeds
  tend to those of a rigid rotor on two springs, K q = ω² diag(M, I_d − I_p) q
  (translation and tilt about the centre of mass; I_d − I_p because the tilt whirls
  forward at the spin speed), with M, I_d and I_p summed from the cylinders here;
  the difference must shrink in proportion to k_b;
- stiff bearings: the curves tend to the critical speeds on rigid supports
  (a model with the bearings' lateral DOFs fixed), the difference shrinking as 1/k_b;
- the crossings: solving ω = ω_c(k_b(ω)) on the map must give the critical speeds
  that a Campbell diagram of the rotor with the speed-dependent bearing (a table of
  k_b over speed) finds by itself.
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

E, nu, rho = 211e9, 0.3, 7810.0
d_shaft = 0.06
layout = [  # (length, end node) of the shaft's sections, from the coupling end
    (0.10, "bearing 1"), (0.50, "disk"), (0.50, "bearing 2"), (0.15, "impeller")]
disks = {"disk": (0.30, 0.04), "impeller": (0.35, 0.05)}  # outer diameter, width [m]
top = "25000 rpm"


def pump_rotor(supports="springs", k_b=1e7):
    """The rotor on spring bearings of stiffness k_b (a number or a law), or, with
    supports="rigid", with the bearings' lateral DOFs fixed."""
    m = feran.Model(f"Pump rotor, {supports} bearings")
    m.add_material(name="steel", E=E, nu=nu, rho=rho)
    m.add_shaft(name="rotor", material="steel", start_node="coupling",
                sections=[dict(length=length, outer_diameter=d_shaft, end_node=end, elements=6)
                          for length, end in layout])
    for node, (D, width) in disks.items():
        m.add_rigid_body(name=node, node=node, outer_diameter=D, width=width, material="steel")
    for bearing in ("bearing 1", "bearing 2"):
        if supports == "rigid":
            m.add_fixed(node=bearing, dofs=["v", "w"])
        else:
            m.add_spring(name=bearing, node=bearing, ky=k_b, kz=k_b)
    m.add_fixed(node="bearing 1", dofs=["u", "rx"])
    m.set_table("campbell", stop=top, points=26, modes=10)
    return m


def forward_criticals(model, count=3):
    c = feran.campbell(model)
    return np.array(c.critical_speeds(whirl="forward", order=1))[:count]


# --- The map: both bearings by their parameter paths, four decades ---
model = pump_rotor()


def criticals_at(k_b, count=3):
    for b in ("bearing 1", "bearing 2"):
        model[f"springs[{b}].ky"] = k_b
        model[f"springs[{b}].kz"] = k_b
    return forward_criticals(model, count)


stiffness = np.logspace(5, 9, 17)  # N/m
curves = [criticals_at(k_b) for k_b in stiffness]
count = min(len(c) for c in curves)
curves = np.array([c[:count] for c in curves])  # stiffness × mode, rad/s
print(f"{count} forward critical speeds below {top} at every stiffness; at k_b = 1e5 N/m: "
      + ", ".join(f"{s * 30 / math.pi:.0f}" for s in curves[0]) + " rpm; at 1e9 N/m: "
      + ", ".join(f"{s * 30 / math.pi:.0f}" for s in curves[-1]) + " rpm")
assert count >= 2

# --- Check 1: soft bearings, the rigid rotor on two springs ---
x, mass, first_moment, Id_x, Ip = 0.0, 0.0, 0.0, 0.0, 0.0  # Id_x about x = 0
nodes_x = {"coupling": 0.0}
for length, end in layout:
    r = d_shaft / 2
    m_s = rho * math.pi * r**2 * length
    centre = x + length / 2
    mass, first_moment, Ip = mass + m_s, first_moment + m_s * centre, Ip + m_s * r**2 / 2
    Id_x += m_s * (3 * r**2 + length**2) / 12 + m_s * centre**2
    x += length
    nodes_x[end] = x
for node, (D, width) in disks.items():
    m_d = rho * math.pi * D**2 / 4 * width
    mass, first_moment, Ip = mass + m_d, first_moment + m_d * nodes_x[node], Ip + m_d * D**2 / 8
    Id_x += m_d * (D**2 / 16 + width**2 / 12) + m_d * nodes_x[node] ** 2
x_cm = first_moment / mass
Id = Id_x - mass * x_cm**2
s1, s2 = nodes_x["bearing 1"] - x_cm, nodes_x["bearing 2"] - x_cm


def rigid_rotor(k_b):
    K = k_b * np.array([[2.0, s1 + s2], [s1 + s2, s1**2 + s2**2]])
    return np.sqrt(np.sort(np.linalg.eigvals(np.diag([1 / mass, 1 / (Id - Ip)]) @ K).real))


# Well below the map: 1e3 and 1e4 N/m.
soft = [np.abs(criticals_at(k_b, 2) / rigid_rotor(k_b) - 1) for k_b in (1e3, 1e4)]
print(f"rigid rotor ({mass:.2f} kg, I_d {Id:.4f}, I_p {Ip:.4f} kg m²): differences at 1e3 N/m "
      f"{np.array2string(soft[0], precision=1)}, at 1e4 N/m {np.array2string(soft[1], precision=1)}")
# The shaft's flexibility corrects ω² by a term of order k_b / k_shaft: ten times less
# at 1e3 N/m than at 1e4 N/m (a ratio between 8 and 12 allows for the next order).
assert np.all(soft[0] < 1e-3)
assert np.all((soft[1] / soft[0] > 8) & (soft[1] / soft[0] < 12)), soft

# --- Check 2: stiff bearings, rigid supports ---
rigid = forward_criticals(pump_rotor("rigid"), count)
# Well above the map: 1e11 and 1e12 N/m.
stiff = [np.abs(criticals_at(k_b, count) / rigid - 1) for k_b in (1e12, 1e11)]
print(f"rigid supports ({', '.join(f'{s * 30 / math.pi:.0f}' for s in rigid)} rpm): differences at 1e12 N/m "
      f"{np.array2string(stiff[0], precision=1)}, at 1e11 N/m {np.array2string(stiff[1], precision=1)}")
# The bearings' compliance adds a term of order k_shaft / k_b: ten times less per decade.
assert np.all(stiff[0] < 1e-4)
assert np.all((stiff[1] / stiff[0] > 8) & (stiff[1] / stiff[0] < 12)), stiff

# --- The bearings' own stiffness against speed, and the crossings ---
table_rpm = np.array([0, 5000, 10000, 15000, 20000, 25000])
table_k = np.array([3e6, 6e6, 1.2e7, 2.5e7, 5e7, 8e7])  # N/m, e.g. an oil film stiffening with speed
table_speeds = table_rpm * math.pi / 30


def bearing_stiffness(speed):
    return np.interp(speed, table_speeds, table_k)  # the table law: piecewise linear in speed


def crossing(mode, guess):
    """The speed where the map's mode meets the bearing curve: ω = ω_c(k_b(ω)), by the
    secant method on the map's own computation (a model per trial stiffness)."""
    def residual(speed):
        return criticals_at(float(bearing_stiffness(speed)), count)[mode] - speed

    a, b = guess, 1.05 * guess
    fa, fb = residual(a), residual(b)
    for _ in range(30):
        a, b, fa = b, b - fb * (b - a) / (fb - fa), fb
        fb = residual(b)
        if abs(b - a) < 1e-9 * b:
            break
    return b


# First guesses from the map: where each curve crosses the bearing curve.
guesses = []
for mode in range(count):
    gap = np.log(stiffness) - np.log(bearing_stiffness(curves[:, mode]))
    change = np.nonzero(np.diff(np.sign(gap)))[0]
    if len(change) and curves[change[0], mode] < table_speeds[-1]:
        guesses.append((mode, curves[change[0], mode]))
on_map = np.array([crossing(mode, g) for mode, g in guesses])

variable = pump_rotor(k_b={"law": "table", "speed_unit": "rpm", "speeds": table_rpm.tolist(),
                           "values": table_k.tolist()})
campbell = feran.campbell(variable)
direct = np.array(campbell.critical_speeds(whirl="forward", order=1))
print("critical speeds in the speed-dependent bearings: on the map "
      + ", ".join(f"{s * 30 / math.pi:.2f}" for s in on_map) + " rpm; Campbell diagram "
      + ", ".join(f"{s * 30 / math.pi:.2f}" for s in direct) + " rpm")
assert len(on_map) >= 1 and len(direct) == len(on_map), (on_map, direct)
# Both are roots found to 1e-8 rad/s of the same equations; 1e-6 allows for the
# secant method's last step.
agreement = np.max(np.abs(on_map / direct - 1))
print(f"largest difference {agreement:.1e}")
assert agreement < 1e-6, (on_map, direct)

fig, ax = plt.subplots(figsize=(7, 5))
for mode in range(count):
    ax.loglog(stiffness, curves[:, mode] * 30 / math.pi, "o-", ms=3, label=f"forward critical {mode + 1}")
speeds = np.linspace(0, table_speeds[-1], 400)
ax.loglog(bearing_stiffness(speeds), speeds * 30 / math.pi, "k--", label="bearing stiffness")
ax.loglog([bearing_stiffness(s) for s in on_map], on_map * 30 / math.pi, "rs", ms=8, mfc="none",
          label="critical speeds in these bearings")
ax.set_xlabel("bearing stiffness [N/m]")
ax.set_ylabel("critical speed [rpm]")
ax.set_title("undamped critical speed map")
ax.legend(fontsize=8)
ax.grid(True, which="both", lw=0.3)
fig.savefig(os.path.join(out, "critical_speed_map.png"), dpi=90)
print(f"written: {out}/critical_speed_map.png")
