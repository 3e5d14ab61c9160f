// The animation benchmark of issue 5 (bench/animation_dragon.sh): the Stanford dragon
// (dragon_vrip_res3, 47,794 triangles) as a convolution mesh component, and in the same
// object a limb of two segments and an arc that sweeps through the dragon's body as the clock
// runs, blending with it wherever their supports meet. The mesh's file and transform are the
// same in every frame, so an animation keeps its acceleration structure; only the limb is
// rebuilt. Render from the repository root:
//   build/convray bench/scenes/dragon_limb.ini
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <-0.9, 1.5, -3.4>
  look_at <0, 0.65, 0>
  right x * image_width / image_height
  angle 40
}
light_source { <-5, 9, -6> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.35 shadowless }
background { color rgb <0.86, 0.89, 0.93> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.75 scale 0.5 } }

// The model is 0.2 units long; scaled by 10 (a component's scale scales its radius too), its
// mean edge is 0.0205; radius 0.012 (0.6 mean edges) keeps the scales and the claws sharp.
#declare R = 0.012;
#declare Offset = 0.006;
#declare T = pi / 3 * pow(R * R - Offset * Offset, 3) / pow(R, 4);

// The limb: shoulder -> elbow (segment), elbow -> wrist (segment), a curled hand (arc). It
// swings from the left of the dragon, through its body, to the right, once over the clock.
#declare Swing = -70 + 140 * clock;
#declare Shoulder = <0, 1.5, -0.3>;
#declare Elbow = Shoulder + vrotate(<0, -0.55, 0>, <0, 0, Swing>);
#declare Wrist = Elbow + vrotate(<0, -0.5, -0.05>, <0, 0, 0.6 * Swing>);
#declare LimbRadius = 0.16;
// A long segment's field at distance q is s (16/15) R (1 - q^2/R^2)^(5/2): a tube of radius
// 0.085 on its own.
#declare LimbStrength = T / ((16 / 15) * LimbRadius * pow(1 - 0.085 * 0.085 / (LimbRadius * LimbRadius), 2.5));

convolution {
  threshold T
  mesh { "dragon_vrip_res3.ply.gz"
    radius R / 10
    translate <0.006, -0.0528 + Offset / 10, 0.0045>
    scale 10
    pigment { color rgb <0.25, 0.6, 0.35> }
  }
  segment { Shoulder, Elbow radius LimbRadius strength LimbStrength }
  segment { Elbow, Wrist radius LimbRadius strength LimbStrength }
  arc { Wrist, Wrist + vrotate(<0.12, -0.1, 0>, <0, 0, Swing>),
        Wrist + vrotate(<0.22, 0.02, 0>, <0, 0, Swing>)
        radius LimbRadius strength LimbStrength }
  pigment { color rgb <0.85, 0.45, 0.3> }
  finish { ambient 0.1 diffuse 0.7 specular 0.4 roughness 0.02 }
}
