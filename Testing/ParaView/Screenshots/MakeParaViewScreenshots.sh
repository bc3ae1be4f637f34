#!/bin/bash
# Screenshots of the plugin in ParaView's GUI for docs/PARAVIEW.md, under Xvfb:
#   XVFB_SCREEN=1440x900x24 Testing/ParaView/RunWithXvfb.sh Xvfb \
#     Testing/ParaView/Screenshots/MakeParaViewScreenshots.sh <plugin folder> <output folder>
# Needs paraview, xdotool and ImageMagick's import/convert. The pointer positions below are
# those of ParaView 5.11 (Debian 12) in a 1440x900 window.
set -e
plugins="${1:?plugin folder (lib/paraview-5.11/plugins of the build)}"
out="${2:?output folder}"
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$out"
scratch="$(mktemp -d)"
export PV_PLUGIN_PATH="$plugins"
paraview --dr --script="$here/ParaViewScene.py" > "$scratch/paraview.log" 2>&1 &
pv=$!
trap 'kill $pv 2>/dev/null || true; rm -rf "$scratch"' EXIT
sleep 25
wid=$(xdotool search --onlyvisible --name "ParaView" | head -1)
xdotool windowmove "$wid" 0 0 windowsize "$wid" 1440 900
sleep 3
# Widen the left dock (pipeline browser and properties), shorten the pipeline browser.
xdotool mousemove 296 600 mousedown 1 sleep 0.3 mousemove 420 600 sleep 0.3 mousemove 560 600 sleep 0.3 mouseup 1
sleep 1
xdotool mousemove 270 399 mousedown 1 sleep 0.3 mousemove 270 330 sleep 0.3 mousemove 270 280 sleep 0.3 mouseup 1
sleep 1
# Show the advanced properties (the gear button) and take the whole window.
xdotool mousemove 534 385 click 1
sleep 2
import -window root "$out/paraview_panel.png"
# The Filters menu, then the plugin's category.
xdotool mousemove 215 10 click 1
sleep 1
xdotool mousemove 260 200 sleep 0.3 mousemove 283 330 sleep 0.3 mousemove 285 336 click 1
sleep 2
import -window root "$scratch/menu.png"
convert "$scratch/menu.png" -crop 800x450+0+0 +repage "$out/paraview_filters_menu.png"
