#!/usr/bin/env bash
# Configures and builds feran in ./build (Release, tests included).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DFERAN_WARNINGS_AS_ERRORS="${FERAN_WARNINGS_AS_ERRORS:-OFF}" >/dev/null
cmake --build build -j "$jobs"
