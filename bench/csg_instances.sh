#!/usr/bin/env bash
# Issue 24's instances: a declared union of M spheres placed P times (`object { U rotate ...
# translate ... }` in a loop; bench/scenes/csg_instances.inc), rendered by convray and by
# POV-Ray 3.7 in the same run, whole process timed by the wall clock, pictures compared with
# idiff; convray's parse and build phases from --stats. With --other BIN, a second convray
# binary (an older build) renders the same scenes for a before/after column. Prints a
# Markdown table (also OUT/table.md). `bash bench/csg_instances.sh -h` for the options.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

usage() {
  cat <<'USAGE'
usage: bash bench/csg_instances.sh [OPTIONS]

Options:
  --cases "MxP ..."  members x placements (default "100x100 1000x100 100x1000 1000x1000")
  --textured         give each member a patterned pigment (checker) instead of a colour
  --timeout S        seconds a render may take before it is stopped (default 300)
  --size WxH         image size (default 320x240)
  --threads N        threads for every renderer (default 2)
  --build DIR        build folder holding convray (default build)
  --other BIN        another convray binary to time on the same scenes (default: none)
  --out DIR          output folder (default out/csg_instances)
  -h, --help         this message
Each render: `convray +I... +O... +WW +HH -A -D +WTn --stats` and
`povray +I... +O... +WW +HH -A -D +WTn`. A render stopped by the timeout shows as >S.
USAGE
}

die() { echo "csg_instances.sh: $*" >&2; exit 1; }

cases="100x100 1000x100 100x1000 1000x1000"
textured=0
limit=300
size=320x240
threads=2
build=build
other=""
out=out/csg_instances
while (($#)); do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --cases) cases=${2:?}; shift 2 ;;
    --textured) textured=1; shift ;;
    --timeout) limit=${2:?}; shift 2 ;;
    --size) size=${2:?}; shift 2 ;;
    --threads) threads=${2:?}; shift 2 ;;
    --build) build=${2:?}; shift 2 ;;
    --other) other=${2:?}; shift 2 ;;
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
[[ -z $other || -x $other ]] || die "--other: no program $other"
[[ -z $other ]] || other=$(realpath "$other")
mkdir -p "$out"
out=$(realpath "$out")
cp bench/scenes/csg_instances.inc "$out/"
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

# convray's phase $2 (parse, build, render) from its --stats log $1, in seconds.
phase() { awk -v p="$2" '$1 == "time" && $2 == p ":" { printf "%.2f", $3 }' "$out/$1"; }

table="$out/table.md"
{
  printf '| members x placements | convray (s) | parse (s) | build (s) | render (s) |'
  [[ -z $other ]] || printf ' other convray (s) | its parse (s) |'
  echo ' POV-Ray (s) | convray / POV-Ray | PSNR (dB) |'
  printf '| --- | ---: | ---: | ---: | ---: |'
  [[ -z $other ]] || printf ' ---: | ---: |'
  echo ' ---: | ---: | ---: |'
} | tee "$table"
for case in $cases; do
  [[ $case =~ ^([1-9][0-9]*)x([1-9][0-9]*)$ ]] || die "--cases: expected MxP, got '$case'"
  members=${BASH_REMATCH[1]}
  placements=${BASH_REMATCH[2]}
  name="instances_${members}x${placements}"
  printf '#declare %s = %d;\n' Members "$members" Placements "$placements" \
    Textured "$textured" > "$out/$name.pov"
  echo '#include "csg_instances.inc"' >> "$out/$name.pov"
  ours=$(timed "${name}_convray.log" "$convray" "+I$name.pov" "+O${name}_convray.png" \
           $switches --stats)
  row="| $members x $placements | $ours | $(phase "${name}_convray.log" parse) |"
  row+=" $(phase "${name}_convray.log" build) | $(phase "${name}_convray.log" render) |"
  if [[ -n $other ]]; then
    theirs_other=$(timed "${name}_other.log" "$other" "+I$name.pov" "+O${name}_other.png" \
                     $switches --stats)
    row+=" $theirs_other | $(phase "${name}_other.log" parse) |"
  fi
  theirs=$(timed "${name}_povray.log" povray "+I$name.pov" "+O${name}_povray.png" $switches)
  # idiff prints no PSNR for identical pictures, only PASS.
  psnr=$( (idiff -a "$out/${name}_povray.png" "$out/${name}_convray.png" 2>&1 || true) |
           awk '/Peak SNR/ {print $4; found = 1} /^PASS/ && !found {print "identical"}')
  [[ -n $psnr ]] || psnr="-"
  ratio=$(awk -v a="$ours" -v b="$theirs" \
            'BEGIN { if (a ~ />/ || b ~ />/) print "-"; else printf "%.2f", a / b }')
  echo "$row $theirs | $ratio | $psnr |" | tee -a "$table"
done
