#!/usr/bin/env bash
# Instructions executed per frame of each benchmark scene, counted by valgrind (cachegrind
# without its cache model) on one thread: the same number on every run, where frame times on a
# shared machine move by 20% or more from run to run. Use it to compare two builds of a
# change; frame times (bench/run.sh) stay the measure. valgrind runs the AVX2 code (it does not
# emulate AVX-512), so the counts are those of the AVX2 target.
#   SHADELAB_BUILD_DIR=build bench/instructions.sh [SCENE...]   scenes: sphere teapot fill phong
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SHADELAB_BUILD_DIR:-build}
command -v valgrind >/dev/null || { echo "bench/instructions.sh: valgrind is missing (scripts/setup.sh --deps)" >&2; exit 2; }
cmake --build "$build" --target bench_gl_shadelab bench_phong_shadelab >/dev/null
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(sphere teapot fill phong)

# instructions FRAMES SCENE: the whole run's count.
instructions() {
  local cmd
  if [ "$2" = phong ]; then cmd=("$build/bench/bench_phong_shadelab")
  else cmd=("$build/bench/bench_gl_shadelab" "$2"); fi
  local log
  log=$(SHADELAB_THREADS=1 valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null \
    "${cmd[@]}" --frames "$1" --warmup 0 2>&1 >/dev/null) || return 0  # no count: the caller says why
  sed -n 's/.*I *refs: *//p' <<<"$log" | tr -d ,
}
printf '%-8s %22s\n' scene "instructions / frame"
for scene in "${scenes[@]}"; do
  case "$scene" in sphere|teapot|fill|phong) ;; *) echo "bench/instructions.sh: unknown scene $scene" >&2; exit 2 ;; esac
  two=$(instructions 2 "$scene")
  four=$(instructions 4 "$scene")
  if [ -z "$two" ] || [ -z "$four" ]; then
    # valgrind 3.19 stops at an instruction it does not know (on some CPUs, libhwy's timer
    # setup executes RDTSCP when the library loads) and prints no count.
    echo "bench/instructions.sh: valgrind could not run the $scene benchmark on this machine" >&2
    exit 1
  fi
  printf '%-8s %22s\n' "$scene" "$(( (four - two) / 2 ))"   # setup and warm-up cancel out
done
