#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, AddressSanitizer + UndefinedBehaviorSanitizer) into
# build-fuzz/ and runs them. Fails on any crash, hang, leak, out-of-memory or sanitizer report;
# the reproducer is left in build-fuzz/crashes/. docs/robustness.md says more.
#
#   fuzz/run.sh [SECONDS] [TARGET...]   explore: each target for SECONDS (default 60) from its
#                                       seeds, with a random seed: finds new inputs
#   fuzz/run.sh --ci [TARGET...]        what CI runs: every past finding (fuzz/regressions/)
#                                       once, then a fixed number of executions per target
#                                       from a fixed seed, so that a run is repeatable
#   ... --build DIR                     (after SECONDS or --ci) use the targets of a build
#                                       folder configured elsewhere with the same
#                                       instrumentation and -DSHADELAB_FUZZ=ON (scripts/test.sh
#                                       runs them from build-asan/, which also runs the tests)
#
# e.g. fuzz/run.sh 600 fuzz_gl; a finding is replayed with build-fuzz/fuzz/TARGET FILE.
set -euo pipefail
cd "$(dirname "$0")/.."
ci=0
seconds=60
if [ "${1:-}" = "--ci" ]; then
  ci=1
  shift
elif [ $# -gt 0 ] && [[ "$1" =~ ^[0-9]+$ ]]; then
  seconds="$1"
  shift
fi
build=""
if [ "${1:-}" = "--build" ]; then
  build="$2"
  shift 2
fi
targets=("$@")
all=(fuzz_scene fuzz_obj fuzz_png fuzz_overrides fuzz_vary fuzz_gl fuzz_lab)
[ ${#targets[@]} -gt 0 ] || targets=("${all[@]}")

# Executions per target in --ci mode: about 40 s each on a 2-core machine of the CI's kind.
declare -A ci_runs=([fuzz_scene]=400000 [fuzz_obj]=100000 [fuzz_png]=100000 [fuzz_overrides]=150000
                    [fuzz_vary]=80000 [fuzz_gl]=150000 [fuzz_lab]=50000)

if [ -z "$build" ]; then
  build=build-fuzz
  flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined"
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DSHADELAB_FUZZ=ON -DSHADELAB_BUILD_TESTS=OFF \
    -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" >/dev/null
fi
cmake --build "$build" --target "${targets[@]}"

export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1"
common=(-timeout=10 -rss_limit_mb=2048 -print_final_stats=1)
mkdir -p "$build"/crashes
# One target: its past findings, then the run; prints what happened (the log's end on failure).
fuzz_target() {
  local t="$1" name log work budget
  name="${t#fuzz_}"
  log="$build/$t.log"
  # Past findings first: each must now run clean.
  if [ -d "fuzz/regressions/$name" ]; then
    if ! "$build/fuzz/$t" "${common[@]}" fuzz/regressions/"$name"/* >"$log" 2>&1; then
      echo "fuzz: $t FAILED on a past finding (fuzz/regressions/$name); see $log"
      tail -n 40 "$log"
      return 1
    fi
    echo "fuzz: $t: $(ls "fuzz/regressions/$name" | wc -l) past findings run clean"
  fi
  work="$build/corpus/$name"
  # Exploring keeps what earlier runs found; --ci starts from the checked-in seeds alone.
  [ $ci = 0 ] || rm -rf "$work"
  mkdir -p "$work"
  cp -n "fuzz/corpus/$name"/* "$work"/ 2>/dev/null || true
  if [ $ci = 1 ]; then
    budget=(-seed=1 -runs="${ci_runs[$t]:-100000}" -max_total_time=300)
    echo "fuzz: $t for ${ci_runs[$t]:-100000} executions (seed 1)"
  else
    budget=(-max_total_time="$seconds")
    echo "fuzz: $t for ${seconds}s"
  fi
  if ! "$build/fuzz/$t" "$work" "${budget[@]}" "${common[@]}" \
       -artifact_prefix="$build/crashes/$t-" 2>"$log"; then
    echo "fuzz: $t FAILED; see $log and $build/crashes/"
    tail -n 40 "$log"
    return 1
  fi
  grep -E '^stat::number_of_executed_units|^#[0-9]+.*DONE' "$log" | tail -n 2 || true
  return 0
}

# The targets run side by side, one per core (each libFuzzer process is single-threaded); each
# one's report is printed whole, in the order given.
parallel=$(nproc)
status=0
pids=()
for i in "${!targets[@]}"; do
  fuzz_target "${targets[$i]}" >"$build/${targets[$i]}.report" 2>&1 &
  pids[$i]=$!
  while [ "$(jobs -rp | wc -l)" -ge "$parallel" ]; do wait -n || true; done
done
for i in "${!targets[@]}"; do
  wait "${pids[$i]}" || status=1
  cat "$build/${targets[$i]}.report"
done
exit $status
