#!/usr/bin/env bash
# Set-up on a fresh Debian 12 machine (as root): install what is missing, build, then
#   demo : run the Hertz contact demo
#   test : run the whole test suite (ctest; each Check runner prints its summary)
# Usage: bash tools/bootstrap.sh demo|test
set -euo pipefail
mode=${1:-test}
cd "$(dirname "$0")/.."

packages=(build-essential cmake pkg-config libsuitesparse-dev libopenblas-dev liblapacke-dev check
          gfortran python3 python3-numpy abigail-tools
          nlohmann-json3-dev gmsh python3-matplotlib python3-meshio
          clang libclang-rt-14-dev valgrind)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq "${missing[@]}"
fi

build=${MC_BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j"$(nproc)"

case "$mode" in
  demo)
    "$build/examples/hertz" 0.004 mortar hertz_pressure.csv ;;
  test)
    ctest --test-dir "$build" --output-on-failure -V -j1 ;;
  *)
    echo "usage: $0 demo|test" >&2; exit 2 ;;
esac
