#!/usr/bin/env bash
# The screenshots of docs/view.md, on an Xvfb server of its own, captured with ImageMagick's
# import: convray view's loop (a save: the coarse picture, then the full one; a syntax error;
# the keys and a radius edit), and the +D preview window while the render fills it and once
# it is done.
# Usage: bash scripts/make-view-images.sh   (after a build; needs xvfb, xdotool, imagemagick)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
convray=$PWD/build/convray
out=$PWD/docs/images/view
mkdir -p "$out"
tmp=$(mktemp -d)
xvfb_pid=""
convray_pid=""
cleanup() {
  [ -n "$convray_pid" ] && kill "$convray_pid" 2>/dev/null || true
  [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT

Xvfb -displayfd 3 -screen 0 1600x1200x24 -nolisten tcp 3>"$tmp/display" 2>/dev/null &
xvfb_pid=$!
for _ in $(seq 100); do [ -s "$tmp/display" ] && break; sleep 0.1; done
export DISPLAY=":$(head -1 "$tmp/display")"
unset WAYLAND_DISPLAY SDL_VIDEODRIVER

# Waits until the title of window $id matches the extended regular expression $1.
wait_title() {
  for _ in $(seq 1500); do
    xdotool getwindowname "$id" | grep -Eq "$1" && return 0
    sleep 0.02
  done
  echo "the title never matched '$1'" >&2
  return 1
}

# convray view on a copy of soup.pov (its mesh found through -L scenes), named as a user in
# that folder would name it, so that the overlays say soup.pov, not the temporary folder.
cp scenes/soup.pov "$tmp/soup.pov"
(cd "$tmp" && exec "$convray" view soup.pov --size 480x360 --antialias -L "$OLDPWD/scenes") \
  >/dev/null 2>&1 &
convray_pid=$!
id=$(timeout 20 xdotool search --sync --onlyvisible --name '^convray view: ' | head -1)
wait_title ', done$'
# A save (a warmer background): caught as the full picture starts over the coarse one.
sed -i 's/color rgb <0.78, 0.84, 0.92>/color rgb <0.92, 0.84, 0.74>/' "$tmp/soup.pov"
wait_title ', [0-9]{1,2}%$'
import -window "$id" "$out/loop-coarse.png"
wait_title ', done$'
import -window "$id" "$out/loop-done.png"
cp "$tmp/soup.pov" "$tmp/good.pov"
printf 'sphere { <0, 0, 0>, 1\n  pigment { colour rgb 1 }\n  oops\n}\n' >>"$tmp/soup.pov"
wait_title ', error$'
sleep 0.2
import -window "$id" "$out/loop-error.png"
cp "$tmp/good.pov" "$tmp/soup.pov"
wait_title ', done$'
xdotool key --window "$id" h
xdotool mousemove --window "$id" 345 190 key --window "$id" R key --window "$id" R
sleep 1
wait_title ', done$'
sleep 0.2
import -window "$id" "$out/loop-keys.png"
xdotool key --window "$id" q 2>/dev/null || true  # its key-up may find the window gone
wait "$convray_pid"
convray_pid=""

# Anti-aliased on one thread, so that the window is caught half filled, tile by tile.
"$convray" scenes/soup.pov +W400 +H300 +A0.0 +R4 +WT1 +D +P -o "$tmp/soup.png" >/dev/null 2>&1 &
convray_pid=$!
id=$(timeout 20 xdotool search --sync --onlyvisible --name '^convray: ' | head -1)
sleep 0.6
import -window "$id" "$out/view-filling.png"
until xdotool getwindowname "$id" | grep -q 'press a key'; do sleep 0.2; done
import -window "$id" "$out/view-done.png"
xdotool windowfocus --sync "$id" key space
wait "$convray_pid"
convray_pid=""
echo "wrote $out/loop-{coarse,done,error,keys}.png, view-filling.png and view-done.png"
