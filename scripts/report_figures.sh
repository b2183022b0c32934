#!/usr/bin/env bash
# Screenshots of the examples' reports for docs/figures/ (docs/report.md): writes the
# reports of examples 01, 02, 03 and 05 (with a small design study), opens each in headless
# Chromium through the browser check (tests/browser/check_report.mjs), and keeps the
# screenshots of their main sections as docs/figures/report_<example>_<section>.png.
set -euo pipefail
cd "$(dirname "$0")/.."
FERAN=${FERAN:-./build/feran}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$FERAN" study tests/browser/bearings_small.study.toml -o "$out/study" --threads 2 >/dev/null
"$FERAN" report examples/01_internal_damping/model.toml -o "$out/01.html" -q
"$FERAN" report examples/02_centrifuge/model.toml -o "$out/02.html" -q
"$FERAN" report examples/03_coulomb_friction/model_20_8N.toml --speed-unit Hz -o "$out/03.html" -q
"$FERAN" report examples/05_api684_bearings/model.toml --config tests/browser/report.toml --study "$out/study" \
  -o "$out/05.html" -q
FERAN_SECTION_SCREENSHOTS=1 node tests/browser/check_report.mjs "$out/01.html" "$out/01" >/dev/null
FERAN_SECTION_SCREENSHOTS=1 node tests/browser/check_report.mjs "$out/05.html" "$out/05" >/dev/null
for e in 02 03; do FERAN_SECTION_SCREENSHOTS=1 node tests/browser/check_report.mjs "$out/$e.html" "$out/$e" >/dev/null; done
cp "$out/02-runup.png" docs/figures/report_02_centrifuge_runup.png
cp "$out/03-runup.png" docs/figures/report_03_coulomb_friction_runup.png
for s in campbell runup; do cp "$out/01-$s.png" "docs/figures/report_01_internal_damping_$s.png"; done
for s in model api684 study; do cp "$out/05-$s.png" "docs/figures/report_05_api684_bearings_$s.png"; done
echo "written: docs/figures/report_*.png"
