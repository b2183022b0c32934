#!/usr/bin/env bash
# Sets up, builds, and runs feran's main job on a shipped example: the Campbell
# diagram of the paper's internal-damping rotor (examples/01_internal_damping),
# printed and written to out/ as JSON, CSV and a PNG figure. Then regenerates every
# figure of the paper into out/figures/ (scripts/figures.sh; docs/validation.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh feran_cli >/dev/null
mkdir -p out
./build/feran campbell examples/01_internal_damping/model.toml \
  --json out/campbell.json --csv out/campbell.csv
/usr/bin/python3 scripts/plot_campbell.py out/campbell.json out/campbell.png
echo
echo "Written: out/campbell.json, out/campbell.csv, out/campbell.png"
echo
echo "Regenerating the paper's figures (Figs. 1, 4-10) ..."
FERAN=./build/feran bash scripts/figures.sh out/figures
echo "Written: out/figures/fig01.png ... fig10.png (and .svg), their data in out/figures/data/"
