# The set-up the window tests share (sourced, not run): the tools they need, a folder of their
# own, an Xvfb server on a display number of its own, and the cleanup that ends every process
# they start by its PID. Where a tool is missing or Xvfb does not start, the test exits 77,
# which CTest reports as skipped, never as passed.
#
# Before sourcing: test_name (for the messages). Arguments: the screen's WIDTHxHEIGHT.
# After: DISPLAY set, the working folder is $tmp (removed at exit), fail MESSAGE counts into
# $failures, and a convray started in the background goes into $convray_pid (ended at exit).
skip() {
  echo "SKIPPED: $test_name: $*"
  exit 77
}
for tool in Xvfb xdotool xwininfo import compare convert; do
  command -v "$tool" >/dev/null ||
    skip "$tool is missing (apt-get install xvfb xdotool x11-utils imagemagick; bash scripts/setup.sh installs them)"
done

tmp=$(mktemp -d)
xvfb_pid=""
convray_pid=""
cleanup() {
  [ -n "$convray_pid" ] && kill "$convray_pid" 2>/dev/null && wait "$convray_pid" 2>/dev/null
  [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null && wait "$xvfb_pid" 2>/dev/null
  rm -rf "$tmp"
}
trap cleanup EXIT

failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# A display number of its own: Xvfb picks a free one and writes it to fd 3 (-displayfd).
Xvfb -displayfd 3 -screen 0 "$1x24" -nolisten tcp 3>"$tmp/display" 2>"$tmp/xvfb.log" &
xvfb_pid=$!
for _ in $(seq 100); do
  [ -s "$tmp/display" ] && break
  kill -0 "$xvfb_pid" 2>/dev/null || skip "Xvfb did not start: $(tail -3 "$tmp/xvfb.log")"
  sleep 0.1
done
[ -s "$tmp/display" ] || skip "Xvfb gave no display number in 10 s"
export DISPLAY=":$(head -1 "$tmp/display")"
unset WAYLAND_DISPLAY SDL_VIDEODRIVER
cd "$tmp" || exit 1
