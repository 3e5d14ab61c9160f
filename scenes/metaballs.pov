// Points are the paper's simplest skeleton, and POV-Ray's blob spheres use the same quartic
// kernel: a convolution of points (left) and a blob of spheres (right) with the same radii,
// strengths and threshold are the same surface. Convolution objects then add what blobs do
// not have: segments, arcs, triangles and meshes in the same field (the ring of segments
// around the left cluster fuses with it).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 4, -9>
  look_at <0, 0.5, 0>
  right x * image_width / image_height
  angle 44
}
light_source { <-6, 10, -8> color rgb 1 }
light_source { <6, 3, -8> color rgb 0.3 shadowless }
background { color rgb <0.1, 0.1, 0.14> }
plane { y, -0.6 pigment { color rgb 0.5 } finish { reflection 0.15 } }

#declare Centers = array[5] { <0, 0.5, 0>, <0.9, 0.9, 0.2>, <-0.8, 1.1, -0.3>, <0.2, 1.6, 0.4>,
                              <-0.3, 0.3, 0.8> }

convolution {
  threshold 0.4
  #for (I, 0, 4)
    point { Centers[I] radius 1.1 strength 1 }
  #end
  #for (K, 0, 5)
    segment { vrotate(<1.6, 0.4, 0>, 60 * K * y), vrotate(<1.6, 0.4, 0>, 60 * (K + 1) * y)
              radius 0.5 strength 2 }
  #end
  pigment { color rgb <0.3, 0.8, 0.5> }
  finish { phong 0.8 diffuse 0.7 }
  translate -2.3 * x
}

blob {
  threshold 0.4
  #for (I, 0, 4)
    sphere { Centers[I], 1.1, 1 }
  #end
  pigment { color rgb <0.3, 0.8, 0.5> }
  finish { phong 0.8 diffuse 0.7 }
  translate 2.3 * x
}
