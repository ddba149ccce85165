#include "view/opener_page.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <utility>
#include <vector>

namespace clr {
namespace {

// Where the page's folder goes: $XDG_RUNTIME_DIR (the user's own, 0700) when it names a
// folder, else the system's temporary folder ($TMPDIR or /tmp).
std::string parent_folder() {
    const char* runtime = std::getenv("XDG_RUNTIME_DIR");
    struct stat info {};
    if (runtime && runtime[0] == '/' && ::stat(runtime, &info) == 0 && S_ISDIR(info.st_mode)) return runtime;
    std::error_code error;
    const std::filesystem::path temporary = std::filesystem::temp_directory_path(error);
    return error ? std::string("/tmp") : temporary.string();
}

// The page: the address is made of digits, letters, '.', ':', '/', '?', '=', '[' and ']'
// (view_server.cpp), none of which needs escaping in an HTML attribute.
std::string page_text(const std::string& url) {
    return "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">\n<meta http-equiv=\"refresh\" content=\"0;url=" + url +
           "\">\n<title>clrender view</title></head>\n<body><a href=\"" + url + "\">clrender view</a></body></html>\n";
}

}  // namespace

std::optional<OpenerPage> OpenerPage::write(const std::string& url, std::string& why) {
    const std::string parent = parent_folder();
    const std::string pattern = parent + "/clrender-view-XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    if (!::mkdtemp(name.data())) {
        why = "cannot make a folder in " + parent + ": " + std::strerror(errno);
        return std::nullopt;
    }
    const std::string folder = name.data();
    const std::string path = folder + "/open.html";
    const int file = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    const std::string text = page_text(url);
    bool written = file >= 0 && ::write(file, text.data(), text.size()) == static_cast<ssize_t>(text.size());
    const int error = errno;
    if (file >= 0) written = ::close(file) == 0 && written;
    if (!written) {
        why = "cannot write " + path + ": " + std::strerror(error);
        ::unlink(path.c_str());
        ::rmdir(folder.c_str());
        return std::nullopt;
    }
    return OpenerPage(folder, path);
}

OpenerPage::OpenerPage(OpenerPage&& other) noexcept
    : folder_(std::exchange(other.folder_, {})), path_(std::exchange(other.path_, {})) {}

OpenerPage::~OpenerPage() {
    if (path_.empty()) return;
    ::unlink(path_.c_str());
    ::rmdir(folder_.c_str());
}

}  // namespace clr
