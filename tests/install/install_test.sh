#!/usr/bin/env bash
# cmake --install into a temporary prefix, then programs built against that installation only:
# a C++ program through find_package(shadelab) (a CMake project of its own, consumer/), a C
# OSMesa program through pkg-config, run and checked; the installed command renders a scene and,
# when a GLUT or an EGL program is given, runs it through the installed GLVND vendors. Nothing
# is rebuilt. Exit status 77 (skipped) without pkg-config.
#   install_test.sh BUILD_DIR SOURCE_DIR OUT_DIR C_COMPILER CXX_COMPILER [GLUT_PROGRAM] [EGL_PROGRAM]
set -euo pipefail
build=$1 source=$2 out=$3 cc=$4 cxx=$5 glut=${6:-} egl=${7:-}
prefix=$out/prefix
step() { echo "install_test: $*"; }
fail() { echo "FAIL: $*"; exit 1; }
if ! command -v pkg-config >/dev/null; then
  echo "SKIP: pkg-config not installed (scripts/setup.sh --deps)"
  exit 77
fi
rm -rf "$out"
mkdir -p "$out"

step "cmake --install $build --prefix $prefix"
cmake --install "$build" --prefix "$prefix" >"$out/install.log"

libdir=$(cd "$prefix" && dirname "$(find . -name libshadelab.a)")
libdir=${libdir#./}
for f in bin/shadelab "$libdir"/libshadelab.a include/shadelab/render.hpp \
         "$libdir"/libshadelab-gl.so.0 "$libdir"/libshadelab-gl.a "$libdir"/libshadelab-glut.a \
         include/shadelab-gl/GL/gl.h include/shadelab-gl/GL/osmesa.h \
         include/shadelab-gl/GL/shadelab_glut.h "$libdir"/libGLX_shadelab.so.0 \
         "$libdir"/libEGL_shadelab.so.0 share/glvnd/egl_vendor.d/50_shadelab.json \
         "$libdir"/shadelab/libOSMesa.so.8 "$libdir"/cmake/shadelab/shadelabConfig.cmake \
         "$libdir"/cmake/shadelab/shadelabTargets.cmake "$libdir"/pkgconfig/shadelab.pc \
         "$libdir"/pkgconfig/shadelab-gl.pc "$libdir"/pkgconfig/shadelab-glut.pc \
         share/shadelab/scenes/teapot.json; do
  [ -e "$prefix/$f" ] || fail "$f not installed"
done
# Every public header of the source tree, the parts pipeline.hpp includes among them.
for h in $(cd "$source/include" && find shadelab -name '*.hpp'); do
  [ -e "$prefix/include/$h" ] || fail "include/$h not installed"
done
# No installed header may shadow the system's: nothing directly in include/ but the two folders.
extra=$(ls "$prefix/include" | grep -v -x -e shadelab -e shadelab-gl || true)
[ -z "$extra" ] || fail "unexpected in include/: $extra"
# GLVND loads the vendors by soname: no link-time name for them.
for f in "$libdir"/libGLX_shadelab.so "$libdir"/libEGL_shadelab.so; do
  [ ! -e "$prefix/$f" ] || fail "$f installed (the vendors are loaded by soname only)"
done
# Installed binaries do not point back into the build tree.
for f in bin/shadelab "$libdir"/libshadelab-gl.so.0 "$libdir"/libGLX_shadelab.so.0; do
  dynamic=$(readelf -d "$prefix/$f")
  [[ "$dynamic" != *"$build"* ]] || fail "$f has the build folder in its run path"
done

step "the installed Python package"
package=$(cd "$prefix" && find . -path '*dist-packages/shadelab/__init__.py' | head -1)
[ -n "$package" ] || fail "the Python package (shadelab/__init__.py under dist-packages) not installed"
site=$prefix/$(dirname "$(dirname "${package#./}")")
ls "$site"/shadelab/_shadelab*.so >/dev/null 2>&1 || fail "the Python package's native module not installed"
(cd "$out" && PYTHONPATH=$site /usr/bin/python3 -c "
import shadelab
image = shadelab.render('$prefix/share/shadelab/scenes/teapot.json', size=(64, 48))
assert image.shape == (48, 64, 4) and shadelab.__file__.startswith('$site'), shadelab.__file__
") || fail "the installed Python package does not render"

step "the installed command"
"$prefix/bin/shadelab" render "$prefix/share/shadelab/scenes/teapot.json" --size 64x48 \
  -o "$out/teapot.png" >/dev/null
[ -s "$out/teapot.png" ] || fail "shadelab render wrote nothing"
if [ -n "$glut" ]; then
  # `shadelab run` finds the installed vendor (lib/) and libOSMesa.so.8 (lib/shadelab/).
  "$prefix/bin/shadelab" run --xvfb --frames 1 --timeout 60 --capture "$out/glut-%d.png" \
    -- "$glut" >"$out/run.log" 2>&1 || { cat "$out/run.log"; fail "shadelab run"; }
  [ -s "$out/glut-1.png" ] || fail "shadelab run captured no frame"
fi
if [ -n "$egl" ]; then
  # ... and the installed EGL vendor through its JSON file in share/glvnd/egl_vendor.d, headless
  # (only shadelab's EGL vendor has a default display without an X server).
  env -u DISPLAY -u WAYLAND_DISPLAY -u __EGL_VENDOR_LIBRARY_FILENAMES "$prefix/bin/shadelab" run \
    --timeout 60 -- "$egl" >"$out/egl.log" 2>&1 || { cat "$out/egl.log"; fail "shadelab run (EGL)"; }
  grep -q "^ok default_display" "$out/egl.log" || { cat "$out/egl.log"; fail "the EGL vendor"; }
fi

step "find_package(shadelab): consumer/ configured against $prefix"
cmake -S "$source/tests/install/consumer" -B "$out/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_C_COMPILER="$cc" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >"$out/consumer-configure.log" ||
  { cat "$out/consumer-configure.log"; fail "configuring the consumer"; }
grep -qF "shadelab_DIR: $prefix/" "$out/consumer-configure.log" ||
  fail "find_package found another shadelab: $(grep shadelab_DIR "$out/consumer-configure.log")"
cmake --build "$out/consumer" >"$out/consumer-build.log" ||
  { cat "$out/consumer-build.log"; fail "building the consumer"; }
for p in render_scene osmesa_sphere_shared osmesa_sphere_static; do
  "$out/consumer/$p" | tee "$out/$p.txt"
  [ "$(tail -n 1 "$out/$p.txt")" = ok ] || fail "$p"
done
loaded=$(ldd "$out/consumer/osmesa_sphere_shared")
[[ "$loaded" == *"=> $prefix/$libdir/libshadelab-gl.so.0 "* ]] ||
  fail "osmesa_sphere_shared does not load the installed libshadelab-gl: $loaded"

step "pkg-config shadelab-gl shadelab-glut"
export PKG_CONFIG_PATH=$prefix/$libdir/pkgconfig
flags=$(pkg-config --cflags --libs shadelab-glut shadelab-gl)
echo "  $flags"
# The .pc files are relocatable: their folders are relative to the file's (${pcfiledir}/../..).
read -r gl_include _ < <(pkg-config --cflags-only-I shadelab-gl)
[ "$(realpath -m "${gl_include#-I}")" = "$(realpath "$prefix/include/shadelab-gl")" ] ||
  fail "pkg-config: $gl_include is not the installed include/shadelab-gl"
# shellcheck disable=SC2086
"$cc" -std=c11 -Wall -Werror "$source/tests/install/consumer/osmesa_sphere.c" -o "$out/osmesa_pc" \
  $flags -Wl,-rpath,"$(pkg-config --variable=libdir shadelab-gl)"
"$out/osmesa_pc" | tee "$out/osmesa_pc.txt"
[ "$(tail -n 1 "$out/osmesa_pc.txt")" = ok ] || fail "osmesa_pc"
# The core library through pkg-config too: the C++ program above, built with its flags.
# shellcheck disable=SC2086
"$cxx" -std=c++20 "$source/tests/install/consumer/render_scene.cpp" -o "$out/render_scene_pc" \
  $(pkg-config --cflags --libs shadelab)
"$out/render_scene_pc" >/dev/null || fail "render_scene_pc"
echo "install_test: ok"
