// A surface skeleton: a fan of triangles (a leaf) and a stem segment in one convolution
// object. The triangle's field is the paper's closed form, so the leaf is a smooth slab of
// constant thickness with rounded rims; a blob would need hundreds of spheres for it.
// Textured with POV-Ray patterns: a gradient colour map and bumps.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 4.5, -6>
  look_at <0, 0.3, 0.4>
  right x * image_width / image_height
  angle 46
}
light_source { <-4, 9, -5> color rgb 1 }
light_source { <5, 4, -6> color rgb 0.3 shadowless }
background { color rgb <0.95, 0.95, 0.88> }
plane { y, -0.25
  pigment { granite color_map { [0 color rgb <0.55, 0.45, 0.35>] [1 color rgb <0.8, 0.7, 0.55>] } scale 2 }
}

// The right half of the leaf's outline, from the stem's end (the origin) to the tip.
#declare N = 8;
#declare Outline = array[N + 1];
#for (I, 0, N)
  #declare A = pi * I / N;
  #declare Outline[I] = <1.3 * sin(A) * (1 - 0.3 * cos(A)), 0.15 * sin(2 * A), 2.6 * (1 - cos(A)) / 2>;
#end

convolution {
  radius 0.25
  offset 0.06
  #for (I, 1, N - 1)  // Outline[0] is the stem's end: no triangle of zero area
    triangle { <0, 0, 0>, Outline[I], Outline[I + 1] }
    triangle { <0, 0, 0>, Outline[I] * <-1, 1, 1>, Outline[I + 1] * <-1, 1, 1> }
  #end
  segment { <0, 0, -1.2>, <0, 0.05, 2.4> radius 0.22 strength 0.9 }
  pigment {
    gradient z
    color_map { [0 color rgb <0.2, 0.45, 0.1>] [0.6 color rgb <0.45, 0.7, 0.15>] [1 color rgb <0.8, 0.75, 0.2>] }
    scale 2.6
  }
  normal { bumps 0.15 scale 0.1 }
  finish { diffuse 0.75 specular 0.25 roughness 0.02 }
  rotate -15 * y
}
