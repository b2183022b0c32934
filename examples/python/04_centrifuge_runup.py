"""A run-up of the lab centrifuge from Python, with its waterfall.

The fourth Python tutorial of feran. It reads the centrifuge of Fischer &
Strackeljan (2006, section 3.1; examples/02_centrifuge), runs it up from rest to
100 Hz in 5 s through the whirl resonances of its mounting and holds it there for
4 s, integrating the equations of motion in time (trapezoidal rule, 0.1 ms steps).
It draws the envelope of the rotor's deflection against speed, its time history and
the waterfall (spectra of successive windows stacked against speed), and checks two
things that do not depend on the integration:

- once the transients of the ramp have died away at 100 Hz, the orbit of the rotor is
  the steady unbalance response at 100 Hz, computed in the frequency domain, to the
  integrator's error, which falls as Δt² (the trapezoidal rule is of second order);
- the waterfall's strongest line follows the speed (order 1): the unbalance drives
  the rotor at the rotation frequency.

    python3 examples/python/04_centrifuge_runup.py [OUTPUT_DIRECTORY]
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import feran  # noqa: E402
import feran.plot  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out, exist_ok=True)
here = os.path.dirname(os.path.abspath(__file__))
model = feran.read_model(os.path.join(here, "..", "02_centrifuge", "model.toml"))

# The critical speeds the run-up passes, from the Campbell diagram.
criticals = feran.campbell(model, stop="100 Hz", points=101).critical_speeds(whirl="forward", order=1)
print("forward critical speeds below 100 Hz: " + ", ".join(f"{s / (2 * math.pi):.2f} Hz" for s in criticals))

# The run-up: a speed table (time, speed), linear between its points.
table = [("0 s", "0 Hz"), ("5 s", "100 Hz"), ("9 s", "100 Hz")]
runup = feran.runup(model, table=table, integrator="trapezoidal", dt="0.1 ms", output_interval="0.5 ms",
                    probe="rotor")
assert runup.complete, runup.message
rotor = runup.probes.index("rotor")
print(runup.report())

# --- Check 1: the end of the hold against the steady unbalance response ---
steady = feran.response(model, start="100 Hz", stop="100 Hz", points=1, probe="rotor")
expected = steady.orbit_major[0, 0]  # the orbit is a circle here: minor = major


def held_orbit(result):
    """The mean |r| of the rotor over the last second at 100 Hz."""
    return result.magnitude[result.probes.index("rotor"), result.time > result.time[-1] - 1].mean()


finer = feran.runup(model, table=table, integrator="trapezoidal", dt="0.05 ms", output_interval="0.5 ms",
                    probe="rotor")
errors = [abs(held_orbit(r) / expected - 1) for r in (runup, finer)]
print(f"at 100 Hz: run-up orbit {held_orbit(runup) * 1e6:.3f} µm, steady response {expected * 1e6:.3f} µm; "
      f"difference {errors[0]:.1e} with 0.1 ms steps, {errors[1]:.1e} with 0.05 ms (ratio {errors[0] / errors[1]:.2f})")
# The trapezoidal rule shifts a harmonic's frequency by (ω Δt)² / 12 = 3.3e-4 at
# 0.1 ms, which above the resonances changes the amplitude by about twice that; what
# is left of the ramp's transients after 4 s is smaller still. Halving Δt must
# quarter the difference (second order).
assert errors[0] < 2e-3, errors
assert 3 < errors[0] / errors[1] < 5, errors

# --- Check 2: the waterfall's strongest line is order 1 ---
window = 0.4  # s: 2.5 Hz resolution
speeds, freqs, spectra = feran.plot.waterfall_spectra(runup, probe="rotor", window=window)
strongest = freqs[spectra.argmax(axis=1)]
running = speeds / (2 * math.pi)
# Above 30 Hz, away from the mounting's resonances: within one bin (1/window) plus
# half the speed change over a window (20 Hz/s during the ramp).
fast = running > 30
allowed = 1 / window + 0.5 * 20 * window
off = np.max(np.abs(strongest[fast] - running[fast]))
print(f"waterfall: strongest line within {off:.2f} Hz of the speed above 30 Hz (allowed {allowed:.1f} Hz)")
assert off <= allowed, (strongest[fast], running[fast])

feran.plot.runup_envelope(runup).savefig(os.path.join(out, "centrifuge_envelope.png"), dpi=90)
feran.plot.waterfall(runup, probe="rotor", window=window, fmax=150).savefig(
    os.path.join(out, "centrifuge_waterfall.png"), dpi=90)
fig, ax = plt.subplots(figsize=(8, 3.5))
ax.plot(runup.time, runup.displacement[rotor, :, 1] * 1e3, lw=0.4)
for s in criticals:
    ax.axvline(5 * s / (2 * math.pi * 100), color="r", ls=":", lw=0.8)  # when the ramp passes it
ax.set_xlabel("time [s]")
ax.set_ylabel("v at the rotor [mm]")
ax.set_title("run-up 0–100 Hz in 5 s, then 4 s at 100 Hz")
fig.tight_layout()
fig.savefig(os.path.join(out, "centrifuge_time_history.png"), dpi=90)
print(f"written: {out}/centrifuge_envelope.png, centrifuge_waterfall.png, centrifuge_time_history.png")
