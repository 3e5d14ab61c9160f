// The paper's Fig. 9: the same polygon soup (models/soup.obj, a damaged icosphere of 321
// triangles) convolved with the Cauchy kernel of McCormack and Sherstyuk (left) and with the
// paper's finite-support quartic kernel (right). The Cauchy kernel's infinite support is cut
// per triangle at its bounding box grown by `radius`, so wherever a neighbour's box ends the
// field jumps and the surface steps: the ledges and seams on the left. The quartic kernel is
// zero with zero slope at R, so the right surface is smooth everywhere.
//   convray scenes/kernels/model.pov +W480 +H240 -o model.png
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1.8, -6.6>
  look_at <0, 0, 0>
  right x * image_width / image_height
  angle 42
}
light_source { <-6, 9, -7> color rgb 1 }
light_source { <7, 4, -3> color rgb 0.35 shadowless }
background { color rgb <0.78, 0.84, 0.92> }

plane { y, -1.3
  pigment { checker color rgb 0.85 color rgb 0.55 scale 0.5 }
  finish { diffuse 0.8 ambient 0.1 }
}

#declare Clay = texture {
  pigment { color rgb <0.85, 0.55, 0.35> }
  finish { ambient 0.1 diffuse 0.75 phong 0.6 phong_size 60 }
}

convolution {
  kernel cauchy 6  // 1 / (1 + 36 r^2)^2
  radius 0.25      // truncation margin of each triangle's box
  threshold 0.042  // the field 1.1 from the centre: the surface stands about 0.1 off
  mesh { "../models/soup.obj" }
  texture { Clay }
  translate -1.15 * x
}

convolution {
  radius 0.25
  offset 0.1
  mesh { "../models/soup.obj" }
  texture { Clay }
  translate 1.15 * x
}
