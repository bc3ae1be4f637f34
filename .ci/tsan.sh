#!/usr/bin/env bash
# ThreadSanitizer build of the module and its C++ tests, then the tests that decimate on
# several threads (docs/RELIABILITY.md): the Batched schedule's blocks and re-costing passes,
# the initial costs of both schedules, and the parallel loops' own tests.
#
#   .ci/tsan.sh                       build in build-tsan/ and run the threaded tests
#   BUILD_DIR=dir JOBS=n .ci/tsan.sh
#
# Only this project's code is instrumented; VTK runs on the main thread only in these tests.
# Takes about 6 minutes on 2 cores from scratch.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build-tsan}
jobs=${JOBS:-2}

echo "== tsan: configure $build"
cmake -S "$root" -B "$build" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DBUILD_TESTING=ON \
  -DCOLORDECIMATION_SANITIZE=thread \
  -DCOLORDECIMATION_WRAP_PYTHON=OFF
echo "== tsan: build the C++ tests"
cmake --build "$build" -j "$jobs" --target TestColorDecimationCore TestColorDecimationFilter \
  TestColorDecimationControls
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"
echo "== tsan: ctest"
ctest --test-dir "$build" -j 1 --output-on-failure --timeout 900 --no-tests=error \
  -R "ThreadsSameResult|SmallPiecesOnThreads|CountingSort|BatchedOneAtATimeIsGreedy|InvariantsBatched|InvariantsLarge|Progress|Abort|LargeSeams|ParallelFor|CollectInOrder" "$@"
