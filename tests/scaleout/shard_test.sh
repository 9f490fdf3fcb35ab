#!/usr/bin/env bash
# Batches in shards (docs/scale-out.md): an animation, a two-key sweep and a gallery run as 4
# shards in parallel processes, merged, equal byte for byte to the unsharded outputs; a batch
# resumed after a part is lost; a merge with parts missing refused; the GNU parallel script of
# the document run as written; the animated PNG and MP4 read back by ffprobe.
#   shard_test.sh SHADELAB SOURCE_DIR OUT_DIR
set -euo pipefail
shadelab=$1 source=$2 out=$3
fail() { echo "FAIL: $*"; exit 1; }
step() { echo "shard_test: $*"; }
rm -rf "$out" && mkdir -p "$out" && cd "$out"
scene=$source/scenes/lecture/10-spot-cutoff.json
scenes=$source/tests/scaleout/scenes

# Four shards at once, then the merge; the result must be the unsharded run's bytes.
sharded() {  # OUTPUT COMMAND ARGS... (the command's -o/outdir is OUTPUT)
  local output=$1 pids=() i
  shift
  for i in 1 2 3 4; do
    "$@" --shard "$i/4" >"shard-$i.log" 2>&1 &
    pids+=($!)
  done
  for i in "${!pids[@]}"; do wait "${pids[$i]}" || { cat "shard-$((i + 1)).log"; fail "shard $((i + 1))/4 of $*"; }; done
  "$shadelab" merge "$output" >/dev/null || fail "merge $output"
}

step "animate: 10 frames"
animate=("$shadelab" animate "$scene" --vary 'lights[0].spot.cutoff=5:60' --frames 10 --size 64x64)
"${animate[@]}" -o full.png >/dev/null 2>&1
sharded parts.png "${animate[@]}" -o parts.png
cmp full.png parts.png || fail "the merged animation differs from the unsharded one"
step "animate: a lost part is rendered again by its shard alone"
rm parts.png.parts/part-00006.png
if "$shadelab" merge parts.png >merge.log 2>&1; then fail "merge succeeded with a part missing"; fi
grep -q "1 of 10 parts" merge.log || { cat merge.log; fail "merge did not say which part is missing"; }
before=$(stat -c %Y parts.png.parts/part-00002.png)
sleep 1
"${animate[@]}" -o parts.png --shard 3/4 >/dev/null 2>&1  # part 6 is shard 3's (6 mod 4 + 1)
[ -f parts.png.parts/part-00006.png ] || fail "the shard did not render its missing part"
[ "$(stat -c %Y parts.png.parts/part-00002.png)" = "$before" ] || fail "the shard rendered a part again"
"$shadelab" merge parts.png --remove-parts >/dev/null
cmp full.png parts.png || fail "the resumed animation differs"
[ ! -e parts.png.parts ] || fail "--remove-parts left the parts"
frames=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames,codec_name \
  -of csv=p=0 full.png)
[ "$frames" = "apng,10" ] || fail "ffprobe reads the animated PNG as \"$frames\", not apng with 10 frames"

step "animate: MP4 through ffmpeg, sharded"
orbit=("$shadelab" animate "$source/scenes/teapot.json" --orbit --frames 12 --size 80x60)
"${orbit[@]}" -o orbit.mp4 >/dev/null 2>&1
sharded orbit2.mp4 "${orbit[@]}" -o orbit2.mp4
for f in orbit.mp4 orbit2.mp4; do
  probe=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=codec_name,width,height,nb_read_frames \
    -of csv=p=0 "$f")
  [ "$probe" = "h264,80,60,12" ] || fail "$f: ffprobe says \"$probe\""
done

step "sweep: two keys, six pictures"
sweep=("$shadelab" sweep "$scene" --vary 'lights[0].spot.cutoff=10,20,40' --vary shading=flat,phong --size 40x40)
"${sweep[@]}" -o sheet.png >/dev/null 2>&1
sharded sheet2.png "${sweep[@]}" -o sheet2.png
cmp sheet.png sheet2.png || fail "the merged sweep differs from the unsharded one"

step "gallery: figures, rows and their animations"
"$shadelab" gallery gallery --scenes "$scenes" --samples 4 >/dev/null 2>&1
sharded gallery2 "$shadelab" gallery gallery2 --scenes "$scenes" --samples 4
diff -r gallery gallery2 || fail "the merged gallery differs from the unsharded one"
[ "$(ls gallery | wc -l)" = 7 ] || fail "the gallery has $(ls gallery | wc -l) files, not 7"

step "docs/scale-out.md's GNU parallel script"
PATH=$(dirname "$shadelab"):$PATH "$source/examples/scale-out/parallel.sh" gallery3 4 --scenes "$scenes" --samples 4 \
  >parallel.log 2>&1 || { cat parallel.log; fail "examples/scale-out/parallel.sh"; }
diff -r gallery gallery3 || fail "the gallery from parallel.sh differs"

step "bad input"
if "$shadelab" sweep "$scene" --vary 'lights[0].spot.cutoff=10,20' -o x.png --shard 5/4 2>/dev/null; then
  fail "--shard 5/4 accepted"
fi
if "$shadelab" merge nothing.png 2>/dev/null; then fail "merge without a manifest succeeded"; fi
echo "shard_test: passed"
