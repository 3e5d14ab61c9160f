#pragma once
// The files a render writes, named as POV-Ray names them:
//   no +O                 the scene's base name with .png, in the current folder
//   +Oout/  (a folder)    the scene's base name with .png, in that folder
//   +Oname  (no extension)  name.png
//   animation frames      the name plus the frame number, zero-padded to the width of the
//                         final frame number: +Oout/walk.png, frame 7 of 48 -> out/walk07.png
#include <string>

namespace convray::app {

// Whether `output` names a folder: it ends with '/' or is an existing directory.
bool names_folder(const std::string& output);

// The still image's file for this scene and +O value (possibly empty).
std::string resolve_output(const std::string& output, const std::string& scene);

// The file of one frame, from the still's file name.
std::string frame_file_name(const std::string& still_name, long long frame, int digits);

}  // namespace convray::app
