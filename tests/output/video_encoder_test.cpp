// VideoEncoder: real videos checked with ffprobe (skipped where ffmpeg is not installed), and
// fake encoders (small shell scripts chosen through CLRENDER_FFMPEG) that fail in the ways a
// real one can, to show that failures are reported and leave nothing behind.
#include "output/video_encoder.h"

#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cmath>
#include <chrono>
#include <thread>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.h"
#include "output/encoder_timeout.h"
#include "output/video_probe.h"
#include "output/yuv420_frame.h"
#include "support/scoped_env.h"
#include "support/taken_temp_names.h"
#include "support/temp_folder.h"

namespace clr {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::TempFolder;

using testing::ScopedEnv;

// The real encoder, or nullopt where ffmpeg is not installed.
std::optional<std::string> real_encoder() {
    try {
        return find_encoder();
    } catch (const OutputError&) {
        return std::nullopt;
    }
}

// A frame whose colours change across it and from frame to frame.
Image test_frame(int width, int height, int index) {
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.resize(static_cast<std::size_t>(width) * height * 4);
    for (int row = 0; row < height; ++row)
        for (int col = 0; col < width; ++col) {
            std::uint8_t* texel = &image.rgba[(static_cast<std::size_t>(row) * width + col) * 4];
            texel[0] = static_cast<std::uint8_t>(col * 255 / width);
            texel[1] = static_cast<std::uint8_t>(row * 255 / height);
            texel[2] = static_cast<std::uint8_t>(index * 40);
            texel[3] = 255;
        }
    return image;
}

void encode(const VideoSettings& settings, const std::string& encoder, int frames) {
    VideoEncoder video(settings, encoder);
    for (int i = 0; i < frames; ++i) video.add_frame(test_frame(settings.width, settings.height, i));
    video.finish();
}

// stdout (and stderr) of a shell command.
std::string command_output(const std::string& command) {
    std::string output;
    FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return output;
    std::array<char, 4096> buffer;
    std::size_t count;
    while ((count = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) output.append(buffer.data(), count);
    ::pclose(pipe);
    return output;
}

std::string probe(const std::string& video) {
    return command_output(
        "ffprobe -v error -select_streams v:0 -count_frames "
        "-show_entries stream=codec_name,pix_fmt,width,height,nb_read_frames -of default=nw=1 '" + video + "'");
}

std::vector<std::string> entries(const std::string& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    return names;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += name + " ";
    return text;
}

// Writes an executable shell script and returns its path.
std::string write_script(const TempFolder& folder, const std::string& name, const std::string& body) {
    folder.write(name, "#!/bin/sh\n" + body + "\n");
    ::chmod(folder.file(name).c_str(), 0755);
    return folder.file(name);
}

// The OutputError message of running `action`, or "" if it throws none.
template <typename Action>
std::string output_error_of(Action action) {
    try {
        action();
    } catch (const OutputError& error) {
        EXPECT_EQ(error.code(), kExitOutput);
        return error.what();
    }
    return "";
}

TEST(VideoEncoder, FormatFromExtension) {
    EXPECT_EQ(video_format_for("out.mp4"), VideoFormat::Mp4);
    EXPECT_EQ(video_format_for("a/b/Out.MP4"), VideoFormat::Mp4);
    EXPECT_EQ(video_format_for("loop.gif"), VideoFormat::Gif);
    EXPECT_EQ(video_format_for("LOOP.Gif"), VideoFormat::Gif);
    for (const char* path : {"out.avi", "out", "mp4", "out.mp4.png", "gif/"}) {
        try {
            video_format_for(path);
            ADD_FAILURE() << path << " was accepted";
        } catch (const UsageError& error) {
            EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
        }
    }
}

TEST(VideoEncoder, MissingEncoderIsReportedUpFront) {
    {
        ScopedEnv ffmpeg("CLRENDER_FFMPEG", "/nonexistent/ffmpeg");
        const std::string message = output_error_of([] { find_encoder(); });
        EXPECT_NE(message.find("/nonexistent/ffmpeg"), std::string::npos) << message;
        EXPECT_NE(message.find("CLRENDER_FFMPEG"), std::string::npos) << message;
    }
    {
        TempFolder empty;
        ScopedEnv path("PATH", empty.path().c_str());
        ScopedEnv ffmpeg("CLRENDER_FFMPEG", "");
        EXPECT_EQ(output_error_of([] { find_encoder(); }),
                  "video encoder 'ffmpeg' not found on PATH; install the ffmpeg package (apt-get install ffmpeg)");
    }
}

TEST(VideoEncoder, FindsTheEncoderOnPathOrFromTheEnvironment) {
    TempFolder bin;
    const std::string fake = write_script(bin, "ffmpeg", "exit 0");
    bin.write("not-executable", "#!/bin/sh\n");
    const std::string search_path = "/nonexistent:" + bin.path();
    ScopedEnv path("PATH", search_path.c_str());
    {
        ScopedEnv ffmpeg("CLRENDER_FFMPEG", "");
        EXPECT_EQ(find_encoder(), fake);
    }
    {
        ScopedEnv ffmpeg("CLRENDER_FFMPEG", fake.c_str());
        EXPECT_EQ(find_encoder(), fake);
    }
    {
        const std::string not_executable = bin.file("not-executable");
        ScopedEnv ffmpeg("CLRENDER_FFMPEG", not_executable.c_str());
        EXPECT_THROW(find_encoder(), OutputError);
    }
}

TEST(VideoEncoder, Mp4OfOddSizedFramesIsPaddedH264) {
    const std::optional<std::string> encoder = real_encoder();
    if (!encoder) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder folder;
    const std::string video = folder.file("odd.mp4");
    encode({video, 33, 17}, *encoder, 5);
    const std::string info = probe(video);
    for (const char* line : {"codec_name=h264", "pix_fmt=yuv420p", "width=34", "height=18", "nb_read_frames=5"})
        EXPECT_NE(info.find(line), std::string::npos) << line << " not in:\n" << info;
    EXPECT_EQ(entries(folder.path()), std::vector<std::string>({"odd.mp4"})) << "temporary files left behind";
}

TEST(VideoEncoder, GifHasEveryFrame) {
    const std::optional<std::string> encoder = real_encoder();
    if (!encoder) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder folder;
    const std::string video = folder.file("loop.gif");
    encode({video, 20, 12}, *encoder, 4);
    const std::string info = probe(video);
    for (const char* line : {"codec_name=gif", "width=20", "height=12", "nb_read_frames=4"})
        EXPECT_NE(info.find(line), std::string::npos) << line << " not in:\n" << info;
    EXPECT_EQ(entries(folder.path()), std::vector<std::string>({"loop.gif"}));
}

// The delays, in hundredths of a second, of a GIF that ffmpeg writes at `fps` from six
// frames fed through a pipe as clrender feeds them; "" when it writes none.
std::vector<long> gif_delays(const std::string& encoder, const TempFolder& folder, double fps) {
    const std::string gif = folder.file("rate.gif");
    char rate[32];
    std::snprintf(rate, sizeof rate, "%.12g", fps);
    const std::string command = "head -c 1152 /dev/zero | '" + encoder + "' -v error -f rawvideo -pix_fmt rgb24 -s 8x8 -r " +
                                rate + " -i - -f gif -y '" + gif + "' && ffprobe -v error -show_entries packet=duration " +
                                "-of csv=p=0 '" + gif + "'";
    std::vector<long> delays;
    std::istringstream lines(command_output(command));
    for (long delay; lines >> delay;) delays.push_back(delay);
    return delays;
}

// Whether every delay is the rate's own, 100 / fps hundredths, give or take the rounding.
bool delays_hold(const std::vector<long>& delays, double fps) {
    if (delays.empty()) return false;
    for (long delay : delays)
        if (std::abs(delay - 100 / fps) > 1) return false;
    return true;
}

// The GIF range is what a GIF holds: at the fastest and slowest rates taken every frame's
// delay is the rate's own; just outside them ffmpeg silently writes other delays (10 for
// a delay of 1, 65535 for a longer one), so those rates are refused.
TEST(VideoEncoder, GifFrameRatesTakenAreTheOnesItsDelaysHold) {
    const std::optional<std::string> encoder = real_encoder();
    if (!encoder) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder folder;
    const double slowest = std::ceil(kMinGifFps * 1e6) / 1e6;  // as the message shows it
    for (double taken : {kMaxGifFps, 25.0, slowest}) {
        EXPECT_EQ(video_fps_problem(taken, VideoFormat::Gif), "") << taken;
        EXPECT_TRUE(delays_hold(gif_delays(*encoder, folder, taken), taken)) << taken << " fps";
    }
    for (double refused : {60.0, 100.0, 0.0015}) {
        EXPECT_NE(video_fps_problem(refused, VideoFormat::Gif).find("a GIF takes from 0.001526 to 50 frames per second"),
                  std::string::npos)
            << video_fps_problem(refused, VideoFormat::Gif);
        EXPECT_FALSE(delays_hold(gif_delays(*encoder, folder, refused), refused)) << refused << " fps: ffmpeg holds it";
    }
    // The encoder itself never takes a rate its format cannot hold.
    EXPECT_THROW(VideoEncoder({folder.file("fast.gif"), 8, 8, 60}, *encoder), std::invalid_argument);
}

// At the slowest MP4 rate taken, clrender's encoder writes a video that passes its own check;
// at rates refused, ffmpeg fails.
TEST(VideoEncoder, Mp4FrameRatesTakenAreOnesFfmpegWrites) {
    const std::optional<std::string> encoder = real_encoder();
    if (!encoder) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder folder;
    VideoSettings slow{folder.file("slow.mp4"), 16, 16};
    slow.fps = kMinMp4Fps;
    encode(slow, *encoder, 3);
    EXPECT_NE(probe(slow.path).find("nb_read_frames=3"), std::string::npos) << probe(slow.path);
    EXPECT_EQ(video_fps_problem(kMaxMp4Fps, VideoFormat::Mp4), "");
    for (double refused : {1e-5, 1e-6}) {
        EXPECT_NE(video_fps_problem(refused, VideoFormat::Mp4).find("an MP4 takes from 0.001 to 1000 frames per second"),
                  std::string::npos);
        // What ffmpeg itself does with such a rate, through a raw pipe as clrender feeds it.
        const std::string command = "head -c 2304 /dev/zero | '" + *encoder + "' -v error -f rawvideo -pix_fmt rgb24 -s 16x16 -r " +
                                    std::to_string(refused) + " -i - -c:v libx264 -pix_fmt yuv420p -f mp4 -y '" +
                                    folder.file("x.mp4") + "' >/dev/null 2>&1; echo $?";
        EXPECT_NE(command_output(command), "0\n") << refused << " fps: ffmpeg wrote it, so it need not be refused";
    }
}

// The same frames and options give the same bytes (docs/command-line.md, Reproducible output).
TEST(VideoEncoder, SameFramesGiveTheSameBytes) {
    const std::optional<std::string> encoder = real_encoder();
    if (!encoder) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder folder;
    for (const char* extension : {".mp4", ".gif"}) {
        const std::string first = folder.file(std::string("first") + extension);
        const std::string second = folder.file(std::string("second") + extension);
        encode({first, 32, 24}, *encoder, 3);
        encode({second, 32, 24}, *encoder, 3);
        EXPECT_EQ(read_bytes(first), read_bytes(second)) << extension;
    }
}

TEST(VideoEncoder, NothingAppearsBeforeFinish) {
    const std::optional<std::string> encoder = real_encoder();
    if (!encoder) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder folder;
    const std::string video = folder.file("partial.mp4");
    {
        VideoEncoder encoding({video, 16, 16}, *encoder);
        encoding.add_frame(test_frame(16, 16, 0));
        EXPECT_FALSE(fs::exists(video));
    }  // destroyed without finish(): abandoned
    EXPECT_TRUE(entries(folder.path()).empty()) << joined(entries(folder.path()));
}

TEST(VideoEncoder, FailingEncoderReportsItsLogAndLeavesNothing) {
    TempFolder scripts, folder;
    const std::string fake = write_script(scripts, "fake-ffmpeg", "cat >/dev/null; echo boom >&2; exit 1");
    const std::string video = folder.file("out.mp4");
    const std::string message = output_error_of([&] { encode({video, 33, 17}, fake, 3); });
    EXPECT_NE(message.find(video), std::string::npos) << message;
    EXPECT_NE(message.find("boom"), std::string::npos) << message;
    EXPECT_NE(message.find("exited with status 1"), std::string::npos) << message;
    EXPECT_TRUE(entries(folder.path()).empty()) << joined(entries(folder.path()));
}

// The encoder exits before reading anything: writing to its stdin would raise SIGPIPE and
// kill the test binary if clrender did not ignore it. 256x256 frames (256 KiB as RGBA, as much
// as the pipe's buffer then holds) overflow it, so the failure shows up in add_frame itself.
TEST(VideoEncoder, EncoderDyingAtOnceIsAnErrorNotACrash) {
    TempFolder scripts, folder;
    const std::string fake = write_script(scripts, "fake-ffmpeg", "exit 3");
    for (int size : {8, 256}) {
        const std::string video = folder.file("out.gif");
        const std::string message = output_error_of([&] { encode({video, size, size}, fake, 10); });
        EXPECT_NE(message.find("exited with status 3"), std::string::npos) << size << ": " << message;
        if (size == 256) {
            EXPECT_NE(message.find("stopped reading frames"), std::string::npos) << message;
        }
        EXPECT_TRUE(entries(folder.path()).empty()) << joined(entries(folder.path()));
    }
}

TEST(VideoEncoder, EncoderThatWritesNothingIsAnError) {
    TempFolder scripts, folder;
    const std::string fake = write_script(scripts, "fake-ffmpeg", "cat >/dev/null; exit 0");
    const std::string message = output_error_of([&] { encode({folder.file("out.mp4"), 8, 8}, fake, 2); });
    EXPECT_NE(message.find("wrote no video"), std::string::npos) << message;
    EXPECT_TRUE(entries(folder.path()).empty()) << joined(entries(folder.path()));
}

// The video's folder removed while it is made: ffmpeg writes on into its open file and exits 0,
// and its file is then not found by its path. The message names the folder, not the encoder
// alone ("'ffmpeg' exited successfully but wrote no video" said nothing of the folder).
TEST(VideoEncoder, AFolderRemovedMeanwhileIsNamedAsTheCause) {
    const std::optional<std::string> encoder = real_encoder();
    if (!encoder) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder folder;
    fs::create_directory(folder.file("out"));
    const std::string message = output_error_of([&] {
        VideoEncoder video({folder.file("out/x.mp4"), 64, 48}, *encoder);
        for (int i = 0; i < 5; ++i) video.add_frame(test_frame(64, 48, i));
        fs::remove_all(folder.file("out"));
        for (int i = 5; i < 10; ++i) video.add_frame(test_frame(64, 48, i));
        video.finish();
    });
    EXPECT_NE(message.find(folder.file("out/x.mp4") + ": video encoding failed: "), std::string::npos) << message;
    EXPECT_NE(message.find("; the folder '" + folder.file("out") +
                           "' is gone: it was removed or renamed while the output was made"),
              std::string::npos)
        << message;
    EXPECT_TRUE(entries(folder.path()).empty()) << joined(entries(folder.path()));
}

// Another user who may write into the video's folder replaces the temporary file clrender made
// with a symbolic link before ffmpeg starts (here the encoder does it itself, first): ffmpeg,
// given the name, opened it through the link and overwrote its target, a file of the user who
// renders, and the "video" renamed into place was that link. It writes into the file clrender
// made, whatever the folder's names lead to meanwhile.
TEST(VideoEncoder, ALinkPlantedAtTheTemporaryNameIsNotFollowed) {
    const std::optional<std::string> encoder = real_encoder();
    if (!encoder) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder scripts, folder, elsewhere;
    elsewhere.write("mine.txt", "the user's own file\n");
    const std::string planting = write_script(
        scripts, "planting-ffmpeg",
        "for temp in '" + folder.path() + "'/.clrender-*.tmp; do rm -f \"$temp\"; ln -s '" + elsewhere.file("mine.txt") +
            "' \"$temp\"; done\nexec '" + *encoder + "' \"$@\"");
    const std::string video = folder.file("out.mp4");
    output_error_of([&] { encode({video, 16, 16}, planting, 3); });
    EXPECT_TRUE(read_bytes(elsewhere.file("mine.txt")) == "the user's own file\n") << "overwritten by the video";
    EXPECT_FALSE(fs::is_symlink(video));
}

// Another user who may write into the folder can guess the usual temporary names and make
// them first; here only the logs', so that the video's file is made and its log is not: the
// pair is given up for an unpredictable one, and the video is written all the same.
TEST(VideoEncoder, IsWrittenWhenTheUsualLogNamesAreTaken) {
    const std::optional<std::string> encoder = real_encoder();
    if (!encoder) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder folder;
    testing::take_the_next_usual_temp_names(folder, 64);
    for (const std::string& name : entries(folder.path()))
        if (fs::path(name).extension() != ".log") fs::remove(folder.file(name));
    const std::vector<std::string> taken = entries(folder.path());
    encode({folder.file("out.mp4"), 16, 16}, *encoder, 3);
    EXPECT_NE(probe(folder.file("out.mp4")).find("nb_read_frames=3"), std::string::npos);
    std::vector<std::string> expected = taken;
    expected.push_back("out.mp4");
    std::sort(expected.begin(), expected.end());
    std::vector<std::string> left = entries(folder.path());
    std::sort(left.begin(), left.end());
    EXPECT_EQ(left, expected) << "a temporary file left behind, or one of theirs removed";
}

TEST(VideoEncoder, FinishingWithoutFramesIsAnError) {
    TempFolder scripts, folder;
    const std::string fake = write_script(scripts, "fake-ffmpeg", "cat >/dev/null");
    const std::string message = output_error_of([&] { encode({folder.file("out.mp4"), 8, 8}, fake, 0); });
    EXPECT_NE(message.find("no frames"), std::string::npos) << message;
    EXPECT_TRUE(entries(folder.path()).empty()) << joined(entries(folder.path()));
}

// A fake encoder that copies its input to the output file (its last argument) receives every
// byte of every frame, in order: a GIF's as the frames hold them (RGBA, told so by "-pix_fmt
// rgb0"), an MP4's converted to yuv420p at the padded size (told so by "-pix_fmt yuv420p").
TEST(VideoEncoder, SendsTheFramesAsTheyAreInMemory) {
    TempFolder scripts, folder;
    const std::string fake = write_script(scripts, "fake-ffmpeg",
                                          "echo \"$*\" > \"$0.args\"; for last; do :; done; cat >\"$last\"");
    const std::string prober = write_script(scripts, "fake-ffprobe", "echo 2");  // raw bytes are no video
    ScopedEnv checker("CLRENDER_FFPROBE", prober.c_str());
    const std::string gif = folder.file("raw.gif");
    encode({gif, 5, 3}, fake, 2);
    std::string expected;
    for (int index = 0; index < 2; ++index) {
        const Image frame = test_frame(5, 3, index);
        expected.append(reinterpret_cast<const char*>(frame.rgba.data()), frame.rgba.size());
    }
    EXPECT_EQ(read_bytes(gif), expected);
    EXPECT_NE(read_bytes(fake + ".args").find("-f rawvideo -pix_fmt rgb0 -s 5x3 "), std::string::npos)
        << read_bytes(fake + ".args");

    const std::string mp4 = folder.file("raw.mp4");
    encode({mp4, 5, 3}, fake, 2);
    expected.clear();
    for (int index = 0; index < 2; ++index) {
        std::vector<std::uint8_t> yuv;
        rgba_to_yuv420(test_frame(5, 3, index), yuv);
        expected.append(reinterpret_cast<const char*>(yuv.data()), yuv.size());
    }
    EXPECT_EQ(read_bytes(mp4).size(), 2u * (6 * 4 * 3 / 2));
    EXPECT_EQ(read_bytes(mp4), expected);
    EXPECT_NE(read_bytes(fake + ".args").find("-f rawvideo -pix_fmt yuv420p -s 6x4 "), std::string::npos)
        << read_bytes(fake + ".args");
}

// What x264 encodes is exactly the frames clrender converted: at CRF 0 (lossless), the
// decoded video's planes are rgba_to_yuv420's bytes, at an odd size too; and the stream says
// BT.709, limited range, so that a player converts them back to the colours rendered. Decoded
// back to RGB by ffmpeg's exact conversion, a frame whose colour is the same within each 2x2
// block (so 4:2:0's shared chroma loses nothing) is within 2 levels of what was rendered: the
// rounding to 8 bits there and back (limited range spreads a step of Y' over 255/219 levels of
// R'G'B'). Another matrix or range would be tens of levels off.
TEST(VideoEncoder, Mp4DecodesToTheConvertedFrames) {
    const std::optional<std::string> encoder = real_encoder();
    if (!encoder) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder folder;
    const int width = 33, height = 17, frames = 3;
    const std::string video = folder.file("lossless.mp4");
    VideoSettings settings{video, width, height};
    settings.quality = 0;
    // Colours that change by a few levels from block to block, differently in each channel.
    std::vector<Image> rendered;
    for (int index = 0; index < frames; ++index) {
        Image frame = test_frame(width, height, index);
        for (int row = 0; row < height; ++row)
            for (int col = 0; col < width; ++col) {
                std::uint8_t* texel = &frame.rgba[(static_cast<std::size_t>(row) * width + col) * 4];
                const int block_col = col / 2, block_row = row / 2;
                texel[0] = static_cast<std::uint8_t>(40 + block_col * 3 + index * 20);
                texel[1] = static_cast<std::uint8_t>(200 - block_row * 3 - block_col);
                texel[2] = static_cast<std::uint8_t>(90 + block_row * 4 - index * 30);
            }
        rendered.push_back(frame);
    }
    {
        VideoEncoder encoding(settings, *encoder);
        for (const Image& frame : rendered) encoding.add_frame(frame);
        encoding.finish();
    }

    std::string converted;
    for (const Image& frame : rendered) {
        std::vector<std::uint8_t> yuv;
        rgba_to_yuv420(frame, yuv);
        converted.append(reinterpret_cast<const char*>(yuv.data()), yuv.size());
    }
    const std::string planes = folder.file("planes.yuv");
    command_output("ffmpeg -v error -i '" + video + "' -f rawvideo -pix_fmt yuv420p -y '" + planes + "'");
    EXPECT_EQ(read_bytes(planes).size(), converted.size());
    EXPECT_TRUE(read_bytes(planes) == converted) << "the decoded planes differ from the converted frames";

    const std::string tags = command_output(
        "ffprobe -v error -select_streams v:0 -show_entries stream=color_range,color_space,color_primaries,color_transfer "
        "-of default=nw=1 '" + video + "'");
    for (const char* tag : {"color_range=tv", "color_space=bt709", "color_primaries=bt709", "color_transfer=bt709"})
        EXPECT_NE(tags.find(tag), std::string::npos) << tag << " not in:\n" << tags;

    const std::string rgb = folder.file("frames.rgb");
    // Converted back as the tags say, each block's chroma for its four pixels (not interpolated
    // across blocks) with exact rounding, then cut to the rendered size.
    command_output("ffmpeg -v error -i '" + video +
                   "' -vf scale=in_color_matrix=bt709:in_range=tv:flags=neighbor+accurate_rnd+full_chroma_int,"
                   "format=rgb24,crop=" +
                   std::to_string(width) + ":" + std::to_string(height) + ":0:0 -f rawvideo -pix_fmt rgb24 -y '" + rgb +
                   "'");
    const std::string decoded = read_bytes(rgb);
    ASSERT_EQ(decoded.size(), static_cast<std::size_t>(width * height * 3 * frames));
    int worst = 0;
    for (int index = 0; index < frames; ++index) {
        const Image& frame = rendered[index];
        // The last column and row share their chroma with the black padding: left out.
        for (int row = 0; row < height - 1; ++row)
            for (int col = 0; col < width - 1; ++col)
                for (int c = 0; c < 3; ++c) {
                    const std::size_t at = ((static_cast<std::size_t>(index) * height + row) * width + col) * 3 + c;
                    worst = std::max(worst, std::abs(static_cast<std::uint8_t>(decoded[at]) - frame.at(col, row, c)));
                }
    }
    EXPECT_LE(worst, 2) << "the decoded video is further from the frames than the conversion's rounding explains";
}

// ffmpeg reads the frames' fourth byte as padding: frames that differ only in their alpha
// bytes give the same video, byte for byte, as opaque ones (a GIF would gain transparent
// pixels if ffmpeg read them as alpha), at an odd size too (the MP4's padded column and row).
TEST(VideoEncoder, AlphaBytesDoNotChangeTheVideo) {
    const std::optional<std::string> encoder = real_encoder();
    if (!encoder) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder folder;
    for (const char* extension : {".mp4", ".gif"}) {
        const std::string opaque = folder.file(std::string("opaque") + extension);
        const std::string translucent = folder.file(std::string("translucent") + extension);
        const VideoSettings size{"", 33, 17};
        {
            VideoEncoder video({opaque, size.width, size.height}, *encoder);
            for (int i = 0; i < 3; ++i) video.add_frame(test_frame(size.width, size.height, i));
            video.finish();
        }
        {
            VideoEncoder video({translucent, size.width, size.height}, *encoder);
            for (int i = 0; i < 3; ++i) {
                Image frame = test_frame(size.width, size.height, i);
                for (std::size_t texel = 0; texel < frame.rgba.size(); texel += 4)
                    frame.rgba[texel + 3] = static_cast<std::uint8_t>((texel * 37 + i * 101) % 256);
                video.add_frame(frame);
            }
            video.finish();
        }
        EXPECT_FALSE(read_bytes(opaque).empty()) << extension;
        EXPECT_TRUE(read_bytes(opaque) == read_bytes(translucent))  // no EXPECT_EQ: it would print the videos
            << extension << ": the alpha bytes changed the video";
    }
}

TEST(VideoEncoder, DestructorStopsAStuckEncoder) {
    TempFolder scripts, folder;
    const std::string fake = write_script(scripts, "fake-ffmpeg", "exec sleep 1000");
    const auto start = std::chrono::steady_clock::now();
    {
        VideoEncoder video({folder.file("out.mp4"), 8, 8}, fake);
        video.add_frame(test_frame(8, 8, 0));  // fits in the pipe's buffer
    }
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    EXPECT_TRUE(entries(folder.path()).empty()) << joined(entries(folder.path()));
}

// ffprobe's count is exact for both formats even when frames repeat (a still camera): x264
// and the GIF muxer keep every frame, so a correct video is never rejected.
TEST(VideoEncoder, IdenticalFramesPassTheFrameCountCheck) {
    const std::optional<std::string> encoder = real_encoder();
    if (!encoder) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder folder;
    for (const char* name : {"still.mp4", "still.gif"}) {
        const std::string video = folder.file(name);
        VideoEncoder encoding({video, 24, 16, 30}, *encoder);
        for (int i = 0; i < 6; ++i) encoding.add_frame(test_frame(24, 16, 0));
        encoding.finish();
        EXPECT_NE(probe(video).find("nb_read_frames=6"), std::string::npos) << name << ":\n" << probe(video);
    }
}

// An encoder that exits 0 after writing something that is not the video asked for.
TEST(VideoEncoder, VideoWithMissingFramesOrGarbageIsRejected) {
    const std::optional<std::string> encoder = real_encoder();
    if (!encoder) GTEST_SKIP() << "ffmpeg is not installed";
    TempFolder scripts, folder;
    // Encodes only the first 2 frames it is given (2 x 16 x 16 x 1.5 bytes of yuv420p), then
    // reads the rest.
    const std::string short_video = write_script(
        scripts, "two-frames",
        "head -c " + std::to_string(2 * yuv420_bytes(16, 16)) + " | '" + *encoder + "' \"$@\" && cat > /dev/null");
    const std::string video = folder.file("out.mp4");
    folder.write("out.mp4", "earlier");
    std::string message = output_error_of([&] { encode({video, 16, 16}, short_video, 5); });
    EXPECT_NE(message.find("the finished video is not valid: it holds 2 readable frame(s), 5 were sent"),
              std::string::npos) << message;
    EXPECT_EQ(read_bytes(video), "earlier");

    const std::string garbage = write_script(scripts, "garbage", "cat >/dev/null; for last; do :; done; echo junk >\"$last\"");
    message = output_error_of([&] { encode({video, 16, 16}, garbage, 3); });
    EXPECT_NE(message.find("the finished video is not valid: the check cannot read it: '"), std::string::npos) << message;
    EXPECT_EQ(read_bytes(video), "earlier");
    EXPECT_EQ(entries(folder.path()), std::vector<std::string>({"out.mp4"}));
}

TEST(VideoEncoder, FfprobeIsFoundBesideTheEncoderOrFromTheEnvironment) {
    TempFolder bin;
    const std::string encoder = write_script(bin, "ffmpeg", "exit 0");
    const std::string beside = write_script(bin, "ffprobe", "exit 0");
    {
        ScopedEnv prober("CLRENDER_FFPROBE", nullptr);
        EXPECT_EQ(find_video_prober(encoder), beside);
    }
    {
        ScopedEnv prober("CLRENDER_FFPROBE", "/nonexistent/ffprobe");
        const std::string message = output_error_of([&] { find_video_prober(encoder); });
        EXPECT_NE(message.find("'/nonexistent/ffprobe' (from CLRENDER_FFPROBE) not found"), std::string::npos) << message;
        TempFolder folder;
        EXPECT_THROW(VideoEncoder({folder.file("out.mp4"), 8, 8}, encoder), OutputError) << "checked before any frame";
        EXPECT_TRUE(entries(folder.path()).empty());
    }
    {
        TempFolder empty;
        ScopedEnv path("PATH", empty.path().c_str());
        ScopedEnv prober("CLRENDER_FFPROBE", nullptr);
        const std::string message = output_error_of([] { find_video_prober("/nonexistent/ffmpeg"); });
        EXPECT_NE(message.find("'ffprobe' not found"), std::string::npos) << message;
    }
}

TEST(VideoEncoder, StallTimeoutComesFromTheEnvironment) {
    {
        ScopedEnv timeout("CLRENDER_ENCODER_TIMEOUT", nullptr);
        EXPECT_EQ(encoder_stall_timeout().count(), 60);
    }
    {
        ScopedEnv timeout("CLRENDER_ENCODER_TIMEOUT", "1.5");
        EXPECT_EQ(encoder_stall_timeout().count(), 1.5);
    }
    for (const char* bad : {"0", "-1", "soon", "1s", "nan", "inf", "1e9"}) {
        ScopedEnv timeout("CLRENDER_ENCODER_TIMEOUT", bad);
        try {
            encoder_stall_timeout();
            ADD_FAILURE() << bad << " was accepted";
        } catch (const UsageError& error) {
            EXPECT_NE(std::string(error.what()).find(std::string("CLRENDER_ENCODER_TIMEOUT must be") ), std::string::npos);
            EXPECT_NE(std::string(error.what()).find(bad), std::string::npos) << error.what();
        }
    }
}

// 64x64 frames (6 KiB as the yuv420p an MP4's encoder is sent): eleven fill a pipe's 64 KiB,
// so a later one of the twenty waits on the encoder.
TEST(VideoEncoder, EncoderThatStopsReadingTimesOut) {
    TempFolder scripts, folder;
    const std::string fake = write_script(scripts, "fake-ffmpeg", "exec sleep 1000");
    ScopedEnv timeout("CLRENDER_ENCODER_TIMEOUT", "0.5");
    const auto start = std::chrono::steady_clock::now();
    const std::string message = output_error_of([&] { encode({folder.file("out.mp4"), 64, 64}, fake, 20); });
    EXPECT_NE(message.find("the encoder stopped reading frames for 0.5 s"), std::string::npos) << message;
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
    EXPECT_TRUE(entries(folder.path()).empty()) << joined(entries(folder.path()));
}

// FrameSink cancels the encoder from another thread when the render fails: a write waiting
// on a stalled encoder must give up at once, not at the stall timeout.
TEST(VideoEncoder, CancelEndsAWaitFromAnotherThread) {
    TempFolder scripts, folder;
    const std::string fake = write_script(scripts, "fake-ffmpeg", "exec sleep 1000");
    VideoEncoder video({folder.file("out.mp4"), 64, 64}, fake);
    const auto start = std::chrono::steady_clock::now();
    std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        video.cancel();
    });
    const std::string message = output_error_of([&] {
        for (int i = 0; i < 20; ++i) video.add_frame(test_frame(64, 64, i));
    });
    canceller.join();
    EXPECT_NE(message.find("abandoned"), std::string::npos) << message;
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10)) << "the default timeout is 60 s";
    EXPECT_TRUE(entries(folder.path()).empty()) << joined(entries(folder.path()));
}

TEST(VideoEncoder, RejectsFramesOfTheWrongSize) {
    TempFolder scripts, folder;
    const std::string fake = write_script(scripts, "fake-ffmpeg", "cat >/dev/null");
    VideoEncoder video({folder.file("out.mp4"), 8, 8}, fake);
    EXPECT_THROW(video.add_frame(test_frame(8, 9, 0)), std::invalid_argument);
    EXPECT_THROW(video.add_frame(test_frame(9, 8, 0)), std::invalid_argument);
}

TEST(VideoEncoder, UnstartableEncoderOrMissingFolderIsAnOutputError) {
    TempFolder folder;
    EXPECT_THROW(VideoEncoder({folder.file("out.mp4"), 8, 8}, "/nonexistent/ffmpeg"), OutputError);
    EXPECT_TRUE(entries(folder.path()).empty()) << joined(entries(folder.path()));
    EXPECT_THROW(VideoEncoder({folder.file("missing/out.mp4"), 8, 8}, "/bin/cat"), OutputError);
    EXPECT_THROW(VideoEncoder({folder.file("out.avi"), 8, 8}, "/bin/cat"), UsageError);
}

}  // namespace
}  // namespace clr
