#!/usr/bin/env bash
# A GLUT + GLU program built with -lGL -lGLU -lglut, run unchanged on Mesa (llvmpipe through
# GLX) and through `shadelab run --capture` on the same Xvfb, and again through
# `shadelab run --xvfb` on a server of its own; each captured frame is compared with Mesa's at
# the conformance bar (gl_compare: 99.5 % of pixels within 2/255), and with the program's own
# glReadPixels of the same frame on shadelab (identical: the capture is what the window shows);
# then the same program single-buffered (GLUT_SINGLE, frames shown by glFlush).
#   glut_vs_mesa.sh SHADELAB PROGRAM PPM_TO_PNG GL_COMPARE OUT_DIR   (run inside with_xvfb.sh)
set -eu
shadelab=$1 program=$2 ppm_to_png=$3 compare=$4 out=$5
name=$(basename "$program")
rm -rf "$out" && mkdir -p "$out"
frame=3

__GLX_VENDOR_LIBRARY_NAME=mesa "$program" --frames $frame --dump $frame "$out/mesa.ppm"
"$ppm_to_png" "$out/mesa.ppm" "$out/mesa.png"

"$shadelab" run --frames $frame --capture "$out/shadelab-%d.png" -- "$program" --dump $frame "$out/shadelab.ppm"
test -f "$out/shadelab-1.png" -a -f "$out/shadelab-$frame.png" -a ! -f "$out/shadelab-$((frame + 1)).png"
"$ppm_to_png" "$out/shadelab.ppm" "$out/shadelab-readpixels.png"
"$compare" "$out/shadelab-readpixels.png" "$out/shadelab-$frame.png" --tolerance 0 --min-percent 100 \
  --name "$name.capture-is-readpixels" --diff "$out/capture-diff.png"
"$compare" "$out/mesa.png" "$out/shadelab-$frame.png" --name "$name" --diff "$out/diff.png"

env -u DISPLAY "$shadelab" run --xvfb --frames $frame --capture "$out/own-xvfb-%d.png" -- "$program"
"$compare" "$out/mesa.png" "$out/own-xvfb-$frame.png" --name "$name.own-xvfb" --diff "$out/own-diff.png"

# GLUT_SINGLE: a frame is the display callback's glFlush.
__GLX_VENDOR_LIBRARY_NAME=mesa "$program" --single --frames $frame --dump $frame "$out/mesa-single.ppm"
"$ppm_to_png" "$out/mesa-single.ppm" "$out/mesa-single.png"
"$shadelab" run --frames $frame --capture "$out/single-%d.png" -- "$program" --single
"$compare" "$out/mesa-single.png" "$out/single-$frame.png" --name "$name.single" --diff "$out/single-diff.png"
