#!/usr/bin/env bash
# valgrind memcheck on a representative decimation (a 20480-triangle coloured icosphere,
# 90 % reduction: the defaults with the collapse record and a level extracted from it, then the
# paper's metric and the geometric one; Testing/Hostile/TestValgrindDecimation.cxx): fails on any
# memory error or definite/possible leak (docs/RELIABILITY.md). Runs the ctest test
# ColorDecimation.Valgrind (label valgrind).
#
#   .ci/valgrind.sh                   reuse build-test-vtk/ (scripts/test.sh) when it exists,
#                                     else build in build-valgrind/ (RelWithDebInfo)
#   BUILD_DIR=build .ci/valgrind.sh   use that (non-sanitizer) build tree
#
# Needs valgrind (installed here with apt-get when missing: scripts/lib.sh, as root or through
# sudo).
# Takes about 5 s under valgrind, plus about 1 minute on 2 cores when it builds its own tree.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# Default: the Release tree that scripts/test.sh leaves (CI runs it first), when it is there
# and is not a sanitizer build; otherwise a RelWithDebInfo tree of its own.
build=${BUILD_DIR:-}
if [ -z "$build" ]; then
  build=$root/build-valgrind
  cache=$root/build-test-vtk/CMakeCache.txt
  if [ -f "$cache" ] && ! grep -q '^COLORDECIMATION_SANITIZE:STRING=.\+' "$cache"; then
    build=$root/build-test-vtk
  fi
fi
jobs=${JOBS:-2}

if ! command -v valgrind > /dev/null; then
  echo "== valgrind: installing valgrind"
  . "$root/scripts/lib.sh"
  ensure_packages valgrind
fi

if [ ! -f "$build/CMakeCache.txt" ]; then
  echo "== valgrind: configure $build"
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBUILD_TESTING=ON
else
  cmake "$build" > /dev/null # pick up a valgrind installed since
fi
echo "== valgrind: build"
cmake --build "$build" -j "$jobs" --target TestValgrindDecimation
echo "== valgrind: ctest -L valgrind"
ctest --test-dir "$build" --output-on-failure -L valgrind --no-tests=error
