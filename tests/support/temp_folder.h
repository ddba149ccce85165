// Files for tests: a fresh temporary folder, and whole files read as bytes.
#pragma once

#include <filesystem>
#include <string>

namespace clr::testing {

// A fresh, empty, uniquely named folder under the system's temporary folder (mkdtemp), removed
// with everything in it when the object goes out of scope, even if a test made it read-only.
class TempFolder {
public:
    TempFolder();
    ~TempFolder();
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;

    const std::string& path() const { return path_; }
    // The path of `name` (which may contain folders) inside this folder.
    std::string file(const std::string& name) const { return path_ + "/" + name; }
    // Writes `bytes` exactly (binary) to file(name), replacing it; returns that path.
    std::string write(const std::string& name, const std::string& bytes) const;
    // How many files and folders are directly inside.
    int entry_count() const;

private:
    std::string path_;
};

// The whole contents of a file, byte for byte; empty when it cannot be read.
std::string read_bytes(const std::filesystem::path& path);

}  // namespace clr::testing
