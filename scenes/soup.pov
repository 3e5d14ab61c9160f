// A polygon soup made smooth. models/soup.obj is a damaged icosphere: holes (7 boundary
// edges), non-manifold edges, flipped and degenerate faces. Convolving its triangles with the
// finite-support kernel gives one smooth closed surface whatever the damage; the radius R sets
// how much detail survives (left R = 0.15, right R = 0.45), the offset how far the surface
// stands off the triangles.
//   convray scenes/soup.pov -o soup.png
//   echo '0 0 0' | convray field scenes/soup.pov --object Soup
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 2.2, -6.5>
  look_at <0, 0.1, 0>
  right x * image_width / image_height
  angle 45
}
light_source { <-6, 9, -7> color rgb 1 }
light_source { <7, 4, -3> color rgb 0.35 shadowless }
background { color rgb <0.78, 0.84, 0.92> }

plane { y, -1.45
  pigment { checker color rgb 0.85 color rgb 0.55 scale 0.5 }
  finish { diffuse 0.8 ambient 0.1 }
}

#declare Clay = texture {
  pigment { color rgb <0.85, 0.55, 0.35> }
  finish { ambient 0.1 diffuse 0.75 phong 0.6 phong_size 60 }
}

#declare Soup = convolution {
  radius 0.15
  offset 0.04
  mesh { "models/soup.obj" }
  texture { Clay }
}

object { Soup translate -1.3 * x }

convolution {
  radius 0.45
  offset 0.12
  mesh { "models/soup.obj" }
  texture { Clay }
  translate 1.3 * x
}
