#!/usr/bin/env bash
# Regenerates every figure of the paper (Fischer & Strackeljan 2006, Figs. 1 and 4-10)
# from the shipped examples: sets up, builds feran, runs the Campbell diagrams,
# steady-state responses and run-ups behind each figure into out/figures/data/ (JSON
# and CSV as feran writes them) and draws out/figures/figN.png and .svg with
# scripts/paper_figures.py. docs/validation.md compares them with the paper.
#
# Usage: figures.sh [OUT_DIR]          (default out/figures)
# FERAN=path/to/feran figures.sh       uses that program and skips set-up and build.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/figures}
data=$out/data
if [ -z "${FERAN:-}" ]; then
  bash scripts/setup.sh
  bash scripts/build.sh feran_cli >/dev/null
  FERAN=./build/feran
fi
mkdir -p "$data"

ex=examples
id=$ex/01_internal_damping
cf=$ex/02_centrifuge
co=$ex/03_coulomb_friction

# feran SUBCOMMAND MODEL NAME [OPTIONS...]: writes $data/NAME.json and .csv.
run() {
  local sub=$1 model=$2 name=$3
  shift 3
  echo "feran $sub $model $*"
  "$FERAN" "$sub" "$model" --quiet --json "$data/$name.json" --csv "$data/$name.csv" "$@"
}

# Campbell diagrams (0.5 Hz grid).
run campbell $cf/model.toml              fig01_campbell                                        # Fig. 1, 0-200 Hz
run campbell $id/model.toml              fig04_campbell_with                                   # Fig. 4, 0-80 Hz
run campbell $id/model_without_internal_damping.toml fig04_campbell_without
run campbell $cf/model_step.toml         fig08_campbell_step                                   # Fig. 8, 0-60 Hz
run campbell $cf/model.toml              fig09_campbell_unchanged --stop 60Hz --points 121 --modes 4
run campbell $cf/model_arctan.toml       fig09_campbell_arctan                                 # Fig. 9 right

# Steady-state unbalance responses (the reference curves), 0.1 Hz grid.
run response $id/model.toml              fig05_steady_state --start 0Hz --stop 80Hz --points 801 --probe rotor
run response $cf/model_step.toml         fig07_steady_state --start 0.1Hz --stop 140Hz --points 1400 --probe rotor
run response $cf/model.toml              fig10_steady_state_100 --start 0.1Hz --stop 100Hz --points 1000 --probe rotor
run response $cf/model_soft_mounting.toml fig10_steady_state_10 --start 0.1Hz --stop 100Hz --points 1000 --probe rotor

# Run-ups, each with the integrator and step of its model's [runup] table.
# With internal damping the rotor turns unstable above 53.6 Hz and the run is stopped
# at the blow-up limit near 77 Hz: exit code 3, the results up to there are written.
echo "(expected: the next run stops at the blow-up limit, exit code 3)"
set +e
run runup $id/model.toml fig05_runup_with
rc=$?
set -e
[ $rc -eq 0 ] || [ $rc -eq 3 ] || exit $rc
run runup $id/model_without_internal_damping.toml fig05_runup_without
for f in 5_2N 20_8N 41_6N; do
  run runup $co/model_$f.toml fig06_runup_$f
done
run runup $cf/model_step.toml   fig07_runup_step                                              # 0-140 Hz in 14 s
run runup $cf/model.toml        fig10_runup_constant                                          # 0-100 Hz in 5 s
run runup $cf/model_arctan.toml fig10_runup_arctan

/usr/bin/python3 scripts/paper_figures.py "$data" "$out"
