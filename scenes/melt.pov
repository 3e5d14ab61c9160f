// A segment melting into a mesh. Segment and mesh are components of one convolution object,
// so their fields add: as the segment comes closer (left to right: gaps 0.9, 0.45, 0) a neck
// grows between them smoothly, with no seam. Rendered as an animation, `clock` moves it
// (the middle copy follows the clock: convray scenes/melt.pov +K0.5).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 2.5, -10>
  look_at <0, 0.3, 0>
  right x * image_width / image_height
  angle 50
}
light_source { <-6, 10, -8> color rgb 1 }
light_source { <8, 4, -6> color rgb 0.3 shadowless }
background { color rgb <0.97, 0.95, 0.9> }
plane { y, -1.3 pigment { color rgb <0.75, 0.72, 0.66> } }

// The soup (radius about 1) and, above it, a horizontal segment `Gap` above its top.
#macro Melting(Gap)
  convolution {
    radius 0.35
    offset 0.1
    mesh { "models/soup.obj" }
    segment { <-0.9, 1.1 + Gap, 0>, <0.9, 1.1 + Gap, 0> radius 0.5 }
    pigment { color rgb <0.95, 0.45, 0.3> }
    finish { phong 0.5 diffuse 0.75 }
  }
#end

object { Melting(0.9) translate -3.2 * x }
object { Melting(0.45 - 0.45 * clock) }
object { Melting(0) translate 3.2 * x }
