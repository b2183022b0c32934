#!/usr/bin/env bash
# Builds the fuzzing harnesses of tests/fuzz with clang-14 (libFuzzer, AddressSanitizer,
# UndefinedBehaviorSanitizer) in build-fuzz/ and runs each for SECONDS (default 60),
# seeded from every example, every test model and the regression inputs, with the
# model-format dictionary. Prints the executions and coverage features of each; exits
# non-zero when a harness finds a crash, a leak, a hang or undefined behaviour (the
# input is saved as BUILD/findings/HARNESS-*). docs/fuzzing.md says more.
#   bash scripts/fuzz.sh                       # a minute each in build-fuzz/ (optimised, -O1)
#   bash scripts/fuzz.sh 14400                 # four hours each
#   bash scripts/fuzz.sh 60 build-sanitize     # in a tree configured with -DFERAN_FUZZ=ON
#                                              # already (the test suite's sanitizer pass)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/compiler_cache.sh
seconds=${1:-60}
build=${2:-build-fuzz}
jobs=$(nproc 2>/dev/null || echo 2)
if [ $# -lt 2 ]; then
  CC=clang-14 CXX=clang++-14 cmake -S . -B build-fuzz -DFERAN_FUZZ=ON -DFERAN_BUILD_TESTS=OFF \
    -DFERAN_BUILD_PYTHON=OFF -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1 -gline-tables-only" "${feran_launcher[@]}" >/dev/null
elif ! grep -q '^FERAN_FUZZ:BOOL=ON' "$build/CMakeCache.txt" 2>/dev/null; then
  echo "fuzz.sh: $build is not a tree configured with -DFERAN_FUZZ=ON (clang-14)" >&2
  exit 2
fi
cmake --build "$build" -j "$jobs" --target fuzz_reader fuzz_model >/dev/null  # the harnesses only

seeds=$build/seeds
rm -rf "$seeds" && mkdir -p "$seeds" "$build/findings"
n=0
while IFS= read -r -d '' f; do
  n=$((n + 1))
  cp "$f" "$seeds/seed-$n"
done < <(find examples tests/models tests/fuzz/regressions -type f \( -name '*.toml' -o -path '*/regressions/*' \) -print0)

status=0
for harness in fuzz_reader fuzz_model; do
  corpus=$build/corpus/$harness
  mkdir -p "$corpus"
  log=$build/$harness.log
  set +e
  "$build/tests/fuzz/$harness" -max_total_time="$seconds" -dict=tests/fuzz/model.dict -max_len=65536 \
    -timeout=60 -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix="$build/findings/$harness-" \
    "$corpus" "$seeds" >"$log" 2>&1
  code=$?
  set -e
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || true)
  features=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || true)
  coverage=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || true)
  echo "fuzz: $harness: ${execs:-?} executions in ${seconds} s, ${coverage:-?} edges, ${features:-?} features, corpus $(ls "$corpus" | wc -l) inputs"
  if [ "$code" -ne 0 ]; then
    echo "fuzz: $harness found a defect (exit $code); the input is in $build/findings/, the report in $log:" >&2
    grep -E 'ERROR|SUMMARY|runtime error|==[0-9]+==' "$log" | head -20 >&2 || true
    status=1
  fi
done
exit $status
