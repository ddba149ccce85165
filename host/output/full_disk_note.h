// Why an output may have failed when the program that wrote it does not say: ffmpeg 5.1 exits
// 0 after its writes failed with ENOSPC, leaving a cut-off file that only the video check
// (output/video_probe.h) finds, so that its message would blame the check rather than the disk.
#pragma once

#include <cstdint>
#include <string>

namespace clr {

// Free space below this, on the file system of a failed output, is named as its likely
// cause: ffmpeg writes its file in pieces of 32 KiB, and moves the MP4 index to the front
// (+faststart) in pieces of about as much.
constexpr std::uint64_t kNearlyFullDiskBytes = 1 << 20;

// "; the disk holding it has only 4 KiB free: it is likely full (No space left on device)"
// for the file system of `path`'s folder when less than kNearlyFullDiskBytes are free to clrender's user,
// else "" (also where the system cannot say).
std::string full_disk_note(const std::string& path);

}  // namespace clr
