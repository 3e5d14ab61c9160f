#!/usr/bin/env bash
# POV-Ray's +D preview window on a real X server (Xvfb), driven as a person would with xdotool:
#   1. +D +P: the window shows the written picture, byte for byte (a screenshot compared with
#      the PNG), the file is the one -D writes; a key closes it, convray exits 0, no window
#      is left;
#   2. +D alone (-P): the window closes by itself at the end;
#   3. a partial render shows its rectangle only; a picture wider than 1280 pixels is scaled
#      down to fit (PSNR against the file scaled alike above 40 dB);
#   4. an animation shows each frame: at the end, the last one;
#   5. q during a render stops it: exit 1, the message, the previous file untouched.
# Where Xvfb, xdotool or ImageMagick is missing it says why and exits 77, which CTest reports
# as skipped, never as passed. Every process it starts (Xvfb, convray) is ended by its PID.
#
# usage: preview_window_test.sh CONVRAY SOURCE_DIR
set -uo pipefail
convray=$1
source_dir=$2
scene=$source_dir/scenes/soup.pov

test_name="preview window test"
# shellcheck source=xvfb_session.sh
source "$(dirname "${BASH_SOURCE[0]}")/xvfb_session.sh" 1600x1200

# Starts convray in the background (its PID in convray_pid), output in NAME.out, NAME.err.
start() {
  local name=$1
  shift
  "$convray" "$@" >"$name.out" 2>"$name.err" &
  convray_pid=$!
}

# Waits for convray's exit; its status in `status`. A run that outlives 30 s is killed.
finish() {
  local waited=0
  while kill -0 "$convray_pid" 2>/dev/null && [ $waited -lt 300 ]; do
    sleep 0.1
    waited=$((waited + 1))
  done
  kill "$convray_pid" 2>/dev/null && fail "convray still running after 30 s: killed"
  wait "$convray_pid"
  status=$?
  convray_pid=""
}

# The preview window's id, once it is mapped and its title says +P holds it (the finished
# picture is drawn before that title is set).
window_when_done() {
  local id
  id=$(timeout 20 xdotool search --sync --onlyvisible --name '^convray: ' | head -1)
  [ -n "$id" ] || return 1
  for _ in $(seq 200); do
    case "$(xdotool getwindowname "$id" 2>/dev/null)" in
      *"(press a key or close)") echo "$id"; return 0 ;;
    esac
    sleep 0.1
  done
  return 1
}

# Pixels that differ between two pictures of the same size (ImageMagick's absolute error).
differing_pixels() {
  compare -metric AE "$1" "$2" null: 2>&1 | awk '{print $1}'
}

no_window_left() {
  if xdotool search --name '^convray: ' >/dev/null 2>&1; then
    fail "$1: a convray window is still open"
  fi
}

# 1. +D +P: the window shows the file's pixels; a key closes it.
"$convray" "$scene" +W160 +H120 -D -o plain.png >/dev/null || fail "the -D render failed"
start shown "$scene" +W160 +H120 +D +P -o shown.png
if id=$(window_when_done); then
  geometry=$(xwininfo -id "$id" | awk '/Width:/ {w=$2} /Height:/ {h=$2} END {print w "x" h}')
  [ "$geometry" = 160x120 ] || fail "+D +P: the window is $geometry, not 160x120"
  import -window "$id" shown-screen.png
  differ=$(differing_pixels shown-screen.png shown.png)
  [ "$differ" = 0 ] || fail "+D +P: $differ pixels on screen differ from the file"
  kill -0 "$convray_pid" 2>/dev/null || fail "+P: convray ended before a key was pressed"
  xdotool windowfocus --sync "$id" key space
else
  fail "+D +P: no finished preview window within 20 s"
fi
finish
[ "$status" = 0 ] || fail "+D +P: exit status $status: $(cat shown.err)"
cmp -s shown.png plain.png || fail "+D +P: the file differs from the -D render's"
grep -q "press a key" shown.err || fail "+P: no word on how to close the window"
no_window_left "+D +P"

# 2. +D alone: the window closes when the render is done. Anti-aliased, so that it stays up
# (a second or two) long enough to be seen.
slow_switches=(+W240 +H180 +A0.0 +R2)
"$convray" "$scene" "${slow_switches[@]}" -D -o closing-plain.png >/dev/null || fail "-D +A render"
start closing "$scene" "${slow_switches[@]}" +D -o closing.png
timeout 20 xdotool search --sync --name '^convray: ' >/dev/null || fail "+D: no window seen"
finish
[ "$status" = 0 ] || fail "+D: exit status $status: $(cat closing.err)"
cmp -s closing.png closing-plain.png || fail "+D: the file differs from the -D render's"
no_window_left "+D -P"

# 3a. A partial render: the window is its rectangle (columns 41-120, rows 31-90).
start part "$scene" +W160 +H120 +SC41 +EC120 +SR31 +ER90 +D +P -o part.png
if id=$(window_when_done); then
  import -window "$id" part-screen.png
  convert part.png -crop 80x60+40+30 +repage part-crop.png
  differ=$(differing_pixels part-screen.png part-crop.png)
  [ "$differ" = 0 ] || fail "partial +D: $differ pixels differ from the file's rectangle"
  xdotool windowfocus --sync "$id" key space
else
  fail "partial +D: no finished preview window"
fi
finish
[ "$status" = 0 ] || fail "partial +D: exit status $status: $(cat part.err)"

# 3b. Wider than 1280 pixels: scaled down to 1280 x 274 (nearest pixels; compared with the
# file sampled alike, PSNR above 40 dB).
cat >ball.pov <<'POV'
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -4> look_at <0, 0.6, 0> }
light_source { <5, 5, -5> color rgb 1 }
background { rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { rgb <0.4, 0.35, 0.3> } }
sphere { <0, 0.8, 0>, 0.8 pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.5 } }
POV
start wide ball.pov +W1400 +H300 +D +P -o wide.png
if id=$(window_when_done); then
  geometry=$(xwininfo -id "$id" | awk '/Width:/ {w=$2} /Height:/ {h=$2} END {print w "x" h}')
  [ "$geometry" = 1280x274 ] || fail "wide +D: the window is $geometry, not 1280x274"
  import -window "$id" wide-screen.png
  convert wide.png -sample '1280x274!' wide-sampled.png
  psnr=$(compare -metric PSNR wide-screen.png wide-sampled.png null: 2>&1 | awk '{print $1}')
  awk -v p="$psnr" 'BEGIN {exit !(p == "inf" || p > 40)}' ||
    fail "wide +D: PSNR $psnr dB against the file, not above 40"
  echo "wide +D: PSNR $psnr dB against the file sampled to the window's size"
  xdotool windowfocus --sync "$id" key space
else
  fail "wide +D: no finished preview window"
fi
finish
[ "$status" = 0 ] || fail "wide +D: exit status $status: $(cat wide.err)"

# 4. An animation: one window; at the end it shows the last frame.
start frames ball.pov +W120 +H90 +KFI1 +KFF3 +D +P -o frame.png
if id=$(window_when_done); then
  case "$(xdotool getwindowname "$id")" in
    *"frame 3 (3/3), done"*) ;;
    *) fail "animation +D: the title at the end is '$(xdotool getwindowname "$id")'" ;;
  esac
  import -window "$id" frames-screen.png
  differ=$(differing_pixels frames-screen.png frame3.png)
  [ "$differ" = 0 ] || fail "animation +D: $differ pixels differ from the last frame"
  xdotool windowfocus --sync "$id" key space
else
  fail "animation +D: no finished preview window"
fi
finish
[ "$status" = 0 ] || fail "animation +D: exit status $status: $(cat frames.err)"
no_window_left "animation"

# 5. q during a long render stops it; the file that was there stays as it was.
echo "the previous picture" >slow.png
start slow "$scene" +W640 +H480 +A0 +R9 +WT1 +D -o slow.png
if id=$(timeout 20 xdotool search --sync --onlyvisible --name '^convray: '); then
  xdotool windowfocus --sync "$id" key q
fi
finish
[ "$status" = 1 ] || fail "q: exit status $status, not 1: $(cat slow.err)"
grep -q "render stopped: the preview window was closed" slow.err ||
  fail "q: no message saying the render stopped: $(cat slow.err)"
[ "$(cat slow.png)" = "the previous picture" ] || fail "q: the previous slow.png was changed"
no_window_left "q"

if [ $failures -gt 0 ]; then
  echo "preview window test: $failures failures"
  exit 1
fi
echo "preview window test: all passed"
