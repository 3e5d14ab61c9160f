#!/usr/bin/env bash
# POV-Ray's own example scenes (Debian's povray-examples) rendered by POV-Ray 3.7 and by
# convray with the same switches; writes docs/compatibility.md: each scene's status, the
# totals, and the median time ratio. Run through `bash scripts/compare-povray.sh --examples`;
# `-h` for the options. Not run by CI (about half an hour on two cores).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

examples=/usr/share/doc/povray/examples
includes=/usr/share/povray-3.7/include
width=160
height=120

usage() {
  cat <<'USAGE'
usage: bash scripts/compare-povray.sh --examples [OPTIONS] [SCENE.pov ...]

Renders every scene under /usr/share/doc/povray/examples (or the scenes given) with
`povray` and with `convray`, both `+W160 +H120 -A -D +WT1 +L<include folder> +L<scene's
folder>` under `nice -n 10` and a time limit, several scenes at once, and compares the
pictures with idiff (PSNR over 8-bit RGB). Each scene gets one status:

  identical        the same pixels
  within 30 dB     PSNR >= 30 dB
  differs          PSNR < 30 dB
  refused          convray exits 2 (the first line of its error is kept)
  (a scene that renders keeps convray's first warning: what it left out or changed)
  crash            convray exits otherwise, or is killed by a signal
  timeout          convray runs past the time limit
  (POV-Ray fails, POV-Ray timeout: not counted; POV-Ray cannot render the scene either)

POV-Ray's pictures and times are kept in OUT/povray/ and reused by later runs (POV-Ray
does not change between runs); --fresh renders them again.

Options:
  --jobs N        scenes rendered at once (default 2: one per core; each render is 1 thread)
  --timeout S     time limit of each render in seconds (default 60)
  --build DIR     build folder holding convray (default build)
  --out DIR       pictures, logs, results (default out/examples; git-ignored)
  --doc FILE      the report (default docs/compatibility.md when every example runs,
                  OUT/compatibility.md when scenes are given)
  --fresh         render POV-Ray's pictures again
  -h, --help      this message
USAGE
}

die() { echo "compare-examples.sh: $*" >&2; exit 1; }

# One scene, both renderers: `compare-examples.sh --job SCENE --results DIR` (run by xargs
# below). Writes DIR/ID.tsv: status, PSNR, POV-Ray's seconds, convray's seconds, detail.
run_job() {
  local scene=$1 id=$2
  local pov_dir="$out/povray" our_dir="$out/convray" work="$out/work/$id"
  rm -rf "$work"
  mkdir -p "$work/pov" "$work/our"
  local switches=("+W$width" "+H$height" -A -D +WT1 "+L$includes" "+L$(dirname "$scene")")
  if ((fresh)) || [[ ! -f $pov_dir/$id.status ]]; then
    # POV-Ray writes only in its current folder (Debian's povray.conf): run it there.
    local start rc=0
    start=$(date +%s.%N)
    (cd "$work/pov" && nice -n 10 timeout -k 5 "$limit" povray "+I$scene" +Opov.png \
      "${switches[@]}" >log.txt 2>&1) || rc=$?
    local seconds
    seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
    [[ -f $work/pov/pov.png ]] && mv "$work/pov/pov.png" "$pov_dir/$id.png"
    mv "$work/pov/log.txt" "$pov_dir/$id.log"
    printf '%s\t%s\n' "$rc" "$seconds" >"$pov_dir/$id.status"
  fi
  local pov_rc pov_seconds
  IFS=$'\t' read -r pov_rc pov_seconds <"$pov_dir/$id.status"

  local start rc=0
  start=$(date +%s.%N)
  (cd "$work/our" && nice -n 10 timeout -k 5 "$limit" "$convray" "+I$scene" +Oour.png \
    "${switches[@]}" --quiet >/dev/null 2>log.txt) || rc=$?
  local our_seconds
  our_seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
  rm -f "$our_dir/$id.png"
  [[ -f $work/our/our.png ]] && mv "$work/our/our.png" "$our_dir/$id.png"
  mv "$work/our/log.txt" "$our_dir/$id.log"
  rm -rf "$work"

  local status psnr="" detail=""
  if [[ $pov_rc == 124 || $pov_rc == 137 ]]; then
    status="POV-Ray timeout"
  elif [[ $pov_rc != 0 || ! -f $pov_dir/$id.png ]]; then
    status="POV-Ray fails"
    detail=$(grep -m1 -E 'Parse Error|Error' "$pov_dir/$id.log" || true)
  elif [[ $rc == 124 || $rc == 137 ]]; then
    status=timeout
  elif [[ $rc == 2 ]]; then
    status=refused
    detail=$(first_error "$our_dir/$id.log")
  elif [[ $rc != 0 || ! -f $our_dir/$id.png ]]; then
    status=crash
    detail="exit code $rc: $(tail -n 1 "$our_dir/$id.log")"
  else
    # idiff exits non-zero whenever the pictures differ; only its numbers matter here.
    local report
    report=$(idiff "$pov_dir/$id.png" "$our_dir/$id.png" 2>&1 || true)
    psnr=$(awk '/Peak SNR/ { print $4 }' <<<"$report")
    # 8-bit pictures: any difference fails idiff's default threshold, so PASS is identical.
    if grep -q '^PASS' <<<"$report" && [[ -z $psnr ]]; then
      status=identical
      psnr=inf
    elif [[ -z $psnr ]]; then
      status=differs
      detail="idiff: $(grep -v '^Comparing' <<<"$report" | head -n 1)"
    elif awk -v p="$psnr" 'BEGIN { exit !(p == "inf" || p + 0 >= 30) }'; then
      status="within 30 dB"
    else
      status=differs
    fi
    # What convray said it left out or changed: its first warning.
    [[ -n $detail ]] || detail=$(first_warning "$our_dir/$id.log")
  fi
  printf '%s\t%s\t%s\t%s\t%s\n' "$status" "$psnr" "$pov_seconds" "$our_seconds" \
    "${detail//$'\t'/ }" >"$results/$id.tsv"
}

# The error convray stopped on: its last unindented line with a file:line:col (or any
# unindented line), #debug output left out.
first_error() {
  local line
  line=$(grep -v -e '^[[:space:]]' -e ': #debug: ' "$1" | grep -E ':[0-9]+:[0-9]+: ' | tail -n 1 || true)
  [[ -n $line ]] || line=$(grep -v -e '^[[:space:]]' -e ': #debug: ' "$1" | tail -n 1 || true)
  # Paths under the examples folder are shown relative to it.
  echo "${line#"$examples"/}"
}

# The first warning of a scene convray rendered (unindented lines with a file:line:col,
# #debug output left out): one about the scene's own files before one about POV-Ray's
# include folder (whose declarations a scene mostly does not use), with how many others
# followed; paths under the examples folder made relative.
first_warning() {
  local all line count
  all=$(grep -v -e '^[[:space:]]' -e ': #debug: ' "$1" | grep -E ':[0-9]+:[0-9]+: ' || true)
  [[ -n $all ]] || return 0
  count=$(wc -l <<<"$all")
  line=$(grep -m1 -v "^$includes/" <<<"$all" || head -n 1 <<<"$all")
  ((count > 1)) && line="$line (+$((count - 1)) more)"
  echo "${line#"$examples"/}"
}

# A scene's id: its path under the examples folder with / as __ (names repeat across folders).
scene_id() {
  local relative=${1#"$examples"/}
  relative=${relative%.pov}
  echo "${relative//\//__}"
}

jobs=2
limit=60
build=build
out=out/examples
doc=""
fresh=0
job=""
results=""
scenes=()
while (($#)); do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --jobs) jobs=${2:?--jobs needs a number}; shift 2 ;;
    --timeout) limit=${2:?--timeout needs seconds}; shift 2 ;;
    --build) build=${2:?--build needs a folder}; shift 2 ;;
    --out) out=${2:?--out needs a folder}; shift 2 ;;
    --doc) doc=${2:?--doc needs a file}; shift 2 ;;
    --fresh) fresh=1; shift ;;
    --job) job=${2:?}; shift 2 ;;
    --results) results=${2:?}; shift 2 ;;
    -*) usage >&2; die "unknown option '$1'" ;;
    *) scenes+=("$1"); shift ;;
  esac
done
convray=$(realpath "$build/convray")
out=$(realpath -m "$out")
if [[ -n $job ]]; then
  run_job "$job" "$(scene_id "$job")"
  exit 0
fi

command -v povray >/dev/null || die "povray is not installed (Debian package povray)"
command -v idiff >/dev/null || die "idiff is not installed (Debian package openimageio-tools)"
[[ -d $examples ]] || die "no $examples (Debian package povray-examples)"
[[ -x $convray ]] || die "no $build/convray: build first (cmake --build $build --target convray)"
everything=0
if ((${#scenes[@]} == 0)); then
  everything=1
  mapfile -t scenes < <(find "$examples" -name '*.pov' | LC_ALL=C sort)
fi
[[ -n $doc ]] || { ((everything)) && doc=docs/compatibility.md || doc="$out/compatibility.md"; }
mkdir -p "$out/povray" "$out/convray" "$out/work"
# This run's results, apart from any other run's on the same OUT.
results=$(mktemp -d "$out/results.XXXXXX")

echo "compare-examples.sh: ${#scenes[@]} scenes, $jobs at once, ${limit} s each" >&2
start=$(date +%s)
printf '%s\0' "${scenes[@]}" |
  xargs -0 -P "$jobs" -I{} bash scripts/compare-examples.sh --job {} --timeout "$limit" \
    --build "$build" --out "$out" --results "$results" $( ((fresh)) && echo --fresh)
minutes=$(awk -v s="$(( $(date +%s) - start ))" 'BEGIN { printf "%.1f", s / 60 }')

python3 scripts/compatibility_report.py "$results" "$examples" "$minutes" "$jobs" "$limit" \
  "${scenes[@]}" >"$doc"
rm -rf "$results"
echo "compare-examples.sh: wrote $doc ($minutes min)" >&2
sed -n '/^| status/,/^$/p' "$doc" >&2
