#!/usr/bin/env python3
"""Times one analysis through the Python package, inside one process: what a script
or notebook pays per call once feran is imported and the model read. Prints one JSON
object (median/min/max wall and median CPU time over the repeats, after one warm-up
call). Run by bench/run.py with PYTHONPATH set to the build's python directory.

Usage: python_api.py ANALYSIS MODEL REPEATS   (ANALYSIS: campbell, response, runup)
"""
import json
import statistics
import sys
import time

import feran

analysis, path, repeats = sys.argv[1], sys.argv[2], int(sys.argv[3])
model = feran.read_model(path)
run = getattr(feran, analysis)
run(model)  # warm-up
walls, cpus = [], []
for _ in range(repeats):
    w, c = time.perf_counter(), time.process_time()
    run(model)
    walls.append(time.perf_counter() - w)
    cpus.append(time.process_time() - c)
print(json.dumps({"median_s": statistics.median(walls), "min_s": min(walls), "max_s": max(walls),
                  "median_cpu_s": statistics.median(cpus)}))
