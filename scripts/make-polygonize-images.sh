#!/usr/bin/env bash
# The pictures of docs/polygonization.md, made by convray itself: the example soup's surface
# polygonized, then rendered as plain triangles, once flat (the facets) and once with the
# normals polygonize writes (from the exact gradient); and the convolution surface itself,
# ray traced directly, for comparison.
#   bash scripts/make-polygonize-images.sh   (after a build)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
convray=./build/convray
out=docs/images/polygonize
work=out/polygonize
mkdir -p "$out" "$work/flat" "$work/smooth"
soup=scenes/models/soup.obj
for cell in 0.1 0.04; do
  $convray polygonize "$soup" --radius 0.25 --offset 0.1 --cell $cell --outer \
    -o "$work/soup-$cell.obj" > "$work/soup-$cell.log"
  bash scripts/obj-to-mesh2.sh "$work/soup-$cell.obj" --flat > "$work/flat/polygonized.inc"
  bash scripts/obj-to-mesh2.sh "$work/soup-$cell.obj" > "$work/smooth/polygonized.inc"
  $convray scenes/polygonize/mesh_view.pov "+L$work/flat" +W400 +H300 +A0.3 --quiet \
    -o "$out/soup-cell$cell-flat.png"
  $convray scenes/polygonize/mesh_view.pov "+L$work/smooth" +W400 +H300 +A0.3 --quiet \
    -o "$out/soup-cell$cell-smooth.png"
done
$convray quick "$soup" --radius 0.25 --offset 0.1 --size 400x300 --camera 0,2.2,-4.2 \
  --look-at 0,0,0 --angle 40 -o "$out/soup-traced.png"
echo "pictures written to $out/"
