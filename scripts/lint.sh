#!/usr/bin/env bash
# The checks a maintained C++ project runs on its own code, each timed, all run even
# when one fails (exit non-zero if any did):
#  1. clang-format (.clang-format): every C++ file of the repository laid out as the
#     file says; `bash scripts/lint.sh --fix-format` rewrites them so;
#  2. clang-tidy-14 (.clang-tidy: the checks chosen, every one an error) over the
#     library and the program, taken in the unity build's batches of BUILD (default
#     ./build, a tree configured by scripts/build.sh; its compile_commands.json);
#  3. flake8 (.flake8: pyflakes' errors and pycodestyle's layout) over every Python file;
#  4. ESLint (eslint.config.mjs: its recommended rules) over the JavaScript of the report
#     and of the browser tests, from the project's npm packages (scripts/setup.sh);
#  5. abilities, not casts: no Element::target<> or Force::target<> in the library, the
#     program or the Python module (docs/architecture.md); tests may inspect types.
# docs/contributing.md says what each checks and how to run one alone.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
fix=0
for arg in "$@"; do
  case $arg in
    --fix-format) fix=1 ;;
    *) build=$arg ;;
  esac
done
jobs=$(nproc 2>/dev/null || echo 2)
status=0
check() {  # check NAME COMMAND...: runs the command, prints its time and verdict
  local name=$1 start=$SECONDS
  shift
  if "$@"; then
    echo "lint: $name: clean ($((SECONDS - start)) s)"
  else
    echo "lint: $name: FAILED ($((SECONDS - start)) s)" >&2
    status=1
  fi
}

mapfile -t cxx < <(git ls-files '*.cpp' '*.hpp' '*.h')
if [ "$fix" -eq 1 ]; then
  clang-format-14 -i "${cxx[@]}"
  echo "lint: clang-format rewrote the C++ files that were not laid out as .clang-format says"
  exit 0
fi
check "clang-format, ${#cxx[@]} files" clang-format-14 --dry-run --Werror "${cxx[@]}"

tidy() {
  [ -f "$build/compile_commands.json" ] || { echo "lint: no $build/compile_commands.json: configure $build first (scripts/build.sh)" >&2; return 1; }
  # The unity batches of the library and of the program (each a handful of sources
  # parsed with their headers once, as they are compiled), else the sources themselves,
  # in a copy of the compile commands without the precompiled header (g++'s, which
  # clang cannot read; every source includes what it uses).
  mkdir -p "$build/lint"
  mapfile -t units < <(/usr/bin/python3 - "$build" <<'PY'
import json, os, re, sys
root, build = os.getcwd(), sys.argv[1]
kept = []
for entry in json.load(open(os.path.join(build, "compile_commands.json"))):
    f = entry["file"]
    unity = "/Unity/" in f
    if (unity and ("/src/CMakeFiles/" in f or "/apps/" in f)) or (
            not unity and f.startswith((os.path.join(root, "src/"), os.path.join(root, "apps/")))):
        entry["command"] = re.sub(r" -Winvalid-pch| -include \S*cmake_pch\.hxx", "", entry["command"])
        kept.append(entry)
        print(f)
json.dump(kept, open(os.path.join(build, "lint", "compile_commands.json"), "w"))
PY
)
  [ "${#units[@]}" -gt 0 ] || { echo "lint: $build/compile_commands.json lists no source of the library" >&2; return 1; }
  printf '%s\0' "${units[@]}" | xargs -0 -n 1 -P "$jobs" clang-tidy-14 -p "$build/lint" --quiet \
    --extra-arg=-Wno-unknown-warning-option 2>/dev/null
}
check "clang-tidy, the library and the program" tidy

mapfile -t py < <(git ls-files '*.py')
check "flake8, ${#py[@]} files" flake8 "${py[@]}"

check "eslint, the report's script and the browser tests" node_modules/.bin/eslint src/io/report src/analyses src/study tests/browser

no_casts() {  # the casts outside tests, other than target<>'s own definitions
  local found
  found=$(git grep -n -E '(\.|->)target<' -- src apps python/src include \
    ':!include/feran/model/element.hpp' ':!include/feran/model/force.hpp' || true)
  [ -z "$found" ] || { echo "$found"; echo "lint: ask the element or force for an ability instead" >&2; return 1; }
}
check "abilities, not casts: no target<> outside tests" no_casts
exit $status
