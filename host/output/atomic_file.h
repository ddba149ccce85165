// Writes a file so that it appears under its final name complete or not at all: data goes
// to a temporary file in the same folder (named by temp_files.h), and commit() renames it
// into place (core/replacement_file.h, synced to the disk first). A writer that is destroyed without commit() (an error, an exception) removes
// the temporary file.
//
// The final name is checked and resolved by resolve_output_target() (output_target.h): a
// symbolic link is written through, a FIFO, socket, device or folder is refused.
//
// Several files that must change together (a still image and its --stats report) are each
// complete()d first and only then committed: a failure before the renames leaves every
// earlier file as it was.
#pragma once

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "core/replacement_file.h"

namespace clr {

class AtomicFile {
public:
    // Creates the temporary file beside the file `final_path` resolves to. Throws OutputError
    // if it cannot or if `final_path` is not a place for an output.
    explicit AtomicFile(std::string final_path);
    // Takes over `finished_temp_path`, a complete file that another writer (the video
    // encoder) made beside the file `final_path` resolves to and synced: it is renamed into
    // place by commit() and removed if destroyed uncommitted.
    static std::unique_ptr<AtomicFile> adopt(const std::string& finished_temp_path, std::string final_path);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    const std::string& temp_path() const { return temp_->temporary_path(); }
    const std::string& final_path() const { return final_path_; }  // as given, for messages
    const std::string& target_path() const { return target_path_; }  // the entry that is replaced
    std::FILE* stream() { return stream_; }  // open for binary writing until complete()

    // Writes all bytes; throws OutputError on failure (a short write, ENOSPC).
    void write(const void* data, std::size_t size);
    // Flushes, syncs and closes the temporary file: after it, the data is on disk and only
    // the rename is left. Throws OutputError (ENOSPC and I/O errors often surface only here).
    void complete();
    // complete()s if that is not done yet, then renames the temporary file to the final name.
    void commit();

private:
    AtomicFile() = default;

    std::string final_path_;
    std::string target_path_;
    std::optional<ReplacementFile> temp_;
    std::FILE* stream_ = nullptr;  // owns temp_'s descriptor
    bool completed_ = false;
    bool committed_ = false;
};

}  // namespace clr
