#!/usr/bin/env bash
# glut_multisample.c (a GLUT_MULTISAMPLE window) through `shadelab run --xvfb`, drawn by the fast
# pipeline and by the reference one (SHADELAB_REFERENCE): frames 1 and 2 of both must agree
# (the conformance bar, 99.5 % of pixels within 2/255). Mesa is no oracle here: Debian 12's
# llvmpipe reports 4 samples for its multisampled GLX and EGL configurations but rasterizes them
# with one (docs/gl.md, multisampling).
#   multisample_test.sh SHADELAB PROGRAM GL_COMPARE OUT_DIR
set -eu
shadelab=$1 program=$2 compare=$3 out=$4
mkdir -p "$out"
rm -f "$out"/f*.png "$out"/r*.png
env -u DISPLAY "$shadelab" run --xvfb --frames 2 --size 400x400 --timeout 30 --capture "$out/f%04d.png" -- "$program"
env -u DISPLAY SHADELAB_REFERENCE=1 "$shadelab" run --xvfb --frames 2 --size 400x400 --timeout 30 \
  --capture "$out/r%04d.png" -- "$program"
for f in 0001 0002; do
  "$compare" "$out/r$f.png" "$out/f$f.png" --diff "$out/d$f.png" --name "frame $f, fast against reference" --min-percent 99.5
done
