// Which file an output name really writes, and whether two names are one file.
//
// Policy for outputs that are not plain files: a symbolic link is written THROUGH (the new
// file replaces the regular file the link resolves to; the link survives and shows the new
// contents); a link to a missing file is refused, as are named pipes, sockets, devices and
// folders (writing there would hang, discard the image, or replace something that is not an
// image). Refusals are OutputErrors (exit code 4).
//
// A render that `clrender view` starts for its video has kLinksReplacedVariable set: there a
// symbolic link at an output's name is replaced by the output, as any other file there would
// be, and never written through (the viewer writes only into its --output-dir).
#pragma once

#include <sys/types.h>

#include <string>
#include <tuple>

namespace clr {

// The path whose directory entry the output will replace: `path` when it does not exist yet
// or is a regular file, the resolved target when `path` is a symbolic link to a regular
// file. Throws OutputError for everything else.
// Under kLinksReplacedVariable ("1"), a symbolic link is `path` itself.
std::string resolve_output_target(const std::string& path);

// Set to "1" by clrender view in the environment of its video's render.
inline constexpr const char* kLinksReplacedVariable = "CLRENDER_LINKS_REPLACED";

// A file's identity: (device, inode) after following symbolic links for a file that exists,
// so that hard links and symbolic links of one file compare equal; the normalised absolute
// path (std::filesystem::weakly_canonical) for one that does not exist yet.
struct FileIdentity {
    bool exists = false;
    dev_t device = 0;
    ino_t inode = 0;
    std::string path;  // empty when `exists`

    bool operator<(const FileIdentity& other) const {
        return std::tie(exists, device, inode, path) < std::tie(other.exists, other.device, other.inode, other.path);
    }
    bool operator==(const FileIdentity& other) const {
        return std::tie(exists, device, inode, path) == std::tie(other.exists, other.device, other.inode, other.path);
    }
};

FileIdentity identify_file(const std::string& path);

}  // namespace clr
