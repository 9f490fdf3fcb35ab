#!/usr/bin/env bash
# `shadelab run` against bad input and misbehaving programs: exit statuses and messages.
#   run_cli.sh SHADELAB MISBEHAVE GLUT_PROGRAM OUT_DIR
set -u
shadelab=$1 misbehave=$2 glut=$3 out=$4
mkdir -p "$out"
failures=0
expect() {  # expect STATUS TEXT -- COMMAND...: the status, and TEXT in stderr (empty: anything)
  local want=$1 text=$2
  shift 3
  local err="$out/stderr"
  "$@" 2>"$err" >/dev/null
  local got=$?
  if [ "$got" != "$want" ] || { [ -n "$text" ] && ! grep -qF -- "$text" "$err"; }; then
    echo "FAIL: $* -> status $got (want $want), stderr: $(cat "$err")"
    failures=$((failures + 1))
  else
    echo "ok: status $got: $*"
  fi
}
unset DISPLAY
expect 2 "is required" -- "$shadelab" run
expect 2 "--capture" -- "$shadelab" run --capture out.png -- "$misbehave" status 0
expect 2 "--size" -- "$shadelab" run --size 12 -- "$misbehave" status 0
expect 2 "" -- "$shadelab" run --frames 0 -- "$misbehave" status 0
expect 127 "cannot run" -- "$shadelab" run -- "$out/no-such-program"
expect 7 "" -- "$shadelab" run -- "$misbehave" status 7
expect 139 "signal 11" -- "$shadelab" run -- "$misbehave" crash
expect 124 "did not end within" -- "$shadelab" run --timeout 1 --frames 1 -- "$misbehave" hang
# No display and no --xvfb: the GLUT program's own failure (freeglut cannot open the display).
expect 1 "" -- "$shadelab" run -- "$glut" --frames 1
# Xvfb that cannot be started (not on PATH).
expect 1 "Xvfb" -- env PATH=/nonexistent "$shadelab" run --xvfb -- "$misbehave" status 0
# A program ended after its frames: what it printed into its buffered standard output is not lost.
"$shadelab" run --xvfb --frames 1 -- "$glut" --say "printed before the first frame" >"$out/said.txt" 2>/dev/null
said=$(cat "$out/said.txt")
if [ "$said" = "printed before the first frame" ]; then
  echo "ok: the program's buffered output reaches the pipe when --frames ends it"
else
  echo "FAIL: the program's buffered output was lost when --frames ended it (got: '$said')"; failures=$((failures + 1))
fi

# A program that ends before its frames are counted: its own status, and a note.
expect 0 "ended after" -- "$shadelab" run --xvfb --frames 50 -- "$glut" --frames 2
# --explain needs a pixel; a frame the program never shows is said (status 1).
expect 2 "--explain" -- "$shadelab" run --explain 12 -- "$misbehave" status 0
expect 1 "drew nothing in frame 5" -- "$shadelab" run --xvfb --scene-frame 5 --capture-scene "$out/none.json" -- "$glut" --frames 2
# A single-buffered window's frame is its glFlush.
rm -f "$out/single.json"
expect 0 "frame 1 written" -- "$shadelab" run --xvfb --frames 1 --capture-scene "$out/single.json" -- "$glut" --single
if [ -s "$out/single.json" ] && grep -q '"objects"' "$out/single.json"; then
  echo "ok: a single-buffered frame is captured"
else
  echo "FAIL: no scene for the single-buffered frame"; failures=$((failures + 1))
fi
# --size: the window is resized before its first frame.
rm -f "$out"/size-*.png
"$shadelab" run --xvfb --frames 2 --size 200x150 --capture "$out/size-%d.png" -- "$glut" >/dev/null 2>&1
if file "$out/size-2.png" 2>/dev/null | grep -q "200 x 150" || python3 -c "
import struct,sys; d=open('$out/size-2.png','rb').read(24); sys.exit(0 if struct.unpack('>II', d[16:24])==(200,150) else 1)"; then
  echo "ok: --size 200x150 gives 200x150 frames"
else
  echo "FAIL: --size 200x150 did not give 200x150 frames"; failures=$((failures + 1))
fi
echo "$failures failed"
[ "$failures" = 0 ]
