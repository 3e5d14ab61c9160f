// The blob half of metaballs.pov alone, for POV-Ray 3.7 (which has no `convolution`): the
// same camera, lights, floor and blob as metaballs.pov, so POV-Ray's picture of it can be
// compared with convray's, pixel for pixel, at any clock:
//
//   povray +Iscenes/animations/metaballs_povray.pov +K0.5 +W320 +H240 -D -P +O/tmp/povray.png
//   convray scenes/animations/metaballs_povray.pov --clock 0.5 --width 320 --height 240 -o /tmp/convray.png
#version 3.7;
global_settings { assumed_gamma 1.0 }

#include "metaballs_blob.inc"
