// A figure from a skeleton of segments and arcs: torso and limbs are segments, the shoulders
// and the hips arcs, the head a point. The joints blend without bulges or creases. Each part
// is a named position, so an animation can move them with the clock.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <1.5, 3.2, -8>
  look_at <0, 2.1, 0>
  right x * image_width / image_height
  angle 40
}
light_source { <-5, 9, -7> color rgb 1 area_light <1.5, 0, 0>, <0, 0, 1.5>, 3, 3 }
light_source { <6, 5, -5> color rgb 0.25 shadowless }
background { color rgb <0.85, 0.88, 0.93> }
plane { y, 0 pigment { checker color rgb 0.92 color rgb 0.78 } }

#declare Swing = 25 * sin(2 * pi * clock);
#declare Neck = <0, 3.4, 0>;
#declare Pelvis = <0, 2.0, 0>;
#declare LeftShoulder = <-0.6, 3.15, 0>;
#declare RightShoulder = <0.6, 3.15, 0>;
#declare LeftHip = <-0.35, 1.85, 0>;
#declare RightHip = <0.35, 1.85, 0>;

convolution {
  radius 0.45
  offset 0.26
  segment { Neck, Pelvis }
  arc { LeftShoulder, <0, 3.3, 0>, RightShoulder }
  arc { LeftHip, <0, 1.95, 0>, RightHip }
  // Arms: upper and lower, swinging.
  segment { LeftShoulder, LeftShoulder + vrotate(<-0.2, -0.8, 0>, x * Swing) }
  segment { LeftShoulder + vrotate(<-0.2, -0.8, 0>, x * Swing),
            LeftShoulder + vrotate(<-0.25, -1.55, -0.2>, x * Swing) }
  segment { RightShoulder, RightShoulder + vrotate(<0.2, -0.8, 0>, -x * Swing) }
  segment { RightShoulder + vrotate(<0.2, -0.8, 0>, -x * Swing),
            RightShoulder + vrotate(<0.25, -1.55, -0.2>, -x * Swing) }
  // Legs.
  segment { LeftHip, LeftHip + vrotate(<-0.05, -0.9, 0>, -x * Swing) }
  segment { LeftHip + vrotate(<-0.05, -0.9, 0>, -x * Swing),
            LeftHip + vrotate(<-0.1, -1.75, 0.1>, -x * Swing) }
  segment { RightHip, RightHip + vrotate(<0.05, -0.9, 0>, x * Swing) }
  segment { RightHip + vrotate(<0.05, -0.9, 0>, x * Swing),
            RightHip + vrotate(<0.1, -1.75, 0.1>, x * Swing) }
  // Head: a point of its own radius and strength.
  point { <0, 3.85, 0> radius 0.75 strength 1.6 }
  pigment { color rgb <0.9, 0.7, 0.55> }
  finish { diffuse 0.75 specular 0.3 roughness 0.03 }
}
