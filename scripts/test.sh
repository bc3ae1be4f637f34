#!/usr/bin/env bash
# The tests on a fresh Debian 12 machine: install what is missing (apt-get, as root), build
# everything (module, tools, tests) in Release and run the whole ctest suite.
#
# Usage: scripts/test.sh [--flavour vtk|paraview|both] [extra ctest arguments]
#   vtk       Debian's VTK 9.1 (libvtk9-dev), the default on a machine that has neither
#   paraview  ParaView 5.11's VTK 9.2 (paraview-dev), which also builds and tests the plugin
#   both      one after the other, swapping the packages (what CI runs)
# Without --flavour, the flavour already installed is tested (VTK when there is none).
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/lib.sh

flavour=""
if [ "${1:-}" = "--flavour" ]; then
  flavour="$2"
  shift 2
fi
if [ -z "$flavour" ]; then
  flavour=$(installed_flavour)
  [ "$flavour" = none ] && flavour=vtk
fi
if [ "$flavour" = both ]; then
  scripts/test.sh --flavour vtk "$@"
  scripts/test.sh --flavour paraview "$@"
  exit 0
fi

ensure_flavour "$flavour"
# The benchmarks' meshoptimizer 1.3 (WebAssembly): the pinned npm package, when node and npm
# are there and it is not installed yet (or another version is: simplify.mjs --version fails,
# the one check of the pin); if npm fails (no registry), its tests are skipped.
if command -v node >/dev/null && command -v npm >/dev/null &&
  ! node Tools/MeshOptimizerJS/simplify.mjs --version >/dev/null 2>&1; then
  npm ci --prefix Tools/MeshOptimizerJS --no-audit --no-fund --fetch-retries=1 \
    --fetch-timeout=60000 ||
    echo "== npm ci failed: the meshoptimizer 1.3 (WebAssembly) tests will be skipped"
fi
build="build-test-$flavour"
echo "== configure and build ($flavour) in $build"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON \
  -DCOLORDECIMATION_FLAVOUR="$(cmake_flavour "$flavour")"
cmake --build "$build" --parallel "$(nproc)"
echo "== ctest ($flavour)"
ctest --test-dir "$build" --output-on-failure --parallel "$(nproc)" "$@"
