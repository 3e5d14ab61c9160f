// The paper's Fig. 6: one triangle convolved with the Cauchy kernel of McCormack and
// Sherstyuk (left, `kernel cauchy 4`: 1 / (1 + 16 r^2)^2, truncated to the triangle's box
// grown by 0.6) and with the paper's quartic kernel (right, R = 0.25). Both surfaces stand
// 0.08 off the triangle's flat middle (offset), and both round its edges and corners; the
// Cauchy surface is wider at the corners because its kernel reaches further.
//   convray scenes/kernels/triangle.pov +W480 +H240 -o triangle.png
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 3.2, -3.4>
  look_at <0, -0.05, 0.05>
  right x * image_width / image_height
  angle 40
}
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 3, -4> color rgb 0.35 shadowless }
background { color rgb <0.78, 0.84, 0.92> }

plane { y, -0.35
  pigment { checker color rgb 0.85 color rgb 0.6 scale 0.25 }
  finish { diffuse 0.8 ambient 0.1 }
}

#declare Clay = texture {
  pigment { color rgb <0.85, 0.55, 0.35> }
  finish { ambient 0.1 diffuse 0.75 phong 0.5 phong_size 40 }
}

#declare Corners = array[3] { <-0.8, 0, -0.5>, <0.8, 0, -0.5>, <0.1, 0, 0.8> }

convolution {
  kernel cauchy 4
  radius 0.6        // with kernel cauchy: the truncation margin around the triangle's box
  threshold 0.1438  // the field 0.08 above the centroid (convray field)
  triangle { Corners[0], Corners[1], Corners[2] }
  texture { Clay }
  translate -0.95 * x
}

convolution {
  radius 0.25
  offset 0.08
  triangle { Corners[0], Corners[1], Corners[2] }
  texture { Clay }
  translate 0.95 * x
}
