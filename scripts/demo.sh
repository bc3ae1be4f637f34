#!/usr/bin/env bash
# The main job on a fresh Debian 12 machine: install what is missing (apt-get, as root),
# configure and build in Release into build/ (the CLI is build/bin/color-decimate), then
# decimate the built-in default coloured mesh to 10 % of its triangles and write the input and
# the result next to each other in build/demo/, printing the figures.
#
# Usage: scripts/demo.sh [extra color-decimate options, e.g. --reduction 0.97]
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/lib.sh

flavour=$(installed_flavour)
[ "$flavour" = none ] && flavour=vtk
ensure_flavour "$flavour"

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCOLORDECIMATION_FLAVOUR="$(cmake_flavour "$flavour")"
cmake --build build --parallel "$(nproc)" --target color-decimate

mkdir -p build/demo
build/bin/color-decimate --demo build/demo/demo-decimated.ply \
  --write-demo build/demo/demo-input.ply --stats build/demo/demo-stats.json "$@"
echo "== wrote build/demo/demo-input.ply, build/demo/demo-decimated.ply and build/demo/demo-stats.json"
