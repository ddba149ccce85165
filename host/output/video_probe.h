// Checks a finished video before it replaces anything: ffprobe must decode exactly the frames
// that were sent. An encoder that exits 0 after writing garbage, or a file cut short because
// the disk filled up, then never reaches the final name.
#pragma once

#include <functional>
#include <string>

#include "output/encoder_timeout.h"

namespace clr {

// The ffprobe program: $CLRENDER_FFPROBE when set (a path, or a name looked up on $PATH),
// else "ffprobe" in the encoder program's folder (the same ffmpeg build), else on $PATH.
// Throws OutputError naming what is missing.
std::string find_video_prober(const std::string& encoder_program);

struct ProbeResult {
    bool ok = false;
    std::string problem;  // why not, when !ok: "it holds 7 frames, 10 were sent"
};

// Decodes `video` with `prober` (its complaints are appended to the log file `log_path`)
// and compares the frames it reads with `expected_frames`. Gives up after `limit`. Calls
// `check_stop` every 100 ms or so; what it throws stops the prober and passes through.
ProbeResult check_frame_count(const std::string& prober, const std::string& video, long expected_frames,
                              const std::string& log_path, Seconds limit, const std::function<void()>& check_stop);

}  // namespace clr
