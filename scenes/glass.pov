// Glass and mirrors: a ring of four arcs (a smooth torus made from a circular skeleton) in
// glass, ior 1.5, and a chrome bead chain of segments, on a checker floor in front of a mirror.
// Refraction, total internal reflection, reflection and filtered shadows, traced recursively.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }

camera {
  location <0, 3, -7.5>
  look_at <0, 0.6, 0>
  right x * image_width / image_height
  angle 44
}
light_source { <-4, 9, -6> color rgb 1 }
background { color rgb <0.55, 0.7, 0.9> }

plane { y, 0
  pigment { checker color rgb <0.9, 0.9, 0.85> color rgb <0.15, 0.2, 0.3> }
  finish { diffuse 0.8 reflection 0.05 }
}
// The mirror behind.
box { <-6, 0, 3>, <6, 4, 3.2>
  pigment { color rgb 0.05 }
  finish { reflection 0.85 ambient 0 diffuse 0.1 }
}

// Glass ring: arcs through three points each, a circle of radius 1.2 in the plane y = 1.3.
#declare Ring = 1.2;
convolution {
  radius 0.6
  offset 0.3
  #for (K, 0, 3)
    arc { vrotate(<Ring, 0, 0>, y * 90 * K), vrotate(<Ring, 0, 0>, y * (90 * K + 45)),
          vrotate(<Ring, 0, 0>, y * 90 * (K + 1)) }
  #end
  pigment { color rgbf <0.95, 1, 0.97, 0.92> }
  finish { ambient 0 diffuse 0.05 phong 0.9 phong_size 120 reflection 0.08 }
  interior { ior 1.5 }
  rotate 70 * x
  translate <-1.3, 1.65, 0>
}

// Chrome chain: a zigzag of segments.
convolution {
  radius 0.5
  offset 0.25
  #for (K, 0, 4)
    segment { <0.5 * K, 0.45 + 0.35 * mod(K, 2), 0>, <0.5 * (K + 1), 0.45 + 0.35 * mod(K + 1, 2), 0> }
  #end
  pigment { color rgb <0.8, 0.8, 0.85> }
  finish { ambient 0 diffuse 0.1 reflection 0.75 metallic phong 0.9 phong_size 200 }
  translate <0.6, 0, -0.8>
}
