#!/usr/bin/env bash
# Levels of detail from one run against one plain run, on the same mesh, in alternating rounds
# (docs/BENCHMARK.md, "Levels of detail from one run", has the figures and the commands).
#
# Usage: scripts/bench-lod.sh [MESH] [ROUNDS]   (default: the 7 mm kitchen of ../shared/data, 5)
#
# Each round runs, one after the other:
#   A  color-decimate MESH a.ply --reduction R_max                (one run to the coarsest level)
#   B  color-decimate MESH b.ply --lod LEVELS                      (one run with the record, then
#                                                                   every level extracted)
# and prints the medians of the whole command's wall time, of the filter's time and of each
# level's extraction, with B / A. Then the slider: in one Python process, the level filter's
# update for each of LEVELS after the first (the mesh and the record are then cached), against
# the record run's time.
set -euo pipefail
cd "$(dirname "$0")/.."
mesh=${1:-../shared/data/redkitchen_tsdf_7mm.ply}
rounds=${2:-5}
levels=${LEVELS:-0.5,0.9,0.97}
build=${BUILD:-build-test-vtk}
cli="$build/bin/color-decimate"
top=$(echo "$levels" | tr ',' '\n' | sort -g | tail -1)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case "$mesh" in
  demo*) ;;
  *) [ -f "$mesh" ] || { echo "no mesh $mesh"; exit 1; } ;;
esac
[ -x "$cli" ] || { echo "no $cli (build first: scripts/test.sh)"; exit 1; }
echo "mesh $mesh, levels $levels, plain run to $top, $rounds rounds, $(nproc) cores, $(date -u '+%F %R') UTC"
echo "commit $(git log -1 --format='%h %cs'), load $(cut -d' ' -f1-3 /proc/loadavg)"

run() { # label, then the command: prints "label wall" and keeps the stats in $work/label.N.json
  local label=$1 n=$2
  shift 2
  local start end
  start=$(date +%s.%N)
  "$@" --stats "$work/$label.$n.json" --quiet
  end=$(date +%s.%N)
  echo "$label $n $(echo "$end - $start" | bc)" >>"$work/walls"
}
for n in $(seq 1 "$rounds"); do
  run plain "$n" "$cli" "$mesh" "$work/a.ply" --reduction "$top"
  run lod "$n" "$cli" "$mesh" "$work/b.ply" --lod "$levels"
done
python3 - "$work" "$rounds" <<'PY'
import json, statistics, sys
work, rounds = sys.argv[1], int(sys.argv[2])
walls = {}
for line in open(work + "/walls"):
    label, n, seconds = line.split()
    walls.setdefault(label, []).append(float(seconds))
def stats(label, n):
    return json.load(open("%s/%s.%d.json" % (work, label, n)))
med = statistics.median
plain = [stats("plain", n) for n in range(1, rounds + 1)]
lod = [stats("lod", n) for n in range(1, rounds + 1)]
pf = med(s["filter_seconds"] for s in plain)
lf = med(s["filter_seconds"] for s in lod)
print("| | plain run | --lod run | ratio |")
print("|---|--:|--:|--:|")
print("| whole command (read, decimate, write), s | %.3f | %.3f | %.3f |" % (med(walls["plain"]), med(walls["lod"]), med(walls["lod"]) / med(walls["plain"])))
ratios = [b / a for a, b in zip(walls["plain"], walls["lod"])]
print("| whole command, per-round ratio (median) | | | %.3f |" % med(ratios))
print("| decimation filter, s | %.3f | %.3f (with the record) | %.3f |" % (pf, lf, lf / pf))
print("| decimation state, MiB | %.1f | %.1f | |" % (plain[0]["state_memory_bytes"] / 2**20, lod[0]["state_memory_bytes"] / 2**20))
print("| peak RSS, MiB | %.1f | %.1f | |" % (med(s["peak_rss_bytes"] for s in plain) / 2**20, med(s["peak_rss_bytes"] for s in lod) / 2**20))
print()
print("| level | triangles | reduction | collapses | extraction s (median) | write s | extraction / decimation |")
print("|---|--:|--:|--:|--:|--:|--:|")
for i, level in enumerate(lod[0]["levels"]):
    ex = med(s["levels"][i]["extract_seconds"] for s in lod)
    wr = med(s["levels"][i]["write_seconds"] for s in lod)
    print("| %g | %d | %.4f | %d | %.3f | %.3f | %.3f |" % (level["target_reduction"], level["output_triangles"], level["reduction"], level["collapses"], ex, wr, ex / lf))
print("\n(the first level's extraction also reads the mesh and checks the record; the others reuse them)")
PY

# The slider: the level filter updated for each level in one process (first update excluded).
# The wrapping is where the flavour installs it: python3/dist-packages (VTK 9.1) or
# python3.X/site-packages (ParaView 5.11's VTK 9.2).
site=$(ls -d "$build"/lib/python3*/*-packages 2>/dev/null | head -1 || true)
if [ "${mesh##*.}" = ply ] && [ -n "$site" ] && [ -d "$site/colordecimation" ]; then
  PYTHONPATH="$site${PYTHONPATH:+:$PYTHONPATH}" /usr/bin/python3 - "$mesh" "$levels" <<'PY'
import statistics, sys, time
from vtkmodules.vtkIOPLY import vtkPLYReader
from colordecimation import vtkColorHalfEdgeDecimation, vtkColorHalfEdgeLevelOfDetail
reader = vtkPLYReader()
reader.SetFileName(sys.argv[1])
reader.Update()
mesh = reader.GetOutput()
levels = [float(x) for x in sys.argv[2].split(",")]
run = vtkColorHalfEdgeDecimation()
run.SetInputData(mesh)
run.GenerateCollapseRecordOn()
run.SetTargetReduction(max(levels))
start = time.perf_counter(); run.Update(); record_seconds = time.perf_counter() - start
lod = vtkColorHalfEdgeLevelOfDetail()
lod.SetInputData(mesh)
lod.SetRecordConnection(run.GetOutputPort(1))
lod.SetTargetReduction(levels[0])
start = time.perf_counter(); lod.Update(); first = time.perf_counter() - start
moves = []
for repeat in range(3):
    for r in levels[1:] + levels[:1]:
        lod.SetTargetReduction(r)
        start = time.perf_counter(); lod.Update(); moves.append(time.perf_counter() - start)
print("\nslider (VTK, one process): record run %.3f s; first level %.3f s (reads the mesh and "
      "checks the record); later moves median %.3f s, max %.3f s (%d moves), %.1f %% of the run"
      % (record_seconds, first, statistics.median(moves), max(moves), len(moves),
         100 * statistics.median(moves) / record_seconds))
PY
fi
