// The packets of tev's IPC protocol (the TCP protocol of the tev image viewer, as its
// src/Ipc.cpp and python/ipc.py define it), which clrender sends to show a render as it is
// made (docs/command-line.md, Streaming to tev). Every packet is:
//   uint32 length   the whole packet's size in bytes, these four included
//   uint8  type     2 CloseImage, 4 CreateImage, 6 UpdateImage (version 3)
//   fields          per type; integers little-endian, strings UTF-8 ending with a 0 byte,
//                   booleans one byte, floats IEEE 754 binary32 little-endian
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace clr {

enum class TevPacketType : std::uint8_t { CloseImage = 2, CreateImage = 4, UpdateImage = 6 };

using TevPacket = std::vector<std::uint8_t>;

// CreateImage: bool grab_focus, string name, int32 width, int32 height, int32 channel count,
// the channel names as strings. An image of that name is replaced.
TevPacket tev_create_image(const std::string& name, int width, int height, const std::vector<std::string>& channels,
                           bool grab_focus = true);

// UpdateImage (version 3): bool grab_focus, string name, int32 channel count, the channel
// names, int32 x, y, width, height of the rectangle, int64 offset of each channel, int64
// stride of each channel, then the floats. clrender sends the channels interleaved: channel
// c of the rectangle's pixel p (row by row) is float number c + p * channels.size().
// `values` holds width * height * channels.size() floats (std::invalid_argument otherwise).
TevPacket tev_update_image(const std::string& name, const std::vector<std::string>& channels, int x, int y, int width,
                           int height, const std::vector<float>& values, bool grab_focus = false);

// CloseImage: string name.
TevPacket tev_close_image(const std::string& name);

}  // namespace clr
