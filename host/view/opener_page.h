// The page that hands the viewer's address, token included, to the browser. A program's
// arguments are readable by every user of the machine (/proc/PID/cmdline), and xdg-open passes
// its argument on to the browser it starts: with the address as the argument, any local user
// could read the token while they ran and drive the viewer. xdg-open gets the path of this page
// instead: a file only its owner can read (0600, in a folder of its own made 0700 by mkdtemp,
// under $XDG_RUNTIME_DIR or the temporary folder), which forwards the browser to the address.
// The page and its folder are removed when the viewer stops.
#pragma once

#include <optional>
#include <string>

namespace clr {

class OpenerPage {
public:
    // Writes the page forwarding to `url`; std::nullopt (with `why` set) when it cannot.
    static std::optional<OpenerPage> write(const std::string& url, std::string& why);
    OpenerPage(OpenerPage&& other) noexcept;
    OpenerPage& operator=(OpenerPage&&) = delete;
    OpenerPage(const OpenerPage&) = delete;
    ~OpenerPage();  // removes the page and its folder

    const std::string& path() const { return path_; }

private:
    OpenerPage(std::string folder, std::string path) : folder_(std::move(folder)), path_(std::move(path)) {}
    std::string folder_, path_;
};

}  // namespace clr
