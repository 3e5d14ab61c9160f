// Metaballs fusing, twice: on the left a convolution of `point` components, on the right a
// POV-Ray `blob` of spheres with the same centres, radius, strength and threshold. A point
// component has the field of a blob sphere, s (1 - d^2/R^2)^2, so the two halves are the
// same surface in every frame: three groups of three balls drift together and fuse as the
// clock runs from 0 to 1, necks growing between them with no seam.
//
// The blob half and the setting are in metaballs_blob.inc, in POV-Ray's language only:
// metaballs_povray.pov renders that half alone, in POV-Ray as in convray, to compare them.
//
//   convray scenes/animations/metaballs.ini
//   convray scenes/animations/metaballs.pov --clock 0.5
#version 3.7;
global_settings { assumed_gamma 1.0 }

#include "metaballs_blob.inc"

convolution {
  threshold MetaThreshold
  #for (I, 0, 8)
    point { MetaCenter(I) radius MetaRadius strength MetaStrength }
  #end
  texture { MetaTexture }
  translate -MetaSpacing * x
}
