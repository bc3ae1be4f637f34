#!/usr/bin/env bash
# Bit-exactness check: the same output, bit for bit, from two revisions of the module.
#
#   scripts/bitcheck/run.sh BASE_BUILD NEW_BUILD [MESH ...]
#
# BASE_BUILD and NEW_BUILD are configured and built trees (VTK 9.1 flavour) of the two
# revisions, e.g. a `git worktree add ../base <rev>` built in ../base/build. The harness
# (OutputHash.cxx) is compiled against each; both run every MESH (default: every .ply of
# ../shared/data and seven generated meshes, written here by NEW_BUILD's color-decimate)
# and their lines are compared. Define PAPER_BASE=1 / PAPER_NEW=1 when that revision has
# SetPaperDefaults() (the defaults changed in 61a9391; the runs then start from the paper's
# settings). Exit status 0 when every run is identical.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
base=$(cd "$1" && pwd); new=$(cd "$2" && pwd); shift 2
work=${WORK:-$new/bitcheck}
mkdir -p "$work"
vtk_libs=$(ls /usr/lib/x86_64-linux-gnu/libvtk{CommonCore,CommonDataModel,CommonExecutionModel,IOPLY,IOXML,IOCore,CommonMisc,CommonSystem,CommonMath,CommonTransforms,sys}-9.1.so)
compile() { # BUILD OUT PAPER
  local src
  src=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$1/CMakeCache.txt")
  g++ -O2 -std=c++17 ${3:+-DHAVE_PAPER} -o "$2" "$here/OutputHash.cxx" -I/usr/include/vtk-9.1 \
    -I"$src/Filters" -I"$1/Filters" -L"$1/lib" -Wl,-rpath,"$1/lib" -lvtkColorDecimation $vtk_libs
}
compile "$base" "$work/hash-base" "${PAPER_BASE:-}"
compile "$new" "$work/hash-new" "${PAPER_NEW:-}"
meshes=("$@")
if [ ${#meshes[@]} -eq 0 ]; then
  meshes=("$root"/../shared/data/*.ply)
  for spec in grid150:sharp grid200:constant ico6:sharp ico8:fine sphere1M:fine torus120:fine \
    uv300:smooth; do
    out="$work/${spec/:/_}.vtp"
    [ -f "$out" ] || "$new/bin/color-decimate" "demo:$spec" "$out" --reduction 0 > /dev/null
    meshes+=("$out")
  done
fi
"$work/hash-base" "${meshes[@]}" > "$work/base.txt"
"$work/hash-new" "${meshes[@]}" > "$work/new.txt"
runs=$(wc -l < "$work/base.txt")
if diff "$work/base.txt" "$work/new.txt" > "$work/diff.txt"; then
  echo "bitcheck: $runs runs, all identical"
else
  echo "bitcheck: $(grep -c '^>' "$work/diff.txt") of $runs runs differ ($work/diff.txt)"
  exit 1
fi
