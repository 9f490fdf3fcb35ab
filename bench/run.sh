#!/usr/bin/env bash
# shadelab against Mesa on the same programs, on this machine (docs/performance.md).
#
#   bench/run.sh [--frames N] [--rounds R] [--quick] [--no-softpipe] [--no-sweeps]
#                [--no-corpus | --corpus-only] [--corpus-targets "best avx2"] [--out DIR]
#
# Builds the benchmark programs into build/, then runs each scene in turn with Mesa's
# llvmpipe, Mesa's softpipe and libshadelab-gl (the same GL 1.x source, bench/gl_bench.c), and
# the per-pixel Phong scene with llvmpipe running a GLSL shader against shadelab's Phong mode.
# Prints a table of median frame times and the ratio shadelab / llvmpipe, checks that each
# pair of images agrees within the conformance bar, then sweeps triangle count, resolution and
# thread count, writing CSV files and, with gnuplot, PNG plots into the output folder
# (default out/bench). Timings are medians of N frames (default 10) after 2 warm-up frames.
# With --rounds R (default 1), each scene runs R times, llvmpipe and shadelab alternating:
# the table shows the median of each side's R medians and the median of the R ratios, which
# a shared machine's bursts of load move far less than a single pair.
# Then the corpus (bench/corpus.c: the kinds of program people run, one scene each): each
# scene with llvmpipe and with shadelab, each at the better of 1 and all threads, the ratio,
# whether the images agree, and whether any fragment left the SIMD path (SHADELAB_STATS); its
# last line names the worst ratio. The corpus runs once at the best SIMD target the machine
# has and once with AVX2 forced (the target of machines without AVX-512; --corpus-targets
# names others: best, avx512, avx2, sse4, ssse3, scalar), a table each. The script fails if a
# corpus scene's images disagree or shadelab drew fragments on the scalar reference path.
# SHADELAB_BUILD_DIR chooses the build folder (default build); SHADELAB_SIMD (avx512, avx2,
# sse4, ssse3, scalar) the instruction set shadelab's SIMD code runs (the corpus then runs at
# that target alone).
set -euo pipefail
cd "$(dirname "$0")/.."

frames=10
rounds=1
softpipe=1
sweeps=1
quick=0
corpus=1
corpus_targets="best avx2"
[ -z "${SHADELAB_SIMD:-}" ] || corpus_targets=$SHADELAB_SIMD
scenes=1
out=out/bench
while [ $# -gt 0 ]; do
  case "$1" in
    --frames) frames="$2"; shift 2 ;;
    --rounds) rounds="$2"; shift 2 ;;
    --quick) quick=1; shift ;;
    --no-softpipe) softpipe=0; shift ;;
    --no-sweeps) sweeps=0; shift ;;
    --no-corpus) corpus=0; shift ;;
    --corpus-only) scenes=0; sweeps=0; shift ;;
    --corpus-targets) corpus_targets="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    -h|--help) sed -n '2,26p' "$0"; exit 0 ;;
    *) echo "bench/run.sh: unknown option $1" >&2; exit 2 ;;
  esac
done

build=${SHADELAB_BUILD_DIR:-build}
if [ ! -f "$build/build.ninja" ]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" --target bench_gl_mesa bench_gl_shadelab bench_phong_glsl \
  bench_phong_shadelab bench_corpus_mesa bench_corpus_shadelab gl_compare >/dev/null
mkdir -p "$out"
B=$build/bench
cores=$(nproc)
export MESA_SHADER_CACHE_DISABLE=true MESA_DEBUG=silent LP_NUM_THREADS="$cores"

# median_ms of one run: run COMMAND... -> prints the median in ms.
median() { "$@" | sed -n 's/.*median_ms=\([0-9.]*\).*/\1/p'; }
llvmpipe() { GALLIUM_DRIVER=llvmpipe "$@"; }
softpipe_run() { GALLIUM_DRIVER=softpipe "$@"; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.3f", a / b; else print "-" }'; }
# The median of its arguments.
median_of() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { printf "%s", (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# paired MESA_COMMAND -- SHADELAB_COMMAND: runs the pair `rounds` times, alternating, and sets
# l, m (the medians of their frame-time medians) and r (the median of the rounds' ratios).
paired() {
  local mesa=() ours=() ls=() ms=() rs=() a b k
  while [ "$1" != -- ]; do mesa+=("$1"); shift; done
  shift
  ours=("$@")
  for ((k = 0; k < rounds; ++k)); do
    a=$(median "${mesa[@]}")
    b=$(median "${ours[@]}")
    ls+=("$a"); ms+=("$b"); rs+=("$(ratio "$b" "$a")")
  done
  l=$(median_of "${ls[@]}"); m=$(median_of "${ms[@]}"); r=$(median_of "${rs[@]}")
}

echo "machine: $(lscpu | sed -n 's/^Model name: *//p' | head -1), $cores cores; Mesa: $(dpkg-query -W -f='${Version}' libosmesa6 2>/dev/null || echo '?')"
echo "frames: median of $frames after 2 warm-up frames, 1920x1080; $rounds round(s) per scene, alternating"
if [ "$scenes" = 1 ]; then
  printf '\n%-34s %12s %12s %12s %16s  %s\n' scene "llvmpipe ms" "softpipe ms" "shadelab ms" "shadelab/llvmpipe" "images"
  csv="$out/scenes.csv"
  echo "scene,llvmpipe_ms,softpipe_ms,shadelab_ms,ratio" > "$csv"
  big_triangles=1000000
  [ "$quick" = 1 ] && big_triangles=100000
  run_scene() {  # label, then the arguments of bench_gl_*
    local label="$1"; shift
    local l s=- m r agree
    paired llvmpipe $B/bench_gl_mesa "$@" --frames "$frames" --png "$out/$label.mesa.png" -- \
      $B/bench_gl_shadelab "$@" --frames "$frames" --png "$out/$label.shadelab.png"
    if [ "$softpipe" = 1 ]; then
      s=$(median softpipe_run $B/bench_gl_mesa "$@" --frames 3 --warmup 0)
    fi
    agree=$($build/tests/gl-conformance/gl_compare "$out/$label.mesa.png" "$out/$label.shadelab.png" \
              --name "$label" --diff "$out/$label.diff.png" | sed -n 's/^RESULT .*within2=\([0-9.]*\).* \(PASS\|FAIL\)$/\1% \2/p')
    printf '%-34s %12s %12s %12s %16s  %s\n' "$label" "$l" "$s" "$m" "$r" "$agree"
    echo "$label,$l,$s,$m,$r" >> "$csv"
  }
  run_scene "a-sphere-${big_triangles}-8-lights" sphere --triangles "$big_triangles"
  run_scene "b-shiny-teapot" teapot
  run_scene "c-fill-wall-2-layers" fill
  # The sphere's mesh again, compiled once into a display list (glBegin/glEnd) and called each
  # frame: next to (a), what a list costs against glDrawElements.
  run_scene "e-sphere-${big_triangles}-display-list" list --triangles "$big_triangles"
  paired llvmpipe $B/bench_phong_glsl --frames "$frames" --png "$out/d-phong.mesa.png" -- \
    $B/bench_phong_shadelab --frames "$frames" --png "$out/d-phong.shadelab.png"
  agree=$($build/tests/gl-conformance/gl_compare "$out/d-phong.mesa.png" "$out/d-phong.shadelab.png" \
            --name d-phong --diff "$out/d-phong.diff.png" | sed -n 's/^RESULT .*within2=\([0-9.]*\).* \(PASS\|FAIL\)$/\1% \2/p')
  printf '%-34s %12s %12s %12s %16s  %s\n' "d-phong-8-lights (GLSL on Mesa)" "$l" - "$m" "$r" "$agree"
  echo "d-phong-8-lights,$l,-,$m,$r" >> "$csv"
fi

# --- the corpus ------------------------------------------------------------------------------
# smaller A B: the smaller of two times.
smaller() { awk -v a="$1" -v b="$2" 'BEGIN { print (a + 0 < b + 0) ? a : b }'; }
# The median frame time of a corpus program at the better of 1 and all threads.
best_llvmpipe() {
  smaller "$(LP_NUM_THREADS=1 median llvmpipe "$@")" "$(LP_NUM_THREADS=$cores median llvmpipe "$@")"
}
best_shadelab() {
  smaller "$(SHADELAB_THREADS=1 median "$@")" "$(SHADELAB_THREADS=$cores median "$@")"
}
corpus_status=0
# run_corpus TARGET: the corpus table with shadelab's SIMD code at TARGET ("best": the
# machine's best), into $out/corpus.csv (best) or $out/corpus-TARGET.csv.
run_corpus() {
  local C=$B scene l m r agree stats ref worst=0 worst_scene="" ratios=() csv="$out/corpus.csv" ran
  local simd="" saved=${SHADELAB_SIMD:-}
  [ "$1" = best ] || { simd=$1; csv="$out/corpus-$1.csv"; }
  export SHADELAB_SIMD=$simd
  rm -f "$out/corpus-target.stats"
  SHADELAB_STATS="$out/corpus-target.stats" "$C/bench_corpus_shadelab" empty --frames 1 --warmup 0 >/dev/null
  ran=$(sed -n 's/.*target=\([^ ]*\).*/\1/p' "$out/corpus-target.stats" | head -1)
  rm -f "$out/corpus-target.stats"
  echo
  echo "corpus (bench/corpus.c), 1920x1080, shadelab's SIMD target $1 ($ran); each side at the better"
  echo "of 1 and $cores threads; scalar = fragments shadelab drew on the reference path (SHADELAB_STATS), 0 expected"
  printf '%-22s %12s %12s %16s  %-14s %s\n' scene "llvmpipe ms" "shadelab ms" "shadelab/llvmpipe" images scalar
  echo "scene,llvmpipe_ms,shadelab_ms,ratio,within2,reference_fragments" > "$csv"
  for scene in $("$C/bench_corpus_mesa" --list); do
    local ls=() ms=() rs=() k a b
    for ((k = 0; k < rounds; ++k)); do
      a=$(best_llvmpipe "$C/bench_corpus_mesa" "$scene" --frames "$frames")
      b=$(best_shadelab "$C/bench_corpus_shadelab" "$scene" --frames "$frames")
      ls+=("$a"); ms+=("$b"); rs+=("$(ratio "$b" "$a")")
    done
    l=$(median_of "${ls[@]}"); m=$(median_of "${ms[@]}"); r=$(median_of "${rs[@]}")
    llvmpipe "$C/bench_corpus_mesa" "$scene" --frames 1 --warmup 0 --png "$out/corpus-$scene.mesa.png" >/dev/null
    stats="$out/corpus-$scene.stats"
    rm -f "$stats"
    SHADELAB_STATS="$stats" "$C/bench_corpus_shadelab" "$scene" --frames 1 --warmup 0 \
      --png "$out/corpus-$scene.shadelab.png" >/dev/null
    ref=$(sed -n 's/.* reference=\([0-9]*\).*/\1/p' "$stats" | awk '{ n += $1 } END { print n + 0 }')
    agree=$($build/tests/gl-conformance/gl_compare "$out/corpus-$scene.mesa.png" "$out/corpus-$scene.shadelab.png" \
              --name "$scene" --diff "$out/corpus-$scene.diff.png" | sed -n 's/^RESULT .*within2=\([0-9.]*\).* \(PASS\|FAIL\)$/\1% \2/p')
    printf '%-22s %12s %12s %16s  %-14s %s\n' "$scene" "$l" "$m" "$r" "$agree" "$ref"
    echo "$scene,$l,$m,$r,${agree%%%*},$ref" >> "$csv"
    [ "$ref" = 0 ] || corpus_status=1
    case "$agree" in *PASS) ;; *) corpus_status=1 ;; esac
    ratios+=("$r")
    if awk -v a="$r" -v b="$worst" 'BEGIN { exit !(a + 0 > b + 0) }'; then worst=$r; worst_scene=$scene; fi
  done
  echo "corpus at $1 ($ran): median ratio $(median_of "${ratios[@]}"), worst $worst ($worst_scene), $(printf '%s\n' "${ratios[@]}" | awk '$1 >= 1' | wc -l) of ${#ratios[@]} scenes at or above llvmpipe's time"
  [ "$corpus_status" = 0 ] || echo "corpus: FAILED: images disagree or fragments left the SIMD path (above)"
  export SHADELAB_SIMD=$saved
}

if [ "$corpus" = 1 ]; then
  for target in $corpus_targets; do run_corpus "$target"; done
fi

[ "$sweeps" = 1 ] || exit "$corpus_status"

echo; echo "sweep: triangles (sphere, 8 lights, 1920x1080) -> $out/triangles.csv"
echo "triangles,llvmpipe_ms,shadelab_ms" > "$out/triangles.csv"
counts="1000 4000 16000 64000 256000 1000000 4000000"
[ "$quick" = 1 ] && counts="1000 16000 256000"
for n in $counts; do
  l=$(median llvmpipe $B/bench_gl_mesa sphere --triangles "$n" --frames "$frames")
  m=$(median $B/bench_gl_shadelab sphere --triangles "$n" --frames "$frames")
  echo "$n,$l,$m" | tee -a "$out/triangles.csv"
done

echo; echo "sweep: resolution (the shiny teapot) -> $out/resolution.csv"
echo "pixels,size,llvmpipe_ms,shadelab_ms" > "$out/resolution.csv"
for size in 640x480 1280x720 1920x1080 2560x1440 3840x2160; do
  l=$(median llvmpipe $B/bench_gl_mesa teapot --size "$size" --frames "$frames")
  m=$(median $B/bench_gl_shadelab teapot --size "$size" --frames "$frames")
  px=$(( ${size%x*} * ${size#*x} ))
  echo "$px,$size,$l,$m" | tee -a "$out/resolution.csv"
done

echo; echo "sweep: threads (sphere 1M, and Phong) -> $out/threads.csv"
echo "threads,sphere_llvmpipe_ms,sphere_shadelab_ms,phong_llvmpipe_ms,phong_shadelab_ms" > "$out/threads.csv"
for t in $(seq 1 "$cores"); do
  sl=$(LP_NUM_THREADS=$t median llvmpipe $B/bench_gl_mesa sphere --triangles "$big_triangles" --frames "$frames")
  sm=$(SHADELAB_THREADS=$t median $B/bench_gl_shadelab sphere --triangles "$big_triangles" --frames "$frames")
  pl=$(LP_NUM_THREADS=$t median llvmpipe $B/bench_phong_glsl --frames "$frames")
  pm=$(SHADELAB_THREADS=$t median $B/bench_phong_shadelab --frames "$frames")
  echo "$t,$sl,$sm,$pl,$pm" | tee -a "$out/threads.csv"
done

if command -v gnuplot >/dev/null; then
  gnuplot <<EOF
set terminal pngcairo size 800,500 font "DejaVu Sans,11"
set datafile separator ","
set key top left
set grid
set ylabel "frame time (ms, median)"
set output "$out/triangles.png"
set title "Frame time against triangle count (sphere, 8 point lights, 1920x1080)"
set logscale xy
set xlabel "triangles"
plot "$out/triangles.csv" every ::1 using 1:2 with linespoints title "Mesa llvmpipe", \
     "" every ::1 using 1:3 with linespoints title "shadelab"
set output "$out/resolution.png"
set title "Frame time against resolution (the shiny teapot)"
set xlabel "pixels"
plot "$out/resolution.csv" every ::1 using 1:3 with linespoints title "Mesa llvmpipe", \
     "" every ::1 using 1:4 with linespoints title "shadelab"
set output "$out/threads.png"
set title "Frame time against threads"
unset logscale
set xlabel "threads"
set xtics 1
plot "$out/threads.csv" every ::1 using 1:2 with linespoints title "sphere, llvmpipe", \
     "" every ::1 using 1:3 with linespoints title "sphere, shadelab", \
     "" every ::1 using 1:4 with linespoints title "Phong, llvmpipe (GLSL)", \
     "" every ::1 using 1:5 with linespoints title "Phong, shadelab"
EOF
  echo; echo "plots: $out/triangles.png $out/resolution.png $out/threads.png"
else
  echo; echo "gnuplot is not installed (scripts/setup.sh installs gnuplot-nox): no plots"
fi
exit "$corpus_status"
