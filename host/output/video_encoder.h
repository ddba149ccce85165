// Writes an animation as a video (MP4 with H.264 in yuv420p, or an animated GIF) by running
// the ffmpeg program and piping it raw RGB frames (SPEC 3). The video appears under its final
// name complete or not at all, as every output does (SPEC 4).
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace clr {

enum class VideoFormat { Mp4, Gif };

// The format for `path` from its extension (".mp4", ".gif", any case). Throws UsageError for
// any other extension, naming the path and the supported ones.
VideoFormat video_format_for(const std::string& path);

// The ffmpeg program to run: $CLRENDER_FFMPEG when set (a path, or a name looked up on
// $PATH), else "ffmpeg" looked up on $PATH. Call it before rendering, so that a missing
// encoder is reported before any time is spent. Throws OutputError naming what is missing.
std::string find_encoder();

struct VideoSettings {
    std::string path;  // final file name; its extension picks the format
    int width = 0;     // of the frames passed to add_frame, in pixels
    int height = 0;
    double fps = 10;   // frames per second
    int quality = 18;  // MP4 only: x264 CRF, 0-51, lower is better (18 looks lossless to most eyes)
};

// One running ffmpeg, fed a frame at a time. Typical use:
//     VideoEncoder video(settings, find_encoder());
//     for (...) video.add_frame(image);
//     video.finish();
// Without finish() (an exception while rendering), the destructor stops ffmpeg and removes
// everything it wrote. Creating an encoder makes clrender ignore SIGPIPE process-wide, so
// that an encoder that dies mid-stream is reported as an error instead of killing clrender.
class VideoEncoder {
public:
    // Starts ffmpeg writing to a temporary file beside settings.path. Throws UsageError for an
    // unsupported extension, std::invalid_argument for settings out of range, and OutputError
    // when the temporary file cannot be created or the encoder cannot be started.
    VideoEncoder(const VideoSettings& settings, const std::string& encoder_program);
    ~VideoEncoder();
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    // Sends one frame (alpha is dropped). Throws std::invalid_argument unless it is exactly
    // width x height, and OutputError if the encoder has stopped reading (it is then stopped
    // and its files removed; the encoder can take no more frames).
    void add_frame(const Image& rgba);

    // Ends the stream, waits for ffmpeg and moves the video to its final name. Throws
    // OutputError with the reason and the end of ffmpeg's log if encoding failed, leaving
    // nothing under the final name.
    void finish();

private:
    void start();
    void close_stdin();
    int wait_for_encoder();                              // returns the wait status
    void move_into_place();
    void remove_files();
    void abandon() noexcept;                             // stop ffmpeg, remove its files
    [[noreturn]] void fail(const std::string& reason);  // remove the files, throw OutputError

    VideoSettings settings_;
    VideoFormat format_;
    std::string program_;
    std::string temp_path_;  // the video while it is written
    std::string log_path_;   // ffmpeg's stderr
    pid_t pid_ = -1;         // ffmpeg while it runs
    int stdin_fd_ = -1;      // write end of ffmpeg's stdin
    int frames_added_ = 0;
    bool done_ = false;      // finished, or failed and cleaned up
    std::vector<std::uint8_t> rgb_;  // one frame, reused
};

}  // namespace clr
