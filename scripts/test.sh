#!/usr/bin/env bash
# Builds shadelab (installing missing Debian packages first) and runs every test with ctest;
# then builds it again with clang, AddressSanitizer + UndefinedBehaviorSanitizer and libFuzzer's
# coverage (build-asan/), runs the whole suite there and every fuzz target from the same build:
# its past findings, then a fixed, repeatable number of executions; then the test program (every
# render there draws on threads) under ThreadSanitizer (build-tsan/). Any sanitizer report or
# crash fails. The sanitized builds compile the SIMD code for AVX2 and the portable target
# only (SHADELAB_SIMD_TARGETS=reduced). At the end, even after a failure, it prints each
# stage's wall time and the CPU time of its processes (docs/robustness.md).
#
#   scripts/test.sh           everything (what CI runs)
#   scripts/test.sh --quick   the normal build's tests only
set -euo pipefail
cd "$(dirname "$0")/.."

quick=0
case "${1:-}" in
  --quick) quick=1 ;;
  "") ;;
  *) echo "usage: scripts/test.sh [--quick]" >&2; exit 2 ;;
esac

# --- stage times -----------------------------------------------------------------------------
# Wall time, and the user + system time of every process the stage ran (from this shell's
# cutime/cstime): on a shared machine the CPU time shows a regression that the wall time hides.
stage_names=()
stage_walls=()
stage_cpus=()
stage_results=()
current_stage=""
stage_wall_start=0
stage_cpu_start=0
clock_ticks=$(getconf CLK_TCK)
script_start=$SECONDS

children_cpu_ticks() {  # user + system ticks of this shell's finished children
  local stat
  stat=$(< "/proc/$$/stat")
  stat=${stat##*) }
  local fields
  read -ra fields <<< "$stat"
  echo $((fields[13] + fields[14]))
}

stage_begin() {  # NAME
  current_stage="$1"
  stage_wall_start=$SECONDS
  stage_cpu_start=$(children_cpu_ticks)
  echo "test: == $current_stage"
}

stage_end() {  # RESULT
  stage_names+=("$current_stage")
  stage_walls+=($((SECONDS - stage_wall_start)))
  stage_cpus+=($(( ($(children_cpu_ticks) - stage_cpu_start) / clock_ticks )))
  stage_results+=("$1")
  current_stage=""
}

stage() {  # NAME COMMAND... : runs the command as a stage (set -e ends the script on failure)
  stage_begin "$1"
  shift
  "$@"
  stage_end ok
}

mmss() { printf '%d:%02d' $(($1 / 60)) $(($1 % 60)); }

print_stage_times() {
  local status=$?
  [ -z "$current_stage" ] || stage_end "FAILED (exit $status)"
  echo
  echo "test: stage times (wall; CPU = user + system time of the stage's processes)"
  printf '  %-46s %8s %8s  %s\n' stage wall CPU result
  local i cpu_total=0
  for i in "${!stage_names[@]}"; do
    printf '  %-46s %8s %8s  %s\n' "${stage_names[$i]}" "$(mmss "${stage_walls[$i]}")" \
      "$(mmss "${stage_cpus[$i]}")" "${stage_results[$i]}"
    cpu_total=$((cpu_total + stage_cpus[i]))
  done
  printf '  %-46s %8s %8s  %s\n' total "$(mmss $((SECONDS - script_start)))" "$(mmss $cpu_total)" \
    "$([ "$status" = 0 ] && echo ok || echo "FAILED (exit $status)")"
  exit "$status"
}
trap print_stage_times EXIT
trap 'exit 130' INT TERM

# --- the stages ------------------------------------------------------------------------------
jobs=$(nproc)

sanitized_configure() {  # DIR FLAGS [CMAKE OPTION...]
  local dir="$1" flags="$2"
  shift 2
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADELAB_SIMD_TARGETS=reduced \
    -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="$flags" -DCMAKE_SHARED_LINKER_FLAGS="$flags" "$@" >/dev/null
}

# One build serves the sanitized test run and the fuzz targets: clang, ASan + UBSan (clang's
# UBSan also checks float-to-integer conversions), and libFuzzer's coverage instrumentation.
asan_build() {
  sanitized_configure build-asan \
    "-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DSHADELAB_FUZZ=ON
  cmake --build build-asan
}

tsan_build() {
  sanitized_configure build-tsan -fsanitize=thread
  cmake --build build-tsan --target shadelab_tests gl_clear_ahead
}

sanitizer_tests() {
  # Leaks inside Mesa's libraries and reports from interceptors Mesa calls (the conformance
  # reference) are suppressed; nothing of ours.
  # (Exported: the later stages run with them too.)
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:suppressions=$PWD/tests/sanitizers/asan.supp"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
  ctest --test-dir build-asan --output-on-failure -j "$jobs"
}

tsan_run() {
  export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$PWD/tests/sanitizers/tsan.supp"
  # The test program in two halves side by side (its tests are mostly single-threaded).
  local pids=() status=0 i
  for i in 0 1; do
    GTEST_TOTAL_SHARDS=2 GTEST_SHARD_INDEX=$i build-tsan/tests/shadelab_tests \
      >"build-tsan/shadelab_tests.$i.log" 2>&1 &
    pids+=($!)
  done
  for i in 0 1; do
    if ! wait "${pids[$i]}"; then
      status=1
      echo "test: ThreadSanitizer run, half $i, FAILED:"
      tail -n 60 "build-tsan/shadelab_tests.$i.log"
    else
      tail -n 3 "build-tsan/shadelab_tests.$i.log"
    fi
  done
  build-tsan/tests/steady/gl_clear_ahead || status=1
  return $status
}

stage "set-up and build (build/)" scripts/setup.sh --build
stage "tests (build/)" ctest --test-dir build --output-on-failure -j "$jobs"
[ "$quick" = 1 ] && exit 0
stage "sanitizer build (build-asan/, clang)" asan_build
stage "sanitizer tests (ASan + UBSan)" sanitizer_tests
stage "fuzzing (fuzz/run.sh --ci, in build-asan/)" fuzz/run.sh --ci --build build-asan
stage "ThreadSanitizer build (build-tsan/)" tsan_build
stage "ThreadSanitizer run" tsan_run
