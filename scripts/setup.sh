#!/usr/bin/env bash
# Set up cdea on Debian 12: install the Debian packages that are missing,
# configure (Release) and build into ./build. Safe to run again: it installs
# nothing that is already there and rebuilds only what changed.
#
#   bash scripts/setup.sh            # packages + configure + the cdea program
#   bash scripts/setup.sh --all      # the same, and the Python module, the
#                                    # tests and the benchmarks (for ctest)
#
# Environment: BUILD_DIR (default: build), JOBS (default: number of cores).
set -euo pipefail

cd "$(dirname "$0")/.."
build_dir="${BUILD_DIR:-build}"
jobs="${JOBS:-$(nproc)}"
# The program alone is what a first run needs; the test suite needs every
# target.
targets=(--target cdea)
what="$build_dir/cdea"
case "${1:-}" in
  "") ;;
  --all) targets=(); what="$build_dir/cdea, the Python module in $build_dir/python, the tests and benchmarks" ;;
  *) echo "setup: unknown option '$1' (allowed: none, or --all to build the tests, benchmarks and Python module too)" >&2
     exit 1 ;;
esac

# python3-pytest and python3-vtk9: the Python tests, which read the ParaView
# output back with VTK's XML reader. libnlopt-cxx-dev: the layout optimizer
# (cdea optimize); libceres-dev: the least-squares calibration (cdea fit).
# pybind11-dev, python3-dev and python3-numpy: the Python module `cdea`
# (build/python, doc/python.md). python3-pandas and python3-xarray: the
# results' to_pandas() and to_xarray() (python/cdea_load.py), and their tests.
packages=(cmake g++ make libdeal.ii-dev libeigen3-dev libhdf5-dev hdf5-tools
          libnlopt-cxx-dev libceres-dev openmpi-bin python3 python3-h5py python3-matplotlib
          python3-pytest python3-vtk9 pybind11-dev python3-dev python3-numpy
          python3-pandas python3-xarray)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing Debian packages: ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then
    echo "setup: these packages are missing and installing them needs root:" >&2
    echo "  sudo apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

log=$(mktemp)
trap 'rm -f "$log"' EXIT
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release > "$log" 2>&1 || {
  cat "$log" >&2
  echo "setup: configuring failed (log above)" >&2
  exit 1
}
cmake --build "$build_dir" -j "$jobs" "${targets[@]}"
echo "setup: built $what"
