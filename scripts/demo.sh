#!/usr/bin/env bash
# Sets up, builds, and runs feran's main job on a shipped example: the Campbell
# diagram of the paper's internal-damping rotor (examples/01_internal_damping),
# printed and written to out/ as JSON, CSV and a PNG figure, and its interactive
# report (out/report.html: open it in a browser, no network needed). Then regenerates every
# figure of the paper into out/figures/ (scripts/figures.sh; docs/validation.md).
# Builds in ./build with the configuration of scripts/test.sh (scripts/build.sh), so
# that either run after the other compiles nothing twice. Ends by checking that every
# file it promises was written (non-zero exit otherwise).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
bash scripts/setup.sh
bash scripts/build.sh feran_cli feran_python >/dev/null
# Install the library, the program and the Python package under /usr/local: the
# package goes to /usr/local/lib/python3.11/dist-packages, on the path of Debian's
# python3, so that `python3 -c "import feran"` works in any new shell.
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
$sudo cmake --install build >/dev/null
out="$root/out"
rm -f "$out"/campbell.json "$out"/campbell.csv "$out"/campbell.png "$out"/campbell_python.png "$out"/report.html
mkdir -p "$out"
./build/feran campbell examples/01_internal_damping/model.toml \
  --json out/campbell.json --csv out/campbell.csv
/usr/bin/python3 scripts/plot_campbell.py out/campbell.json out/campbell.png
# From another folder, so that Python imports the installed package, not a source tree.
# The paths are passed as arguments, not expanded into the program's text.
(cd /tmp && /usr/bin/python3 - "$root/examples/01_internal_damping/model.toml" "$out/campbell_python.png" <<'PY'
import sys
import matplotlib
matplotlib.use("Agg")
import feran, feran.plot
model_file, figure = sys.argv[1:3]
model = feran.read_model(model_file)
c = feran.campbell(model)
print("python3: feran", feran.__file__.rsplit("/", 2)[0], "- forward critical speeds",
      ", ".join(f"{s:.2f} Hz" for s in c.critical_speeds(whirl="forward", order=1, unit="Hz")))
feran.plot.campbell(c).savefig(figure, dpi=120)
PY
)
./build/feran report examples/01_internal_damping/model.toml -o out/report.html
echo
echo "Written: out/campbell.json, out/campbell.csv, out/campbell.png, out/campbell_python.png (from Python),"
echo "         out/report.html (the interactive report)"
echo
echo "Regenerating the paper's figures (Figs. 1, 4-10) ..."
rm -rf "$out/figures"
FERAN=./build/feran bash scripts/figures.sh out/figures
echo "Written: out/figures/fig01.png ... fig10.png (and .svg), their data in out/figures/data/"

# Every promised file, present and not empty.
missing=()
for f in campbell.json campbell.csv campbell.png campbell_python.png report.html; do
  [ -s "$out/$f" ] || missing+=("out/$f")
done
for n in 01 04 05 06 07 08 09 10; do
  for ext in png svg; do
    [ -s "$out/figures/fig$n.$ext" ] || missing+=("out/figures/fig$n.$ext")
  done
done
if [ ${#missing[@]} -ne 0 ]; then
  echo "demo.sh: not written: ${missing[*]}" >&2
  exit 1
fi
echo "demo.sh: all $((5 + 16)) promised files written"
