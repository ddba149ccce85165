// Progress of a run, for people and for scripts (docs/command-line.md, Progress):
// - a bar on a terminal: percentage, elapsed and remaining time, redrawn after every band of
//   rows, so a long still shows it as an animation does; silent with -q, or when standard
//   error is not a terminal (logs stay clean);
// - --progress json: one JSON object per line on standard error, on a terminal or not, for
//   render farms and scripts: per band for a still, per frame for an animation.
#pragma once

#include <string>

#include "core/stopwatch.h"

namespace clr {

enum class ProgressStyle { Bar, None, Json };

// "bar", "none", "json" as --progress takes them; nullopt-free: the caller checks the value.
ProgressStyle progress_style_named(const std::string& name);

class Progress {
public:
    // `quiet` (-q) silences the bar, not the JSON lines that --progress json asks for.
    Progress(int total_frames, ProgressStyle style, bool quiet);
    // Ends an unfinished bar line, so that an error or interruption message that follows (the
    // frame loop unwinds through here) starts on its own line.
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    // The animation frame index the next updates are about; the first starts the clock.
    void frame_started(int frame);
    // `fraction` (0..1) of the current frame is rendered: called after each band of rows.
    void frame_part_done(double fraction);
    // The current frame is rendered (or, with --resume, found finished). `in_place`: how many of
    // the run's frames have their file under its final name by now, which JSON lines report as
    // "frames_done": a frame handed to the writer is not yet a file (a full disk may still fail it).
    void frame_done(int in_place);
    void finish();  // ends the progress line
    // Every output of the run is under its final name (the still's image, the video, the
    // report): the last JSON line, with every frame done.
    void all_in_place();

private:
    double fraction_of_run() const;
    void draw_bar();
    void print_json_line() const;

    int total_;
    int done_ = 0;      // frames rendered
    int in_place_ = 0;  // frames whose files are under their final names
    bool started_ = false;
    int frame_ = 0;
    double frame_fraction_ = 0;
    bool bar_;
    bool json_;
    bool line_open_ = false;  // a bar is drawn and its line not yet ended
    Stopwatch since_start_;
    Stopwatch since_last_part_;  // the last update shown within a frame
};

// "1:05" or "12:03:07": a duration for people.
std::string format_duration(double seconds);

// The bar line without its leading carriage return, e.g.
// "clrender: [########            ]  40%  frame 3/5  0.50 frames/s  elapsed 0:04  left 0:06" (frames per
// second once a frame of an animation is done).
std::string format_progress_bar(double fraction, int frames_done, int frames, double elapsed_s);

// Frames per second for the bar: "12", "2.4", "0.25".
std::string format_frame_rate(double frames_per_second);

// One --progress json line (without the newline): {"frame", "frames", "frames_done",
// "percent", "elapsed_s", "eta_s"}; eta_s is null until some of the work is done.
std::string format_progress_json(int frame, int frames, int frames_done, double fraction, double elapsed_s);

}  // namespace clr
