#!/usr/bin/env bash
# +D where no window can be shown, as in CI and on a render farm: convray says so once on
# standard error, renders as with -D (exit 0, the same bytes), and never waits for a +P key
# nobody can press. Needs no X server, so it always runs.
#   1. DISPLAY and WAYLAND_DISPLAY unset: "no display available", once, even for 3 frames;
#   2. DISPLAY naming no server: the same, with X11's reason;
#   3. SDL_VIDEODRIVER=dummy (asked for): the preview runs unseen, said once; +P returns.
#   4. convray view, which needs a window, says so and exits 1 in each of these cases.
#
# usage: preview_headless_test.sh CONVRAY SOURCE_DIR
set -uo pipefail
convray=$1
scene=$2/scenes/soup.pov
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# Runs convray with a 30 s limit (a +P that waited for a key would hang); status in `status`.
run() {
  local name=$1
  shift
  timeout 30 "$@" >"$name.out" 2>"$name.err"
  status=$?
}

# How many lines of FILE contain TEXT.
lines_with() { grep -c -- "$2" "$1"; }

env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER "$convray" "$scene" +W96 +H72 -D \
  -o plain.png >/dev/null || fail "the -D render failed"

run none env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER "$convray" "$scene" +W96 +H72 +D +P \
  -o none.png
[ "$status" = 0 ] || fail "no display: exit status $status: $(cat none.err)"
cmp -s none.png plain.png || fail "no display: the file differs from the -D render's"
[ "$(lines_with none.err "no display available")" = 1 ] ||
  fail "no display: not said exactly once: $(cat none.err)"
grep -q "rendering without the preview window" none.err || fail "no display: $(cat none.err)"
[ "$(wc -l <none.err)" = 1 ] || fail "no display: more than one line on stderr: $(cat none.err)"

run frames env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER "$convray" "$scene" +W48 +H36 \
  +KFI1 +KFF3 Display=on -o frame.png
[ "$status" = 0 ] || fail "no display, 3 frames: exit status $status: $(cat frames.err)"
[ "$(lines_with frames.err "no display available")" = 1 ] ||
  fail "no display, 3 frames: not said exactly once: $(cat frames.err)"
[ -s frame1.png ] && [ -s frame2.png ] && [ -s frame3.png ] || fail "no display: frames missing"

# A display number no server answers (a free one: no lock file).
number=97
while [ -e "/tmp/.X$number-lock" ] || [ -e "/tmp/.X11-unix/X$number" ]; do number=$((number + 1)); done
run gone env -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER DISPLAY=":$number" "$convray" "$scene" \
  +W96 +H72 --display -o gone.png
[ "$status" = 0 ] || fail "no X server: exit status $status: $(cat gone.err)"
cmp -s gone.png plain.png || fail "no X server: the file differs from the -D render's"
grep -q "no display available (DISPLAY=:$number" gone.err || fail "no X server: $(cat gone.err)"

run dummy env -u DISPLAY -u WAYLAND_DISPLAY SDL_VIDEODRIVER=dummy "$convray" "$scene" +W96 +H72 \
  +D +P +A0.3 -o dummy.png
"$convray" "$scene" +W96 +H72 +A0.3 -D -o dummy-plain.png >/dev/null || fail "the -D +A render"
[ "$status" = 0 ] || fail "dummy driver: exit status $status: $(cat dummy.err)"
cmp -s dummy.png dummy-plain.png || fail "dummy driver: the file differs from the -D render's"
[ "$(lines_with dummy.err "shows no window")" = 1 ] ||
  fail "dummy driver: the unseen preview not said once: $(cat dummy.err)"

# convray view cannot work without a window: it says so and exits 1, at once, for each way
# of having none (and 2 for a scene that is not there).
run view-none env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER "$convray" view "$scene"
[ "$status" = 1 ] || fail "view, no display: exit status $status: $(cat view-none.err)"
grep -q "convray view: no display available (neither DISPLAY nor WAYLAND_DISPLAY is set); view needs a window" view-none.err ||
  fail "view, no display: $(cat view-none.err)"
run view-gone env -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER DISPLAY=":$number" "$convray" view "$scene"
[ "$status" = 1 ] || fail "view, no X server: exit status $status: $(cat view-gone.err)"
grep -q "no display available (DISPLAY=:$number" view-gone.err || fail "view, no X server: $(cat view-gone.err)"
run view-dummy env -u DISPLAY -u WAYLAND_DISPLAY SDL_VIDEODRIVER=dummy "$convray" view "$scene"
[ "$status" = 1 ] || fail "view, dummy driver: exit status $status: $(cat view-dummy.err)"
grep -q "shows no window (SDL_VIDEODRIVER); view needs one" view-dummy.err ||
  fail "view, dummy driver: $(cat view-dummy.err)"
run view-missing env -u DISPLAY "$convray" view no-such-scene.pov
[ "$status" = 2 ] || fail "view, missing scene: exit status $status: $(cat view-missing.err)"
grep -q "no-such-scene.pov: no such file" view-missing.err || fail "view, missing: $(cat view-missing.err)"

if [ $failures -gt 0 ]; then
  echo "preview headless test: $failures failures"
  exit 1
fi
echo "preview headless test: all passed"
