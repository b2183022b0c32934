#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite through ctest, twice:
#  1. the Release build, warnings as errors (scripts/build.sh: the configuration demo.sh
#     builds too), then the code checks of scripts/lint.sh (clang-format, clang-tidy,
#     flake8, ESLint) and the Release tests;
#  2. a build with clang-14, AddressSanitizer and UndefinedBehaviorSanitizer (without
#     its null, alignment and pointer-overflow checks: CMakeLists.txt), a Debug
#     build (no NDEBUG), so that Eigen's and feran's debug assertions and memory
#     errors are checked too, optimised only at -O1 (the level the sanitizers' own
#     documentation recommends): at -O0 Eigen's uninlined expressions made these
#     tests 3.4 times slower (491 s against 146 s on two cores) for a build 1.2 to
#     1.5 times faster. The full-length example run-ups and the long study tests
#     (the command-line studies, with and without MPI, and the Friswell study; label
#     long_runup, minutes each when instrumented) and four heavy numerical tests (listed
#     below) run in the Release pass only; the run-up code itself is covered in both. It is built without debug
#     information (-g0): the sanitizers' reports still name the functions (rebuild
#     with -DCMAKE_CXX_FLAGS_DEBUG=-g for file and line). clang compiles this
#     instrumented build in half g++'s time;
#  3. the two fuzzing harnesses (libFuzzer) for 30 s each from the seed corpus
#     (scripts/fuzz.sh, docs/fuzzing.md), linked against the same instrumented library:
#     the sanitizer build carries libFuzzer's coverage instrumentation (FERAN_FUZZ).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/compiler_cache.sh
jobs=$(nproc 2>/dev/null || echo 2)
stage() { echo "test.sh: $1 took $((SECONDS - stage_start)) s (total ${SECONDS} s)"; stage_start=$SECONDS; }
stage_start=$SECONDS
bash scripts/setup.sh
stage "set-up"
bash scripts/build.sh
stage "the Release build"
bash scripts/lint.sh build
stage "the code checks (format, clang-tidy, flake8, ESLint)"
ctest --test-dir build --output-on-failure -j "$jobs"
stage "the Release tests"
# Informative, never failing: the program's start-up and a few quick cases against the
# committed bench/results.json (bench/README.md), where a slowdown shows before anyone
# measures; a machine's noise is no test failure.
/usr/bin/python3 bench/run.py --compare --repeats 3 \
  --only startup,modal_12_6,response_100_201,runup_trapezoidal_201 || echo "test.sh: the speed check did not run"
stage "the speed check"

CC=clang-14 CXX=clang++-14 cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-g0 -O1" \
  -DFERAN_SANITIZE=ON -DFERAN_FUZZ=ON -DFERAN_LONG_TESTS=OFF -DFERAN_BUILD_PYTHON=OFF -DFERAN_BROWSER_TESTS=OFF \
  -DFERAN_WARNINGS_AS_ERRORS=ON -DFERAN_UNITY_BUILD=ON "${feran_launcher[@]}" >/dev/null
cmake --build build-sanitize -j "$jobs" >/dev/null
stage "the sanitizer build"
# Besides the long run-ups, four numerical tests of 16 to 39 s each when instrumented
# (seconds in Release, where they run) whose code the sanitizer pass runs in smaller
# tests: the pedestal example's Campbell diagram (frequency tables: a self-consistent
# solve per mode and speed), API 684's worst-peak check, the report's Trumpler verdicts
# and the run-up growth rate about the equilibrium. About 45 s of the pass.
heavy='^(example\.07_pedestal\.model\.campbell|verification\.Api684\.TheSmallestSurplusIsThatOfTheWorstPeak'
heavy+='|unit_io\.HtmlReport\.JudgesTheJournalBearingsFilmAndLoadByTrumplersLimits'
heavy+='|unit_analyses_static\.Supports\.RunupGrowthRateAboutTheEquilibriumIsTheEigenvaluesRealPart)$'
ctest --test-dir build-sanitize --output-on-failure -j "$jobs" -LE long_runup -E "$heavy"
stage "the sanitizer tests"

bash scripts/fuzz.sh 30 build-sanitize
stage "fuzzing (build and 2 x 30 s)"
