// A hole repaired. models/holed_sheet.obj is a 4 x 4 sheet with a ragged hole of radius about
// 0.6, as a scanner leaves them. The field of a flat sheet with a round hole of radius a is,
// at the hole's centre, the plane's field at distance a: so the hole closes exactly when the
// offset reaches a. Left: offset 0.3, the hole narrows but stays open; right: offset 0.7
// (R = 1), the surface closes over it.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 6.5, -7>
  look_at <0, -0.3, 0>
  right x * image_width / image_height
  angle 50
}
light_source { <-5, 12, -6> color rgb 1 }
light_source { <6, 6, -8> color rgb 0.3 shadowless }
background { color rgb <0.1, 0.12, 0.16> }

plane { y, -1.5 pigment { color rgb <0.35, 0.4, 0.45> } }

#declare Sheet = texture {
  pigment { color rgb <0.3, 0.65, 0.9> }
  finish { ambient 0.12 diffuse 0.7 specular 0.4 roughness 0.02 }
}

convolution {
  radius 1
  offset 0.3
  mesh { "models/holed_sheet.obj" }
  texture { Sheet }
  translate -2.3 * x
}
convolution {
  radius 1
  offset 0.7
  mesh { "models/holed_sheet.obj" }
  texture { Sheet }
  translate 2.3 * x
}
