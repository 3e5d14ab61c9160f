// A close look at the Cauchy surface of scenes/kernels/model.pov (left object there): the
// polygon soup models/soup.obj under `kernel cauchy 6` with each triangle's field cut at its
// bounding box grown by 0.25. Each place where a neighbour's box ends is a step in the field
// and a ledge in the surface, whose faces are the box's faces (lit by their normals).
//   convray scenes/kernels/model-closeup.pov +W480 +H360 -o model-closeup.png
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <-1.3, 1.6, -3.3>
  look_at <0, 0.1, 0>
  right x * image_width / image_height
  angle 40
}
light_source { <-6, 9, -7> color rgb 1 }
light_source { <7, 4, -3> color rgb 0.35 shadowless }
background { color rgb <0.78, 0.84, 0.92> }

convolution {
  kernel cauchy 6
  radius 0.25
  threshold 0.042
  mesh { "../models/soup.obj" }
  texture {
    pigment { color rgb <0.85, 0.55, 0.35> }
    finish { ambient 0.1 diffuse 0.75 phong 0.6 phong_size 60 }
  }
}
