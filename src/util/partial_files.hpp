#pragma once
// The temporaries an atomic write leaves beside its destination while it runs, and what
// happens to them when a run does not finish.
//
// A temporary for DIR/NAME is DIR/.NAME.convray.HOST.PID.RANDOM.partial (a plain file) or the
// same name ending in .partial.d (a private folder, for writers that open files by name:
// OpenImageIO's, ffmpeg). The name says who owns it, so
//   - a run killed by SIGINT, SIGTERM, SIGHUP or SIGQUIT removes its temporaries on the way
//     out (the handlers unlink what is registered here, then die of the same signal);
//   - a run killed with SIGKILL (or a power cut) leaves them, and the next run that writes to
//     the same destination removes those whose owner is gone: same host, process no longer
//     alive, same user. Temporaries of live processes, of other hosts (a shared network
//     folder) and of other users are never touched.
#include <filesystem>
#include <string>

namespace convray {

// A fresh temporary name for `destination`, in its folder (RANDOM from the OS's entropy).
std::filesystem::path partial_name_for(const std::filesystem::path& destination,
                                       const char* suffix = ".partial");

// Whether `entry` (a name in the destination's folder) is a temporary for `destination`
// whose owner process is gone; only temporaries of this host and user can be.
bool is_orphaned_partial(const std::filesystem::path& destination, const std::string& entry);

// Removes the orphaned temporaries of `destination` (files, and private folders with what
// they hold). Best effort: what cannot be removed stays.
void remove_orphaned_partials(const std::filesystem::path& destination);

// Registers a path to unlink (a file) or rmdir (a folder, once its file is gone) if a
// terminating signal arrives before unregister_partial; installs the handlers on first use.
// At most 64 paths at once; more are simply not cleaned at a signal.
void register_partial(const std::filesystem::path& path);
void unregister_partial(const std::filesystem::path& path);

}  // namespace convray
