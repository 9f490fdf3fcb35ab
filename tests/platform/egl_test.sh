#!/usr/bin/env bash
# EGL through GLVND on shadelab, headless (no X server, no DISPLAY): egl_surfaceless' functional
# checks on shadelab's vendor (selected by its JSON file alone), then the wrong calls of
# `egl_surfaceless --errors` on Mesa and on shadelab, whose answers must be the same.
# Last, the program through `shadelab run`, which must select shadelab's EGL vendor itself.
#   egl_test.sh SHADELAB_JSON PROGRAM SHADELAB OUT_DIR
set -eu
json=$1 program=$2 shadelab=$3 out=$4
mkdir -p "$out"
unset DISPLAY WAYLAND_DISPLAY
mesa_json=$(ls /usr/share/glvnd/egl_vendor.d/*mesa*.json | head -1)
__EGL_VENDOR_LIBRARY_FILENAMES="$json" "$program"
__EGL_VENDOR_LIBRARY_FILENAMES="$mesa_json" "$program" --errors >"$out/errors.mesa"
__EGL_VENDOR_LIBRARY_FILENAMES="$json" "$program" --errors >"$out/errors.shadelab"
diff -u "$out/errors.mesa" "$out/errors.shadelab"
echo "errors as Mesa's: $(grep -c . "$out/errors.shadelab") lines"
env -u __EGL_VENDOR_LIBRARY_FILENAMES "$shadelab" run -- "$program" >"$out/run.out"
grep -q "^ok default_display" "$out/run.out"  # only shadelab's vendor has a headless default display
echo "shadelab run selects the EGL vendor"
