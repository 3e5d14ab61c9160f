#!/usr/bin/env bash
# Issue 24's benchmark: N spheres at the top level, in a union, a merge and a difference
# (bench/scenes/csg_many.inc), under a point light and an area light, each rendered by
# convray and by POV-Ray 3.7 in the same run, whole process timed by the wall clock
# (`date +%s.%N`), pictures compared with idiff. Prints a Markdown table (also written to
# OUT/table.md). Run `bash bench/csg_many.sh -h` for the options.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

usage() {
  cat <<'USAGE'
usage: bash bench/csg_many.sh [OPTIONS]

Options:
  --sizes "N ..."   sphere counts (default "100 1000 10000 100000 1000000")
  --kinds "K ..."   of top union merge difference (default all four)
  --lights "L ..."  of point area (default both)
  --timeout S       seconds a render may take before it is stopped (default 300)
  --size WxH        image size (default 320x240)
  --threads N       threads for both renderers (default 2)
  --build DIR       build folder holding convray (default build)
  --out DIR         output folder (default out/csg_many)
  -h, --help        this message
Each render: `convray +I... +O... +WW +HH -A -D +WTn --stats` and
`povray +I... +O... +WW +HH -A -D +WTn`. A render stopped by the timeout shows as >S.
Columns: the whole process's wall time of each, convray's render phase (from --stats) per
ray it traced (camera and shadow rays), the PSNR of convray's picture against POV-Ray's, and
for the union its time over the top level's at the same N (issue 24: at most 1.5).
USAGE
}

die() { echo "csg_many.sh: $*" >&2; exit 1; }

sizes="100 1000 10000 100000 1000000"
kinds="top union merge difference"
lights="point area"
limit=300
size=320x240
threads=2
build=build
out=out/csg_many
while (($#)); do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --sizes) sizes=${2:?}; shift 2 ;;
    --kinds) kinds=${2:?}; shift 2 ;;
    --lights) lights=${2:?}; shift 2 ;;
    --timeout) limit=${2:?}; shift 2 ;;
    --size) size=${2:?}; shift 2 ;;
    --threads) threads=${2:?}; shift 2 ;;
    --build) build=${2:?}; shift 2 ;;
    --out) out=${2:?}; shift 2 ;;
    *) usage >&2; die "unknown option '$1'" ;;
  esac
done
[[ $size =~ ^([1-9][0-9]*)x([1-9][0-9]*)$ ]] || die "--size: expected WxH, got '$size'"
width=${BASH_REMATCH[1]}
height=${BASH_REMATCH[2]}
command -v povray >/dev/null || die "povray is not installed (Debian package povray)"
command -v idiff >/dev/null || die "idiff is not installed (Debian package openimageio-tools)"
[[ -x $build/convray ]] || die "no $build/convray: build first (cmake --build $build)"
convray=$(realpath "$build/convray")
mkdir -p "$out"
out=$(realpath "$out")
cp bench/scenes/csg_many.inc "$out/"
switches="+W$width +H$height -A -D +WT$threads"

# Runs a command under the timeout in $out, its output into the log $1; prints its wall
# seconds, or >LIMIT if it was stopped (or failed: see the log).
timed() {
  local log=$1 start end
  shift
  start=$(date +%s.%N)
  if (cd "$out" && timeout "$limit" "$@" > "$out/$log" 2>&1); then
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }'
  else
    echo ">$limit"
  fi
}

kind_number() {
  case "$1" in top) echo 0 ;; union) echo 1 ;; merge) echo 2 ;; difference) echo 3 ;;
    *) die "unknown kind '$1'" ;; esac
}

table="$out/table.md"
{
  echo "| light | objects | N | convray (s) | POV-Ray (s) | convray / POV-Ray | convray render (µs/ray) | PSNR (dB) | union / top |"
  echo "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
} | tee "$table"
for light in $lights; do
  [[ $light == point || $light == area ]] || die "unknown light '$light'"
  for n in $sizes; do
    top_time=""
    for kind in $kinds; do
      name="${light}_${kind}_$n"
      printf '#declare N = %d;\n#declare Kind = %d;\n#declare Area = %d;\n#include "csg_many.inc"\n' \
        "$n" "$(kind_number "$kind")" "$([[ $light == area ]] && echo 1 || echo 0)" > "$out/$name.pov"
      ours=$(timed "${name}_convray.log" "$convray" "+I$name.pov" "+O${name}_convray.png" \
               $switches --stats)
      render=$(awk '/^time render:/ {print $3}' "$out/${name}_convray.log")
      rays=$(awk '/^rays: camera/ {print $3 + $5}' "$out/${name}_convray.log")
      per_ray=$(awk -v r="$render" -v n="$rays" 'BEGIN { if (n > 0) printf "%.3f", 1e6 * r / n; else print "-" }')
      theirs=$(timed "${name}_povray.log" povray "+I$name.pov" "+O${name}_povray.png" $switches)
      psnr=$( (idiff -a "$out/${name}_povray.png" "$out/${name}_convray.png" 2>&1 || true) |
               awk '/Peak SNR/ {print $4}')
      [[ -n $psnr ]] || psnr="-"
      ratio=$(awk -v a="$ours" -v b="$theirs" 'BEGIN { if (a ~ />/ || b ~ />/) print "-"; else printf "%.2f", a / b }')
      [[ $kind == top ]] && top_time=$ours
      vs_top=""
      if [[ $kind == union && -n $top_time && $top_time != \>* && $ours != \>* ]]; then
        vs_top=$(awk -v a="$ours" -v b="$top_time" 'BEGIN { printf "%.2f", a / b }')
      fi
      echo "| $light | $kind | $n | $ours | $theirs | $ratio | $per_ray | $psnr | $vs_top |" | tee -a "$table"
    done
  done
done
