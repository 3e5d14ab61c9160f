#!/usr/bin/env bash
# Issue 5's animation benchmark: 60 frames at 640x480 of the Stanford dragon (dragon_vrip_res3,
# 47,794 triangles) with a limb of segments and an arc sweeping through it and blending
# (bench/scenes/dragon_limb.pov, .ini). Goal: after the first frame, every frame of the
# animation takes at most 1.15 times as long as rendering frame 0 alone (a process of its own).
#
#   bash bench/animation_dragon.sh [--size WxH] [--frames N] [--build DIR] [--out DIR]
#
# Writes out/bench/animation_dragon.md (a table: frame 0 alone; every frame's parse, build,
# render and total time in the animation; the ratios) and exits 1 when the goal is missed.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
size=640x480 frames=60 build=build out=out/bench
while [ $# -gt 0 ]; do
  case "$1" in
    --size) size=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h|--help) sed -n '2,11p' "$0"; exit 0 ;;
    *) echo "animation_dragon.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
convray=$build/convray
[ -x "$convray" ] || { echo "animation_dragon.sh: $convray is missing: build first" >&2; exit 2; }
bash scripts/fetch-models.sh >/dev/null
width=${size%x*} height=${size#*x}
last=$((frames - 1))
ini=bench/scenes/dragon_limb.ini
common=("$ini" "+W$width" "+H$height" "+KFF$last" --stats)
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "==> frame 0 alone ($size, a process of its own)"
start=$(date +%s.%N)
"$convray" "${common[@]}" +SF0 +EF0 "+O$work/alone/" > "$work/alone.log"
alone=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
echo "==> the animation: $frames frames in one process"
start=$(date +%s.%N)
"$convray" "${common[@]}" "+O$work/animation/" > "$work/animation.log"
whole=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')

# Per frame: number, parse, build, render, total (from --stats; "frame N ..." lines first).
awk '/^convray: frame/ { frame = $3 }
     /^time parse:/ { parse = $3 } /^time build:/ { build = $3 } /^time render:/ { render = $3 }
     /^time total:/ { print frame, parse, build, render, $3 }' "$work/animation.log" > "$work/frames.txt"
[ "$(wc -l < "$work/frames.txt")" -eq "$frames" ] || { echo "animation_dragon.sh: expected $frames frames" >&2; exit 1; }

report=$out/animation_dragon.md
awk -v alone="$alone" -v whole="$whole" -v size="$size" -v frames="$frames" '
  { f[NR] = $1; p[NR] = $2; b[NR] = $3; r[NR] = $4; t[NR] = $5 }
  END {
    max = 0; sum = 0
    for (i = 2; i <= NR; ++i) { sum += t[i]; if (t[i] > max) { max = t[i]; at = f[i] } }
    mean = sum / (NR - 1)
    printf "Frame 0 alone (whole process): %.3f s. The animation (%d frames, %s, one process): %.1f s.\n\n", alone, frames, size, whole
    printf "| | parse s | build s | render s | frame s | frame / frame 0 alone |\n| --- | ---: | ---: | ---: | ---: | ---: |\n"
    printf "| frame 0 (first of the animation) | %.3f | %.3f | %.3f | %.3f | %.3f |\n", p[1], b[1], r[1], t[1], t[1] / alone
    pmean = bmean = rmean = 0
    for (i = 2; i <= NR; ++i) { pmean += p[i]; bmean += b[i]; rmean += r[i] }
    n = NR - 1
    printf "| frames 1-%d, mean | %.3f | %.3f | %.3f | %.3f | %.3f |\n", NR - 1, pmean / n, bmean / n, rmean / n, mean, mean / alone
    printf "| slowest frame (%d) | %.3f | %.3f | %.3f | %.3f | **%.3f** |\n\n", at, p[at + 1], b[at + 1], r[at + 1], max, max / alone
    printf "Goal: every frame after the first at most 1.15 x frame 0 alone: %s (worst %.3f).\n", (max / alone <= 1.15) ? "met" : "NOT met", max / alone
    exit (max / alone <= 1.15) ? 0 : 1
  }' "$work/frames.txt" | tee "$report"
status=${PIPESTATUS[0]}
cp "$work/frames.txt" "$out/animation_dragon_frames.txt"
echo "==> wrote $report"
exit "$status"
