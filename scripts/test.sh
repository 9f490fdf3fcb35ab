#!/usr/bin/env bash
# Builds shadelab (installing missing Debian packages first) and runs every test with ctest,
# then the whole suite again under AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/),
# the test program (every render there draws on threads) under ThreadSanitizer (build-tsan/),
# and every fuzz target: its past findings, then a fixed, repeatable number of executions
# (build-fuzz/; about 40 s each); any sanitizer report or crash fails.
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

scripts/setup.sh --build
ctest --test-dir build --output-on-failure -j "$(nproc)"
[ "$quick" = 1 ] && exit 0

sanitized_build() {  # DIR FLAGS [TARGET...]
  local dir="$1" flags="$2"
  shift 2
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="$flags" -DCMAKE_SHARED_LINKER_FLAGS="$flags" >/dev/null
  if [ $# -gt 0 ]; then cmake --build "$dir" --target "$@"; else cmake --build "$dir"; fi
}

echo "test: AddressSanitizer + UndefinedBehaviorSanitizer"
sanitized_build build-asan "-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
# Leaks inside Mesa's libraries and reports from interceptors Mesa calls (the conformance
# reference) are suppressed; nothing of ours.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:suppressions=$PWD/tests/sanitizers/asan.supp"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
ctest --test-dir build-asan --output-on-failure -j "$(nproc)"

echo "test: ThreadSanitizer (the unit, rendering and differential tests: all draw on threads; GL clears ahead)"
sanitized_build build-tsan "-fsanitize=thread" shadelab_tests gl_clear_ahead
TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1" build-tsan/tests/shadelab_tests
TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1" build-tsan/tests/steady/gl_clear_ahead

echo "test: fuzzing: past findings, then a repeatable run per target (fuzz/run.sh --ci; docs/robustness.md)"
fuzz/run.sh --ci
