// The Stanford bunny (npm package bunny, .cache/models/bunny.obj), or a surface
// `convray polygonize` extracted from it, as plain triangles, seen from below and in front (its face).
// scripts/make-repair-images.sh writes the triangles into shape.inc
// (`#declare Shape = mesh2 {...}`) and renders this scene with -L pointing at it; see
// docs/repair.md. The bunny's units: about 10 wide, its base at y = 0.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#include "shape.inc"

camera {
  location <-18, -6, -19>
  look_at <0, 4, 0>
  right x * image_width / image_height
  angle 46
}
light_source { <-10, 20, -20> color rgb 0.9 }
light_source { <10, -15, -15> color rgb 0.5 shadowless }
background { color rgb <0.1, 0.12, 0.16> }

object {
  Shape
  texture {
    pigment { color rgb <0.85, 0.75, 0.6> }
    finish { ambient 0.15 diffuse 0.7 specular 0.25 roughness 0.03 }
  }
}
