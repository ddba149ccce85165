// Writes an animation as a video (MP4 with H.264 in yuv420p, or an animated GIF) by running
// the ffmpeg program and piping it the raw frames (docs/command-line.md, Outputs). The
// video appears under its final name complete or not at all, as every output does
// (docs/command-line.md, Failures).
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/folder_entry.h"
#include "core/image.h"
#include "output/atomic_file.h"
#include "output/child_process.h"
#include "output/encoder_timeout.h"

namespace clr {

enum class VideoFormat { Mp4, Gif };

// The format for `path` from its extension (".mp4", ".gif", any case). Throws UsageError for
// any other extension, naming the path and the supported ones.
VideoFormat video_format_for(const std::string& path);

// The frame rates each format holds, measured with Debian 12's ffmpeg 5.1 (docs/animation.md,
// Frame rates): a GIF's frame delays are whole hundredths of a second from 2 to 65535 (ffmpeg
// writes a delay of 1 as 10, and clips longer ones); ffmpeg's MP4 muxer fails with x264 below
// about 1.2e-5 frames per second, and clrender's whole pipeline gave a video with 1 of 3 frames
// at 1e-4 while 2e-4 held: 0.001 keeps a margin of 5.
constexpr double kMinMp4Fps = 0.001, kMaxMp4Fps = 1000;
constexpr double kMinGifFps = 100.0 / 65535, kMaxGifFps = 50;

// The threads x264 encodes an MP4 with, on every machine (docs/animation.md, MP4 encoding).
// x264's output depends on its thread count, so a count taken from the machine would give
// other bytes for the same frames on another machine (a farm's 1-CPU node against a desktop);
// a constant keeps them the same everywhere. Frame threads are deterministic for a given count;
// x264's lookahead thread is not, and is turned off (video_encoder.cpp, mp4_arguments).
constexpr int kX264Threads = 4;

// "" when a video of `format` can hold `fps` frames per second, else why not, with the range
// it takes ("a GIF takes from 0.0015259 to 50 frames per second (...)").
std::string video_fps_problem(double fps, VideoFormat format);

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
//     video.finish();    // or finish_uncommitted(), to rename it later with other outputs
// Without finish() (an exception while rendering), the destructor stops ffmpeg and removes
// everything it wrote. Creating an encoder makes clrender ignore SIGPIPE process-wide, so
// that an encoder that dies mid-stream is reported as an error instead of killing clrender.
//
// No call blocks for long: every wait on ffmpeg is made in slices of at most 100 ms that check
// interruption_requested() (then ffmpeg is stopped, its files removed and Interrupted thrown)
// and cancel(); an encoder that makes no progress for encoder_stall_timeout() is an error.
class VideoEncoder {
public:
    // Starts ffmpeg writing to a temporary file beside settings.path. Throws UsageError for an
    // unsupported extension or a bad $CLRENDER_ENCODER_TIMEOUT, std::invalid_argument for
    // settings out of range, and OutputError when ffprobe is missing, the temporary file
    // cannot be created or the encoder cannot be started.
    VideoEncoder(const VideoSettings& settings, const std::string& encoder_program);
    ~VideoEncoder();
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    // Sends one frame: an MP4's converted to yuv420p (output/yuv420_frame.h), a GIF's as it is
    // (ffmpeg ignores the alpha bytes); `rgba` can be reused once this returns. Throws
    // std::invalid_argument unless it is exactly
    // width x height, and OutputError if the encoder has stopped reading (it is then stopped
    // and its files removed; the encoder can take no more frames).
    void add_frame(const Image& rgba);

    // Ends the stream, waits for ffmpeg, checks the video with ffprobe (exactly the frames
    // sent) and syncs it, but leaves it under its temporary name: the returned file renames it
    // into place on commit() (together with the other outputs of the run, staged_outputs.h)
    // and removes it if destroyed uncommitted. Throws OutputError with the reason and the end
    // of ffmpeg's log if encoding failed, leaving nothing new under the final name.
    std::unique_ptr<AtomicFile> finish_uncommitted();
    // finish_uncommitted(), then the rename into place.
    void finish();

    // Thread-safe: makes a wait in add_frame or finish (on another thread) give up within
    // about 100 ms, throwing OutputError, so that the encoder can be abandoned.
    void cancel() noexcept { cancelled_ = true; }

private:
    void start();
    void send(const std::uint8_t* data, std::size_t size);
    [[noreturn]] void fail_after_broken_pipe();
    int wait_after_last_frame();                         // returns ffmpeg's wait status
    void check_video();
    void check_stop();  // interrupted, cancelled or the log over its bound: abandon, throw
    void close_stdin();
    void remove_files();
    void abandon() noexcept;                             // stop ffmpeg, remove its files
    [[noreturn]] void fail(const std::string& reason);  // remove the files, throw OutputError

    VideoSettings settings_;
    VideoFormat format_;
    std::string program_;
    std::string prober_;     // ffprobe, which checks the finished video
    Seconds stall_timeout_;  // the longest the encoder may make no progress
    std::string temp_path_;  // the video while it is written
    std::string log_path_;   // ffmpeg's stderr
    // Both removed through their folder held open: renaming the output folder during a render
    // must not leave them behind.
    FolderEntry temp_entry_, log_entry_;
    std::unique_ptr<ChildProcess> encoder_;  // ffmpeg while it runs
    int stdin_fd_ = -1;      // write end of ffmpeg's stdin, non-blocking
    std::vector<std::uint8_t> converted_;  // an MP4's frame as yuv420p, reused from frame to frame
    int frames_added_ = 0;
    bool done_ = false;      // finished, or failed and cleaned up
    std::atomic<bool> cancelled_{false};
};

}  // namespace clr
