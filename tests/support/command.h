// Runs the clrender binary as a user would, capturing its exit code and output.
#pragma once

#include <string>

namespace clr::testing {

struct CommandResult {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};

// Runs `clrender <arguments>` through the shell in `folder` (empty: the current one), with
// optional environment assignments placed before it ("CLRENDER_DEVICE=x").
CommandResult run_clrender(const std::string& arguments, const std::string& folder = "", const std::string& environment = "");

// A fresh, empty temporary folder, removed when the object goes out of scope.
class TempFolder {
public:
    TempFolder();
    ~TempFolder();
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;
    const std::string& path() const { return path_; }
    std::string file(const std::string& name) const { return path_ + "/" + name; }
    void write(const std::string& name, const std::string& text) const;

private:
    std::string path_;
};

}  // namespace clr::testing
