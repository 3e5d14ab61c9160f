// The reference for tests/render/povray_camera_test.cpp: an off-centre sphere seen through a
// look_at camera, flat white on black, so each pixel says hit or miss. Regenerate with
//   povray +Ipovray_sphere.pov +Opovray_sphere_160x120.png +W160 +H120 -A -D -V
//   povray +Ipovray_sphere.pov +Opovray_sphere_161x97.png +W161 +H97 -A -D -V
// (POV-Ray 3.7.0.10). `right` follows the image's aspect, as convray's camera does.
camera {
  perspective
  location <0.3, 0.4, -5>
  right x * image_width / image_height
  up y
  angle 40
  look_at <0.1, 0.05, 0>
}
background { rgb 0 }
sphere { <0.7, 0.45, 0>, 0.5 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }
