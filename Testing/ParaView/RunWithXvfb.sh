#!/bin/sh
# Runs a command with DISPLAY set to a fresh Xvfb server, stopped afterwards:
#   RunWithXvfb.sh <Xvfb> <command> [arguments...]
# The server picks a free display number itself (-displayfd), which also works where X's
# abstract sockets are shared with other chroots or containers (there, xvfb-run's search by
# lock files can pick a display that is in use). XVFB_SCREEN sets the screen (default
# 1280x1024x24).
xvfb="$1"
shift
fifo_dir="$(mktemp -d)" || exit 1
mkfifo "$fifo_dir/display" || exit 1
"$xvfb" -displayfd 3 -screen 0 "${XVFB_SCREEN:-1280x1024x24}" -nolisten tcp -ac -noreset 3>"$fifo_dir/display" &
server=$!
read -r display < "$fifo_dir/display"
rm -rf "$fifo_dir"
if [ -z "$display" ]; then
  echo "RunWithXvfb.sh: Xvfb did not start" >&2
  kill "$server" 2>/dev/null
  exit 1
fi
DISPLAY=":$display" "$@"
status=$?
kill "$server" 2>/dev/null
wait "$server" 2>/dev/null
exit $status
