#!/usr/bin/env bash
# The screenshots of docs/view.md: convray's +D preview window on an Xvfb server of its own,
# captured with ImageMagick's import while the render fills it and once it is done.
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
echo "wrote $out/view-filling.png and $out/view-done.png"
