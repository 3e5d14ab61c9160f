// The repair soup (models/repair_soup.obj: a 4 x 4 sheet with round holes of radii 0.15,
// 0.3 and 0.45, flipped and duplicated triangles, slivers and a fin), or a surface
// `convray polygonize` extracted from it, as plain triangles. scripts/make-repair-images.sh
// writes the triangles into shape.inc (`#declare Shape = mesh2 {...}`) and renders this scene
// with -L pointing at it; see docs/repair.md.
//
// The soup lies in the plane z = 0; rotated here so that it lies flat (y up), with the holes
// of radii 0.15 (front left), 0.3 (front right) and 0.45 (back left), the defects back right.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#include "shape.inc"

camera {
  location <0.4, 5.2, -5.6>
  look_at <0, -0.25, 0>
  right x * image_width / image_height
  angle 44
}
light_source { <-4, 10, -6> color rgb 1 }
light_source { <6, 5, -7> color rgb 0.35 shadowless }
background { color rgb <0.1, 0.12, 0.16> }

// A checkered floor below: the holes show it.
plane {
  y, -1
  pigment { checker color rgb <0.55, 0.58, 0.62>, color rgb <0.3, 0.33, 0.37> scale 0.5 }
}

object {
  Shape
  rotate -90 * x
  texture {
    pigment { color rgb <0.3, 0.65, 0.9> }
    finish { ambient 0.15 diffuse 0.7 specular 0.3 roughness 0.02 }
  }
}
