#!/usr/bin/env bash
# Installs the Debian 12 packages feran needs to build, test and plot.
# Idempotent: prints nothing and changes nothing when everything is present.
set -euo pipefail

packages=(
  build-essential cmake
  libeigen3-dev libspectra-dev liblapack-dev libopenblas-dev
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-numpy python3-matplotlib
  python3-dev pybind11-dev python3-pytest python3-pandas  # the Python module (python/)
  clang-14 libclang-rt-14-dev  # libFuzzer and its sanitizers (scripts/fuzz.sh)
  libpagmo-dev  # the optimisers of design studies (pagmo2, built without NLopt)
  libopenmpi-dev openmpi-bin  # feran study over the processes of an MPI job (apps/feran/mpi/)
  python3-distributed  # feran.Study on a dask.distributed cluster (python/feran/study.py)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
