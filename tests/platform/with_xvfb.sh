#!/usr/bin/env bash
# Runs a command with DISPLAY set to a private Xvfb started for it (first free display, chosen
# by Xvfb itself with -displayfd), and stops the server afterwards. Exit status: the command's,
# or 1 when Xvfb does not start.   with_xvfb.sh COMMAND ARGS...
set -u
fifo=$(mktemp -u) && mkfifo "$fifo" || exit 1
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$fifo" >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null; wait $xvfb 2>/dev/null; rm -f "$fifo"' EXIT
if ! read -r -t 15 number <"$fifo"; then
  echo "with_xvfb.sh: Xvfb did not start" >&2
  exit 1
fi
export DISPLAY=":$number"
"$@"
