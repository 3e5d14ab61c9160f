#pragma once
// `--video FILE`: the rendered frames assembled into one video by ffmpeg (Debian package
// ffmpeg), which convray runs as a separate program when it is installed; convray itself
// links no video library.
#include <string>
#include <vector>

namespace convray::app {

// The full path of an executable `name` on PATH, or empty.
std::string find_on_path(const std::string& name);

// Throws InputError naming the video file when ffmpeg is missing (with how to install it):
// checked before any frame is rendered.
void check_video_tools(const std::string& video);

// Writes `video` from the frames, in order, at `fps` frames per second. The file appears
// complete or not at all (written under a temporary name, then renamed). Throws InputError
// with ffmpeg's exit status when it fails.
void assemble_video(const std::vector<std::string>& frames, const std::string& video, double fps);

}  // namespace convray::app
