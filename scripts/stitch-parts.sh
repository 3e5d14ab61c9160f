#!/usr/bin/env bash
# Stitches the parts of a picture rendered apart with POV-Ray's partial-render switches
# (+SR/+ER rows, +SC/+EC columns; docs/render-farm.md) into the whole picture.
#
#   bash scripts/stitch-parts.sh OUTPUT PART...
#
# Each part is the whole picture, black outside its rectangle, as convray and POV-Ray 3.7 write
# partial renders, so the picture is the per-pixel maximum of the parts: a pixel outside a part
# is 0 there, and parts that overlap hold the same values (a pixel does not depend on the part
# it was rendered in). The values are only compared and copied, never recomputed, so the result
# has exactly the pixels of one render of the whole picture. A band no part covered stays
# black. The parts must have one size and one format; OUTPUT's extension chooses its format.
# It is written beside OUTPUT under a temporary name and renamed when complete.
# Needs oiiotool (Debian package openimageio-tools).
set -euo pipefail

usage() { echo "usage: $0 OUTPUT PART..." >&2; exit 2; }
[ $# -ge 2 ] || usage
output="$1"; shift
command -v oiiotool > /dev/null || { echo "$0: needs oiiotool (apt-get install openimageio-tools)" >&2; exit 1; }

# "WIDTH x HEIGHT, N channel, TYPE", the part of oiiotool --info that must agree.
shape() { oiiotool --info "$1" | sed -n '1s/^[^:]*: *//p'; }
first_shape=""
for part in "$@"; do
  [ -f "$part" ] || { echo "$0: $part: no such file" >&2; exit 1; }
  this=$(shape "$part") || { echo "$0: $part: not a picture oiiotool reads" >&2; exit 1; }
  [ -n "$first_shape" ] || first_shape="$this"
  [ "$this" = "$first_shape" ] || {
    echo "$0: $part is $this, but $1 is $first_shape: parts of one picture must agree" >&2; exit 1; }
done

# oiiotool: the first part, then each further one combined by --max.
args=("$1"); shift
for part in "$@"; do args+=("$part" --max); done
dir=$(dirname -- "$output"); base=$(basename -- "$output")
temporary="$dir/.$base.stitch-$$.${base##*.}"
trap 'rm -f -- "$temporary"' EXIT
oiiotool "${args[@]}" -o "$temporary"
mv -f -- "$temporary" "$output"
trap - EXIT
echo "stitched $(( ${#args[@]} / 2 + 1 )) parts into $output"
