#!/usr/bin/env bash
# Configures and builds feran in ./build (Release, tests included).
# Usage: build.sh [target ...]   (default: everything)
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DFERAN_UNITY_BUILD=ON -DFERAN_WARNINGS_AS_ERRORS="${FERAN_WARNINGS_AS_ERRORS:-OFF}" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j "$jobs" "${targets[@]}"
