// Which frames of an animation to render (--frames) and where each one is written (-o with a
// frame pattern). Frames are numbered from 0.
#pragma once

#include <string>
#include <vector>

namespace clr {

// Parses "7", "0-99" or "5,7,10-20": comma-separated frame numbers and inclusive ranges,
// spaces around items allowed. Returns the frames ascending, each once. Throws UsageError
// for bad syntax ("5-", "a", "3-1", an empty item) or a frame >= frame_count.
std::vector<int> parse_frame_list(const std::string& text, int frame_count);

// Whether the file-name part of `path` holds a frame-number placeholder: printf-style "%d"
// or "%0Nd" (as ffmpeg reads them: "%Nd" pads with zeros too), or a run of '#' (Blender's
// style, padded to the number of '#').
bool is_frame_pattern(const std::string& path);

// `pattern` with its first placeholder (in the file-name part) replaced by `frame`:
// "out_%04d.png" and "out_####.png" give "out_0007.png", "out_%d.png" gives "out_7.png".
// A frame wider than the padding is written in full. Throws UsageError if `pattern` has no
// placeholder, std::invalid_argument for a negative frame.
std::string frame_path(const std::string& pattern, int frame);

}  // namespace clr
