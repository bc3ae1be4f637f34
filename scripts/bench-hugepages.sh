#!/usr/bin/env bash
# The filter with its large arrays on huge pages against the same binary on ordinary pages, in
# alternating rounds (docs/BENCHMARK.md, "Large arrays on huge pages").
#
# Usage (root: it switches the kernel's transparent huge pages between "madvise", where the
# filter's madvise(MADV_HUGEPAGE) is honoured, and "never"; the setting found is restored):
#   scripts/bench-hugepages.sh [MESH] [REDUCTION] [ROUNDS] [color-decimate options...]
# (default: the 7 mm kitchen of ../shared/data, 0.9, 5 rounds, the defaults)
set -euo pipefail
cd "$(dirname "$0")/.."
mesh=${1:-../shared/data/redkitchen_tsdf_7mm.ply}
reduction=${2:-0.9}
rounds=${3:-5}
shift $(($# < 3 ? $# : 3))
cli=${BUILD:-build-test-vtk}/bin/color-decimate
thp=/sys/kernel/mm/transparent_hugepage/enabled
[ -x "$cli" ] || { echo "no $cli (build first: scripts/test.sh)"; exit 1; }
[ -w "$thp" ] || { echo "cannot switch $thp (not root, or no transparent huge pages): skipped"; exit 0; }
found=$(sed 's/.*\[\(.*\)\].*/\1/' "$thp")
work=$(mktemp -d)
trap 'echo "$found" > "$thp"; rm -rf "$work"' EXIT
echo "mesh $mesh, reduction $reduction, $rounds rounds, options: ${*:-(defaults)}"
echo "commit $(git log -1 --format='%h %cs'), $(nproc) cores, $(date -u '+%F %R') UTC"
for n in $(seq 1 "$rounds"); do
  for mode in madvise never; do
    echo "$mode" > "$thp"
    "$cli" "$mesh" "$work/out.vtp" --reduction "$reduction" --stats "$work/$mode.$n.json" --quiet "$@"
  done
done
python3 - "$work" "$rounds" <<'PY'
import json, statistics, sys
work, rounds = sys.argv[1], int(sys.argv[2])
def stats(mode, key):
    return [json.load(open("%s/%s.%d.json" % (work, mode, n)))[key] for n in range(1, rounds + 1)]
huge, plain = stats("madvise", "filter_seconds"), stats("never", "filter_seconds")
print("| | huge pages | ordinary pages | ratio |")
print("|---|--:|--:|--:|")
print("| filter, median s | %.3f | %.3f | %.3f |" % (statistics.median(huge), statistics.median(plain), statistics.median(huge) / statistics.median(plain)))
print("| per-round ratio, median | | | %.3f |" % statistics.median(h / p for h, p in zip(huge, plain)))
print("| peak RSS, median MiB | %.0f | %.0f | |" % (statistics.median(stats("madvise", "peak_rss_bytes")) / 2**20, statistics.median(stats("never", "peak_rss_bytes")) / 2**20))
print("\nfilter seconds, huge: %s\nfilter seconds, ordinary: %s" % (" ".join("%.3f" % t for t in huge), " ".join("%.3f" % t for t in plain)))
PY
