#!/usr/bin/env bash
# Two builds of the CLI in alternating rounds on one mesh: the filter's time and its phases
# (medians), the ratio new / old overall and per round, and whether the outputs are the same
# file (docs/BENCHMARK.md). Make both builds the same way, each in a worktree of a path of the
# same length (two builds of the same code in other places ran a phase 30 % apart):
#   git worktree add /tmp/old <commit> && cmake -S /tmp/old -B /tmp/old/build \
#     -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF && cmake --build /tmp/old/build \
#     --target color-decimate
# and the same for the new commit in /tmp/new (uncommitted changes: git diff | git -C /tmp/new
# apply).
#
# Usage: scripts/bench-ab.sh OLD_CLI NEW_CLI [MESH] [ROUNDS] [color-decimate options...]
# (default: the 7 mm kitchen of ../shared/data, 5 rounds, the defaults)
set -euo pipefail
cd "$(dirname "$0")/.."
old=$1
new=$2
mesh=${3:-../shared/data/redkitchen_tsdf_7mm.ply}
rounds=${4:-5}
shift $(($# < 4 ? $# : 4))
for cli in "$old" "$new"; do
  [ -x "$cli" ] || { echo "no $cli"; exit 1; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "mesh $mesh, $rounds rounds, options: ${*:-(defaults)}"
echo "old $old, new $new; $(nproc) cores, $(date -u '+%F %R') UTC"
for n in $(seq 1 "$rounds"); do
  "$old" "$mesh" "$work/old.ply" --stats "$work/old.$n.json" --quiet "$@"
  "$new" "$mesh" "$work/new.ply" --stats "$work/new.$n.json" --quiet "$@"
done
cmp -s "$work/old.ply" "$work/new.ply" && echo "outputs: the same file" ||
  echo "outputs: different files"
python3 - "$work" "$rounds" <<'PY'
import json, statistics, sys
work, rounds = sys.argv[1], int(sys.argv[2])
runs = {k: [json.load(open(f"{work}/{k}.{n}.json")) for n in range(1, rounds + 1)]
        for k in ("old", "new")}
filt = {k: [r["filter_seconds"] for r in v] for k, v in runs.items()}
mo, mn = statistics.median(filt["old"]), statistics.median(filt["new"])
print(f"filter median: old {mo:.3f} s, new {mn:.3f} s, new/old {mn / mo:.3f}")
ratios = [b / a for a, b in zip(filt["old"], filt["new"])]
print("per round new/old:", " ".join(f"{r:.3f}" for r in ratios),
      f"(median {statistics.median(ratios):.3f})")
names = [p["name"] for p in runs["new"][0]["phases"]]
for name in dict.fromkeys(names):
    med = {}
    for k, v in runs.items():
        med[k] = statistics.median(sum(p["seconds"] for p in r["phases"] if p["name"] == name)
                                   for r in v)
    print(f"  {name:20s} old {med['old']:.3f}  new {med['new']:.3f}")
PY
