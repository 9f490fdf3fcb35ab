#!/usr/bin/env bash
# GLX through GLVND on shadelab (run inside with_xvfb.sh): glx_contexts' functional checks on
# shadelab's vendor, then the wrong calls of `glx_contexts --errors` on Mesa and on shadelab,
# whose answers (return values and X/GLX error codes) must be the same.
#   glx_test.sh VENDOR_DIR PROGRAM OUT_DIR
set -eu
vendor_dir=$1 program=$2 out=$3
mkdir -p "$out"
export LD_LIBRARY_PATH="$vendor_dir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
__GLX_VENDOR_LIBRARY_NAME=shadelab "$program"
__GLX_VENDOR_LIBRARY_NAME=mesa "$program" --errors >"$out/errors.mesa"
__GLX_VENDOR_LIBRARY_NAME=shadelab "$program" --errors >"$out/errors.shadelab"
diff -u "$out/errors.mesa" "$out/errors.shadelab"
echo "errors as Mesa's: $(grep -c . "$out/errors.shadelab") lines"
