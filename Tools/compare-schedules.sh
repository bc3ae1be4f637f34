#!/usr/bin/env bash
# Greedy against Batched (CollapseSchedule) on the same meshes: the filter's time, the output
# triangles, the colour PSNR of unlit renders and the shape PSNR of lit ones
# (color-decimate-eval, six axis views at 512x512) and the two-sided Metro distance
# (color-decimate-metro, 100,000 samples per side), as a Markdown table on standard output.
#
#   Tools/compare-schedules.sh BUILD_DIR MESH... [-- extra color-decimate options]
#   e.g. Tools/compare-schedules.sh build ../shared/data/igea.ply ../shared/data/bunny.ply
#
# Renders need an X display: the script runs color-decimate-eval under xvfb-run -a when
# there is none. Work files go to BUILD_DIR/compare-schedules/.
set -euo pipefail
build=$1
shift
meshes=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
  meshes+=("$1")
  shift
done
[ "${1:-}" = "--" ] && shift
bin=$build/bin
work=$build/compare-schedules
mkdir -p "$work"
run_x=()
if [ -z "${DISPLAY:-}" ]; then
  run_x=(xvfb-run -a)
fi
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($1)" "$2"; }

echo "| mesh | input triangles | schedule | seconds | output triangles | colour PSNR (dB) | shape PSNR (dB) | Metro RMS (% diag) | Metro max (% diag) |"
echo "|---|--:|---|--:|--:|--:|--:|--:|--:|"
for mesh in "${meshes[@]}"; do
  name=$(basename "${mesh%.*}")
  for schedule in greedy batched; do
    out=$work/${name}_$schedule.ply
    "$bin/color-decimate" "$mesh" "$out" --schedule "$schedule" --quiet \
      --stats "$work/${name}_$schedule.json" "$@"
    "${run_x[@]}" "$bin/color-decimate-eval" "$mesh" "$out" --json "$work/${name}_$schedule.eval.json" >/dev/null
    "$bin/color-decimate-metro" "$mesh" "$out" --samples 100000 --json "$work/${name}_$schedule.metro.json" >/dev/null
    stats=$work/${name}_$schedule.json
    eval=$work/${name}_$schedule.eval.json
    metro=$work/${name}_$schedule.metro.json
    echo "| $name | $(json "format(d['input_triangles'], ',')" "$stats") | $schedule" \
      "| $(json "'%.3f' % d['filter_seconds']" "$stats")" \
      "| $(json "format(d['output_triangles'], ',')" "$stats")" \
      "| $(json "'%.2f' % d['unlit']['psnr']" "$eval")" \
      "| $(json "'%.2f' % d['lit']['psnr']" "$eval")" \
      "| $(json "'%.4f' % d['rms_percent']" "$metro")" \
      "| $(json "'%.3f' % d['max_percent']" "$metro") |"
  done
done
