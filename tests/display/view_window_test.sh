#!/usr/bin/env bash
# convray view on a real X server (Xvfb), driven as a person would with xdotool, the window
# read back with a screenshot (ImageMagick's import) and compared with file renders:
#   1. the window shows the file render's picture, byte for byte;
#   2. an edit of the scene file, saved, renders again: the window shows the new file render;
#   3. a syntax error: file:line:col on standard error and in the window (red text at the
#      bottom), the last good picture kept above it; fixing the file clears it;
#   4. a left drag turns the view; c prints a camera block that, pasted into the scene,
#      renders what the window shows; s writes the same picture;
#   5. R over the right-hand object prints its edited header, and the window shows the scene
#      with that header written in;
#   6. q closes the window: exit 0, no window left.
# Where Xvfb, xdotool or ImageMagick is missing it says why and exits 77 (skipped, never
# passed). Every process it starts (Xvfb, convray) is ended by its PID.
#
# usage: view_window_test.sh CONVRAY SOURCE_DIR
set -uo pipefail
convray=$1
source_dir=$2

test_name="view window test"
# shellcheck source=xvfb_session.sh
source "$(dirname "${BASH_SOURCE[0]}")/xvfb_session.sh" 1280x1024
[ -f /usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf ] ||
  skip "the overlay font is missing (apt-get install fonts-dejavu-core)"

size=(+W160 +H120)
library=(-L "$source_dir/scenes")
cp "$source_dir/scenes/soup.pov" scene.pov

# The file render of SCENE into OUT.
render() { "$convray" "$1" "${size[@]}" "${library[@]}" -D -o "$2" >/dev/null 2>render.err ||
  fail "the render of $1 failed: $(cat render.err)"; }

differing_pixels() { compare -metric AE "$1" "$2" null: 2>&1 | awk '{print $1}'; }

# Waits until the window's title ends in ", done" (or `$1`); 30 s at most.
wait_title() {
  local want=${1:-done}
  for _ in $(seq 300); do
    case "$(xdotool getwindowname "$id" 2>/dev/null)" in *", $want") return 0 ;; esac
    sleep 0.1
  done
  fail "the title never said '$want' (it says '$(xdotool getwindowname "$id" 2>/dev/null)')"
  return 1
}

# Screenshots until the window shows PNG exactly (20 s at most); 0 when it does. With a
# second argument `below-text`, the top 24 rows are left out: a key's message is drawn there
# for a few seconds.
wait_for_picture() {
  for _ in $(seq 100); do
    import -window "$id" screen.png 2>/dev/null
    if [ "${2:-}" = below-text ]; then
      convert screen.png -crop 160x96+0+24 +repage screen-below.png
      convert "$1" -crop 160x96+0+24 +repage want-below.png
      [ "$(differing_pixels screen-below.png want-below.png)" = 0 ] && return 0
    else
      [ "$(differing_pixels screen.png "$1")" = 0 ] && return 0
    fi
    sleep 0.2
  done
  return 1
}

"$convray" view scene.pov --size 160x120 "${library[@]}" -o saved.png >view.out 2>view.err &
convray_pid=$!
id=$(timeout 20 xdotool search --sync --onlyvisible --name '^convray view: ' | head -1)
[ -n "$id" ] || { fail "no view window within 20 s: $(cat view.err)"; exit 1; }

# 1. The window shows the file render.
render scene.pov file.png
wait_title done
geometry=$(xwininfo -id "$id" | awk '/Width:/ {w=$2} /Height:/ {h=$2} END {print w "x" h}')
[ "$geometry" = 160x120 ] || fail "the window is $geometry, not 160x120"
wait_for_picture file.png || fail "the window does not show the file render ($(differing_pixels screen.png file.png) pixels differ)"

# 2. An edit, saved, renders again.
sed -i 's/background { color rgb <0.78, 0.84, 0.92> }/background { color rgb <0.9, 0.5, 0.3> }/' scene.pov
render scene.pov edited.png
wait_for_picture edited.png || fail "the saved edit was not rendered ($(differing_pixels screen.png edited.png) pixels differ)"
cp scene.pov good.pov

# 3. A syntax error: its place on stderr and in the window, the last picture kept above it.
printf 'sphere { <0, 0, 0>, 1\n  pigment { colour rgb 1 }\n  oops\n}\n' >>scene.pov
errline=$(($(wc -l <good.pov) + 3))
wait_title error
sleep 0.3
import -window "$id" error-screen.png
grep -q "scene.pov:$errline:3: " view.err || fail "no scene.pov:$errline:3: on stderr: $(cat view.err)"
convert error-screen.png -crop 160x60+0+0 +repage top-now.png
convert edited.png -crop 160x60+0+0 +repage top-before.png
[ "$(differing_pixels top-now.png top-before.png)" = 0 ] || fail "the last picture was not kept above the error"
convert error-screen.png -crop 160x22+0+98 +repage band-now.png
convert edited.png -crop 160x22+0+98 +repage band-before.png
changed=$(differing_pixels band-now.png band-before.png)
[ "$changed" -gt 100 ] 2>/dev/null || fail "no error text drawn at the bottom ($changed pixels changed)"
reddish=$(convert band-now.png -fx '(r > 0.8 && g < 0.6) ? 1 : 0' -format '%[fx:round(mean*w*h)]' info:)
[ "$reddish" -gt 10 ] 2>/dev/null || fail "the error text is not red ($reddish red pixels)"
cp good.pov scene.pov
wait_for_picture edited.png || fail "fixing the error did not clear it"

# 4. A left drag turns the view; c prints it; the block renders what the window shows.
xdotool mousemove --window "$id" 60 60 mousedown 1 mousemove --window "$id" 90 50 \
  mousemove --window "$id" 110 45 mouseup 1
sleep 0.5
wait_title done
import -window "$id" dragged.png
[ "$(differing_pixels dragged.png edited.png)" -gt 1000 ] || fail "the drag did not change the view"
xdotool key --window "$id" c
for _ in $(seq 50); do grep -q '^}' view.out && break; sleep 0.1; done
awk '/^camera \{/ {on=1; block=""} on {block = block $0 "\n"} /^\}/ && on {on=0; last=block}
     END {printf "%s", last}' view.out >camera.txt
grep -q "look_at" camera.txt || fail "c printed no camera block: $(cat view.out)"
# The scene with its camera replaced by the printed block (soup.pov's camera ends at a line "}").
awk 'BEGIN {skip=0} /^camera \{/ {skip=1; system("cat camera.txt"); next} skip && /^\}/ {skip=0; next}
     !skip {print}' good.pov >moved.pov
render moved.pov moved.png
[ "$(differing_pixels dragged.png moved.png)" = 0 ] ||
  fail "the printed camera block renders another picture ($(differing_pixels dragged.png moved.png) pixels differ)"
xdotool key --window "$id" s
for _ in $(seq 50); do [ -s saved.png ] && break; sleep 0.1; done
[ "$(differing_pixels saved.png moved.png)" = 0 ] || fail "s wrote another picture than the render"

# 5. R over the right-hand object (the view of step 4 still holds): its header, edited.
xdotool key --window "$id" Home
wait_for_picture edited.png below-text || fail "Home did not bring back the scene's camera"
xdotool mousemove --window "$id" 114 64 key --window "$id" R
for _ in $(seq 50); do grep -q "radius 0.495" view.out && break; sleep 0.1; done
grep -q "radius 0.495" view.out || fail "R printed no edited header: $(cat view.out)"
sed 's/^  radius 0.45$/  radius 0.495/' good.pov >radius.pov
render radius.pov radius.png
wait_for_picture radius.png below-text ||
  fail "the radius edit shows another picture than the scene with the printed header"
# The message line (radius and offset) is drawn over the picture: its pixels differ.
import -window "$id" radius-screen.png
convert radius-screen.png -crop 160x20+0+0 +repage radius-top.png
convert radius.png -crop 160x20+0+0 +repage radius-file-top.png
[ "$(differing_pixels radius-top.png radius-file-top.png)" -gt 100 ] || fail "no values shown over the picture"

# 6. q closes it.
xdotool key --window "$id" q 2>/dev/null  # its key-up may find the window gone
for _ in $(seq 100); do kill -0 "$convray_pid" 2>/dev/null || break; sleep 0.1; done
if kill -0 "$convray_pid" 2>/dev/null; then
  fail "q did not end convray view"
else
  wait "$convray_pid"
  status=$?
  convray_pid=""
  [ "$status" = 0 ] || fail "q: exit status $status: $(cat view.err)"
fi
xdotool search --name '^convray view: ' >/dev/null 2>&1 && fail "a view window is still open"

if [ $failures -gt 0 ]; then
  echo "view window test: $failures failures"
  exit 1
fi
echo "view window test: all passed"
