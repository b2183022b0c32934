#!/usr/bin/env bash
# Sets up, builds, and runs feran's main job on a shipped example: the Campbell
# diagram of the paper's internal-damping rotor (examples/01_internal_damping),
# printed and written to out/ as JSON, CSV and a PNG figure, and its interactive
# report (out/report.html: open it in a browser, no network needed). Then regenerates every
# figure of the paper into out/figures/ (scripts/figures.sh; docs/validation.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh feran_cli feran_python >/dev/null
# Install the library, the program and the Python package under /usr/local: the
# package goes to /usr/local/lib/python3.11/dist-packages, on the path of Debian's
# python3, so that `python3 -c "import feran"` works in any new shell.
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
$sudo cmake --install build >/dev/null
mkdir -p out
./build/feran campbell examples/01_internal_damping/model.toml \
  --json out/campbell.json --csv out/campbell.csv
/usr/bin/python3 scripts/plot_campbell.py out/campbell.json out/campbell.png
(cd /tmp && /usr/bin/python3 -c "
import feran, feran.plot, matplotlib
matplotlib.use('Agg')
model = feran.read_model('$PWD/examples/01_internal_damping/model.toml')
c = feran.campbell(model)
print('python3: feran', feran.__file__.rsplit('/', 2)[0], '- forward critical speeds',
      ', '.join(f'{s:.2f} Hz' for s in c.critical_speeds(whirl='forward', order=1, unit='Hz')))
feran.plot.campbell(c).savefig('$PWD/out/campbell_python.png', dpi=120)
")
./build/feran report examples/01_internal_damping/model.toml -o out/report.html
echo
echo "Written: out/campbell.json, out/campbell.csv, out/campbell.png, out/campbell_python.png (from Python),"
echo "         out/report.html (the interactive report)"
echo
echo "Regenerating the paper's figures (Figs. 1, 4-10) ..."
FERAN=./build/feran bash scripts/figures.sh out/figures
echo "Written: out/figures/fig01.png ... fig10.png (and .svg), their data in out/figures/data/"
