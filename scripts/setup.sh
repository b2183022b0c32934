#!/usr/bin/env bash
# Installs the Debian 12 packages feran needs to build, test and plot, and the
# front-end packages of its HTML reports from npm (package-lock.json).
# Idempotent: prints nothing and changes nothing when everything is present.
set -euo pipefail

packages=(
  build-essential cmake
  ccache  # a second build of the same sources (CI on the same machine, a new clone) compiles only what changed
  libeigen3-dev libspectra-dev liblapack-dev libopenblas-dev
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-numpy python3-matplotlib
  python3-dev pybind11-dev python3-pytest python3-pandas  # the Python module (python/)
  clang-14 libclang-rt-14-dev  # libFuzzer and its sanitizers (scripts/fuzz.sh)
  libpagmo-dev  # the optimisers of design studies (pagmo2, built without NLopt)
  libopenmpi-dev openmpi-bin  # feran study over the processes of an MPI job (apps/feran/mpi/)
  python3-distributed  # feran.Study on a dask.distributed cluster (python/feran/study.py)
  chromium  # the browser tests of the HTML reports (tests/browser/)
  clang-format-14 clang-tidy-14 flake8  # the code's checks (scripts/lint.sh)
)
# Node.js and npm install the reports' front-end packages; a machine that has them
# from elsewhere (a newer Node.js) keeps its own.
command -v npm >/dev/null || packages+=(nodejs npm)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# plotly.js (inlined into every report at build time), playwright-core (which
# drives Debian's Chromium in the browser tests; it downloads no browser of its own)
# and ESLint (scripts/lint.sh), at the versions of the lock file. Installed again
# only when the lock file changed.
install_front_end() {
  local stamp="$root/node_modules/.package-lock.json"  # written by npm ci
  if [ ! -f "$stamp" ] || [ "$root/package-lock.json" -nt "$stamp" ]; then
    echo "setup: installing the front-end packages (npm ci)"
    (cd "$root" && npm ci --ignore-scripts --no-audit --no-fund --loglevel=error >/dev/null)
  fi
}

if [ ${#missing[@]} -eq 0 ]; then
  install_front_end
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
install_front_end
