// Writes a file so that it appears under its final name complete or not at all: data goes
// to a temporary file in the same folder, and commit() renames it into place. A writer that
// is destroyed without commit() (an error, an exception) removes the temporary file.
#pragma once

#include <cstdio>
#include <string>

namespace clr {

class AtomicFile {
public:
    // Creates the temporary file beside `final_path`. Throws OutputError if it cannot.
    explicit AtomicFile(std::string final_path);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    const std::string& temp_path() const { return temp_path_; }
    const std::string& final_path() const { return final_path_; }
    std::FILE* stream() { return stream_; }  // open for binary writing until commit()

    // Writes all bytes; throws OutputError on failure.
    void write(const void* data, std::size_t size);
    // Flushes, closes and renames the temporary file to the final name. Throws OutputError.
    void commit();

private:
    std::string final_path_;
    std::string temp_path_;
    std::FILE* stream_ = nullptr;
    bool committed_ = false;
};

}  // namespace clr
