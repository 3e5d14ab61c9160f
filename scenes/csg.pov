// CSG with mesh convolutions: a bite taken out of the smoothed soup (difference with a
// sphere), and the repaired sheet cut by a box (intersection). Inside and outside come from
// the field itself (inside where F >= T), and every crossing along a ray is found, so the
// cut faces are exact.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3, -7>
  look_at <0, 0, 0>
  right x * image_width / image_height
  angle 46
}
light_source { <-5, 8, -8> color rgb 1 }
light_source { <6, 3, -6> color rgb 0.3 shadowless }
background { color rgb <0.86, 0.9, 0.95> }
plane { y, -1.5 pigment { checker color rgb 0.9 color rgb 0.7 } }

#declare Soup = convolution {
  radius 0.3
  offset 0.08
  mesh { "models/soup.obj" }
}

difference {
  object { Soup }
  sphere { <0.7, 0.8, -0.8>, 0.9 }
  pigment { color rgb <0.9, 0.75, 0.3> }
  finish { phong 0.7 diffuse 0.7 }
  translate -1.4 * x
}

intersection {
  convolution {
    radius 1
    offset 0.7
    mesh { "models/holed_sheet.obj" }
    scale 0.55
  }
  box { <-0.8, -1, -0.8>, <0.8, 1, 0.8> rotate 45 * y }
  pigment { color rgb <0.35, 0.6, 0.35> }
  finish { phong 0.4 }
  rotate -25 * x
  translate <1.5, 0, 0>
}
