// A polygonized surface (convray polygonize -> scripts/obj-to-mesh2.sh) rendered as the
// triangles it is, for docs/polygonization.md. The mesh is the include file polygonized.inc,
// found through a +L folder (scripts/make-polygonize-images.sh), and about 2 units across.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Camera = <0, 2.2, -4.2>;
#declare LookAt = <0, 0, 0>;
camera {
  location Camera
  look_at LookAt
  right x * image_width / image_height
  angle 40
}
light_source { Camera + <-3, 6, -2> color rgb 1 }
light_source { Camera + <4, 2, 0> color rgb 0.35 shadowless }
background { color rgb <0.86, 0.9, 0.95> }
object {
  #include "polygonized.inc"
  pigment { color rgb <0.85, 0.6, 0.35> }
  finish { diffuse 0.75 specular 0.3 roughness 0.02 }
}
