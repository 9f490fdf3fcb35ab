#!/usr/bin/env bash
# piglit (Debian's `piglit` package), the OpenGL implementations' test suite, on shadelab and on
# Mesa's llvmpipe on this machine: the tests of quick_gl's "spec@!opengl 1.0" ... "1.5" groups
# that need no more than the OpenGL version shadelab reports (its glGetString(GL_VERSION), read
# through glxinfo) and no GLSL, run with PIGLIT_PLATFORM=glx under a private Xvfb through
# shadelab's GLX vendor and through Mesa's; prints pass / fail / skip / crash counts side by side
# and the tests whose results differ (docs/platform.md). Installs nothing: scripts/setup.sh does.
#
#   tests/piglit/run.sh [--build DIR] [--out DIR] [--timeout S] [--shadelab-only] [--up-to 1.N]
#   tests/piglit/run.sh --ci [--build DIR] [--out DIR]
#
# --up-to 1.N takes the groups up to "!opengl 1.N" whatever version shadelab reports (the
# report then also shows what the tests of the next version's group already do).
#
# --ci runs only the fixed list tests/piglit/ci-pass.txt (tests that pass on llvmpipe and on
# shadelab today, under a second each; those of the groups the reported version selects) on
# shadelab, and fails unless every one passes: the ctest
# `piglit.ci`. Exit status otherwise: 0 (the report is the output), 2 for bad arguments or a
# missing tool.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${SHADELAB_BUILD:-$root/build}
out="" timeout=60 shadelab_only=0 ci=0 up_to=""
while (($#)); do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --timeout) timeout=$2; shift 2 ;;
    --shadelab-only) shadelab_only=1; shift ;;
    --up-to) up_to=$2; shift 2 ;;
    --ci) ci=1; shadelab_only=1; shift ;;
    *) echo "usage: tests/piglit/run.sh [--ci] [--build DIR] [--out DIR] [--timeout S] [--shadelab-only] [--up-to 1.N]" >&2; exit 2 ;;
  esac
done
out=${out:-$build/piglit}
vendor=$(cd "$build" 2>/dev/null && pwd)/gl/platform
for tool in piglit Xvfb glxinfo python3; do
  command -v "$tool" >/dev/null || { echo "run.sh: $tool not found (scripts/setup.sh installs it)" >&2; exit 2; }
done
[ -f "$vendor/libGLX_shadelab.so.0" ] || { echo "run.sh: no $vendor/libGLX_shadelab.so.0 (build the shadelab-glx target)" >&2; exit 2; }

# Every run has an X server of its own, never the caller's DISPLAY.
if [ -z "${SHADELAB_PIGLIT_XVFB:-}" ]; then
  SHADELAB_PIGLIT_XVFB=1 exec "$root/tests/platform/with_xvfb.sh" "$0" --build "$build" --out "$out" \
    --timeout "$timeout" $([ $ci = 1 ] && echo --ci) $([ $shadelab_only = 1 ] && [ $ci = 0 ] && echo --shadelab-only) \
    ${up_to:+--up-to "$up_to"}
fi

shadelab_env=(env "LD_LIBRARY_PATH=$vendor${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" __GLX_VENDOR_LIBRARY_NAME=shadelab)
llvmpipe_env=(env __GLX_VENDOR_LIBRARY_NAME=mesa GALLIUM_DRIVER=llvmpipe LP_NUM_THREADS=0 MESA_SHADER_CACHE_DISABLE=true)
version=$("${shadelab_env[@]}" glxinfo -B | sed -n 's/^OpenGL version string: \([0-9]*\.[0-9]*\).*/\1/p')
[ -n "$version" ] || { echo "run.sh: glxinfo could not create a context on shadelab" >&2; exit 1; }
major=${version%.*} minor=${version#*.}
((major > 1)) && minor=5
if [ -n "$up_to" ]; then
  [[ "$up_to" =~ ^1\.[0-5]$ ]] || { echo "run.sh: --up-to: expected 1.0 to 1.5" >&2; exit 2; }
  minor=${up_to#1.}
fi
# The groups up to the version shadelab reports; GLSL tests need OpenGL 2.0 and are left out.
select=(-t "spec@!opengl 1\\.[0-$minor]@" -x glsl -x shader)
mkdir -p "$out"

# --ci: the listed tests of those groups (a test of a newer group cannot run: piglit refuses the
# functions of a version above the reported one; GL_VERSION is the newest version none of whose
# commands is pending in the GL front end, gl/api/pending.txt).
ci_list="$out/ci-pass.txt"
if [ $ci = 1 ]; then
  grep -E "^spec@!opengl 1\.[0-$minor]@" "$here/ci-pass.txt" >"$ci_list" || true
fi

run_piglit() {  # NAME ENV...: results in $out/NAME
  local name=$1
  shift
  local list=()
  [ $ci = 1 ] && list=(--test-list "$ci_list")
  "$@" PIGLIT_PLATFORM=glx piglit run quick_gl "${select[@]}" "${list[@]}" -p glx --timeout "$timeout" \
    -l dummy -o -n "$name" "$out/$name" >"$out/$name.log" 2>&1 || true
}

echo "piglit: OpenGL $version reported by shadelab: groups !opengl 1.0 to 1.$minor, without GLSL"
[ $ci = 1 ] && echo "piglit: only the tests of $here/ci-pass.txt in those groups ($(wc -l <"$ci_list") of $(grep -c '^spec@' "$here/ci-pass.txt"))"
start=$SECONDS
run_piglit shadelab "${shadelab_env[@]}"
echo "piglit: shadelab ran in $((SECONDS - start)) s"
if [ $shadelab_only = 0 ]; then
  start=$SECONDS
  run_piglit llvmpipe "${llvmpipe_env[@]}"
  echo "piglit: llvmpipe ran in $((SECONDS - start)) s"
fi
args=(--out "$out" --version "$version" --up-to "1.$minor")
[ $shadelab_only = 1 ] && args+=(--shadelab-only)
[ $ci = 1 ] && args+=(--require-pass "$ci_list")
python3 "$here/summary.py" "${args[@]}" | tee "$out/summary.txt"
