// The check that decodes a finished video (video_probe.h) runs ffprobe on every CPU clrender
// may use: ffprobe decodes on one thread by default, and nothing else runs by then.
#include <gtest/gtest.h>
#include <sched.h>
#include <sys/stat.h>

#include <string>

#include "output/video_encoder.h"
#include "support/scoped_env.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::read_bytes;
using testing::ScopedEnv;
using testing::TempFolder;

std::string executable(const TempFolder& folder, const std::string& name, const std::string& body) {
    const std::string path = folder.write(name, "#!/bin/sh\n" + body + "\n");
    ::chmod(path.c_str(), 0755);
    return path;
}

TEST(VideoCheckThreads, FfprobeDecodesOnEveryUsableCpu) {
    TempFolder scripts, folder;
    // The encoder copies its input to its output (its last argument); the checker notes its
    // arguments and counts the one frame sent.
    const std::string encoder = executable(scripts, "fake-ffmpeg", "for last; do :; done; cat >\"$last\"");
    const std::string prober =
        executable(scripts, "fake-ffprobe", "echo \" $* \" >'" + scripts.file("arguments") + "'; echo 1");
    ScopedEnv checker("CLRENDER_FFPROBE", prober.c_str());
    Image frame;
    frame.width = 4;
    frame.height = 2;
    frame.rgba.assign(4 * 2 * 4, 128);
    VideoEncoder video({folder.file("out.mp4"), 4, 2}, encoder);
    video.add_frame(frame);
    video.finish();

    cpu_set_t allowed;
    ASSERT_EQ(::sched_getaffinity(0, sizeof(allowed), &allowed), 0);
    const std::string arguments = read_bytes(scripts.file("arguments"));
    EXPECT_NE(arguments.find(" -threads " + std::to_string(CPU_COUNT(&allowed)) + " "), std::string::npos) << arguments;
    EXPECT_NE(arguments.find(" -count_frames "), std::string::npos) << arguments;
}

}  // namespace
}  // namespace clr
