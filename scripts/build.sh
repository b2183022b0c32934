#!/usr/bin/env bash
# Configures and builds feran in ./build (Release, tests included, warnings as errors).
# demo.sh and test.sh both build here with this one configuration, so that the second
# of them compiles nothing the first compiled.
# Usage: build.sh [target ...]   (default: everything)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/compiler_cache.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DFERAN_UNITY_BUILD=ON \
  -DFERAN_WARNINGS_AS_ERRORS="${FERAN_WARNINGS_AS_ERRORS:-ON}" "${feran_launcher[@]}" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j "$jobs" "${targets[@]}"
