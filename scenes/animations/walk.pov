// A walking figure built from convolution segments and arcs. Each leg is a thigh, a shin and
// a foot (three segments in a row: the knee and the ankle blend without bulges), the hips and
// the shoulders are arcs, the arms two segments each, the torso a thick segment and the head
// a point. One walking cycle (two steps) is clock 0 to 1, and the scene is cyclic: the
// picture at clock 1 is the one at clock 0.
//
// The pose is computed from the clock: the thighs swing sinusoidally, the knee bends during
// the swing, the pelvis height is set so that the lower foot touches the floor (so the body
// bobs by itself), and the body moves forward exactly as far as the foot on the floor moves
// back relative to the hip, so the standing foot never slides. The camera tracks the figure;
// the checker's period is one cycle's distance, so the last frame runs on into the first.
//
//   convray scenes/animations/walk.ini
//   convray scenes/animations/walk.pov --clock 0.25
#version 3.7;
global_settings { assumed_gamma 1.0 }

// Body measures.
#declare Thigh = 0.95;
#declare Shin = 0.95;
#declare FootLength = 0.38;     // from the ankle to the toe
#declare Heel = 0.1;            // from the ankle back to the heel
#declare HipWidth = 0.28;       // half the distance between the hip joints
#declare ShoulderWidth = 0.62;
#declare TorsoLength = 1.35;    // pelvis to neck
#declare UpperArm = 0.75;
#declare Forearm = 0.7;
#declare ThighSwing = 24;       // degrees forward and back
#declare ArmSwing = 20;

// Thicknesses. Every part is a tube of the given radius around its skeleton: a long segment
// of strength s and radius R is a tube of radius r where T = s (16/15) R (1 - r^2/R^2)^(5/2)
// (docs/language.md, "Offset or threshold"), so each part gets the strength that gives its
// thickness at one threshold T. A point of strength s makes a ball of radius r where
// T = s (1 - r^2/R^2)^2.
#declare T = 0.2;
#macro TubeStrength(R, Rtube) (T / ((16 / 15) * R * pow(1 - Rtube * Rtube / (R * R), 2.5))) #end
#macro BallStrength(R, Rball) (T / pow(1 - Rball * Rball / (R * R), 2)) #end
#declare LimbR = 0.32;   // kernel radius of legs and arms: small enough that the legs do not fuse
#declare TorsoR = 0.7;   // as they pass each other

// One leg at phase P (radians): the thigh swings forward while cos(P) > 0 (the swing phase)
// and back while the foot is on the floor; the knee bends most early in the swing.
#macro ThighAngle(P) radians(ThighSwing * sin(P)) #end
#macro KneeBend(P) radians(6 + 58 * pow(max(0, cos(P + 0.35)), 1.5)) #end
// Joint positions relative to the hip, in the plane of walking (x forward, y up).
#macro KneeRel(P) (Thigh * <sin(ThighAngle(P)), -cos(ThighAngle(P)), 0>) #end
#macro ShinDir(P) <sin(ThighAngle(P) - KneeBend(P)), -cos(ThighAngle(P) - KneeBend(P)), 0> #end
#macro AnkleRel(P) (KneeRel(P) + Shin * ShinDir(P)) #end
// The foot is at right angles to the shin: heel down at the front, toe down behind.
#macro FootDir(P) <-ShinDir(P).y, ShinDir(P).x, 0> #end
#macro ToeRel(P) (AnkleRel(P) + FootLength * FootDir(P)) #end
#macro HeelRel(P) (AnkleRel(P) - Heel * FootDir(P)) #end
#macro LowestRel(P) min(AnkleRel(P).y, ToeRel(P).y, HeelRel(P).y) #end

// Phases: at clock 0 the near leg (-z) strikes the floor with its heel, in front; the far leg
// is half a cycle later (at clock 0.5 it is the far leg's turn).
#declare Phase = 2 * pi * clock;
#declare NearPhase = Phase + pi / 2;
#declare FarPhase = NearPhase + pi;

// The stance: one step is half a cycle, from the heel strike (P = pi/2) to the toe-off
// (P = 3 pi/2) of one leg. During a step the hip moves forward by as much as that ankle moves
// back, so a step is StepLength long, and after Steps steps the figure is at HipX.
#declare StepLength = AnkleRel(pi / 2).x - AnkleRel(3 * pi / 2).x;
#declare StepPos = Phase / pi;                   // from 0 to 2 over the cycle: two steps
#declare Steps = floor(StepPos);                 // 0: the near leg stands, 1: the far leg
#declare StancePhase = pi / 2 + (StepPos - Steps) * pi;
#declare HipX = Steps * StepLength + AnkleRel(pi / 2).x - AnkleRel(StancePhase).x;
// Pelvis height: the lower foot rests on the floor (its tube's radius above it).
#declare FootTube = 0.15;
#declare HipY = FootTube - min(LowestRel(NearPhase), LowestRel(FarPhase));
#declare Pelvis = <HipX, HipY, 0>;
#declare Neck = Pelvis + <0.1, TorsoLength, 0>;     // a slight forward lean
#declare Track = 2 * StepLength * clock;            // where the camera looks: steady speed

camera {
  location <Track + 2.2, 2.9, -9.8>
  look_at <Track + 0.2, 2.35, 0>
  right x * image_width / image_height
  angle 42
}
light_source { <Track - 3, 10, -7> color rgb 1 }
light_source { <Track + 6, 4, -6> color rgb 0.3 shadowless }
background { color rgb <0.82, 0.86, 0.92> }
// One cycle moves the figure 2 StepLength: the checker's period, so the floor looks the
// same at clock 0 and 1.
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.72 scale StepLength } }

#declare Trousers = texture { pigment { color rgb <0.2, 0.3, 0.6> }
                              finish { diffuse 0.75 specular 0.2 roughness 0.05 } }
#declare Shirt = texture { pigment { color rgb <0.85, 0.3, 0.2> }
                           finish { diffuse 0.75 specular 0.2 roughness 0.05 } }
#declare Skin = texture { pigment { color rgb <0.92, 0.72, 0.58> }
                          finish { diffuse 0.75 specular 0.3 roughness 0.03 } }
#declare Shoes = texture { pigment { color rgb 0.15 } finish { diffuse 0.7 phong 0.6 } }

// A leg from the hip joint at phase P: thigh, shin and foot are segments in a row.
#macro Leg(HipJoint, P)
  segment { HipJoint, HipJoint + KneeRel(P) radius LimbR strength TubeStrength(LimbR, 0.19)
            texture { Trousers } }
  segment { HipJoint + KneeRel(P), HipJoint + AnkleRel(P)
            radius LimbR strength TubeStrength(LimbR, 0.16) texture { Trousers } }
  segment { HipJoint + HeelRel(P), HipJoint + ToeRel(P)
            radius LimbR strength TubeStrength(LimbR, 0.14) texture { Shoes } }
#end
// An arm from the shoulder, swinging with the opposite leg (phase P of that leg): the upper
// arm swings back while that leg swings back, the elbow bends more in front.
#macro Arm(Shoulder, P)
  #local Swing = radians(ArmSwing * sin(P));
  #local Elbow = Shoulder + UpperArm * <sin(Swing), -cos(Swing), 0>;
  #local Bend = Swing + radians(20 + 15 * sin(P));
  segment { Shoulder, Elbow radius LimbR strength TubeStrength(LimbR, 0.15) texture { Shirt } }
  segment { Elbow, Elbow + Forearm * <sin(Bend), -cos(Bend), 0>
            radius LimbR strength TubeStrength(LimbR, 0.13) texture { Skin } }
#end

convolution {
  threshold T
  // Torso: one thick segment; hips and shoulders are arcs that blend into it.
  segment { Pelvis + 0.1 * y, Neck - 0.1 * y radius TorsoR strength TubeStrength(TorsoR, 0.36)
            texture { Shirt } }
  arc { Pelvis + <0, 0, -HipWidth>, Pelvis + <0, -0.08, 0>, Pelvis + <0, 0, HipWidth>
        radius LimbR strength TubeStrength(LimbR, 0.2) texture { Trousers } }
  arc { Neck + <0, -0.1, -ShoulderWidth>, Neck + <0, 0.02, 0>, Neck + <0, -0.1, ShoulderWidth>
        radius LimbR strength TubeStrength(LimbR, 0.17) texture { Shirt } }
  Leg(Pelvis + <0, 0, -HipWidth>, NearPhase)
  Leg(Pelvis + <0, 0, HipWidth>, FarPhase)
  // The near arm swings with the far leg, the far arm with the near leg.
  Arm(Neck + <0, -0.1, -ShoulderWidth - 0.05>, FarPhase)
  Arm(Neck + <0, -0.1, ShoulderWidth + 0.05>, NearPhase)
  // Neck and head: a short segment and a point; a small point for the nose shows the way.
  segment { Neck, Neck + <0.03, 0.3, 0> radius LimbR strength TubeStrength(LimbR, 0.14)
            texture { Skin } }
  point { Neck + <0.08, 0.62, 0> radius 0.6 strength BallStrength(0.6, 0.33) texture { Skin } }
  point { Neck + <0.4, 0.6, 0> radius 0.15 strength BallStrength(0.15, 0.07) texture { Skin } }
}
