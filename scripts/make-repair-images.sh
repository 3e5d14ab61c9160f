#!/usr/bin/env bash
# The pictures and figures of docs/repair.md: the repair soup (scenes/models/repair_soup.obj)
# and the Stanford bunny (npm package bunny) before and after `convray polygonize`, rendered
# by convray itself as plain triangles (scenes/repair/*.pov), and the distances between each
# input and its surfaces (`convray distance`).
# Usage: bash scripts/make-repair-images.sh   (after a build; called by make-docs-images.sh)
# Writes docs/images/repair/*.png; the meshes and the reports go to out/repair/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
convray=./build/convray
images=docs/images/repair
work=out/repair
mkdir -p "$images" "$work"
render=(+W480 +H360 +A0.3 +WT2 --quiet -L "$work")

# OBJ -> `#declare Shape = mesh2 {...}` in $work/shape.inc, the include every scene of
# scenes/repair/ reads: convray's scene language has no mesh file for plain triangles. Faces
# with more corners are fanned; `v//vn` corners keep their vertex index.
to_mesh2() {
  awk '
    $1 == "v" { vertex[nv++] = $2 ", " $3 ", " $4 }
    $1 == "f" {
      for (i = 2; i <= NF; ++i) { split($i, corner, "/"); index_of[i] = corner[1] - 1 }
      for (i = 3; i < NF; ++i) face[nf++] = index_of[2] ", " index_of[i] ", " index_of[i + 1]
    }
    END {
      print "#declare Shape = mesh2 {"
      printf "  vertex_vectors { %d", nv
      for (i = 0; i < nv; ++i) printf ",\n    <%s>", vertex[i]
      printf "\n  }\n  face_indices { %d", nf
      for (i = 0; i < nf; ++i) printf ",\n    <%s>", face[i]
      print "\n  }\n}"
    }' "$1" >"$work/shape.inc"
}

# picture SCENE MESH NAME: MESH as plain triangles in scenes/repair/SCENE.pov -> NAME.png
picture() {
  to_mesh2 "$2"
  $convray "scenes/repair/$1.pov" "${render[@]}" -o "$images/$3.png"
}

# surface INPUT NAME OPTIONS...: polygonize INPUT into $work/NAME.obj; the command's report,
# the surface's `convray info` and its distance to the input go to $work/NAME.txt.
surface() {
  local input=$1 name=$2
  shift 2
  {
    echo "\$ convray polygonize $input $* -o $work/$name.obj"
    $convray polygonize "$input" "$@" -o "$work/$name.obj"
    echo "\$ convray info $work/$name.obj"
    $convray info "$work/$name.obj"
    echo "\$ convray distance $input $work/$name.obj"
    $convray distance "$input" "$work/$name.obj"
  } >"$work/$name.txt" 2>&1
}

# The repair soup: holes of radii 0.15, 0.3 and 0.45. A hole of radius a closes when
# a <= offset D (and R > D), so D = 0.1, 0.2, 0.35 and 0.5 close none, one, two and three.
# R = 2 D (the default offset's ratio) and a lattice of R / 4 keep each run to a few seconds.
soup=scenes/models/repair_soup.obj
picture sheet "$soup" sheet-input
for pair in 0.2,0.1 0.4,0.2 0.7,0.35 1,0.5; do
  radius=${pair%,*} offset=${pair#*,}
  cell=$(awk -v r="$radius" 'BEGIN { print r / 4 }')
  surface "$soup" "sheet-r$radius-d$offset" --radius "$radius" --offset "$offset" --cell "$cell"
  picture sheet "$work/sheet-r$radius-d$offset.obj" "sheet-r$radius-d$offset"
done
# One radius, several offsets: the rule again at R = 0.7; and the limit of small D / R.
for offset in 0.1 0.2 0.5; do
  surface "$soup" "sheet-r0.7-d$offset" --radius 0.7 --offset "$offset" --cell 0.07
done
picture sheet "$work/sheet-r0.7-d0.1.obj" sheet-r0.7-d0.1

# The bunny (closed): its surface has one shell outside the skin and one inside; --outer
# keeps the outside one.
bash scripts/fetch-models.sh bunny >/dev/null
bunny=.cache/models/bunny.obj
picture bunny "$bunny" bunny-input
surface "$bunny" bunny-r0.5-d0.25 --radius 0.5 --offset 0.25 --cell 0.125
surface "$bunny" bunny-r0.5-d0.25-outer --radius 0.5 --offset 0.25 --cell 0.125 --outer
picture bunny "$work/bunny-r0.5-d0.25-outer.obj" bunny-r0.5-d0.25-outer
surface "$bunny" bunny-r1-d0.5-outer --radius 1 --offset 0.5 --cell 0.25 --outer
picture bunny "$work/bunny-r1-d0.5-outer.obj" bunny-r1-d0.5-outer
echo "pictures written to $images/, meshes and reports to $work/"
