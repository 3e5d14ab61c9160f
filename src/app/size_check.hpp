#pragma once
// Jobs sized before they start (issue 17): one whose estimate does not fit in the memory this
// process can have is refused with its estimate and what to change, unless the user insists
// (--force); an insisted job that then runs out of memory still ends with CommandStep's
// message, never an abort.
#include <cstdint>
#include <string>

namespace convray::app {

// Throws UsageError "JOB needs about SIZE (DETAILS), more than the AVAILABLE this process can
// have (physical memory, ulimit -v): ADVICE, or --force to try anyway" when `bytes` exceeds
// memory_available() and `force` is false.
void refuse_unless_fits(uint64_t bytes, const std::string& job, const std::string& details,
                        const std::string& advice, bool force);

// An image of width x height: refused as above when its film, the pixels it is encoded from
// and the encoded file cannot fit; `advice` names the options that set the size.
void refuse_unless_image_fits(int width, int height, const std::string& advice, bool force);

// An animation's `frames` images of width x height written to `output`'s folder: refused when
// their largest size (each image uncompressed in its format, `bits_per_channel` x 3 channels,
// plus a row byte and headers; a PNG is never larger) exceeds the space free there for this
// user (statvfs), unless `force`. Checked before the first frame, so that a run that cannot
// fit does not fill the disk first and fail hours later.
void refuse_unless_frames_fit_on_disk(uint64_t frames, int width, int height, int bits_per_channel,
                                      const std::string& output, bool force);

}  // namespace convray::app
