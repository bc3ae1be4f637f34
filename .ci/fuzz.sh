#!/usr/bin/env bash
# Build the libFuzzer target (Clang, with ASan and UBSan) and fuzz vtkColorHalfEdgeDecimation
# for a bounded time; fails on any crash, leak, undefined behaviour, timeout or broken output
# invariant (docs/RELIABILITY.md). The same configuration as the "fuzz" preset.
#
#   .ci/fuzz.sh                       build in build-fuzz/, fuzz for 120 s
#   FUZZ_SECONDS=600 .ci/fuzz.sh      longer
#   BUILD_DIR=dir JOBS=n .ci/fuzz.sh
#
# The run starts from the committed seeds (Testing/Fuzz/corpus/) and keeps what it learns in
# $BUILD_DIR/fuzz-corpus/. A failing input is written to $BUILD_DIR/fuzz-artifacts/; commit it
# to Testing/Fuzz/regressions/ (a ctest test replays every file there, in every build).
# Needs clang and libclang-rt-14-dev (Debian 12); installed here with apt-get when missing
# (scripts/lib.sh: as root, or through sudo).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build-fuzz}
jobs=${JOBS:-2}
seconds=${FUZZ_SECONDS:-120}

if ! command -v clang++ > /dev/null || ! echo 'int main(){}' |
    clang++ -x c++ -fsanitize=fuzzer-no-link,address -o /dev/null - 2> /dev/null; then
  echo "== fuzz: installing clang and libclang-rt-14-dev"
  . "$root/scripts/lib.sh"
  ensure_packages clang libclang-rt-14-dev
fi

echo "== fuzz: configure $build"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DBUILD_TESTING=ON \
  -DCOLORDECIMATION_SANITIZE=address,undefined \
  -DCOLORDECIMATION_FUZZ=ON \
  -DCOLORDECIMATION_WRAP_PYTHON=OFF
echo "== fuzz: build"
cmake --build "$build" -j "$jobs" --target ColorDecimationFuzzer ColorDecimationFuzzReplay

export ASAN_OPTIONS="detect_leaks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
echo "== fuzz: replay the seeds and the regressions (Clang + ASan + UBSan)"
replay=0
ctest --test-dir "$build" --output-on-failure -L fuzz --no-tests=error || replay=1

corpus="$build/fuzz-corpus"
artifacts="$build/fuzz-artifacts"
mkdir -p "$corpus" "$artifacts"
echo "== fuzz: ${seconds} s"
status=0
"$build/bin/ColorDecimationFuzzer" "$corpus" "$root/Testing/Fuzz/corpus" \
  -max_total_time="$seconds" -timeout=25 -rss_limit_mb=4096 -max_len=16384 \
  -artifact_prefix="$artifacts/" -print_final_stats=1 > "$build/fuzz.log" 2>&1 || status=$?
tail -n 25 "$build/fuzz.log"
if [ "$status" != 0 ]; then
  echo "fuzz: FAILED (exit $status); inputs in $artifacts:" >&2
  ls -l "$artifacts" >&2
  echo "commit them to Testing/Fuzz/regressions/ once the cause is understood" >&2
  exit 1
fi
echo "fuzz: no crash in ${seconds} s ($(ls "$corpus" | wc -l) inputs in the working corpus)"
if [ "$replay" != 0 ]; then
  echo "fuzz: FAILED: the replay of the seeds or regressions failed (see above)" >&2
  exit 1
fi
