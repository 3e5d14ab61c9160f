// The worked example of docs/language.md: a convolution object with every kind of component.
// A polygon soup read from a file (found through -L), a handle of two segments and an arc, a
// knob with its own texture, and a point of negative strength that cuts a window in the wall.
// From the repository's root:
//   convray docs/examples/convolution.pov -L scenes/models -o pot.png
//   printf '0 0 0\n0 -1 0\n0 -1.2 0\n' |
//     convray field docs/examples/convolution.pov --object Pot -L scenes/models
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.4, 0> right x * image_width / image_height angle 45 }
light_source { <-5, 9, -7> color rgb 1 }
background { color rgb <0.85, 0.88, 0.93> }
plane { y, -1.2 pigment { checker color rgb 0.9 color rgb 0.7 } }

#declare Pot = convolution {
  radius 0.3
  offset 0.08                         // the soup's surface stands 0.08 off its triangles
  mesh { "soup.obj" }                 // a damaged icosphere of radius 1
  // A handle: two segments and an arc, thinner than the body (own radius and strength).
  segment { <1.0, 0.4, 0>, <1.5, 0.4, 0> radius 0.2 strength 1.5 }
  segment { <1.0, -0.4, 0>, <1.5, -0.4, 0> radius 0.2 strength 1.5 }
  arc { <1.5, 0.4, 0>, <1.9, 0, 0>, <1.5, -0.4, 0> radius 0.2 strength 1.5 }
  // A knob with its own colour, and a window: negative strength subtracts.
  point { <0, 1.2, 0> radius 0.45 strength 2 pigment { color rgb <0.2, 0.4, 0.9> } }
  point { <0, 0.2, -1.1> radius 0.4 strength -3 }
  pigment { color rgb <0.9, 0.6, 0.35> }
  finish { phong 0.5 diffuse 0.75 }
}
object { Pot rotate -30 * y }
