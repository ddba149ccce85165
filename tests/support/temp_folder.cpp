#include "support/temp_folder.h"

#include <stdlib.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <system_error>

namespace clr::testing {

namespace fs = std::filesystem;

namespace {

// Gives the owner full access to `folder` and every folder below it, so that remove_all can
// empty them; never throws.
void restore_owner_access(const fs::path& folder) {
    std::error_code ignored;
    fs::permissions(folder, fs::perms::owner_all, fs::perm_options::add, ignored);
    for (fs::directory_iterator it(folder, ignored), end; it != end; it.increment(ignored)) {
        if (it->is_directory(ignored) && !it->is_symlink(ignored)) restore_owner_access(it->path());
    }
}

}  // namespace

TempFolder::TempFolder() {
    std::string name = (fs::temp_directory_path() / "clrender-test-XXXXXX").string();
    if (!::mkdtemp(name.data())) {
        throw std::runtime_error("cannot make a temporary folder " + name + ": " + std::strerror(errno));
    }
    path_ = name;
}

TempFolder::~TempFolder() {
    restore_owner_access(path_);
    std::error_code ignored;
    fs::remove_all(path_, ignored);
}

std::string TempFolder::write(const std::string& name, const std::string& bytes) const {
    const std::string path = file(name);
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

int TempFolder::entry_count() const {
    return static_cast<int>(std::distance(fs::directory_iterator(path_), fs::directory_iterator()));
}

std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace clr::testing
