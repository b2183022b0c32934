#!/usr/bin/env python3
"""Whole-program benchmark: runs the feran command on a fixed set of models and
writes bench/results.json (case, model size, median wall time over repeated runs,
peak memory) and a scaling table with fitted exponents.

Usage: bench/run.py [--feran PATH] [--repeats N] [--out FILE] [--only SUBSTRING]
       bench/run.py --compare [--against FILE] [--from FILE] [--margin F] [--floor-ms MS]
(see bench/README.md). Needs only the Python standard library.
"""
import argparse
import json
import math
import os
import platform
import shutil
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SIZES = [6, 48, 99, 201, 501]


def model_path(n):
    return os.path.join(HERE, "models", f"friswell_5_9_1_{n}.toml")


def reduced_dofs(n):
    # 6 DOF per node, u and rx held at the first bearing.
    return 6 * (n + 1) - 2


def cases():
    """(name, group, size in elements or None, arguments, per-unit divisor, unit)."""
    # The program's start-up alone: loading it and its libraries, nothing read.
    out = [("startup_version", "startup", None, ["--version"], 1, "run")]
    for n in SIZES:
        m = model_path(n)
        out.append((f"modal_12_{n}", "modal", n, ["modal", m, "--speed", "4000rpm", "--modes", "12"], 1, "run"))
        out.append((f"campbell_20x12_{n}", "campbell20", n,
                    ["campbell", m, "--points", "20", "--modes", "12"], 1, "run"))
        out.append((f"response_100_{n}", "response", n,
                    ["response", m, "--points", "100", "--probe", "disk 2"], 100, "speed"))
        out.append((f"runup_trapezoidal_{n}", "runup", n,
                    ["runup", m, "--speed", "4000rpm", "--duration", "0.1s", "--dt", "1e-4s",
                     "--integrator", "trapezoidal", "--probe", "disk 2"], 1000, "step"))
    out.append(("campbell_100x8_6", "campbell100", 6,
                ["campbell", model_path(6), "--points", "100", "--modes", "8"], 1, "run"))
    # Speed sweeps on one core, for the parallel speed-up.
    out.append(("campbell_100x8_6_1thread", "threads", 6,
                ["campbell", model_path(6), "--points", "100", "--modes", "8", "--threads", "1"], 1, "run"))
    out.append(("campbell_20x12_501_1thread", "threads", 501,
                ["campbell", model_path(501), "--points", "20", "--modes", "12", "--threads", "1"], 1, "run"))
    out.append(("response_100_501_1thread", "threads", 501,
                ["response", model_path(501), "--points", "100", "--probe", "disk 2", "--threads", "1"],
                100, "speed"))
    # The paper's examples, with the analysis tables in their model files.
    ex = os.path.join(ROOT, "examples")
    ex1 = os.path.join(ex, "01_internal_damping", "model.toml")
    out.append(("example01_campbell", "examples", None, ["campbell", ex1], 1, "run"))
    out.append(("example01_response", "examples", None, ["response", ex1], 1, "run"))
    # The paper's Fig. 5 run-up with internal damping turns unstable near 77 Hz and
    # stops there (exit code 3, results kept): the run measured is up to that point.
    out.append(("example01_runup", "examples", None, ["runup", ex1], 1, "run"))
    ex2 = os.path.join(ex, "02_centrifuge", "model.toml")
    out.append(("example02_campbell", "examples", None, ["campbell", ex2], 1, "run"))
    out.append(("example02_runup_arctan", "examples", None,
                ["runup", os.path.join(ex, "02_centrifuge", "model_arctan.toml")], 1, "run"))
    out.append(("example03_runup_20_8N", "examples", None,
                ["runup", os.path.join(ex, "03_coulomb_friction", "model_20_8N.toml")], 1, "run"))
    # The oil-whip run-up: the nonlinear film force of two journal bearings at every
    # Newton iteration, 4 s of rotor time at 50 µs.
    out.append(("example06_runup_oil_whip", "examples", None,
                ["runup", os.path.join(ex, "06_oil_whip", "model.toml")], 1, "run"))
    # The oil-whip rotor's steady states (its [orbits] table): the equilibrium and the
    # whip branch by harmonic balance, each state with its Floquet multipliers (Hill's
    # method), over 5000–5400 rpm; the run-up above reaches one whip state in 4 s.
    out.append(("example06_orbits_whip", "examples", None,
                ["orbits", os.path.join(ex, "06_oil_whip", "model.toml")], 1, "run"))
    # The same whip found from a run (start_at): the condensed rotor run at 5380 rpm until
    # it repeats (about 5 s of rotor time, BDF2 at 64 steps a revolution), then its
    # branch down to the fold and the Hopf point.
    out.append(("example06_orbits_from_run", "examples", None,
                ["orbits", os.path.join(ex, "06_oil_whip", "model.toml"), "--start-at", "5380rpm", "--direction",
                 "down"], 1, "run"))
    # Frequency-dependent pedestal tables: each mode iterated to its own frequency,
    # against the same rotor with the pedestal built in (one eigen solve per speed).
    ex7 = os.path.join(ex, "07_pedestal")
    out.append(("example07_campbell_tables", "examples", None, ["campbell", os.path.join(ex7, "model.toml")], 1, "run"))
    out.append(("example07_campbell_built_in", "examples", None,
                ["campbell", os.path.join(ex7, "model_explicit.toml")], 1, "run"))
    # The automatic eigen-solver choice against both solvers (docs/performance.md):
    # auto should never be much slower than the faster of the two.
    pump = os.path.join(HERE, "models", "pump_130.toml")
    ex2s = os.path.join(ex, "02_centrifuge", "model_soft_mounting.toml")
    for base, argv in [("pump130_campbell", ["campbell", pump]),
                       ("pump130_modal12", ["modal", pump, "--speed", "3000rpm", "--modes", "12"]),
                       ("friswell48_campbell100x8", ["campbell", model_path(48), "--points", "100", "--modes", "8"]),
                       ("friswell6_campbell100x8", ["campbell", model_path(6), "--points", "100", "--modes", "8"]),
                       ("example01_campbell", ["campbell", ex1]),
                       ("example02_campbell", ["campbell", ex2]),
                       ("example02_soft_campbell", ["campbell", ex2s]),
                       ("example02_modal8", ["modal", ex2, "--speed", "100Hz", "--modes", "8"])]:
        for solver in ["auto", "dense", "sparse"]:
            out.append((f"choice_{base}_{solver}", "solver_choice", None, argv + ["--solver", solver], 1, "run"))
    # Design studies on one core: evaluations per second per core (per_unit: the
    # designs), and the Friswell grid on one and on two MPI processes.
    studies = os.path.join(ROOT, "tests", "models", "studies")
    scratch = os.path.join(ROOT, "build", "bench-studies")
    for name, study, designs, extra in [
            ("study_centrifuge_campbell_1thread", os.path.join(studies, "centrifuge_sobol.toml"), 64, []),
            ("study_centrifuge_runup_1thread", os.path.join(HERE, "studies", "centrifuge_runup_study.toml"), 8, []),
            ("study_friswell_grid_1thread", os.path.join(studies, "friswell_margin_grid.toml"), 1681, [])]:
        out.append((name, "study", None, ["study", study, "-o", os.path.join(scratch, name), "--threads", "1"],
                    designs, "design"))
    out.append(("study_friswell_grid_2processes", "study_mpi", None,
                ["study", os.path.join(studies, "friswell_margin_grid.toml"), "-o",
                 os.path.join(scratch, "study_friswell_grid_2processes"), "--threads", "1"], 1681, "design"))
    return out


def mpi_launcher():
    """mpirun for two processes, allowed as root and on two cores whatever their binding."""
    return ["mpirun", "--allow-run-as-root", "-np", "2", "--oversubscribe"]


def run_once(cmd, allowed_exit=(0,)):
    """Wall time [s], CPU time (user + system) [s] and peak resident memory [MiB]."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    err = proc.stderr.read().decode(errors="replace")
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    proc.stderr.close()
    code = os.waitstatus_to_exitcode(status)
    if code not in allowed_exit:
        sys.exit(f"run.py: {' '.join(cmd)} exited with {code}:\n{err}")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0  # ru_maxrss: KiB


def fit_exponent(xs, ys):
    """Least-squares slope of log y against log x."""
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    mx, my = statistics.fmean(lx), statistics.fmean(ly)
    sxx = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sxx


def compare(reference, cases, margin, floor_ms):
    """Prints each case of @p cases against the same case of @p reference (a results
    document): both medians per unit, their ratio, and a verdict — 'slower' or 'faster'
    when the ratio is beyond 1 ± margin and the whole run's time differs by more than
    floor_ms (a machine's noise on short runs), else 'same'. Returns the number of cases found slower."""
    old = {c["case"]: c for c in reference["cases"]}
    slower = 0
    print(f"against the results of {reference.get('date', '?')} ({reference.get('machine', {}).get('platform', '?')}); "
          f"verdict beyond ±{100 * margin:.0f} % and {floor_ms:g} ms")
    print(f"{'case':36s} {'before':>11s} {'now':>11s} {'ratio':>7s}  verdict")
    for c in cases:
        o = old.get(c["case"])
        if o is None:
            print(f"{c['case']:36s} {'-':>11s} {c['median_per_unit_ms']:11.3f} {'-':>7s}  new case")
            continue
        a, b = o["median_per_unit_ms"], c["median_per_unit_ms"]
        ratio = b / a if a > 0 else math.inf
        # The floor on the whole run's time, whatever the unit the case is given per.
        beyond = 1e3 * abs(c["median_s"] - o["median_s"]) > floor_ms
        verdict = "same"
        if beyond and ratio > 1 + margin:
            verdict, slower = "SLOWER", slower + 1
        elif beyond and ratio < 1 / (1 + margin):
            verdict = "faster"
        print(f"{c['case']:36s} {a:11.3f} {b:11.3f} {ratio:7.2f}  {verdict}")
    return slower


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--feran", default=os.path.join(ROOT, "build", "feran"), help="the feran program")
    ap.add_argument("--repeats", type=int, default=7, help="runs per case (median reported)")
    ap.add_argument("--out", default=None, help="results file to write (default bench/results.json; "
                    "with --compare none unless given)")
    ap.add_argument("--only", default="", help="run only cases whose name contains this (or one of these, "
                    "separated by commas)")
    ap.add_argument("--compare", action="store_true",
                    help="print each case against --against (ratio and verdict) instead of replacing it")
    ap.add_argument("--against", default=os.path.join(HERE, "results.json"), help="the results compared with")
    ap.add_argument("--from", dest="source", default=None,
                    help="with --compare: take the cases from this results file instead of running them")
    ap.add_argument("--margin", type=float, default=0.15, help="relative noise margin of a verdict (0.15)")
    ap.add_argument("--floor-ms", type=float, default=2.0, help="absolute noise floor of a verdict in ms (2)")
    args = ap.parse_args()
    wanted = [w for w in args.only.split(",") if w]

    def selected(name):
        return not wanted or any(w in name for w in wanted)

    if args.compare:
        with open(args.against) as f:
            reference = json.load(f)
        if args.source:
            with open(args.source) as f:
                cases_now = [c for c in json.load(f)["cases"] if selected(c["case"])]
            compare(reference, cases_now, args.margin, args.floor_ms)
            return
    elif args.source:
        ap.error("--from compares a results file: give --compare too")
    if args.out is None and not args.compare:
        args.out = os.path.join(HERE, "results.json")
    if not os.path.exists(model_path(SIZES[-1])):
        subprocess.run([sys.executable, os.path.join(HERE, "make_models.py")], check=True)

    results = []
    for name, group, n, argv, per, unit in cases():
        if not selected(name):
            continue
        # No output files: the analysis and the program around it are measured, not
        # the writing of results (a 501-element response's JSON is tens of MB).
        cmd = [args.feran] + argv + ([] if group == "startup" else ["--quiet"])
        if group == "study_mpi":
            if shutil.which("mpirun") is None:
                continue
            cmd = mpi_launcher() + cmd
        # A study writes a directory, which must not hold a study already.
        fresh = argv[argv.index("-o") + 1] if group.startswith("study") else None
        allowed = (0, 3) if name == "example01_runup" else (0,)

        def once():
            if fresh:
                shutil.rmtree(fresh, ignore_errors=True)
            return run_once(cmd, allowed)
        once()  # warm-up: file cache, shared libraries
        walls, cpus, mems = [], [], []
        for _ in range(args.repeats if not group.startswith("study") else min(args.repeats, 3)):
            w, c, m = once()
            walls.append(w)
            cpus.append(c)
            mems.append(m)
        med = statistics.median(walls)
        r = {
            "case": name,
            "group": group,
            "command": "feran " + " ".join(os.path.relpath(a, ROOT) if os.path.isabs(a) else a for a in argv),
            "elements": n,
            "dofs": 6 * (n + 1) if n else None,
            "reduced_dofs": reduced_dofs(n) if n else None,
            "repeats": len(walls),
            "median_s": med,
            "min_s": min(walls),
            "max_s": max(walls),
            "median_cpu_s": statistics.median(cpus),
            "per_unit": unit,
            "median_per_unit_ms": 1e3 * med / per,
            "median_cpu_per_unit_ms": 1e3 * statistics.median(cpus) / per,
            "peak_memory_mib": max(mems),
        }
        results.append(r)
        print(f"{name:32s} {1e3 * med:10.2f} ms  ({r['median_per_unit_ms']:.3f} ms/{unit}, CPU "
              f"{1e3 * r['median_cpu_s']:.1f} ms)  {r['peak_memory_mib']:7.1f} MiB", flush=True)

    # The same analyses through the Python package, timed inside one process
    # (bench/python_api.py): the cost per call of a script, against the whole CLI run.
    package = os.path.join(os.path.dirname(os.path.abspath(args.feran)), "python")
    ex = os.path.join(ROOT, "examples")
    for name, analysis, model, cli in [
            ("python_example01_campbell", "campbell", os.path.join(ex, "01_internal_damping", "model.toml"),
             "example01_campbell"),
            ("python_example01_response", "response", os.path.join(ex, "01_internal_damping", "model.toml"),
             "example01_response"),
            ("python_example02_campbell", "campbell", os.path.join(ex, "02_centrifuge", "model.toml"),
             "example02_campbell")]:
        if not selected(name) or not os.path.isdir(os.path.join(package, "feran")):
            continue
        env = dict(os.environ, PYTHONPATH=package)
        out = subprocess.run(["/usr/bin/python3", os.path.join(HERE, "python_api.py"), analysis, model,
                              str(args.repeats)], env=env, check=True, capture_output=True, text=True).stdout
        r = {"case": name, "group": "python", "command": f"feran.{analysis}(feran.read_model("
             f"\"{os.path.relpath(model, ROOT)}\"))", "cli_case": cli, "repeats": args.repeats,
             **json.loads(out), "per_unit": "run"}
        r["median_per_unit_ms"] = 1e3 * r["median_s"]
        r["median_cpu_per_unit_ms"] = 1e3 * r["median_cpu_s"]
        results.append(r)
        print(f"{name:32s} {1e3 * r['median_s']:10.2f} ms  (in one Python process, CPU "
              f"{1e3 * r['median_cpu_s']:.1f} ms)", flush=True)

    if args.compare:
        compare(reference, results, args.margin, args.floor_ms)
        if args.out is None:
            return
    if args.only and os.path.exists(args.out):
        # A partial run updates its cases in the existing results and keeps the rest.
        with open(args.out) as f:
            old = json.load(f)["cases"]
        fresh = {r["case"] for r in results}
        results = [r for r in old if r["case"] not in fresh] + results
    by_name = {r["case"]: r for r in results}
    scaling = []
    for group in ["modal", "campbell20", "response", "runup"]:
        rows = [r for r in results if r["group"] == group]
        # Fit over the models large enough that the program's start-up (~10 ms) does
        # not dominate: 99, 201 and 501 elements.
        big = [r for r in rows if r["elements"] >= 99]
        entry = {"group": group, "dofs": [r["dofs"] for r in rows],
                 "median_per_unit_ms": [r["median_per_unit_ms"] for r in rows],
                 "median_cpu_per_unit_ms": [r["median_cpu_per_unit_ms"] for r in rows],
                 "peak_memory_mib": [r["peak_memory_mib"] for r in rows]}
        if len(big) >= 2:
            entry["time_exponent"] = fit_exponent([r["dofs"] for r in big], [r["median_per_unit_ms"] for r in big])
            entry["cpu_time_exponent"] = fit_exponent([r["dofs"] for r in big],
                                                      [r["median_cpu_per_unit_ms"] for r in big])
            # Memory above the program's fixed footprint (the 6-element model's).
            base = min(r["peak_memory_mib"] for r in rows)
            extra = [(r["dofs"], r["peak_memory_mib"] - base) for r in big if r["peak_memory_mib"] - base > 0.5]
            if len(extra) >= 2:
                entry["memory_exponent"] = fit_exponent([d for d, _ in extra], [m for _, m in extra])
        scaling.append(entry)
    speedups = {}
    for single, multi in [("campbell_100x8_6_1thread", "campbell_100x8_6"),
                          ("campbell_20x12_501_1thread", "campbell_20x12_501"),
                          ("response_100_501_1thread", "response_100_501")]:
        if single in by_name and multi in by_name:
            speedups[multi] = by_name[single]["median_s"] / by_name[multi]["median_s"]

    # Studies: designs per second per core, and the parallel efficiency of two MPI
    # processes (one thread each) against one process on one thread.
    study_rates = {r["case"]: 1e3 / r["median_per_unit_ms"]
                   for r in results if r["group"] == "study"}
    mpi = {}
    one, two = by_name.get("study_friswell_grid_1thread"), by_name.get("study_friswell_grid_2processes")
    if one and two:
        mpi = {"one_process_s": one["median_s"], "two_processes_s": two["median_s"],
               "speedup": one["median_s"] / two["median_s"], "efficiency": one["median_s"] / (2 * two["median_s"])}

    python_over_cli = {r["case"]: r["median_s"] / by_name[r["cli_case"]]["median_s"]
                       for r in results if r["group"] == "python" and r["cli_case"] in by_name}

    choice = {}
    for r in results:
        if r["group"] == "solver_choice" and r["case"].endswith("_auto"):
            base = r["case"][:-len("_auto")]
            d, sp = by_name.get(base + "_dense"), by_name.get(base + "_sparse")
            if d and sp:
                best = min(d["median_s"], sp["median_s"])
                choice[base] = {"auto_s": r["median_s"], "dense_s": d["median_s"], "sparse_s": sp["median_s"],
                                "auto_over_best": r["median_s"] / best}

    doc = {
        "machine": {"cpus": os.cpu_count(), "platform": platform.platform(), "python": platform.python_version()},
        "feran": os.path.relpath(args.feran, ROOT) if os.path.abspath(args.feran).startswith(ROOT) else "feran",
        "date": time.strftime("%Y-%m-%d %H:%M:%S"),
        "cases": results,
        "scaling": scaling,
        "parallel_speedup": speedups,
        "solver_choice": choice,
        "python_over_cli": python_over_cli,
        "study_designs_per_second_per_core": study_rates,
        "study_mpi_efficiency": mpi,
    }
    with open(args.out, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    for s in scaling:
        if "time_exponent" in s:
            mem = s.get("memory_exponent")
            print(f"scaling {s['group']:10s} time ~ n^{s['time_exponent']:.2f}"
                  + (f", memory above base ~ n^{mem:.2f}" if mem is not None else ""))
    for k, v in speedups.items():
        print(f"speed-up on {os.cpu_count()} cores, {k}: {v:.2f}x")
    for k, v in choice.items():
        print(f"solver choice {k:28s} dense {1e3 * v['dense_s']:9.1f} ms  sparse {1e3 * v['sparse_s']:8.1f} ms"
              f"  auto {1e3 * v['auto_s']:8.1f} ms  auto/best {v['auto_over_best']:.2f}")


if __name__ == "__main__":
    main()
