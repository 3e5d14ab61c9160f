#include "app/video.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "app/option_values.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

extern char** environ;

namespace convray::app {
namespace {

namespace fs = std::filesystem;

// A private folder under the system's temporary folder, removed when this goes away.
class TemporaryFolder {
 public:
  TemporaryFolder() {
    std::string pattern = (fs::temp_directory_path() / "convray-video-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw InputError({pattern}, "cannot create a temporary folder");
    path_ = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// Runs the program with these arguments (no shell), standard input closed; its exit status.
int run_program(const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// H.264 in the containers that expect it, with the pixel format every player reads (which
// needs even sizes); other extensions (.webm, .gif, ...) get ffmpeg's own choice.
std::vector<std::string> codec_arguments(const std::string& video) {
  const std::string extension = lower(fs::path(video).extension().string());
  if (extension == ".mp4" || extension == ".mov" || extension == ".mkv" || extension == ".m4v") {
    return {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2"};
  }
  return {};
}

}  // namespace

std::string find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::istringstream folders(path ? path : "");
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    if (folder.empty()) continue;
    const fs::path candidate = fs::path(folder) / name;
    if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) {
      return candidate.string();
    }
  }
  return "";
}

void check_video_tools(const std::string& video) {
  if (find_on_path("ffmpeg").empty()) {
    throw InputError({video},
                     "--video needs ffmpeg, which is not installed (on Debian: sudo "
                     "apt-get install ffmpeg); render without --video to get the "
                     "frames alone");
  }
  if (!fs::path(video).has_extension()) {
    throw InputError({video},
                     "--video: give the file an extension (.mp4, .webm, .gif, ...) so "
                     "that ffmpeg knows the format");
  }
  check_writable_destination(video, "the video");
}

void assemble_video(const std::vector<std::string>& frames, const std::string& video, double fps) {
  if (frames.empty()) throw InputError({video}, "no frames to assemble");
  // ffmpeg reads a numbered sequence: links 000000, 000001, ... to the frames in order, so a
  // Frame_Step or a subset leaves no gap.
  TemporaryFolder links;
  const std::string extension = fs::path(frames.front()).extension().string();
  for (size_t i = 0; i < frames.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "%06zu", i);
    fs::create_symlink(fs::absolute(frames[i]), links.path() / (name + extension));
  }
  // ffmpeg opens its output by name: it writes inside a private folder beside the video,
  // which is renamed into place only when ffmpeg succeeded (util/atomic_file.hpp).
  AtomicFileByName file(video, "the video", "video" + fs::path(video).extension().string());
  std::vector<std::string> command = {"ffmpeg",
                                      "-nostdin",
                                      "-y",
                                      "-loglevel",
                                      "error",
                                      "-framerate",
                                      std::to_string(fps),
                                      "-i",
                                      (links.path() / ("%06d" + extension)).string()};
  for (const std::string& a : codec_arguments(video)) command.push_back(a);
  command.push_back(file.path().string());
  const int status = run_program(command);
  if (status != 0) {
    throw InputError({video}, "ffmpeg failed (exit status " + std::to_string(status) +
                                  "); its message is above");
  }
  file.commit();
}

}  // namespace convray::app
