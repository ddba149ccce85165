// What a viewer of an MP4 sees is what clrender rendered: the video's frames, decoded and
// converted back to RGB as the stream's tags say (BT.709, limited range), against the frames
// clrender wrote as PPM files in the same run (docs/animation.md, MP4 encoding).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "support/command.h"
#include "support/small_disk.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

using testing::have_program;
using testing::read_bytes;
using testing::run_clrender;
using testing::TempFolder;

const char* kAnimatedScene = R"({
  "eyeLocations": [[-3, 1, 8], [3, 2, 7]], "lookat": [0, 0, 0], "up": [0, 1, 0], "fov_angle": 55,
  "width": 64, "height": 48, "DefaultColor": [0.1, 0.1, 0.2],
  "spheres": [{"center": [0, 0, 0], "radius": 1.5, "ambient": [1, 0.3, 0.2]}]
})";

// The pixels of a binary PPM ("P6 width height 255", then RGB), empty if it is not one.
std::string ppm_pixels(const std::string& bytes, int width, int height) {
    std::istringstream header(bytes);
    std::string magic;
    int file_width = 0, file_height = 0, maximum = 0;
    header >> magic >> file_width >> file_height >> maximum;
    if (magic != "P6" || file_width != width || file_height != height || maximum != 255) return "";
    const std::size_t start = static_cast<std::size_t>(header.tellg()) + 1;  // one whitespace byte
    return bytes.substr(start);
}

// At --quality 0 x264 is lossless, so what remains is the conversion: 8-bit rounding there and
// back (within 2 levels) and 4:2:0, where four pixels share one colour difference, which shows
// along the edge of the sphere only. Decoded as BT.601 instead, the mean is 3 levels and 84%
// of the values are within 2; here the mean was 0.57 and 98.3% within 2.
TEST(Mp4FramesCli, DecodedFramesMatchTheRenderedOnes) {
    if (!have_program("ffmpeg") || !have_program("ffprobe")) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder folder;
    folder.write("anim.json", kAnimatedScene);
    const int width = 161, height = 121;  // odd: the video is padded, the comparison is not
    const auto result = run_clrender("anim.json -q --size 161x121 --quality 0 -o 'f_%04d.ppm' --video anim.mp4",
                                     folder.path());
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string decoded_path = folder.file("decoded.rgb");
    const std::string command = "ffmpeg -v error -i '" + folder.file("anim.mp4") +
                                "' -vf scale=in_color_matrix=bt709:in_range=tv:flags=neighbor+accurate_rnd+full_chroma_int,"
                                "format=rgb24,crop=161:121:0:0 -f rawvideo -pix_fmt rgb24 -y '" + decoded_path + "'";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    const std::string decoded = read_bytes(decoded_path);
    const std::size_t frame_bytes = static_cast<std::size_t>(width) * height * 3;
    ASSERT_GT(decoded.size(), 0u);
    ASSERT_EQ(decoded.size() % frame_bytes, 0u);
    const int frames = static_cast<int>(decoded.size() / frame_bytes);
    ASSERT_GE(frames, 2);

    long long total = 0, within_2 = 0, values = 0;
    for (int frame = 0; frame < frames; ++frame) {
        char name[32];
        std::snprintf(name, sizeof name, "f_%04d.ppm", frame);
        const std::string rendered = ppm_pixels(read_bytes(folder.file(name)), width, height);
        ASSERT_EQ(rendered.size(), frame_bytes) << name;
        for (std::size_t i = 0; i < frame_bytes; ++i) {
            const int difference = std::abs(static_cast<unsigned char>(rendered[i]) -
                                            static_cast<unsigned char>(decoded[frame * frame_bytes + i]));
            total += difference;
            within_2 += difference <= 2;
            ++values;
        }
    }
    EXPECT_LE(static_cast<double>(total) / values, 1.0) << "mean absolute difference, levels";
    EXPECT_GE(static_cast<double>(within_2) / values, 0.97) << "fraction of values within 2 levels";
}

}  // namespace
}  // namespace clr
