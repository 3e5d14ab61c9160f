#!/usr/bin/env bash
# +D where SDL2 itself cannot be loaded (display/sdl_library.hpp opens it with dlopen when
# the first window opens): convray names the library and the loader's reason once, renders as
# with -D (exit 0, the same bytes), and convray view says it needs a window (exit 1). The
# library is hidden by bind-mounting an empty file over it in a mount namespace of the test's
# own, which needs root and unshare: without them the test says why and exits 77 (skipped).
#
# usage: preview_without_sdl_test.sh CONVRAY SOURCE_DIR
set -uo pipefail
convray=$1
scene=$2/scenes/soup.pov
library=$(ldconfig -p 2>/dev/null | awk '/libSDL2-2\.0\.so\.0 .*x86-64|libSDL2-2\.0\.so\.0 \(/ {print $NF; exit}')
if [ -z "$library" ] || [ ! -e "$library" ]; then
  echo "SKIPPED: libSDL2-2.0.so.0 is not installed"
  exit 77
fi
library=$(readlink -f "$library")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
: >empty.so
if ! unshare -m true 2>/dev/null; then
  echo "SKIPPED: no mount namespace here (unshare -m needs root)"
  exit 77
fi
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

env -u DISPLAY -u WAYLAND_DISPLAY "$convray" "$scene" +W96 +H72 -D -o plain.png >/dev/null ||
  fail "the -D render failed"

# Inside the namespace: the library is an empty file; a DISPLAY is set, so SDL is asked for.
unshare -m bash -c "mount --bind '$tmp/empty.so' '$library' &&
  DISPLAY=:97 timeout 30 '$convray' '$scene' +W96 +H72 +D -o hidden.png >hidden.out 2>hidden.err;
  echo \$? >hidden.status;
  DISPLAY=:97 timeout 30 '$convray' view '$scene' >view.out 2>view.err; echo \$? >view.status"
[ "$(cat hidden.status)" = 0 ] || fail "+D without SDL: exit status $(cat hidden.status): $(cat hidden.err)"
cmp -s hidden.png plain.png || fail "+D without SDL: the file differs from the -D render's"
grep -q "no display available (SDL2: cannot load libSDL2-2.0.so.0 (.*apt-get install" hidden.err ||
  fail "+D without SDL: the message does not name the library: $(cat hidden.err)"
[ "$(grep -c "no display available" hidden.err)" = 1 ] || fail "+D without SDL: said more than once"
[ "$(cat view.status)" = 1 ] || fail "view without SDL: exit status $(cat view.status): $(cat view.err)"
grep -q "SDL2: cannot load libSDL2-2.0.so.0" view.err || fail "view without SDL: $(cat view.err)"

if [ "$failures" -gt 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "preview without SDL: 2 cases passed"
