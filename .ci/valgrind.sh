#!/usr/bin/env bash
# valgrind memcheck on a representative decimation (a 20480-triangle coloured icosphere,
# 90 % reduction, both metrics, Testing/Hostile/TestValgrindDecimation.cxx): fails on any
# memory error or definite/possible leak (docs/RELIABILITY.md). Runs the ctest test
# ColorDecimation.Valgrind (label valgrind).
#
#   .ci/valgrind.sh                   build in build-valgrind/ (RelWithDebInfo)
#   BUILD_DIR=build .ci/valgrind.sh   reuse an existing (non-sanitizer) build tree
#
# Needs valgrind (installed here with apt-get when missing and running as root).
# Takes about 3 minutes on 2 cores (build) plus about 15 s under valgrind.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build-valgrind}
jobs=${JOBS:-2}

if ! command -v valgrind > /dev/null; then
  if [ "$(id -u)" = 0 ] && command -v apt-get > /dev/null; then
    echo "== valgrind: installing valgrind"
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq valgrind
  else
    echo "valgrind.sh needs valgrind (apt-get install valgrind)" >&2
    exit 1
  fi
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
