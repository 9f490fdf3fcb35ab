#!/usr/bin/env bash
# Runs an unchanged GL program on shadelab (`shadelab run --xvfb --capture`) and on Mesa's
# llvmpipe (GLVND's Mesa vendor under a private Xvfb, frames captured by the mesa_frames preload
# library), both at one window size, and compares each frame both showed with gl_compare:
# the share of pixels within 2/255 (the conformance bar is 99.5 %).
#   compare_with_mesa.sh SHADELAB MESA_FRAMES.so GL_COMPARE OUT_DIR FRAMES -- PROGRAM ARGS...
# Environment: SIZE=WxH (default 400x400). Prints a line per frame; status 1 when a frame is
# missing on either side or below the bar, 2 for bad arguments.
set -u
if [ $# -lt 7 ] || [ "$6" != "--" ]; then
  echo "usage: compare_with_mesa.sh SHADELAB MESA_FRAMES.so GL_COMPARE OUT_DIR FRAMES -- PROGRAM ARGS..." >&2
  exit 2
fi
shadelab=$1 frames_lib=$2 compare=$3 out=$4 frames=$5
shift 6
here=$(cd "$(dirname "$0")" && pwd)
size=${SIZE:-400x400}
mkdir -p "$out"
rm -f "$out"/s*.png "$out"/m*.png
env -u DISPLAY "$shadelab" run --xvfb --frames "$frames" --size "$size" --timeout 30 \
  --capture "$out/s%04d.png" -- "$@" >"$out/shadelab.out" 2>"$out/shadelab.err"
env -u DISPLAY "$here/with_xvfb.sh" env __GLX_VENDOR_LIBRARY_NAME=mesa GALLIUM_DRIVER=llvmpipe \
  LD_PRELOAD="$frames_lib" MESA_FRAMES_OUT="$out/m%04d.png" MESA_FRAMES_COUNT="$frames" \
  MESA_FRAMES_SIZE="$size" timeout 30 "$@" >"$out/mesa.out" 2>"$out/mesa.err"
status=0
for ((f = 1; f <= frames; ++f)); do
  n=$(printf '%04d' "$f")
  if [ ! -e "$out/s$n.png" ] || [ ! -e "$out/m$n.png" ]; then
    echo "frame $f: missing on $([ -e "$out/s$n.png" ] && echo Mesa || echo shadelab)'s side"
    status=1
    continue
  fi
  if ! "$compare" "$out/m$n.png" "$out/s$n.png" --diff "$out/d$n.png" --name "frame $f" --min-percent 99.5; then
    status=1
  fi
done
exit $status
