#!/usr/bin/env bash
# Spreads an animation's frames over cores or machines with GNU parallel (Debian package
# `parallel`): one convray job per frame (+SFn +EFn), each deterministic, with +C so that a
# rerun after an interruption renders only the missing frames. See docs/render-farm.md.
#
#   bash scripts/render-farm-parallel.sh ANIMATION.ini [PARALLEL_OPTIONS...]
#
# Examples:
#   bash scripts/render-farm-parallel.sh scenes/animations/walk.ini -j4
#   bash scripts/render-farm-parallel.sh scenes/animations/walk.ini --sshloginfile nodes.txt
# With --sshlogin(file) the remote machines must see this checkout and the output folder at the
# same path (a shared file system). Environment: CONVRAY (the binary), CONVRAY_ARGS (extra
# arguments for every frame).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
convray="${CONVRAY:-$here/build/convray}"
[ $# -ge 1 ] || { echo "usage: $0 ANIMATION.ini [PARALLEL_OPTIONS...]" >&2; exit 2; }
command -v parallel >/dev/null || { echo "$0: GNU parallel is not installed (sudo apt-get install parallel)" >&2; exit 2; }
animation="$1"; shift
read -r -a extra <<< "${CONVRAY_ARGS:-}"
# Frames from convray itself, so INI sections, subsets and Frame_Step are honoured; each job is
# pinned to one thread unless the caller's CONVRAY_ARGS say otherwise.
"$convray" "$animation" "${extra[@]}" --list-frames | cut -f1 |
  parallel --halt now,fail=1 --workdir "$PWD" "$@" \
    "$convray" "$animation" "${extra[@]}" +WT1 "+SF{}" "+EF{}" +C --quiet
