#!/usr/bin/env bash
# cpack -G DEB from the built tree (nothing is rebuilt), then the package: its contents
# (dpkg-deb -c), its control fields (dpkg-deb -f: the Debian packages it depends on), and what it
# carries, unpacked into a scratch root (dpkg-deb -x): its `shadelab render` renders scenes from
# its scenes/ as the build's command does, with LD_LIBRARY_PATH pointing inside the root; an
# OSMesa program built through its pkg-config files runs on its libshadelab-gl; the consumer
# project builds through its CMake package. Exit status 77 (skipped) when a tool it needs is
# missing.
#   deb_test.sh BUILD_DIR SOURCE_DIR OUT_DIR C_COMPILER CXX_COMPILER BUILD_SHADELAB
set -euo pipefail
build=$1 source=$2 out=$3 cc=$4 cxx=$5 built_shadelab=$6
fail() { echo "FAIL: $*"; exit 1; }
step() { echo "deb_test: $*"; }

# cpack's DEB generator needs dpkg-shlibdeps (dpkg-dev) for the Depends it computes and `file`
# to find the ELF files it hands it.
missing=()
for tool in cpack dpkg-deb dpkg-shlibdeps file pkg-config; do
  command -v "$tool" >/dev/null || missing+=("$tool")
done
if ((${#missing[@]})); then
  echo "SKIP: ${missing[*]} not installed (dpkg-dev, file, pkg-config: scripts/setup.sh --deps)"
  exit 77
fi

rm -rf "$out"
mkdir -p "$out"
step "cpack -G DEB"
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$out" >"$out/cpack.log" 2>&1 ||
  { cat "$out/cpack.log"; fail "cpack"; }
debs=("$out"/shadelab_*.deb)
[ -f "${debs[0]}" ] || fail "no shadelab_*.deb in $out"
deb=${debs[0]}
step "$(basename "$deb"), $(stat -c %s "$deb") bytes"

# Contents. The library folder is the build's CMAKE_INSTALL_LIBDIR (lib, or lib/<multiarch>).
dpkg-deb -c "$deb" | awk '{print $6}' | sed 's|^\./|/|' >"$out/files.txt"
grep -q 'dist-packages/shadelab/__init__\.py$' "$out/files.txt" || fail "no Python package in the package"
lib=$(grep '/libshadelab\.a$' "$out/files.txt" | head -1)
[ -n "$lib" ] || fail "no libshadelab.a in the package"
libdir=$(dirname "$lib")
for f in /usr/bin/shadelab "$libdir"/libshadelab.a /usr/include/shadelab/render.hpp \
         "$libdir"/libshadelab-gl.so.0 "$libdir"/libshadelab-gl.so "$libdir"/libshadelab-gl.a \
         /usr/include/shadelab-gl/GL/gl.h /usr/include/shadelab-gl/GL/osmesa.h \
         /usr/include/shadelab-gl/GL/shadelab_glut.h "$libdir"/libshadelab-glut.a \
         "$libdir"/libGLX_shadelab.so.0 "$libdir"/libEGL_shadelab.so.0 \
         /usr/share/glvnd/egl_vendor.d/50_shadelab.json "$libdir"/shadelab/libOSMesa.so.8 \
         "$libdir"/cmake/shadelab/shadelabConfig.cmake "$libdir"/cmake/shadelab/shadelabTargets.cmake \
         "$libdir"/pkgconfig/shadelab.pc "$libdir"/pkgconfig/shadelab-gl.pc \
         "$libdir"/pkgconfig/shadelab-glut.pc /usr/share/shadelab/scenes/teapot.json; do
  grep -qx -- "$f" "$out/files.txt" || fail "$f not in the package"
done
# Every public header of the source tree, the parts pipeline.hpp includes among them.
for h in $(cd "$source/include" && find shadelab -name '*.hpp'); do
  grep -qx -- "/usr/include/$h" "$out/files.txt" || fail "/usr/include/$h not in the package"
done
# Nothing outside /usr, no header straight in /usr/include, nothing named like the system's GL
# libraries in the library folder, no link-time name for the vendors (GLVND loads them by soname).
if grep -v -e '^/$' -e '^/usr/' "$out/files.txt"; then fail "files outside /usr"; fi
if grep -E '^/usr/include/[^/]+$' "$out/files.txt"; then fail "headers directly in /usr/include"; fi
if grep -E "^$libdir/lib(GL|EGL|GLX|OpenGL|OSMesa)\.so" "$out/files.txt"; then
  fail "a library named like the system's in $libdir"
fi
if grep -E "^$libdir/lib(GLX|EGL)_shadelab\.so$" "$out/files.txt"; then fail "vendor namelinks"; fi

# Control fields: the runtime libraries dpkg-shlibdeps found, and the development packages of
# the headers and the static core library.
[ "$(dpkg-deb -f "$deb" Package)" = shadelab ] || fail "Package is not shadelab"
depends=$(dpkg-deb -f "$deb" Depends)
step "Depends: $depends"
for p in libc6 libstdc++6 libpng16-16 libhwy1 libx11-6 fonts-dejavu-core libglm-dev libpng-dev \
         libhwy-dev libtinyobjloader-dev libstb-dev; do
  [[ ", $depends," == *", $p "* || ", $depends," == *", $p,"* ]] || fail "Depends lacks $p"
done

step "dpkg-deb -x into $out/root"
root=$out/root
dpkg-deb -x "$deb" "$root"
export LD_LIBRARY_PATH=$root$libdir
# The EGL vendor's JSON names the library by its soname, found in the library folder.
grep -q '"library_path" *: *"libEGL_shadelab.so.0"' "$root/usr/share/glvnd/egl_vendor.d/50_shadelab.json" ||
  fail "50_shadelab.json does not name libEGL_shadelab.so.0"

# The packaged command renders the packaged scenes (a textured one too), the same bytes as the
# build's command.
for scene in teapot lecture/14-emission-night; do
  name=$(basename "$scene")
  "$root/usr/bin/shadelab" render "$root/usr/share/shadelab/scenes/$scene.json" --size 64x48 \
    -o "$out/$name.png" >/dev/null || fail "the packaged shadelab cannot render $scene.json"
  "$built_shadelab" render "$source/scenes/$scene.json" --size 64x48 -o "$out/$name.build.png" >/dev/null
  cmp -s "$out/$name.png" "$out/$name.build.png" ||
    fail "the packaged shadelab renders $scene.json differently from the build's"
done
step "the packaged shadelab renders the packaged scenes as the build's does"

# An OSMesa program through the package's pkg-config files (relocatable: they find the root
# from their own folder), no run path: libshadelab-gl.so.0 comes from LD_LIBRARY_PATH.
export PKG_CONFIG_PATH=$root$libdir/pkgconfig
# shellcheck disable=SC2046
"$cc" -std=c11 -Wall -Werror "$source/tests/install/consumer/osmesa_sphere.c" -o "$out/osmesa_pc" \
  $(pkg-config --cflags --libs shadelab-glut shadelab-gl)
loaded=$(ldd "$out/osmesa_pc")
[[ "$loaded" == *"=> $root$libdir/libshadelab-gl.so.0 "* ]] ||
  fail "osmesa_pc does not load the packaged libshadelab-gl: $loaded"
"$out/osmesa_pc" | tee "$out/osmesa_pc.txt"
[ "$(tail -n 1 "$out/osmesa_pc.txt")" = ok ] || fail "osmesa_pc"

# The consumer project through the package's CMake package (its static libraries stripped of
# their debug information by cpack).
cmake -S "$source/tests/install/consumer" -B "$out/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_C_COMPILER="$cc" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_PREFIX_PATH="$root/usr" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >"$out/consumer-configure.log" 2>&1 ||
  { cat "$out/consumer-configure.log"; fail "configuring the consumer"; }
grep -qF "shadelab_DIR: $root/usr/" "$out/consumer-configure.log" ||
  fail "find_package found another shadelab: $(grep shadelab_DIR "$out/consumer-configure.log")"
cmake --build "$out/consumer" >"$out/consumer-build.log" 2>&1 ||
  { cat "$out/consumer-build.log"; fail "building the consumer"; }
for p in render_scene osmesa_sphere_shared osmesa_sphere_static; do
  "$out/consumer/$p" >"$out/$p.txt" || { cat "$out/$p.txt"; fail "$p"; }
  [ "$(tail -n 1 "$out/$p.txt")" = ok ] || fail "$p"
done
step "the consumer project builds and runs against the package"
echo "deb_test: ok"
