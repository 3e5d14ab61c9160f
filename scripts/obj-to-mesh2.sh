#!/usr/bin/env bash
# Converts a triangle OBJ (as `convray polygonize` writes it: `v`, optional `vn`, and faces
# `f a b c` or `f a//a b//b c//c`) into a scene-language `mesh2` object, so that a polygonized
# surface can be rendered as the triangles it is. Normals, when present, give smooth shading;
# --flat drops them to show the facets.
#   bash scripts/obj-to-mesh2.sh MESH.obj [--flat] > MESH.inc    (then: object { mesh2 { ... } })
set -euo pipefail
[ $# -ge 1 ] || { sed -n '2,6p' "$0" >&2; exit 2; }
flat=0
[ "${2:-}" = --flat ] && flat=1
awk -v flat=$flat '
  /^v /  { v[nv++] = sprintf("<%s, %s, %s>", $2, $3, $4) }
  /^vn / { n[nn++] = sprintf("<%s, %s, %s>", $2, $3, $4) }
  /^f /  {
    if (NF != 4) { print "obj-to-mesh2: only triangles are supported" > "/dev/stderr"; exit 2 }
    for (k = 2; k <= 4; k++) { split($k, parts, "/"); idx[k] = parts[1] - 1 }
    f[nf++] = sprintf("<%d, %d, %d>", idx[2], idx[3], idx[4])
  }
  END {
    print "mesh2 {"
    printf "  vertex_vectors { %d", nv; for (i = 0; i < nv; i++) printf ",\n    %s", v[i]; print " }"
    if (!flat && nn == nv) {
      printf "  normal_vectors { %d", nn; for (i = 0; i < nn; i++) printf ",\n    %s", n[i]; print " }"
    }
    printf "  face_indices { %d", nf; for (i = 0; i < nf; i++) printf ",\n    %s", f[i]; print " }"
    print "}"
  }' "$1"
