#!/usr/bin/env bash
# Takes a fresh Debian 12 machine to a built shadelab: installs the Debian packages the project
# needs (only those missing), builds everything, and renders the shiny teapot and the lecture's
# gallery into out/.
#   scripts/setup.sh            install, build, render
#   scripts/setup.sh --deps     install packages only
#   scripts/setup.sh --build    install and build, render nothing
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  build-essential cmake ninja-build pkg-config ccache
  dpkg-dev file  # cpack -G DEB: dpkg-shlibdeps for the package's Depends, `file` to find its ELF files
  python3 khronos-api  # gl/api/generate.py: the GL entry points from the OpenGL registry (gl.xml)
  libglm-dev nlohmann-json3-dev libcli11-dev libtinyobjloader-dev
  libpng-dev libjpeg62-turbo-dev  # PNG read and written with libpng, JPEG read with libjpeg-turbo
  libstb-dev  # stb_truetype (contact sheets' labels), stb_image_write (lecture, conformance, bench C programs)
  libgtest-dev libgmock-dev fonts-dejavu-core libhwy-dev libbenchmark-dev libcpp-httplib-dev
  libosmesa6-dev  # Mesa: the oracle of the GL conformance suite and the benchmarks
  # shadelab as a GLVND vendor (libGLX_shadelab) and its tests: X11, GLVND's vendor headers,
  # GLUT and GLU programs, Xvfb, and Mesa's own GLX vendor (llvmpipe) to compare with
  libx11-dev libxext-dev libglvnd-dev freeglut3-dev libglu1-mesa-dev xvfb libgl1-mesa-dri libglx-mesa0
  piglit mesa-utils  # tests/piglit/run.sh: piglit's GL 1.x tests, glxinfo for the GL version
  # the Python module (python/): pybind11, numpy; its tests run with pytest, the example
  # notebook with nbclient on an IPython kernel
  pybind11-dev python3-dev python3-numpy python3-pytest python3-nbclient python3-nbformat python3-ipykernel
  ffmpeg parallel # shadelab animate's MP4/WebM output; GNU parallel in docs/scale-out.md (tested)
  gnuplot-nox     # bench/run.sh plots
  valgrind        # bench/instructions.sh: instructions per frame, steady on a noisy machine
  chromium firefox-esr nodejs  # the lab's browser tests (driven by playwright-core and puppeteer-core from npm)
  clang libclang-rt-14-dev     # libFuzzer for fuzz/run.sh
)

install_packages() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if ((${#missing[@]})); then
    local sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    echo "setup: installing ${missing[*]}"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
  fi
}

build() {
  # playwright-core for the lab's browser tests, at the version package-lock.json pins (npm
  # comes with some nodejs packages; Debian's is installed only when it is missing).
  if ! command -v npm >/dev/null; then
    PACKAGES=(npm)
    install_packages
  fi
  (cd tests/lab/browser && npm ci --no-audit --no-fund --loglevel=error)
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
  cmake --build build
}

render_examples() {
  mkdir -p out
  ./build/shadelab render scenes/teapot.json -o out/teapot.png
  echo "setup: rendered out/teapot.png (the lecture's shiny red teapot)"
  ./build/shadelab gallery out/gallery
}

case "${1:-all}" in
  --deps) install_packages ;;
  --build) install_packages; build ;;
  all) install_packages; build; render_examples ;;
  *) echo "usage: scripts/setup.sh [--deps|--build]" >&2; exit 2 ;;
esac
