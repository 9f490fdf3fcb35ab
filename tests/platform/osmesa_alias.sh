#!/usr/bin/env bash
# libOSMesa.so.8 is shadelab: a conformance program built against Mesa's libOSMesa, unchanged,
# loads shadelab's libOSMesa.so.8 through LD_LIBRARY_PATH and draws exactly what the same
# program built against libshadelab-gl draws.
#   osmesa_alias.sh PLATFORM_DIR MESA_BUILT_PROGRAM SHADELAB_BUILT_PROGRAM GL_COMPARE OUT_DIR
set -eu
dir=$1 mesa_built=$2 shadelab_built=$3 compare=$4 out=$5
mkdir -p "$out"
loaded=$(LD_TRACE_LOADED_OBJECTS=1 LD_LIBRARY_PATH="$dir" "$mesa_built" | grep 'libOSMesa.so.8 =>')
echo "$loaded"
case "$loaded" in *"$dir/libOSMesa.so.8"*) ;; *) echo "FAIL: Mesa's libOSMesa was loaded"; exit 1 ;; esac
LD_LIBRARY_PATH="$dir" "$mesa_built" "$out/alias.png"
"$shadelab_built" "$out/shadelab.png"
"$compare" "$out/shadelab.png" "$out/alias.png" --tolerance 0 --min-percent 100 --name osmesa-alias \
  --diff "$out/alias-diff.png"
