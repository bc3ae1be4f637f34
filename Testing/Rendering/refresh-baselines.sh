#!/bin/sh
# Rewrites the PNG baselines of the image tests (Testing/Data/Baseline/<scene>.png) from
# the current sources, on purpose, after a change that is MEANT to change the pictures.
# Never run in CI. Look at the new pictures before committing them.
#
# usage: Testing/Rendering/refresh-baselines.sh [BUILD_DIR]   (default: build-refresh)
set -eu
if [ "${CI:-}" = "true" ]; then
  echo "refresh-baselines.sh: refusing to rewrite baselines in CI" >&2
  exit 1
fi
src=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-"$src/build-refresh"}
# Whatever happens below, put the build directory back to comparing.
trap 'cmake -S "$src" -B "$build" -DCOLORDECIMATION_REFRESH_BASELINES=OFF > /dev/null 2>&1 || true' EXIT
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCOLORDECIMATION_REFRESH_BASELINES=ON
cmake --build "$build" -j2 --target TestColorDecimationRendering
status=0
(cd "$build" && ctest -R '^ColorDecimation\.Image\.' --output-on-failure) || status=$?
if [ "$status" -ne 0 ]; then
  echo "refresh-baselines.sh: some pictures could not be written" >&2
  exit "$status"
fi
echo "Rewrote $src/Testing/Data/Baseline/*.png: look at them, run ctest, then commit them."
echo "Alternates (<scene>_1.png ...) were left as they were: delete the stale ones."
