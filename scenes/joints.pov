// A segment skeleton without joint bulges (front) next to the same skeleton as POV-Ray's blob
// cylinders (back). A blob cylinder is a capsule of distance kernels: where two meet, their
// fields add and the joint swells. The convolution of segments integrates the kernel along the
// skeleton: a straight run of segments has exactly the field of one segment, and a bend only
// a gentle one.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 5, -9>
  look_at <0, 0.4, 0.6>
  right x * image_width / image_height
  angle 48
}
light_source { <-6, 10, -8> color rgb 1 }
light_source { <8, 5, -4> color rgb 0.3 shadowless }
background { color rgb <0.93, 0.93, 0.9> }
plane { y, -0.8 pigment { color rgb <0.6, 0.62, 0.58> } }

// The zigzag: five points, four segments, the middle two collinear.
#declare P = array[5] { <-3.2, 0, 0>, <-1.6, 1.2, 0>, <0, 0.4, 0>, <1.6, -0.4, 0>, <3.2, 1, 0> }

// Convolution: R = 0.8. A long segment's field at distance q is (16/15) R (1 - q^2/R^2)^(5/2),
// so threshold 0.359 gives it radius 0.433, the blob cylinder's below.
convolution {
  radius 0.8
  threshold 0.359
  #for (I, 0, 3)
    segment { P[I], P[I + 1] }
  #end
  pigment { color rgb <0.2, 0.5, 0.85> }
  finish { phong 0.5 diffuse 0.75 }
  translate -1.2 * z
}

// Blob: capsules of radius 0.8, threshold 0.5, so a lone cylinder has radius
// 0.8 sqrt(1 - sqrt(0.5)) = 0.433, the same thickness as the convolution's.
blob {
  threshold 0.5
  #for (I, 0, 3)
    cylinder { P[I], P[I + 1], 0.8, 1 }
  #end
  pigment { color rgb <0.85, 0.35, 0.2> }
  finish { phong 0.5 diffuse 0.75 }
  translate 2.2 * z
}
